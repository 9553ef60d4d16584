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
// Ghosts are never integrated: a solver makes them from the current state, each step or (impactSph's
// `mirrorGhosts withList`) at its list rebuilds, re-placing them from their sources in between
// (doc/methods/sph-impact.md section 4.3).
//
// Parity: the image across a skew-symmetric plane (the odd extension of the motion) is the
// negated mirror image, parity -1; across a mirror or symmetry plane parity +1. A ghost's parity
// is the product over the planes that made it. With s the parity, a vector maps to s Q a, a
// tensor to s Q T Q^T, a pseudo-scalar (pressure, a Laplacian of J) to s a, and what is the
// identity at rest (F, J) by its departure from it: I + s Q (F - I) Q^T, 1 + s (J - 1).
//
// Reference images (referenceImagesAcross): a total-Lagrangian method mirrors its reference
// configuration once, through the symmetryPlane and skewSymmetricPlane conditions
// (BoundaryConditionList::referenceImages); those blocks carry no velocity (the method maps its
// own fields each stage).
#include "boundaryConditions/Plane.hpp"
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
    std::vector<double> parity;       // +1, or -1 for an odd number of skew-symmetric images

    std::size_t size() const { return source.size(); }
    bool empty() const { return source.empty(); }
    void clear() {
        position.clear();
        velocity.clear();
        source.clear();
        map.clear();
        parity.clear();
    }
    void append(const GhostBlock& other) {
        position.insert(position.end(), other.position.begin(), other.position.end());
        velocity.insert(velocity.end(), other.velocity.begin(), other.velocity.end());
        source.insert(source.end(), other.source.begin(), other.source.end());
        map.insert(map.end(), other.map.begin(), other.map.end());
        parity.insert(parity.end(), other.parity.begin(), other.parity.end());
    }
    // A field of the real particles copied to the ghosts (scalars: density, mass, pressure, h).
    template <class T>
    std::vector<T> gather(const std::vector<T>& field) const {
        std::vector<T> out(source.size());
        for (std::size_t g = 0; g < source.size(); ++g) out[g] = field[source[g]];
        return out;
    }
    // (Separate names: in 1D a vector and a tensor are the same C++ type.)
    // The image s Q a of a vector belonging to ghost g's source.
    Vector<Dim> reflectVector(std::size_t g, const Vector<Dim>& a) const { return parity[g] * (map[g] * a); }
    // The image s Q T Q^T of a tensor (stress) belonging to ghost g's source.
    Tensor<Dim> reflectTensor(std::size_t g, const Tensor<Dim>& t) const {
        return parity[g] * map[g] * t * map[g].transpose();
    }
    // The image s a of a pseudo-scalar (pressure, a Laplacian of J: odd under skew symmetry).
    double reflectScalar(std::size_t g, double a) const { return parity[g] * a; }
    // The image I + s Q (F - I) Q^T of a deformation gradient or cofactor.
    Tensor<Dim> reflectDeformation(std::size_t g, const Tensor<Dim>& F) const {
        return Tensor<Dim>::Identity() +
               parity[g] * map[g] * (F - Tensor<Dim>::Identity()) * map[g].transpose();
    }
    // The image 1 + s (J - 1) of a Jacobian.
    double reflectJacobian(std::size_t g, double J) const { return 1.0 + parity[g] * (J - 1.0); }

    // Appends the images across `plane` (parity `planeParity`) of the points `real` (sources
    // 0..n-1) and of the ghosts already in the block (images of images: the edges and corners of
    // perpendicular planes), in that order, for every point with tolerance < d < depth; a point on
    // the plane is its own image and makes none.
    void referenceImagesAcross(const std::vector<Vector<Dim>>& real, const Plane<Dim>& plane,
                               double planeParity, double depth) {
        const Tensor<Dim> reflection =
            Tensor<Dim>::Identity() - 2.0 * plane.normal() * plane.normal().transpose();
        const std::size_t earlier = size();
        // (By value: the pushes below may move the ghosts' own storage.)
        auto image = [&](const Vector<Dim> x, std::size_t src, const Tensor<Dim> q, double s) {
            const double d = plane.signedDistance(x);
            if (d <= plane.tolerance() || d >= depth) return;
            position.push_back(plane.mirror(x));
            source.push_back(src);
            map.push_back(Tensor<Dim>(reflection * q));
            parity.push_back(planeParity * s);
        };
        for (std::size_t i = 0; i < real.size(); ++i) image(real[i], i, Tensor<Dim>::Identity(), 1.0);
        for (std::size_t g = 0; g < earlier; ++g) image(position[g], source[g], map[g], parity[g]);
    }
};

}  // namespace mfdyn
