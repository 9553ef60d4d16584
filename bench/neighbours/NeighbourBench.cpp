// Neighbour-list build for a jittered cubic lattice (default 10^6 particles, ~50 neighbours
// each): mfdyn's cell list on 1 and 2 threads against CGAL's kd-tree (build plus one fixed-radius
// query per particle) on the same cloud. Every method's list is checked against the kd-tree's.
// The only translation unit of the benchmarks that includes CGAL.
//
// Usage: neighbourBench [particles=1000000] [neighbours=50] [repeats=3] [maxThreads=2]
#include "particles/NeighbourSearch.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <omp.h>
#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace mfdyn;

namespace {

using Kernel = CGAL::Epick;
using Point = Kernel::Point_3;
using PointMap = CGAL::Pointer_property_map<Point>::const_type;
using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<Kernel>>;
using Tree = CGAL::Kd_tree<Traits>;
using Sphere = CGAL::Fuzzy_sphere<Traits>;

double seconds(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Kd-tree rows, each sorted; the list in CSR like ours so that both pay for storing it.
NeighbourList kdTreeList(const std::vector<Point>& points, double radius) {
    const std::size_t n = points.size();
    const PointMap map = CGAL::make_property_map(points);
    Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n),
              Tree::Splitter(), Traits(map));
    tree.build();  // built before the parallel queries: search() would build it lazily, unsafely
    std::vector<std::vector<NeighbourList::Index>> rows(n);
#pragma omp parallel
    {
        std::vector<std::size_t> found;
#pragma omp for schedule(dynamic, 1024)
        for (std::size_t i = 0; i < n; ++i) {
            found.clear();
            tree.search(std::back_inserter(found), Sphere(points[i], radius, 0.0, Traits(map)));
            for (std::size_t j : found)
                if (j != i) rows[i].push_back(NeighbourList::Index(j));
            std::sort(rows[i].begin(), rows[i].end());
        }
    }
    std::vector<std::size_t> offsets(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] = offsets[i] + rows[i].size();
    std::vector<NeighbourList::Index> indices(offsets[n]);
    for (std::size_t i = 0; i < n; ++i)
        std::copy(rows[i].begin(), rows[i].end(), indices.begin() + offsets[i]);
    return NeighbourList(std::move(offsets), std::move(indices));
}

struct Result {
    std::string method;
    int threads;
    double seconds;
    double cpuSeconds;  // all threads: on a shared machine the fairer measure of the work done
};

}  // namespace

