// health: how healthy a run is while it still looks fine, on by default in every solver.
//
//     health off;                       // controlDict: leave it out
//     health { minTimeStepFraction 1e-4; domainMin (-1 -1 -1); domainMax (1 1 1); }  // settings
//
// Between every checkInterval steps (cheap: one pass over the particles' values):
//   non-finite   any NaN or infinity in any field of any owned particle stops the run (RunError:
//                SolverRun writes the state first), naming the particle, its position and every
//                non-finite component: the solvers' own phase checks look at the fields each phase
//                uses, this one at everything a run stores.
//   time step    the stable step the solver voted, against the first finite vote: a fall below
//                minTimeStepFraction stops the run naming the vote's reason and its particle. The
//                collapse is a symptom (an inverted particle, a runaway speed); the run would
//                otherwise grind on for days at that step. Checked on every vote before the step
//                takes it (checkVote, every step whatever checkInterval says), not after it: a
//                leapfrog's kick after a collapse still spans half the step before, which can break
//                the state before a check after the step.
//   domain       particles outside the box (the health dict's domainMin/domainMax, else the
//                method's own, MPM's grid): stop (onLeaving stop), or count and warn once.
// At its writes (writeControl, default writeTime), a row of health.csv:
//   the energy budget  K = sum 1/2 m |v|^2, U (internal or stored elastic), Phi (potential), D
//                (dissipated by the scheme's stabilisation) and W (work of the boundary conditions and
//                non-conservative forces), each where the solver measures it. The imbalance
//                (K + U + Phi + D - W) - (the same at the first write) is the energy the scheme lost
//                or made without accounting for it, relative to the largest |K| + |U| + |Phi| seen.
//                Where D or W is not measured the imbalance contains it (the summary says so).
//                maxEnergyImbalance (optional) stops the run when |relative imbalance| exceeds it.
//   energy growth  with energyGrowthLimit L, every energyCheckInterval steps (default 10) where the
//                solver measures the external work W: the energy put in, E_in = the largest over the
//                checks of (K + U)_0 + (W - W_0) - (Phi - Phi_0), against K + U; above L x E_in the
//                run stops naming the fastest particle (tlSph's own check, on by default there, has
//                the same rule). L defaults to 1.5 where the method says its budget closes step by
//                step (RunContext::energyBudgetCloses: impactSph), else the check is off unless set:
//                on 2026-12-08, on by default everywhere, mpmFsi's budget did not close (gravity's
//                nodal increments a grid condition removes count in W but never reached K or Phi:
//                the hanging block "grew" 5.5-fold in 20 steps), nor fpmSolid's under velocity
//                conditions (the driven boundary's stress power is not in W). The clamped plate of
//                tutorials/fpmSolid/oscillatingPlate with the traction condition grew 500-fold in
//                0.1 s with every other check silent: with L = 1.5 it stops at 0.039 s.
//   indicators   the method's own (RunContext::healthIndicators: neighbour deficiency,
//                tensile instability, hourglass), each with the count of particles past its
//                threshold; a warning the first time a count is not zero.
// Its cost (seconds in check and write against the time loop) is in the summary line.
//
// Reductions go through GlobalReduce (every rank agrees on whether to stop); the particle a
// diagnosis names is the bad one of lowest global id on any rank (GlobalReduce::firstMessage).
#include "functionObjects/Health.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>

