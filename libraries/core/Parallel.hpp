#pragma once
// Loops and reductions. Every particle loop goes through parallelFor, every reduction through
// LocalReduce or GlobalReduce: OpenMP lives here and nowhere in solver code.
//
// Two kinds of reduction, and the choice matters once particles are spread over MPI ranks:
//   LocalReduce   over this process's items, threads only. For quantities of the rank's own
//                 data (its bounding box, its largest displacement, a count of its own bad
//                 inputs behind an early return or throw).
//   GlobalReduce  LocalReduce followed by the global hook (globalSum/globalMin/globalMax below),
//                 which an MPI build fills with MPI_Allreduce. For figures every rank must agree
//                 on: time-step votes, conservation sums and error norms, state-check counts,
//                 projections. A global reduction is collective: every rank must reach it, so
//                 it must never sit behind a rank-local early return (that would deadlock).
//
// Reductions are deterministic for any thread count: the range is cut into fixed blocks
// (independent of the number of threads), each block is summed in order, and the block sums
// are added in block order. Across ranks `sum` still depends on where the ranks' items end (in
// the last bits); `exactSum` (ExactSum) does not: the correctly rounded sum on any decomposition.
#include "core/Communicator.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace mfdyn {

int threadCount();

// Below this many items a loop runs on one thread: starting a parallel region costs more than
// the work (and far more on an oversubscribed machine, where waiting threads are descheduled).
inline constexpr std::size_t parallelThreshold = 4096;

template <class Body>
void parallelFor(std::size_t n, Body&& body) {
#pragma omp parallel for schedule(static) if (n >= parallelThreshold)
    for (std::size_t i = 0; i < n; ++i) body(i);
}

// For loops whose items are heavy (a gather over ~50 neighbours each): `work` is the cost of the
// whole loop in item-equivalents of a light loop (e.g. the pair count), compared with the same
// threshold.
template <class Body>
void parallelForWork(std::size_t n, std::size_t work, Body&& body) {
#pragma omp parallel for schedule(static) if (work >= parallelThreshold && n > 1)
    for (std::size_t i = 0; i < n; ++i) body(i);
}

// A fixed-size array of sums for LocalReduce::sum and GlobalReduce::sum (which value-initialise
// their type to zero; Eigen vectors are not):
// GlobalReduce::sum<SumArray<3>>(n, [&](std::size_t i) { SumArray<3> t; ...; return t; }).
template <int N>
struct SumArray {
    std::array<double, N> s{};
    SumArray& operator+=(const SumArray& o) {
        for (int k = 0; k < N; ++k) s[k] += o.s[k];
        return *this;
    }
};

