#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <optional>

namespace mfdyn {

// hydrostaticPressure: a fluid's pressure binned by height along a vertical line against the
// hydrostatic rho g (H - h) (doc/methods/mpm.md 5, X1); HydrostaticPressure.cpp documents the
// keywords and the norms.
class HydrostaticPressure final : public FunctionObject {
public:
    HydrostaticPressure(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override;
    std::vector<ReferenceValue> referenceValues() const override;
    std::vector<std::string> summary() const override;

private:
    HydrostaticPressure(const KeywordValues& values, const std::string& name, const RunContext& context);

    std::int64_t region_ = -1;  // -1: every particle
    std::string regionName_;
    double rho_, g_;
    double up_[3] = {0, 0, 0};  // unit, against gravity
    bool line_ = false;         // only particles within halfWidth_ of the line through point_
    double point_[3] = {0, 0, 0};
    double halfWidth_ = 0;
    std::optional<double> freeSurface_;  // H given; else the highest particle + surfaceOffset_
    double surfaceOffset_ = 0, surfaceBand_ = 0;
    long bins_;
    std::unique_ptr<CsvFile> profile_;
    std::unique_ptr<ErrorNormWriter> norms_;
    std::size_t writes_ = 0;
    // The latest write.
    double time_ = 0, height_ = 0;
    std::size_t binsUsed_ = 0;
    double worstRelative_ = 0, worstHeight_ = 0, worstPressure_ = 0, worstExact_ = 0;
};

}  // namespace mfdyn
