#pragma once
// The engine every shape function of the family shares: a tensor product of one 1D function per
// axis, in cell units, and the fold at the grid's edges. A type supplies its 1D function as a
// Basis (LinearShapeFunction.hpp, ...):
//
//     struct Basis {
//         static constexpr int width;                // nodes per axis
//         static constexpr double supportHalfWidth;  // in cells
//         static constexpr bool needsSize;           // reads the particle's half-size (uGIMP)
//         // N and dN/dxi of the `width` nodes start, start + 1, ... (the return value) at the cell
//         // coordinate xi in [0, n], as on an unbounded grid: start may be -1 and start + width - 1
//         // may be n + 1 (the nodes outside are folded below). lp: the half-size in cells.
//         template <class T> static std::int64_t weights(T xi, double lp, std::int64_t n, T* w, T* dw);
//     };
//
// Tensor product (x fastest, so the entries come by increasing node index):
//
//     N_ijk(x) = N_i(xi) N_j(eta) N_k(zeta),   grad N_ijk = (N_i' N_j N_k / hx, N_i N_j' N_k / hy, N_i N_j N_k' / hz)
//
// Edge fold. On the unbounded grid the functions of the nodes g < 0 (or g > n) reach into the
// grid near its edges, and dropping them would break the partition of unity there. Their node
// positions are linear extrapolations of the two edge nodes, x_g = (1 - g) x_0 + g x_1 (and
// x_g = (1 + e) x_n - e x_{n-1}, e = g - n), so giving node 0 the share (1 - g) N_g and node 1
// the share g N_g (node n (1 + e) N_g, node n - 1 -e N_g) keeps sum_I N_I = 1 and sum_I N_I x_I = x
// exactly, with every node at its grid position. For the B-splines this is the boundary
// modification of Steffen, Kirby & Berzins 2008 as de Vaucorbeil et al. 2020 ("Material point
// method after 25 years", Adv. Appl. Mech. 53:185) compute it in their code Karamelo (its
// boundary node types): the folded functions are the natural splines (N'' = 0 at the edge) of the
// open knot vector's spline space, one function per node. (That space itself has n + 3 functions
// with Greville abscissae 0, 1/3, 1, ..., n - 1/3, n for the cubic, not all on nodes, so
// sum N_I x_I = x would fail with the grid's node positions in the edge cells.) Only one outside
// node is ever non-zero (the supports are at most 2 cells wide), and the grid must have at least
// width - 1 cells per axis, so the folded window start..start + width - 1 lies inside [0, n].
// The weights of the fold stay non-negative (shown in each type's .cpp).
//
// Complexity: the 1D functions are inlined into one loop over particles (parallelFor); a particle
// costs Dim 1D evaluations and width^Dim products, with no virtual call, no std::function and no
// allocation.
#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mfdyn {

namespace shapeFunctionDetail {

inline double realPart(double v) {
    return v;
}
inline double realPart(const std::complex<double>& v) {
    return v.real();
}

// floor of the real part, for the piece a point falls in (a complex-step argument takes the piece
// of its real part, so its derivative is that piece's).
template <class T>
std::int64_t floorIndex(const T& v) {
    return std::int64_t(std::floor(realPart(v)));
}

// A particle's cell coordinate may lie this far outside [0, n] (CartesianGrid::contains has the
// same tolerance); it is then evaluated at the edge.
inline constexpr double edgeTolerance = 1e-12;

// The fold described above: the window of `width` weights from node `start` of the unbounded
// grid becomes a window inside [0, n] (n >= width - 1); returns its first node.
template <int width, class T>
std::int64_t foldIntoGrid(std::int64_t start, std::int64_t n, T* w, T* dw) {
    if (start >= 0 && start + width - 1 <= n) return start;
    const std::int64_t first = std::clamp<std::int64_t>(start, 0, n - width + 1);
    T fw[width]{}, fdw[width]{};
    for (int k = 0; k < width; ++k) {
        const std::int64_t g = start + k;
        if (g < 0) {
            const double a = 1.0 - double(g), b = double(g);
            fw[0 - first] += a * w[k];
            fw[1 - first] += b * w[k];
            fdw[0 - first] += a * dw[k];
            fdw[1 - first] += b * dw[k];
        } else if (g > n) {
            const double e = double(g - n);
            fw[n - first] += (1.0 + e) * w[k];
            fw[n - 1 - first] -= e * w[k];
            fdw[n - first] += (1.0 + e) * dw[k];
            fdw[n - 1 - first] -= e * dw[k];
        } else {
            fw[g - first] += w[k];
            fdw[g - first] += dw[k];
        }
    }
    for (int k = 0; k < width; ++k) {
        w[k] = fw[k];
        dw[k] = fdw[k];
    }
    return first;
}

constexpr std::size_t power(std::size_t base, int exponent) {
    return exponent == 0 ? 1 : base * power(base, exponent - 1);
}

template <int Dim>
std::string vectorText(const Vector<Dim>& v) {
    std::ostringstream s;
    s.precision(12);
    s << '(';
    for (int d = 0; d < Dim; ++d) s << (d ? " " : "") << v[d];
    s << ')';
    return s.str();
}

}  // namespace shapeFunctionDetail

