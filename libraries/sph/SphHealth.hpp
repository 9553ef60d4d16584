#pragma once
// impactSph's part of the health check (functionObjects/Health.hpp, issue 20): the argmin that
// names the particle limiting the time step, and the method's indicators of a degrading
// discretisation, computed from a state alone so that tests can give them hand-made states.
// Definitions, thresholds and sources: SphHealth.cpp.
#include "core/Tensor.hpp"
#include "functionObjects/HealthIndicator.hpp"
#include "kernels/KernelEvaluator.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace mfdyn {

// The smallest value and the global id that has it (ties: the lowest id), summable by
// LocalReduce/GlobalReduce::sum: += keeps the lexicographic minimum of (value, id), which is
// commutative and associative, so every blocking and every rank count gives the same answer (an
// MPI build reduces it with an MPI_Op made from +=). The zero (value-initialised) is the identity:
// +inf with no id. A NaN never wins (the health check reports NaNs itself).
struct ArgMin {
    double value = std::numeric_limits<double>::infinity();
    std::int64_t id = std::numeric_limits<std::int64_t>::max();
    ArgMin& operator+=(const ArgMin& o) {
        if (o.value < value || (o.value == value && o.id < id)) *this = o;
        return *this;
    }
    // The global id, -1 when no item had a value below +inf.
    std::int64_t particle() const { return id == std::numeric_limits<std::int64_t>::max() ? -1 : id; }
};

// The state the indicators read: particles [0, owned) are measured, [owned, size) are ghosts
// (mirror images) seen as neighbours only. Every array has `size` entries except tau, soundSpeed
// and globalId (owned) and imageOf (one per ghost: the index of the particle it images, so that a
// particle's own image is not its nearest neighbour).
template <int Dim>
struct SphHealthState {
    std::size_t owned = 0, size = 0;
    const Vector<Dim>* x = nullptr;
    const Vector<Dim>* v = nullptr;
    const double *m = nullptr, *rho = nullptr, *h = nullptr, *p = nullptr;
    const double* soundSpeed = nullptr;    // owned; the scale below which velocity differences are noise
    const SymmTensor<Dim>* tau = nullptr;  // owned; null without a deviatoric stress
    const std::int64_t* globalId = nullptr;
    const std::size_t* imageOf = nullptr;
    KernelEvaluator<Dim> W;
};

// The thresholds (SphHealth.cpp says why these).
inline constexpr double tensileClumpRatio = 0.5;     // nearest distance / (m/rho)^(1/d)
inline constexpr double hourglassThreshold = 0.7;    // unexplained fraction of the velocity differences
inline constexpr double hourglassNoiseFloor = 1e-3;  // a mode slower than this x c: noise

// Per particle (owned), for the tests: the Shepard sum S, the nearest-neighbour ratio q, whether
// it is in tension, and the hourglass measure e (0 where the mode is slower than the gate).
template <int Dim>
struct SphHealthValues {
    std::vector<double> shepard, nearestRatio, hourglass;
    std::vector<char> tension;
};
template <int Dim>
SphHealthValues<Dim> sphHealthValues(const SphHealthState<Dim>& state);

// neighbourDeficiency, tensileInstability, hourglass (HealthIndicator.hpp), reduced over every
// rank (collective: every rank calls it).
template <int Dim>
std::vector<HealthIndicator> sphHealthIndicators(const SphHealthState<Dim>& state);

}  // namespace mfdyn
