#include "meshfreeOperators/ReferenceOperators.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "meshfreeOperators/PointText.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"
#include "particles/NeighbourSearch.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace mfdyn {

GradientCorrection gradientCorrectionFromName(const Dictionary& dict, const std::string& key) {
    const auto name = dict.get<std::string>(key);
    if (name == "corrected") return GradientCorrection::corrected;
    if (name == "uncorrected") return GradientCorrection::uncorrected;
    if (name == "correctedKernel") return GradientCorrection::correctedKernel;
    throw dict.error(key, "unknown gradient correction '" + name +
                              "'; valid names: corrected, uncorrected, correctedKernel");
}

std::string gradientCorrectionName(GradientCorrection correction) {
    switch (correction) {
        case GradientCorrection::corrected:
            return "corrected";
        case GradientCorrection::uncorrected:
            return "uncorrected";
        case GradientCorrection::correctedKernel:
            return "correctedKernel";
    }
    return "unknown";
}

namespace {

// Below this reciprocal condition number a correction matrix counts as singular.
constexpr double minReciprocalCondition = 1e-8;

// Per-particle failure codes, set inside parallel loops (an exception must not leave an OpenMP
// region) and turned into an Error for the lowest failing index afterwards.
enum Failure : unsigned char {
    none = 0,
    noNeighbours,
    asymmetric,
    gradientMatrix,
    kernelMatrix,
    laplacianMatrix
};

template <int N>
bool wellConditioned(const Eigen::Matrix<double, N, N>& m) {
    if (!m.allFinite()) return false;
    const Eigen::JacobiSVD<Eigen::Matrix<double, N, N>> svd(m);
    const auto& s = svd.singularValues();
    return s(0) > 0.0 && s(N - 1) >= minReciprocalCondition * s(0);
}

template <int Dim>
void throwFirstFailure(const std::vector<unsigned char>& failure, const std::vector<Vector<Dim>>& X,
                       const NeighbourList& list, double h, double support) {
    const auto it = std::find_if(failure.begin(), failure.end(), [](unsigned char f) { return f != none; });
    if (it == failure.end()) return;
    const std::size_t a = std::size_t(it - failure.begin());
    const std::size_t count =
        std::size_t(std::count_if(failure.begin(), failure.end(), [](unsigned char f) { return f != none; }));
    std::string what;
    switch (*it) {
        case noNeighbours:
            what = "has no neighbour within the support radius";
            break;
        case asymmetric:
            what = "is in an asymmetric neighbour pair (internal error)";
            break;
        case gradientMatrix:
            what = "has a singular or ill-conditioned gradient correction matrix L_a";
            break;
        case kernelMatrix:
            what = "has a singular or ill-conditioned kernel correction matrix (beta_a)";
            break;
        default:
            what = "has a singular or ill-conditioned corrected-Laplacian system";
            break;
    }
    std::ostringstream msg;
    msg << "ReferenceOperators: particle " << a << " at X = " << pointText<Dim>(X[a]) << " " << what << " ("
        << list.rowSize(a) << " neighbours within " << support << " = supportRadius(h = " << h << ")";
    if (count > 1) msg << "; " << count - 1 << " more particles fail alike";
    msg << "). Too few neighbours, or all on a line or plane: increase h relative to the particle spacing"
           " (h = 1.2-1.3 dx is usual), or remove isolated particles.";
    throw Error(msg.str());
}

}  // namespace

