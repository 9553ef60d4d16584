#pragma once
// Free-surface particles and their outward unit normals, from positions and neighbour rows alone
// (no mesh, no volumes needed): what the finite pointset method imposes p = p_o and
// sigma n = -p_o n on (doc/methods/fpm.md §3.3, §5 item 8, §6 "boundary detection and a normal
// estimator"), and what SPH or tlSph may use for a free surface.
//
// Notation: particle i with support radius h_i (the rows' radius: rows[i] must hold the
// neighbours within h_i; self may be in the row or not, it is skipped and added once), offsets
// r_j = x_j - x_i, weights w_j = V_j W(|r_j| / h_i) with the Wendland C2 shape
// W(q) = (1 - q)^4 (1 + 4q) (zero beyond h_i; W(0) = 1 for self), V_j the particle volumes (1 when
// none are given: FPM's particles have none; give them where the spacing varies, e.g. a denser
// boundary layer, so that the centre of mass below is that of the body and not of the sampling).
//
// Detection, two tests, both needed:
//   1. Centre-of-mass offset (the direction of the kernel-sum gradient): s_i = sum_j w_j r_j over
//      the neighbourhood with self, and the ratio
//          c_i = |s_i| / (h_i sum_j w_j)    (0 inside a uniform lattice, 0.071 on a flat face of a
//                                            cubic lattice at h = 2 spacings; see Options)
//      must exceed Options::offsetThreshold. It is a cheap prefilter: in a jittered cloud interior
//      particles reach c of the order of a face's, so test 2 decides.
//   2. Scan region (Marrone, Colagrossi, Le Touzé & Graziani 2010, "Fast free-surface detection
//      and level-set function definition in SPH solvers", J. Comput. Phys. 229, 3652-3663): with
//      n_i a normal of the candidate, l = Options::scanLength h_i and T = x_i + l n_i, the
//      particle is on the surface when no neighbour j lies in the umbrella-shaped region
//          |r_j| >= sqrt(2) l  and  |x_j - T| < l                       (the cap), or
//          |r_j| <  sqrt(2) l  and  |n.(x_j - T)| + |(x_j - T) - n (n.(x_j - T))| < l   (the cone)
//      i.e. the cone of half-angle 45 degrees from x_i along n up to T, capped by the ball of
//      radius l about T (their region with tau.(x_j - T) written as the distance from the axis,
//      which is the same in 2D and the rotationally symmetric region in 3D). It rejects the
//      candidates of test 1 that have a particle outside them. It is tried with the covariance
//      normal (below) and, if that region holds a neighbour, with the centre-of-mass normal: either
//      empty suffices (a jittered face particle whose covariance normal tilts into a neighbour is
//      found along the other; with Normals::centreOfMass only that one is tried).
//      The region reaches 2 l from x_i, so l <= h_i / 2 (the default) keeps it inside the rows.
//   A particle with no neighbour at all is on the surface, with a zero normal.
//
// Normals (Options::normals), unit, outward:
//   centreOfMass  n = -s_i / |s_i|: the thesis's "zeroth-order" normal (von Nida 2005, §5.2.4,
//                 Remark 7.2). The thesis calls it the gradient of a first-order fit; a consistent
//                 fit reproduces the constant 1 exactly and its gradient vanishes, so what it means
//                 is the gradient of the kernel sum sum_j V_j W_ij, whose direction is that of s_i.
//                 Exact where the neighbourhood is symmetric about the normal (a flat face, the
//                 axis of a sphere); otherwise its error is of the order of the neighbourhood's
//                 asymmetry, which does not fall with h at a fixed h / spacing.
//   covariance    the eigenvector of least eigenvalue of the weighted covariance of the whole
//                 neighbourhood (self included) about its weighted mean, C = sum w (x_j - m)(x_j - m)^T:
//                 the direction in which the body is thinnest near x_i. Oriented with n.s_i < 0.
//   planeFit      the normal of the weighted total-least-squares plane through the surface
//                 particles of the neighbourhood (self included): the eigenvector of least
//                 eigenvalue of their covariance, oriented with the covariance normal. First order:
//                 exact for a plane, error O(kappa h) on a surface of curvature kappa sampled
//                 asymmetrically about x_i; on a lattice its error is that of the staircase.
//   smoothedCovariance (default) the weighted mean, over the surface particles of the
//                 neighbourhood (self included, weights w_j), of their covariance normals,
//                 normalised. Exact on a plane whose particles within 2 h have exact covariance
//                 normals (a flat face more than 2 h from an edge), first order on a curved one
//                 like the covariance normal, and it averages the lattice staircase's noise over a
//                 support: on the test lattices (tests/unit/meshfreeOperators/SurfaceDetectionTest.cpp,
//                 h = 2 spacings) its mean error is about 2/3 of centreOfMass's and its largest
//                 below it.
//   planeFit and smoothedCovariance need the surface flags of the neighbours, so they take one more
//   pass over the rows of the surface particles.
//   Measured angles against the exact normal of a lattice sphere and disc (R = 5, spacing a,
//   h = 2a, a = 0.75 and 0.375), max / mean in degrees: see the test's header.
//
// Cost: one pass over the rows (detection and the covariance normal), plus, for planeFit and
// smoothedCovariance, a second pass over the rows of the surface particles; every loop is a
// gather over particle i's own row (parallelForWork), so the results are bit-identical for any
// thread count. The output arrays are resized, never shrunk.
#include "core/Tensor.hpp"
#include "particles/NeighbourList.hpp"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class SurfaceDetection {
public:
    enum class Normals { centreOfMass, covariance, planeFit, smoothedCovariance };

    struct Options {
        // Test 1's threshold on c_i: a prefilter, so that the scan region runs on few particles.
        // At h = 2 spacings (the thesis's) a face of a cubic lattice gives c = 0.071 and the layer
        // below it 0 (its support holds one layer on either side); jittering by 0.2 spacings
        // spreads both, the interior up to c = 0.10, so c alone cannot separate the two: 0.02 passes
        // every face particle measured and leaves the decision to the scan region.
        double offsetThreshold = 0.02;
        // Test 2's length l / h_i: Marrone et al. take l = their smoothing length, about 1.33
        // spacings; 0.5 h is one spacing at the thesis's h = 2 spacings, and keeps the region (2 l)
        // inside the rows.
        double scanLength = 0.5;
        Normals normals = Normals::smoothedCovariance;
    };

    explicit SurfaceDetection(Options options = {});

    // Several ranks (issue 21): fills the halo part of a per-particle array of x.size() elements
    // (elementBytes each) from the other ranks (ParticleSetBase::refreshHalo).
    using HaloRefresh = std::function<void(void* data, std::size_t elementBytes)>;

    // x: positions; rows[i]: the neighbours of i within h[i] (self optional; wider rows are fine,
    // weights vanish beyond h[i]); h: support radius per particle; volume: per particle, or empty
    // for 1. The particles judged are the rows' (rows.size()); x may hold more, read as
    // neighbours only: another rank's halo, whose flags and normals pass 2 and edges() read, so
    // `halo` refreshes them (after pass 1, and the normals again after pass 2). The output
    // arrays have x.size() elements.
    void detect(const std::vector<Vector<Dim>>& x, const NeighbourList& rows, const std::vector<double>& h,
                const std::vector<double>& volume = {}, const HaloRefresh& halo = {});
    void detect(const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                const std::vector<double>& volume = {}, const HaloRefresh& halo = {});

    const Options& options() const { return options_; }
    std::size_t size() const { return surface_.size(); }
    // 1 for a surface particle, 0 otherwise.
    const std::vector<unsigned char>& surface() const { return surface_; }
    std::size_t surfaceCount() const { return surfaceCount_; }  // of the rows' particles
    // Outward unit normals of the surface particles (zero elsewhere, and for an isolated particle).
    const std::vector<Vector<Dim>>& normal() const { return normal_; }
    // Test 1's c_i, every particle.
    const std::vector<double>& offsetRatio() const { return offsetRatio_; }
    // After detect: 1 for a surface particle near an edge or a corner, where one normal cannot
    // describe the surface: a surface particle of its row (the rows given to detect) has a normal
    // more than `angle` (radians) from its own; one per row. A flat face 2 h from an edge has none; a sphere of
    // radius R, normals up to about h / R apart (plus the normals' own error), so the angle is
    // the case's (at a plate's 90 degree corner the normals turn by 45 degrees over a spacing).
    std::vector<unsigned char> edges(const NeighbourList& rows, double angle) const;

    static std::string normalsName(Normals normals);
    // By name (centreOfMass, covariance, planeFit, smoothedCovariance); an unknown name throws,
    // listing the valid ones.
    static Normals normalsNamed(const std::string& name);

private:
    Options options_;
    std::vector<unsigned char> surface_;
    std::vector<Vector<Dim>> normal_;
    std::vector<double> offsetRatio_;
    std::vector<Vector<Dim>> first_;  // pass 1's normals, for pass 2
    std::size_t surfaceCount_ = 0;
};

}  // namespace mfdyn
