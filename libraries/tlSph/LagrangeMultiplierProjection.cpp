// Lee, Gil, Greto, Kulasegaram, Bonet 2016, App. B, eqs. (B.1)-(B.6) (doc/methods/tl-jst-sph.md 2.7,
// "Essential, exact"), with the projectors C_B of the roller and skew-symmetric conditions.
//
// Derivation. Let d_a = pdot~_a - pdot_a over the real particles a, w_Ba = W~_a(X_B) (zero unless
// a = B or a is a neighbour of B), and Q_B a Dim x r_B matrix of orthonormal columns spanning
// range(C_B), so C_B = Q_B Q_B^T and C_B e = 0 <=> Q_B^T e = 0. The problem
//
//     min 1/2 sum_a V_a |d_a|^2   s.t.   Q_B^T sum_a V_a w_Ba d_a = Q_B^T r_B  for every B,
//     r_B = pdot_B^pres - sum_a V_a w_Ba pdot_a,
//
// has the Lagrangian 1/2 sum V |d|^2 - sum_B mu_B . Q_B^T (sum_a V_a w_Ba d_a - r_B). Stationarity
// in d_a gives V_a d_a = sum_B V_a w_Ba Q_B mu_B: the V_a cancel, and
//
//     d_a = sum_B w_Ba Q_B mu_B                                                 (B.4)
//
// (the paper's V_B W~_a(X_B) beta_B with beta_B = C_B Q_B mu_B / V_B). Into the constraints:
//
//     sum_B' K_BB' mu_B' = Q_B^T r_B,   K_BB' = [sum_a V_a w_Ba w_B'a] Q_B^T Q_B'   (B.5, B.6)
//
// K = A V^-1 A^T with A the constraint rows, so it is symmetric positive semi-definite, and
// definite when the interpolation conditions are independent (checked: a pivot of the LDL^T
// factorisation below 1e-10 of the largest is an Error). Working in the r_B-dimensional range of
// C_B removes the unconstrained directions, in which C_B K C_B would be singular. K depends only
// on X, V and the constrained set: assembled and factorised once (Eigen SimplicialLDLT, AMD
// ordering); K_BB' is non-zero only when the supports of B and B' overlap (|X_B - X_B'| < 2 x 2h).
//
// With momentum conservation (B.2) add E d = 0, E d = sum_a V_a Phi_a^T d_a, Phi_a = [I, R(x~_a - c)]
// (R(y) nu = nu x y; in 2D nu is the z component, in 1D there is no angular part), c the
// volume-weighted centroid of x~ (about which the moment condition is equivalent to the one about
// the origin once the total force is fixed, and better conditioned). Then d_a gains Phi_a nu, and
//
//     [ K    Bm ] [mu]   [r]       Bm = A V^-1 E^T: rows Q_B^T sum_a V_a w_Ba Phi_a,
//     [ Bm^T G  ] [nu] = [0],      G  = E V^-1 E^T = sum_a V_a Phi_a^T Phi_a.
//
// Bm and G depend on x~, so they are formed per call and eliminated by the Schur complement with
// the stored factorisation: Y = K^-1 Bm (Dim + n_ang back-substitutions), mu0 = K^-1 r,
// (G - Bm^T Y) nu = -Bm^T mu0, mu = mu0 - Y nu.
//
// Costs per call: one sparse back-substitution, a gather over each constraint's stencil and a
// scatter over the particles within reach of a constraint; nothing else is touched.
#include "tlSph/LagrangeMultiplierProjection.hpp"

#include "boundaryConditions/Fixed.hpp"
#include "boundaryConditions/PrescribedVelocity.hpp"
#include "boundaryConditions/SkewSymmetricPlane.hpp"
#include "boundaryConditions/SymmetryPlane.hpp"
#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