template <int Dim>
ReferenceOperators<Dim>::ReferenceOperators(const std::vector<Vector<Dim>>& X,
                                            const std::vector<double>& volume, double h, const Kernel& kernel,
                                            Options options)
    : X_(X), volume_(volume), h_(h), options_(options) {
    const std::size_t n = X_.size();
    if (volume_.size() != n)
        throw Error("ReferenceOperators: " + std::to_string(volume_.size()) + " volumes for " +
                    std::to_string(n) + " particles");
    if (!(h > 0.0) || !std::isfinite(h))
        throw Error("ReferenceOperators: smoothing length h = " + std::to_string(h) + " must be positive");
    for (std::size_t a = 0; a < n; ++a)
        if (!(volume_[a] > 0.0) || !std::isfinite(volume_[a]))
            throw Error("ReferenceOperators: particle " + std::to_string(a) +
                        " at X = " + pointText<Dim>(X_[a]) + " has volume " + std::to_string(volume_[a]) +
                        "; volumes must be positive");
    if (n == 0) return;

    const double support = kernel.supportRadius(h);
    NeighbourSearchOptions searchOptions;
    searchOptions.criterion = PairCriterion::either;
    searchOptions.includeSelf = false;
    searchOptions.sortRows = true;  // the mirror look-up below bisects rows
    NeighbourSearch<Dim> search({}, searchOptions);
    list_ = search.build(X_, support);
    // Options::order: every row in increasing key (the bisection below compares keys).
    const std::int64_t* key = options_.order.empty() ? nullptr : options_.order.data();
    if (key) {
        if (options_.order.size() != n)
            throw Error("ReferenceOperators: " + std::to_string(options_.order.size()) + " order keys for " +
                        std::to_string(n) + " particles");
        list_.sortRowsBy(key);
    }

    const auto& offsets = list_.offsets();
    const auto& indices = list_.indices();
    const std::size_t pairs = list_.pairCount();
    const KernelEvaluator<Dim> W = kernel.evaluator<Dim>();
    std::vector<unsigned char> failure(n, none);

    // The rows computed (Options::interior): the interior points' and their neighbours'.
    std::vector<char> active(n, 1);
    if (options_.interior < n) {
        std::fill(active.begin(), active.end(), 0);
        for (std::size_t a = 0; a < options_.interior; ++a) {
            active[a] = 1;
            for (const NeighbourList::Index b : list_[a]) active[b] = 1;
        }
    }

    // The order-1 least-squares gradient on the reference rows (difference form), with failures
    // flagged so that they are reported below in this class's words. Same threshold as the
    // matrices checked here: the scaled moment matrix has the eigenvalue ratio of the unscaled one.
    using LeastSquares = LeastSquaresOperators<Dim>;
    auto leastSquaresGradient = [&](typename LeastSquares::KernelWeight shape) {
        typename LeastSquares::Options fit;
        fit.order = 1;
        fit.form = LeastSquares::Form::difference;
        fit.minReciprocalCondition = minReciprocalCondition;
        fit.onFailure = LeastSquares::OnFailure::flag;
        LeastSquares ops(fit);
        ops.rebuild(X_, X_, list_, volume_, std::vector<double>(n, h), kernel, shape);
        return ops;
    };

    // Mirror pairs: the list is symmetric (one support radius), so a is in row b.
    mirror_.assign(pairs, 0);
    parallelFor(n, [&](std::size_t a) {
        if (!active[a]) return;
        if (list_.rowSize(a) == 0) failure[a] = noNeighbours;
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            const auto begin = indices.begin() + std::ptrdiff_t(offsets[b]);
            const auto end = indices.begin() + std::ptrdiff_t(offsets[b + 1]);
            const auto it = key ? std::lower_bound(begin, end, NeighbourList::Index(a),
                                                   [&](NeighbourList::Index x, NeighbourList::Index y) {
                                                       return key[x] < key[y] || (key[x] == key[y] && x < y);
                                                   })
                                : std::lower_bound(begin, end, NeighbourList::Index(a));
            if (it == end || *it != a)
                failure[a] = asymmetric;
            else
                mirror_[k] = std::size_t(it - indices.begin());
        }
    });
    throwFirstFailure<Dim>(failure, X_, list_, h, support);

    // Plain kernel gradients grad W_b(X_a) and values W_b(X_a) per pair.
    std::vector<Vector<Dim>> plainGradient(pairs);
    std::vector<double> value(pairs);
    parallelFor(n, [&](std::size_t a) {
        if (!active[a]) return;
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const Vector<Dim> r = X_[a] - X_[indices[k]];
            const double d = r.norm();
            const auto wv = W.evaluate(d, h);
            value[k] = wv.W;
            plainGradient[k] = d > 0.0 ? Vector<Dim>(r * (wv.dWdr / d)) : Vector<Dim>::Zero();
        }
    });

    // Corrected kernel: alpha_a, beta_a with sums including self (r = 0, W(0)).
    const bool needKernel =
        options_.correctedKernel || options_.gradient == GradientCorrection::correctedKernel;
    std::vector<double> alpha;
    std::vector<Vector<Dim>> beta;
    if (needKernel) {
        alpha.assign(n, 0.0);
        beta.assign(n, Vector<Dim>::Zero());
        const double W0 = W.W(0.0, h);
        // beta_a = -[sum V W r (x) r]^-1 sum V W r is the sum over the row of the order-1
        // least-squares gradient weights with w_ab = V_b W_b(X_a) (r_ab = -(X_b - X_a)).
        const LeastSquares kernelFit = leastSquaresGradient(LeastSquares::KernelWeight::value);
        parallelFor(n, [&](std::size_t a) {
            if (!active[a]) return;
            if (kernelFit.status()[a] != LeastSquares::Status::ok) {
                failure[a] = kernelMatrix;
                return;
            }
            Vector<Dim> be = Vector<Dim>::Zero();
            for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) be += kernelFit.gradient()[k];
            double sum = volume_[a] * W0;
            for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k)
                sum += volume_[indices[k]] * value[k] * (1.0 + be.dot(X_[a] - X_[indices[k]]));
            beta[a] = be;
            alpha[a] = 1.0 / sum;
        });
        throwFirstFailure<Dim>(failure, X_, list_, h, support);
        if (options_.correctedKernel) {
            correctedKernel_.assign(pairs, 0.0);
            correctedKernelSelf_.assign(n, 0.0);
            parallelFor(n, [&](std::size_t a) {
                correctedKernelSelf_[a] = alpha[a] * W0;
                for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k)
                    correctedKernel_[k] = alpha[a] * (1.0 + beta[a].dot(X_[a] - X_[indices[k]])) * value[k];
            });
        }
    }

    // Gradient.
    std::optional<LeastSquares> correctedFit;
    if (options_.gradient == GradientCorrection::corrected)
        correctedFit.emplace(leastSquaresGradient(LeastSquares::KernelWeight::radialDerivative));
    gradient_.assign(pairs, Vector<Dim>::Zero());
    parallelFor(n, [&](std::size_t a) {
        if (!active[a]) return;
        const std::size_t k0 = offsets[a], k1 = offsets[a + 1];
        if (options_.gradient == GradientCorrection::uncorrected) {
            for (std::size_t k = k0; k < k1; ++k) gradient_[k] = plainGradient[k];
            return;
        }
        if (options_.gradient == GradientCorrection::corrected) {
            // L_a grad W_b(X_a) is the order-1 least-squares gradient weight with
            // w_ab = -V_b W'(r)/r, divided by V_b (applied with V_b in the sums).
            if (correctedFit->status()[a] != LeastSquares::Status::ok) {
                failure[a] = gradientMatrix;
                return;
            }
            for (std::size_t k = k0; k < k1; ++k)
                gradient_[k] = correctedFit->gradient()[k] / volume_[indices[k]];
            return;
        }
        // correctedKernel: grad W~_b(X_a) with alpha_a, beta_a frozen, then corrected by its own
        // L~_a (its vectors are not parallel to X_b - X_a, so this is not a least-squares fit).
        for (std::size_t k = k0; k < k1; ++k)
            gradient_[k] = alpha[a] * (value[k] * beta[a] +
                                       (1.0 + beta[a].dot(X_[a] - X_[indices[k]])) * plainGradient[k]);
        Tensor<Dim> M = Tensor<Dim>::Zero();
        for (std::size_t k = k0; k < k1; ++k)
            M.noalias() += volume_[indices[k]] * gradient_[k] * (X_[indices[k]] - X_[a]).transpose();
        if (!wellConditioned<Dim>(M)) {
            failure[a] = gradientMatrix;
            return;
        }
        const Tensor<Dim> L = M.inverse();
        for (std::size_t k = k0; k < k1; ++k) gradient_[k] = L * gradient_[k];
    });
    throwFirstFailure<Dim>(failure, X_, list_, h, support);

    gradientAtNeighbour_.resize(pairs);
    parallelFor(n, [&](std::size_t a) {
        if (!active[a]) return;
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k)
            gradientAtNeighbour_[k] = gradient_[mirror_[k]];
    });

    // Corrected Laplacian, solved in s = r/h so that the system is O(1) whatever the units.
    if (options_.laplacian) {
        constexpr int N = Dim + 1;
        using Matrix = Eigen::Matrix<double, N, N>;
        using Column = Eigen::Matrix<double, N, 1>;
        const double step = 1e-4 * h;
        laplacian_.assign(pairs, 0.0);
        parallelFor(n, [&](std::size_t a) {
            if (!active[a]) return;
            const std::size_t k0 = offsets[a], k1 = offsets[a + 1];
            Matrix A = Matrix::Zero();
            Column rhs = Column::Zero();
            rhs(Dim) = 2.0 * Dim;
            for (std::size_t k = k0; k < k1; ++k) {
                const Vector<Dim> r = X_[a] - X_[indices[k]];
                const double d = r.norm();
                const double dW = W.dWdr(d, h);
                const double d2W = d > step ? (W.dWdr(d + step, h) - W.dWdr(d - step, h)) / (2.0 * step)
                                            : (W.dWdr(d + step, h) - dW) / step;
                const double lap = d2W + (Dim - 1) * (d > 0.0 ? dW / d : d2W);
                laplacian_[k] = lap * h * h;  // Lap W in units of 1/h^2 until scaled back below
                const Vector<Dim> s = r / h;
                const double s2 = s.squaredNorm();
                const double V = volume_[indices[k]];
                A.template topLeftCorner<Dim, Dim>().noalias() += V * s * s.transpose();
                A.template topRightCorner<Dim, 1>() += V * s2 * s;
                A(Dim, Dim) += V * s2 * s2;
                rhs.template head<Dim>() -= V * laplacian_[k] * s;
                rhs(Dim) -= V * s2 * laplacian_[k];
            }
            A.template bottomLeftCorner<1, Dim>() = A.template topRightCorner<Dim, 1>().transpose();
            if (!wellConditioned<N>(A)) {
                failure[a] = laplacianMatrix;
                return;
            }
            const Column c = A.fullPivLu().solve(rhs);
            const double invH2 = 1.0 / (h * h);
            for (std::size_t k = k0; k < k1; ++k) {
                const Vector<Dim> s = (X_[a] - X_[indices[k]]) / h;
                laplacian_[k] =
                    (laplacian_[k] + c.template head<Dim>().dot(s) + c(Dim) * s.squaredNorm()) * invH2;
            }
        });
        throwFirstFailure<Dim>(failure, X_, list_, h, support);
    }
}

