#pragma once
// Particle fields at arbitrary points: the interpolation that the `sample` utility and the
// `probes` function object share.
//
//     interpolation shepard;            // shepard | mls
//     kernel { type wendlandC2; }       // any registered kernel (default wendlandC2)
//     h 0.02;                           // smoothing length; else the particles' smoothingLength field
//     positionField referencePosition;  // interpolate in the reference configuration
//
// These keywords are declared once, in Interpolation::keywords() (doc/models/functionObject/probes.md
// shows them).
//
// Both methods are linear in the particle values, f(x) = sum_j phi_j(x) f_j, so the weights
// phi_j of a point are found once (one neighbour search, one small solve) and applied to every
// field and component. Equations and sources are in Interpolation.cpp.
#include "core/Dictionary.hpp"
#include "core/Tensor.hpp"
#include "kernels/Kernel.hpp"
#include "particles/CellBins.hpp"
#include "particles/FieldStore.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

// A sample point; components beyond the particle dimension are ignored.
using SamplePoint = std::array<double, 3>;

class Interpolation {
public:
    enum class Method { shepard, mls };
    // interpolation, kernel, h and positionField, with the defaults of the caller.
    static KeywordSchema keywords(const std::string& defaultPositionField = "position",
                                  Method defaultMethod = Method::shepard);
    // What became of one point.
    enum class Status {
        ok,
        // mls only: the neighbours do not span the dimension (too few, or all on a line), so
        // the linear fit is undetermined and the Shepard value is used instead.
        shepardFallback,
        // No particle within the support: the values are NaN.
        noNeighbours
    };
    struct Stencil {
        std::vector<std::size_t> particles;
        std::vector<double> weights;  // phi_j, summing to 1
        Status status = Status::noNeighbours;
    };

    // Reads the keywords above from `dict`; `particles` must outlive this object. Positions,
    // smoothing lengths and volumes are taken now and at each update(). `defaultPositionField`
    // and `defaultMethod` are what positionField and interpolation default to.
    // From values read through a schema that includes interpolationKeywords(...).
    Interpolation(const KeywordValues& values, const FieldStore& particles);
    Interpolation(const Dictionary& dict, const FieldStore& particles,
                  const std::string& defaultPositionField = "position",
                  Method defaultMethod = Method::shepard);
    ~Interpolation();
    // After the particles moved (or changed in number): read them again and re-bin, keeping
    // the kernel, whose tables are costly to build.
    void update();

    Method method() const { return method_; }
    const std::string& positionField() const { return positionField_; }
    // The particle fields update() reads (some only where they exist: the volumes' mass and
    // density, or volume), for a function object's FunctionObject::fieldsRead.
    std::vector<std::string> fieldsRead() const;
    const Kernel& kernel() const { return *kernel_; }

    // The weights at each point.
    std::vector<Stencil> stencils(const std::vector<SamplePoint>& points) const;
    Stencil stencil(const SamplePoint& point) const;
    // Every component of `field` at every point: value[point][component]; NaN where the point
    // has no neighbours.
    static std::vector<std::vector<double>> apply(const std::vector<Stencil>& stencils,
                                                  const FieldBase& field);

    // "shepard", "mls".
    static std::string methodName(Method method);

private:
    // The particles whose support holds x, with their weights w_j = V_j W(|x - x_j|, h_j).
    template <int Dim>
    void gather(const CellBins<Dim>& bins, const SamplePoint& x, Stencil& s) const;

    const FieldStore& particles_;
    int dim_;
    Method method_;
    std::unique_ptr<Kernel> kernel_;
    std::optional<double> hKeyword_;
    std::string positionField_;
    std::vector<SamplePoint> position_;  // zero-padded to 3 components
    std::vector<double> h_;              // per particle
    std::vector<double> volume_;         // per particle
    double maxSupport_ = 0.0;
    // The particles binned in cells (the one of dim_ is used), queried within the largest
    // support radius of each sample point.
    CellBins<1> bins1_;
    CellBins<2> bins2_;
    CellBins<3> bins3_;
};

}  // namespace mfdyn
