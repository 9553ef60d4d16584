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
// N_I, linear completeness sum_I N_I x_I = x_p (and sum_I grad N_I (x) x_I = I), N_I >= 0,
// everywhere inside the grid, boundary cells included (uGIMP and the B-splines are modified at
// the grid's edges so that this holds: TensorProductShapeFunction.hpp).
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"

#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace mfdyn {

// For each particle p, entries [p stride, p stride + count[p]) of node, weight and gradient
// (count[p] = stride for every type here). Entries with zero weight may be present (a fixed stride
// keeps the list branch-free). Their gradient is not always zero: a particle exactly on a node or
// cell face has a linear hat of zero weight with a one-sided slope of 1/h, and dropping that
// entry breaks sum_I grad N_I = 0 (and so momentum conservation), so never skip an entry
// for its weight. Order of the entries inside a particle: nodes by increasing index.
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

    // Half-width of the support in cells along each axis (linear 1, uGIMP 1 + l_p/h <= 1.5 (it
    // returns 1.5, its largest), quadratic B-spline 1.5, cubic B-spline 2), for a CFL or contact
    // rule. No room is needed around the particles: at the grid's edges every type folds the
    // functions of the missing outside nodes onto the edge nodes (see each .cpp), so a particle
    // anywhere in the closed box is evaluated.
    virtual double supportHalfWidth() const = 0;
    // Most nodes a particle touches along one axis (2, 3, 3, 4); the list's stride is its Dim-th power.
    virtual int nodesPerAxis() const = 0;
    // Whether evaluate() reads the particles' half-sizes (uGIMP).
    virtual bool needsParticleSize() const { return false; }
    // Fewest cells along an axis this type can work on (its nodesPerAxis() - 1: the folded edge
    // functions need that many nodes).
    int minimumCells() const { return nodesPerAxis() - 1; }
    // Empty when the grid has at least minimumCells() cells on every axis, else the reason
    // ("quadraticBSpline needs at least 2 cells along each axis; the grid has 1 along y"), for
    // the caller's InputError at its `grid` or `shapeFunction` entry; evaluate() throws Error
    // with the same text.
    std::string gridProblem(const CartesianGrid<Dim>& grid) const;

    // N and grad N of every particle (x inside the grid: the caller checks). halfSize: per
    // particle, half the particle's extent along each axis (uGIMP), else empty. Parallel over
    // particles, deterministic (each particle's entries depend on that particle alone), no
    // allocation once the list has held as many particles. Sizes the list itself. Throws Error,
    // writing nothing out of bounds, for a particle outside the grid (beyond 1e-12 of a cell, or
    // not finite: the lowest such index is named), a grid too small (gridProblem), or for uGIMP
    // a half-size missing, not positive or above half a cell.
    virtual void evaluate(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
                          std::span<const Vector<Dim>> halfSize, ParticleNodeList<Dim>& list) const = 0;

    // One axis of the tensor product, with a complex argument: the nodesPerAxis() weights N and
    // derivatives dN/dxi (per cell) of the nodes first, first + 1, ... (the return value) at the
    // cell coordinate xi = (x - origin)/h of a grid of `cells` cells along that axis, and for
    // uGIMP the half-size in cells. The same template evaluate() runs with real numbers; the
    // contract test differentiates N by the complex step, dN/dxi = Im N(xi + i e)/e with
    // e = 1e-30 (Squire & Trapp 1998), which has no cancellation, so it checks the coded
    // derivative to rounding (1e-12 and far below) where a finite difference could not.
    virtual std::int64_t axisWeights(std::complex<double> xi, double halfSizeInCells, std::int64_t cells,
                                     std::span<std::complex<double>> N,
                                     std::span<std::complex<double>> dNdxi) const = 0;

    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

extern template struct ParticleNodeList<1>;
extern template struct ParticleNodeList<2>;
extern template struct ParticleNodeList<3>;
extern template class ShapeFunction<1>;
extern template class ShapeFunction<2>;
extern template class ShapeFunction<3>;

}  // namespace mfdyn
