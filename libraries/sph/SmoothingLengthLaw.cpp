// The smoothingLength family's shared parts (the laws are in their own files).
#include "sph/SmoothingLengthLaw.hpp"

#include <cmath>

namespace mfdyn {

SmoothingLengthLaw::~SmoothingLengthLaw() = default;

KeywordSchema SmoothingLengthLaw::etaKeyword(const char* type) {
    return KeywordSchema(familyName, type)
        .scalar("eta", "-", "ratio of h to the particle spacing (m/rho)^(1/d), in the kernel's own h")
        .greaterThan(0)
        .orDefault(1.2);
}

double SmoothingLengthLaw::dimensionRoot(double x, int dim) {
    return dim == 1 ? x : dim == 2 ? std::sqrt(x) : std::cbrt(x);
}

}  // namespace mfdyn
