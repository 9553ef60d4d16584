#pragma once
// fpmSolid: the finite pointset method for hypo-elastic solids (von Nida 2005; doc/methods/fpm.md).
// What is built, the step, constant/fpmProperties and the fields: the opening comment of FpmSolver.cpp.
#include "core/KeywordSchema.hpp"
#include "fpm/EulerPart.hpp"
#include "geometry/Shape.hpp"
#include "materials/MaterialSet.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"
#include "particles/NeighbourSearch.hpp"
#include "solver/Solver.hpp"

#include <array>
#include <memory>
#include <vector>

namespace mfdyn {

template <int Dim>
class FpmSolver final : public Solver {
public:
    explicit FpmSolver(SolverRun& run);
    ~FpmSolver() override;

    static KeywordSchema keywords();
    static KeywordSchema motionKeywords();
    static KeywordSchema initialStressKeywords();
    static KeywordSchema eulerKeywords();
    static constexpr const char* propertiesDictionary = "fpmProperties";

    TimeStepVote stableTimeStep() override;
    void step(double dt) override;
    ParticleSetBase& particles() override { return *owner_; }
    std::vector<ExtraFile> extraOutput() const override;
    std::vector<std::string> summary(double loopSeconds) const override;

    // The rotation-only reference (see the top of this file), measured after each step.
    struct RotationError {
        double stress = 0;      // max |S - S_exact| over particles and components
        double radius = 0;      // max | |x - c| - |x0 - c| |
        double zeroStress = 0;  // max |S| over the particles that started unstressed
    };

private:
    static KeywordValues readSettings(const Dictionary& properties);
    void readSubsystems();
    void readMotion();
    void readMaterials();
    void initialiseFields();
    SymmTensor<Dim> initialStressAt(const Vector<Dim>& X) const;
    Vector<Dim> prescribedVelocity(const Vector<Dim>& x) const;
    void measureRotationError(double t);
    void readEuler();
    void eulerStep(double dt);

    std::unique_ptr<ParticleSet<Dim>> owner_;
    const Dictionary& properties_;
    const KeywordValues settings_;
    std::unique_ptr<FitWeight> fitWeight_;
    std::unique_ptr<MaterialSet<Dim>> materials_;  // null without constant/materialProperties
    std::unique_ptr<Shape> stressShape_;
    SymmTensor<Dim> stress0_{};
    bool hasInitialStress_ = false;

    bool prescribed_ = false;    // motion: prescribed rigid rotation, else frozen
    bool upwindMotion_ = false;  // motion: the Euler part's upwind velocity
    double omega_ = 0;
    Vector<3> axis_ = Vector<3>::UnitZ();
    Vector<Dim> centre_ = Vector<Dim>::Zero();

    double spacing_ = 0;
    double h_ = 0;
    bool reference_ = false;                 // the rotation-only reference applies
    bool euler_ = false, rotation_ = false;  // the subsystems that run

    // The Euler part (fpm/EulerPart.hpp): null unless subsystems has euler.
    std::unique_ptr<fpm::EulerPart<Dim>> eulerPart_;
    std::vector<double>* e_ = nullptr;   // specificInternalEnergy, when an equation of state needs it
    std::vector<double> c_;              // the sound speed of the step's start
    std::size_t flat_ = 0, tooFew_ = 0;  // central evaluations of the Euler part, summed over the steps
    double maxShift_ = 0;                // the largest shift length taken
    struct StateChange {
        double rho = 0, p = 0,
               v = 0;  // max over particles of |rho - rho_start|, |p - p_start|, |v - v_start|
    };
    std::vector<double> rhoStart_, pStart_;
    std::vector<Vector<Dim>> vStart_;
    StateChange lastChange_, worstChange_;

    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    std::vector<double>& rho_;
    std::vector<double>* p_ = nullptr;
    std::vector<double>* V_ = nullptr;
    std::vector<SymmTensor<Dim>>* S_ = nullptr;

    NeighbourSearch<Dim> search_;
    NeighbourList rows_;
    NeighbourList wideRows_;  // the Euler part's shifted fits: within (1 + maxShift) h
    LeastSquaresOperators<Dim> fit_;
    std::vector<double> hField_;
    std::vector<Tensor<Dim>> gradV_;
    std::vector<double> radius0_;  // |x - c| at this run's start

    RotationError last_, worst_;
    double neighboursPerParticle_ = 0;
    std::size_t grown_ = 0, shepard_ = 0;  // fallbacks taken, summed over the steps
};

}  // namespace mfdyn
