// mieGruneisen with gruneisen constantRhoGamma (Γρ = Γ0ρ0): the same Hugoniot as the thesis's
// constant Γ (P(ρ, e_H) = P_H exactly with hugoniot linearUsUp), c² equal to the isentropic
// derivative dP/dρ + (P/ρ²) dP/de (central differences, step 1e-6 relative: error ~1e-10 of c²),
// and c² > 0 in the state where the constant-Γ form gives c² < 0 (ρ = 5219.54, e = 8.286e6 for Al2).
#include "core/Dictionary.hpp"
#include "materials/equationOfState/EquationOfState.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfdyn;

namespace {
std::unique_ptr<EquationOfState> al2(const std::string& extra) {
    return EquationOfState::New(Dictionary::parse(
        "type mieGruneisen; rho0 2785; c0 5330; s 1.338; gamma0 2.0; hugoniot linearUsUp; " + extra, "test"));
}
}  // namespace

TEST(MieGruneisenRhoGamma, ReproducesTheHugoniot) {
    const auto eos = al2("gruneisen constantRhoGamma;");
    for (double up : {500.0, 2000.0, 4000.0}) {
        const double us = 5330 + 1.338 * up;
        const double rho = 2785 * us / (us - up);
        EXPECT_NEAR(eos->pressure(rho, 0.5 * up * up) / (2785 * us * up), 1.0, 1e-12);
    }
}

TEST(MieGruneisenRhoGamma, SoundSpeedIsTheIsentropicDerivative) {
    const auto eos = al2("gruneisen constantRhoGamma;");
    for (double rho : {2500.0, 2785.0, 3500.0, 5000.0}) {
        for (double e : {0.0, 1e6, 8e6}) {
            const double d = 1e-6 * rho, de = 1e-6 * std::max(e, 1e5);
            const double dPdrho = (eos->pressure(rho + d, e) - eos->pressure(rho - d, e)) / (2 * d);
            const double dPde = (eos->pressure(rho, e + de) - eos->pressure(rho, e - de)) / (2 * de);
            const double expected = dPdrho + eos->pressure(rho, e) / (rho * rho) * dPde;
            EXPECT_NEAR(eos->soundSpeedSquared(rho, e) / expected, 1.0, 1e-6) << rho << " " << e;
        }
    }
}

TEST(MieGruneisenRhoGamma, StaysHyperbolicWhereConstantGammaDoesNot) {
    EXPECT_LT(al2("")->soundSpeedSquared(5219.54, 8.28606e6), 0.0);
    EXPECT_GT(al2("gruneisen constantRhoGamma;")->soundSpeedSquared(5219.54, 8.28606e6), 0.0);
    EXPECT_THROW(al2("gruneisen sometimes;"), InputError);
}