template <int Dim, class Basis>
class TensorProductShapeFunction : public ShapeFunction<Dim> {
public:
    static constexpr int width = Basis::width;
    static constexpr std::size_t stride = shapeFunctionDetail::power(Basis::width, Dim);

    double supportHalfWidth() const override { return Basis::supportHalfWidth; }
    int nodesPerAxis() const override { return width; }
    bool needsParticleSize() const override { return Basis::needsSize; }

    void evaluate(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
                  std::span<const Vector<Dim>> halfSize, ParticleNodeList<Dim>& list) const override;

    std::int64_t axisWeights(std::complex<double> xi, double halfSizeInCells, std::int64_t cells,
                             std::span<std::complex<double>> N,
                             std::span<std::complex<double>> dNdxi) const override {
        if (N.size() < std::size_t(width) || dNdxi.size() < std::size_t(width))
            throw std::invalid_argument("axisWeights: spans shorter than nodesPerAxis()");
        std::complex<double> w[width]{}, dw[width]{};
        const std::int64_t start = Basis::weights(xi, halfSizeInCells, cells, w, dw);
        const std::int64_t first = shapeFunctionDetail::foldIntoGrid<width>(start, cells, w, dw);
        for (int k = 0; k < width; ++k) {
            N[k] = w[k];
            dNdxi[k] = dw[k];
        }
        return first;
    }

private:
    std::string badParticleMessage(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
                                   std::span<const Vector<Dim>> halfSize, std::size_t p) const;
};

