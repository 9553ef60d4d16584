// trajectoryError: positions and velocities against the body force's exact trajectory from the
// state at the start of the run. For particle a with error e_a = |x_a - x_exact(t)|:
//
//   L1 = (1/N) Σ e_a,   L2 = sqrt((1/N) Σ e_a²),   Linf = max e_a        (in m, and m/s)
//
// N, the sums and the maximum are over the particles of every rank (GlobalReduce, globalMax), each
// particle against its own start state, found by its global id.
//
// written to errorNorms.csv (time,field,L1,L2,Linf) for fields `position` and `velocity`. The
// relative error of the summary divides by the same norms of the exact displacement since the
// start, |x_exact(t) - x_a(t0)| (the position's own size depends on where the origin is), and of
// the exact speed |v_exact(t)|.
#include "ballistics/TrajectoryError.hpp"

#include "ballistics/ParticleFlightSolver.hpp"
#include "core/Parallel.hpp"

#include <cmath>
#include <limits>

namespace mfdyn {

namespace {
const BodyForceSolver& bodyForceSolver(const Dictionary& dict, const RunContext& context) {
    auto* solver = dynamic_cast<const BodyForceSolver*>(&context.solverContext());
    if (!solver)
        throw dict.error("type", "trajectoryError needs a solver with a body force (particleFlight)");
    return *solver;
}
}  // namespace

KeywordSchema TrajectoryError::keywords() {
    return KeywordSchema("functionObject", "trajectoryError").append(functionObjectKeywords());
}

TrajectoryError::TrajectoryError(const Dictionary& dict, const std::string& name, const RunContext& context)
    : TrajectoryError(keywords().read(dict), name, context) {}

TrajectoryError::TrajectoryError(const KeywordValues& values, const std::string& name,
                                 const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      solver_(bodyForceSolver(values.dict(), context)),
      t0_(context.time().value()),
      norms_(outputFile("errorNorms.csv"), name) {
    const FieldStore& fields = context.fields();
    const int dim = fields.dimension();
    const FieldBase& x = fields.field("position");
    const FieldBase& v = fields.field("velocity");
    const FieldBase& id = fields.field("globalId");
    const std::size_t n = context.ownedParticles();
    x0_.resize(n * dim);
    v0_.resize(n * dim);
    for (std::size_t i = 0; i < n; ++i) {
        start_[std::int64_t(id.component(i, 0))] = i;
        for (int d = 0; d < dim; ++d)
            x0_[i * dim + d] = x.component(i, d), v0_[i * dim + d] = v.component(i, d);
    }
    // Asked at the origin at rest, not at a particle: every rank must reach the same verdict, and
    // one without particles (under MPI) would otherwise not ask, not throw, and wait for the others.
    const double zero[3] = {0, 0, 0};
    double probe[3], probeV[3];
    if (!solver_.bodyForce().exactTrajectory(zero, zero, 0.0, probe, probeV))
        throw values.dict().error("type", "the selected bodyForce has no exact trajectory to compare with");
}

void TrajectoryError::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    // No return on a rank with no particles: the sums below are global, so every rank must reach
    // them; the row is skipped only when no rank has a particle.
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& v = fields.field("velocity");
    const FieldBase& id = fields.field("globalId");
    // Each particle's state at the start, by its global id: on several ranks particles change rank
    // and order, so an index at the start names another particle later. One that was not there at
    // the start has none; it is counted in the sums below, so that every rank refuses together.
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> slot(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto found = start_.find(std::int64_t(id.component(i, 0)));
        slot[i] = found == start_.end() ? none : found->second;
    }
    const double tau = context().time().value() - t0_;
    // The scales' maxima ride in the sum as maxima (+= is the combination, as the reduction
    // applies it): one reduction for the sums and the scales, as before the scales were added.
    struct Norms {
        double count = 0, l1x = 0, l2x = 0, l1v = 0, l2v = 0;  // count: N over every rank
        double l1s = 0, l2s = 0, l1u = 0, l2u = 0;             // the scales: exact displacement, speed
        double maxS = 0, maxU = 0;
        double unknown = 0;  // particles without a start state
        Norms& operator+=(const Norms& o) {
            unknown += o.unknown;
            count += o.count, l1x += o.l1x, l2x += o.l2x, l1v += o.l1v, l2v += o.l2v;
            l1s += o.l1s, l2s += o.l2s, l1u += o.l1u, l2u += o.l2u;
            maxS = std::max(maxS, o.maxS), maxU = std::max(maxU, o.maxU);
            return *this;
        }
    };
    std::vector<double> ex(n), ev(n);
    const Norms sums = GlobalReduce::sum<Norms>(n, [&](std::size_t i) {
        double xe[3], ve[3];
        const std::size_t s = slot[i];
        if (s == none) {
            Norms unknown;
            unknown.unknown = 1;
            return unknown;
        }
        solver_.bodyForce().exactTrajectory(&x0_[s * dim], &v0_[s * dim], tau, xe, ve);
        double dx = 0, dv = 0, ds = 0, du = 0;
        for (int d = 0; d < dim; ++d) {
            dx += std::pow(x.component(i, d) - xe[d], 2);
            dv += std::pow(v.component(i, d) - ve[d], 2);
            ds += std::pow(xe[d] - x0_[s * dim + d], 2);
            du += ve[d] * ve[d];
        }
        ex[i] = std::sqrt(dx), ev[i] = std::sqrt(dv);
        const double sx = std::sqrt(ds), sv = std::sqrt(du);
        return Norms{1, ex[i], dx, ev[i], dv, sx, ds, sv, du, sx, sv, 0};
    });
    if (sums.unknown > 0)
        throw RunError("trajectoryError '" + name() + "': " + std::to_string(std::int64_t(sums.unknown)) +
                       " particles were not there at the start of the run: they have no exact trajectory");
    if (sums.count == 0) return;  // the same on every rank
    double maxX = 0, maxV = 0;
    for (std::size_t i = 0; i < n; ++i) maxX = std::max(maxX, ex[i]), maxV = std::max(maxV, ev[i]);
    maxX = globalMax(maxX), maxV = globalMax(maxV);
    const double t = context().time().value(), N = sums.count;
    norms_.add(t, "position", sums.l1x / N, std::sqrt(sums.l2x / N), maxX, sums.l1s / N,
               std::sqrt(sums.l2s / N), sums.maxS);
    norms_.add(t, "velocity", sums.l1v / N, std::sqrt(sums.l2v / N), maxV, sums.l1u / N,
               std::sqrt(sums.l2u / N), sums.maxU);
}

MFDYN_REGISTER(FunctionObject, TrajectoryError, "trajectoryError",
               "particle positions and velocities against the body force's exact trajectory");

}  // namespace mfdyn
