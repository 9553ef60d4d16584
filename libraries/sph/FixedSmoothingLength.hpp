#pragma once
// `fixed`: see FixedSmoothingLength.cpp for its equations and keywords.
#include "sph/SmoothingLengthLaw.hpp"

namespace mfdyn {

class FixedSmoothingLength final : public SmoothingLengthLaw {
public:
    static KeywordSchema keywords();
    explicit FixedSmoothingLength(const Dictionary& dict);
    double initial(int dim, double mass, double rho) const override;
    void update(int, std::size_t, const double*, const double*, const double*, double*) const override {}

private:
    explicit FixedSmoothingLength(const KeywordValues& v);
    double h_ = 0.0;  // 0: not given
};

}  // namespace mfdyn
