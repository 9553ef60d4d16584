#pragma once
// Weighted least-squares derivative and interpolation operators of order 1 or 2 (moving least
// squares, Lancaster & Salkauskas 1981; the generalised finite difference / finite pointset
// form, e.g. Liszka & Orkisz 1980, Onate et al. 1996), built at evaluation points x_a from their
// neighbours b among particles x_b, with one weight w_ab per pair, and rebuilt as often as the
// particles move (every step for an updated-Lagrangian method) in the memory of the previous build.
//
// Fit around x_a, in the scaled offsets s = (x_b - x_a) / h_a (h_a the point's length scale, so
// that the moment matrix is O(1) whatever the units and the order-2 columns are as large as the
// order-1 ones):
//
//     value form:       f_b         ~ c_0 + c_1 . s + 1/2 sum_i c_ii s_i^2 + sum_{i<j} c_ij s_i s_j
//     difference form:  f_b - f_a   ~       c_1 . s + 1/2 sum_i c_ii s_i^2 + sum_{i<j} c_ij s_i s_j
//
// (order 1 stops after c_1), minimising sum_b w_ab (fit - data)^2. With p_b the basis row and
// M_a = sum_b w_ab p_b p_b^T the moment matrix, c = M_a^-1 sum_b w_ab p_b data_b, so each pair
// gets the coefficient weights phi_ab = w_ab M_a^-1 p_b, computed once per point and applied to
// any field by one sum over the row:
//
//     f(x_a)        = sum_b phi_ab[0] f_b                       (value form only)
//     grad f(x_a)   = sum_b G_ab (f_b [- f_a]),   G_ab = phi_ab[c_1] / h_a
//     Hess f(x_a)   = sum_b H_ab (f_b [- f_a]),   H_ab = phi_ab[c_ij] / h_a^2 (symmetric)
//     Lap f(x_a)    = sum_b tr(H_ab) (f_b [- f_a])
//
// Exactness: every polynomial of the basis degree is reproduced to round-off wherever M_a is
// invertible (the neighbours determine the fit): order 1 gives exact gradients of linear fields,
// order 2 exact gradients, Hessians and Laplacians of quadratics, at interior and boundary
// points alike (no symmetry of the neighbourhood is assumed). The difference form needs the
// field's value at the point, so its points are the particles (point a is particle a); the value
// form works at any point and also interpolates.
//
// The weights are the caller's, per pair of the given rows (any kernel, gather or scatter h), or
// w_ab = V_b W(|x_b - x_a|, h_a) (KernelWeight::value) or w_ab = -V_b W'(r)/r
// (KernelWeight::radialDerivative, with which the order-1 difference-form gradient is the
// corrected kernel gradient of Bonet & Lok 1999 exactly: G_ab = L_a V_b grad W_b(x_a)). Weights are
// divided by their row sum before M_a is formed, which leaves phi unchanged and M_a O(1).
//
// Solve: M_a is symmetric positive semi-definite; its eigenvalues (SelfAdjointEigenSolver) give the
// reciprocal condition number lambda_min / lambda_max, and below Options::minReciprocalCondition
// (or with fewer neighbours than basis terms, or non-finite entries) the point fails: with
// OnFailure::throwError the rebuild throws an Error naming the first failing point, its position,
// its neighbour count and how many others fail; with OnFailure::flag the point's weights are zero
// and status() says why, for callers with a fallback (Interpolation falls back to Shepard).
// Otherwise M_a^-1 p_b comes from the LDLT factorisation of M_a.
//
// Fit weights by name (the finite pointset method, von Nida 2005 ch. 3; doc/methods/fpm.md §2):
// rebuild(points, x, rows, h, fitWeight) takes w_ab = W(|x_b - y_a| / h_a) of the family fitWeight
// (fitWeights/FitWeight.hpp), squared or not as the weight says, with h_a the support radius and
// the scale. Then:
//
//   * Derivative::full (value form): the gradient weights are those of the derivative of the
//     approximant c_0(y) with respect to the evaluation point y (the thesis's 3.11), with the
//     weights and the basis moving with y (h_a held fixed): with a = M^-1 e_0,
//         d phi_b[0] / dy_k = (dw_b/dy_k) a.p_b + w_b a.(dp_b/dy_k) - w_b (M^-1 (dM/dy_k) a).p_b,
//         dM/dy_k = sum_b (dw_b/dy_k) p_b p_b^T + w_b (dp_b/dy_k p_b^T + p_b dp_b/dy_k^T),
//         dp_b/dy_k = -(1/h_a) dp/ds_k,
//     so grad f(y) = sum_b (d phi_b[0] / dy) f_b. Derivative::diffuse (default) keeps the fit's
//     linear coefficients c_1 / h. Both reproduce the gradient of a linear field exactly (c_0(y)
//     is then the field itself for every y). Hessians stay the fit's coefficients either way.
//   * Fallback::growSupport: a failing point is refitted with h_a x 1.2, x 1.44, ... up to
//     x maxSupportGrowth (2): the caller's rows must hold the neighbours within
//     maxSupportGrowth h_a (weights beyond the current radius are zero), the factor taken is
//     supportFactor()[a]. The operator does not search: the rows are the caller's.
//   * Fallback::shepard (either rebuild): a failing point gets the order-0 fit, value weights
//     w_ab / sum_b w_ab and zero gradient and Hessian, status Status::shepard.
//   The fallbacks taken are counted per rebuild (fallbackCounts(), for a solver's log); a point
//   that no fallback saves fails as before (Error or flag). Options::minNeighbours (the note's
//   2(d+1)) raises the neighbour count below which a point fails, Options::tikhonov shifts M by
//   eps tr(M) I before the eigenvalue check and the solve (the note's eps ~ 1e-12: it perturbs
//   reproduction by about eps times the condition number, and its own y-derivative is left out
//   of the full derivative).
//
// Memory: the pair arrays are resized, never shrunk, so a rebuild whose neighbour counts do not
// grow reallocates nothing (capacity() is the test's handle). Points are independent
// (parallelFor): results are bit-identical for any thread count.
#include "core/Tensor.hpp"
#include "kernels/Kernel.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"
#include "particles/NeighbourList.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class LeastSquaresOperators {
public:
    enum class Form { difference, value };
    enum class OnFailure { throwError, flag };
    enum class KernelWeight { value, radialDerivative };
    enum class Status : unsigned char { ok, tooFewNeighbours, illConditioned, shepard };
    enum class Derivative { diffuse, full };
    enum class Fallback { none, growSupport, shepard };

    struct Options {
        int order = 1;  // 1: linear basis (gradient); 2: quadratic (gradient, Hessian, Laplacian)
        Form form = Form::difference;
        double minReciprocalCondition = 1e-10;
        OnFailure onFailure = OnFailure::throwError;
        Derivative derivative = Derivative::diffuse;  // full: value form and a fit weight
        Fallback fallback = Fallback::none;           // growSupport: a fit weight
        int minNeighbours = 0;                        // with a positive weight; 0: the basis size
        double tikhonov = 0.0;                        // M + tikhonov tr(M) I; in [0, 1e-3]
        double maxSupportGrowth = 2.0;                // growSupport's largest factor on h
        double supportGrowthStep = 1.2;               // and its factor per try
    };

    // Fallbacks taken by the last rebuild.
    struct FallbackCounts {
        std::size_t grown = 0;    // fitted with a grown support
        std::size_t shepard = 0;  // fitted by Shepard (order 0)
        std::size_t failed = 0;   // no fit (flagged; with throwError the rebuild threw)
    };

    explicit LeastSquaresOperators(Options options);

    // The general build: evaluation points, particle positions x, rows[a] the neighbours b of
    // point a (self may be in a row: it adds nothing to the difference form), one weight per pair
    // in row order (w >= 0), and a length scale per point (h_a > 0).
    void rebuild(const std::vector<Vector<Dim>>& points, const std::vector<Vector<Dim>>& x,
                 const NeighbourList& rows, const std::vector<double>& weights,
                 const std::vector<double>& scale);
    // Kernel weights with the point's smoothing length h_a (gather form), also the scale.
    void rebuild(const std::vector<Vector<Dim>>& points, const std::vector<Vector<Dim>>& x,
                 const NeighbourList& rows, const std::vector<double>& volume, const std::vector<double>& h,
                 const Kernel& kernel, KernelWeight shape = KernelWeight::value);
    // Fit weights by name: w_ab = weight.fitWeight(|x_b - y_a|, h_a), h_a the support radius and
    // the scale (see the top of this file; the full derivative and growSupport need this form).
    void rebuild(const std::vector<Vector<Dim>>& points, const std::vector<Vector<Dim>>& x,
                 const NeighbourList& rows, const std::vector<double>& h, const FitWeight& weight);

    const Options& options() const { return options_; }
    // Names the points in the failure messages of the rebuilds that follow: point a is "particle
    // labels[a]" (a global id, which a distributed run needs: a is the index on this process).
    // The array must outlive those rebuilds; null (the default) names points by index only.
    void labelPoints(const std::int64_t* labels) { labels_ = labels; }
    // Number of basis terms: Dim (+ Dim(Dim+1)/2 at order 2) (+ 1 in value form).
    int basisSize() const;
    std::size_t size() const { return status_.size(); }
    std::size_t pairCount() const { return indices_.size(); }
    const std::vector<std::size_t>& offsets() const { return offsets_; }
    const std::vector<NeighbourList::Index>& indices() const { return indices_; }
    const std::vector<Status>& status() const { return status_; }
    static std::string statusName(Status status);
    const FallbackCounts& fallbackCounts() const { return counts_; }
    // The factor on h_a each point was fitted with (1 unless growSupport grew it).
    const std::vector<double>& supportFactor() const { return supportFactor_; }

    // Per-pair weights (see the top of this file); zero at failed points.
    const std::vector<Vector<Dim>>& gradient() const { return gradient_; }
    const std::vector<Tensor<Dim>>& hessian() const;  // order 2
    const std::vector<double>& laplacian() const;     // order 2
    const std::vector<double>& value() const;         // value form
    // Capacity of the pair arrays: unchanged by a rebuild whose pair count does not grow.
    std::size_t capacity() const { return gradient_.capacity(); }

    // Applied to particle fields f (one value per particle; difference form: particle a's value at
    // point a). For a vector field the row index of the gradient is the component of f.
    std::vector<double> valueOf(const std::vector<double>& f) const;
    std::vector<Vector<Dim>> gradientOf(const std::vector<double>& f) const;
    std::vector<Tensor<Dim>> gradientOf(const std::vector<Vector<Dim>>& f) const;
    std::vector<Tensor<Dim>> hessianOf(const std::vector<double>& f) const;
    std::vector<double> laplacianOf(const std::vector<double>& f) const;

