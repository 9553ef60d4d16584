#pragma once
// Particles in Dim = 1, 2 or 3 dimensions: every field one contiguous array, created on demand
// (FieldStore). Always present: `position` (vector), `globalId` and `region` (integer).
//
// Dim is known only once the particle file is read, so a solver does
//
//     withDimension(file.particles->dimension(), [&](auto dim) {
//         constexpr int Dim = decltype(dim)::value;
//         auto& particles = particleSetCast<Dim>(*file.particles);
//         ...  // everything below is compiled for each Dim
//     });
//
// and never branches on the dimension again.
#include "particles/ParticleSetBase.hpp"

#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace mfdyn {

template <int Dim>
class ParticleSet final : public ParticleSetBase {
    static_assert(Dim >= 1 && Dim <= 3, "particles are 1D, 2D or 3D");

public:
    static constexpr int dim = Dim;
    using VectorType = Vector<Dim>;
    using TensorType = Tensor<Dim>;
    using SymmTensorType = SymmTensor<Dim>;

    explicit ParticleSet(std::size_t n = 0);
    ParticleSet(const ParticleSet&) = default;

    std::vector<VectorType>& position() { return field<VectorType>("position"); }
    const std::vector<VectorType>& position() const { return requireField<VectorType>("position"); }
    // The reference configuration X of a total-Lagrangian method where the set carries one
    // (`referencePosition`), else the current positions: what a plane or a constraint set up at the
    // start is measured against.
    const std::vector<VectorType>& referenceOrCurrentPosition() const {
        if (const auto* x0 = this->template findField<VectorType>("referencePosition")) return *x0;
        return position();
    }
    std::vector<std::int64_t>& globalId() { return field<std::int64_t>("globalId"); }
    const std::vector<std::int64_t>& globalId() const { return requireField<std::int64_t>("globalId"); }
    std::vector<std::int64_t>& region() { return field<std::int64_t>("region"); }
    const std::vector<std::int64_t>& region() const { return requireField<std::int64_t>("region"); }

    // Typed shorthands that need no `.template` in code templated on Dim.
    std::vector<double>& scalarField(const std::string& name) { return field<double>(name); }
    std::vector<VectorType>& vectorField(const std::string& name) { return field<VectorType>(name); }
    std::vector<TensorType>& tensorField(const std::string& name) {
        return field<TensorType>(name, FieldKind::tensor);
    }
    std::vector<SymmTensorType>& symmTensorField(const std::string& name) {
        return field<SymmTensorType>(name);
    }
    std::vector<std::int64_t>& integerField(const std::string& name) { return field<std::int64_t>(name); }

    using ParticleSetBase::addField;
    FieldBase& addField(const std::string& name, FieldKind kind) override;
    std::unique_ptr<ParticleSetBase> clone() const override { return std::make_unique<ParticleSet>(*this); }

