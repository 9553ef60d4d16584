#pragma once
// swingingCubeError: a total-Lagrangian run of the swinging cube against its exact solution
// (verification/SwingingCube). See SwingingCubeError.cpp.
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/Interpolation.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class SwingingCubeError final : public FunctionObject {
public:
    SwingingCubeError(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    ~SwingingCubeError() override;
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override { return norms_.latest(); }
    std::vector<std::string> summary() const override { return summary_; }
    std::optional<std::vector<std::string>> fieldsRead() const override;

    // One field's absolute norms at the current time, as written.
    struct Norms {
        double L1 = 0, L2 = 0, Linf = 0;
        // The same norms of the exact field at this time: the scale of the relative error.
        double exactL1 = 0, exactL2 = 0, exactLinf = 0;
    };
    // momentum, firstPiolaStress (and the components when asked), computed now without writing.
    std::vector<std::pair<std::string, Norms>> compute() const;

private:
    SwingingCubeError(const KeywordValues& values, const std::string& name, const RunContext& context);
    template <int Dim>
    std::vector<std::pair<std::string, Norms>> computeDim() const;
    // Stencils of the cloud points, again if the particles were reordered or changed in number.
    void refreshStencils() const;

    double rho0_, youngsModulus_, poissonRatio_, amplitude_;
    int cloud_;
    bool volumeWeighted_;
    bool components_;
    std::string positionField_;
    std::unique_ptr<Interpolation> interpolation_;
    std::vector<SamplePoint> points_;
    mutable std::vector<Interpolation::Stencil> stencils_;
    mutable std::vector<double> stencilPositions_;  // the reference positions the stencils were built on
    ErrorNormWriter norms_;
    std::vector<std::string> summary_;
};

}  // namespace mfdyn
