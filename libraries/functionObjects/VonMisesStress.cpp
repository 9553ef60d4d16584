// VonMisesField: the Cauchy stress of the material point method's fields, see VonMisesStress.hpp.
#include "functionObjects/VonMisesStress.hpp"

#include "core/Error.hpp"

namespace mfdyn {

VonMisesField::VonMisesField(const FieldStore& store, const std::string& where)
    : sigma_(store.findField("cauchyStress")), dim_(store.dimension()) {
    const std::string prefix = where.empty() ? "" : where + ": ";
    if (!sigma_ || sigma_->kind() != FieldKind::symmTensor)
        throw InputError(prefix +
                         "the derived field vonMisesStress needs the symmetric tensor field "
                         "'cauchyStress' (a material point method run writes it), and this run has " +
                         (sigma_ ? "it as another kind" : std::string("none")));
    if (dim_ < 3) {
        zz_ = store.findField("cauchyStressZZ");
        if (!zz_ || zz_->components() != 1)
            throw InputError(prefix +
                             "the derived field vonMisesStress needs the scalar field 'cauchyStressZZ' "
                             "(sigma_zz of plane strain) in a " +
                             std::to_string(dim_) + "D run, and this run has none");
    }
}

double VonMisesField::operator()(std::size_t i) const {
    const auto c = [&](int k) { return sigma_->component(i, k); };
    switch (dim_) {
        case 1: {
            const double zz = zz_->component(i, 0);
            return vonMisesStress(c(0), zz, zz, 0, 0, 0);
        }
        case 2:  // (xx, yy, xy)
            return vonMisesStress(c(0), c(1), zz_->component(i, 0), c(2), 0, 0);
        default:  // (xx, yy, zz, xy, yz, xz)
            return vonMisesStress(c(0), c(1), c(2), c(3), c(4), c(5));
    }
}

}  // namespace mfdyn
