// swingingCubeError: errors of a total-Lagrangian run of the swinging cube (Lee, Gil, Greto, Karim
// & Bonet 2016 section 8.2, eq. 52; doc/methods/tl-jst-sph.md 8.2) against verification/SwingingCube, the
// small-strain linear elastic solution on [0, 1]^Dim, u = U0 cos(omega t) phi(X) with
// omega = sqrt(Dim)/2 c_d pi. At each of its write times t it writes to errorNorms.csv
// (time,field,L1,L2,Linf) the absolute norms of
//
//     momentum          e = rho0 v_h - p(X, t)              (|e| the Euclidean norm)
//     firstPiolaStress  e = P_h - P(X, t)                   (|e| the Frobenius norm)
//     firstPiolaStress_xx, _yx, ... each component (with `components yes`)
//
//     L2 = sqrt(sum_q w_q |e_q|^2),  L1 = sum_q w_q |e_q|,  Linf = max_q |e_q|,
//
// (and the same norms of the exact p and P, the scale of the relative error in the summary)
// over quadrature points q in the REFERENCE configuration (the paper's "L2 error on a fine
// background cloud of quadrature points"):
//   - default: the cell centres of a regular grid of `cloud`^Dim cells on [0, 1]^Dim, w = 1/cloud^Dim,
//     the particle values interpolated there (Interpolation.hpp: `interpolation`, `kernel`, `h`;
//     positionField defaults to referencePosition, so the interpolation is in X, where the
//     exact solution is given). The weights are found once and reused while the particles keep
//     their order, as reference positions do not move.
//   - `volumeWeighted yes`: the particles themselves, w = V_a = m_a/rho0_a (mass, density), e at
//     X_a; cheaper, no interpolation error, but the quadrature is the particles' own.
// Particle fields read: velocity, firstPiolaStress, referencePosition (or positionField), and
// mass and density for the volumes. The time is the run's time (the exact solution starts at t = 0).
//
//     swingingCube
//     {
//         type swingingCubeError;
//         rho0 1100;  youngsModulus 17e6;  poissonRatio 0.3;  amplitude 5e-4;
//         cloud 20;  interpolation mls;  h 0.13;      // h: else the smoothingLength field
//         writeControl runTime;  writeInterval 0.004;
//     }
// Keywords: doc/models/functionObject/swingingCubeError.md (the schema below).
#include "functionObjects/SwingingCubeError.hpp"

#include "particles/ParticleSet.hpp"
#include "verification/SwingingCube.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mfdyn {

namespace {

const char* axisNames = "xyz";

template <int Dim>
Vector<Dim> vectorAt(const FieldBase& f, std::size_t i) {
    Vector<Dim> v;
    for (int c = 0; c < Dim; ++c) v(c) = f.component(i, c);
    return v;
}

// Eigen tensors are stored column-major: component c is (c % Dim, c / Dim).
template <int Dim>
Tensor<Dim> tensorFrom(const std::vector<double>& values) {
    Tensor<Dim> t;
    for (int c = 0; c < Dim * Dim; ++c) t(c % Dim, c / Dim) = values[std::size_t(c)];
    return t;
}

template <int Dim>
Tensor<Dim> tensorAt(const FieldBase& f, std::size_t i) {
    Tensor<Dim> t;
    for (int c = 0; c < Dim * Dim; ++c) t(c % Dim, c / Dim) = f.component(i, c);
    return t;
}

struct Accumulator {
    double l1 = 0, l2 = 0, linf = 0;
    void add(double w, double e) {
        l1 += w * e, l2 += w * e * e;
        linf = std::max(linf, e);
    }
};

}  // namespace

