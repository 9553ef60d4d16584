#pragma once
// Exact solution of the 1D Riemann problem between two uniform states, each with its own closure
// (ideal gas, stiffened gas, linear barotropic). Star state by a safeguarded Newton iteration on
// f_L(P) + f_R(P) + v_R - v_L = 0; sampling in the similarity variable xi = (x - x0)/t.
// Equations and sources: RiemannSolver.cpp, RiemannEquationOfState.cpp.
#include "verification/RiemannEquationOfState.hpp"

namespace mfdyn {

class RiemannSolver {
public:
    enum class WaveKind { shock, rarefaction };

    // One of the two nonlinear waves. For a shock headSpeed == tailSpeed == the shock speed. The
    // head faces the undisturbed state, the tail the star region.
    struct Wave {
        WaveKind kind;
        double headSpeed;
        double tailSpeed;
    };

    // Throws Error for an inadmissible state or when the data generate vacuum (the two
    // rarefactions cannot bring the velocities together above the pressure floor).
    RiemannSolver(const PrimitiveState& left, const RiemannEquationOfState& leftEos,
                  const PrimitiveState& right, const RiemannEquationOfState& rightEos);

    double starPressure() const { return pStar_; }
    double starVelocity() const { return vStar_; }
    double starDensityLeft() const { return rhoStarL_; }
    double starDensityRight() const { return rhoStarR_; }
    FlowState starLeft() const;
    FlowState starRight() const;
    const Wave& leftWave() const { return leftWave_; }
    const Wave& rightWave() const { return rightWave_; }
    double contactSpeed() const { return vStar_; }
    // Newton iterations used (a diagnostic for tests).
    int iterations() const { return iterations_; }

    const PrimitiveState& left() const { return left_; }
    const PrimitiveState& right() const { return right_; }
    const RiemannEquationOfState& leftEos() const { return leftEos_; }
    const RiemannEquationOfState& rightEos() const { return rightEos_; }

    // The state at xi = (x - x0)/t. At xi == contact speed the left star state is returned.
    FlowState sample(double xi) const;
    // True when xi lies on the left material's side of the contact.
    bool isLeftMaterial(double xi) const { return xi <= vStar_; }
    // The initial data as a FlowState (what sample gives far from the waves).
    FlowState leftState() const;
    FlowState rightState() const;

private:
    void solveStarPressure();
    FlowState sampleSide(double xi, int side) const;

    PrimitiveState left_, right_;
    RiemannEquationOfState leftEos_, rightEos_;
    double pStar_ = 0.0, vStar_ = 0.0, rhoStarL_ = 0.0, rhoStarR_ = 0.0;
    Wave leftWave_{}, rightWave_{};
    int iterations_ = 0;
};

}  // namespace mfdyn
