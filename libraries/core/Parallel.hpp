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
// are added in block order.
#include "core/Communicator.hpp"

#include <algorithm>
#include <array>
#include <atomic>
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
