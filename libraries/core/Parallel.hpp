#pragma once
// Loops and reductions. Every particle loop goes through parallelFor, every global reduction
// through Reduce: OpenMP lives here and nowhere in solver code, and an MPI build replaces the
// bodies of Reduce::sum/max/min with an MPI_Allreduce after the local part.
//
// Reductions are deterministic for any thread count: the range is cut into fixed blocks
// (independent of the number of threads), each block is summed in order, and the block sums
// are added in block order.
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
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

// A fixed-size array of sums for Reduce::sum (which value-initialises its type to zero; Eigen
// vectors are not): Reduce::sum<SumArray<3>>(n, [&](std::size_t i) { SumArray<3> t; ...; return t; }).
template <int N>
struct SumArray {
    std::array<double, N> s{};
    SumArray& operator+=(const SumArray& o) {
        for (int k = 0; k < N; ++k) s[k] += o.s[k];
        return *this;
    }
};

struct Reduce {
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
        return global(total);
    }

    template <class Term>
    static double max(std::size_t n, Term&& term) {
        double m = -std::numeric_limits<double>::infinity();
#pragma omp parallel for reduction(max : m) schedule(static) if (n >= parallelThreshold)
        for (std::size_t i = 0; i < n; ++i) m = std::max(m, double(term(i)));
        return globalMax(m);
    }

    template <class Term>
    static double min(std::size_t n, Term&& term) {
        double m = std::numeric_limits<double>::infinity();
#pragma omp parallel for reduction(min : m) schedule(static) if (n >= parallelThreshold)
        for (std::size_t i = 0; i < n; ++i) m = std::min(m, double(term(i)));
        return globalMin(m);
    }

    // The hooks an MPI build fills in; on one process they return their argument.
    template <class T>
    static T global(const T& local) {
        return local;
    }
    static double globalMax(double local) {
        return local;
    }
    static double globalMin(double local) {
        return local;
    }
};

}  // namespace mfdyn
