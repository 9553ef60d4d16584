#pragma once
// Ghost particles made by mirror boundaries for one step. The solver appends them to its
// neighbour search as read-only neighbours and fills every other field it needs by copying
// from the source particle:
//
//     rhoGhost[g] = rho[block.source[g]];        (or block.gather(rho))
//
// Vectors other than velocity (and tensors) must be reflected, not copied: with the orthogonal
// map Q kept per ghost (R = I - 2 n n^T for the image across one plane of unit normal n; the
// product R2 R1 for the image across plane 2 of an image across plane 1, as at a corner), a
// vector maps to Q a and a tensor to Q T Q^T.
// Ghosts are regenerated every step (doc/methods/sph-impact.md section 4), never integrated.
#include "core/Tensor.hpp"

#include <cstddef>
#include <vector>

namespace mfdyn {

template <int Dim>
struct GhostBlock {
    std::vector<Vector<Dim>> position;
    std::vector<Vector<Dim>> velocity;
    std::vector<std::size_t> source;  // index of the real particle each ghost mirrors
    std::vector<Tensor<Dim>> map;     // orthogonal map from the source to the ghost (reflections)

    std::size_t size() const { return source.size(); }
    bool empty() const { return source.empty(); }
    void clear() {
        position.clear();
        velocity.clear();
        source.clear();
        map.clear();
    }
    void append(const GhostBlock& other) {
        position.insert(position.end(), other.position.begin(), other.position.end());
        velocity.insert(velocity.end(), other.velocity.begin(), other.velocity.end());
        source.insert(source.end(), other.source.begin(), other.source.end());
        map.insert(map.end(), other.map.begin(), other.map.end());
    }
    // A field of the real particles copied to the ghosts (scalars: density, mass, pressure, h).
    template <class T>
    std::vector<T> gather(const std::vector<T>& field) const {
        std::vector<T> out(source.size());
        for (std::size_t g = 0; g < source.size(); ++g) out[g] = field[source[g]];
        return out;
    }
    // (Two names: in 1D a vector and a tensor are the same C++ type.)
    // The mirror image Q a of a vector belonging to ghost g's source.
    Vector<Dim> reflectVector(std::size_t g, const Vector<Dim>& a) const { return map[g] * a; }
    // The mirror image Q T Q^T of a tensor (stress) belonging to ghost g's source.
    Tensor<Dim> reflectTensor(std::size_t g, const Tensor<Dim>& t) const {
        return map[g] * t * map[g].transpose();
    }
};

}  // namespace mfdyn