// An exact sum of doubles: Neal's superaccumulator (R. M. Neal, "Fast exact summation using small
// and large superaccumulators", arXiv:1505.05571, 2015; the same idea as Collange, Defour, Graillat
// and Iakymchuk's ExBLAS, 2015). The sum is kept as a fixed-point number over the whole range of
// the double exponents, 2^-1074 (the smallest subnormal) to 2^2112, in `limbs` signed 64-bit
// limbs of 32 bits each: limb k holds digit k of weight 2^(32k - 1074). A double is its 53-bit
// integer mantissa times a power of two, so it falls on at most three limbs, added exactly (no
// rounding anywhere); the 31 spare bits of each limb take 2^30 such additions before the carries
// must be propagated (`normalise`, counted by `count_`). Two accumulators add limb by limb. So +=
// is exact, hence associative and commutative: the result does not depend on the order of the
// terms, on how they are cut into blocks, threads or ranks, and `value()` rounds the exact sum to
// the nearest double (ties to even) once. Why this one: the sums that feed back into a tlSph state
// (the momentum and D(J) projections) must come out the same on any number of ranks as serially
// (issue 21), the state is trivially copyable (globalSum gathers it as bytes), and an addition
// costs a few integer operations on three limbs; Demmel and Nguyen's reproducible summation would
// be faithful and order-independent but not correctly rounded, compensated (Kahan, Ogita-Rump-
// Oishi) sums are neither. Infinities and NaN are summed apart in IEEE arithmetic and win over any
// finite sum; an exact sum beyond the double range rounds to +-inf; a zero sum is +0.
class ExactSum {
public:
    static constexpr int limbs = 67;  // 32 x 67 = 2144 bits above 2^-1074: the range, then carries
    ExactSum& operator+=(double x) {
        const auto bits = std::bit_cast<std::uint64_t>(x);
        const int exponent = int(bits >> 52) & 0x7ff;
        if (exponent == 0x7ff) [[unlikely]] {
            special_ += x;
            return *this;
        }
        std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
        if (exponent) mantissa |= std::uint64_t(1) << 52;
        // mantissa x 2^(exponent - 1075), subnormals mantissa x 2^-1074: bit `at` above 2^-1074.
        const int at = exponent ? exponent - 1 : 0, k = at >> 5, shift = at & 31;
        const std::uint64_t low = mantissa << shift, high = shift ? mantissa >> (64 - shift) : 0;
        const std::int64_t sign = -std::int64_t(bits >> 63);  // 0 or -1: v -> (v ^ sign) - sign
        limb_[k] += (std::int64_t(low & 0xffffffff) ^ sign) - sign;
        limb_[k + 1] += (std::int64_t(low >> 32) ^ sign) - sign;
        limb_[k + 2] += (std::int64_t(high) ^ sign) - sign;
        low_ = std::min(low_, k), high_ = std::max(high_, k + 2);
        if (++count_ >= countLimit) [[unlikely]]
            normalise();
        return *this;
    }
    ExactSum& operator+=(const ExactSum& o) {
        for (int k = 0; k < limbs; ++k) limb_[k] += o.limb_[k];
        special_ += o.special_;
        count_ += o.count_;
        low_ = std::min(low_, o.low_), high_ = std::max(high_, o.high_);
        if (count_ >= countLimit) normalise();
        return *this;
    }
    // Adds x[0], ..., x[len - 1] (len <= chunk, a multiple of 4), exactly, the fast way: the terms
    // are split against three bins below the largest of them (ExtractScalar of Rump, Ogita and
    // Oishi 2008, "Accurate floating-point summation part I", SIAM J. Sci. Comput. 31, Lemma 3.3;
    // the bins of Demmel and Nguyen's reproducible summation): q = fl(fl(M + x) - M) with
    // M = 1.5 x 2^k is x rounded to a multiple of 2^(k-52), and x - q is exact. The parts of one
    // bin are multiples of its unit that sum exactly in a double (k leaves room for 256 of them),
    // in plain vectorisable floating point; the three bin sums then go into the limbs, and only
    // what lies more than 2^82 below the largest term (or a chunk of infinities, NaN, or values
    // beyond 2^±900) is added term by term. Overwrites x.
    static constexpr std::size_t chunk = 256;
    void add(double* x, std::size_t len);
    // The exact sum rounded to the nearest double (ties to even).
    double value() const;

private:
    // Each limb's magnitude stays below count_ x 2^32 (a normalised one: count_ 1): below 2^63 as
    // long as count_ < 2^31, and two accumulators under 2^30 each may be added.
    static constexpr std::int64_t countLimit = std::int64_t(1) << 30;
    // Carries upwards: limbs 0 to limbs - 2 in [0, 2^32), the top limb signed (0 or -1: no sum of
    // fewer than 2^64 doubles reaches 2^1088).
    void normalise();
    std::array<std::int64_t, limbs> limb_{};
    std::int64_t count_ = 0;
    double special_ = 0;           // the sum of the infinities and NaN
    int low_ = limbs, high_ = -1;  // the limbs ever touched: value() carries over these only
};

// N exact sums side by side (the exact counterpart of SumArray<N>), for GlobalReduce::exactSum.
template <int N>
struct ExactSums {
    std::array<ExactSum, N> s{};
    ExactSums& operator+=(const ExactSums& o) {
        for (int k = 0; k < N; ++k) s[k] += o.s[k];
        return *this;
    }
};

