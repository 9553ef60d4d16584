#pragma once
// Shared by the boundary-condition tests: a small lattice of particles with named regions and a
// velocity field, and conditions built from dictionary text as a case writes them.
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/BoundaryConditionList.hpp"
#include "core/Dictionary.hpp"

#include <cmath>
#include <memory>
#include <string>

namespace mfdyn::test {

// A square (2D) or cube (3D) lattice of n^Dim particles at (k + offset) * spacing, k = 0..n-1.
// Region `wall` (id 1): the particles with y < 0.15; the rest `fluid` (id 0). Velocity and
// `acceleration` fields are filled with distinct, non-zero values so that untouched particles
// can be told from constrained ones.
template <int Dim>
ParticleSet<Dim> lattice(int n = 11, double spacing = 0.1, double offset = 0.0) {
    std::size_t count = 1;
    for (int d = 0; d < Dim; ++d) count *= std::size_t(n);
    ParticleSet<Dim> p(count);
    p.regionNames = {"fluid", "wall"};
    auto& x = p.position();
    auto& v = p.vectorField("velocity");
    auto& a = p.vectorField("acceleration");
    for (std::size_t i = 0; i < count; ++i) {
        std::size_t rest = i;
        for (int d = 0; d < Dim; ++d) {
            x[i][d] = (double(rest % std::size_t(n)) + offset) * spacing;
            rest /= std::size_t(n);
        }
        p.globalId()[i] = std::int64_t(100 + i);
        p.region()[i] = (Dim > 1 && x[i][1] < 0.15) ? 1 : 0;
        for (int d = 0; d < Dim; ++d) {
            v[i][d] = std::sin(1.0 + double(i) + 2.0 * d);
            a[i][d] = 10.0 * std::cos(0.5 + double(i) + 3.0 * d);
        }
    }
    return p;
}

// One condition named `test`, from the body of its dictionary as it appears in
// constant/boundaryConditions.
template <int Dim>
std::unique_ptr<BoundaryCondition<Dim>> condition(const std::string& body, const ParticleSet<Dim>& p) {
    const auto file =
        Dictionary::parse("boundaryConditions { test { " + body + " } }", "constant/boundaryConditions");
    return BoundaryCondition<Dim>::New(file.subDict("boundaryConditions").subDict("test"), p);
}

template <int Dim>
BoundaryConditionList<Dim> conditions(const std::string& text, const ParticleSet<Dim>& p) {
    return BoundaryConditionList<Dim>(Dictionary::parse(text, "constant/boundaryConditions"), p);
}

// The message of the InputError `f` throws, or "" if it throws none.
template <class F>
std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace mfdyn::test
