#include "particles/VerletList.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mfdyn {

template <int Dim>
VerletList<Dim>::VerletList(double skin, NeighbourDomain<Dim> domain, NeighbourSearchOptions options,
                            VerletPolicy policy)
    : skin_(skin), policy_(policy), search_(std::move(domain), options) {
    if (!(std::isfinite(skin) && skin >= 0))
        throw Error("VerletList: the skin must be finite and non-negative, found " + std::to_string(skin));
}

template <int Dim>
bool VerletList<Dim>::update(const std::vector<Vector<Dim>>& positions,
                             const std::vector<double>& supportRadius) {
    if (supportRadius.size() != positions.size())
        throw Error("VerletList: " + std::to_string(supportRadius.size()) + " support radii for " +
                    std::to_string(positions.size()) + " particles");
    if (!needsRebuild(positions, supportRadius.data(), false)) return false;
    rebuild(positions, supportRadius.data(), false);
    if (rowKey_) candidates_.sortRowsBy(rowKey_->data());
    return true;
}

template <int Dim>
bool VerletList<Dim>::update(const std::vector<Vector<Dim>>& positions, double supportRadius) {
    if (!needsRebuild(positions, &supportRadius, true)) return false;
    rebuild(positions, &supportRadius, true);
    if (rowKey_) candidates_.sortRowsBy(rowKey_->data());
    return true;
}

template <int Dim>
double VerletList<Dim>::maxDisplacement(const std::vector<Vector<Dim>>& positions) const {
    if (!built_ || positions.size() != builtPosition_.size()) return 0.0;
    const NeighbourDomain<Dim>& domain = search_.domain();
    // Max is exact, so LocalReduce::max is the same for any thread count. Local: the rebuild is
    // this rank's decision about its own list (behind the early return above, a global
    // reduction would leave the other ranks waiting).
    return std::sqrt(LocalReduce::max(positions.size(), [&](std::size_t i) {
        return domain.separation(positions[i], builtPosition_[i]).squaredNorm();
    }));
}

template <int Dim>
bool VerletList<Dim>::needsRebuild(const std::vector<Vector<Dim>>& positions, const double* radius,
                                   bool constantRadius) {
    fast_ = 0;
    if (!built_ || positions.size() != builtPosition_.size()) return true;
    const std::size_t n = positions.size();
    if (n == 0) return false;
    if (policy_ == VerletPolicy::checked) {
        if (fastPairsMissing(positions, radius, constantRadius)) return true;
        checked_ += fast_ > 0;
        return false;
    }
    const double growth =
        constantRadius ? radius[0] - builtRadius_[0]
                       : LocalReduce::max(n, [&](std::size_t i) { return radius[i] - builtRadius_[i]; });
    return 2 * maxDisplacement(positions) + std::max(growth, 0.0) > skin_;
}

template <int Dim>
bool VerletList<Dim>::fastPairsMissing(const std::vector<Vector<Dim>>& positions, const double* radius,
                                       bool constantRadius) {
    using Index = NeighbourList::Index;
    const std::size_t n = positions.size();
    const NeighbourDomain<Dim>& domain = search_.domain();
    auto r = [&](std::size_t i) { return constantRadius ? radius[0] : radius[i]; };
    displacement_.resize(n);
    parallelFor(n, [&](std::size_t i) {
        displacement_[i] = std::sqrt(domain.separation(positions[i], builtPosition_[i]).squaredNorm());
    });
    // Slow: D_i <= skin/2 and D_i + skin/2 <= skin - G_i. For two slow particles D_i + D_j <=
    // skin - G_i (and - G_j): no pair between them can be missing (see the header). A position
    // or radius that is not finite is left to the search to report: rebuild.
    const double half = 0.5 * skin_;
    fastParticles_.clear();
    double maxD = half, maxR = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = displacement_[i], ri = r(i);
        if (!(std::isfinite(d) && std::isfinite(ri))) return true;
        maxR = std::max(maxR, ri);
        if (d <= half && d + half <= skin_ - (ri - builtRadius_[i])) continue;
        fastParticles_.push_back(Index(i));
        maxD = std::max(maxD, d);
    }
    fast_ = fastParticles_.size();
    if (fast_ == 0) return false;

    // A particle that is a neighbour of fast particle f now was, at the build, within
    // max(r_f, r_j) + D_j <= maxR + maxD of f's position now: one query of the last build's
    // cells finds it. Each query scans about (reach / build radius)^Dim rows' worth of
    // candidates; past an eighth of the particles' worth (plus a few rows: a rebuild has its
    // fixed costs too) a rebuild is cheaper.
    const double reach = maxR + maxD;
    const double built = builtMaxRadius_ + skin_;
    const double scale = built > 0 ? std::pow(reach / built, Dim) : std::numeric_limits<double>::infinity();
    if (!(double(fast_) * scale <= 0.125 * double(n) + 16.0)) return true;

    // Sequential over the fast particles: few by construction, and the answer (any pair
    // missing) cannot depend on an order. mark_[j] == tag: j is in the row being tested.
    const PairCriterion criterion = search_.options().criterion;
    const CellBins<Dim>& bins = search_.bins();
    if (mark_.size() != n) mark_.assign(n, 0), tag_ = 0;
    for (const Index f : fastParticles_) {
        if (tag_ == std::numeric_limits<std::uint32_t>::max())
            std::fill(mark_.begin(), mark_.end(), 0), tag_ = 0;
        ++tag_;
        for (const Index j : candidates_[f]) mark_[j] = tag_;
        const Vector<Dim>& xf = positions[f];
        const double rf2 = r(f) * r(f);
        bool missing = false;
        bins.forEachCandidate(xf, reach, [&](Index j) {
            if (j == f) return;
            const double d2 = domain.separation(xf, positions[j]).squaredNorm();
            const double rj2 = r(j) * r(j);
            if (criterion == PairCriterion::gather) {
                // Rows are not symmetric: f's row needs j within r_f, j's row f within r_j.
                if (d2 < rf2 && mark_[j] != tag_) missing = true;
                if (d2 < rj2) {
                    const auto row = candidates_[j];
                    missing = missing || std::find(row.begin(), row.end(), f) == row.end();
                }
            } else {
                // Symmetric criteria build symmetric rows: f's row answers for both.
                const bool in =
                    criterion == PairCriterion::either ? d2 < std::max(rf2, rj2) : d2 < std::min(rf2, rj2);
                if (in && mark_[j] != tag_) missing = true;
            }
        });
        if (missing) return true;
    }
    return false;
}

template <int Dim>
void VerletList<Dim>::rebuild(const std::vector<Vector<Dim>>& positions, const double* radius,
                              bool constantRadius) {
    const std::size_t n = positions.size();
    if (constantRadius) {
        builtRadius_.assign(n, radius[0]);
        search_.bin(positions, radius[0] + skin_);
    } else {
        builtRadius_.assign(radius, radius + n);
        std::vector<double> searchRadius(n);
        parallelFor(n, [&](std::size_t i) { searchRadius[i] = radius[i] + skin_; });
        search_.bin(positions, searchRadius);
    }
    candidates_ = search_.list(std::move(candidates_));  // the previous list's memory refilled
    builtPosition_ = positions;
    builtMaxRadius_ = std::max(0.0, search_.maxRadius() - skin_);
    built_ = true;
    fast_ = 0;
    ++rebuilds_;
}

template class VerletList<1>;
template class VerletList<2>;
template class VerletList<3>;

}  // namespace mfdyn
