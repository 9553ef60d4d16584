// ellipticalDropError: the elliptical drop (Monaghan 1994, J. Comput. Phys. 110:399, §5; Zisis
// 2017 PhD thesis §4.5.1, Fig. 4.2; doc/methods/sph-impact.md §8.1) against its exact solution. A disc of
// radius R of incompressible, inviscid fluid with free surface and initial velocity
// v0 = (−A0 x, A0 y) stays an ellipse with semi-axes a(t) along x and b(t) along y, ab = R²:
//
//   A' = A² (a² − b²)/(a² + b²),   a' = −A a,   b' = A b,   A(0) = A0, a(0) = b(0) = R,
//   v(x, y, t) = (−A x, A y)  (about the centre)       (libraries/verification/EllipticalDrop,
//                                                         solved for R = 1 and scaled by R)
//
// so the drop shrinks along x and stretches along y; with A0 = 100, R = 1: b(0.0076) = 1.9445.
// Without `radius`, R is that of the disc the particles fill, R = (Σ m/ρ / π)^½ at the first write:
// a cubic lattice clipped to a unit disc holds N Δx² ≠ π (1264 points at Δx = 0.05: 3.16, R = 1.0029),
// and its moments give exactly this R at t = 0, so the comparison starts from zero error.
//
// Semi-axes of the particle cloud from its mass-weighted second moments about the centre of mass
// x_c = Σ m x / Σ m: for a uniform ellipse ⟨(x − x_c)²⟩ = a²/4 and ⟨(y − y_c)²⟩ = b²/4, so
//
//   a = 2 ⟨(x − x_c)²⟩^½,   b = 2 ⟨(y − y_c)²⟩^½,   ⟨f⟩ = Σ m f / Σ m.
//
// Limits of this estimator: it assumes the drop stays uniform in density and elliptical, which the
// exact solution does; points at cell centres leave out each cell's own moment (Δx²/12 per axis,
// a relative offset Δx²/6 in a: 4e-4 at Δx = 0.05, far below the test's 1-2%). The principal axes
// are taken as x and y (the problem's symmetry).
//
// errorNorms.csv (time, field, L1, L2, Linf):
//   a, b       the relative error |a − a_exact|/a_exact (one number: L1 = L2 = Linf);
//   ab         the area error |ab − a_exact b_exact|/(a_exact b_exact) (exact: ab = R²);
//   velocity   e_i = |v_i − v_exact(x_i − x_c)| over all particles, weights w = m/ρ:
//              L1 = Σ w e / Σ w,  L2 = (Σ w e² / Σ w)^½,  Linf = max e   [m/s].
// semiAxes.csv: time, a, b, aExact, bExact, ab, abExact (= R²), A (exact strain rate).
// Time is the run's time: the drop is a disc at t = 0 (a restart continues against the same clock).
//
//     drop
//     {
//         type          ellipticalDropError;
//         writeControl  timeStep;  writeInterval 100;
//         A0            100;        // 1/s, initial strain rate (default 100)
//         radius        1;          // m, initial disc radius (default 1)
//     }
#include "functionObjects/EllipticalDropError.hpp"

#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace mfdyn {

KeywordSchema EllipticalDropError::keywords() {
    return KeywordSchema("functionObject", "ellipticalDropError")
        .scalar("A0", "1/s", "initial strain rate of the velocity field (-A0 x, A0 y)")
        .greaterThan(0)
        .orDefault(100.0)
        .scalar("radius", "m", "initial drop radius (default: from the particles' mass and density)")
        .greaterThan(0)
        .optional()
        .append(functionObjectKeywords());
}

EllipticalDropError::EllipticalDropError(const Dictionary& dict, const std::string& name,
                                         const RunContext& context)
    : EllipticalDropError(keywords().read(dict), name, context) {}

