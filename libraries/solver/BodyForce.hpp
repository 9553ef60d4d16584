#pragma once
// Body forces per unit mass, a(x, t), for any method: a solver that applies one adds a(x, t) to
// each particle's acceleration (particleFlight integrates it alone). It lives in the shared solver
// layer so that every method selects gravity or a user's force through the same `bodyForce`
// sub-dictionary. A body force may know the exact trajectory it produces, which makes a solver's
// error measurable (trajectoryError) and lets a user library prove its model end to end.
#include "core/Registry.hpp"
#include "core/Time.hpp"

#include <memory>

namespace mfdyn {

class BodyForce {
public:
    static constexpr const char* familyName = "bodyForce";
    using Selector = Registry<BodyForce, const Dictionary&, int>;
    // `dimension` is the particles' space dimension; vectors below have that many components.
    static std::unique_ptr<BodyForce> New(const Dictionary& dict, int dimension) {
        return Selector::New(dict, dimension);
    }

    BodyForce(const Dictionary& dict, int dimension);
    virtual ~BodyForce();
    int dimension() const { return dimension_; }

    // Acceleration a at position x and time t.
    virtual void acceleration(const double* x, double t, double* a) const = 0;
    // Potential per unit mass (a = -grad phi), for the energy balance.
    virtual double potential(const double* x) const = 0;
    // The state after time `tau` from (x0, v0), when known in closed form.
    virtual bool exactTrajectory(const double* x0, const double* v0, double tau, double* x, double* v) const {
        (void)x0, (void)v0, (void)tau, (void)x, (void)v;
        return false;
    }
    // The step this force allows (e.g. a fraction of an oscillation period).
    virtual TimeStepVote stableTimeStep() const;

private:
    int dimension_;
};

}  // namespace mfdyn
