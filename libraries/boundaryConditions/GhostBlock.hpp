#pragma once
// Ghost particles made by mirror boundaries for one step. The solver appends them to its
// neighbour search as read-only neighbours and fills every other field it needs by copying
// from the source particle:
//
//     rhoGhost[g] = rho[block.source[g]];        (or block.gather(rho))
//
// Vectors other than velocity (and tensors) must be reflected, not copied: with the plane's unit
// normal n kept per ghost, R = I - 2 n n^T, a vector maps to R a and a tensor to R T R.
// Ghosts are regenerated every step (sph-impact.md section 4), never integrated.
#include "core/Tensor.hpp"

#include <cstddef>
#include <vector>

namespace mfdyn {

template <int Dim>
struct GhostBlock {
    std::vector<Vector<Dim>> position;
    std::vector<Vector<Dim>> velocity;
    std::vector<std::size_t> source;  // index of the real particle each ghost mirrors
    std::vector<Vector<Dim>> normal;  // unit normal of the mirror plane that made it

    std::size_t size() const { return source.size(); }
    bool empty() const { return source.empty(); }
    void clear() {
        position.clear();
        velocity.clear();
        source.clear();
        normal.clear();
    }
    void append(const GhostBlock& other) {
        position.insert(position.end(), other.position.begin(), other.position.end());
        velocity.insert(velocity.end(), other.velocity.begin(), other.velocity.end());
        source.insert(source.end(), other.source.begin(), other.source.end());
        normal.insert(normal.end(), other.normal.begin(), other.normal.end());
    }
    // A field of the real particles copied to the ghosts (scalars: density, mass, pressure, h).
    template <class T>
    std::vector<T> gather(const std::vector<T>& field) const {
        std::vector<T> out(source.size());
        for (std::size_t g = 0; g < source.size(); ++g) out[g] = field[source[g]];
        return out;
    }
    // (Two names: in 1D a vector and a tensor are the same C++ type.)
    // The mirror image R a of a vector belonging to ghost g's source.
    Vector<Dim> reflectVector(std::size_t g, const Vector<Dim>& a) const {
        return a - 2.0 * a.dot(normal[g]) * normal[g];
    }
    // The mirror image R T R of a tensor (stress) belonging to ghost g's source.
    Tensor<Dim> reflectTensor(std::size_t g, const Tensor<Dim>& t) const {
        const Tensor<Dim> r = Tensor<Dim>::Identity() - 2.0 * normal[g] * normal[g].transpose();
        return r * t * r;
    }
};

}  // namespace mfdyn
