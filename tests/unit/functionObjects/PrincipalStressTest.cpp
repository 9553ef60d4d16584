// fieldMinMax's derived fields maxPrincipalStress and minPrincipalStress (issue 19 item 6, for
// fpmSolid's sphere tests): the extreme eigenvalues of sigma = S - p I from deviatoricStress and
// pressure, below 3D with sigma_zz = -p (the stored deviator in-plane, S_zz = 0). Hand values: a
// diagonal stress, a pure shear S12 = 5 (p = 0: 5 and -5; p = 2 shifts both by -2), rotated
// tensors (the eigenvalues of their diagonal), the out-of-plane -p where it is the extreme, two
// nearly equal eigenvalues to 1e-14 (why Eigen's iterative solver and not computeDirect), a
// pressure of 1e9 beside a unit deviator; then through fieldMinMax from a dictionary, and its
// errors for a missing field.
#include "FunctionObjectTestCase.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/PrincipalStress.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

template <int Dim>
using Context = functionObjectTest::TestContext<Dim>;
fs::path freshCase(const std::string& tag) {
    return functionObjectTest::freshCase("PrincipalStress", tag);
}

std::unique_ptr<FunctionObject> make(const std::string& text, const std::string& name, const RunContext& c) {
    return FunctionObject::New(Dictionary::parse(text, "controlDict"), name, c);
}