EllipticalDropError::EllipticalDropError(const KeywordValues& values, const std::string& name,
                                         const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      exact_(values.scalar("A0")),
      radius_(values.optionalScalar("radius").value_or(0.0)),
      norms_(outputFile("errorNorms.csv"), name, startTime()) {
    const Dictionary& dict = values.dict();
    if (context.dimension() != 2)
        throw dict.error("type", "ellipticalDropError measures a 2D drop; this case is " +
                                     std::to_string(context.dimension()) + "D");
    if (!values.given("radius") && !context.fields().findField("density"))
        throw values.error("radius",
                           "this run has no density field to find the drop's radius from: give `radius`");
    for (const char* f : {"mass", "velocity"})
        if (!context.fields().findField(f))
            throw dict.error("type", std::string("this run has no field '") + f + "'");
    axes_ = std::make_unique<CsvFile>(
        outputFile("semiAxes.csv"),
        std::vector<std::string>{"time", "a", "b", "aExact", "bExact", "ab", "abExact", "A"}, startTime());
}

void EllipticalDropError::write() {
    const FieldStore& fields = context().fields();
    // No return on a rank with no particles: the moments below are global sums every rank must
    // reach; the row is skipped only when no rank has a particle.
    const std::size_t n = context().ownedParticles();
    const double t = context().time().value();
    const FieldBase& position = fields.field("position");
    const FieldBase& mass = fields.field("mass");
    const FieldBase& velocity = fields.field("velocity");
    const FieldBase* density = fields.findField("density");

    struct Sums {
        double m = 0, mx = 0, my = 0, mxx = 0, myy = 0, count = 0;
        Sums& operator+=(const Sums& o) {
            m += o.m, mx += o.mx, my += o.my, mxx += o.mxx, myy += o.myy, count += o.count;
            return *this;
        }
    };
    const Sums first = GlobalReduce::sum<Sums>(n, [&](std::size_t i) {
        const double m = mass.component(i, 0), x = position.component(i, 0), y = position.component(i, 1);
        return Sums{m, m * x, m * y, 0, 0, 1};
    });
    if (first.count == 0) return;  // the same on every rank
    const double xc = first.mx / first.m, yc = first.my / first.m;
    const Sums second = GlobalReduce::sum<Sums>(n, [&](std::size_t i) {
        const double m = mass.component(i, 0), dx = position.component(i, 0) - xc,
                     dy = position.component(i, 1) - yc;
        return Sums{0, 0, 0, m * dx * dx, m * dy * dy, 0};
    });
    const double a = 2.0 * std::sqrt(second.mxx / first.m), b = 2.0 * std::sqrt(second.myy / first.m);
    if (radius_ == 0) {
        const double area = GlobalReduce::sum<double>(n, [&](std::size_t i) {
            return density ? mass.component(i, 0) / density->component(i, 0) : 0.0;
        });
        radius_ = std::sqrt(area / std::numbers::pi);
    }

    const EllipticalDrop::State s = exact_.state(t);
    const double aExact = radius_ * s.a, bExact = radius_ * s.b;
    axes_->row({t, a, b, aExact, bExact, a * b, aExact * bExact, s.A});
    const double ea = std::abs(a - aExact) / aExact, eb = std::abs(b - bExact) / bExact;
    const double eab = std::abs(a * b - aExact * bExact) / (aExact * bExact);
    norms_.add(t, "a", ea, ea, ea);
    norms_.add(t, "b", eb, eb, eb);
    norms_.add(t, "ab", eab, eab, eab);

    // Velocity against v = (−A (x − x_c), A (y − y_c)); the strain rate is scale-free. Linf rides
    // in the sum as a max (+= is the combination; the MPI hook reduces with it).
    struct Norms {
        double w = 0, l1 = 0, l2 = 0, linf = 0;
        Norms& operator+=(const Norms& o) {
            w += o.w, l1 += o.l1, l2 += o.l2, linf = std::max(linf, o.linf);
            return *this;
        }
    };
    const Norms e = GlobalReduce::sum<Norms>(n, [&](std::size_t i) {
        const double w = density ? mass.component(i, 0) / density->component(i, 0) : mass.component(i, 0);
        const double ex = velocity.component(i, 0) + s.A * (position.component(i, 0) - xc);
        const double ey = velocity.component(i, 1) - s.A * (position.component(i, 1) - yc);
        const double err = std::hypot(ex, ey);
        return Norms{w, w * err, w * err * err, err};
    });
    norms_.add(t, "velocity", e.l1 / e.w, std::sqrt(e.l2 / e.w), e.linf);

    char line[256];
    std::snprintf(
        line, sizeof line,
        "t = %.6g: a = %.5f (exact %.5f, %+.2f%%), b = %.5f (exact %.5f, %+.2f%%), ab = %.5f (exact %.5f)", t,
        a, aExact, 100 * (a - aExact) / aExact, b, bExact, 100 * (b - bExact) / bExact, a * b,
        aExact * bExact);
    summary_ = {line};
    references_ = {{"a", a, aExact}, {"b", b, bExact}, {"ab", a * b, aExact * bExact}};
}

MFDYN_REGISTER(
    FunctionObject, EllipticalDropError, "ellipticalDropError",
    "2D elliptical drop (Monaghan 1994) against the exact ellipse: semi-axes, area and velocity errors");

}  // namespace mfdyn
