#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <optional>

namespace mfdyn {

// bodyCentroid: per body (particleGen region) the mass, the mass-weighted centroid, and the lowest
// and highest particle along `up`, with the depth below a `level` (a float's draft, a drop's
// penetration, a fluid's mean height); BodyCentroid.cpp documents the keywords and the output.
class BodyCentroid final : public FunctionObject {
public:
    BodyCentroid(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<std::string> summary() const override;

private:
    BodyCentroid(const KeywordValues& values, const std::string& name, const RunContext& context);

    struct Body {
        std::int64_t region;
        std::string name;
        double mass = 0, initialMass = 0;
        double centroid[3] = {0, 0, 0};
        double height = 0, lowest = 0, highest = 0;  // along up: centroid, min, max
        double deepest = 0, deepestTime = 0;         // the largest level - lowest so far
    };
    std::vector<Body> bodies_;
    double up_[3] = {0, 0, 0};  // unit vector
    std::optional<double> level_;
    std::unique_ptr<CsvFile> csv_;
    double time_ = 0;
    std::size_t writes_ = 0;
};

}  // namespace mfdyn
