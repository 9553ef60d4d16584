#include "meshfreeOperators/LeastSquaresOperators.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "meshfreeOperators/PointText.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace mfdyn {

namespace {

// The basis of order Order in Dim dimensions, with the constant term when Offset is 1 (value form):
// the row p(s) in the layout [1 (value form)] [s_i] [s_i^2 / 2] [s_i s_j, i < j], at most 10 terms
// (value form, order 2, 3D). Fixed sizes keep the per-point matrices on the stack, so a rebuild
// allocates nothing inside its parallel loop.
template <int Dim, int Order, int Offset>
struct Basis {
    static constexpr int size = Offset + Dim + (Order == 2 ? Dim * (Dim + 1) / 2 : 0);
    using Column = Eigen::Matrix<double, size, 1>;
    using Matrix = Eigen::Matrix<double, size, size>;

    static void row(const Vector<Dim>& s, Column& p) {
        if constexpr (Offset == 1) p(0) = 1.0;
        for (int i = 0; i < Dim; ++i) p(Offset + i) = s[i];
        if constexpr (Order == 2) {
            int q = Offset + Dim;
            for (int i = 0; i < Dim; ++i) p(q++) = 0.5 * s[i] * s[i];
            for (int i = 0; i < Dim; ++i)
                for (int j = i + 1; j < Dim; ++j) p(q++) = s[i] * s[j];
        }
    }

    // g_i = c . dp/ds_i: the s-gradient of the polynomial c . p(s).
    static Vector<Dim> gradientDot(const Vector<Dim>& s, const Column& c) {
        Vector<Dim> g;
        for (int i = 0; i < Dim; ++i) g[i] = c(Offset + i);
        if constexpr (Order == 2) {
            int q = Offset + Dim;
            for (int i = 0; i < Dim; ++i, ++q) g[i] += c(q) * s[i];  // d(s_i^2 / 2)/ds_i
            for (int k = 0; k < Dim; ++k)
                for (int l = k + 1; l < Dim; ++l, ++q) {
                    g[k] += c(q) * s[l];
                    g[l] += c(q) * s[k];
                }
        }
        return g;
    }

    // u += f * dp/ds_i.
    static void addDerivative(const Vector<Dim>& s, int i, double f, Column& u) {
        u(Offset + i) += f;
        if constexpr (Order == 2) {
            int q = Offset + Dim;
            u(q + i) += f * s[i];
            q += Dim;
            for (int k = 0; k < Dim; ++k)
                for (int l = k + 1; l < Dim; ++l, ++q) {
                    if (k == i) u(q) += f * s[l];
                    if (l == i) u(q) += f * s[k];
                }
        }
    }
};

}  // namespace

template <int Dim>
LeastSquaresOperators<Dim>::LeastSquaresOperators(Options options) : options_(options) {
    if (options_.order != 1 && options_.order != 2)
        throw Error("LeastSquaresOperators: order " + std::to_string(options_.order) +
                    "; valid orders: 1 (linear basis), 2 (quadratic basis)");
    if (!(options_.minReciprocalCondition > 0.0) || !(options_.minReciprocalCondition < 1.0))
        throw Error("LeastSquaresOperators: minReciprocalCondition must lie in (0, 1)");
    if (options_.derivative == Derivative::full && options_.form != Form::value)
        throw Error(
            "LeastSquaresOperators: the full derivative differentiates the fitted value c_0(y): it needs "
            "the value form");
    if (!(options_.tikhonov >= 0.0) || !(options_.tikhonov <= 1e-3))
        throw Error("LeastSquaresOperators: tikhonov must lie in [0, 1e-3] (the note's 1e-12 tr M)");
    if (!(options_.maxSupportGrowth >= 1.0) || !(options_.supportGrowthStep > 1.0))
        throw Error("LeastSquaresOperators: maxSupportGrowth must be >= 1 and supportGrowthStep > 1");
}

template <int Dim>
int LeastSquaresOperators<Dim>::basisSize() const {
    return (options_.form == Form::value ? 1 : 0) + Dim + (options_.order == 2 ? Dim * (Dim + 1) / 2 : 0);
}

