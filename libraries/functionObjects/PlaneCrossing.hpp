#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <optional>

namespace mfdyn {

// planeCrossing: the first time any particle (of a region) lies beyond a plane, the thesis's dam
// exit time (doc/methods/mpm.md 4.4); PlaneCrossing.cpp documents the keywords and the estimate.
class PlaneCrossing final : public FunctionObject {
public:
    PlaneCrossing(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ReferenceValue> referenceValues() const override;
    std::vector<std::string> summary() const override;
    bool stopRequested() const override { return stop_ && crossed_; }
    std::string stopReason() const override;

private:
    PlaneCrossing(const KeywordValues& values, const std::string& name, const RunContext& context);
    double estimatedTime() const;

    std::int64_t region_ = -1;  // -1: every particle
    std::string regionName_;
    double point_[3] = {0, 0, 0};
    double normal_[3] = {0, 0, 0};  // unit; "beyond" is (x - point) . normal > 0
    bool stop_ = false;
    std::optional<double> reference_;
    std::unique_ptr<CsvFile> leading_;
    std::size_t writes_ = 0;
    // The leading particle at the latest write (largest signed distance).
    double distance_ = 0, time_ = 0;
    // The crossing: the write that first found a particle beyond, and the write before it.
    bool crossed_ = false, crossedAtStart_ = false;
    double crossTime_ = 0, beforeTime_ = 0, beforeDistance_ = 0, crossDistance_ = 0;
    std::int64_t crossId_ = -1;
    double crossPosition_[3] = {0, 0, 0};
};

}  // namespace mfdyn