KeywordSchema SwingingCubeError::keywords() {
    return KeywordSchema("functionObject", "swingingCubeError")
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .scalar("youngsModulus", "Pa", "Young's modulus E")
        .greaterThan(0)
        .scalar("poissonRatio", "-", "Poisson's ratio nu")
        .greaterThan(-1)
        .lessThan(0.5)
        .scalar("amplitude", "m", "displacement amplitude U0 of the analytic mode")
        .integer("cloud", "-", "background cloud: cells per side of the unit cube (one point per cell)")
        .atLeast(1)
        .orDefault(20)
        .flag("volumeWeighted", "quadrature at the particles with weights V_a, instead of on the cloud")
        .orDefault(false)
        .flag("components", "also a row per component of P")
        .orDefault(false)
        .append(Interpolation::keywords("referencePosition", Interpolation::Method::mls))
        .append(functionObjectKeywords());
}

SwingingCubeError::SwingingCubeError(const Dictionary& dict, const std::string& name,
                                     const RunContext& context)
    : SwingingCubeError(keywords().read(dict), name, context) {}

SwingingCubeError::SwingingCubeError(const KeywordValues& values, const std::string& name,
                                     const RunContext& context)
    : FunctionObject(values, name, context),
      rho0_(values.scalar("rho0")),
      youngsModulus_(values.scalar("youngsModulus")),
      poissonRatio_(values.scalar("poissonRatio")),
      amplitude_(values.scalar("amplitude")),
      cloud_(int(values.integer("cloud"))),
      volumeWeighted_(values.flag("volumeWeighted")),
      components_(values.flag("components")),
      positionField_(values.word("positionField")),
      norms_(outputFile("errorNorms.csv"), name, startTime()) {
    const Dictionary& dict = values.dict();
    requireField(dict, "positionField", positionField_);
    requireField(dict, "type", "velocity");
    requireField(dict, "type", "firstPiolaStress");
    requireField(dict, "type", "mass");
    requireField(dict, "type", "density");
    const int dim = context.dimension();
    if (volumeWeighted_) return;  // the interpolation keywords are read (by the schema) but not used
    interpolation_ = std::make_unique<Interpolation>(values, context.fields());
    std::size_t count = 1;
    for (int k = 0; k < dim; ++k) count *= std::size_t(cloud_);
    points_.assign(count, SamplePoint{0, 0, 0});
    for (std::size_t q = 0; q < count; ++q) {
        std::size_t rest = q;
        for (int k = 0; k < dim; ++k) {
            points_[q][k] = (double(rest % std::size_t(cloud_)) + 0.5) / cloud_;
            rest /= std::size_t(cloud_);
        }
    }
    refreshStencils();
    std::size_t empty = 0;
    for (const auto& s : stencils_) empty += s.status == Interpolation::Status::noNeighbours;
    if (empty)
        throw dict.error("cloud", std::to_string(empty) + " of the " + std::to_string(count) +
                                      " quadrature points in [0, 1]^" + std::to_string(dim) +
                                      " have no particle within the kernel support: the particles do not "
                                      "cover the unit cube in their reference positions, or h is too small");
}

SwingingCubeError::~SwingingCubeError() = default;

std::optional<std::vector<std::string>> SwingingCubeError::fieldsRead() const {
    std::vector<std::string> read{positionField_, "velocity", "firstPiolaStress", "mass", "density"};
    if (interpolation_) {
        const auto more = interpolation_->fieldsRead();
        read.insert(read.end(), more.begin(), more.end());
    }
    return read;
}

void SwingingCubeError::refreshStencils() const {
    const FieldBase& X = context().fields().field(positionField_);
    const auto* data = static_cast<const double*>(X.data());
    const std::size_t n = X.size() * std::size_t(X.components());
    if (!stencils_.empty() && stencilPositions_.size() == n &&
        std::equal(data, data + n, stencilPositions_.begin()))
        return;
    stencilPositions_.assign(data, data + n);
    interpolation_->update();
    stencils_ = interpolation_->stencils(points_);
}

