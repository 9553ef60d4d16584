// The Euler part's pressure-gradient upwinding: see EulerPart.hpp.
#include "fpm/EulerPart.hpp"

#include "core/Parallel.hpp"
#include "fpm/ShiftedFit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace mfdyn::fpm {

namespace {

// The minimisation direction of (5.25)-(5.27): with E = tr(epsdot) I - epsdot (the 3D form of
// the note; in 2D the same expression gives E = [[e22, -e21], [-e21, e11]]), a unit s with
// s^T E s = 0 where E's extreme eigenvalues l1 < 0 < l3 (s = sqrt(l3/(l3 - l1)) e1 + sqrt(-l1/(l3 - l1)) e3),
// else the eigenvector of the eigenvalue of least magnitude.
template <int Dim>
Vector<Dim> minimisationDirection(const Tensor<Dim>& gradV) {
    const Tensor<Dim> epsdot = 0.5 * (gradV + gradV.transpose());
    const Tensor<Dim> E = epsdot.trace() * Tensor<Dim>::Identity() - epsdot;
    Eigen::SelfAdjointEigenSolver<Tensor<Dim>> eigen(E);
    const auto& l = eigen.eigenvalues();  // ascending
    const auto& e = eigen.eigenvectors();
    if (l(0) < 0 && l(Dim - 1) > 0) {
        const double span = l(Dim - 1) - l(0);
        return std::sqrt(l(Dim - 1) / span) * e.col(0) + std::sqrt(-l(0) / span) * e.col(Dim - 1);
    }
    int k = 0;
    for (int j = 1; j < Dim; ++j)
        if (std::abs(l(j)) < std::abs(l(k))) k = j;
    return e.col(k);
}

}  // namespace

template <int Dim>
EulerPart<Dim>::EulerPart(typename LeastSquaresOperators<Dim>::Options fit, UpwindOptions upwind)
    : upwind_(upwind), shifted_(shiftedFitOptions<Dim>(fit, upwind.shiftedFitCondition)) {}

template <int Dim>
void EulerPart<Dim>::upwind(const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                            const FitWeight& weight, const std::vector<double>& rho,
                            const std::vector<double>& p, const std::vector<Vector<Dim>>& v,
                            const std::vector<double>& c, const std::vector<Vector<Dim>>& gradP,
                            const std::vector<Tensor<Dim>>& gradV) {
    const std::size_t n = rows.size();  // the particles evaluated; x may hold a halo beyond
    EulerUpwind<Dim>& r = result_;
    r.divV.assign(n, 0.0);
    r.gradP.assign(n, Vector<Dim>::Zero());
    r.vCorrect.assign(n, Vector<Dim>::Zero());
    r.pCorrect.assign(n, 0.0);
    r.vUpwind.assign(v.begin(), v.begin() + std::ptrdiff_t(n));
    r.shift.assign(n, 0.0);
    r.flat = r.tooFew = 0;

    // n_i and the shift of the shifted particles; a particle whose shifted fits fail (a shifted
    // point beyond the cloud's edge) is tried again with half the shift, up to `shortenings`
    // times, then evaluated centrally.
    std::vector<Vector<Dim>> dir(n, Vector<Dim>::Zero());
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < n; ++i) {
        const double g = gradP[i].norm();
        if (upwind_.direction == UpwindDirection::central || !shifts(g, p[i], h)) {
            ++r.flat;
            r.divV[i] = gradV[i].trace();
            r.gradP[i] = gradP[i];
            continue;
        }
        dir[i] = upwind_.direction == UpwindDirection::gradient ? Vector<Dim>(gradP[i] / g)
                                                                : minimisationDirection<Dim>(gradV[i]);
        r.shift[i] =
            std::min(upwind_.deltaIsTime ? upwind_.delta * c[i] : upwind_.delta * h, upwind_.maxShift * h);
        active.push_back(i);
    }
    r.shortened = 0;
    for (int attempt = 0; attempt <= upwind_.shortenings && !active.empty(); ++attempt) {
        std::vector<std::size_t> failed = evaluate(active, dir, x, rows, h, weight, rho, p, v, c);
        for (std::size_t i : failed) r.shift[i] *= 0.5;
        if (attempt > 0) r.shortened += active.size() - failed.size();
        active = std::move(failed);
    }
    for (std::size_t i : active) {
        ++r.tooFew;
        r.shift[i] = 0;
        r.divV[i] = gradV[i].trace();
        r.gradP[i] = gradP[i];
    }
}

