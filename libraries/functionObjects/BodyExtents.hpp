#pragma once
#include "functionObjects/FunctionObject.hpp"

#include <array>
#include <vector>

namespace mfdyn {

class BodyExtents final : public FunctionObject {
public:
    BodyExtents(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ReferenceValue> referenceValues() const override;

private:
    BodyExtents(const KeywordValues& values, const std::string& name, const RunContext& context);
    // The global ids of the top row and of the centre column (mode lines), at the first write.
    void chooseLines();
    // Whether particle i belongs to the measured body (`region`: the region field, or null).
    bool member(const FieldBase* region, std::size_t i) const;
    // "bodyExtents '<name>': no particle( in region '<region>')", the empty body's error.
    std::string noParticle() const;
    // mode radius: r, (3D) the height, the outer ring's mean radius, appended to `row`.
    void writeRadius(std::vector<double>& row) const;
    // max - min of x.d for each of directions_, appended to `row`.
    void writeDirections(std::vector<double>& row) const;

    std::int64_t region_ = -1;  // -1: every particle
    std::string regionName_;
    bool lines_ = false;
    bool radius_ = false;                            // mode radius
    std::vector<std::array<double, 3>> directions_;  // unit vectors (`directions`), zero-padded
    std::array<double, 3> axis_{0, 0, 1};            // mode radius, unit
    bool fixedCentre_ = false;                       // `centre` given (else the centroid each write)
    std::array<double, 3> centre_{0, 0, 0};
    std::vector<double> reference_;  // empty: none
    std::unique_ptr<CsvFile> csv_;
    std::vector<std::int64_t> row_, column_;  // sorted global ids (mode lines)
    std::vector<double> extents_;
    bool written_ = false;
};

}  // namespace mfdyn
