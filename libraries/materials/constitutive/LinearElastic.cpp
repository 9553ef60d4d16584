// Linear elasticity in the deformation gradient (doc/methods/tl-jst-sph.md section 1, "Linear elastic"; the
// text of Lee, Gil, Greto, Kulasegaram & Bonet 2016, CMAME 311:71, sections 8.1-8.2, uses it
// without writing it out):
//
//     eps = sym(F) - I = (F + F^T)/2 - I,
//     P   = lambda tr(eps) I + 2 mu eps = lambda tr(F - I) I + mu (F + F^T - 2 I),
//     W   = lambda/2 tr(eps)^2 + mu eps:eps          (P = dW/dF),
//     p   = kappa tr(F - I)                          (= tr(P)/3, kappa (J - 1) linearised).
//
// H and J are not used: the law is the same in every mixed formulation. Validity: small strains
// and small rotations (P is not objective: a rotation by theta gives stresses O(mu theta^2)).
#include "materials/constitutive/LinearElastic.hpp"

namespace mfdyn {

KeywordSchema LinearElastic::keywords() {
    return KeywordSchema(familyName, "linearElastic").append(elasticKeywords());
}

LinearElastic::LinearElastic(const Dictionary& dict) : ConstitutiveLaw(dict, keywords().read(dict)) {}

void LinearElastic::stress(const Fields& f, bool) const {
    const double lambda = lameLambda();
    const Tensor<3> identity = Tensor<3>::Identity();
    for (std::size_t i = 0; i < f.size; ++i) {
        const Tensor<3> eps = 0.5 * (f.F[i] + f.F[i].transpose()) - identity;
        const double trace = eps.trace();
        f.P[i] = lambda * trace * identity + 2.0 * mu_ * eps;
        if (f.pressure) f.pressure[i] = kappa_ * trace;
        if (f.energyDensity) f.energyDensity[i] = 0.5 * lambda * trace * trace + mu_ * eps.squaredNorm();
    }
}

MFDYN_REGISTER(ConstitutiveLaw, LinearElastic, "linearElastic",
               "small-strain Hooke law P = lambda tr(F-I) I + mu (F + F^T - 2I), not objective");

}  // namespace mfdyn
