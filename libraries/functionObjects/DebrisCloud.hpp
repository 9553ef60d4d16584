#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <memory>

namespace mfdyn {

class DebrisCloud final : public FunctionObject {
public:
    DebrisCloud(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<std::string> summary() const override { return summary_; }
    std::optional<std::vector<std::string>> fieldsRead() const override {
        return std::vector<std::string>{"position"};
    }

private:
    DebrisCloud(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::vector<double> direction_;  // unit impact direction, dim components
    double rear_, front_;            // target faces, as distances along the direction
    std::vector<std::int64_t> targetRegions_;
    double trim_;
    std::unique_ptr<CsvFile> csv_;
    std::vector<std::string> summary_;
};

}  // namespace mfdyn