namespace mfdyn {

namespace {

// Rigid-body modes: Dim translations and the rotations (none in 1D, 1 in 2D, 3 in 3D).
template <int Dim>
constexpr int rigidModes() {
    return Dim == 1 ? 1 : Dim == 2 ? 3 : 6;
}

// Phi(y) = [I, R(y)] with R(y) nu = nu x y.
template <int Dim>
Eigen::Matrix<double, Dim, rigidModes<Dim>()> rigidBasis(const Vector<Dim>& y) {
    Eigen::Matrix<double, Dim, rigidModes<Dim>()> phi = Eigen::Matrix<double, Dim, rigidModes<Dim>()>::Zero();
    phi.template leftCols<Dim>().setIdentity();
    if constexpr (Dim == 2) {
        phi(0, 2) = -y[1], phi(1, 2) = y[0];
    } else if constexpr (Dim == 3) {
        // nu x y = -[y]_x nu.
        phi(0, 4) = y[2], phi(0, 5) = -y[1];
        phi(1, 3) = -y[2], phi(1, 5) = y[0];
        phi(2, 3) = y[1], phi(2, 4) = -y[0];
    }
    return phi;
}

// Orthonormal basis of range(C) for a projector C (eigenvalues 0 or 1), in the first columns.
template <int Dim>
int rangeBasis(const Tensor<Dim>& C, Tensor<Dim>& Q, double threshold) {
    const Eigen::SelfAdjointEigenSolver<Tensor<Dim>> eig(Tensor<Dim>(0.5 * (C + C.transpose())));
    Q.setZero();
    int r = 0;
    for (int k = Dim - 1; k >= 0; --k)  // eigenvalues ascending: largest first
        if (eig.eigenvalues()[k] > threshold) Q.col(r++) = eig.eigenvectors().col(k);
    return r;
}

}  // namespace

template <int Dim>
struct LagrangeMultiplierProjection<Dim>::Factorisation {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
};

template <int Dim>
LagrangeMultiplierProjection<Dim>::LagrangeMultiplierProjection(const ReferenceOperators<Dim>& operators,
                                                                const std::vector<double>& volume,
                                                                std::vector<Constraint> constraints,
                                                                std::size_t realParticles)
    : n_(realParticles == allParticles ? operators.size() : realParticles),
      constraints_(std::move(constraints)),
      factorisation_(std::make_unique<Factorisation>()) {
    if (!operators.options().correctedKernel)
        throw Error(
            "LagrangeMultiplierProjection: the reference operators were built without the corrected "
            "kernel (options.correctedKernel = true is needed for W~_a(X_B))");
    if (n_ > operators.size() || volume.size() < n_)
        throw Error("LagrangeMultiplierProjection: " + std::to_string(n_) +
                    " real particles, but the operators hold " + std::to_string(operators.size()) +
                    " and the volumes " + std::to_string(volume.size()));
    V_.assign(volume.begin(), volume.begin() + long(n_));
    const std::size_t m = constraints_.size();

    // Projector bases and multiplier offsets.
    basis_.resize(m), rank_.resize(m), offset_.resize(m + 1, 0);
    std::vector<char> seen(n_, 0);
    for (std::size_t i = 0; i < m; ++i) {
        const auto& c = constraints_[i];
        if (c.particle >= n_)
            throw Error("LagrangeMultiplierProjection: constraint on particle " + std::to_string(c.particle) +
                        ", beyond the " + std::to_string(n_) + " real particles");
        if (seen[c.particle])
            throw Error("LagrangeMultiplierProjection: particle " + std::to_string(c.particle) +
                        " is constrained twice; give it one projector onto the union (projectorUnion)");
        seen[c.particle] = 1;
        const Tensor<Dim>& C = c.projector;
        const double scale = std::max(1.0, C.norm());
        if ((C - C.transpose()).norm() > 1e-10 * scale || (C * C - C).norm() > 1e-10 * scale) {
            std::ostringstream s;
            s << "LagrangeMultiplierProjection: the constraint of particle " << c.particle
              << " is not a symmetric projector (C^2 = C = C^T): " << C.reshaped().transpose();
            throw Error(s.str());
        }
        rank_[i] = rangeBasis<Dim>(C, basis_[i], 0.5);
        offset_[i + 1] = offset_[i] + std::size_t(rank_[i]);
    }
    unknowns_ = offset_[m];

    // Stencils: row B of the operators, self first, real neighbours only.
    const auto& rows = operators.neighbours();
    const auto& W = operators.correctedKernel();
    const auto& Wself = operators.correctedKernelSelf();
    stencilStart_.assign(1, 0);
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t B = constraints_[i].particle;
        stencilParticle_.push_back(B), stencilWeight_.push_back(Wself[B]);
        for (std::size_t k = rows.offsets()[B]; k < rows.offsets()[B + 1]; ++k)
            if (rows.indices()[k] < n_)
                stencilParticle_.push_back(rows.indices()[k]), stencilWeight_.push_back(W[k]);
        stencilStart_.push_back(stencilParticle_.size());
    }

