// conservedQuantities: the totals a conservative scheme must keep, and their drift.
//
//   M = Σ m_a                          mass
//   P = Σ m_a v_a                      linear momentum (Dim components)
//   L = Σ m_a x_a × v_a                angular momentum about the origin (z in 2D; 3 components in 3D)
//   K = Σ ½ m_a |v_a|²                 kinetic energy
//   U, Φ                               internal and potential energy, when the solver provides them
//   E = K + U + Φ                      total energy
//
// Sums go through GlobalReduce::sum (fixed blocks), so the figures do not depend on the thread
// count, and an MPI build sums over every rank.
//
// maxEnergyGrowth g (optional, off without it): at each of its writes, |E| > g |E_0| (E_0 the total
// energy of its first write), or an E that is not finite, stops the run with a RunError naming the
// growth, the energies, the fastest particle and the remedies (SolverRun writes the state and the
// exit status is 1). An instability of the scheme grows the energy by orders of magnitude (the
// oscillating plate in {p,F,J} before issue 16's fix: 1e5-fold in 0.04 s); a run that conserves
// energy keeps it within the percent. It is opt-in, like the object itself, because a run driven
// by its boundaries or body forces (a punch, an impact from rest) gains energy legitimately: no
// factor suits every run, and a run that starts with E_0 = 0 has nothing to compare with (a
// warning says the check is off). It costs nothing beyond the object's own sums.
#include "functionObjects/ConservedQuantities.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>

