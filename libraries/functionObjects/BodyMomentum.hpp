#pragma once
#include "functionObjects/FunctionObject.hpp"

namespace mfdyn {

class BodyMomentum final : public FunctionObject {
public:
    BodyMomentum(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<std::string> summary() const override;

private:
    BodyMomentum(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::vector<double> measure() const;

    std::vector<std::string> regionNames_;
    std::vector<std::int64_t> regions_;  // region ids, in the order written
    double centre_[3] = {0, 0, 0};
    int perRegion_ = 0;  // columns per region: mass, momentum (dim), angular momentum (0, 1 or 3)
    std::vector<std::string> columns_;
    std::unique_ptr<CsvFile> csv_;
    std::vector<double> first_, last_;
};

}  // namespace mfdyn