template <int Dim>
const std::vector<double>& ReferenceOperators<Dim>::laplacian() const {
    if (!options_.laplacian)
        throw Error(
            "ReferenceOperators::laplacian: built without the corrected Laplacian (Options::laplacian)");
    return laplacian_;
}

template <int Dim>
const std::vector<double>& ReferenceOperators<Dim>::correctedKernel() const {
    if (!options_.correctedKernel)
        throw Error("ReferenceOperators::correctedKernel: built without it (Options::correctedKernel)");
    return correctedKernel_;
}

template <int Dim>
const std::vector<double>& ReferenceOperators<Dim>::correctedKernelSelf() const {
    if (!options_.correctedKernel)
        throw Error("ReferenceOperators::correctedKernelSelf: built without it (Options::correctedKernel)");
    return correctedKernelSelf_;
}

template <int Dim>
void ReferenceOperators<Dim>::checkSize(std::size_t n, const char* what) const {
    if (n != size())
        throw Error(std::string("ReferenceOperators::") + what + ": " + std::to_string(n) + " values for " +
                    std::to_string(size()) + " particles");
}

template <int Dim>
std::vector<Tensor<Dim>> ReferenceOperators<Dim>::gradientOf(const std::vector<Vector<Dim>>& f) const {
    checkSize(f.size(), "gradientOf");
    const auto& offsets = list_.offsets();
    const auto& indices = list_.indices();
    std::vector<Tensor<Dim>> out(size());
    parallelFor(size(), [&](std::size_t a) {
        Tensor<Dim> G = Tensor<Dim>::Zero();
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            G.noalias() += (volume_[b] * (f[b] - f[a])) * gradient_[k].transpose();
        }
        out[a] = G;
    });
    return out;
}

