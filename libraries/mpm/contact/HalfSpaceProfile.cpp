// The half-space profile of a shape function (issue 18, the float's waterline; used by
// MultiFieldContact's `surfaceGap` check).
//
// A body filling the half-space r < s (r the coordinate along its outward normal from a node,
// in cells) puts at that node the mass m_I = rho int_{r<s} N dV and the first moment
// sum_p N m_p (x_p - x_I) . n = rho int_{r<s} r N dV. For a tensor product N(x) = prod N1(x_d)
// and a normal along an axis, the transverse factors cancel in the ratio, so the nodal centre of
// mass is
//
//     c(s) = int_{-R}^{s} r N1(r) dr / int_{-R}^{s} N1(r) dr,        R the support's half-width,
//
// whatever lies beyond the support across the normal: unlike the nodal volume (the volume
// check, which a free surface within reach leaves short of dx^d), the centre along the normal
// does not see a waterline that cuts the support transversely. c rises monotonically from -R
// (s -> -R) to 0 (s >= R, the whole support filled; N1 is even). A second body filling r > s'
// has, by the same symmetry, the centre -c(-s'). So from the two bodies' nodal centres c_a, c_b
// along the pair normal, their surfaces are s_a = c^-1(c_a) and s_b = -c^-1(-c_b), and the gap
// between them s_b - s_a (cells): 0 when they touch, negative when they overlap.
//
// Quadratic B-spline: c(0) = -(int_0^{1/2} r (3/4 - r^2) dr + int_{1/2}^{3/2} r (3/2 - r)^2/2 dr)
// / (1/2) = -(5/64 + 1/8) / (1/2) = -13/32 (HalfSpaceProfileTest). Linear hat: c(0) = -1/3.
// Limits: an oblique normal sees the projection of the tensor product, not N1 (its first
// absolute moment differs by about 2% of a cell at 45 degrees for the quadratic B-spline, as the
// projected sum of uniform variables shows); the folded functions at the grid's edges and a body
// thinner than the support (a corner, an apex) are not half-spaces.
#include "mpm/contact/HalfSpaceProfile.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

namespace mfdyn {

template <int Dim>
HalfSpaceProfile::HalfSpaceProfile(const ShapeFunction<Dim>& shape) {
    reach_ = shape.supportHalfWidth();
    constexpr int samples = 4000;  // trapezoid steps over [-R, R]: c to about 1e-7 of a cell
    step_ = 2 * reach_ / samples;
    // One axis of the shape function at the node `middle` of a grid far wider than the support,
    // so that no folded edge function enters; uGIMP at a quarter-cell half-size (2 x 2 points).
    constexpr std::int64_t cells = 64, middle = 32;
    std::array<std::complex<double>, 8> N{}, dN{};
    const int count = shape.nodesPerAxis();
    auto weight = [&](double r) {
        const std::int64_t first =
            shape.axisWeights(std::complex<double>(double(middle) + r, 0.0), 0.25, cells,
                              std::span(N.data(), count), std::span(dN.data(), count));
        const std::int64_t k = middle - first;
        return k >= 0 && k < count ? N[std::size_t(k)].real() : 0.0;
    };
    centre_.assign(samples + 1, -reach_);
    double m0 = 0, m1 = 0, previous = weight(-reach_);
    for (int k = 1; k <= samples; ++k) {
        const double r0 = -reach_ + (k - 1) * step_, r1 = -reach_ + k * step_, w = weight(r1);
        m0 += 0.5 * step_ * (previous + w);
        m1 += 0.5 * step_ * (r0 * previous + r1 * w);
        previous = w;
        if (m0 > 0) centre_[std::size_t(k)] = std::max(m1 / m0, centre_[std::size_t(k) - 1]);
    }
}

double HalfSpaceProfile::centre(double s) const {
    if (s <= -reach_) return -reach_;
    if (s >= reach_) return centre_.back();
    const double u = (s + reach_) / step_;
    const std::size_t k = std::min(std::size_t(u), centre_.size() - 2);
    const double f = u - double(k);
    return (1 - f) * centre_[k] + f * centre_[k + 1];
}

double HalfSpaceProfile::surface(double c) const {
    if (!(c > centre_.front())) return -reach_;
    if (c >= centre_.back()) return reach_;
    // The first tabulated centre above c, then linear between it and the one before.
    const auto it = std::upper_bound(centre_.begin(), centre_.end(), c);
    const std::size_t k = std::size_t(it - centre_.begin());
    const double c0 = centre_[k - 1], c1 = centre_[k];
    const double f = c1 > c0 ? (c - c0) / (c1 - c0) : 0.0;
    return -reach_ + (double(k - 1) + f) * step_;
}

template HalfSpaceProfile::HalfSpaceProfile(const ShapeFunction<1>&);
template HalfSpaceProfile::HalfSpaceProfile(const ShapeFunction<2>&);
template HalfSpaceProfile::HalfSpaceProfile(const ShapeFunction<3>&);

}  // namespace mfdyn