    // Transposed stencils, by particle (counting sort keeps the constraints ascending per particle).
    std::vector<std::size_t> count(n_ + 1, 0);
    for (const std::size_t a : stencilParticle_) ++count[a + 1];
    for (std::size_t a = 0; a < n_; ++a) count[a + 1] += count[a];
    reachConstraint_.resize(stencilParticle_.size()), reachWeight_.resize(stencilParticle_.size());
    {
        std::vector<std::size_t> fill(count.begin(), count.end() - 1);
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t s = stencilStart_[i]; s < stencilStart_[i + 1]; ++s) {
                const std::size_t slot = fill[stencilParticle_[s]]++;
                reachConstraint_[slot] = i, reachWeight_[slot] = stencilWeight_[s];
            }
    }
    reachStart_ = std::move(count);
    for (std::size_t a = 0; a < n_; ++a)
        if (reachStart_[a + 1] > reachStart_[a]) touched_.push_back(a);

    if (unknowns_ == 0) return;
    // K_ij = M_ij Q_i^T Q_j with M_ij = sum_a V_a w_ia w_ja, row by row: through the stencil of i
    // to each particle a, then to every constraint j reaching a (a dense accumulator over j).
    std::vector<Eigen::Triplet<double>> triplets;
    std::vector<double> row(m);  // (not row(m, 0.0): a false -Wfree-nonheap-object in GCC 12)
    std::vector<char> inRow(m);
    std::vector<std::size_t> columns;
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t s = stencilStart_[i]; s < stencilStart_[i + 1]; ++s) {
            const std::size_t a = stencilParticle_[s];
            const double vw = V_[a] * stencilWeight_[s];
            for (std::size_t p = reachStart_[a]; p < reachStart_[a + 1]; ++p) {
                const std::size_t j = reachConstraint_[p];
                if (!inRow[j]) inRow[j] = 1, columns.push_back(j);
                row[j] += vw * reachWeight_[p];
            }
        }
        for (const std::size_t j : columns) {
            for (int ci = 0; ci < rank_[i]; ++ci)
                for (int cj = 0; cj < rank_[j]; ++cj)
                    triplets.emplace_back(int(offset_[i] + ci), int(offset_[j] + cj),
                                          row[j] * basis_[i].col(ci).dot(basis_[j].col(cj)));
            row[j] = 0.0, inRow[j] = 0;
        }
        columns.clear();
    }
    Eigen::SparseMatrix<double> K{long(unknowns_), long(unknowns_)};
    K.setFromTriplets(triplets.begin(), triplets.end());
    auto& ldlt = factorisation_->ldlt;
    ldlt.compute(K);
    const Eigen::VectorXd D = ldlt.info() == Eigen::Success ? ldlt.vectorD() : Eigen::VectorXd();
    if (D.size() == 0 || !(D.minCoeff() > 1e-10 * D.cwiseAbs().maxCoeff()))
        throw Error("LagrangeMultiplierProjection: the " + std::to_string(m) +
                    " interpolation constraints are linearly dependent (the multiplier matrix is singular: "
                    "smallest LDL^T pivot " +
                    std::to_string(D.size() ? D.minCoeff() : 0.0) + ", largest " +
                    std::to_string(D.size() ? D.cwiseAbs().maxCoeff() : 0.0) +
                    "); constrain fewer particles or fewer directions");
}