// How many global reductions this process has made. Counted so that a test can show that code
// meant to be rank-local (the neighbour search, the Verlet list) never reaches the MPI hook, where
// behind a rank-local early return it would deadlock; one relaxed increment per reduction.
inline std::atomic<std::uint64_t> globalReductionCount{0};

// The global hooks, over every rank (core/Communicator.hpp); on one process they return their
// argument. `T` for globalSum is anything summable by LocalReduce (double, size_t, SumArray<N>,
// a struct of doubles whose += also takes a max, such as an error norm's Linf): T must be
// trivially copyable. Every rank gathers every rank's partial and adds them in rank order
// itself, so all ranks hold the same bits and the result does not depend on MPI's reduction
// tree (the one order there is; it differs from the serial sum only in where the blocks of
// LocalReduce end, i.e. in the last bits).
template <class T>
T globalSum(const T& local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return local;
    static_assert(std::is_trivially_copyable_v<T>, "globalSum: T must be trivially copyable");
    std::vector<T> all(std::size_t(Communicator::size()));
    Communicator::allGather(&local, sizeof(T), all.data());
    T total{};
    for (const T& part : all) total += part;
    return total;
}
double globalMax(double local);
double globalMin(double local);
// One text for every rank, from the rank with the lowest `key`: each rank passes its candidate
// (key = e.g. the lowest global id among its bad particles, text = that one's description) or
// noMessageKey and an empty text when it has none; every rank returns the text of the lowest key
// (empty when no rank has one; equal keys: the lowest rank). So that an error found on some
// ranks is thrown with the same words on all: the keys are gathered, then the winner's text is
// broadcast. On one process the candidate is the answer.
inline constexpr std::int64_t noMessageKey = std::numeric_limits<std::int64_t>::max();
std::string globalFirstMessage(std::int64_t key, std::string text);
// The median (the upper one of an even count) of the values of every rank together: what a
// setting taken from "the median particle" (a Verlet skin) must be for every rank to agree with
// a serial run. Gathers every value: for set-up, not for a time loop.
double globalMedian(const std::vector<double>& local);
// Every rank's values, in rank order, on every rank (a selection's global ids). Collective.
std::vector<std::int64_t> globalConcatenation(const std::vector<std::int64_t>& local);

struct LocalReduce {
    static constexpr std::size_t blockSize = 4096;

    // Sum of term(i) for i in [0, n). `T` must support += and value-initialisation to zero.
    template <class T, class Term>
    static T sum(std::size_t n, Term&& term) {
        const std::size_t blocks = (n + blockSize - 1) / blockSize;
        std::vector<T> partial(blocks, T{});
#pragma omp parallel for schedule(static) if (n >= parallelThreshold)
        for (std::size_t b = 0; b < blocks; ++b) {
            T s{};
            const std::size_t end = std::min(n, (b + 1) * blockSize);
            for (std::size_t i = b * blockSize; i < end; ++i) s += term(i);
            partial[b] = s;
        }
        T total{};
        for (const T& p : partial) total += p;
        return total;
    }

