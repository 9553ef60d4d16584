#pragma once
// Total-Lagrangian SPH operators on the reference configuration X (doc/methods/tl-jst-sph.md 2.2; Bonet & Lok
// 1999; Lee et al. 2016 App. A), computed once at construction and never updated: the corrected
// kernel gradient, the corrected kernel, and the corrected Laplacian, each stored per pair in the
// order of the neighbour list's compressed rows, so that a gather loop over row a reads them
// contiguously with the neighbour indices.
//
// Notation: W_b(X) = W(|X - X_b|, h), r_ab = X_a - X_b, grad W_b(X_a) = W'(r) r_ab / r, V_b the
// reference volume. Rows hold the b != a with |r_ab| < supportRadius(h); self is not in the rows.
//
// Gradient, grad f(X_a) ~ sum_b V_b (f_b - f_a) (x) g_ab, with g_ab per GradientCorrection:
//   uncorrected      g_ab = grad W_b(X_a). Not first-order complete (wrong at boundaries).
//   corrected        g_ab = L_a grad W_b(X_a), L_a = [sum_b V_b grad W_b(X_a) (x) (X_b - X_a)]^-1
//                    (eq. 21). Exact for linear f = C X + d: the sum is C (L_a M_a)^T = C, M_a the
//                    bracket, in the order (grad f)_ij = sum_b V_b (f_b - f_a)_i (g_ab)_j.
//   correctedKernel  the corrected gradient of the corrected kernel (eq. 23). Implemented with alpha_a,
//                    beta_a frozen at X_a: grad W~_b(X_a) ~ alpha_a [W_b(X_a) beta_a + (1 + beta_a . r_ab)
//                    grad W_b(X_a)], then corrected as above, g_ab = L~_a grad W~_b(X_a) with
//                    L~_a = [sum_{b != a} V_b grad W~_b(X_a) (x) (X_b - X_a)]^-1. The correction makes
//                    it exact for linear fields whatever the derivatives of alpha, beta would add (the
//                    analytic gradient of W~ reproduces linear fields too, so the two agree there).
//                    The difference form over b != a is what is stored; self drops out of it.
//
// Corrected kernel (eq. 18), sums over b INCLUDING a:
//   W~_b(X_a) = alpha_a [1 + beta_a . r_ab] W_b(X_a),
//   beta_a = -[sum V_b W_b r_ab (x) r_ab]^-1 sum V_b W_b r_ab,
//   alpha_a = 1 / sum V_b W_b [1 + beta_a . r_ab],
// so that sum_b V_b W~_b(X_a) = 1 and sum_b V_b W~_b(X_a) X_b = X_a.
//
// Corrected Laplacian (App. A), L[f](X_a) ~ sum_b V_b (f_b - f_a) Lap~ W_b(X_a):
//   Lap W = W''(r) + (Dim - 1) W'(r)/r,  Lap~ W_b(X_a) = Lap W_b(X_a) + alpha_a . r_ab + beta_a |r_ab|^2,
//   with (alpha_a, beta_a) solving the (Dim+1)x(Dim+1) system
//   [sum V r(x)r, sum V |r|^2 r; (sum V |r|^2 r)^T, sum V |r|^4] [alpha; beta]
//       = [-sum V r Lap W; 2 Dim - sum V |r|^2 Lap W],
//   so that sum_b V_b r_ab Lap~ = 0 and sum_b V_b |r_ab|^2 Lap~ = 2 Dim: L is 0 on linear fields and
//   Dim on |X|^2/2 exactly (to round-off). Kernels give W and W' only; W'' is a central difference of
//   the evaluator's W' with step 1e-4 h. Its error (~1e-8 relative) changes Lap~ slightly but not
//   the two exactness conditions, which the correction enforces whatever Lap W is. Not exact for
//   every quadratic (x^2 alone is not constrained), and not symmetric: Lap~ W_b(X_a) != Lap~ W_a(X_b).
//
// Internal force (29c): T_a = sum_b V_b [P_b g_ba - P_a g_ab], with g_ba = gradientAtNeighbour(k).
// Pairwise it cancels, sum_a V_a T_a = 0, and with a linearly exact gradient
// sum_a V_a T_a (x) X_a = sum_a V_a P_a for any P ((T (x) X)_ij = T_i X_j).
//
// Particles whose correction matrix is singular or ill-conditioned (reciprocal condition number
// below 1e-8: too few neighbours, or all on a line/plane) or that have no neighbour at all stop
// the construction with an Error naming the particle index and position.
//
// The corrected gradient and beta_a are order-1 least-squares fits (LeastSquaresOperators.hpp,
// difference form): L_a V_b grad W_b(X_a) is its gradient weight with w_ab = -V_b W'(r)/r, and
// beta_a the sum over the row of its gradient weights with w_ab = V_b W_b(X_a). The
// correctedKernel gradient (its vectors are not along X_b - X_a) and the Laplacian correction (two
// moment conditions, not a fit) are computed here.
//
// Everything is computed in gather loops over rows (parallelFor): results are bit-identical for
// any thread count.
//
// A rank's share of a distributed body (issue 21; TlSphSolver): the points are its owned
// particles [0, interior), a halo of other ranks' particles and mirror images, the latter two
// cut off where the rank's reach ends. Options::interior says so: operators are computed (and
// their failures reported) only in the rows of the interior points and of their neighbours,
// which a gather over an interior row reads (gradientAtNeighbour, the Laplacian at mirror());
// the other rows keep their neighbours but zero weights. Options::order gives every point a key
// (the global id, the images after the real particles in the order a serial run makes them):
// each row lists its neighbours in increasing key, as the serial run's rows list them by index,
// so every sum over a row adds the same terms in the same order, and a halo two supports deep
// gives the interior and first-ring rows the serial run's bits.
#include "core/Dictionary.hpp"
#include "core/Tensor.hpp"
#include "kernels/Kernel.hpp"
#include "particles/NeighbourList.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mfdyn {

