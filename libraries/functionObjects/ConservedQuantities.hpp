#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <optional>

namespace mfdyn {

class ConservedQuantities final : public FunctionObject {
public:
    ConservedQuantities(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<std::string> summary() const override;

private:
    ConservedQuantities(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::vector<double> measure() const;
    // The RunError text of maxEnergyGrowth: the growth, the energies, the fastest particle, remedies.
    std::string growthDiagnosis() const;

    std::vector<std::string> columns_;
    std::unique_ptr<CsvFile> csv_;
    std::vector<double> first_, last_;
    std::optional<double> maxGrowth_;  // maxEnergyGrowth (none: no check)
};

}  // namespace mfdyn
