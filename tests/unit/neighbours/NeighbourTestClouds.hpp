#pragma once
// Point clouds and the brute-force reference shared by the neighbour-search tests.
#include "particles/NeighbourDomain.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/NeighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace mfdyn::test {

using Rows = std::vector<std::vector<NeighbourList::Index>>;

template <int Dim>
std::vector<Vector<Dim>> randomCloud(std::size_t n, unsigned seed, double lo = 0.0, double hi = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<Vector<Dim>> x(n);
    for (auto& p : x)
        for (int d = 0; d < Dim; ++d) p[d] = u(rng);
    return x;
}

// A Cartesian lattice of `perSide` points per direction and the given spacing, starting at 0.
template <int Dim>
std::vector<Vector<Dim>> latticeCloud(int perSide, double spacing) {
    std::size_t n = 1;
    for (int d = 0; d < Dim; ++d) n *= std::size_t(perSide);
    std::vector<Vector<Dim>> x(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t rest = i;
        for (int d = 0; d < Dim; ++d) {
            x[i][d] = spacing * double(rest % std::size_t(perSide));
            rest /= std::size_t(perSide);
        }
    }
    return x;
}

// Gaussian clusters of very different widths plus a few far outliers: dense spots in a mostly
// empty box, the case a uniform grid handles worst.
template <int Dim>
std::vector<Vector<Dim>> clusteredCloud(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    const int clusters = 5;
    std::vector<Vector<Dim>> centre(clusters);
    std::vector<double> width(clusters);
    for (int c = 0; c < clusters; ++c) {
        for (int d = 0; d < Dim; ++d) centre[c][d] = u(rng);
        width[c] = 0.003 * std::pow(10.0, 2.0 * u(rng));
    }
    std::vector<Vector<Dim>> x(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (i % 97 == 0) {
            for (int d = 0; d < Dim; ++d) x[i][d] = 1e3 * (u(rng) - 0.5);
            continue;
        }
        const int c = int(i % clusters);
        for (int d = 0; d < Dim; ++d) x[i][d] = centre[c][d] + width[c] * g(rng);
    }
    return x;
}

// Radii varying by a factor of three between particles.
inline std::vector<double> variableRadii(std::size_t n, double base, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    std::vector<double> r(n);
    for (auto& ri : r) ri = base * u(rng);
    return r;
}

template <int Dim>
bool pairMatches(const NeighbourDomain<Dim>& domain, const std::vector<Vector<Dim>>& x,
                 const std::vector<double>& r, std::size_t i, std::size_t j, PairCriterion criterion) {
    const double d2 = domain.separation(x[i], x[j]).squaredNorm();
    const double ri2 = r[i] * r[i], rj2 = r[j] * r[j];
    switch (criterion) {
        case PairCriterion::either:
            return d2 < ri2 || d2 < rj2;
        case PairCriterion::both:
            return d2 < ri2 && d2 < rj2;
        case PairCriterion::gather:
            return d2 < ri2;
    }
    return false;
}

// Every pair checked, rows by increasing index.
template <int Dim>
Rows bruteForce(const NeighbourDomain<Dim>& domain, const std::vector<Vector<Dim>>& x,
                const std::vector<double>& r, PairCriterion criterion, bool includeSelf) {
    Rows rows(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = 0; j < x.size(); ++j)
            if (i == j ? includeSelf : pairMatches(domain, x, r, i, j, criterion))
                rows[i].push_back(NeighbourList::Index(j));
    return rows;
}

inline Rows sortedRows(const NeighbourList& list) {
    Rows rows(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        rows[i].assign(list[i].begin(), list[i].end());
        std::sort(rows[i].begin(), rows[i].end());
    }
    return rows;
}

inline std::size_t meanRowSize(const Rows& rows) {
    std::size_t total = 0;
    for (const auto& row : rows) total += row.size();
    return rows.empty() ? 0 : total / rows.size();
}

}  // namespace mfdyn::test
