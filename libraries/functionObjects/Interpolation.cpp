// Particle-to-point interpolation.
//
// With w_j(x) = V_j W(|x - x_j|, h_j) (scatter form: each particle carries its own h) over the
// particles whose support contains x:
//
// shepard (Shepard 1968; the normalised SPH sum, e.g. Monaghan 2005 Rep. Prog. Phys. 68, sec. 2):
//
//     f(x) = sum_j w_j f_j / sum_j w_j,     phi_j = w_j / sum_k w_k.
//
//   Exact for constants at any particle arrangement. For a linear field the error is
//   grad f . sum_j phi_j (x_j - x), the offset of the weighted centroid from x: zero on a
//   lattice symmetric about x, and O(h^2) relative on a smoothly perturbed one well inside
//   the particles; of order h near a boundary, where the neighbours lie on one side.
//
// mls, first order (Lancaster & Salkauskas 1981; Belytschko et al. 1996, Comput. Methods Appl.
// Mech. Eng. 139, eqs. 2.1-2.10): fit f(y) ~ a + b.(y - x) minimising sum_j w_j (a + b.(x_j - x)
// - f_j)^2, and take f(x) = a. With p_j = (1, (x_j - x)/H) (H the largest support radius, so
// that M is well scaled), the normal equations are
//
//     M c = sum_j w_j p_j f_j,   M = sum_j w_j p_j p_j^T    ((d+1) x (d+1), symmetric),
//
//   and a = c_0 = e_0^T M^-1 sum_j w_j p_j f_j, so phi_j = w_j z . p_j with M z = e_0, one solve
//   per point whatever the number of fields. Any linear field is reproduced exactly (to
//   round-off) wherever M is invertible, i.e. the neighbours span d dimensions; where they do
//   not (fewer than d+1 neighbours, or all on one line in 2D), the point falls back to Shepard
//   and is flagged. The fit is LeastSquaresOperators (libraries/meshfreeOperators) in value form,
//   order 1, with these scatter weights: phi_j is its value weight.
//
// Volumes V_j: mass/density when both fields exist, else a `volume` field, else one common
// volume (spacing^d on a uniform lattice), whose value cancels from both normalised forms.
#include "functionObjects/Interpolation.hpp"

#include "core/Error.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace mfdyn {

namespace {
// Below this reciprocal condition number of the scaled moment matrix the linear fit is treated
// as undetermined: its entries are O(1) after scaling by H, so 1e-10 leaves many digits for
// the solve while still catching neighbours that are (nearly) collinear.
constexpr double minReciprocalCondition = 1e-10;

// The first-order MLS shape functions of the stencil's particles at x: LeastSquaresOperators in
// value form with the stencil's weights, over the stencil alone (one row), scaled by H. False where
// the fit is undetermined (the caller falls back to Shepard); s.weights is then untouched.
template <int Dim>
bool mlsWeights(const std::vector<SamplePoint>& position, const SamplePoint& x, double H,
                Interpolation::Stencil& s) {
    const std::size_t m = s.particles.size();
    std::vector<Vector<Dim>> neighbours(m);
    for (std::size_t q = 0; q < m; ++q)
        for (int k = 0; k < Dim; ++k) neighbours[q][k] = position[s.particles[q]][k];
    Vector<Dim> point;
    for (int k = 0; k < Dim; ++k) point[k] = x[k];
    std::vector<NeighbourList::Index> row(m);
    for (std::size_t q = 0; q < m; ++q) row[q] = NeighbourList::Index(q);
    typename LeastSquaresOperators<Dim>::Options options;
    options.order = 1;
    options.form = LeastSquaresOperators<Dim>::Form::value;
    options.minReciprocalCondition = minReciprocalCondition;
    options.onFailure = LeastSquaresOperators<Dim>::OnFailure::flag;
    LeastSquaresOperators<Dim> mls(options);
    mls.rebuild({point}, neighbours, NeighbourList({0, m}, std::move(row)), s.weights, {H});
    if (mls.status()[0] != LeastSquaresOperators<Dim>::Status::ok) return false;
    s.weights = mls.value();
    return true;
}
}  // namespace

std::string Interpolation::methodName(Method method) {
    return method == Method::mls ? "mls" : "shepard";
}

KeywordSchema Interpolation::keywords(const std::string& defaultPositionField, Method defaultMethod) {
    return KeywordSchema("functionObject", "interpolation")
        .word("interpolation", {"shepard", "mls"},
              "shepard (kernel-weighted average) or mls (first-order moving least squares)")
        .orDefault(methodName(defaultMethod))
        .dictionary("kernel", "the interpolation kernel (default { type wendlandC2; })")
        .optional()
        .scalar("h", "m", "smoothing length (default: the particles' smoothingLength field)")
        .greaterThan(0)
        .optional()
        .identifier(
            "positionField",
            "vector field of the particles' coordinates (referencePosition: total-Lagrangian reference)")
        .orDefault(defaultPositionField);
}

std::vector<std::string> Interpolation::fieldsRead() const {
    std::vector<std::string> fields{positionField_, "mass", "density", "volume"};
    if (!hKeyword_) fields.push_back("smoothingLength");
    return fields;
}

Interpolation::Interpolation(const Dictionary& dict, const FieldStore& particles,
                             const std::string& defaultPositionField, Method defaultMethod)
    : Interpolation(keywords(defaultPositionField, defaultMethod).read(dict), particles) {}

