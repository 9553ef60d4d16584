// PrincipalStressField: sigma = S - p I of the finite pointset method's fields and its extreme
// eigenvalues, see PrincipalStress.hpp.
#include "functionObjects/PrincipalStress.hpp"

#include "core/Error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace mfdyn {

std::array<double, 3> symmetricEigenvalues(double xx, double yy, double zz, double xy, double yz, double xz) {
    Eigen::Matrix3d m;
    m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d& e = solver.eigenvalues();  // ascending
    return {e[0], e[1], e[2]};
}

PrincipalStressField::PrincipalStressField(const FieldStore& store, const std::string& where,
                                           const std::string& field)
    : S_(store.findField("deviatoricStress")), p_(store.findField("pressure")), dim_(store.dimension()) {
    const std::string prefix = where.empty() ? "" : where + ": ";
    if (!S_ || S_->kind() != FieldKind::symmTensor)
        throw InputError(prefix + "the derived field " + field +
                         " needs the symmetric tensor field 'deviatoricStress' (a finite pointset method "
                         "run writes it), and this run has " +
                         (S_ ? "it as another kind" : std::string("none")));
    if (!p_ || p_->kind() != FieldKind::scalar)
        throw InputError(prefix + "the derived field " + field +
                         " needs the scalar field 'pressure' (sigma = S - p I), and this run has " +
                         (p_ ? "it as another kind" : std::string("none")));
}

PrincipalStresses PrincipalStressField::operator()(std::size_t i) const {
    const auto c = [&](int k) { return S_->component(i, k); };
    const double p = p_->component(i, 0);
    switch (dim_) {
        case 1:  // (xx); the lateral S is zero
            return {std::min(c(0), 0.0) - p, std::max(c(0), 0.0) - p};
        case 2: {  // (xx, yy, xy); S_zz = 0
            const double m = 0.5 * (c(0) + c(1)), r = std::hypot(0.5 * (c(0) - c(1)), c(2));
            return {std::min(m - r, 0.0) - p, std::max(m + r, 0.0) - p};
        }
        default: {  // (xx, yy, zz, xy, yz, xz)
            const auto e = symmetricEigenvalues(c(0), c(1), c(2), c(3), c(4), c(5));
            return {e[0] - p, e[2] - p};
        }
    }
}

}  // namespace mfdyn
