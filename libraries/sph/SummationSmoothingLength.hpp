#pragma once
// `summation`: see SummationSmoothingLength.cpp for its equations and keywords.
#include "sph/SmoothingLengthLaw.hpp"

namespace mfdyn {

class SummationSmoothingLength final : public SmoothingLengthLaw {
public:
    static KeywordSchema keywords();
    explicit SummationSmoothingLength(const Dictionary& dict);
    void update(int, std::size_t, const double*, const double*, const double*, double*) const override {}
    bool iterative() const override { return true; }
    double tolerance() const override { return tolerance_; }
    int maxIterations() const override { return maxIterations_; }
    double initial(int dim, double mass, double rho) const override;

private:
    explicit SummationSmoothingLength(const KeywordValues& v);
    double tolerance_;
    int maxIterations_;
};

}  // namespace mfdyn