namespace mfdyn {

KeywordSchema ConservedQuantities::keywords() {
    return KeywordSchema("functionObject", "conservedQuantities")
        .scalar("maxEnergyGrowth", "-",
                "stop the run (an error, exit status 1) when |total energy| exceeds this factor times its "
                "value at the first write (off without it)")
        .greaterThan(1)
        .optional()
        .append(functionObjectKeywords());
}

ConservedQuantities::ConservedQuantities(const Dictionary& dict, const std::string& name,
                                         const RunContext& context)
    : ConservedQuantities(keywords().read(dict), name, context) {}

ConservedQuantities::ConservedQuantities(const KeywordValues& values, const std::string& name,
                                         const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      maxGrowth_(values.optionalScalar("maxEnergyGrowth")) {
    const int dim = context.dimension();
    const char* axes[] = {"x", "y", "z"};
    columns_ = {"time", "mass"};
    for (int d = 0; d < dim; ++d) columns_.push_back(std::string("momentum_") + axes[d]);
    if (dim == 2) columns_.push_back("angularMomentum_z");
    if (dim == 3)
        for (int d = 0; d < 3; ++d) columns_.push_back(std::string("angularMomentum_") + axes[d]);
    columns_.push_back("kineticEnergy");
    if (context.internalEnergy()) columns_.push_back("internalEnergy");
    if (context.potentialEnergy()) columns_.push_back("potentialEnergy");
    columns_.push_back("totalEnergy");
    csv_ = std::make_unique<CsvFile>(outputFile("conservedQuantities.csv"), columns_, startTime());
}

std::vector<double> ConservedQuantities::measure() const {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase* massField = fields.findField("mass");
    const FieldBase& position = fields.field("position");
    const FieldBase* velocity = fields.findField("velocity");
    auto mass = [&](std::size_t i) { return massField ? massField->component(i, 0) : 1.0; };
    auto vel = [&](std::size_t i, int d) { return velocity ? velocity->component(i, d) : 0.0; };

    // One pass gathers every sum: [M, P(dim), L(0|1|3), K].
    const int nL = dim == 2 ? 1 : dim == 3 ? 3 : 0;
    const std::size_t width = 1 + dim + nL + 1;
    struct Sums {
        std::array<double, 9> v{};
        Sums& operator+=(const Sums& o) {
            for (std::size_t k = 0; k < v.size(); ++k) v[k] += o.v[k];
            return *this;
        }
    };
    const Sums total = GlobalReduce::sum<Sums>(n, [&](std::size_t i) {
        Sums s;
        const double m = mass(i);
        double x[3] = {0, 0, 0}, v[3] = {0, 0, 0};
        for (int d = 0; d < dim; ++d) x[d] = position.component(i, d), v[d] = vel(i, d);
        s.v[0] = m;
        for (int d = 0; d < dim; ++d) s.v[1 + d] = m * v[d];
        const double lx = x[1] * v[2] - x[2] * v[1], ly = x[2] * v[0] - x[0] * v[2],
                     lz = x[0] * v[1] - x[1] * v[0];
        if (nL == 1) s.v[1 + dim] = m * lz;
        if (nL == 3) s.v[1 + dim] = m * lx, s.v[2 + dim] = m * ly, s.v[3 + dim] = m * lz;
        s.v[1 + dim + nL] = 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return s;
    });

    std::vector<double> row{context().time().value()};
    for (std::size_t k = 0; k < width; ++k) row.push_back(total.v[k]);
    double energy = total.v[width - 1];
    if (auto u = context().internalEnergy()) row.push_back(*u), energy += *u;
    if (auto phi = context().potentialEnergy()) row.push_back(*phi), energy += *phi;
    row.push_back(energy);
    return row;
}

void ConservedQuantities::write() {
    last_ = measure();
    const bool firstWrite = first_.empty();
    if (firstWrite) first_ = last_;
    csv_->row(last_);
    if (!maxGrowth_) return;
    const double e0 = first_.back(), e = last_.back();
    if (firstWrite && !(std::abs(e0) > 0)) {
        Log::warning("conservedQuantities '" + name() +
                     "': the total energy is 0 at the first write, so maxEnergyGrowth has nothing to "
                     "compare with: the check is off");
        return;
    }
    if (std::isfinite(e) && std::abs(e) <= *maxGrowth_ * std::abs(e0)) return;
    throw RunError(growthDiagnosis());
}

std::string ConservedQuantities::growthDiagnosis() const {
    // The energies by kind, then the particle that carries the most kinetic energy per unit mass.
    std::ostringstream s;
    s.precision(4);
    const double e0 = first_.back(), e = last_.back();
    s << "conservedQuantities '" << name() << "' at step " << context().time().timeIndex()
      << ", t = " << context().time().value() << ": the total energy ";
    if (std::isfinite(e))
        s << "grew " << std::abs(e) / std::abs(e0) << "-fold (" << e0 << " -> " << e
          << "), above maxEnergyGrowth " << *maxGrowth_;
    else
        s << "is " << e << " (it was " << e0 << ")";
    s << ".\n    Now:";
    for (std::size_t k = 1; k < columns_.size(); ++k)
        if (columns_[k].find("Energy") != std::string::npos) s << " " << columns_[k] << " " << last_[k];
    const FieldStore& fields = context().fields();
    const FieldBase* velocity = fields.findField("velocity");
    const FieldBase* id = fields.findField("globalId");
    const FieldBase& position = fields.field("position");
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    if (velocity) {
        // Over every rank, described by the rank that owns it, so that every rank throws the same
        // text: a non-finite speed counts as the fastest, and of equals the lowest global id.
        const auto speedSquared = [&](std::size_t i) {
            double v2 = 0;
            for (int d = 0; d < dim; ++d) v2 += velocity->component(i, d) * velocity->component(i, d);
            return v2;
        };
        const auto rankOf = [&](std::size_t i) {
            const double v2 = speedSquared(i);
            return std::isfinite(v2) ? std::sqrt(v2) : std::numeric_limits<double>::infinity();
        };
        const auto key = [&](std::size_t i) {
            return id ? std::int64_t(id->component(i, 0)) : std::int64_t(i);
        };
        const double fastest = GlobalReduce::max(n, rankOf);
        std::size_t chosen = n;
        for (std::size_t i = 0; i < n; ++i)
            if (rankOf(i) == fastest && (chosen == n || key(i) < key(chosen))) chosen = i;
        std::string text;
        if (chosen < n) {
            std::ostringstream d;
            d.precision(4);
            d << (id ? "globalId " : "index ") << key(chosen) << " at (";
            for (int k = 0; k < dim; ++k) d << (k ? " " : "") << position.component(chosen, k);
            d << "), |v| = " << std::sqrt(speedSquared(chosen));
            text = d.str();
        }
        const std::string described =
            GlobalReduce::firstMessage(chosen < n ? key(chosen) : noMessageKey, text);
        if (!described.empty()) s << ".\n    Fastest particle: " << described;
    }
    s << ".\n    With no energy put in, growth is a numerical instability of the scheme: reduce maxCo "
         "(system/controlDict) or the fixed deltaT, raise the method's dissipation, and see where the "
         "growth starts in the written state. A run driven by its boundaries or body forces gains "
         "energy legitimately: raise maxEnergyGrowth (system/controlDict, functions/"
      << name() << ") or remove it.";
    return s.str();
}

std::vector<std::string> ConservedQuantities::summary() const {
    if (first_.empty()) return {};
    // Drift relative to the quantity's own scale; momenta relative to Σ m|v| would need another
    // pass, so they are reported absolutely alongside the mass-relative figures.
    std::vector<std::string> lines;
    char s[160];
    for (std::size_t k = 1; k < columns_.size(); ++k) {
        const std::string& c = columns_[k];
        const double a = first_[k], b = last_[k];
        if (c == "mass" || c == "totalEnergy") {
            std::snprintf(s, sizeof s, "%s drift %.3e relative (%.10g -> %.10g)", c.c_str(),
                          a != 0 ? (b - a) / std::abs(a) : b - a, a, b);
            lines.push_back(s);
        } else if (c.rfind("momentum_", 0) == 0 || c.rfind("angularMomentum_", 0) == 0) {
            std::snprintf(s, sizeof s, "%s change %.3e (%.10g -> %.10g)", c.c_str(), b - a, a, b);
            lines.push_back(s);
        }
    }
    return lines;
}

MFDYN_REGISTER(FunctionObject, ConservedQuantities, "conservedQuantities",
               "mass, linear and angular momentum, kinetic/internal/potential/total energy, with drift");

}  // namespace mfdyn
