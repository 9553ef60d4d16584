// The strength family contract (Strength.hpp) for every registered type, in 2D and 3D, each
// built through Strength<Dim>::New from one dictionary that carries every built-in model's
// keywords: elastic response tau = 2G dev(eps), return onto the yield surface, objectivity under
// a rigid rotation (and its sense), tr tau = 0 kept, and the none type allocating nothing.
#include "materials/strength/Strength.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace mfdyn {
namespace {

constexpr double shearG = 27.1e9;
constexpr double yield0 = 0.265e9;

// Al-2024 (note Table 6.1) for the elastic and von Mises constants; Johnson & Cook's 2024-T351
// hardening so that johnsonCook's initial yield equals yieldStress at room temperature.
const std::vector<std::pair<std::string, std::string>> contractKeywords{{"shearModulus", "27.1e9"},
                                                                        {"yieldStress", "0.265e9"},
                                                                        {"A", "0.265e9"},
                                                                        {"B", "0.426e9"},
                                                                        {"n", "0.34"},
                                                                        {"C", "0.015"},
                                                                        {"m", "1"},
                                                                        {"Tmelt", "775"},
                                                                        {"specificHeat", "875"}};

std::string contractDictionary(const std::string& type, const std::string& without = "") {
    std::string text = "type " + type + ";";
    for (const auto& [key, value] : contractKeywords)
        if (key != without) text += " " + key + " " + value + ";";
    return text;
}

// One block of `n` particles with every field a model may use.
template <int Dim>
struct Block {
    explicit Block(const Strength<Dim>& s, std::size_t n = 3)
        : L(n, Tensor<Dim>::Zero()),
          rho(n, 2785.0),
          tau(n),
          tauRate(n),
          epsP(n, 0.0),
          temperature(n, s.initialTemperature()),
          work(n, 0.0) {}

    typename Strength<Dim>::Fields fields() {
        typename Strength<Dim>::Fields f;
        f.size = tau.size();
        f.velocityGradient = L.data();
        f.density = rho.data();
        f.tau = tau.data();
        f.tauRate = tauRate.data();
        f.plasticStrain = epsP.data();
        f.temperature = temperature.data();
        f.plasticWorkRate = work.data();
        return f;
    }
    void setGradient(const Tensor<Dim>& g) {
        for (auto& l : L) l = g;
    }

    std::vector<Tensor<Dim>> L;
    std::vector<double> rho;
    std::vector<SymmTensor<Dim>> tau, tauRate;
    std::vector<double> epsP, temperature, work;
};

template <int Dim>
std::unique_ptr<Strength<Dim>> make(const std::string& type) {
    return Strength<Dim>::New(Dictionary::parse(contractDictionary(type), "test"));
}

template <int Dim>
std::vector<std::string> registeredTypes() {
    make<Dim>("none");  // registrations are made when the library loads; New makes sure it did
    return Strength<Dim>::Selector::names();
}

// The keyword schema registered with `type` (every strength type declares one).
template <int Dim>
KeywordSchema schemaOf(const std::string& type) {
    const RegistryFamily* family = RegistryIndex::global().findFamily(Strength<Dim>::familyName);
    const RegistryItem* item = family ? family->find(type) : nullptr;
    if (!item || !item->keywords) {
        ADD_FAILURE() << "strength type " << type << " declares no keyword schema";
        return {};
    }
    EXPECT_EQ(item->sourceFile.rfind("libraries/materials/strength/", 0), 0u) << item->sourceFile;
    return item->keywords();
}

template <int Dim>
double norm(const SymmTensor<Dim>& t) {
    return t.full().norm();
}

// 2G (D - alpha tr D I) t for a constant symmetric D: the deviatoric strain of the path.
template <int Dim>
Tensor<Dim> elasticPrediction(const Strength<Dim>& s, const Tensor<Dim>& strain) {
    Tensor<Dim> dev = strain;
    dev.diagonal().array() -= s.deviatorWeight() * strain.trace();
    return 2.0 * s.shearModulus() * dev;
}

// exp(A) of a skew A (Rodrigues): I + sin(t)/t A + (1 - cos t)/t^2 A^2, t^2 = A:A/2.
template <int Dim>
Tensor<Dim> rotation(const Tensor<Dim>& a) {
    const double t = std::sqrt(0.5 * a.squaredNorm());
    return Tensor<Dim>::Identity() + std::sin(t) / t * a + (1.0 - std::cos(t)) / (t * t) * a * a;
}

template <class D>
class StrengthContract : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(StrengthContract, Dimensions);

TYPED_TEST(StrengthContract, BuiltInTypesAreRegistered) {
    constexpr int Dim = TypeParam::value;
    const auto names = registeredTypes<Dim>();
    const std::set<std::string> found(names.begin(), names.end());
    for (const char* t : {"none", "hookean", "vonMises", "johnsonCook"}) EXPECT_TRUE(found.count(t)) << t;
    for (const auto& t : names) {
        const auto s = make<Dim>(t);
        EXPECT_EQ(s->type(), t);
        // Only `none` may leave tau unallocated, and then it has no strength at all.
        EXPECT_EQ(s->allocatesStress(), t != "none") << t;
        EXPECT_EQ(schemaOf<Dim>(t).empty(), t == "none") << t;  // every elastic law declares G at least
        if (!s->allocatesStress()) {
            EXPECT_EQ(s->yieldStress(0.0, 0.0, 300.0), 0.0) << t;
        }
    }
}

// The schema each model declares: defaults within bounds, and every required keyword, removed
// from the dictionary, reported by name.
TYPED_TEST(StrengthContract, RequiredKeywordsAreNamedWhenMissing) {
    constexpr int Dim = TypeParam::value;
    for (const auto& type : registeredTypes<Dim>()) {
        const KeywordSchema schema = schemaOf<Dim>(type);
        for (const Keyword& key : schema.keywords()) {
            if (key.kind == Keyword::Kind::defaulted) {
                if (key.type != Keyword::Type::scalar) continue;
                const double v = key.defaultNumber;
                EXPECT_TRUE(
                    (!key.lower || (key.lower->open ? v > key.lower->value : v >= key.lower->value)) &&
                    (!key.upper || (key.upper->open ? v < key.upper->value : v <= key.upper->value)))
                    << key.name;
                continue;
            }
            if (key.kind != Keyword::Kind::required) continue;
            try {
                Strength<Dim>::New(Dictionary::parse(contractDictionary(type, key.name), "test"));
                ADD_FAILURE() << type << " built without required " << key.name;
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find("missing keyword '" + key.name + "'"), std::string::npos)
                    << e.what();
            }
        }
    }
}

