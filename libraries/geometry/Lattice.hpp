#pragma once
// Where particles sit inside a shape, selected by name:
//     lattice { type cubic; spacing 0.01; }
//     lattice { type hexagonal; spacing 0.01; jitter 0.1; seed 42; }
//     lattice { type nodal; points (21 11 3); }
//     lattice { type materialPoints; cells (10 10); pattern gauss; }   (MPM: V_p = exact volume / N)
// A lattice fills a bounding box with points, each carrying the volume it represents: the same
// pointVolume() for every point of cubic, hexagonal and hcp; per point (pointVolumes) for nodal,
// whose points on the box's faces stand for half a cell or less.
// Every lattice takes `jitter` (default 0): each point is moved by a displacement uniform in
// [−jitter·spacing, +jitter·spacing] per component, drawn from std::mt19937_64 seeded with `seed`
// (default 1) in lattice order, so a jittered lattice is still identical run to run. Jitter breaks
// the lattice's symmetry (regular lattices can hold spurious symmetric modes); it is kept below ½
// so that two points never swap places.
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"
#include "geometry/Shape.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace mfdyn {

class Lattice {
public:
    static constexpr const char* familyName = "lattice";
    using Selector = Registry<Lattice, const Dictionary&, int>;
    static std::unique_ptr<Lattice> New(const Dictionary& dict, int dimension) {
        return Selector::New(dict, dimension);
    }

    virtual ~Lattice();
    int dimension() const { return dimension_; }
    double spacing() const { return spacing_; }

    double jitter() const { return jitter_; }

    // Points covering `box`, `dimension()` coordinates each, in a fixed order (so generation is
    // identical run to run): the lattice sites, jittered when asked.
    virtual std::vector<double> points(const BoundingBox& box) const;
    // Volume per lattice point (spacing^dim for cubic).
    virtual double pointVolume() const = 0;
    // The volume of each of `points` (as returned by points(box)), one per point. By default
    // pointVolume() for every point; the nodal lattice gives its boundary points their
    // tributary (dual-cell) volumes.
    virtual std::vector<double> pointVolumes(const BoundingBox& box, const std::vector<double>& points) const;
    // True for a lattice whose points share the shape's exact volume equally (materialPoints:
    // V_p = exact volume / N, the material point method's rule); particleGen then replaces
    // pointVolumes() by that share when the shape has a closed-form volume, and keeps them (with
    // a log line) when it has none.
    virtual bool volumeFromShape() const { return false; }
    // How many points points(box) returns, counted in floating point without allocating, so that
    // a spacing far too small for the box gives a huge number (particleGen refuses it before
    // generating) rather than an overflowed integer.
    double pointCount(const BoundingBox& box) const;

protected:
    // From the values of commonKeywords(): spacing (0 when not given: nodal with `points`),
    // jitter, seed.
    Lattice(const KeywordValues& v, int dimension);
    // spacing (required unless `spacingOptional`), jitter and seed, declared for lattice `type`.
    static KeywordSchema commonKeywords(const char* type, bool spacingOptional = false);
    std::uint64_t seed() const { return seed_; }

    // The regular lattice sites covering `box`, in a fixed order.
    virtual std::vector<double> sites(const BoundingBox& box) const = 0;
    // The number of sites per direction that sites(box) lays out (1 in unused directions), as reals.
    virtual std::array<double, 3> siteCounts(const BoundingBox& box) const = 0;
    // siteCounts(box) as integers to allocate with; InputError when the product is not finite or
    // beyond 2^53 (where a count is no longer exact in a double, far beyond any memory), instead of
    // the undefined conversion of a huge real to long.
    std::array<long, 3> checkedSiteCounts(const BoundingBox& box) const;
    // Sites along `length` one `step` apart, cell-centred: ceil(L/step − 1e-9), at least 1 (the
    // 1e-9 keeps a length that is a whole number of steps up to round-off from gaining a row).
    static double rowCount(double length, double step);

private:
    int dimension_;
    double spacing_;
    double jitter_;
    std::uint64_t seed_;
};

}  // namespace mfdyn
