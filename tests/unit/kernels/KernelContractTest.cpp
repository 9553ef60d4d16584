// The family contract, over every registered kernel type and d = 1, 2, 3: unit integral, gradient and
// dW/dh equal to finite differences, compact support, and the evaluator table equal to the exact form.
#include "KernelTestTools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <tuple>

namespace mfdyn {
namespace {

using test::makeKernel;

class KernelContract : public ::testing::TestWithParam<std::tuple<std::string, int>> {
protected:
    void SetUp() override {
        type = std::get<0>(GetParam());
        dim = std::get<1>(GetParam());
        kernel = makeKernel("type " + type + ";");
        H = kernel->supportRadius(h);
    }

    // Radii inside the support that stay clear of r = 0, of spline knots and of the support edge by
    // more than the finite-difference stencil, so that every stencil samples one smooth piece.
    std::vector<double> sampleRadii() const {
        std::vector<double> radii;
        for (double u : {0.07, 0.13, 0.21, 0.29, 0.38, 0.46, 0.55, 0.61, 0.72, 0.79, 0.88, 0.93})
            radii.push_back(u * H);
        return radii;
    }

    std::string type;
    int dim = 1;
    std::unique_ptr<Kernel> kernel;
    double h = 0.37;  // not 1, so that a wrong power of h shows
    double H = 0.0;
};

// Central difference with step d, and the truncation error estimated from the same difference at 2d:
// D(2d) - D(d) = 3 c d^2 + O(d^4) when D(d) = f' + c d^2, so |D(d) - f'| ~ |D(2d) - D(d)|/3; the
// tolerance takes the full difference (a factor 3 of safety) plus rounding, eps |f| / d.
struct FiniteDifference {
    double value, tolerance;
};
FiniteDifference centralDifference(const std::function<double(double)>& f, double x, double d) {
    const double d1 = (f(x + d) - f(x - d)) / (2.0 * d);
    const double d2 = (f(x + 2.0 * d) - f(x - 2.0 * d)) / (4.0 * d);
    const double scale = std::max({std::abs(f(x - 2.0 * d)), std::abs(f(x)), std::abs(f(x + 2.0 * d))});
    return {d1, std::abs(d2 - d1) + 8.0 * std::numeric_limits<double>::epsilon() * scale / d};
}

TEST_P(KernelContract, integratesToOne) {
    // Radial Simpson over [0, H): 6000 panels, Richardson-refined, error far below the 1e-8 asked.
    const double edge = H * (1.0 - 1e-14);  // the truncated Gaussian's value at H is its inner limit
    auto f = [&](double r) {
        return test::sphereSurface(dim) * std::pow(r, dim - 1) * kernel->W(std::min(r, edge), h, dim);
    };
    EXPECT_NEAR(test::simpson(f, 0.0, H, 6000), 1.0, 1e-8);
}

TEST_P(KernelContract, compactSupportAndNonNegative) {
    EXPECT_GT(kernel->W(0.0, h, dim), 0.0);
    for (double u : {1.0, 1.0 + 1e-12, 1.3, 2.0, 10.0}) {
        EXPECT_EQ(kernel->W(u * H, h, dim), 0.0) << "u = " << u;
        EXPECT_EQ(kernel->dWdr(u * H, h, dim), 0.0) << "u = " << u;
        EXPECT_EQ(kernel->dWdh(u * H, h, dim), 0.0) << "u = " << u;
    }
    for (int i = 0; i < 1000; ++i) EXPECT_GE(kernel->W(i * H / 1000.0, h, dim), 0.0);
}

template <int Dim>
void checkGradient(const Kernel& kernel, double h, const std::vector<double>& radii) {
    // A direction off every axis, so all components are exercised.
    Vector<Dim> e;
    for (int i = 0; i < Dim; ++i) e[i] = 0.48 - 0.56 * i + 0.1 * i * i;
    e.normalize();
    for (double r : radii) {
        const Vector<Dim> x = r * e;
        const Vector<Dim> grad = kernel.gradW<Dim>(x, h);
        for (int i = 0; i < Dim; ++i) {
            auto f = [&](double xi) {
                Vector<Dim> y = x;
                y[i] = xi;
                return kernel.W(y.norm(), h, Dim);
            };
            const auto fd = centralDifference(f, x[i], 1e-4 * kernel.supportRadius(h));
            EXPECT_NEAR(grad[i], fd.value, fd.tolerance) << "r = " << r << ", component " << i;
        }
        // The SPH sign convention: grad_i W_ij points from i back towards j.
        EXPECT_LE(grad.dot(e), 0.0);
    }
}

TEST_P(KernelContract, gradientMatchesFiniteDifference) {
    if (dim == 1) checkGradient<1>(*kernel, h, sampleRadii());
    if (dim == 2) checkGradient<2>(*kernel, h, sampleRadii());
    if (dim == 3) checkGradient<3>(*kernel, h, sampleRadii());
    // Smooth at the centre: dW/dr vanishes there, up to rounding in summing the spline pieces.
    const double scale = std::abs(kernel->dWdr(0.5 * H, h, dim)) + std::abs(kernel->dWdr(0.25 * H, h, dim));
    EXPECT_NEAR(kernel->dWdr(0.0, h, dim), 0.0, 1e-13 * scale);
}

TEST_P(KernelContract, dWdhMatchesFiniteDifference) {
    for (double r : sampleRadii()) {
        // Keep r/H of every stencil point on the same side of every knot: perturb h by 1e-5 relative.
        const auto fd = centralDifference([&](double hh) { return kernel->W(r, hh, dim); }, h, 1e-5 * h);
        EXPECT_NEAR(kernel->dWdh(r, h, dim), fd.value, fd.tolerance) << "r = " << r;
    }
}

template <int Dim>
void checkEvaluator(const Kernel& kernel, double h) {
    const KernelEvaluator<Dim> ev = kernel.evaluator<Dim>();
    const double H = kernel.supportRadius(h);
    const double W0 = kernel.W(0.0, h, Dim);
    double gradScale = 0.0;
    for (int i = 0; i < 2000; ++i)
        gradScale = std::max(gradScale, std::abs(kernel.dWdr(i * H / 2000.0, h, Dim)));
    // Hermite interpolation on 6144 cells: (1/6144)^4/384 max|w''''| for W, one order less for the
    // derivatives; 1e-10 and 1e-8 leave room for the mollifier's steep derivatives near u = 1.
    for (int i = 0; i <= 12345; ++i) {
        const double r = 1.1 * H * i / 12345.0;
        const auto v = ev.evaluate(r, h);
        ASSERT_NEAR(v.W, kernel.W(r, h, Dim), 1e-10 * W0) << "r/H = " << r / H;
        ASSERT_NEAR(ev.W(r, h), v.W, 0.0);
        ASSERT_NEAR(v.dWdr, kernel.dWdr(r, h, Dim), 1e-8 * gradScale) << "r/H = " << r / H;
        ASSERT_NEAR(ev.dWdr(r, h), v.dWdr, 0.0);
        ASSERT_NEAR(ev.dWdh(r, h), kernel.dWdh(r, h, Dim), 1e-8 * gradScale * H / h) << "r/H = " << r / H;
    }
    Vector<Dim> x = Vector<Dim>::Constant(0.3 * H / std::sqrt(double(Dim)));
    const Vector<Dim> g = ev.gradW(x, x.norm(), h), exact = kernel.gradW<Dim>(x, h);
    for (int i = 0; i < Dim; ++i) EXPECT_NEAR(g[i], exact[i], 1e-8 * gradScale);
    EXPECT_EQ(ev.gradW(Vector<Dim>::Zero(), 0.0, h).norm(), 0.0);
    // Outside the support exactly zero (at r = H itself the rounding of r h^-1 kappa^-1 decides the
    // side, which matters only for the truncated Gaussian's jump).
    EXPECT_EQ(ev.W(H * (1.0 + 1e-12), h), 0.0);
    EXPECT_EQ(ev.dWdr(H * (1.0 + 1e-12), h), 0.0);
    EXPECT_EQ(ev.W(5.0 * H, h), 0.0);
}

TEST_P(KernelContract, evaluatorMatchesExactForm) {
    if (dim == 1) checkEvaluator<1>(*kernel, h);
    if (dim == 2) checkEvaluator<2>(*kernel, h);
    if (dim == 3) checkEvaluator<3>(*kernel, h);
}

TEST_P(KernelContract, supportRadiusConventionRescalesOnly) {
    // With hConvention supportRadius the same kernel is written with h = H.
    auto note = makeKernel("type " + type + "; hConvention supportRadius;");
    EXPECT_EQ(note->kappa(), 1.0);
    EXPECT_DOUBLE_EQ(note->supportRadius(H), H);
    for (double u : {0.0, 0.2, 0.5, 0.77}) {
        EXPECT_NEAR(note->W(u * H, H, dim), kernel->W(u * H, h, dim), 1e-13 * kernel->W(0.0, h, dim));
        EXPECT_NEAR(note->secondMoment(dim) * H, kernel->secondMoment(dim) * h, 1e-14 * H);
    }
}

std::vector<std::tuple<std::string, int>> everyTypeAndDimension() {
    std::vector<std::tuple<std::string, int>> out;
    for (const auto& name : Kernel::Selector::names())
        for (int dim = 1; dim <= 3; ++dim) out.emplace_back(name, dim);
    return out;
}

INSTANTIATE_TEST_SUITE_P(everyType, KernelContract, ::testing::ValuesIn(everyTypeAndDimension()),
                         [](const auto& info) {
                             return std::get<0>(info.param) + "_" + std::to_string(std::get<1>(info.param)) +
                                    "D";
                         });

TEST(KernelFamily, registersTheSevenTypes) {
    const std::vector<std::string> expected{"cubicSpline", "gaussian",   "mollifier", "quinticSpline",
                                            "wendlandC2",  "wendlandC4", "wendlandC6"};
    for (const auto& name : expected) {
        const auto names = Kernel::Selector::names();
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    }
}

// Every kernel type reads through a keyword schema registered with it: `hConvention` for all, the
// gaussian's `cutoff`; each required keyword (none so far) removed is named; a wrong word or an
// out-of-bounds value is an InputError naming the keyword.
TEST(KernelKeywords, EveryTypeDeclaresAKeywordSchema) {
    makeKernel("type wendlandC2;");
    const RegistryFamily* family = RegistryIndex::global().findFamily(Kernel::familyName);
    ASSERT_NE(family, nullptr);
    for (const auto& type : Kernel::Selector::names()) {
        const RegistryItem* item = family->find(type);
        ASSERT_NE(item->keywords, nullptr) << type << " declares no keyword schema";
        const KeywordSchema schema = item->keywords();
        EXPECT_EQ(schema.type(), type);
        EXPECT_NE(schema.find("hConvention"), nullptr) << type;
        EXPECT_EQ(item->sourceFile.rfind("libraries/kernels/", 0), 0u) << item->sourceFile;
        for (const Keyword& k : schema.keywords()) {
            if (k.kind != Keyword::Kind::required) continue;
            // A dictionary with every keyword at its sample value, less this one.
            std::string text = "type " + type + ";";
            for (const Keyword& other : schema.keywords())
                if (other.name != k.name) text += " " + other.name + " " + other.sampleValue() + ";";
            try {
                makeKernel(text);
                ADD_FAILURE() << type << " built without required " << k.name;
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find("missing keyword '" + k.name + "'"), std::string::npos)
                    << e.what();
            }
        }
    }
    try {
        makeKernel("type wendlandC2; hConvention radius;");
        ADD_FAILURE() << "unknown hConvention accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected one of standard | supportRadius"), std::string::npos)
            << e.what();
    }
    try {
        makeKernel("type gaussian; cutoff -1;");
        ADD_FAILURE() << "negative cutoff accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("keyword 'cutoff': expected a value > 0, found -1"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace mfdyn
