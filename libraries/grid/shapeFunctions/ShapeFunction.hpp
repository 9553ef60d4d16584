#pragma once
// Shape functions of grid methods: the family `shapeFunction` (linear, uGIMP, quadraticBSpline,
// cubicBSpline). A shape function maps a particle at x to the grid nodes its support touches,
// with the weights N_I(x_p) and gradients grad N_I(x_p) the particle-to-grid and grid-to-particle
// transfers use. Every type is a tensor product of a 1D function per axis (cell units), so one
// evaluation per particle and step fills a compact, fixed-stride list (ParticleNodeList) that
// both transfers read: no transfer re-evaluates a shape function.
//
// Contract (tests/unit/grid/ShapeFunctionContractTest.cpp runs it over every registered type):
// partition of unity sum_I N_I = 1, sum_I grad N_I = 0, grad N_I equal to a finite difference of
// N_I, linear completeness sum_I N_I x_I = x_p (and sum_I grad N_I (x) x_I = I), everywhere inside
// the grid, boundary cells included (B-splines are modified at the grid's edges so that this holds).
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace mfdyn {

// For each particle p, entries [p stride, p stride + count[p]) of node, weight and gradient.
// Entries with zero weight may be present (a fixed stride keeps the list branch-free); their
// gradient is then zero too. Order of the entries inside a particle: nodes by increasing index.
template <int Dim>
struct ParticleNodeList {
    std::size_t stride = 0;
    std::vector<std::uint32_t> count;
    std::vector<std::int64_t> node;
    std::vector<double> weight;
    std::vector<Vector<Dim>> gradient;

    std::size_t particles() const { return count.size(); }
    // Sizes the arrays for n particles; keeps the capacity, so a steady run allocates nothing.
    void resize(std::size_t n, std::size_t entriesPerParticle);
};

template <int Dim>
class ShapeFunction {
public:
    static constexpr const char* familyName = "shapeFunction";
    using Selector = Registry<ShapeFunction, const Dictionary&>;
    // `dict` holds `type` (shapeFunction { type cubicBSpline; }) or is the enclosing dictionary
    // with a word entry `shapeFunction cubicBSpline;`.
    static std::unique_ptr<ShapeFunction> New(const Dictionary& dict);

    virtual ~ShapeFunction() = default;

    // Half-width of the support in cells along each axis (linear 1, uGIMP 1 + l_p/h, quadratic
    // B-spline 1.5, cubic B-spline 2): the grid must have at least this much room around every
    // particle, and a CFL or contact rule may use it.
    virtual double supportHalfWidth() const = 0;
    // Most nodes a particle touches along one axis (2, 3, 3, 4); the list's stride is its Dim-th power.
    virtual int nodesPerAxis() const = 0;
    // Whether evaluate() reads the particles' half-sizes (uGIMP).
    virtual bool needsParticleSize() const { return false; }

    // N and grad N of every particle (x inside the grid: the caller checks). halfSize: per
    // particle, half the particle's extent along each axis (uGIMP), else empty. Parallel over
    // particles, deterministic.
    virtual void evaluate(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
                          std::span<const Vector<Dim>> halfSize, ParticleNodeList<Dim>& list) const = 0;

    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

}  // namespace mfdyn