template <int Dim>
std::string LeastSquaresOperators<Dim>::statusName(Status status) {
    switch (status) {
        case Status::ok:
            return "ok";
        case Status::tooFewNeighbours:
            return "too few neighbours with a positive weight for the basis";
        case Status::illConditioned:
            return "singular or ill-conditioned moment matrix";
        case Status::shepard:
            return "Shepard (order 0) fallback";
    }
    return "unknown";
}

template <int Dim>
void LeastSquaresOperators<Dim>::rebuild(const std::vector<Vector<Dim>>& points,
                                         const std::vector<Vector<Dim>>& x, const NeighbourList& rows,
                                         const std::vector<double>& volume, const std::vector<double>& h,
                                         const Kernel& kernel, KernelWeight shape) {
    if (rows.size() != points.size() || h.size() != points.size() || volume.size() != x.size())
        throw Error("LeastSquaresOperators: " + std::to_string(points.size()) + " points, " +
                    std::to_string(rows.size()) + " rows, " + std::to_string(h.size()) +
                    " smoothing lengths, " + std::to_string(x.size()) + " particles, " +
                    std::to_string(volume.size()) + " volumes");
    const auto& offsets = rows.offsets();
    const auto& indices = rows.indices();
    weightBuffer_.resize(rows.pairCount());
    const KernelEvaluator<Dim> W = kernel.evaluator<Dim>();
    parallelForWork(points.size(), rows.pairCount(), [&](std::size_t a) {
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            const double d = (points[a] - x[b]).norm();
            if (shape == KernelWeight::value) {
                weightBuffer_[k] = volume[b] * W.W(d, h[a]);
            } else {
                // W' <= 0 inside the support, so -V W'/r is a non-negative weight; self adds nothing.
                weightBuffer_[k] = d > 0.0 ? -volume[b] * W.dWdr(d, h[a]) / d : 0.0;
            }
        }
    });
    rebuild(points, x, rows, weightBuffer_, h);
}

template <int Dim>
void LeastSquaresOperators<Dim>::prepare(const std::vector<Vector<Dim>>& points,
                                         const std::vector<Vector<Dim>>& x, const NeighbourList& rows,
                                         const std::vector<double>& scale) {
    const std::size_t n = points.size();
    if (options_.form == Form::difference && n != x.size())
        throw Error("LeastSquaresOperators: the difference form evaluates at the particles (" +
                    std::to_string(x.size()) + "), not at " + std::to_string(n) + " other points");
    for (std::size_t a = 0; a < n; ++a)
        if (!(scale[a] > 0.0) || !std::isfinite(scale[a]))
            throw Error("LeastSquaresOperators: point " + std::to_string(a) + " at " +
                        pointText<Dim>(points[a]) + " has length scale " + std::to_string(scale[a]) +
                        "; it must be positive");
    for (const auto b : rows.indices())
        if (b >= x.size())
            throw Error("LeastSquaresOperators: neighbour index " + std::to_string(b) + " for " +
                        std::to_string(x.size()) + " particles");

    particles_ = x.size();
    offsets_.assign(rows.offsets().begin(), rows.offsets().end());
    indices_.assign(rows.indices().begin(), rows.indices().end());
    status_.resize(n);
    supportFactor_.assign(n, 1.0);
    const std::size_t pairs = indices_.size();
    const bool second = options_.order == 2;
    // resize keeps the capacity: no reallocation while the pair count does not grow.
    gradient_.resize(pairs);
    hessian_.resize(second ? pairs : 0);
    laplacian_.resize(second ? pairs : 0);
    value_.resize(options_.form == Form::value ? pairs : 0);
}

template <int Dim>
void LeastSquaresOperators<Dim>::zeroPoint(std::size_t a) {
    for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) {
        gradient_[k].setZero();
        if (options_.order == 2) {
            hessian_[k].setZero();
            laplacian_[k] = 0.0;
        }
        if (options_.form == Form::value) value_[k] = 0.0;
    }
}

template <int Dim>
void LeastSquaresOperators<Dim>::shepardPoint(std::size_t a, const std::vector<double>& w) {
    // Order 0: f(y) = sum_b w_b f_b / sum_b w_b, a partition of unity, with zero derivatives.
    double sum = 0.0;
    for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
        if (w[k] > 0.0) sum += w[k];
    zeroPoint(a);
    if (!(sum > 0.0) || !std::isfinite(sum)) return;  // nothing to average: the point stays failed
    status_[a] = Status::shepard;
    if (options_.form == Form::value)
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) value_[k] = w[k] > 0.0 ? w[k] / sum : 0.0;
}