    // Ghosts (see ParticleSetBase): ghost g is the image of owned particle source[g] under the
    // orthogonal map[g] (a reflection R = I - 2 n n^T, or a product of them at a corner). Every
    // field is copied from the source; the caller then sets what the image changes: its
    // position (a mirror image is affine, not Q x), its velocity (the boundary's condition), and
    // the vectors and tensors that reflect (reflectToGhosts). Returns the first ghost's index.
    std::size_t addGhosts(const std::vector<std::size_t>& source, const std::vector<TensorType>& map) {
        if (map.size() != source.size())
            throw Error("addGhosts: " + std::to_string(map.size()) + " maps for " +
                        std::to_string(source.size()) + " ghosts");
        const std::size_t first = appendGhostCopies(source);
        ghostMap_.insert(ghostMap_.end(), map.begin(), map.end());
        return first;
    }
    const std::vector<TensorType>& ghostMap() const { return ghostMap_; }
    std::size_t appendHalo(std::size_t n, const HaloExchange& exchange) override {
        const std::size_t first = ParticleSetBase::appendHalo(n, exchange);
        ghostMap_.insert(ghostMap_.end(), n, TensorType::Identity());
        return first;
    }
    void clearGhosts() override {
        ghostMap_.clear();
        ParticleSetBase::clearGhosts();
    }
    // After the owned values of `field` changed: each ghost's value copied again from its source.
    template <class T>
    void copyToGhosts(std::vector<T>& field) const {
        refreshHalo(field.data(), sizeof(T));
        const std::size_t owned = ownedCount();
        const auto& source = ghostSource();
        for (std::size_t g = haloCount(); g < source.size(); ++g) field[owned + g] = field[source[g]];
    }
    // Each ghost's value the image of its source's: Q a for a vector, Q T Q^T for a tensor.
    // (Two names: in 1D a vector and a tensor are the same C++ type.)
    void reflectVectorsToGhosts(std::vector<VectorType>& field) const {
        refreshHalo(field.data(), sizeof(VectorType));
        const std::size_t owned = ownedCount();
        const auto& source = ghostSource();
        for (std::size_t g = haloCount(); g < source.size(); ++g) field[owned + g] = ghostMap_[g] * field[source[g]];
    }
    void reflectTensorsToGhosts(std::vector<TensorType>& field) const {
        refreshHalo(field.data(), sizeof(TensorType));
        const std::size_t owned = ownedCount();
        const auto& source = ghostSource();
        for (std::size_t g = haloCount(); g < source.size(); ++g)
            field[owned + g] = ghostMap_[g] * field[source[g]] * ghostMap_[g].transpose();
    }
    void reflectTensorsToGhosts(std::vector<SymmTensorType>& field) const {
        refreshHalo(field.data(), sizeof(SymmTensorType));
        const std::size_t owned = ownedCount();
        const auto& source = ghostSource();
        for (std::size_t g = haloCount(); g < source.size(); ++g)
            field[owned + g] =
                SymmTensorType::fromFull(ghostMap_[g] * field[source[g]].full() * ghostMap_[g].transpose());
    }

private:
    std::vector<TensorType> ghostMap_;
};

extern template class ParticleSet<1>;
extern template class ParticleSet<2>;
extern template class ParticleSet<3>;

// Calls f(std::integral_constant<int, Dim>{}) for dim = 1, 2, 3 and returns its result; any
// other value is an InputError.
template <class F>
decltype(auto) withDimension(int dim, F&& f) {
    switch (dim) {
        case 1:
            return std::forward<F>(f)(std::integral_constant<int, 1>{});
        case 2:
            return std::forward<F>(f)(std::integral_constant<int, 2>{});
        case 3:
            return std::forward<F>(f)(std::integral_constant<int, 3>{});
    }
    throw InputError("dimension " + std::to_string(dim) + " is not 1, 2 or 3");
}

// The typed set behind `base`; Error when its dimension is not Dim.
template <int Dim>
ParticleSet<Dim>& particleSetCast(ParticleSetBase& base) {
    if (base.dimension() != Dim)
        throw Error("particle set is " + std::to_string(base.dimension()) + "D, used as " +
                    std::to_string(Dim) + "D");
    return static_cast<ParticleSet<Dim>&>(base);
}

template <int Dim>
const ParticleSet<Dim>& particleSetCast(const ParticleSetBase& base) {
    return particleSetCast<Dim>(const_cast<ParticleSetBase&>(base));
}

// Ownership of a particle set read without its dimension in the type, checked (what a solver
// does with SolverRun::takeParticles()).
template <int Dim>
std::unique_ptr<ParticleSet<Dim>> adoptParticleSet(std::unique_ptr<ParticleSetBase> base) {
    particleSetCast<Dim>(*base);
    return std::unique_ptr<ParticleSet<Dim>>(static_cast<ParticleSet<Dim>*>(base.release()));
}

// A scalar field the particle file must carry: an InputError naming it, what it is for and the
// fields there are, when it is missing.
template <int Dim>
std::vector<double>& requireScalarField(ParticleSet<Dim>& particles, const std::string& name,
                                        const std::string& why) {
    if (!particles.hasField(name)) {
        std::string have;
        for (const auto& n : particles.fieldNames()) have += " " + n;
        throw InputError("the particle file has no field '" + name + "' (" + why + "); fields:" + have);
    }
    return particles.scalarField(name);
}

}  // namespace mfdyn