// Names in dictionaries: "corrected", "uncorrected", "correctedKernel".
enum class GradientCorrection { corrected, uncorrected, correctedKernel };

// The GradientCorrection named by dict's entry `key`; an unknown name is an InputError that lists
// the valid ones. A missing key is an InputError too (dict.get).
GradientCorrection gradientCorrectionFromName(const Dictionary& dict, const std::string& key);
std::string gradientCorrectionName(GradientCorrection correction);

template <int Dim>
class ReferenceOperators {
public:
    struct Options {
        GradientCorrection gradient = GradientCorrection::corrected;
        bool laplacian = true;         // corrected Laplacian weights (App. A)
        bool correctedKernel = false;  // W~ values (for interpolation / Lagrange-multiplier BCs)
        // Rows of points [0, interior) and of their neighbours are computed (default: all).
        std::size_t interior = std::size_t(-1);
        // A key per point: rows in increasing key, then index (NeighbourList::sortRowsBy) instead
        // of index alone (empty).
        std::vector<std::int64_t> order;
    };

    // X: reference positions; volume: V_a; h: uniform smoothing length; kernel: any Kernel, support
    // kernel.supportRadius(h). The kernel is used only during construction.
    ReferenceOperators(const std::vector<Vector<Dim>>& X, const std::vector<double>& volume, double h,
                       const Kernel& kernel, Options options);

    // Neighbours b != a with |X_a - X_b| < support, rows sorted by index (by Options::order when
    // given); k indexes pairs.
    const NeighbourList& neighbours() const { return list_; }
    std::size_t size() const { return X_.size(); }
    const std::vector<Vector<Dim>>& referencePositions() const { return X_; }
    const std::vector<double>& volume() const { return volume_; }
    double smoothingLength() const { return h_; }
    const Options& options() const { return options_; }

    // Per pair k = (a, b) of row a (see the top of this file).
    const std::vector<Vector<Dim>>& gradient() const { return gradient_; }
    // g_ba = grad~ W_a(X_b): gradient() at a's place in row b.
    const std::vector<Vector<Dim>>& gradientAtNeighbour() const { return gradientAtNeighbour_; }
    // k' with pair k = (a, b) and pair k' = (b, a).
    const std::vector<std::size_t>& mirror() const { return mirror_; }
    // Lap~ W_b(X_a); throws when options.laplacian is off.
    const std::vector<double>& laplacian() const;
    // W~_b(X_a) and W~_a(X_a); throw when options.correctedKernel is off.
    const std::vector<double>& correctedKernel() const;
    const std::vector<double>& correctedKernelSelf() const;

    // (grad f)_a; for a vector field the row index is the component of f.
    std::vector<Tensor<Dim>> gradientOf(const std::vector<Vector<Dim>>& f) const;
    std::vector<Vector<Dim>> gradientOf(const std::vector<double>& f) const;
    // L[f]_a, componentwise for a vector field; need options.laplacian.
    std::vector<double> laplacianOf(const std::vector<double>& f) const;
    std::vector<Vector<Dim>> laplacianOf(const std::vector<Vector<Dim>>& f) const;
    // T_a of (29c) for first Piola stresses P, one per particle.
    std::vector<Vector<Dim>> internalForce(const std::vector<Tensor<Dim>>& P) const;

private:
    void checkSize(std::size_t n, const char* what) const;

    std::vector<Vector<Dim>> X_;
    std::vector<double> volume_;
    double h_ = 0.0;
    Options options_;
    NeighbourList list_;
    std::vector<std::size_t> mirror_;
    std::vector<Vector<Dim>> gradient_;
    std::vector<Vector<Dim>> gradientAtNeighbour_;
    std::vector<double> laplacian_;
    std::vector<double> correctedKernel_;
    std::vector<double> correctedKernelSelf_;
};

}  // namespace mfdyn