template <int Dim>
LagrangeMultiplierProjection<Dim>::~LagrangeMultiplierProjection() = default;
template <int Dim>
LagrangeMultiplierProjection<Dim>::LagrangeMultiplierProjection(LagrangeMultiplierProjection&&) noexcept =
    default;
template <int Dim>
LagrangeMultiplierProjection<Dim>& LagrangeMultiplierProjection<Dim>::operator=(
    LagrangeMultiplierProjection&&) noexcept = default;

template <int Dim>
void LagrangeMultiplierProjection<Dim>::checkSizes(const std::vector<Vector<Dim>>& rate,
                                                   const std::vector<Vector<Dim>>& prescribed) const {
    if (rate.size() != n_ || prescribed.size() != constraints_.size())
        throw Error("LagrangeMultiplierProjection: " + std::to_string(rate.size()) + " rates and " +
                    std::to_string(prescribed.size()) + " prescribed values, expected " + std::to_string(n_) +
                    " and " + std::to_string(constraints_.size()));
}

template <int Dim>
std::vector<Vector<Dim>> LagrangeMultiplierProjection<Dim>::interpolate(
    const std::vector<Vector<Dim>>& rate) const {
    if (rate.size() != n_)
        throw Error("LagrangeMultiplierProjection: " + std::to_string(rate.size()) + " rates, expected " +
                    std::to_string(n_));
    std::vector<Vector<Dim>> value(constraints_.size());
    parallelFor(constraints_.size(), [&](std::size_t i) {
        Vector<Dim> s = Vector<Dim>::Zero();
        for (std::size_t k = stencilStart_[i]; k < stencilStart_[i + 1]; ++k) {
            const std::size_t a = stencilParticle_[k];
            s += V_[a] * stencilWeight_[k] * rate[a];
        }
        value[i] = s;
    });
    return value;
}

template <int Dim>
std::vector<double> LagrangeMultiplierProjection<Dim>::rightHandSide(
    const std::vector<Vector<Dim>>& rate, const std::vector<Vector<Dim>>& prescribed) const {
    const auto value = interpolate(rate);
    std::vector<double> r(unknowns_);
    parallelFor(constraints_.size(), [&](std::size_t i) {
        const Vector<Dim> e = prescribed[i] - value[i];
        for (int c = 0; c < rank_[i]; ++c) r[offset_[i] + c] = basis_[i].col(c).dot(e);
    });
    return r;
}

template <int Dim>
void LagrangeMultiplierProjection<Dim>::addMultipliers(std::vector<Vector<Dim>>& rate,
                                                       const std::vector<double>& mu) const {
    parallelFor(touched_.size(), [&](std::size_t t) {
        const std::size_t a = touched_[t];
        Vector<Dim> d = Vector<Dim>::Zero();
        for (std::size_t p = reachStart_[a]; p < reachStart_[a + 1]; ++p) {
            const std::size_t i = reachConstraint_[p];
            for (int c = 0; c < rank_[i]; ++c) d += (reachWeight_[p] * mu[offset_[i] + c]) * basis_[i].col(c);
        }
        rate[a] += d;
    });
}

template <int Dim>
void LagrangeMultiplierProjection<Dim>::project(std::vector<Vector<Dim>>& rate,
                                                const std::vector<Vector<Dim>>& prescribed) const {
    checkSizes(rate, prescribed);
    if (unknowns_ == 0) return;
    const auto r = rightHandSide(rate, prescribed);
    const Eigen::VectorXd mu =
        factorisation_->ldlt.solve(Eigen::Map<const Eigen::VectorXd>(r.data(), long(r.size())));
    addMultipliers(rate, std::vector<double>(mu.data(), mu.data() + mu.size()));
}

