#pragma once
// Initial states: the family `initialState`, the displacement and velocity a total-Lagrangian
// solver starts from (x = X + u(X), v(X), F = I + grad u(X)), chosen by name:
//
//     initialState { type uniformVelocity;  velocity (0 0 -100);  regions (projectile); }
//     initialState { type linearVelocity;   velocity (0 0 0); gradient ((0 1.6667 0) (0 0 0) (0 0 0)); }
//     initialState { type rigidRotation;    omega (0 0 105); centre (0.5 0.5 0.5); }
//     initialState { type twistingColumn;   Omega 105; length 6; }
//     initialState { type swingingCube;     amplitude 5e-4; }
//     initialState { type cantileverMode;   length 0.2; thickness 0.02; velocity 0.05; }
//
//     keyword  meaning                                                        required  default
//     type     one of the models above                                        yes
//     regions  names of the particle regions it applies to                    no        all particles
//     shape    a shape (geometry/Shape.hpp) the reference position must be inside     no        everywhere
//
// The models' own keywords are in their .cpp files. A model gives u(X) (zero unless
// hasDisplacement()), v(X) and grad u(X) = du_i/dX_J; apply() writes them to the particles.
#include "core/Registry.hpp"
#include "core/Tensor.hpp"
#include "geometry/Shape.hpp"
#include "particles/ParticleSet.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class InitialState {
public:
    static constexpr const char* familyName = "initialState";
    using Selector = Registry<InitialState, const Dictionary&>;
    static std::unique_ptr<InitialState> New(const Dictionary& dict);

    virtual ~InitialState();
    InitialState(const InitialState&) = delete;
    InitialState& operator=(const InitialState&) = delete;

    // Displacement u(X) (zero by default), velocity v(X), and displacement gradient grad u
    // (du_i/dX_J; zero by default) at t = 0.
    virtual Vector<Dim> displacement(const Vector<Dim>& X) const;
    virtual Vector<Dim> velocity(const Vector<Dim>& X) const = 0;
    virtual Tensor<Dim> displacementGradient(const Vector<Dim>& X) const;
    virtual bool hasDisplacement() const { return false; }

    // Applies it to the particles of `regions (...)` in its dict (all when absent), X being their
    // reference positions: `position` x = X + u and `velocity` v always, `deformationGradient`
    // F = I + grad u (created if absent) when hasDisplacement(). Throws InputError for an
    // unknown region, Error when X and the particles differ in size.
    void apply(ParticleSet<Dim>& particles, const std::vector<Vector<Dim>>& X) const;

    // The region names it applies to (empty: all particles).
    const std::vector<std::string>& regions() const { return regions_; }

protected:
    explicit InitialState(const Dictionary& dict);

private:
    Dictionary dict_;                     // for the location of errors found in apply()
    std::shared_ptr<const Shape> shape_;  // `shape`: only reference positions inside it
    std::vector<std::string> regions_;
};

extern template class InitialState<1>;
extern template class InitialState<2>;
extern template class InitialState<3>;

}  // namespace mfdyn
