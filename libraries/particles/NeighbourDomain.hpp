#pragma once
// The box a neighbour search bins particles in, and its periodic directions.
//
// Without bounds the box is taken from the particles at each build. With bounds, a particle
// outside them in a non-periodic direction is still found (it is binned in the edge cell); in a
// periodic direction [lo, hi) it is an image of the particle wrapped into the box.
//
// separation() is the one definition of x_i - x_j (the minimum image in periodic directions):
// the search decides neighbourhood with it, so a caller using it sees exactly the distances the
// list was built from.
#include "core/Tensor.hpp"

#include <array>
#include <cmath>

namespace mfdyn {

template <int Dim>
class NeighbourDomain {
public:
    // Unbounded: the box is taken from the particles, no direction is periodic.
    NeighbourDomain() = default;
    // A given box; periodic[d] makes direction d periodic over [lo(d), hi(d)).
    NeighbourDomain(const Vector<Dim>& lo, const Vector<Dim>& hi, const std::array<bool, Dim>& periodic = {});

    bool bounded() const { return bounded_; }
    const Vector<Dim>& lo() const { return lo_; }
    const Vector<Dim>& hi() const { return hi_; }
    bool periodic(int direction) const { return periodic_[direction]; }
    bool anyPeriodic() const { return anyPeriodic_; }
    // hi - lo in periodic directions, 0 in the others.
    double period(int direction) const { return period_[direction]; }

    // x_i - x_j, folded to the minimum image in periodic directions. Antisymmetric bit for bit
    // (nearbyint is odd), so symmetric pair criteria give symmetric lists.
    Vector<Dim> separation(const Vector<Dim>& xi, const Vector<Dim>& xj) const {
        Vector<Dim> d = xi - xj;
        if (anyPeriodic_)
            for (int k = 0; k < Dim; ++k)
                if (periodic_[k]) d[k] -= period_[k] * std::nearbyint(d[k] / period_[k]);
        return d;
    }

    // x moved into [lo, hi) along the periodic directions.
    Vector<Dim> wrap(const Vector<Dim>& x) const;

private:
    bool bounded_ = false;
    bool anyPeriodic_ = false;
    Vector<Dim> lo_ = Vector<Dim>::Zero();
    Vector<Dim> hi_ = Vector<Dim>::Zero();
    std::array<bool, Dim> periodic_{};
    std::array<double, Dim> period_{};
};

}  // namespace mfdyn
