// The shear part's dimensional upwinding: see ShearPart.hpp (the equations and their source).
#include "fpm/ShearPart.hpp"

#include "core/Parallel.hpp"
#include "fpm/ShiftedFit.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn::fpm {

namespace {

template <int Dim>
std::vector<double> component(const std::vector<SymmTensor<Dim>>& S, int k) {
    std::vector<double> c(S.size());
    for (std::size_t i = 0; i < S.size(); ++i) c[i] = S[i].c[std::size_t(k)];
    return c;
}

}  // namespace

template <int Dim>
ShearPart<Dim>::ShearPart(typename LeastSquaresOperators<Dim>::Options fit, ShearOptions shear)
    : shear_(shear), shifted_(shiftedFitOptions<Dim>(fit, shear.shiftedFitCondition)) {}

template <int Dim>
std::vector<Vector<Dim>> ShearPart<Dim>::divergence(const LeastSquaresOperators<Dim>& fit,
                                                    const std::vector<SymmTensor<Dim>>& S) {
    std::vector<Vector<Dim>> div(fit.size(), Vector<Dim>::Zero());  // at the fit's points
    for (int k = 0; k < SymmTensor<Dim>::size; ++k) {
        const std::vector<Vector<Dim>> g = fit.gradientOf(component(S, k));
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j)
                if (SymmTensor<Dim>::index(i, j) == k)
                    for (std::size_t a = 0; a < div.size(); ++a) div[a](i) += g[a](j);
    }
    return div;
}

template <int Dim>
void ShearPart<Dim>::upwind(const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                            const FitWeight& weight, const std::vector<double>& rho,
                            const std::vector<Vector<Dim>>& v, const std::vector<SymmTensor<Dim>>& S,
                            const std::vector<double>& mu, const std::vector<Tensor<Dim>>& gradV,
                            const std::vector<Vector<Dim>>& divS) {
    const std::size_t n = rows.size();  // the particles evaluated; x may hold a halo beyond
    ShearUpwind<Dim>& r = result_;
    r.gradV = gradV;  // central where a particle is not shifted
    r.divS = divS;
    r.vD.assign(v.begin(), v.begin() + std::ptrdiff_t(n));
    r.vCorrect.assign(n, Vector<Dim>::Zero());
    r.shift.assign(n, 0.0);
    r.tooFew = r.unstrained = r.shortened = 0;

    // The m shifted particles (active[j] = i); their 2 d points, point (2 l + s) m + j at
    // x_i - l e_l (s = 0, Pi_l+) and x_i + l e_l (s = 1, Pi_l-).
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < n; ++i) {
        if (!(mu[i] > 0)) {
            ++r.unstrained;
            continue;
        }
        if (shear_.central) continue;  // the particle's own central values
        const double cS = std::sqrt(mu[i] / rho[i]);
        r.shift[i] = std::min(shear_.deltaIsTime ? shear_.delta * cS : shear_.delta * h, shear_.maxShift * h);
        active.push_back(i);
    }
    // A particle whose shifted fits fail (a shifted point beyond the cloud's edge, too few
    // neighbours) is tried again with half the shift, up to shortenings times, then central.
    std::vector<std::size_t> pending = std::move(active);
    for (int attempt = 0; attempt <= shear_.shortenings && !pending.empty(); ++attempt) {
        std::vector<std::size_t> failed = evaluate(pending, x, rows, h, weight, rho, v, S, mu);
        for (std::size_t i : failed) r.shift[i] *= 0.5;
        if (attempt > 0) r.shortened += pending.size() - failed.size();
        pending = std::move(failed);
    }
    for (std::size_t i : pending) {
        ++r.tooFew;
        r.shift[i] = 0;
    }
}

