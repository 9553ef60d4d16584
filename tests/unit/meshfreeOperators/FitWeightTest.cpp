// The family fitWeight: every registered type against its contract (W(0) = 1, 0 <= W <= 1, zero
// beyond the support, zero slope at the centre, dW/dd the derivative of W), each type's closed
// form at one point, `squared`, and the errors of a bad name and a bad parameter.
//
// Tolerances: closed forms are evaluated by the same few operations, 1e-15; the derivative
// against a central difference with step 1e-6 (truncation 1e-12 times W''', round-off 1e-16/1e-6),
// 1e-8.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace mfdyn {
namespace {

std::unique_ptr<FitWeight> make(const std::string& text) {
    return FitWeight::New(Dictionary::parse(text, "test"));
}

TEST(FitWeight, contractOfEveryType) {
    const auto names = FitWeight::Selector::names();
    ASSERT_GE(names.size(), 3u);
    for (const auto& name : names) {
        SCOPED_TRACE(name);
        const auto w = make("type " + name + ";");
        EXPECT_TRUE(w->squared());  // the thesis's default
        EXPECT_NEAR(w->shape(0.0), 1.0, 1e-15);
        EXPECT_NEAR(w->shapeDerivative(0.0), 0.0, 1e-15);
        const double h = 0.37;
        EXPECT_EQ(w->W(1.0001 * h, h), 0.0);
        EXPECT_EQ(w->dWdd(1.0001 * h, h), 0.0);
        for (int i = 1; i < 100; ++i) {
            const double q = i / 100.0, d = q * h;
            EXPECT_GE(w->W(d, h), 0.0);
            EXPECT_LE(w->W(d, h), 1.0);
            const double e = 1e-6 * h;
            const double fd = (w->W(d + e, h) - w->W(d - e, h)) / (2 * e);
            EXPECT_NEAR(w->dWdd(d, h), fd, 1e-8 / h) << "q = " << q;
            EXPECT_NEAR(w->fitWeight(d, h), w->W(d, h) * w->W(d, h), 1e-15);
            EXPECT_NEAR(w->fitWeightDerivative(d, h), 2 * w->W(d, h) * w->dWdd(d, h), 1e-14 / h);
        }
    }
}

TEST(FitWeight, closedForms) {
    const auto g = make("type truncatedGaussian;");  // alpha 6.25 by default
    EXPECT_NEAR(g->shape(0.5), std::exp(-6.25 * 0.25), 1e-15);
    EXPECT_NEAR(g->shape(1.0), std::exp(-6.25), 1e-15);  // the jump truncation leaves: 1.9e-3
    const auto g2 = make("type truncatedGaussian; alpha 2; squared no;");
    EXPECT_FALSE(g2->squared());
    EXPECT_NEAR(g2->fitWeight(0.5, 1.0), std::exp(-0.5), 1e-15);
    EXPECT_NEAR(g2->fitWeightDerivative(0.5, 1.0), -2.0 * 2.0 * 0.5 * std::exp(-0.5), 1e-15);
    const auto wc2 = make("type wendlandC2;");
    EXPECT_NEAR(wc2->shape(0.5), std::pow(0.5, 4) * 3.0, 1e-15);
    const auto m4 = make("type cubicSpline;");
    EXPECT_NEAR(m4->shape(0.5), 0.25, 1e-15);  // both pieces meet at 1/4 (M4's 1/4 of its centre)
    EXPECT_NEAR(m4->shape(0.75), 2.0 / 64.0, 1e-15);
}

TEST(FitWeight, badNameNamesFileLineAndTheValidTypes) {
    const std::string text = "// FPM\n\nfitWeight\n{\n    type gausian;\n}\n";
    const Dictionary dict = Dictionary::parse(text, "constant/fpmProperties");
    try {
        FitWeight::New(dict.subDict("fitWeight"));
        FAIL() << "no InputError for an unknown fit weight";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("constant/fpmProperties:5"), std::string::npos) << what;  // the type line
        for (const auto& name : FitWeight::Selector::names())
            EXPECT_NE(what.find(name), std::string::npos) << name << " missing from: " << what;
    }
}

TEST(FitWeight, badParameterIsAnInputError) {
    EXPECT_THROW(make("type truncatedGaussian; alpha 0;"), InputError);
    EXPECT_THROW(make("type truncatedGaussian; alpha -1;"), InputError);
    EXPECT_THROW(make("type wendlandC2; squared maybe;"), InputError);
}

}  // namespace
}  // namespace mfdyn