template <int Dim>
typename LeastSquaresOperators<Dim>::FitFunction LeastSquaresOperators<Dim>::fitFunction() const {
    const bool valueForm = options_.form == Form::value;
    if (options_.order == 2)
        return valueForm ? &LeastSquaresOperators::fitPoint<2, 1> : &LeastSquaresOperators::fitPoint<2, 0>;
    return valueForm ? &LeastSquaresOperators::fitPoint<1, 1> : &LeastSquaresOperators::fitPoint<1, 0>;
}

template <int Dim>
template <int Order, int Offset>
typename LeastSquaresOperators<Dim>::Status LeastSquaresOperators<Dim>::fitPoint(
    std::size_t a, const Vector<Dim>& y, const std::vector<Vector<Dim>>& x,
    const std::vector<double>& weights, const Vector<Dim>* dWeights, double scale) {
    using B = Basis<Dim, Order, Offset>;
    using Matrix = typename B::Matrix;
    using Column = typename B::Column;
    constexpr int m = B::size;
    constexpr bool second = Order == 2;
    constexpr bool valueForm = Offset == 1;
    const std::size_t k0 = offsets_[a], k1 = offsets_[a + 1];
    const double invScale = 1.0 / scale;
    double sum = 0.0;
    int used = 0;
    for (std::size_t k = k0; k < k1; ++k) {
        const double w = weights[k];
        if (!(w > 0.0)) continue;
        sum += w;
        // In the difference form a pair at the point itself has p = 0 and carries nothing.
        if (valueForm || x[indices_[k]] != y) ++used;
    }
    if (used < std::max(m, options_.minNeighbours) || !std::isfinite(sum)) return Status::tooFewNeighbours;

    // Normalised weights: phi is unchanged and M is O(1). A common factor of all weights, even one
    // that varies with y, leaves c_0(y) unchanged, so the full derivative may scale dw by the same
    // 1/sum and leave d(sum)/dy out. M is symmetric: only its lower triangle is formed (rank-1
    // updates), the only part the eigenvalue solver and the LDLT factorisation read.
    const double invSum = 1.0 / sum;
    Matrix M = Matrix::Zero();
    Column p;
    for (std::size_t k = k0; k < k1; ++k) {
        const double w = weights[k];
        if (!(w > 0.0)) continue;
        B::row(Vector<Dim>((x[indices_[k]] - y) * invScale), p);
        const Column wp = (w * invSum) * p;
        for (int j = 0; j < m; ++j)
            for (int i = j; i < m; ++i) M(i, j) += wp(i) * p(j);
    }
    if (options_.tikhonov > 0.0) M.diagonal().array() += options_.tikhonov * M.trace();
    if (!M.allFinite()) return Status::illConditioned;
    const Eigen::SelfAdjointEigenSolver<Matrix> eigen(M, Eigen::EigenvaluesOnly);
    const auto& lambda = eigen.eigenvalues();  // ascending
    if (eigen.info() != Eigen::Success || !(lambda(m - 1) > 0.0) ||
        !(lambda(0) >= options_.minReciprocalCondition * lambda(m - 1)))
        return Status::illConditioned;
    const Eigen::LDLT<Matrix, Eigen::Lower> ldlt(M);

    // The full derivative's per-point vectors: a = M^-1 e_0 and v_i = M^-1 (dM/dy_i) a, dM/dy_i formed
    // as the old code did (summing (dM/dy_i) a as vectors instead moved shifted, ill-conditioned fits
    // by 3e-11 relative), dp_b/dy_i = -(1/h) dp/ds_i.
    const bool full = dWeights != nullptr;
    Column a0 = Column::Zero();
    std::array<Column, Dim> v;
    if (full) {
        Column e0 = Column::Zero();
        e0(0) = 1.0;
        a0 = ldlt.solve(e0);
        std::array<Matrix, Dim> dM;
        for (int i = 0; i < Dim; ++i) dM[i].setZero();
        for (std::size_t k = k0; k < k1; ++k) {
            const double w = weights[k];
            if (!(w > 0.0)) continue;
            const Vector<Dim> s((x[indices_[k]] - y) * invScale);
            B::row(s, p);
            for (int i = 0; i < Dim; ++i) {
                Column dp = Column::Zero();
                B::addDerivative(s, i, -invScale, dp);
                const Column wdp = (w * invSum) * dp;
                dM[i].noalias() +=
                    (dWeights[k][i] * invSum) * p * p.transpose() + wdp * p.transpose() + p * wdp.transpose();
            }
        }
        for (int i = 0; i < Dim; ++i) v[i] = ldlt.solve(dM[i] * a0);
    }
    // M^-1 once per point: phi_b = w_b M^-1 p_b is then one matrix-vector product per pair (the
    // order-1 full derivative needs no phi beyond a . p_b).
    const bool needPhi = !full || second;
    Matrix Minv = Matrix::Zero();
    if (needPhi) Minv = ldlt.solve(Matrix::Identity());

    const double invScale2 = invScale * invScale;
    for (std::size_t k = k0; k < k1; ++k) {
        const double w = weights[k];
        if (!(w > 0.0)) {  // outside the weight's support: this pair carries nothing
            gradient_[k].setZero();
            if constexpr (second) {
                hessian_[k].setZero();
                laplacian_[k] = 0.0;
            }
            if constexpr (valueForm) value_[k] = 0.0;
            continue;
        }
        const Vector<Dim> s((x[indices_[k]] - y) * invScale);
        B::row(s, p);
        const double ws = w * invSum;
        Column phi = Column::Zero();
        if (needPhi) phi.noalias() = ws * (Minv * p);
        if (full) {
            const double ap = a0.dot(p);
            const Vector<Dim> ga = B::gradientDot(s, a0);
            if constexpr (valueForm) value_[k] = ws * ap;
            for (int i = 0; i < Dim; ++i)
                gradient_[k][i] = dWeights[k][i] * invSum * ap + ws * (-invScale * ga[i] - v[i].dot(p));
        } else {
            if constexpr (valueForm) value_[k] = phi(0);
            for (int i = 0; i < Dim; ++i) gradient_[k][i] = phi(Offset + i) * invScale;
        }
        if constexpr (second) {
            Tensor<Dim>& H = hessian_[k];
            int q = Offset + Dim;
            for (int i = 0; i < Dim; ++i) H(i, i) = phi(q++) * invScale2;
            for (int i = 0; i < Dim; ++i)
                for (int j = i + 1; j < Dim; ++j) H(i, j) = H(j, i) = phi(q++) * invScale2;
            laplacian_[k] = H.trace();
        }
    }
    return Status::ok;
}