template <int Dim>
void LagrangeMultiplierProjection<Dim>::projectConservingMomentum(
    std::vector<Vector<Dim>>& rate, const std::vector<Vector<Dim>>& prescribed,
    const std::vector<Vector<Dim>>& xTilde) const {
    checkSizes(rate, prescribed);
    if (xTilde.size() != n_)
        throw Error("LagrangeMultiplierProjection: " + std::to_string(xTilde.size()) +
                    " positions, expected " + std::to_string(n_));
    if (unknowns_ == 0) return;
    constexpr int k = rigidModes<Dim>();
    using Phi = Eigen::Matrix<double, Dim, k>;

    // The centroid and the rigid-mode Gram matrix are sums over the whole body: global, so that
    // every rank projects out the same rigid modes.
    const auto first = GlobalReduce::sum<SumArray<1 + Dim>>(n_, [&](std::size_t a) {
        SumArray<1 + Dim> s;
        s.s[0] = V_[a];
        for (int d = 0; d < Dim; ++d) s.s[1 + d] = V_[a] * xTilde[a][d];
        return s;
    });
    Vector<Dim> centroid;
    for (int d = 0; d < Dim; ++d) centroid[d] = first.s[1 + d] / first.s[0];
    const auto gram = GlobalReduce::sum<SumArray<k * k>>(n_, [&](std::size_t a) {
        const Phi phi = rigidBasis<Dim>(xTilde[a] - centroid);
        const Eigen::Matrix<double, k, k> g = V_[a] * phi.transpose() * phi;
        SumArray<k * k> s;
        for (int p = 0; p < k * k; ++p) s.s[p] = g(p / k, p % k);
        return s;
    });
    Eigen::Matrix<double, k, k> G;
    for (int p = 0; p < k * k; ++p) G(p / k, p % k) = gram.s[p];

    // Bm: rows Q_i^T sum_a V_a w_ia Phi_a.
    Eigen::MatrixXd Bm(long(unknowns_), k);
    parallelFor(constraints_.size(), [&](std::size_t i) {
        Phi s = Phi::Zero();
        for (std::size_t p = stencilStart_[i]; p < stencilStart_[i + 1]; ++p) {
            const std::size_t a = stencilParticle_[p];
            s += (V_[a] * stencilWeight_[p]) * rigidBasis<Dim>(xTilde[a] - centroid);
        }
        for (int c = 0; c < rank_[i]; ++c) Bm.row(long(offset_[i] + c)) = basis_[i].col(c).transpose() * s;
    });
    const auto r = rightHandSide(rate, prescribed);
    const auto& ldlt = factorisation_->ldlt;
    const Eigen::VectorXd mu0 = ldlt.solve(Eigen::Map<const Eigen::VectorXd>(r.data(), long(r.size())));
    const Eigen::MatrixXd Y = ldlt.solve(Bm);
    const Eigen::MatrixXd S = G - Bm.transpose() * Y;
    // S is positive definite unless the constraints already fix a rigid mode (then least squares
    // picks the smallest multiplier for it).
    const Eigen::VectorXd nu =
        S.completeOrthogonalDecomposition().solve(Eigen::VectorXd(-Bm.transpose() * mu0));
    const Eigen::VectorXd mu = mu0 - Y * nu;
    addMultipliers(rate, std::vector<double>(mu.data(), mu.data() + mu.size()));
    const Eigen::Matrix<double, k, 1> nuFixed = nu;
    parallelFor(n_, [&](std::size_t a) { rate[a] += rigidBasis<Dim>(xTilde[a] - centroid) * nuFixed; });
}

template <int Dim>
double LagrangeMultiplierProjection<Dim>::residual(const std::vector<Vector<Dim>>& rate,
                                                   const std::vector<Vector<Dim>>& prescribed) const {
    checkSizes(rate, prescribed);
    const auto value = interpolate(rate);
    const std::size_t m = constraints_.size();
    // A figure of the whole projection (tests and diagnostics compare it): global on every rank.
    const double worst = GlobalReduce::max(
        m, [&](std::size_t i) { return (constraints_[i].projector * (value[i] - prescribed[i])).norm(); });
    const double scale =
        std::max({1.0, GlobalReduce::max(m, [&](std::size_t i) { return prescribed[i].norm(); }),
                  GlobalReduce::max(n_, [&](std::size_t a) { return rate[a].norm(); })});
    return m ? worst / scale : 0.0;
}