template <int Dim, class Basis>
void TensorProductShapeFunction<Dim, Basis>::evaluate(const CartesianGrid<Dim>& grid,
                                                      std::span<const Vector<Dim>> x,
                                                      std::span<const Vector<Dim>> halfSize,
                                                      ParticleNodeList<Dim>& list) const {
    using namespace shapeFunctionDetail;
    if (const std::string problem = this->gridProblem(grid); !problem.empty()) throw Error(problem);
    const std::size_t n = x.size();
    if constexpr (Basis::needsSize) {
        if (halfSize.size() != n)
            throw Error("shape function " + this->type() + " needs every particle's half-size: got " +
                        std::to_string(halfSize.size()) + " for " + std::to_string(n) + " particles");
    }
    list.resize(n, stride);

    std::array<double, Dim> origin, inverseCell, upper;
    std::array<std::int64_t, Dim> cells, nodeStride;
    for (int d = 0; d < Dim; ++d) {
        origin[d] = grid.origin()[d];
        inverseCell[d] = 1.0 / grid.cellSize(d);
        cells[d] = grid.cells()[d];
        upper[d] = double(cells[d]);
        nodeStride[d] = d == 0 ? 1 : nodeStride[d - 1] * (cells[d - 1] + 1);
    }

    // The lowest bad index, the same for any thread count: the error names it.
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    std::atomic<std::size_t> firstBad{none};
    std::uint32_t* count = list.count.data();
    std::int64_t* nodes = list.node.data();
    double* weights = list.weight.data();
    Vector<Dim>* gradients = list.gradient.data();

    parallelFor(n, [&](std::size_t p) {
        std::int64_t first[Dim];
        double w[Dim][width], dw[Dim][width];
        for (int d = 0; d < Dim; ++d) {
            double xi = (x[p][d] - origin[d]) * inverseCell[d];
            double lp = 0.0;
            if constexpr (Basis::needsSize) lp = halfSize[p][d] * inverseCell[d];
            // Negated tests, so that a NaN is bad too.
            bool bad = !(xi >= -edgeTolerance && xi <= upper[d] + edgeTolerance);
            if constexpr (Basis::needsSize) bad = bad || !(lp > 0.0 && lp <= 0.5 + edgeTolerance);
            if (bad) {
                count[p] = 0;
                std::size_t seen = firstBad.load(std::memory_order_relaxed);
                while (p < seen && !firstBad.compare_exchange_weak(seen, p, std::memory_order_relaxed)) {
                }
                return;
            }
            xi = std::clamp(xi, 0.0, upper[d]);
            lp = std::min(lp, 0.5);
            const std::int64_t start = Basis::weights(xi, lp, cells[d], w[d], dw[d]);
            first[d] = foldIntoGrid<width>(start, cells[d], w[d], dw[d]);
            for (int k = 0; k < width; ++k) dw[d][k] *= inverseCell[d];
        }
        count[p] = std::uint32_t(stride);
        const std::size_t base = p * stride;
        std::int64_t* node = nodes + base;
        double* weight = weights + base;
        Vector<Dim>* gradient = gradients + base;
        if constexpr (Dim == 1) {
            for (int i = 0; i < width; ++i) {
                node[i] = first[0] + i;
                weight[i] = w[0][i];
                gradient[i][0] = dw[0][i];
            }
        } else if constexpr (Dim == 2) {
            int e = 0;
            for (int j = 0; j < width; ++j) {
                const std::int64_t row = first[0] + (first[1] + j) * nodeStride[1];
                for (int i = 0; i < width; ++i, ++e) {
                    node[e] = row + i;
                    weight[e] = w[0][i] * w[1][j];
                    gradient[e][0] = dw[0][i] * w[1][j];
                    gradient[e][1] = w[0][i] * dw[1][j];
                }
            }
        } else {
            int e = 0;
            for (int k = 0; k < width; ++k) {
                for (int j = 0; j < width; ++j) {
                    const std::int64_t row =
                        first[0] + (first[1] + j) * nodeStride[1] + (first[2] + k) * nodeStride[2];
                    const double wjk = w[1][j] * w[2][k];
                    const double djk = dw[1][j] * w[2][k];
                    const double wjdk = w[1][j] * dw[2][k];
                    for (int i = 0; i < width; ++i, ++e) {
                        node[e] = row + i;
                        weight[e] = w[0][i] * wjk;
                        gradient[e][0] = dw[0][i] * wjk;
                        gradient[e][1] = w[0][i] * djk;
                        gradient[e][2] = w[0][i] * wjdk;
                    }
                }
            }
        }
    });
    if (const std::size_t p = firstBad.load(); p != none)
        throw Error(badParticleMessage(grid, x, halfSize, p));
}

template <int Dim, class Basis>
std::string TensorProductShapeFunction<Dim, Basis>::badParticleMessage(const CartesianGrid<Dim>& grid,
                                                                       std::span<const Vector<Dim>> x,
                                                                       std::span<const Vector<Dim>> halfSize,
                                                                       std::size_t p) const {
    using shapeFunctionDetail::vectorText;
    const std::string who = "shape function " + this->type() + ": particle " + std::to_string(p);
    bool inside = true;
    for (int d = 0; d < Dim; ++d) {
        const double xi = (x[p][d] - grid.origin()[d]) / grid.cellSize(d);
        inside = inside && xi >= -shapeFunctionDetail::edgeTolerance &&
                 xi <= double(grid.cells()[d]) + shapeFunctionDetail::edgeTolerance;
    }
    if (!inside)
        return who + " at " + vectorText<Dim>(x[p]) + " is outside the grid " +
               vectorText<Dim>(grid.origin()) + " to " + vectorText<Dim>(grid.upperCorner()) +
               " (the caller checks the particles against the grid before evaluating)";
    Vector<Dim> halfCell;
    for (int d = 0; d < Dim; ++d) halfCell[d] = 0.5 * grid.cellSize(d);
    return who + " has half-size " + vectorText<Dim>(halfSize[p]) + " m; " + this->type() +
           " takes half-sizes above 0 and at most half a cell " + vectorText<Dim>(halfCell) +
           " m (l_p = 0.5 V0^(1/Dim) <= h/2: at least one particle per cell along each axis)";
}

}  // namespace mfdyn