template <int Dim>
std::vector<std::pair<std::string, SwingingCubeError::Norms>> SwingingCubeError::computeDim() const {
    const SwingingCube<Dim> exact(rho0_, youngsModulus_, poissonRatio_, amplitude_);
    const double t = context().time().value();
    const FieldStore& fields = context().fields();
    const FieldBase& velocity = fields.field("velocity");
    const FieldBase& stress = fields.field("firstPiolaStress");

    Accumulator momentumError, stressError, momentumExact, stressExact;
    std::vector<Accumulator> componentError(Dim * Dim), componentExact(Dim * Dim);
    auto add = [&](double w, const Vector<Dim>& X, const Vector<Dim>& v, const Tensor<Dim>& P) {
        const Vector<Dim> pExact = exact.momentum(X, t);
        const Tensor<Dim> PExact = exact.firstPiolaStress(X, t);
        momentumError.add(w, (rho0_ * v - pExact).norm());
        momentumExact.add(w, pExact.norm());
        const Tensor<Dim> e = P - PExact;
        stressError.add(w, e.norm());
        stressExact.add(w, PExact.norm());
        for (int c = 0; c < Dim * Dim; ++c) {
            componentError[std::size_t(c)].add(w, std::abs(e(c % Dim, c / Dim)));
            componentExact[std::size_t(c)].add(w, std::abs(PExact(c % Dim, c / Dim)));
        }
    };

    if (volumeWeighted_) {
        const FieldBase& X = fields.field(positionField_);
        const FieldBase& mass = fields.field("mass");
        const FieldBase& density = fields.field("density");
        for (std::size_t i = 0; i < fields.size(); ++i)
            add(mass.component(i, 0) / density.component(i, 0), vectorAt<Dim>(X, i),
                vectorAt<Dim>(velocity, i), tensorAt<Dim>(stress, i));
    } else {
        refreshStencils();
        const auto v = Interpolation::apply(stencils_, velocity);
        const auto P = Interpolation::apply(stencils_, stress);
        const double w = 1.0 / double(points_.size());
        for (std::size_t q = 0; q < points_.size(); ++q) {
            Vector<Dim> X, vq;
            for (int k = 0; k < Dim; ++k) X(k) = points_[q][k], vq(k) = v[q][std::size_t(k)];
            add(w, X, vq, tensorFrom<Dim>(P[q]));
        }
    }

    auto finish = [](const Accumulator& a, const Accumulator& x) {
        return Norms{a.l1, std::sqrt(a.l2), a.linf, x.l1, std::sqrt(x.l2), x.linf};
    };
    std::vector<std::pair<std::string, Norms>> out{{"momentum", finish(momentumError, momentumExact)},
                                                   {"firstPiolaStress", finish(stressError, stressExact)}};
    if (components_)
        for (int c = 0; c < Dim * Dim; ++c)
            out.emplace_back(std::string("firstPiolaStress_") + axisNames[c % Dim] + axisNames[c / Dim],
                             finish(componentError[std::size_t(c)], componentExact[std::size_t(c)]));
    return out;
}

std::vector<std::pair<std::string, SwingingCubeError::Norms>> SwingingCubeError::compute() const {
    return withDimension(context().dimension(), [&](auto dim) { return computeDim<decltype(dim)::value>(); });
}

void SwingingCubeError::write() {
    const double time = context().time().value();
    const auto norms = compute();
    for (const auto& [field, n] : norms)
        norms_.add(time, field, n.L1, n.L2, n.Linf, n.exactL1, n.exactL2, n.exactLinf);
    char line[200];
    std::snprintf(
        line, sizeof line, "swinging cube at t = %.6g: L2 error of momentum %.4g, of P %.4g (%s)", time,
        norms[0].second.L2, norms[1].second.L2,
        volumeWeighted_ ? "particle quadrature" : ("cloud of " + std::to_string(points_.size())).c_str());
    summary_ = {line};
}

MFDYN_REGISTER(
    FunctionObject, SwingingCubeError, "swingingCubeError",
    "L1/L2/Linf errors of p and P against the swinging cube's exact solution (Lee et al. 2016 eq. 52)");

}  // namespace mfdyn