template <int Dim>
Tensor<Dim> projectorUnion(const Tensor<Dim>& a, const Tensor<Dim>& b) {
    Tensor<Dim> Q;
    const int r = rangeBasis<Dim>(a + b, Q, 1e-6);
    if (r == Dim) return Tensor<Dim>::Identity();
    Tensor<Dim> C = Tensor<Dim>::Zero();
    for (int c = 0; c < r; ++c) C += Q.col(c) * Q.col(c).transpose();
    return C;
}

template <int Dim>
std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint> constraintsFrom(
    const BoundaryConditionList<Dim>& bcs, const ParticleSet<Dim>& particles, double t) {
    std::map<std::size_t, Tensor<Dim>> projector;
    auto add = [&](std::size_t i, const Tensor<Dim>& C) {
        auto [it, fresh] = projector.emplace(i, C);
        if (!fresh) it->second = projectorUnion<Dim>(it->second, C);
    };
    const Tensor<Dim> I = Tensor<Dim>::Identity();
    const auto& X = particles.referenceOrCurrentPosition();
    for (std::size_t k = 0; k < bcs.size(); ++k) {
        const BoundaryCondition<Dim>& bc = bcs[k];
        if (!bc.active(t)) continue;
        if (dynamic_cast<const Fixed<Dim>*>(&bc) || dynamic_cast<const PrescribedVelocity<Dim>*>(&bc)) {
            for (const std::size_t i : bc.selection().indices()) add(i, I);
        } else if (const auto* s = dynamic_cast<const SymmetryPlane<Dim>*>(&bc)) {
            const auto& plane = s->plane();
            const Tensor<Dim> C = plane.normal() * plane.normal().transpose();
            for (const std::size_t i : bc.selection().indices())
                if (std::abs(plane.signedDistance(X[i])) <= plane.tolerance()) add(i, C);
        } else if (const auto* s = dynamic_cast<const SkewSymmetricPlane<Dim>*>(&bc)) {
            const Vector<Dim>& n = s->plane().normal();
            const Tensor<Dim> C = I - n * n.transpose();
            for (const std::size_t i : s->onPlane()) add(i, C);
        }
    }
    std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint> out;
    out.reserve(projector.size());
    for (const auto& [i, C] : projector)
        if (C.norm() > 0) out.push_back({i, C});  // (1D skew-symmetric: nothing tangential)
    return out;
}

template <int Dim>
std::vector<Vector<Dim>> prescribedRates(
    const BoundaryConditionList<Dim>& bcs,
    const std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint>& constraints,
    const std::vector<double>& rho0, double t) {
    std::vector<Vector<Dim>> out(constraints.size(), Vector<Dim>::Zero());
    constexpr std::size_t none = std::size_t(-1);
    std::vector<std::size_t> index(rho0.size(), none);
    for (std::size_t c = 0; c < constraints.size(); ++c)
        if (constraints[c].particle < index.size()) index[constraints[c].particle] = c;
    for (std::size_t k = 0; k < bcs.size(); ++k) {
        const auto* pv = dynamic_cast<const PrescribedVelocity<Dim>*>(&bcs[k]);
        if (!pv || !pv->active(t)) continue;
        const Vector<Dim> acceleration = pv->acceleration(t);
        for (const std::size_t i : pv->selection().indices())
            if (i < index.size() && index[i] != none) out[index[i]] = rho0[i] * acceleration;
    }
    return out;
}

#define MFDYN_INSTANTIATE(D)                                                                              \
    template class LagrangeMultiplierProjection<D>;                                                       \
    template Tensor<D> projectorUnion<D>(const Tensor<D>&, const Tensor<D>&);                             \
    template std::vector<LagrangeMultiplierProjection<D>::Constraint> constraintsFrom<D>(                 \
        const BoundaryConditionList<D>&, const ParticleSet<D>&, double);                                  \
    template std::vector<Vector<D>> prescribedRates<D>(                                                   \
        const BoundaryConditionList<D>&, const std::vector<LagrangeMultiplierProjection<D>::Constraint>&, \
        const std::vector<double>&, double);
MFDYN_INSTANTIATE(1)
MFDYN_INSTANTIATE(2)
MFDYN_INSTANTIATE(3)
#undef MFDYN_INSTANTIATE

}  // namespace mfdyn
