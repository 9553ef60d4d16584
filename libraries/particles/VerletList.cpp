#include "particles/VerletList.hpp"

#include <cmath>

namespace mfdyn {

template <int Dim>
VerletList<Dim>::VerletList(double skin, NeighbourDomain<Dim> domain, NeighbourSearchOptions options)
    : skin_(skin), search_(std::move(domain), options) {
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
    return true;
}

template <int Dim>
bool VerletList<Dim>::update(const std::vector<Vector<Dim>>& positions, double supportRadius) {
    if (!needsRebuild(positions, &supportRadius, true)) return false;
    rebuild(positions, &supportRadius, true);
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
                                   bool constantRadius) const {
    if (!built_ || positions.size() != builtPosition_.size()) return true;
    const std::size_t n = positions.size();
    if (n == 0) return false;
    const double growth =
        constantRadius ? radius[0] - builtRadius_[0]
                       : LocalReduce::max(n, [&](std::size_t i) { return radius[i] - builtRadius_[i]; });
    return 2 * maxDisplacement(positions) + std::max(growth, 0.0) > skin_;
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
    candidates_ = search_.list();
    builtPosition_ = positions;
    built_ = true;
    ++rebuilds_;
}

template class VerletList<1>;
template class VerletList<2>;
template class VerletList<3>;

}  // namespace mfdyn