    // The N exact sums of term(i) for i in [0, n) (ExactSum): term returns double (N = 1) or
    // SumArray<N>. The terms are gathered by chunks of ExactSum::chunk and added with
    // ExactSum::add; one accumulator per thread, added together in any order (exactly), so the
    // state is the same for any thread count; `exactSum` below rounds it.
    template <int N, class Term>
    static ExactSums<N> exactSums(std::size_t n, Term&& term) {
        constexpr std::size_t chunk = ExactSum::chunk;
        auto run = [&](ExactSums<N>& into, std::size_t c) {
            alignas(64) double buffer[N][chunk];
            const std::size_t begin = c * chunk, len = std::min(chunk, n - begin);
            for (std::size_t i = 0; i < len; ++i) {
                const auto t = term(begin + i);
                if constexpr (std::is_same_v<std::decay_t<decltype(t)>, SumArray<N>>)
                    for (int k = 0; k < N; ++k) buffer[k][i] = t.s[k];
                else
                    buffer[0][i] = double(t);
            }
            const std::size_t padded = (len + 3) & ~std::size_t(3);
            for (int k = 0; k < N; ++k) {
                for (std::size_t i = len; i < padded; ++i) buffer[k][i] = 0;
                into.s[k].add(buffer[k], padded);
            }
        };
        ExactSums<N> total;
        const std::size_t chunks = (n + chunk - 1) / chunk;
        if (n < parallelThreshold) {
            for (std::size_t c = 0; c < chunks; ++c) run(total, c);
            return total;
        }
#pragma omp parallel
        {
            ExactSums<N> mine;
#pragma omp for schedule(static) nowait
            for (std::size_t c = 0; c < chunks; ++c) run(mine, c);
#pragma omp critical(mfdynExactSums)
            total += mine;
        }
        return total;
    }
    // The correctly rounded sum of term(i): T double or SumArray<N>, as for sum. Independent of
    // the order of the terms (not only of the thread count), at about twice the cost of sum.
    template <class T, class Term>
    static T exactSum(std::size_t n, Term&& term) {
        return rounded<T>(exactSums<components<T>()>(n, std::forward<Term>(term)));
    }
    template <class T, int N>
    static T rounded(const ExactSums<N>& e) {
        if constexpr (std::is_same_v<T, double>) {
            return e.s[0].value();
        } else {
            T r;
            for (int k = 0; k < N; ++k) r.s[k] = e.s[k].value();
            return r;
        }
    }
    template <class T>
    static constexpr int components() {
        if constexpr (std::is_same_v<T, double>)
            return 1;
        else
            return int(std::tuple_size_v<decltype(T::s)>);
    }

    // -inf over no items.
    template <class Term>
    static double max(std::size_t n, Term&& term) {
        double m = -std::numeric_limits<double>::infinity();
#pragma omp parallel for reduction(max : m) schedule(static) if (n >= parallelThreshold)
        for (std::size_t i = 0; i < n; ++i) m = std::max(m, double(term(i)));
        return m;
    }

    // +inf over no items.
    template <class Term>
    static double min(std::size_t n, Term&& term) {
        double m = std::numeric_limits<double>::infinity();
#pragma omp parallel for reduction(min : m) schedule(static) if (n >= parallelThreshold)
        for (std::size_t i = 0; i < n; ++i) m = std::min(m, double(term(i)));
        return m;
    }
};

// Over the items of every rank: the local reduction, then the global hook. A rank with no items
// contributes zero, -inf or +inf, so it must still call (see above).
struct GlobalReduce {
    static constexpr std::size_t blockSize = LocalReduce::blockSize;

    template <class T, class Term>
    static T sum(std::size_t n, Term&& term) {
        return globalSum(LocalReduce::sum<T>(n, std::forward<Term>(term)));
    }
    // The correctly rounded sum over every rank (LocalReduce::exactSum): the same bits on any
    // number of ranks and threads as serially, whatever the decomposition. For the sums that feed
    // back into the state (a projection's multipliers); diagnostics may keep sum.
    template <class T, class Term>
    static T exactSum(std::size_t n, Term&& term) {
        constexpr int N = LocalReduce::components<T>();
        return LocalReduce::rounded<T>(globalSum(LocalReduce::exactSums<N>(n, std::forward<Term>(term))));
    }
    template <class Term>
    static double max(std::size_t n, Term&& term) {
        return globalMax(LocalReduce::max(n, std::forward<Term>(term)));
    }
    template <class Term>
    static double min(std::size_t n, Term&& term) {
        return globalMin(LocalReduce::min(n, std::forward<Term>(term)));
    }
    // The text of the lowest key over every rank (globalFirstMessage above).
    static std::string firstMessage(std::int64_t key, std::string text) {
        return globalFirstMessage(key, std::move(text));
    }
};

}  // namespace mfdyn
