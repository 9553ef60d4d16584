// Kernels against published numbers: the normalisation constants (doc/methods/sph-impact.md 1.1, Dehnen & Aly
// 2012 Table 1), the second moments s_d of doc/methods/sph-impact.md 1.2, resolution matching, the truncated
// Gaussian in closed form, and the input errors.
#include "KernelTestTools.hpp"

#include "core/Error.hpp"
#include "kernels/Gaussian.hpp"

#include <gtest/gtest.h>

#include <map>

namespace mfdyn {
namespace {

using test::makeKernel;
constexpr double pi = std::numbers::pi;

TEST(KernelNormalisation, matchesClosedForms) {
    // c_d of the unit-support shape; quadrature error is at rounding level, so 1e-13 relative.
    const std::map<std::string, std::array<double, 3>> closed{
        {"cubicSpline", {8.0 / 3.0, 80.0 / (7.0 * pi), 16.0 / pi}},
        {"quinticSpline", {243.0 / 40.0, 7.0 * 2187.0 / (478.0 * pi), 2187.0 / (40.0 * pi)}},
        {"wendlandC2", {5.0 / 4.0, 7.0 / pi, 21.0 / (2.0 * pi)}},
        {"wendlandC4", {3.0 / 2.0, 9.0 / pi, 495.0 / (32.0 * pi)}},
        {"wendlandC6", {55.0 / 32.0, 78.0 / (7.0 * pi), 1365.0 / (64.0 * pi)}},
    };
    for (const auto& [type, c] : closed) {
        auto kernel = makeKernel("type " + type + ";");
        for (int d = 1; d <= 3; ++d)
            EXPECT_NEAR(kernel->normalisation(d), c[d - 1], 1e-13 * c[d - 1]) << type << d;
    }
}

TEST(KernelNormalisation, gaussianRenormalisedOverTruncatedSupport) {
    for (double a : {1.5, 3.0, 4.0}) {
        auto kernel = makeKernel("type gaussian; cutoff " + std::to_string(a) + ";");
        const double e = std::exp(-a * a);
        const std::array<double, 3> kept{std::sqrt(pi) * std::erf(a), pi * (1.0 - e),
                                         std::pow(pi, 1.5) * std::erf(a) - 2.0 * pi * a * e};
        for (int d = 1; d <= 3; ++d) {
            const double c = std::pow(a, d) / kept[d - 1];
            EXPECT_NEAR(kernel->normalisation(d), c, 1e-13 * c) << "cutoff " << a << ", d = " << d;
            // Removed fraction of the untruncated mass pi^(d/2).
            EXPECT_NEAR(kernel->truncatedMass(d), 1.0 - kept[d - 1] / std::pow(pi, 0.5 * d), 1e-15);
        }
        EXPECT_DOUBLE_EQ(kernel->supportRadius(1.0), a);
    }
}

TEST(KernelNormalisation, mollifierConstantToTwelveDigits) {
    // The note's [C] values to their 5 digits, and an independent Simpson-Boole quadrature of the
    // bump (C-infinity, so 200000 panels converge far below the 1e-12 asked).
    auto kernel = makeKernel("type mollifier;");
    const std::array<double, 3> note{2.2523, 2.1436, 2.2671};
    for (int d = 1; d <= 3; ++d) {
        EXPECT_NEAR(kernel->normalisation(d), note[d - 1], 0.5e-4) << d;
        auto f = [&](double u) { return test::sphereSurface(d) * std::pow(u, d - 1) * kernel->shape(u, d); };
        const double c = 1.0 / test::simpson(f, 0.0, 1.0, 200000);
        EXPECT_NEAR(kernel->normalisation(d), c, 1e-12 * c) << d;
    }
}

// doc/methods/sph-impact.md 1.2: s_d for h = H (so s_d(kernel)/kappa here) and H/h_DA = sqrt(d)/(2 s_d). The
// note prints 4 and 3 decimals: its values are within half a unit of the last digit of the truth.
struct NoteRow {
    std::string dictionary;
    std::array<double, 3> s, HoverhDA;
};
const std::vector<NoteRow>& noteTable() {
    static const std::vector<NoteRow> rows{
        {"type mollifier;", {0.3976, 0.5112, 0.5789}, {1.257, 1.383, 1.496}},
        {"type cubicSpline;", {0.2887, 0.3977, 0.4743}, {1.732, 1.778, 1.826}},
        // The note prints s_2 = 0.3277 for M6; the exact value is 0.327648 (below), which rounds to
        // 0.3276 and agrees with the note's own H/h_DA = 2.158. The table here carries the fix.
        {"type quinticSpline;", {0.2357, 0.3276, 0.3944}, {2.121, 2.158, 2.196}},
        {"type wendlandC2;", {0.3086, 0.3727, 0.4472}, {1.620, 1.897, 1.936}},
        {"type wendlandC4;", {0.2582, 0.3257, 0.3922}, {1.936, 2.171, 2.208}},
        // The note's Gaussian exp(-9q^2) is untruncated in its moments. Cutoff 6 (tail e^-36) is the
        // untruncated Gaussian to 1e-14, but on a support twice as wide: s_d halves, H/h_DA doubles.
        {"type gaussian; cutoff 6;",
         {0.2357 / 2.0, 0.3333 / 2.0, 0.4082 / 2.0},
         {2.121 * 2.0, 2.121 * 2.0, 2.121 * 2.0}},
    };
    return rows;
}

TEST(KernelSecondMoment, matchesNoteTable) {
    for (const auto& row : noteTable()) {
        auto kernel = makeKernel(row.dictionary);
        // The gaussian row is the note's scaled by 3/6: its rounding bounds scale alike.
        const double scale = row.dictionary.find("gaussian") != std::string::npos ? 0.5 : 1.0;
        for (int d = 1; d <= 3; ++d) {
            const double sH = kernel->secondMoment(d) / kernel->kappa();
            EXPECT_NEAR(sH, row.s[d - 1], 0.5e-4 * scale + 1e-12) << row.dictionary << " d = " << d;
            EXPECT_NEAR(std::sqrt(double(d)) / (2.0 * sH), row.HoverhDA[d - 1], 0.5e-3 / scale + 1e-12)
                << row.dictionary << " d = " << d;
        }
    }
}

TEST(KernelSecondMoment, splinesExact) {
    // s_d^2 = int u^(d+1) w / int u^(d-1) w is rational for the splines; these digits come from exact
    // rational integration of the polynomial pieces, done apart from this code.
    const std::map<std::string, std::array<double, 3>> exact{
        {"cubicSpline", {0.28867513459481287, 0.3976974544878587, 0.4743416490252569}},
        {"quinticSpline", {0.23570226039551584, 0.3276479346320533, 0.39440531887330776}}};
    for (const auto& [type, s] : exact) {
        auto kernel = makeKernel("type " + type + ";");
        for (int d = 1; d <= 3; ++d)
            EXPECT_NEAR(kernel->secondMoment(d) / kernel->kappa(), s[d - 1], 1e-14) << type << d;
    }
}

TEST(KernelSecondMoment, byIndependentQuadrature) {
    // sigma^2 = integral |x|^2 W over R^d by radial Simpson with the public W, h = 0.37.
    const double h = 0.37;
    for (const auto& type : Kernel::Selector::names()) {
        auto kernel = makeKernel("type " + type + ";");
        const double H = kernel->supportRadius(h), edge = H * (1.0 - 1e-14);
        for (int d = 1; d <= 3; ++d) {
            auto f = [&](double r) {
                return test::sphereSurface(d) * std::pow(r, d + 1) * kernel->W(std::min(r, edge), h, d);
            };
            const double sigma = std::sqrt(test::simpson(f, 0.0, H, 6000));
            EXPECT_NEAR(kernel->secondMoment(d) * h, sigma, 1e-9 * sigma) << type << " d = " << d;
        }
    }
}

TEST(KernelSecondMoment, truncatedGaussianClosedForm) {
    // s_d^2 = int_0^a r^(d+1) e^-r^2 dr / int_0^a r^(d-1) e^-r^2 dr for the default cutoff a = 3.
    auto kernel = makeKernel("type gaussian;");
    const double a = 3.0, e = std::exp(-a * a), erfa = std::erf(a), sp = std::sqrt(pi);
    const std::array<double, 3> s2{
        (0.25 * sp * erfa - 0.5 * a * e) / (0.5 * sp * erfa),
        0.5 * (1.0 - (1.0 + a * a) * e) / (0.5 * (1.0 - e)),
        (0.375 * sp * erfa - e * (0.5 * a * a * a + 0.75 * a)) / (0.25 * sp * erfa - 0.5 * a * e)};
    for (int d = 1; d <= 3; ++d) {
        EXPECT_NEAR(kernel->secondMoment(d), std::sqrt(s2[d - 1]), 1e-13) << d;
        // Truncation at 3h narrows the kernel below sqrt(d/2) (the note's value, times 3) by
        // about a e^-a^2 relative: why the note's table is compared at cutoff 6 above.
        EXPECT_LT(kernel->secondMoment(d), std::sqrt(0.5 * d));
    }
}

TEST(KernelResolution, matchedSmoothingLengthEqualsStandardDeviation) {
    auto m4 = makeKernel("type cubicSpline;");
    auto c2 = makeKernel("type wendlandC2;");
    auto gauss = makeKernel("type gaussian;");
    for (int d = 1; d <= 3; ++d) {
        const double h = matchedSmoothingLength(*m4, 1.2, *c2, d);
        EXPECT_NEAR(c2->secondMoment(d) * h, m4->secondMoment(d) * 1.2, 1e-14);
        // Round trip.
        EXPECT_NEAR(matchedSmoothingLength(*c2, h, *m4, d), 1.2, 1e-14);
    }
    // The note's numbers: M4 support radius H = 2h matched to Wendland C2 in 3D,
    // H2 = H1 s_3(M4)/s_3(C2) = H1 0.4743/0.4472 (4-digit table: relative bound 2.5e-4).
    const double H1 = m4->supportRadius(1.0);
    const double H2 = c2->supportRadius(matchedSmoothingLength(*m4, 1.0, *c2, 3));
    EXPECT_NEAR(H2 / H1, 0.4743 / 0.4472, 2.5e-4 * 0.4743 / 0.4472);
    // The thesis default (doc/methods/sph-impact.md 1.2): a Gaussian e^-(r/h)^2 with h = 1.2 dx cut at 3h has
    // sigma_1D = 0.8485 dx; M4 at equal sigma in 1D has H/dx = 2.94 (last column of the table).
    const double hM4 = matchedSmoothingLength(*gauss, 1.2, *m4, 1);
    EXPECT_NEAR(gauss->secondMoment(1) * 1.2, 0.8485, 1e-3);  // truncation shifts the 4th digit
    EXPECT_NEAR(m4->supportRadius(hM4), 2.94, 0.005 + 0.005);
}

TEST(KernelErrors, unknownTypeListsValidTypes) {
    try {
        makeKernel("type wendlandC3;");
        FAIL() << "no InputError for an unknown kernel type";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("did you mean"), std::string::npos) << message;
        for (const auto& name : Kernel::Selector::names())
            EXPECT_NE(message.find(name), std::string::npos) << name << " missing from: " << message;
        EXPECT_NE(message.find("libmfdyn_kernels"), std::string::npos) << message;
    }
}

TEST(KernelErrors, missingTypeListsValidTypes) {
    try {
        makeKernel("cutoff 3;");
        FAIL() << "no InputError for a missing type";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("wendlandC2"), std::string::npos) << e.what();
    }
}

TEST(KernelErrors, badParametersAreInputErrors) {
    EXPECT_THROW(makeKernel("type gaussian; cutoff -1;"), InputError);
    EXPECT_THROW(makeKernel("type gaussian; cutoff 0;"), InputError);
    EXPECT_THROW(makeKernel("type wendlandC2; hConvention radius;"), InputError);
    EXPECT_THROW(makeKernel("type wendlandC2;")->normalisation(4), std::invalid_argument);
}

TEST(KernelConvention, supportFactors) {
    const std::map<std::string, double> kappa{
        {"cubicSpline", 2.0}, {"quinticSpline", 3.0}, {"wendlandC2", 2.0}, {"wendlandC4", 2.0},
        {"wendlandC6", 2.0},  {"gaussian", 3.0},      {"mollifier", 1.0}};
    for (const auto& [type, k] : kappa) {
        auto kernel = makeKernel("type " + type + ";");
        EXPECT_EQ(kernel->kappa(), k) << type;
        EXPECT_DOUBLE_EQ(kernel->supportRadius(0.5), 0.5 * k) << type;
    }
}

}  // namespace
}  // namespace mfdyn
