#pragma once
#include "core/Log.hpp"
#include "functionObjects/FunctionObject.hpp"

#include <memory>
#include <optional>
#include <set>

namespace mfdyn {

// The run's health, watched between steps: see Health.cpp.
class Health final : public FunctionObject {
public:
    Health(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void check() override;
    // The time-step check, on each vote before the step uses it (check() after the step does not
    // judge the vote again).
    void checkVote(const TimeStepVote& vote) override;
    void write() override;
    std::vector<std::string> summary() const override;

private:
    Health(const KeywordValues& values, const std::string& name, const RunContext& context);
    void checkFinite() const;
    void checkTimeStep(const TimeStepVote& vote);
    void checkDomain();
    void checkEnergyGrowth();
    // "particle <id> at (x, y, z)": the position of global id `id` (owned here), for diagnoses.
    std::string describeParticle(std::int64_t id) const;
    struct Budget {
        double kinetic = 0, internal = 0, potential = 0, dissipated = 0, work = 0;
        bool hasInternal = false, hasPotential = false, hasDissipated = false, hasWork = false;
        double total() const { return kinetic + internal + potential; }
    };
    Budget measureBudget() const;

    long checkInterval_;
    double minTimeStepFraction_;
    std::optional<double> maxEnergyImbalance_;
    std::optional<double> givenGrowthLimit_;  // energyGrowthLimit as given
    double energyGrowthLimit_ = 0;            // 0: no growth check (off, or the work not measured)
    long energyCheckInterval_;
    bool stopOnLeaving_;
    std::optional<DomainBox> domain_;
    std::string domainSource_;

    std::unique_ptr<CsvFile> csv_;
    std::vector<std::string> indicatorNames_;
    std::optional<Budget> first_;
    double energyScale_ = 0;       // the largest |K| + |U| + |Phi| seen: the imbalance's reference
    double lastImbalance_ = 0;     // relative to energyScale_, as of the latest write
    double largestImbalance_ = 0;  // the largest |relative imbalance| over the writes
    // The growth check: K + U + Phi - W at its first measurement (so that K + U + Phi - W constant
    // means nothing was made), and the most energy put in so far.
    std::optional<double> growthBaseline_;
    double energyInput_ = 0;
    double firstVote_ = 0;  // the first finite stable time step
    double smallestVoteRatio_ = 1;
    std::string smallestVoteReason_;
    std::size_t outsideCount_ = 0;
    std::set<std::string> warnedIndicators_;
    std::vector<std::pair<std::string, std::size_t>> largestIndicatorCounts_;
    long checks_ = 0;
    Stopwatch sinceStart_;
    double seconds_ = 0;  // spent in check() and write()
};

}  // namespace mfdyn
