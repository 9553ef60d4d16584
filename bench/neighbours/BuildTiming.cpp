// The neighbour-list build alone, timed in CPU seconds of the calling thread (fair on a shared
// machine), on the cloud of neighbourBench (a jittered cubic lattice, ~49 neighbours), beside
// the memory-bound floor of the same output: writing the list's bytes (4 per pair) and the row
// offsets (8 per particle) into memory already mapped, and into fresh memory (page faults and
// the kernel's zeroing, which a list built anew pays). compare.sh builds it against two trees
// and runs them side by side. It prints a hash of the list (order included): equal hashes, equal
// lists.
//
// Usage: buildTiming [particles=1000000] [repeats=3]
#include "particles/NeighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace mfdyn;

namespace {

double cpuSeconds(const std::function<void()>& f) {
    timespec a, b;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    f();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    return double(b.tv_sec - a.tv_sec) + 1e-9 * double(b.tv_nsec - a.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t requested = argc > 1 ? std::stoul(argv[1]) : 1000000;
    const int repeats = argc > 2 ? std::stoi(argv[2]) : 3;
    const int side = int(std::lround(std::cbrt(double(requested))));
    const std::size_t n = std::size_t(side) * side * side;
    const double radius = std::cbrt(3.0 * (50.0 + 1.0) / (4.0 * std::numbers::pi));
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::vector<Vector<3>> x(n);
    for (std::size_t i = 0; i < n; ++i)
        x[i] = Vector<3>(double(i % side), double(i / side % side), double(i / side / side)) +
               Vector<3>(jitter(rng), jitter(rng), jitter(rng));

    NeighbourSearch<3> search;
    NeighbourList list;
    std::vector<double> fresh, reused;
    for (int r = 0; r < repeats; ++r) {
        list = NeighbourList();
        fresh.push_back(cpuSeconds([&] { list = search.build(x, radius); }));
    }
#ifdef MFDYN_BENCH_REUSE
    // The Verlet list's rebuild: the previous list's memory refilled.
    for (int r = 0; r < repeats; ++r)
        reused.push_back(cpuSeconds([&] {
            search.bin(x, radius);
            list = search.list(std::move(list));
        }));
#endif
    std::uint64_t hash = 1469598103934665603ull;
    for (auto v : list.indices()) hash = (hash ^ v) * 1099511628211ull;
    for (auto v : list.offsets()) hash = (hash ^ v) * 1099511628211ull;

    // The floor: the list's bytes written once, as a build must at least do.
    const std::size_t pairs = list.pairCount();
    std::vector<double> floorMapped, floorFresh;
    {
        std::vector<NeighbourList::Index> indices(pairs, 1);
        std::vector<std::size_t> offsets(n + 1, 1);
        for (int r = 0; r < repeats; ++r)
            floorMapped.push_back(cpuSeconds([&] {
                std::fill(indices.begin(), indices.end(), NeighbourList::Index(r));
                std::fill(offsets.begin(), offsets.end(), std::size_t(r));
            }));
        volatile std::uint64_t sink = indices[pairs / 2] + offsets[n / 2];
        (void)sink;
    }
    for (int r = 0; r < repeats; ++r)
        floorFresh.push_back(cpuSeconds([&] {
            std::vector<NeighbourList::Index> indices(pairs);
            std::vector<std::size_t> offsets(n + 1);
            std::fill(indices.begin(), indices.end(), NeighbourList::Index(r + 1));
            std::fill(offsets.begin(), offsets.end(), std::size_t(r + 1));
            volatile std::uint64_t sink = indices[pairs / 2] + offsets[n / 2];
            (void)sink;
        }));

    const double millions = double(n) / 1e6;
    std::printf("%zu particles, %.2f neighbours each, list hash %016llx; CPU s per 10^6 particles, median of %d\n",
                n, double(pairs) / double(n), (unsigned long long)hash, repeats);
    std::printf("  build (new list)          %.3f\n", median(fresh) / millions);
    if (!reused.empty()) std::printf("  build (previous reused)   %.3f\n", median(reused) / millions);
    std::printf("  floor: write list, mapped %.3f\n", median(floorMapped) / millions);
    std::printf("  floor: write list, fresh  %.3f\n", median(floorFresh) / millions);
    return 0;
}
