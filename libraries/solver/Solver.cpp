#include "solver/Solver.hpp"

#include "boundaryConditions/BoundaryConditionList.hpp"
#include "core/KeywordSchema.hpp"
#include "solver/SolverRun.hpp"

#include <filesystem>

namespace mfdyn {

Solver::Solver(SolverRun& run) : run_(run) {}
Solver::~Solver() = default;

const Case& Solver::runCase() const {
    return run_.runCase();
}
const Time& Solver::time() const {
    return run_.time();
}
const std::string& Solver::startTimeName() const {
    return run_.startTimeName();
}

std::vector<const Dictionary*> Solver::dictionaries() const {
    std::vector<const Dictionary*> d;
    for (const Dictionary& dict : opened_) d.push_back(&dict);
    return d;
}

const Dictionary& Solver::openConstant(const std::string& name) {
    return opened_.emplace_back(run_.runCase().readConstant(name));
}

const Dictionary* Solver::openOptionalConstant(const std::string& name) {
    if (!std::filesystem::exists(run_.runCase().constantFile(name))) return nullptr;
    return &openConstant(name);
}

template <int Dim>
BoundaryConditionList<Dim> Solver::readBoundaryConditions(
    const ParticleSet<Dim>& particles, const typename BoundaryConditionList<Dim>::Hooks& hooks) {
    const Dictionary* dict = openOptionalConstant("boundaryConditions");
    if (!dict) return {};
    BoundaryConditionList<Dim> list(*dict, particles);
    list.requireHooks(*dict, hooks, run_.application());
    Log::info("Boundary conditions:\n" + list.summary());
    return list;
}

template BoundaryConditionList<1> Solver::readBoundaryConditions(const ParticleSet<1>&,
                                                                 const BoundaryConditionList<1>::Hooks&);
template BoundaryConditionList<2> Solver::readBoundaryConditions(const ParticleSet<2>&,
                                                                 const BoundaryConditionList<2>::Hooks&);
template BoundaryConditionList<3> Solver::readBoundaryConditions(const ParticleSet<3>&,
                                                                 const BoundaryConditionList<3>::Hooks&);

void Solver::checkPositiveMassAndDensity(const ParticleSetBase& particles, const std::vector<double>& mass,
                                         const std::vector<double>& density) {
    const auto& id = particles.requireField<std::int64_t>("globalId");
    for (std::size_t i = 0; i < mass.size(); ++i)
        if (!(mass[i] > 0) || !(density[i] > 0))
            // formatKeywordNumber, not std::to_string: a mass of -1e-20 must not read "-0.000000".
            throw InputError("particle " + std::to_string(id[i]) + " has mass " +
                             formatKeywordNumber(mass[i]) + " and density " +
                             formatKeywordNumber(density[i]) + ": both must be positive");
}

std::size_t Solver::ownedParticles() const {
    return const_cast<Solver*>(this)->particles().ownedCount();
}

const std::vector<std::int64_t>& Solver::globalIds() const {
    return fields().requireField<std::int64_t>("globalId");
}

std::vector<std::string> Solver::skippedPhases() const {
    std::vector<std::string> skipped;
    for (std::size_t k = 0; k < phases_.size(); ++k)
        if (phaseEntries_[k] == 0) skipped.push_back(phases_[k].first);
    return skipped;
}

std::size_t Solver::phaseIndex(std::string_view name) {
    for (std::size_t k = 0; k < phases_.size(); ++k)
        if (phases_[k].first == name) return k;
    phases_.emplace_back(std::string(name), 0.0);
    phaseEntries_.push_back(0);
    return phases_.size() - 1;
}

std::string Solver::statePrefix(std::string_view phaseName) const {
    std::ostringstream s;
    s.precision(6);
    s << "phase " << phaseName << ", step " << time().timeIndex() + 1 << ", t = " << time().value() << ": ";
    return s.str();
}

}  // namespace mfdyn