int main(int argc, char** argv) {
    const std::size_t requested = argc > 1 ? std::stoul(argv[1]) : 1000000;
    const double neighbours = argc > 2 ? std::stod(argv[2]) : 50.0;
    const int repeats = argc > 3 ? std::stoi(argv[3]) : 3;
    const int maxThreads = argc > 4 ? std::stoi(argv[4]) : 2;

    // Unit lattice spacing, each coordinate jittered by up to a quarter spacing; the radius
    // whose sphere holds `neighbours` particles besides the centre at unit density.
    const int side = int(std::lround(std::cbrt(double(requested))));
    const std::size_t n = std::size_t(side) * side * side;
    const double radius = std::cbrt(3.0 * (neighbours + 1.0) / (4.0 * std::numbers::pi));
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> jitter(-0.25, 0.25);
    std::vector<Vector<3>> x(n);
    std::vector<Point> points(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = Vector<3>(double(i % side), double(i / side % side), double(i / side / side)) +
               Vector<3>(jitter(rng), jitter(rng), jitter(rng));
        points[i] = Point(x[i][0], x[i][1], x[i][2]);
    }
    // The same cloud stored in cell order, as a run keeps its particles (NeighbourSearch::order).
    std::vector<Vector<3>> xSorted = x;
    {
        NeighbourSearch<3> search;
        search.bin(x, radius);
        search.applyOrder(xSorted);
    }
    std::vector<double> h(n);
    for (std::size_t i = 0; i < n; ++i) h[i] = radius * (0.9 + 0.2 * std::abs(std::sin(0.37 * double(i))));
    std::printf("%zu particles, radius %.4f, %d repeats (minimum reported)\n", n, radius, repeats);

    std::vector<Result> results;
    auto run = [&](const std::string& method, int threads, const std::function<NeighbourList()>& build) {
        omp_set_num_threads(threads);
        double best = 1e300, bestCpu = 1e300;
        NeighbourList list;
        for (int r = 0; r < repeats; ++r) {
            const std::clock_t cpuStart = std::clock();
            best = std::min(best, seconds([&] { list = build(); }));
            bestCpu = std::min(bestCpu, double(std::clock() - cpuStart) / CLOCKS_PER_SEC);
        }
        results.push_back({method, threads, best, bestCpu});
        std::printf("  %-34s %d thread(s): %.3f s (cpu %.3f s), %.1f neighbours/particle\n", method.c_str(),
                    threads, best, bestCpu, double(list.pairCount()) / double(n));
        std::fflush(stdout);
        return list;
    };
    auto equalRows = [&](const NeighbourList& a, const NeighbourList& b,
                         const std::vector<NeighbourList::Index>* order) {
        // a in the original numbering; b either too, or in the cell order `order`.
        std::vector<NeighbourList::Index> rank(n);
        for (std::size_t k = 0; k < n; ++k) rank[order ? (*order)[k] : k] = NeighbourList::Index(k);
        for (std::size_t i = 0; i < n; ++i) {
            std::vector<NeighbourList::Index> row;
            for (auto j : a[i]) row.push_back(rank[j]);
            std::sort(row.begin(), row.end());
            auto other = b[rank[i]];
            std::vector<NeighbourList::Index> sortedOther(other.begin(), other.end());
            std::sort(sortedOther.begin(), sortedOther.end());
            if (row != sortedOther) return false;
        }
        return true;
    };

    std::vector<NeighbourList> kd;
    for (int threads = 1; threads <= maxThreads; ++threads)
        kd.push_back(run("CGAL kd-tree", threads, [&] { return kdTreeList(points, radius); }));

    NeighbourSearch<3> search;
    NeighbourSearchOptions sortedRows;
    sortedRows.sortRows = true;
    NeighbourSearch<3> sortingSearch({}, sortedRows);
    NeighbourSearch<3> variableSearch;
    bool allMatch = true;
    std::vector<NeighbourList::Index> sortedOrder;
    {
        NeighbourSearch<3> s;
        s.bin(x, radius);
        sortedOrder = s.order();
    }
    for (int threads = 1; threads <= maxThreads; ++threads) {
        const NeighbourList a = run("cell list", threads, [&] { return search.build(x, radius); });
        allMatch = allMatch && equalRows(kd[0], a, nullptr);
        const NeighbourList b =
            run("cell list, rows sorted", threads, [&] { return sortingSearch.build(x, radius); });
        allMatch = allMatch && b == kd[0];
        const NeighbourList c =
            run("cell list, cell-ordered particles", threads, [&] { return search.build(xSorted, radius); });
        allMatch = allMatch && equalRows(kd[0], c, &sortedOrder);
        run("cell list, variable h, either", threads, [&] { return variableSearch.build(x, h); });
    }
    std::printf("cell-list lists equal the kd-tree's: %s\n\n", allMatch ? "yes" : "NO");

    // Speed-ups are against the kd-tree on the same number of threads. CPU time sums all threads:
    // on a shared machine it is the fairer measure of the work done.
    std::printf(
        "| method | threads | seconds | s per 10^6 particles per core | speed-up vs kd-tree "
        "| cpu seconds | cpu s per 10^6 particles | cpu speed-up vs kd-tree |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
    const double millions = double(n) / 1e6;
    for (const Result& r : results) {
        const Result& kdTree = results[std::size_t(r.threads - 1)];
        std::printf("| %s | %d | %.3f | %.3f | %.1f | %.3f | %.3f | %.1f |\n", r.method.c_str(), r.threads,
                    r.seconds, r.seconds * r.threads / millions, kdTree.seconds / r.seconds, r.cpuSeconds,
                    r.cpuSeconds / millions, kdTree.cpuSeconds / r.cpuSeconds);
    }
    return allMatch ? EXIT_SUCCESS : EXIT_FAILURE;
}