template <int Dim>
std::vector<std::size_t> EulerPart<Dim>::evaluate(
    const std::vector<std::size_t>& active, const std::vector<Vector<Dim>>& dir,
    const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h, const FitWeight& weight,
    const std::vector<double>& rho, const std::vector<double>& p, const std::vector<Vector<Dim>>& v,
    const std::vector<double>& c) {
    EulerUpwind<Dim>& r = result_;
    const std::size_t n = x.size(), m = active.size();
    // points y+ = x - l n (j < m) and y- = x + l n (m + j), each with particle i's row
    std::vector<Vector<Dim>> points(2 * m);
    for (std::size_t j = 0; j < m; ++j) {
        const std::size_t i = active[j];
        points[j] = x[i] - r.shift[i] * dir[i];
        points[m + j] = x[i] + r.shift[i] * dir[i];
    }
    shifted_.rebuild(points, x, shiftedRows(active, rows, 2), std::vector<double>(2 * m, h), weight);

    const std::vector<double> pS = shifted_.valueOf(p);
    const std::vector<Vector<Dim>> gpS = shifted_.gradientOf(p);
    const std::vector<Tensor<Dim>> gvS = shifted_.gradientOf(v);
    std::vector<std::vector<double>> vS(Dim);
    for (int k = 0; k < Dim; ++k) {
        std::vector<double> vk(n);
        for (std::size_t i = 0; i < n; ++i) vk[i] = v[i](k);
        vS[std::size_t(k)] = shifted_.valueOf(vk);
    }
    const auto& status = shifted_.status();
    using Status = typename LeastSquaresOperators<Dim>::Status;
    std::vector<std::size_t> failed;
    for (std::size_t j = 0; j < m; ++j) {
        const std::size_t i = active[j], a = j, b = m + j;  // y+ and y- of the particle
        if (status[a] != Status::ok || status[b] != Status::ok) {
            failed.push_back(i);
            continue;
        }
        const Vector<Dim>& nn = dir[i];
        const double rc = rho[i] * c[i];
        const Tensor<Dim> dGv = 0.5 * (gvS[a] - gvS[b]);  // (Pi+ - Pi-) grad v / 2
        const Vector<Dim> dGp = 0.5 * (gpS[a] - gpS[b]);
        r.divV[i] = 0.5 * (gvS[a].trace() + gvS[b].trace()) + nn.dot(dGp) / rc;
        r.gradP[i] = 0.5 * (gpS[a] + gpS[b]) + rc * nn.dot(dGv * nn) * nn;
        r.vCorrect[i] = (0.5 * (pS[a] - pS[b]) / rc) * nn;
        double dv = 0;
        for (int k = 0; k < Dim; ++k) {
            dv += 0.5 * (vS[std::size_t(k)][a] - vS[std::size_t(k)][b]) * nn(k);
            r.vUpwind[i](k) = 0.5 * (vS[std::size_t(k)][a] + vS[std::size_t(k)][b]);
        }
        r.vUpwind[i] += r.vCorrect[i];
        r.pCorrect[i] = rc * dv;
    }
    return failed;
}

template <int Dim>
void EulerPart<Dim>::advance(double dt, std::vector<double>& rho, std::vector<Vector<Dim>>& v,
                             std::vector<double>& p, std::vector<double>* e,
                             const std::vector<double>& c) const {
    const EulerUpwind<Dim>& r = result_;
    parallelFor(r.divV.size(), [&](std::size_t i) {  // the particles of the last upwind()
        const double rho0 = rho[i], p0 = p[i], div = r.divV[i];
        rho[i] = rho0 - dt * rho0 * div;
        v[i] -= (dt / rho0) * r.gradP[i];
        p[i] = p0 - dt * rho0 * c[i] * c[i] * div;
        if (e) (*e)[i] -= dt * p0 * div / rho0;
    });
}

template class EulerPart<1>;
template class EulerPart<2>;
template class EulerPart<3>;

}  // namespace mfdyn::fpm
