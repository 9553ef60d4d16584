#include "sph/SmoothingLengthLaw.hpp"

#include <cmath>

namespace mfdyn {

SmoothingLengthLaw::SmoothingLengthLaw(const Dictionary& dict)
    : eta_(dict.getOrDefault<double>("eta", 1.2)),
      tolerance_(dict.getOrDefault<double>("tolerance", 1e-4)),
      maxIterations_(dict.getOrDefault<int>("maxIterations", 30)) {
    if (!(eta_ > 0)) throw dict.error("eta", "eta must be positive");
    if (!(tolerance_ > 0)) throw dict.error("tolerance", "tolerance must be positive");
}

SmoothingLengthLaw::~SmoothingLengthLaw() = default;

namespace {

double root(double x, int dim) { return dim == 1 ? x : dim == 2 ? std::sqrt(x) : std::cbrt(x); }

}  // namespace

// fixed: h never changes. The initial value is `h` when given, else η (m/ρ)^{1/d}.
class FixedSmoothingLength final : public SmoothingLengthLaw {
public:
    explicit FixedSmoothingLength(const Dictionary& dict)
        : SmoothingLengthLaw(dict), h_(dict.getOrDefault<double>("h", 0.0)) {}
    void update(int, std::size_t, const double*, const double*, const double*, double*) const override {}
    double initial(int dim, double mass, double rho) const override {
        return h_ > 0 ? h_ : eta() * root(mass / rho, dim);
    }

private:
    double h_;
};

// massDensity: h = η (m/ρ)^{1/d} (Zisis 2017 eq. 4.2), explicit in the evolved density.
class MassDensitySmoothingLength final : public SmoothingLengthLaw {
public:
    using SmoothingLengthLaw::SmoothingLengthLaw;
    void update(int dim, std::size_t n, const double* m, const double* rho, const double*, double* h) const override {
        for (std::size_t i = 0; i < n; ++i) h[i] = eta() * root(m[i] / rho[i], dim);
    }
    double initial(int dim, double mass, double rho) const override { return eta() * root(mass / rho, dim); }
};

// numberDensity: h = η ñ^{-1/d} (Zisis 2017 eq. 4.1): follows the particle spacing whatever the
// masses; ñ is the number density of the last neighbour sum.
class NumberDensitySmoothingLength final : public SmoothingLengthLaw {
public:
    using SmoothingLengthLaw::SmoothingLengthLaw;
    void update(int dim, std::size_t n, const double*, const double*, const double* number, double* h) const override {
        for (std::size_t i = 0; i < n; ++i) h[i] = eta() / root(number[i], dim);
    }
    bool needsNumberDensity() const override { return true; }
    double initial(int dim, double mass, double rho) const override { return eta() * root(mass / rho, dim); }
};

// summation: h and ρ from c Σ b W(h) = m (η/h)^d, solved per particle by the solver (iterative()).
class SummationSmoothingLength final : public SmoothingLengthLaw {
public:
    using SmoothingLengthLaw::SmoothingLengthLaw;
    void update(int, std::size_t, const double*, const double*, const double*, double*) const override {}
    bool iterative() const override { return true; }
    double initial(int dim, double mass, double rho) const override { return eta() * root(mass / rho, dim); }
};

MFDYN_REGISTER(SmoothingLengthLaw, SummationSmoothingLength, "summation",
               "h and rho solved together per particle (Newton with bisection fallback)");
MFDYN_REGISTER(SmoothingLengthLaw, FixedSmoothingLength, "fixed", "h constant in time");
MFDYN_REGISTER(SmoothingLengthLaw, MassDensitySmoothingLength, "massDensity", "h = eta (m/rho)^(1/d)");
MFDYN_REGISTER(SmoothingLengthLaw, NumberDensitySmoothingLength, "numberDensity", "h = eta n^(-1/d), n = sum W");

}  // namespace mfdyn
