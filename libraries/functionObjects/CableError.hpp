#pragma once
// cableError: the tip of the cable (Lee et al. 2016 section 8.1) against its d'Alembert solution
// (verification/CableWave). See CableError.cpp.
#include "functionObjects/FunctionObject.hpp"
#include "verification/CableWave.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class CableError final : public FunctionObject {
public:
    CableError(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override { return norms_.latest(); }
    std::vector<std::string> summary() const override;
    // peakTipDisplacement: the largest |u_x| of the tip so far against the exact largest.
    std::vector<ReferenceValue> referenceValues() const override;
    std::optional<std::vector<std::string>> fieldsRead() const override {
        return std::vector<std::string>{positionField_, "position", "velocity"};
    }

    // The tip particle's index now and its reference axial coordinate.
    std::size_t tipIndex() const { return tip_; }
    double tipReferenceX() const { return tipX_; }

private:
    CableError(const KeywordValues& values, const std::string& name, const RunContext& context);
    struct History {
        double sumAbs = 0, sumSquares = 0, max = 0;
        void add(double e);
    };
    // The tip's current index, found again by globalId if the particles were reordered.
    std::size_t locateTip() const;

    CableWave exact_;
    std::string positionField_;
    std::size_t tip_ = 0;
    std::int64_t tipId_ = 0;
    double tipX_ = 0;
    std::unique_ptr<CsvFile> csv_;
    ErrorNormWriter norms_;
    History velocityError_, displacementError_;
    History velocityExact_, displacementExact_;  // the same norms of the exact histories (scales)
    std::size_t rows_ = 0;
    double peak_ = 0, peakTime_ = 0;
};

}  // namespace mfdyn
