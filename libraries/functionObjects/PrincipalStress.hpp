#pragma once
// The principal stresses of the finite pointset method's particles (FpmSolver.hpp): the Cauchy
// stress sigma = S - p I from the symmetric deviator `deviatoricStress` (S, a tensor of the run's
// dimension) and the scalar `pressure` (p). Its largest eigenvalue is the maximal principal
// stress sigma_1, its smallest sigma_3 (compression negative).
//
// Below 3D the stored deviator is in-plane and its out-of-plane components are zero: S_zz = 0,
// so sigma_zz = -p (S_zz = -tr S is not assumed: fpmSolid's 2D runs carry the deviator in-plane
// only, whether its strength law weighs the trace as a 2D or 3D one). Then sigma's eigenvalues
// are those of the stored block of S, shifted by -p, and -p itself: in 2D
//
//     sigma_1 = max(m + R, 0) - p,  sigma_3 = min(m - R, 0) - p,
//     m = (S_xx + S_yy)/2,  R = sqrt(((S_xx - S_yy)/2)^2 + S_xy^2),
//
// and in 1D sigma_1 = max(S_xx, 0) - p, sigma_3 = min(S_xx, 0) - p. In 3D the eigenvalues of
// the symmetric 3x3 S come from Eigen's SelfAdjointEigenSolver<Matrix3d> with EigenvaluesOnly
// (its iterative tridiagonal QR, not computeDirect's closed form): on tensors with two nearly
// equal eigenvalues, rotated at random, computeDirect was off by up to 2.3e-8 of |S| (the acos
// of the trigonometric form loses half the digits near a double root) and the iterative solver
// by 6e-15, at 0.45 microseconds a particle against 0.09: the cost of a write, not of a step.
// The eigenvalues are those of S, and p is subtracted after: a large pressure does not swamp
// a small deviator.
//
// fieldMinMax offers the derived fields `maxPrincipalStress` and `minPrincipalStress` from them
// (FieldMinMax.cpp).
#include "particles/FieldStore.hpp"

#include <array>
#include <string>

namespace mfdyn {

// The eigenvalues of the symmetric 3x3 (xx yy zz xy yz xz), ascending.
std::array<double, 3> symmetricEigenvalues(double xx, double yy, double zz, double xy, double yz, double xz);

struct PrincipalStresses {
    double min, max;  // sigma_3 and sigma_1
};

// Reads sigma = S - p I of particle i from the fields above.
class PrincipalStressField {
public:
    static constexpr const char* maxName = "maxPrincipalStress";
    static constexpr const char* minName = "minPrincipalStress";
    static bool isName(const std::string& field) { return field == maxName || field == minName; }
    // The fields it needs, or an InputError naming the missing one (`where`: the caller's context,
    // `field`: the derived field asked for, for the message).
    PrincipalStressField(const FieldStore& store, const std::string& where,
                         const std::string& field = maxName);
    PrincipalStresses operator()(std::size_t i) const;

private:
    const FieldBase* S_;
    const FieldBase* p_;
    int dim_;
};

}  // namespace mfdyn