template <int Dim>
std::vector<std::size_t> ShearPart<Dim>::evaluate(
    const std::vector<std::size_t>& active, const std::vector<Vector<Dim>>& x, const NeighbourList& rows,
    double h, const FitWeight& weight, const std::vector<double>& rho, const std::vector<Vector<Dim>>& v,
    const std::vector<SymmTensor<Dim>>& S, const std::vector<double>& mu) {
    ShearUpwind<Dim>& r = result_;
    const std::size_t n = x.size(), m = active.size();
    constexpr std::size_t pairs = 2 * std::size_t(Dim);
    std::vector<Vector<Dim>> points(pairs * m);
    for (std::size_t q = 0; q < pairs; ++q) {
        const int l = int(q / 2);
        const double sign = q % 2 == 0 ? -1.0 : 1.0;
        for (std::size_t j = 0; j < m; ++j) {
            const std::size_t i = active[j];
            points[q * m + j] = x[i];
            points[q * m + j](l) += sign * r.shift[i];
        }
    }
    shifted_.rebuild(points, x, shiftedRows(active, rows, pairs), std::vector<double>(pairs * m, h), weight);

    // The fields at the shifted points: grad v, grad S^k, and the values of v and S^k.
    const std::vector<Tensor<Dim>> gv = shifted_.gradientOf(v);
    std::vector<std::vector<Vector<Dim>>> gs(SymmTensor<Dim>::size);
    std::vector<std::vector<double>> sv(SymmTensor<Dim>::size), vv(Dim);
    for (int k = 0; k < SymmTensor<Dim>::size; ++k) {
        const std::vector<double> Sk = component(S, k);
        gs[std::size_t(k)] = shifted_.gradientOf(Sk);
        if (shear_.correctedVelocity) sv[std::size_t(k)] = shifted_.valueOf(Sk);
    }
    for (int k = 0; k < Dim; ++k) {
        std::vector<double> vk(n);
        for (std::size_t i = 0; i < n; ++i) vk[i] = v[i](k);
        vv[std::size_t(k)] = shifted_.valueOf(vk);
    }
    const auto& status = shifted_.status();
    using Status = typename LeastSquaresOperators<Dim>::Status;
    const double invD = 1.0 / Dim;
    std::vector<std::size_t> failed;
    for (std::size_t j = 0; j < m; ++j) {
        const std::size_t i = active[j];
        const auto plus = [&](int l) { return std::size_t(2 * l) * m + j; };       // Pi_l+
        const auto minus = [&](int l) { return std::size_t(2 * l + 1) * m + j; };  // Pi_l-
        bool ok = true;
        for (int l = 0; l < Dim; ++l)
            ok = ok && status[plus(l)] == Status::ok && status[minus(l)] == Status::ok;
        if (!ok) {
            failed.push_back(i);
            continue;
        }
        const double Z = std::sqrt(mu[i] * rho[i]);
        Tensor<Dim> G = Tensor<Dim>::Zero();
        Vector<Dim> div = Vector<Dim>::Zero(), vD = Vector<Dim>::Zero(), vC = Vector<Dim>::Zero();
        for (int l = 0; l < Dim; ++l) {
            G += (0.5 * invD) * (gv[plus(l)] + gv[minus(l)]);
            for (int c = 0; c < Dim; ++c)
                vD(c) += 0.5 * invD * (vv[std::size_t(c)][plus(l)] + vv[std::size_t(c)][minus(l)]);
        }
        for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b) {
                const std::size_t k = std::size_t(SymmTensor<Dim>::index(a, b));
                double central = 0;  // (1/d) sum_l Pi_l^c d_b S^ab
                for (int l = 0; l < Dim; ++l)
                    central += 0.5 * invD * (gs[k][plus(l)](b) + gs[k][minus(l)](b));
                const double dS =
                    0.5 * (gs[k][plus(b)](b) - gs[k][minus(b)](b));  // along e_b, shifted along e_b
                const double dv = 0.5 * (gv[plus(b)](a, b) - gv[minus(b)](a, b));
                G(a, b) -= invD * dS / Z;
                div(a) += central - invD * Z * dv;
                if (shear_.correctedVelocity) vC(a) -= invD * 0.5 * (sv[k][plus(b)] - sv[k][minus(b)]) / Z;
            }
        r.gradV[i] = G;
        r.divS[i] = div;
        r.vCorrect[i] = vC;
        r.vD[i] = vD + vC;
    }
    return failed;
}

template <int Dim>
void ShearPart<Dim>::advance(double dt, const std::vector<double>& rho, std::vector<Vector<Dim>>& v,
                             std::vector<double>& p, std::vector<SymmTensor<Dim>>& S, std::vector<double>* e,
                             const std::vector<double>& g, const std::vector<double>& mu,
                             double alpha) const {
    const ShearUpwind<Dim>& r = result_;
    const bool literal = shear_.literalSoundSpeed;
    parallelFor(r.gradV.size(), [&](std::size_t i) {  // the particles of the last upwind()
        const double rho0 = rho[i], p0 = p[i];
        const SymmTensor<Dim> S0 = S[i];
        const Tensor<Dim>& G = r.gradV[i];
        const double trace = G.trace();
        double work = 0;  // S0 : sym grad v_D
        for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b) work += S0(a, b) * 0.5 * (G(a, b) + G(b, a));
        v[i] += (dt / rho0) * r.divS[i];
        p[i] = p0 + dt * (g[i] / rho0) * (work - (literal ? p0 * trace : 0.0));
        if (e) (*e)[i] += dt * work / rho0;
        for (int a = 0; a < Dim; ++a)
            for (int b = a; b < Dim; ++b)
                S[i](a, b) = S0(a, b) +
                             dt * 2.0 * mu[i] * (0.5 * (G(a, b) + G(b, a)) - (a == b ? alpha * trace : 0.0));
    });
}

template class ShearPart<1>;
template class ShearPart<2>;
template class ShearPart<3>;

}  // namespace mfdyn::fpm