namespace mfdyn {

namespace {

constexpr double defaultGrowthLimit = 1.5;  // tlSph's energyGrowthLimit's default

std::string number(double value, const char* format = "%.6g") {
    char s[64];
    std::snprintf(s, sizeof s, format, value);
    return s;
}

}  // namespace

KeywordSchema Health::keywords() {
    return KeywordSchema("functionObject", "health")
        .integer("checkInterval", "steps",
                 "steps between the checks of non-finite values, the time step and the domain")
        .orDefault(1)
        .atLeast(1)
        .scalar("minTimeStepFraction", "-",
                "stop when the stable time step falls below this fraction of its first value (0: never)")
        .orDefault(1e-4)
        .atLeast(0)
        .lessThan(1)
        .scalar(
            "maxEnergyImbalance", "-",
            "stop when |energy imbalance| exceeds this fraction of the largest energy seen (off without it)")
        .greaterThan(0)
        .optional()
        .scalar("energyGrowthLimit", "-",
                "stop when K + U exceeds this multiple of the energy put in (the first K + U plus the "
                "external work and the potential energy released; where the solver measures the "
                "work; default 1.5 where the method's budget closes step by step (impactSph), else "
                "off: see the source); 0: off")
        .atLeast(0)
        .optional()
        .integer("energyCheckInterval", "steps", "steps between the energy-growth checks")
        .orDefault(10)
        .atLeast(1)
        .vector("domainMin", "m", "lower corner of the box the particles must stay in (with domainMax)")
        .optional()
        .vector("domainMax", "m", "upper corner of that box (default: the method's own, a grid's, if any)")
        .optional()
        .word("onLeaving", {"stop", "warn"}, "a particle outside the domain stops the run, or is counted")
        .orDefault("stop")
        .word("writeControl", {"timeStep", "runTime", "adjustableRunTime", "writeTime"},
              "when to write health.csv: every writeInterval steps, every writeInterval of time, or with "
              "the solver")
        .orDefault("writeTime")
        .scalar("writeInterval", "steps or s",
                "steps (timeStep: a whole number, default 1) or time (runTime, adjustableRunTime: required)")
        .greaterThan(0)
        .optional();
}

Health::Health(const Dictionary& dict, const std::string& name, const RunContext& context)
    : Health(keywords().read(dict), name, context) {}

Health::Health(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      checkInterval_(values.integer("checkInterval")),
      minTimeStepFraction_(values.scalar("minTimeStepFraction")),
      maxEnergyImbalance_(values.optionalScalar("maxEnergyImbalance")),
      givenGrowthLimit_(values.optionalScalar("energyGrowthLimit")),
      energyCheckInterval_(values.integer("energyCheckInterval")),
      stopOnLeaving_(values.word("onLeaving") == "stop") {
    const bool lower = values.given("domainMin"), upper = values.given("domainMax");
    if (lower != upper)
        throw values.error(lower ? "domainMin" : "domainMax",
                           "give both domainMin and domainMax (the box's two corners), or neither");
    const int dim = context.dimension();
    if (lower) {
        const std::vector<double>& a = values.vector("domainMin");
        const std::vector<double>& b = values.vector("domainMax");
        for (const auto& [key, v] : {std::pair{"domainMin", &a}, std::pair{"domainMax", &b}})
            if (int(v->size()) != dim)
                throw values.error(key, "expected " + std::to_string(dim) + " components (a " +
                                            std::to_string(dim) + "D run), found " +
                                            std::to_string(v->size()));
        DomainBox box;
        for (int d = 0; d < dim; ++d) {
            if (!(a[d] < b[d]))
                throw values.error("domainMax", "domainMax must exceed domainMin in every component");
            box.min[d] = a[d];
            box.max[d] = b[d];
        }
        domain_ = box;
        domainSource_ = "health's domainMin/domainMax";
    } else if (auto box = context.domain()) {
        domain_ = box;
        domainSource_ = "the method's domain";
    }
}

void Health::check() {
    const Time& time = context().time();
    if (time.timeIndex() % checkInterval_ != 0) return;
    Stopwatch watch;
    ++checks_;
    checkFinite();  // the time step is judged on each vote before the step (checkVote)
    checkDomain();
    if (checks_ == 1)  // the method is built by now: on where its budget closes, unless set
        energyGrowthLimit_ =
            givenGrowthLimit_.value_or(context().energyBudgetCloses() ? defaultGrowthLimit : 0.0);
    if (energyGrowthLimit_ > 0 && (!growthBaseline_ || time.timeIndex() % energyCheckInterval_ == 0))
        checkEnergyGrowth();
    seconds_ += watch.seconds();
}

void Health::checkEnergyGrowth() {
    const Budget b = measureBudget();
    if (!b.hasWork) {  // the work is not measured: a growth may be energy put in
        if (givenGrowthLimit_)
            Log::warning("health: energyGrowthLimit " + number(*givenGrowthLimit_) +
                         " is not applied: this run's method does not measure the external work, so a "
                         "growth cannot be told from energy put in");
        energyGrowthLimit_ = 0;
        return;
    }
    // K + U + Phi - W is constant where nothing is made; what stands above K + U is what came in.
    const double held = b.kinetic + b.internal;
    if (!growthBaseline_) growthBaseline_ = b.total() - b.work;
    energyInput_ = std::max(energyInput_, *growthBaseline_ + b.work - b.potential);
    if (!(energyInput_ > 0) || (std::isfinite(held) && !(held > energyGrowthLimit_ * energyInput_))) return;
    const FieldStore& fields = context().fields();
    const FieldBase* velocity = fields.findField("velocity");
    const std::size_t n = context().ownedParticles();
    std::string who;
    if (velocity) {
        auto speed = [&](std::size_t i) {
            double v2 = 0;
            for (int d = 0; d < velocity->components(); ++d)
                v2 += velocity->component(i, d) * velocity->component(i, d);
            return std::sqrt(v2);
        };
        const double fastest = GlobalReduce::max(n, speed);
        const FieldBase& ids = fields.field("globalId");
        std::size_t first = n;
        for (std::size_t i = 0; i < n; ++i)
            if ((first == n || ids.component(i, 0) < ids.component(first, 0)) && speed(i) == fastest)
                first = i;
        const std::int64_t key = first < n ? std::int64_t(ids.component(first, 0)) : noMessageKey;
        who = GlobalReduce::firstMessage(key, first < n ? describeParticle(key) : std::string());
    }
    const Time& time = context().time();
    throw RunError(
        "health check, phase energyGrowth, end of step " + std::to_string(time.timeIndex()) +
        ", t = " + time.timeName() + ": the energy K + U grew to " + number(held) + ", " +
        number(held / energyInput_, "%.4g") + " times the energy put in " + number(energyInput_) +
        " (the largest so far of K + U at the first check plus the external work and the potential "
        "energy released since; now W = " +
        number(b.work) + ", Phi = " + number(b.potential) + "), above energyGrowthLimit " +
        number(energyGrowthLimit_) + ": the scheme is unstable. Now: kinetic " + number(b.kinetic) +
        ", internal " + number(b.internal) + (who.empty() ? "" : "; the fastest: " + who) +
        ". Remedy: look at that particle's neighbourhood in the state written below; lower maxCo; "
        "more stabilisation (the method's dissipation); if the energy comes from a source the "
        "solver does not count as work, raise energyGrowthLimit or set it to 0 in "
        "health { } of system/controlDict");
}

std::string Health::describeParticle(std::int64_t id) const {
    const FieldStore& fields = context().fields();
    const FieldBase& ids = fields.field("globalId");
    const FieldBase& position = fields.field("position");
    const FieldBase* velocity = fields.findField("velocity");
    const std::size_t n = context().ownedParticles();
    for (std::size_t i = 0; i < n; ++i) {
        if (std::int64_t(ids.component(i, 0)) != id) continue;
        std::string s = "particle " + std::to_string(id) + " at (";
        for (int d = 0; d < position.components(); ++d)
            s += (d ? " " : "") + number(position.component(i, d));
        s += ")";
        if (velocity) {
            double speed = 0;
            for (int d = 0; d < velocity->components(); ++d)
                speed += velocity->component(i, d) * velocity->component(i, d);
            s += ", speed " + number(std::sqrt(speed));
        }
        return s;
    }
    return "particle " + std::to_string(id);
}

namespace {
constexpr std::size_t finiteBlock = 65536;  // values a block of the non-finite scan
}

void Health::checkFinite() const {
    const FieldStore& fields = context().fields();
    const std::size_t n = context().ownedParticles();
    std::vector<const FieldBase*> real;
    for (const auto& f : fields.fields())
        if (!f->isInteger()) real.push_back(f.get());
    // Field by field over contiguous values, without a branch: the common case (all finite) is a
    // stream through memory. The particles are found only when something is not finite.
    double local = 0;
    for (const FieldBase* f : real) {
        const double* v = static_cast<const double*>(f->data());
        const std::size_t m = n * std::size_t(f->components());
        // A double is not finite when its 11 exponent bits are all set: (bits & exponent) + 2^52
        // then reaches bit 63, and no finite value does. An OR of integer sums, which vectorises
        // (the floating-point test x - x == 0 did not: a third of the check's time on MPM); in
        // blocks, threads over the blocks (one block below 65536 values: no threads' start-up).
        const auto nonFinite = [v, m](std::size_t b) {
            constexpr std::uint64_t exponent = 0x7ff0000000000000, carry = 0x0010000000000000;
            const std::size_t end = std::min(m, (b + 1) * finiteBlock);
            std::uint64_t flag = 0;
            for (std::size_t k = b * finiteBlock; k < end; ++k)
                flag |= (std::bit_cast<std::uint64_t>(v[k]) & exponent) + carry;
            return double(flag >> 63);
        };
        const std::size_t blocks = (m + finiteBlock - 1) / finiteBlock;
        local += blocks == 1 ? nonFinite(0) : LocalReduce::sum<double>(blocks, nonFinite);
    }
    if (globalSum(local) == 0) return;
    auto bad = [&](std::size_t i) {
        for (const FieldBase* f : real) {
            const double* v = static_cast<const double*>(f->data()) + i * f->components();
            for (int c = 0; c < f->components(); ++c)
                if (!std::isfinite(v[c])) return true;
        }
        return false;
    };
    const double count = GlobalReduce::sum<double>(n, [&](std::size_t i) { return bad(i) ? 1.0 : 0.0; });
    const FieldBase& ids = fields.field("globalId");
    std::size_t first = n;
    for (std::size_t i = 0; i < n; ++i)
        if ((first == n || ids.component(i, 0) < ids.component(first, 0)) && bad(i)) first = i;
    std::string text;
    std::int64_t key = noMessageKey;
    if (first < n) {
        key = std::int64_t(ids.component(first, 0));
        text = describeParticle(key) + " has";
        for (const FieldBase* f : real) {
            const auto names = componentNames(f->kind(), f->dimension());
            for (int c = 0; c < f->components(); ++c) {
                const double v = f->component(first, c);
                if (std::isfinite(v)) continue;
                text += " " + f->name() + (f->components() > 1 ? "_" + names[std::size_t(c)] : "") + " = " +
                        number(v);
            }
        }
        text +=
            " (" + number(count, "%.0f") + " particle" + (count > 1 ? "s" : "") + " with non-finite values)";
    }
    const Time& time = context().time();
    throw RunError("health check, phase end of step " + std::to_string(time.timeIndex()) +
                   ", t = " + time.timeName() +
                   ": non-finite values: " + GlobalReduce::firstMessage(key, std::move(text)) +
                   ". The solver's own checks did not catch it. Remedy: look at that particle's "
                   "neighbourhood in the state written below; lower maxCo (or deltaT); check the "
                   "materials' constants and the boundary conditions acting there");
}

void Health::checkVote(const TimeStepVote& vote) {
    Stopwatch watch;
    checkTimeStep(vote);
    seconds_ += watch.seconds();
}

void Health::checkTimeStep(const TimeStepVote& vote) {
    const Time& time = context().time();
    if (!(vote.deltaT > 0) || !std::isfinite(vote.deltaT)) return;  // none yet, or "no limit"
    if (firstVote_ == 0) {
        firstVote_ = vote.deltaT;
        return;
    }
    const double ratio = vote.deltaT / firstVote_;
    if (ratio < smallestVoteRatio_) {
        smallestVoteRatio_ = ratio;
        smallestVoteReason_ = vote.reason;
    }
    if (!(ratio < minTimeStepFraction_)) return;
    std::string who;
    if (vote.particle >= 0) {
        const FieldBase& ids = context().fields().field("globalId");
        const std::size_t n = context().ownedParticles();
        bool owned = false;
        for (std::size_t i = 0; i < n && !owned; ++i)
            owned = std::int64_t(ids.component(i, 0)) == vote.particle;
        who = GlobalReduce::firstMessage(owned ? vote.particle : noMessageKey,
                                         owned ? describeParticle(vote.particle) : std::string());
    }
    throw RunError("health check, phase time-step vote before step " + std::to_string(time.timeIndex() + 1) +
                   ", t = " + time.timeName() + ": the stable time step collapsed to " + number(vote.deltaT) +
                   " s, " + number(ratio, "%.3g") + " of its first value " + number(firstVote_) +
                   " s (below minTimeStepFraction " + number(minTimeStepFraction_) +
                   "); the limit: " + vote.reason + (who.empty() ? "" : ", " + who) +
                   ". Remedy: look at that particle in the state written below (a runaway speed, an "
                   "inverted or crushed neighbourhood); refine or lower the load; or set "
                   "health { minTimeStepFraction 0; } in system/controlDict to let the run go on");
}

void Health::checkDomain() {
    if (!domain_) return;
    const FieldStore& fields = context().fields();
    const FieldBase& position = fields.field("position");
    const int dim = position.components();
    const std::size_t n = context().ownedParticles();
    const DomainBox& box = *domain_;
    const double* xs = static_cast<const double*>(position.data());
    auto outside = [&](std::size_t i) {
        for (int d = 0; d < dim; ++d) {
            const double x = xs[i * std::size_t(dim) + std::size_t(d)];
            if (!(x >= box.min[d] && x <= box.max[d])) return true;
        }
        return false;
    };
    const double count = GlobalReduce::sum<double>(n, [&](std::size_t i) { return outside(i) ? 1.0 : 0.0; });
    const std::size_t before = outsideCount_;
    outsideCount_ = std::size_t(count);
    if (count == 0) return;
    if (!stopOnLeaving_) {
        if (before == 0)
            Log::warning("health: " + number(count, "%.0f") + " particles outside the domain (" +
                         domainSource_ + ") at t = " + context().time().timeName() +
                         " (onLeaving warn: the run goes on)");
        return;
    }
    const FieldBase& ids = fields.field("globalId");
    std::size_t first = n;
    for (std::size_t i = 0; i < n; ++i)
        if ((first == n || ids.component(i, 0) < ids.component(first, 0)) && outside(i)) first = i;
    std::string text;
    std::int64_t key = noMessageKey;
    if (first < n) {
        key = std::int64_t(ids.component(first, 0));
        text = describeParticle(key);
    }
    std::string corners = "(";
    for (int d = 0; d < dim; ++d) corners += (d ? " " : "") + number(box.min[d]);
    corners += ") to (";
    for (int d = 0; d < dim; ++d) corners += (d ? " " : "") + number(box.max[d]);
    corners += ")";
    const Time& time = context().time();
    throw RunError("health check, phase end of step " + std::to_string(time.timeIndex()) +
                   ", t = " + time.timeName() + ": " + GlobalReduce::firstMessage(key, std::move(text)) +
                   " left the domain " + corners + " (" + domainSource_ + "; " + number(count, "%.0f") +
                   " particle" + (count > 1 ? "s" : "") +
                   " outside). Remedy: enlarge the domain, look "
                   "for what drove the particle out (a runaway speed, a missing wall), or set "
                   "health { onLeaving warn; } in system/controlDict to count such particles and go on");
}

Health::Budget Health::measureBudget() const {
    const FieldStore& fields = context().fields();
    const std::size_t n = context().ownedParticles();
    const FieldBase* mass = fields.findField("mass");
    const FieldBase* velocity = fields.findField("velocity");
    Budget b;
    const std::optional<double> internal = context().internalEnergy(),
                                potential = context().potentialEnergy(),
                                dissipated = context().schemeDissipation(), work = context().externalWork();
    b.hasInternal = internal.has_value();
    b.hasPotential = potential.has_value();
    b.hasDissipated = dissipated.has_value();
    b.hasWork = work.has_value();
    if (velocity)
        b.kinetic = GlobalReduce::sum<double>(n, [&](std::size_t i) {
            double v2 = 0;
            for (int d = 0; d < velocity->components(); ++d)
                v2 += velocity->component(i, d) * velocity->component(i, d);
            return 0.5 * (mass ? mass->component(i, 0) : 1.0) * v2;
        });
    // Each hook once: tlSph's internal energy evaluates the law at every particle.
    b.internal = internal.value_or(0.0);
    b.potential = potential.value_or(0.0);
    b.dissipated = dissipated.value_or(0.0);
    b.work = work.value_or(0.0);
    return b;
}

void Health::write() {
    Stopwatch watch;
    const Time& time = context().time();
    const Budget b = measureBudget();
    if (!first_) first_ = b;
    energyScale_ = std::max({energyScale_, std::abs(b.kinetic) + std::abs(b.internal) + std::abs(b.potential),
                             std::abs(first_->total())});
    const double imbalance =
        (b.total() + b.dissipated - b.work) - (first_->total() + first_->dissipated - first_->work);
    lastImbalance_ = energyScale_ > 0 ? imbalance / energyScale_ : 0.0;
    largestImbalance_ = std::max(largestImbalance_, std::abs(lastImbalance_));
    const std::vector<HealthIndicator> indicators = context().healthIndicators();
    if (!csv_) {
        std::vector<std::string> columns{"time", "step", "stableDeltaT", "stableDeltaTRatio",
                                         "kineticEnergy"};
        if (b.hasInternal) columns.push_back("internalEnergy");
        if (b.hasPotential) columns.push_back("potentialEnergy");
        if (b.hasDissipated) columns.push_back("dissipated");
        if (b.hasWork) columns.push_back("externalWork");
        for (const char* c : {"energyImbalance", "relativeImbalance", "outsideDomain"}) columns.push_back(c);
        for (const auto& indicator : indicators) {
            indicatorNames_.push_back(indicator.name);
            columns.push_back(indicator.name);
            columns.push_back(indicator.name + "_count");
            columns.push_back(indicator.name + "_worstId");
            Log::info("health: indicator " + indicator.name + ": " + indicator.definition);
            largestIndicatorCounts_.emplace_back(indicator.name, 0);
        }
        csv_ = std::make_unique<CsvFile>(outputFile("health.csv"), columns, startTime());
    }
    const double vote = time.lastVote().deltaT;
    std::vector<double> row{time.value(), double(time.timeIndex()), vote,
                            firstVote_ > 0 && std::isfinite(vote) ? vote / firstVote_ : 1.0, b.kinetic};
    if (first_->hasInternal) row.push_back(b.internal);
    if (first_->hasPotential) row.push_back(b.potential);
    if (first_->hasDissipated) row.push_back(b.dissipated);
    if (first_->hasWork) row.push_back(b.work);
    row.insert(row.end(), {imbalance, lastImbalance_, double(outsideCount_)});
    for (std::size_t k = 0; k < indicatorNames_.size(); ++k) {
        const HealthIndicator* found = nullptr;
        for (const auto& indicator : indicators)
            if (indicator.name == indicatorNames_[k]) found = &indicator;
        if (!found) {
            row.insert(row.end(), {std::nan(""), 0.0, -1.0});
            continue;
        }
        row.insert(row.end(), {found->value, double(found->count), double(found->worst)});
        largestIndicatorCounts_[k].second = std::max(largestIndicatorCounts_[k].second, found->count);
        if (found->count > 0 && warnedIndicators_.insert(found->name).second)
            Log::warning("health: " + std::to_string(found->count) + " particles past the " + found->name +
                         " threshold at t = " + time.timeName() + " (worst: particle " +
                         std::to_string(found->worst) + ", value " + number(found->value) +
                         "): " + found->definition);
    }
    csv_->row(row);
    seconds_ += watch.seconds();
    if (maxEnergyImbalance_ && std::abs(lastImbalance_) > *maxEnergyImbalance_)
        throw RunError("health check, phase end of step " + std::to_string(time.timeIndex()) +
                       ", t = " + time.timeName() + ": the energy imbalance is " +
                       number(100 * lastImbalance_, "%+.3g") + "% of the largest energy " +
                       number(energyScale_) + " (maxEnergyImbalance " + number(*maxEnergyImbalance_) +
                       "): kinetic " + number(b.kinetic) + ", internal " + number(b.internal) +
                       ", potential " + number(b.potential) + ", dissipated " + number(b.dissipated) +
                       ", external work " + number(b.work) +
                       ". Remedy: a growth is an instability (lower maxCo, more stabilisation); a loss "
                       "is the scheme's dissipation or unmeasured work (see health.csv)");
}

std::vector<std::string> Health::summary() const {
    std::ostringstream s;
    s << "energy imbalance " << number(100 * lastImbalance_, "%+.3g") << "% (largest "
      << number(100 * largestImbalance_, "%.3g") << "%) of " << number(energyScale_);
    std::string unmeasured;
    if (first_ && !first_->hasDissipated) unmeasured += "the scheme's dissipation";
    if (first_ && !first_->hasWork)
        unmeasured += std::string(unmeasured.empty() ? "" : " and ") + "external work";
    if (!unmeasured.empty()) s << " (includes " << unmeasured << ": not measured)";
    s << "; stable time step down to " << number(smallestVoteRatio_, "%.3g") << " of its first";
    if (!smallestVoteReason_.empty() && smallestVoteRatio_ < 1) s << " (" << smallestVoteReason_ << ")";
    s << "; non-finite none";
    if (domain_) s << "; outside the domain " << outsideCount_;
    for (const auto& [name, count] : largestIndicatorCounts_) s << "; " << name << " " << count;
    const double loop = sinceStart_.seconds();
    s << "; cost " << number(loop > 0 ? 100 * seconds_ / loop : 0.0, "%.2g") << "% of the run (" << checks_
      << " checks)";
    return {s.str()};
}

MFDYN_REGISTER(FunctionObject, Health, "health",
               "the run's health: non-finite values, time-step collapse, energy budget, indicators");

}  // namespace mfdyn
