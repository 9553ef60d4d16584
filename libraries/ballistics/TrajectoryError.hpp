#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <cstdint>
#include <unordered_map>

namespace mfdyn {

class BodyForceSolver;

class TrajectoryError final : public FunctionObject {
public:
    TrajectoryError(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override { return norms_.latest(); }

private:
    TrajectoryError(const KeywordValues& values, const std::string& name, const RunContext& context);
    const BodyForceSolver& solver_;
    double t0_;
    std::vector<double> x0_, v0_;                          // at the start, Dim per particle
    std::unordered_map<std::int64_t, std::size_t> start_;  // global id -> its place in x0_, v0_
    ErrorNormWriter norms_;
};

}  // namespace mfdyn