template <int Dim>
void LeastSquaresOperators<Dim>::rebuild(const std::vector<Vector<Dim>>& points,
                                         const std::vector<Vector<Dim>>& x, const NeighbourList& rows,
                                         const std::vector<double>& weights,
                                         const std::vector<double>& scale) {
    const std::size_t n = points.size();
    if (rows.size() != n || scale.size() != n || weights.size() != rows.pairCount())
        throw Error("LeastSquaresOperators: " + std::to_string(n) + " points, " +
                    std::to_string(rows.size()) + " rows, " + std::to_string(scale.size()) + " scales, " +
                    std::to_string(weights.size()) + " weights for " + std::to_string(rows.pairCount()) +
                    " pairs");
    if (options_.derivative == Derivative::full)
        throw Error("LeastSquaresOperators: the full derivative needs dW/dy: rebuild with a fitWeight");
    if (options_.fallback == Fallback::growSupport)
        throw Error("LeastSquaresOperators: growSupport re-weighs with a larger h: rebuild with a fitWeight");
    prepare(points, x, rows, scale);
    const FitFunction fit = fitFunction();
    parallelForWork(n, indices_.size(), [&](std::size_t a) {
        status_[a] = (this->*fit)(a, points[a], x, weights, nullptr, scale[a]);
        if (status_[a] == Status::ok) return;
        zeroPoint(a);
        if (options_.fallback == Fallback::shepard) shepardPoint(a, weights);
    });
    finish(points, weights);
}