TYPED_TEST(StrengthContract, ElasticUniaxialAndPureShear) {
    constexpr int Dim = TypeParam::value;
    Tensor<Dim> uniaxial = Tensor<Dim>::Zero();
    uniaxial(0, 0) = 1.0;
    Tensor<Dim> shear = Tensor<Dim>::Zero();
    shear(0, 1) = shear(1, 0) = 0.5;  // pure shear: D without spin, so tau is linear in time
    Tensor<Dim> mixed = 0.3 * uniaxial + shear;
    mixed(Dim - 1, Dim - 1) -= 0.7;
    for (const auto& type : registeredTypes<Dim>()) {
        const auto s = make<Dim>(type);
        for (const Tensor<Dim>& direction : {uniaxial, shear, mixed}) {
            Block<Dim> b(*s);
            const double rate = 1e3, dt = 1e-9;  // total strain 1e-4: sigmaEq ~ 3G 1e-4 << sigma_Y
            const int steps = 100;
            b.setGradient(rate * direction);
            for (int k = 0; k < steps; ++k) s->update(b.fields(), dt);
            if (!s->allocatesStress()) {
                EXPECT_EQ(norm(b.tau[0]), 0.0) << type;
                continue;
            }
            const Tensor<Dim> expected = elasticPrediction(*s, Tensor<Dim>(rate * steps * dt * direction));
            // 100 additions of equal increments: a few hundred ulps of |tau|.
            EXPECT_LE((b.tau[1].full() - expected).norm(), 1e-12 * expected.norm()) << type;
            EXPECT_EQ(b.epsP[1], 0.0) << type;
            EXPECT_EQ(b.work[1], 0.0) << type;
        }
    }
}

TYPED_TEST(StrengthContract, PlasticStateLiesOnTheYieldSurface) {
    constexpr int Dim = TypeParam::value;
    for (const auto& type : registeredTypes<Dim>()) {
        const auto s = make<Dim>(type);
        if (!std::isfinite(s->yieldStress(0.0, 0.0, s->initialTemperature())) || !s->allocatesStress())
            continue;
        Block<Dim> b(*s);
        // Strain increments of 1e-3 along a path that turns and spins: plastic after ~4 steps.
        Tensor<Dim> g = Tensor<Dim>::Zero();
        g(0, 0) = 1.0;
        g(0, 1) = 0.4;
        g(1, 0) = -0.2;
        g(Dim - 1, Dim - 1) += -0.6;
        const double dt = 1e-6, rate = 1e3;
        int plasticSteps = 0;
        for (int k = 0; k < 40; ++k) {
            const Tensor<Dim> turn = k < 20 ? g : Tensor<Dim>(g.transpose());
            b.setGradient(rate * turn);
            const double epsBefore = b.epsP[0], temperatureBefore = b.temperature[0];
            s->update(b.fields(), dt);
            const double sigma = s->equivalentStress(b.tau[0]);
            const double yield =
                s->yieldStress(b.epsP[0], s->equivalentStrainRate(b.L[0]), temperatureBefore);
            EXPECT_GE(b.epsP[0], epsBefore) << type;
            EXPECT_GE(b.work[0], 0.0) << type;
            if (b.epsP[0] > epsBefore) {
                ++plasticSteps;
                // Scaling by sigma_Y/sigma*: a few ulps (1e-10 is the brief's bound).
                EXPECT_NEAR(sigma, yield, 1e-10 * yield) << type << " step " << k;
            } else {
                EXPECT_LE(sigma, yield * (1 + 1e-12)) << type << " step " << k;
            }
        }
        EXPECT_GT(plasticSteps, 20) << type;
    }
}