std::string errorOf(const std::string& text, const RunContext& c) {
    try {
        make(text, "fo", c);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// R diag(d) R^T with R = Rx(beta) Rz(alpha), in the order (xx yy zz xy yz xz).
std::array<double, 6> rotated(const double d[3], double alpha, double beta) {
    const double ca = std::cos(alpha), sa = std::sin(alpha), cb = std::cos(beta), sb = std::sin(beta);
    const double rz[3][3] = {{ca, -sa, 0}, {sa, ca, 0}, {0, 0, 1}};
    const double rx[3][3] = {{1, 0, 0}, {0, cb, -sb}, {0, sb, cb}};
    double r[3][3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += rx[i][k] * rz[k][j];
    double a[3][3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) a[i][j] += r[i][k] * d[k] * r[j][k];
    return {a[0][0],
            a[1][1],
            a[2][2],
            0.5 * (a[0][1] + a[1][0]),
            0.5 * (a[1][2] + a[2][1]),
            0.5 * (a[0][2] + a[2][0])};
}

// One particle of a Dim-D set with the given deviator components (SymmTensor's order) and p.
template <int Dim>
PrincipalStresses principal(const std::vector<double>& s, double p) {
    ParticleSet<Dim> set;
    set.resize(1);
    auto& S = set.symmTensorField("deviatoricStress");
    set.scalarField("pressure")[0] = p;
    const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    const int order2[3] = {0, 1, 3};  // 2D (xx yy xy) within the 3D order
    for (std::size_t k = 0; k < s.size(); ++k) {
        const int m = Dim == 3 ? int(k) : Dim == 2 ? order2[k] : 0;
        S[0](ij[m][0], ij[m][1]) = s[k];
        S[0](ij[m][1], ij[m][0]) = s[k];
    }
    return PrincipalStressField(set, "test")(0);
}

}  // namespace

TEST(PrincipalStress, DiagonalAndPureShear3D) {
    auto s = principal<3>({3, -1, -2, 0, 0, 0}, 0);
    EXPECT_EQ(s.max, 3.0);
    EXPECT_EQ(s.min, -2.0);
    s = principal<3>({3, -1, -2, 0, 0, 0}, 2);
    EXPECT_EQ(s.max, 1.0);
    EXPECT_EQ(s.min, -4.0);
    // Pure shear S12 = 5: eigenvalues 5, 0, -5.
    s = principal<3>({0, 0, 0, 5, 0, 0}, 0);
    EXPECT_NEAR(s.max, 5.0, 1e-14);
    EXPECT_NEAR(s.min, -5.0, 1e-14);
    s = principal<3>({0, 0, 0, 5, 0, 0}, 2);
    EXPECT_NEAR(s.max, 3.0, 1e-14);
    EXPECT_NEAR(s.min, -7.0, 1e-14);
    // The shear in the other planes (yz, xz) alike.
    s = principal<3>({0, 0, 0, 0, 5, 0}, 0);
    EXPECT_NEAR(s.max, 5.0, 1e-14);
    s = principal<3>({0, 0, 0, 0, 0, 5}, 0);
    EXPECT_NEAR(s.min, -5.0, 1e-14);
}

// diag(4, 1, -5) rotated by 30 degrees about z and 60 about x: every component non-zero (> 0.05), the
// eigenvalues still 4, 1, -5.
TEST(PrincipalStress, RotatedTensor3D) {
    const double d[3] = {4, 1, -5};
    const auto a = rotated(d, M_PI / 6, M_PI / 3);
    for (double c : a) EXPECT_GT(std::abs(c), 0.05);
    const auto e = symmetricEigenvalues(a[0], a[1], a[2], a[3], a[4], a[5]);
    EXPECT_NEAR(e[0], -5.0, 1e-14);
    EXPECT_NEAR(e[1], 1.0, 1e-14);
    EXPECT_NEAR(e[2], 4.0, 1e-14);
    const auto s = principal<3>({a.begin(), a.end()}, 1.5);
    EXPECT_NEAR(s.max, 2.5, 1e-14);
    EXPECT_NEAR(s.min, -6.5, 1e-14);
}

// Two eigenvalues 1 and 1 + 1e-9 (and -2 - 1e-9), rotated: the iterative solver keeps them to
// 1e-14; Eigen's closed form (computeDirect) was off by up to 2.3e-8 on such tensors.
TEST(PrincipalStress, NearlyEqualEigenvalues) {
    const double d[3] = {1, 1 + 1e-9, -2 - 1e-9};
    for (double alpha : {0.1, 0.7, 1.3})
        for (double beta : {0.2, 0.9, 2.1}) {
            const auto a = rotated(d, alpha, beta);
            const auto e = symmetricEigenvalues(a[0], a[1], a[2], a[3], a[4], a[5]);
            EXPECT_NEAR(e[0], d[2], 1e-14) << alpha << " " << beta;
            EXPECT_NEAR(e[1], d[0], 1e-14) << alpha << " " << beta;
            EXPECT_NEAR(e[2], d[1], 1e-14) << alpha << " " << beta;
        }
}

// p is subtracted after the eigenvalues: a unit shear beside p = 1e9 keeps its digits.
TEST(PrincipalStress, LargePressure) {
    const auto s = principal<3>({0, 0, 0, 1, 0, 0}, 1e9);
    EXPECT_EQ(s.max, 1.0 - 1e9);
    EXPECT_EQ(s.min, -1.0 - 1e9);
}

// 2D: the in-plane block of S (xx yy xy) and sigma_zz = -p.
TEST(PrincipalStress, PlaneWithOutOfPlanePressure) {
    auto s = principal<2>({0, 0, 5}, 0);  // pure shear: 5, -5 (and sigma_zz 0)
    EXPECT_EQ(s.max, 5.0);
    EXPECT_EQ(s.min, -5.0);
    s = principal<2>({0, 0, 5}, 2);
    EXPECT_EQ(s.max, 3.0);
    EXPECT_EQ(s.min, -7.0);
    // diag(4, -2) rotated by 30 degrees: xx 4 3/4 - 2 1/4 = 2.5, yy 1 - 1.5 = -0.5, xy 6 sqrt3/4.
    s = principal<2>({2.5, -0.5, 1.5 * std::sqrt(3.0)}, 1);
    EXPECT_NEAR(s.max, 3.0, 1e-14);
    EXPECT_NEAR(s.min, -3.0, 1e-14);
    // An in-plane compression diag(-3, -1): the largest principal stress is sigma_zz = -p = 0.
    s = principal<2>({-3, -1, 0}, 0);
    EXPECT_EQ(s.max, 0.0);
    EXPECT_EQ(s.min, -3.0);
    s = principal<2>({3, 1, 0}, 4);  // in-plane tension 3, 1 less p: -1, -3; sigma_zz -4
    EXPECT_EQ(s.max, -1.0);
    EXPECT_EQ(s.min, -4.0);
    // 1D (the field's rule, though fpmSolid is 2D or 3D): S_xx and the lateral 0, less p.
    s = principal<1>({-2}, 1);
    EXPECT_EQ(s.max, -1.0);
    EXPECT_EQ(s.min, -3.0);
}

// Through fieldMinMax: particle 10 the pure shear S12 = 5 with p = 2 (3, -7), particle 11
// diag(-3, -1) with p = 0 (0, -3), particle 12 diag(4, 0) with p = -1 (tension: 5, 1).
TEST(PrincipalStress, DerivedFieldsOfFieldMinMax) {
    const fs::path root = freshCase("fieldMinMax");
    Context<2> c(root);
    auto& p = c.particles;
    p.resize(3);
    for (std::size_t i = 0; i < 3; ++i) p.globalId()[i] = std::int64_t(10 + i);
    const std::string none = errorOf("type fieldMinMax; fields (maxPrincipalStress);", c);
    EXPECT_NE(none.find("controlDict:1"), std::string::npos) << none;
    EXPECT_NE(none.find("the derived field maxPrincipalStress needs the symmetric tensor field "
                        "'deviatoricStress'"),
              std::string::npos)
        << none;
    auto& S = p.symmTensorField("deviatoricStress");
    const std::string noP = errorOf("type fieldMinMax; fields (minPrincipalStress);", c);
    EXPECT_NE(noP.find("controlDict:1"), std::string::npos) << noP;
    EXPECT_NE(noP.find("the derived field minPrincipalStress needs the scalar field 'pressure'"),
              std::string::npos)
        << noP;
    auto& pressure = p.scalarField("pressure");
    S[0](0, 1) = S[0](1, 0) = 5, pressure[0] = 2;
    S[1](0, 0) = -3, S[1](1, 1) = -1;
    S[2](0, 0) = 4, pressure[2] = -1;
    {
        auto fo = make("type fieldMinMax; fields (maxPrincipalStress minPrincipalStress pressure);", "ps", c);
        fo->write();
    }
    const fs::path file = root / "postProcessing" / "ps" / "0" / "fieldMinMax.csv";
    std::ifstream in(file);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(
        header,
        "time,maxPrincipalStress_min,maxPrincipalStress_minId,maxPrincipalStress_max,"
        "maxPrincipalStress_maxId,minPrincipalStress_min,minPrincipalStress_minId,minPrincipalStress_max,"
        "minPrincipalStress_maxId,pressure_min,pressure_minId,pressure_max,pressure_maxId");
    const auto rows = functionObjectTest::csvRows(file);
    ASSERT_EQ(rows.size(), 1u);
    const double expected[] = {0, 0, 11, 5, 12, -7, 10, 1, 12, -1, 12, 2, 10};
    ASSERT_EQ(rows[0].size(), 13u);
    for (std::size_t k = 0; k < 13; ++k)
        EXPECT_NEAR(rows[0][k], expected[k], 1e-9) << header << " column " << k;
    fs::remove_all(root);
}

// A run with a field of that name keeps it: fieldMinMax reads the field, derives nothing.
TEST(PrincipalStress, StoredFieldWins) {
    const fs::path root = freshCase("stored");
    Context<3> c(root);
    auto& p = c.particles;
    p.resize(2);
    p.globalId()[0] = 0, p.globalId()[1] = 1;
    auto& stored = p.scalarField("maxPrincipalStress");
    stored[0] = 7, stored[1] = -7;
    {
        auto fo = make("type fieldMinMax; fields (maxPrincipalStress);", "stored", c);
        fo->write();
    }
    const auto rows =
        functionObjectTest::csvRows(root / "postProcessing" / "stored" / "0" / "fieldMinMax.csv");
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0][1], -7.0);
    EXPECT_EQ(rows[0][3], 7.0);
    fs::remove_all(root);
}