template <int Dim>
std::vector<Vector<Dim>> ReferenceOperators<Dim>::gradientOf(const std::vector<double>& f) const {
    checkSize(f.size(), "gradientOf");
    const auto& offsets = list_.offsets();
    const auto& indices = list_.indices();
    std::vector<Vector<Dim>> out(size());
    parallelFor(size(), [&](std::size_t a) {
        Vector<Dim> g = Vector<Dim>::Zero();
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            g += (volume_[b] * (f[b] - f[a])) * gradient_[k];
        }
        out[a] = g;
    });
    return out;
}

template <int Dim>
std::vector<double> ReferenceOperators<Dim>::laplacianOf(const std::vector<double>& f) const {
    checkSize(f.size(), "laplacianOf");
    const auto& lap = laplacian();
    const auto& offsets = list_.offsets();
    const auto& indices = list_.indices();
    std::vector<double> out(size());
    parallelFor(size(), [&](std::size_t a) {
        double s = 0.0;
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            s += volume_[b] * (f[b] - f[a]) * lap[k];
        }
        out[a] = s;
    });
    return out;
}

template <int Dim>
std::vector<Vector<Dim>> ReferenceOperators<Dim>::laplacianOf(const std::vector<Vector<Dim>>& f) const {
    checkSize(f.size(), "laplacianOf");
    const auto& lap = laplacian();
    const auto& offsets = list_.offsets();
    const auto& indices = list_.indices();
    std::vector<Vector<Dim>> out(size());
    parallelFor(size(), [&](std::size_t a) {
        Vector<Dim> s = Vector<Dim>::Zero();
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            s += (volume_[b] * lap[k]) * (f[b] - f[a]);
        }
        out[a] = s;
    });
    return out;
}

template <int Dim>
std::vector<Vector<Dim>> ReferenceOperators<Dim>::internalForce(const std::vector<Tensor<Dim>>& P) const {
    checkSize(P.size(), "internalForce");
    const auto& offsets = list_.offsets();
    const auto& indices = list_.indices();
    std::vector<Vector<Dim>> out(size());
    parallelFor(size(), [&](std::size_t a) {
        Vector<Dim> fromNeighbours = Vector<Dim>::Zero();
        Vector<Dim> own = Vector<Dim>::Zero();
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = indices[k];
            fromNeighbours.noalias() += volume_[b] * (P[b] * gradientAtNeighbour_[k]);
            own += volume_[b] * gradient_[k];
        }
        out[a] = fromNeighbours - P[a] * own;
    });
    return out;
}

template class ReferenceOperators<1>;
template class ReferenceOperators<2>;
template class ReferenceOperators<3>;

}  // namespace mfdyn
