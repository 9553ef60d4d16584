#pragma once
// The solid enclosed by a closed triangulated surface read from an STL file (3D only):
//     shape { type stlSurface; file "constant/geometry/projectile.stl"; }
// A relative path is taken from the case directory (the parent of the folder the dictionary was
// read from, system/), or from the working directory for a dictionary that has no file.
// The geometry kernel (CGAL) is hidden behind Impl so that no header pulls it in.
#include "geometry/Shape.hpp"

#include <filesystem>
#include <memory>

namespace mfdyn {

class StlSurface final : public Shape {
public:
    StlSurface(const Dictionary& dict, int dimension);
    ~StlSurface() override;
    bool inside(const double* x) const override;
    BoundingBox bounds() const override { return box_; }
    std::optional<double> volume() const override { return volume_; }
    std::size_t triangles() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    BoundingBox box_;
    double volume_ = 0;
};

}  // namespace mfdyn
