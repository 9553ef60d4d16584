// Lee, Gil, Greto, Kulasegaram, Bonet 2016, eqs. 45-51 (doc/methods/tl-jst-sph.md 2.5): see the header.
#include "tlSph/MomentumProjection.hpp"

#include "core/Parallel.hpp"

#include <Eigen/Dense>
#include <array>

namespace mfdyn {

template <int Dim>
void MomentumProjection<Dim>::momentum(std::vector<Vector<Dim>>& f, const std::vector<double>& volume,
                                       const std::vector<Vector<Dim>>& xTilde, bool angular) {
    const std::size_t n = f.size();
    // Pass 1: sum V, sum V x~, sum V f.
    const auto first = GlobalReduce::exactSum<SumArray<1 + 2 * Dim>>(n, [&](std::size_t i) {
        SumArray<1 + 2 * Dim> s;
        s.s[0] = volume[i];
        for (int d = 0; d < Dim; ++d)
            s.s[1 + d] = volume[i] * xTilde[i][d], s.s[1 + Dim + d] = volume[i] * f[i][d];
        return s;
    });
    const double totalVolume = first.s[0];
    if (!(totalVolume > 0)) return;
    Vector<Dim> centroid, lambdaLin;
    for (int d = 0; d < Dim; ++d)
        centroid[d] = first.s[1 + d] / totalVolume, lambdaLin[d] = -first.s[1 + Dim + d] / totalVolume;

    if (Dim == 1 || !angular) {
        parallelFor(n, [&](std::size_t i) { f[i] += lambdaLin; });
        return;
    }
    if constexpr (Dim == 2) {
        // sum V |x'|^2 and sum V (x' x f)_z.
        const auto second = GlobalReduce::exactSum<SumArray<2>>(n, [&](std::size_t i) {
            const Vector<2> r = xTilde[i] - centroid;
            SumArray<2> s;
            s.s[0] = volume[i] * r.squaredNorm();
            s.s[1] = volume[i] * (r[0] * f[i][1] - r[1] * f[i][0]);
            return s;
        });
        const double lambda = second.s[0] > 0 ? -second.s[1] / second.s[0] : 0.0;
        parallelFor(n, [&](std::size_t i) {
            const Vector<2> r = xTilde[i] - centroid;
            f[i] += lambdaLin + lambda * Vector<2>(-r[1], r[0]);
        });
    } else if constexpr (Dim == 3) {
        // M = sum V (|x'|^2 I - x' x'^T) (symmetric: 6 entries) and b = sum V x' x f.
        const auto second = GlobalReduce::exactSum<SumArray<9>>(n, [&](std::size_t i) {
            const Vector<3> r = xTilde[i] - centroid;
            const Vector<3> m = r.cross(f[i]);
            const double v = volume[i], r2 = r.squaredNorm();
            SumArray<9> s;
            s.s = {v * (r2 - r[0] * r[0]),
                   v * (r2 - r[1] * r[1]),
                   v * (r2 - r[2] * r[2]),
                   -v * r[0] * r[1],
                   -v * r[1] * r[2],
                   -v * r[0] * r[2],
                   v * m[0],
                   v * m[1],
                   v * m[2]};
            return s;
        });
        const auto& s = second.s;
        Eigen::Matrix3d M;
        M << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
        const Eigen::Vector3d b(-s[6], -s[7], -s[8]);
        // M is positive definite unless every particle lies on one line (then the rotation about
        // that line is undetermined and least squares picks the smallest multiplier).
        const Eigen::Vector3d lambda = M.completeOrthogonalDecomposition().solve(b);
        parallelFor(n, [&](std::size_t i) {
            const Vector<3> r = xTilde[i] - centroid;
            f[i] += lambdaLin + lambda.cross(r);
        });
    }
}

template <int Dim>
void MomentumProjection<Dim>::mean(std::vector<double>& g, const std::vector<double>& volume) {
    const std::size_t n = g.size();
    const auto s = GlobalReduce::exactSum<SumArray<2>>(n, [&](std::size_t i) {
        SumArray<2> t;
        t.s = {volume[i], volume[i] * g[i]};
        return t;
    });
    if (!(s.s[0] > 0)) return;
    const double m = s.s[1] / s.s[0];
    parallelFor(n, [&](std::size_t i) { g[i] -= m; });
}

template <int Dim>
void MomentumProjection<Dim>::mean(std::vector<double>& g, const std::vector<double>& volume,
                                   const std::vector<char>& skip) {
    if (skip.empty()) return mean(g, volume);
    const std::size_t n = g.size();
    const auto s = GlobalReduce::exactSum<SumArray<2>>(n, [&](std::size_t i) {
        SumArray<2> t;
        if (!skip[i]) t.s = {volume[i], volume[i] * g[i]};
        return t;
    });
    if (!(s.s[0] > 0)) return;
    const double m = s.s[1] / s.s[0];
    parallelFor(n, [&](std::size_t i) {
        if (!skip[i]) g[i] -= m;
    });
}

template struct MomentumProjection<1>;
template struct MomentumProjection<2>;
template struct MomentumProjection<3>;

}  // namespace mfdyn