private:
    void checkField(std::size_t n, const char* what) const;
    // Fits point a at y with the pair weights w[k] (and dw[k] = dw/dy for the full derivative, else
    // null) and scale h: writes its pair arrays and returns ok, or returns why it failed (writing
    // nothing). Fixed-size matrices per basis (Order, Offset: 1 in the value form), chosen once
    // per rebuild by fitFunction().
    template <int Order, int Offset>
    Status fitPoint(std::size_t a, const Vector<Dim>& y, const std::vector<Vector<Dim>>& x,
                    const std::vector<double>& w, const Vector<Dim>* dw, double h);
    using FitFunction = Status (LeastSquaresOperators::*)(std::size_t, const Vector<Dim>&,
                                                          const std::vector<Vector<Dim>>&,
                                                          const std::vector<double>&, const Vector<Dim>*,
                                                          double);
    FitFunction fitFunction() const;
    void shepardPoint(std::size_t a, const std::vector<double>& w);
    void zeroPoint(std::size_t a);
    void prepare(const std::vector<Vector<Dim>>& points, const std::vector<Vector<Dim>>& x,
                 const NeighbourList& rows, const std::vector<double>& scale);
    // Counts the fallbacks and, with throwError, throws for the first failing point.
    void finish(const std::vector<Vector<Dim>>& points, const std::vector<double>& w);
    double centre(const std::vector<double>& f, std::size_t a) const {
        return options_.form == Form::difference ? f[a] : 0.0;
    }

    Options options_;
    const std::int64_t* labels_ = nullptr;
    std::size_t particles_ = 0;
    std::vector<std::size_t> offsets_;
    std::vector<NeighbourList::Index> indices_;
    std::vector<Status> status_;
    std::vector<double> weightBuffer_;        // weights of the kernel and fit-weight rebuilds
    std::vector<Vector<Dim>> dWeightBuffer_;  // their y-derivatives (full derivative)
    std::vector<double> supportFactor_;
    FallbackCounts counts_;
    std::vector<Vector<Dim>> gradient_;
    std::vector<Tensor<Dim>> hessian_;
    std::vector<double> laplacian_;
    std::vector<double> value_;
};

}  // namespace mfdyn