template <int Dim>
void LeastSquaresOperators<Dim>::rebuild(const std::vector<Vector<Dim>>& points,
                                         const std::vector<Vector<Dim>>& x, const NeighbourList& rows,
                                         const std::vector<double>& h, const FitWeight& weight) {
    const std::size_t n = points.size();
    if (rows.size() != n || h.size() != n)
        throw Error("LeastSquaresOperators: " + std::to_string(n) + " points, " +
                    std::to_string(rows.size()) + " rows, " + std::to_string(h.size()) + " support radii");
    prepare(points, x, rows, h);
    const bool full = options_.derivative == Derivative::full;
    weightBuffer_.resize(indices_.size());
    dWeightBuffer_.resize(full ? indices_.size() : 0);
    const bool grow = options_.fallback == Fallback::growSupport;
    const FitFunction fit = fitFunction();
    parallelForWork(n, indices_.size(), [&](std::size_t a) {
        const auto weigh = [&](double radius) {
            for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) {
                const Vector<Dim> r = x[indices_[k]] - points[a];
                const double d = r.norm();
                weightBuffer_[k] = weight.fitWeight(d, radius);
                // dw/dy = dw/dd * dd/dy, dd/dy = -(x - y)/d; dW/dd = 0 at d = 0 (FitWeight's contract).
                if (full)
                    dWeightBuffer_[k] = d > 0.0
                                            ? Vector<Dim>(r * (-weight.fitWeightDerivative(d, radius) / d))
                                            : Vector<Dim>::Zero();
            }
        };
        double factor = 1.0;
        for (;;) {
            weigh(factor * h[a]);
            status_[a] = (this->*fit)(a, points[a], x, weightBuffer_, full ? dWeightBuffer_.data() : nullptr,
                                      factor * h[a]);
            if (status_[a] == Status::ok || !grow || factor >= options_.maxSupportGrowth) break;
            factor = std::min(factor * options_.supportGrowthStep, options_.maxSupportGrowth);
        }
        supportFactor_[a] = factor;
        if (status_[a] == Status::ok) return;
        zeroPoint(a);
        if (options_.fallback == Fallback::shepard) {
            weigh(h[a]);
            shepardPoint(a, weightBuffer_);
        }
    });
    finish(points, weightBuffer_);
}

template <int Dim>
void LeastSquaresOperators<Dim>::finish(const std::vector<Vector<Dim>>& points,
                                        const std::vector<double>& w) {
    counts_ = {};
    std::size_t first = status_.size();
    for (std::size_t a = 0; a < status_.size(); ++a) {
        if (status_[a] == Status::shepard) {
            ++counts_.shepard;
        } else if (status_[a] != Status::ok) {
            ++counts_.failed;
            if (first == status_.size()) first = a;
        } else if (supportFactor_[a] > 1.0) {
            ++counts_.grown;
        }
    }
    if (options_.onFailure == OnFailure::flag || counts_.failed == 0) return;
    const std::size_t a = first;
    int positive = 0;
    for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
        if (k < w.size() && w[k] > 0.0) ++positive;
    std::ostringstream msg;
    msg << "LeastSquaresOperators: point " << a;
    if (labels_) msg << " (particle " << labels_[a] << ")";
    msg << " at " << pointText<Dim>(points[a]) << " fails: " << statusName(status_[a]) << " ("
        << (offsets_[a + 1] - offsets_[a]) << " neighbours, " << positive << " with a positive weight, order "
        << options_.order << ", " << basisSize() << " basis terms";
    if (options_.minNeighbours > basisSize())
        msg << ", at least " << options_.minNeighbours << " neighbours asked";
    if (options_.fallback == Fallback::growSupport)
        msg << ", support grown to " << supportFactor_[a] << " h";
    else if (options_.fallback == Fallback::shepard)
        msg << ", no neighbour with a positive weight for the Shepard fallback";
    if (counts_.failed > 1) msg << "; " << counts_.failed - 1 << " more points fail alike";
    msg << "). Too few neighbours, or all on a line or plane: increase h relative to the particle spacing,"
           " or remove isolated particles";
    if (options_.fallback == Fallback::none)
        msg << ", or choose a fallback (growSupport: h grown up to x" << options_.maxSupportGrowth
            << " with rows that cover it; shepard: an order-0 fit with zero gradient)";
    else if (options_.fallback == Fallback::growSupport)
        msg << "; growSupport needs rows holding the neighbours within " << options_.maxSupportGrowth
            << " h, and the shepard fallback saves any point with one neighbour";
    msg << ".";
    throw Error(msg.str());
}

