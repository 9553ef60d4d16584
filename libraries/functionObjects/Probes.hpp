#pragma once
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/Interpolation.hpp"

namespace mfdyn {

class Probes final : public FunctionObject {
public:
    Probes(const Dictionary& dict, const std::string& name, const RunContext& context);
    void write() override;

private:
    std::vector<std::string> fields_;
    std::vector<SamplePoint> points_;
    Interpolation interpolation_;
    bool warned_ = false;
    std::unique_ptr<CsvFile> csv_;
};

}  // namespace mfdyn
