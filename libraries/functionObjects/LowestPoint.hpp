#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <optional>

namespace mfdyn {

class LowestPoint final : public FunctionObject {
public:
    LowestPoint(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ReferenceValue> referenceValues() const override;
    std::vector<std::string> summary() const override;

private:
    LowestPoint(const KeywordValues& values, const std::string& name, const RunContext& context);

    std::int64_t region_ = -1;  // -1: every particle
    std::string regionName_;
    double down_[3] = {0, 0, 0};  // unit vector
    std::optional<double> reference_;
    std::unique_ptr<CsvFile> csv_;
    // The particle tracked, chosen at the first write: its global id and where it was.
    std::int64_t id_ = -1;
    double start_[3] = {0, 0, 0};
    double displacement_ = 0, sum_ = 0, peak_ = 0, peakTime_ = 0;
    std::size_t writes_ = 0;
};

}  // namespace mfdyn