Interpolation::Interpolation(const KeywordValues& values, const FieldStore& particles)
    : particles_(particles), dim_(particles.dimension()) {
    positionField_ = values.word("positionField");
    const FieldBase* position = particles.findField(positionField_);
    if (!position || position->components() != dim_) {
        std::string message = "no " + std::to_string(dim_) + "-component vector field '" + positionField_ +
                              "' in these particles; fields:";
        for (const auto& name : particles.fieldNames()) message += " " + name;
        throw values.error("positionField", message);
    }
    method_ = values.word("interpolation") == "mls" ? Method::mls : Method::shepard;

    if (values.given("kernel")) {
        kernel_ = Kernel::New(values.dictionary("kernel"));
    } else {
        Dictionary fallback("kernel");
        fallback.set("type", "wendlandC2");
        kernel_ = Kernel::New(fallback);
    }

    hKeyword_ = values.optionalScalar("h");
    if (!hKeyword_ && !particles.findField("smoothingLength"))
        throw values.error("h", "give the smoothing length `h`: the particles have no smoothingLength field");
    update();
}

void Interpolation::update() {
    const std::size_t n = particles_.size();
    const FieldBase* position = particles_.findField(positionField_);
    if (!position) throw Error("interpolation: the particles have no " + positionField_ + " field");
    position_.assign(n, SamplePoint{0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < dim_; ++c) position_[i][c] = position->component(i, c);

    if (hKeyword_) {
        h_.assign(n, *hKeyword_);
    } else if (const FieldBase* f = particles_.findField("smoothingLength")) {
        h_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            h_[i] = f->component(i, 0);
            if (!(h_[i] > 0.0))
                throw Error("interpolation: smoothingLength of particle " + std::to_string(i) + " is " +
                            std::to_string(h_[i]) + ", not positive");
        }
    } else {
        throw Error("interpolation: the particles have lost their smoothingLength field");
    }

    volume_.assign(n, 1.0);
    const FieldBase* mass = particles_.findField("mass");
    const FieldBase* density = particles_.findField("density");
    if (mass && density) {
        for (std::size_t i = 0; i < n; ++i) volume_[i] = mass->component(i, 0) / density->component(i, 0);
    } else if (const FieldBase* v = particles_.findField("volume")) {
        for (std::size_t i = 0; i < n; ++i) volume_[i] = v->component(i, 0);
    }

    maxSupport_ = 0.0;
    for (double h : h_) maxSupport_ = std::max(maxSupport_, kernel_->supportRadius(h));
    // Cells half the largest support wide: the query cuts the rows of cells to the sphere, so
    // narrower cells scan less than the 3^d cells of one support; any width gives the same set.
    auto binAll = [&](auto& bins) {
        using V = typename std::remove_cvref_t<decltype(bins.sortedPositions())>::value_type;
        std::vector<V> x(n);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < V::RowsAtCompileTime; ++c) x[i][c] = position_[i][c];
        bins.bin(x, 0.5 * maxSupport_);
    };
    if (dim_ == 1)
        binAll(bins1_);
    else if (dim_ == 2)
        binAll(bins2_);
    else
        binAll(bins3_);
}

Interpolation::~Interpolation() = default;

template <int Dim>
void Interpolation::gather(const CellBins<Dim>& bins, const SamplePoint& x, Stencil& s) const {
    Vector<Dim> point;
    for (int k = 0; k < Dim; ++k) point[k] = x[k];
    // Candidates within the largest support; each particle then against its own.
    bins.forEachCandidate(point, maxSupport_, [&](std::size_t j) {
        double r2 = 0.0;
        for (int k = 0; k < dim_; ++k) r2 += (position_[j][k] - x[k]) * (position_[j][k] - x[k]);
        const double r = std::sqrt(r2);
        if (r >= kernel_->supportRadius(h_[j])) return;
        const double w = volume_[j] * kernel_->W(r, h_[j], dim_);
        if (w <= 0.0) return;
        s.particles.push_back(j);
        s.weights.push_back(w);
    });
}

Interpolation::Stencil Interpolation::stencil(const SamplePoint& point) const {
    Stencil s;
    SamplePoint x{0.0, 0.0, 0.0};
    for (int c = 0; c < dim_; ++c) x[c] = point[c];
    if (dim_ == 1)
        gather(bins1_, x, s);
    else if (dim_ == 2)
        gather(bins2_, x, s);
    else
        gather(bins3_, x, s);
    if (s.particles.empty()) return s;

    double sum = 0.0;
    for (double w : s.weights) sum += w;

    if (method_ == Method::mls) {
        const bool determined = dim_ == 1   ? mlsWeights<1>(position_, x, maxSupport_, s)
                                : dim_ == 2 ? mlsWeights<2>(position_, x, maxSupport_, s)
                                            : mlsWeights<3>(position_, x, maxSupport_, s);
        if (determined) {
            s.status = Status::ok;
            return s;
        }
        s.status = Status::shepardFallback;
    } else {
        s.status = Status::ok;
    }
    for (double& w : s.weights) w /= sum;
    return s;
}

std::vector<Interpolation::Stencil> Interpolation::stencils(const std::vector<SamplePoint>& points) const {
    std::vector<Stencil> out(points.size());
    for (std::size_t p = 0; p < points.size(); ++p) out[p] = stencil(points[p]);
    return out;
}

std::vector<std::vector<double>> Interpolation::apply(const std::vector<Stencil>& stencils,
                                                      const FieldBase& field) {
    const int nc = field.components();
    std::vector<std::vector<double>> out(stencils.size(), std::vector<double>(nc, 0.0));
    for (std::size_t p = 0; p < stencils.size(); ++p) {
        const Stencil& s = stencils[p];
        if (s.status == Status::noNeighbours) {
            std::fill(out[p].begin(), out[p].end(), std::numeric_limits<double>::quiet_NaN());
            continue;
        }
        for (std::size_t q = 0; q < s.particles.size(); ++q)
            for (int c = 0; c < nc; ++c) out[p][c] += s.weights[q] * field.component(s.particles[q], c);
    }
    return out;
}

}  // namespace mfdyn
