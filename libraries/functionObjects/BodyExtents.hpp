#pragma once
#include "functionObjects/FunctionObject.hpp"

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

    std::int64_t region_ = -1;  // -1: every particle
    std::string regionName_;
    bool lines_ = false;
    std::vector<double> reference_;  // empty: none
    std::unique_ptr<CsvFile> csv_;
    std::vector<std::int64_t> row_, column_;  // sorted global ids (mode lines)
    std::vector<double> extents_;
    bool written_ = false;
};

}  // namespace mfdyn
