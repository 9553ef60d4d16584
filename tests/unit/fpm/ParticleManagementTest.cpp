// fpm/ParticleManagement: insertion into holes and merging of close pairs (doc/methods/fpm.md §3.5).
// On square and cubic lattices of spacing a with h = 2a (the solver's default ratio), holeSize 0.5
// (a hole: no particle within one spacing), mergeDistance 0.15, and linear fields:
//   - one particle removed from the interior: exactly one particle comes back, at the removed site,
//     with the linear fields' values to 1e-12 (the order-1 fit reproduces them), a new global id,
//     the material of its neighbours, and the total mass kept to round-off;
//   - the free faces of a half lattice (and a uniform lattice's faces): no insertion, the candidates
//     beyond them rejected as outside the body;
//   - a particle put next to another (0.05 a apart): the pair merges, mass and momentum exact to
//     round-off, at the mass-weighted mean position;
//   - a uniform lattice: left alone, every field bit for bit.
#include "fpm/ParticleManagement.hpp"

#include "core/Dictionary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>

namespace mfdyn {
namespace {

constexpr double a = 0.1;  // the spacing
constexpr double h = 2 * a;

template <int Dim>
double rhoAt(const Vector<Dim>& x) {
    double r = 1.0;
    for (int d = 0; d < Dim; ++d) r += 0.3 * (d + 1) * x(d);
    return r;
}
template <int Dim>
double pAt(const Vector<Dim>& x) {
    double r = 2.0;
    for (int d = 0; d < Dim; ++d) r -= 0.7 * (d + 2) * x(d);
    return r;
}
template <int Dim>
Vector<Dim> vAt(const Vector<Dim>& x) {
    Vector<Dim> v;
    for (int d = 0; d < Dim; ++d) v(d) = 0.5 - 1.5 * x(d) + 0.25 * x((d + 1) % Dim);
    return v;
}
template <int Dim>
SymmTensor<Dim> sAt(const Vector<Dim>& x) {
    SymmTensor<Dim> s{};
    for (int k = 0; k < SymmTensor<Dim>::size; ++k) s.c[std::size_t(k)] = k + 0.1 * (k + 1) * x(k % Dim);
    return s;
}

// An n^Dim lattice on [0, (n - 1) a]^Dim; `skip` says which sites stay empty.
template <int Dim, class Skip>
std::unique_ptr<ParticleSet<Dim>> lattice(int n, Skip skip) {
    std::vector<Vector<Dim>> sites;
    const int total = int(std::pow(n, Dim));
    for (int k = 0; k < total; ++k) {
        Vector<Dim> x;
        int r = k;
        for (int d = 0; d < Dim; ++d) {
            x(d) = (r % n) * a;
            r /= n;
        }
        if (!skip(x)) sites.push_back(x);
    }
    auto set = std::make_unique<ParticleSet<Dim>>(sites.size());
    auto& x = set->position();
    auto& m = set->scalarField("mass");
    auto& V = set->scalarField("volume");
    auto& rho = set->scalarField("density");
    auto& p = set->scalarField("pressure");
    auto& v = set->vectorField("velocity");
    auto& S = set->symmTensorField("deviatoricStress");
    auto& material = set->integerField("material");
    for (std::size_t i = 0; i < sites.size(); ++i) {
        x[i] = sites[i];
        rho[i] = rhoAt<Dim>(x[i]);
        V[i] = std::pow(a, Dim);
        m[i] = rho[i] * V[i];
        p[i] = pAt<Dim>(x[i]);
        v[i] = vAt<Dim>(x[i]);
        S[i] = sAt<Dim>(x[i]);
        material[i] = 3;
    }
    for (std::size_t i = 0; i < sites.size(); ++i) set->globalId()[i] = std::int64_t(i);
    return set;
}

std::unique_ptr<FitWeight> weight() {
    return FitWeight::New(Dictionary::parse("type truncatedGaussian; alpha 6.25; squared yes;", "test"));
}

template <int Dim>
fpm::ParticleManagement<Dim> management(bool insert, bool merge) {
    typename fpm::ParticleManagement<Dim>::Options o;
    o.insert = insert;
    o.merge = merge;
    return fpm::ParticleManagement<Dim>(o);
}

template <int Dim>
double totalMass(ParticleSet<Dim>& set) {
    double s = 0;
    for (double m : set.scalarField("mass")) s += m;
    return s;
}

template <int Dim>
void holeIsFilled(int n) {
    Vector<Dim> site = Vector<Dim>::Constant((n / 2) * a);
    auto set = lattice<Dim>(n, [&](const Vector<Dim>& x) { return (x - site).norm() < 1e-9; });
    const std::size_t before = set->size();
    const double mass = totalMass(*set);
    const std::int64_t nextId = set->nextGlobalId();
    auto pm = management<Dim>(true, false);
    const auto w = weight();
    const std::vector<std::int64_t> origin = pm.apply(*set, h, *w);
    ASSERT_EQ(pm.last().inserted, 1u);
    ASSERT_EQ(set->size(), before + 1);
    ASSERT_EQ(origin.size(), before + 1);
    EXPECT_EQ(origin.back(), -1);
    for (std::size_t i = 0; i < before; ++i) EXPECT_EQ(origin[i], std::int64_t(i));
    const std::size_t i = before;
    const Vector<Dim> y = set->position()[i];
    EXPECT_LT((y - site).norm(), 1e-12);
    EXPECT_NEAR(set->scalarField("density")[i], rhoAt<Dim>(y), 1e-12);
    EXPECT_NEAR(set->scalarField("pressure")[i], pAt<Dim>(y), 1e-12);
    EXPECT_LT((set->vectorField("velocity")[i] - vAt<Dim>(y)).norm(), 1e-12);
    const SymmTensor<Dim> S = set->symmTensorField("deviatoricStress")[i], Sy = sAt<Dim>(y);
    for (int k = 0; k < SymmTensor<Dim>::size; ++k)
        EXPECT_NEAR(S.c[std::size_t(k)], Sy.c[std::size_t(k)], 1e-12);
    EXPECT_NEAR(set->scalarField("volume")[i], std::pow(a, Dim), 1e-12 * std::pow(a, Dim));
    EXPECT_EQ(set->integerField("material")[i], 3);
    EXPECT_EQ(set->globalId()[i], nextId);
    EXPECT_NEAR(totalMass(*set), mass, 1e-14 * mass);
    EXPECT_NEAR(pm.last().mass, 0.0, 1e-14 * mass);
    EXPECT_GT(pm.last().surface, 0u);  // the faces' candidates, rejected
    // a second pass finds the hole filled
    pm.apply(*set, h, *w);
    EXPECT_EQ(pm.last().inserted, 0u);
    EXPECT_EQ(pm.total().inserted, 1u);
}

TEST(ParticleManagement, OneHoleIsFilledWithTheLinearFieldsValue2D) {
    holeIsFilled<2>(15);
}
TEST(ParticleManagement, OneHoleIsFilledWithTheLinearFieldsValue3D) {
    holeIsFilled<3>(9);
}

template <int Dim>
void freeSurfaceGetsNone(int n) {
    // the half lattice: the sites with x_0 above the middle removed, a free face there
    auto set = lattice<Dim>(n, [&](const Vector<Dim>& x) { return x(0) > (n / 2) * a + 1e-9; });
    const std::size_t before = set->size();
    auto pm = management<Dim>(true, false);
    pm.apply(*set, h, *weight());
    EXPECT_EQ(pm.last().inserted, 0u);
    EXPECT_EQ(set->size(), before);
    EXPECT_GT(pm.last().surface, 0u);
}

TEST(ParticleManagement, AFreeSurfaceGetsNoInsertion2D) {
    freeSurfaceGetsNone<2>(14);
}
TEST(ParticleManagement, AFreeSurfaceGetsNoInsertion3D) {
    freeSurfaceGetsNone<3>(8);
}

template <int Dim>
void closePairMerges(int n) {
    auto set = lattice<Dim>(n, [](const Vector<Dim>&) { return false; });
    const std::size_t before = set->size();
    const std::size_t j = set->append(1);  // next to particle k, 0.05 a away
    const std::size_t k = before / 2;
    set->position()[j] = set->position()[k] + Vector<Dim>::Constant(0.05 * a / std::sqrt(double(Dim)));
    set->scalarField("mass")[j] = 0.37 * set->scalarField("mass")[k];
    set->scalarField("volume")[j] = 0.4 * std::pow(a, Dim);
    set->scalarField("density")[j] = 1.7;
    set->scalarField("pressure")[j] = 3.1;
    set->vectorField("velocity")[j] = Vector<Dim>::Constant(-2.3);
    set->integerField("material")[j] = 3;
    double mass = 0;
    Vector<Dim> momentum = Vector<Dim>::Zero();
    const auto& m = set->scalarField("mass");
    const auto& v = set->vectorField("velocity");
    for (std::size_t i = 0; i < set->size(); ++i) {
        mass += m[i];
        momentum += m[i] * v[i];
    }
    const double mk = m[k], mj = m[j];
    const Vector<Dim> centre = (mk * set->position()[k] + mj * set->position()[j]) / (mk + mj);
    const double rho = (mk * set->scalarField("density")[k] + mj * 1.7) / (mk + mj);
    const double volume = set->scalarField("volume")[k] + set->scalarField("volume")[j];
    const std::int64_t idK = set->globalId()[k];
    auto pm = management<Dim>(false, true);
    const std::vector<std::int64_t> origin = pm.apply(*set, h, *weight());
    ASSERT_EQ(pm.last().merged, 1u);
    ASSERT_EQ(set->size(), before);
    EXPECT_EQ(origin[k], std::int64_t(k));
    EXPECT_EQ(set->globalId()[k], idK);
    double mass1 = 0;
    Vector<Dim> momentum1 = Vector<Dim>::Zero();
    for (std::size_t i = 0; i < set->size(); ++i) {
        mass1 += m[i];
        momentum1 += m[i] * v[i];
    }
    EXPECT_NEAR(mass1, mass, 1e-14 * mass);
    EXPECT_LT((momentum1 - momentum).norm(), 1e-14 * (momentum.norm() + mass));
    EXPECT_LT((set->position()[k] - centre).norm(), 1e-15);
    EXPECT_NEAR(set->scalarField("density")[k], rho, 1e-14);
    EXPECT_NEAR(set->scalarField("volume")[k], volume, 1e-18);
    EXPECT_NEAR(m[k], mk + mj, 1e-16);
    EXPECT_NEAR(pm.last().mass, 0.0, 1e-14 * mass);
    EXPECT_LT(pm.last().momentum.norm(), 1e-14 * (momentum.norm() + mass));
}

TEST(ParticleManagement, ACloseParticlePairMergesKeepingMassAndMomentum2D) {
    closePairMerges<2>(9);
}
TEST(ParticleManagement, ACloseParticlePairMergesKeepingMassAndMomentum3D) {
    closePairMerges<3>(6);
}

template <int Dim>
void uniformLatticeIsLeftAlone(int n) {
    auto set = lattice<Dim>(n, [](const Vector<Dim>&) { return false; });
    const ParticleSet<Dim> copy = *set;
    auto pm = management<Dim>(true, true);
    pm.apply(*set, h, *weight());
    EXPECT_EQ(pm.last().inserted, 0u);
    EXPECT_EQ(pm.last().merged, 0u);
    ASSERT_EQ(set->size(), copy.size());
    for (const auto& f : copy.fields()) {
        const FieldBase& g = set->field(f->name());
        const std::size_t bytes = f->size() * f->elementBytes();
        EXPECT_EQ(std::memcmp(f->data(), g.data(), bytes), 0) << f->name();
    }
}

TEST(ParticleManagement, AUniformLatticeIsLeftAlone2D) {
    uniformLatticeIsLeftAlone<2>(12);
}
TEST(ParticleManagement, AUniformLatticeIsLeftAlone3D) {
    uniformLatticeIsLeftAlone<3>(7);
}

}  // namespace
}  // namespace mfdyn