// Under v = W x the material turns by Q(t) = exp(W t), and an objective stress turns with it:
// tau(t) = Q tau0 Q^T. Forward Euler keeps J2 to second order in the step: the drift of one step
// falls 4-fold when dt is halved, and the error after a fixed angle halves with dt.
TYPED_TEST(StrengthContract, RigidRotationRotatesStressAndKeepsInvariants) {
    constexpr int Dim = TypeParam::value;
    Tensor<Dim> spin = Tensor<Dim>::Zero();
    spin(0, 1) = -1.0;
    spin(1, 0) = 1.0;  // counter-clockwise about z at 1 rad/s (times omega)
    if constexpr (Dim == 3) spin(1, 2) = -0.5, spin(2, 1) = 0.5;
    for (const auto& type : registeredTypes<Dim>()) {
        const auto s = make<Dim>(type);
        if (!s->allocatesStress()) continue;
        // An elastic deviatoric state at about a third of yield.
        Tensor<Dim> t0 = Tensor<Dim>::Zero();
        t0(0, 0) = 60e6;
        t0(1, 1) = -20e6;
        t0(0, 1) = t0(1, 0) = 35e6;
        if constexpr (Dim == 3) t0(2, 2) = -40e6, t0(1, 2) = t0(2, 1) = -10e6;
        t0.diagonal().array() -= t0.trace() / Dim;
        const SymmTensor<Dim> tau0 = SymmTensor<Dim>::fromFull(t0);
        const double j0 = s->equivalentStress(tau0);
        const double omega = 1e4;

        auto drift = [&](double dt) {
            Block<Dim> b(*s, 1);
            b.tau[0] = tau0;
            b.setGradient(omega * spin);
            s->update(b.fields(), dt);
            return s->equivalentStress(b.tau[0]) - j0;
        };
        const double d1 = drift(1e-6), d2 = drift(0.5e-6);
        EXPECT_GT(d1, 0.0) << type;
        EXPECT_NEAR(d1 / d2, 4.0, 0.01) << type << ": J2 drift not O(dt^2)";
        EXPECT_LT(d1, 1e-3 * j0) << type;

        auto rotationError = [&](int steps) {
            const double angle = 0.5, dt = angle / omega / steps;
            Block<Dim> b(*s, 1);
            b.tau[0] = tau0;
            b.setGradient(omega * spin);
            for (int k = 0; k < steps; ++k) s->update(b.fields(), dt);
            const Tensor<Dim> q = rotation<Dim>(angle * spin);
            return (b.tau[0].full() - q * t0 * q.transpose()).norm() / t0.norm();
        };
        const double e1 = rotationError(200), e2 = rotationError(400);
        EXPECT_LT(e1, 5e-3) << type;
        EXPECT_NEAR(e1 / e2, 2.0, 0.05) << type << ": rotation error not first order over a fixed angle";
    }
}

TYPED_TEST(StrengthContract, TraceStaysZero) {
    constexpr int Dim = TypeParam::value;
    for (const auto& type : registeredTypes<Dim>()) {
        const auto s = make<Dim>(type);
        if (!s->allocatesStress()) continue;
        Block<Dim> b(*s);
        // A compressive, spinning, shearing gradient; elastic, then well into plastic flow.
        Tensor<Dim> g = Tensor<Dim>::Zero();
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) g(i, j) = std::sin(1.0 + 3 * i + 7 * j);
        b.setGradient(2e3 * g);
        for (int k = 0; k < 30; ++k) {
            s->update(b.fields(), 1e-6);
            ASSERT_LE(std::abs(b.tau[2].full().trace()), 1e-14 * norm(b.tau[2]) + 1e-9)
                << type << " step " << k;
        }
        const bool yields = std::isfinite(s->yieldStress(0.0, 0.0, s->initialTemperature()));
        EXPECT_TRUE(!yields || b.epsP[2] > 0.0) << type << ": no plastic flow";
    }
}

TYPED_TEST(StrengthContract, StressRateIsTheUpdateIncrement) {
    constexpr int Dim = TypeParam::value;
    for (const auto& type : registeredTypes<Dim>()) {
        const auto s = make<Dim>(type);
        if (!s->allocatesStress()) continue;
        Block<Dim> b(*s, 1);
        Tensor<Dim> g = Tensor<Dim>::Zero();
        g(0, 1) = 1e3;
        g(1, 1) = -4e2;
        b.setGradient(g);
        b.tau[0](0, 0) = 1e6, b.tau[0](1, 1) = -1e6, b.tau[0](0, 1) = 5e5;
        const SymmTensor<Dim> before = b.tau[0];
        s->stressRate(b.fields());
        const double dt = 1e-7;  // elastic: update is tau + dt rate exactly
        s->update(b.fields(), dt);
        for (int k = 0; k < SymmTensor<Dim>::size; ++k)
            EXPECT_NEAR(b.tau[0].c[k], before.c[k] + dt * b.tauRate[0].c[k], 1e-9) << type;
    }
}

}  // namespace
}  // namespace mfdyn