template <int Dim>
const std::vector<Tensor<Dim>>& LeastSquaresOperators<Dim>::hessian() const {
    if (options_.order != 2) throw Error("LeastSquaresOperators::hessian: needs order 2");
    return hessian_;
}

template <int Dim>
const std::vector<double>& LeastSquaresOperators<Dim>::laplacian() const {
    if (options_.order != 2) throw Error("LeastSquaresOperators::laplacian: needs order 2");
    return laplacian_;
}

template <int Dim>
const std::vector<double>& LeastSquaresOperators<Dim>::value() const {
    if (options_.form != Form::value) throw Error("LeastSquaresOperators::value: needs the value form");
    return value_;
}

template <int Dim>
void LeastSquaresOperators<Dim>::checkField(std::size_t n, const char* what) const {
    if (n != particles_)
        throw Error(std::string("LeastSquaresOperators::") + what + ": " + std::to_string(n) +
                    " values for " + std::to_string(particles_) + " particles");
}

template <int Dim>
std::vector<double> LeastSquaresOperators<Dim>::valueOf(const std::vector<double>& f) const {
    checkField(f.size(), "valueOf");
    const auto& v = value();
    std::vector<double> out(size());
    parallelForWork(size(), pairCount(), [&](std::size_t a) {
        double s = 0.0;
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) s += v[k] * f[indices_[k]];
        out[a] = s;
    });
    return out;
}

template <int Dim>
std::vector<Vector<Dim>> LeastSquaresOperators<Dim>::gradientOf(const std::vector<double>& f) const {
    checkField(f.size(), "gradientOf");
    std::vector<Vector<Dim>> out(size());
    parallelForWork(size(), pairCount(), [&](std::size_t a) {
        const double fa = centre(f, a);
        Vector<Dim> g = Vector<Dim>::Zero();
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) g += (f[indices_[k]] - fa) * gradient_[k];
        out[a] = g;
    });
    return out;
}

template <int Dim>
std::vector<Tensor<Dim>> LeastSquaresOperators<Dim>::gradientOf(const std::vector<Vector<Dim>>& f) const {
    checkField(f.size(), "gradientOf");
    std::vector<Tensor<Dim>> out(size());
    parallelForWork(size(), pairCount(), [&](std::size_t a) {
        const Vector<Dim> fa = options_.form == Form::difference ? f[a] : Vector<Dim>::Zero();
        Tensor<Dim> G = Tensor<Dim>::Zero();
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
            G.noalias() += (f[indices_[k]] - fa) * gradient_[k].transpose();
        out[a] = G;
    });
    return out;
}

template <int Dim>
std::vector<Tensor<Dim>> LeastSquaresOperators<Dim>::hessianOf(const std::vector<double>& f) const {
    checkField(f.size(), "hessianOf");
    const auto& H = hessian();
    std::vector<Tensor<Dim>> out(size());
    parallelForWork(size(), pairCount(), [&](std::size_t a) {
        const double fa = centre(f, a);
        Tensor<Dim> s = Tensor<Dim>::Zero();
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) s += (f[indices_[k]] - fa) * H[k];
        out[a] = s;
    });
    return out;
}

template <int Dim>
std::vector<double> LeastSquaresOperators<Dim>::laplacianOf(const std::vector<double>& f) const {
    checkField(f.size(), "laplacianOf");
    const auto& L = laplacian();
    std::vector<double> out(size());
    parallelForWork(size(), pairCount(), [&](std::size_t a) {
        const double fa = centre(f, a);
        double s = 0.0;
        for (std::size_t k = offsets_[a]; k < offsets_[a + 1]; ++k) s += (f[indices_[k]] - fa) * L[k];
        out[a] = s;
    });
    return out;
}

template class LeastSquaresOperators<1>;
template class LeastSquaresOperators<2>;
template class LeastSquaresOperators<3>;

}  // namespace mfdyn
