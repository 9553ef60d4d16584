// `prescribedVelocity`: chosen components of the node velocity follow a constant or a table in
// time (rows (t (vx vy vz)), linear between them, held before the first and after the last):
//
//     v_i = v_i(t),   a_i = dv_i/dt(t)   on the components of `components (...)` (default all)
//
// with t the time of the updated velocity. The rate, not (v_i(t) - v_i^n)/dt, goes into the
// acceleration: for a constant velocity it is zero, which is the thesis's rule for every grid
// condition (doc/methods/mpm.md 2.5: a = 0 where v is set), and fixed is prescribedVelocity
// (0 0 0). The other components are free.
#include "grid/gridBoundaryConditions/GridPrescribedVelocity.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

namespace {

// A `(vx vy vz)` token of the table as a Dim-vector: at least Dim numbers, the ones beyond the
// grid's dimension zero (as a dictionary vector's, so one table serves a 2D and a 3D case).
template <int Dim>
Vector<Dim> rowVector(const Token& token, const Dictionary& dict) {
    if (token.kind != Token::Kind::list)
        throw dict.error("table", "expected a velocity (vx vy vz) in each row, found " + token.str());
    if (int(token.list.size()) < Dim)
        throw dict.error("table",
                         "expected " + std::to_string(Dim) + " velocity components, found " + token.str());
    Vector<Dim> v;
    for (std::size_t k = 0; k < token.list.size(); ++k) {
        const Token& c = token.list[k];
        if (!c.isNumber() || !std::isfinite(c.number()))
            throw dict.error("table", "expected a finite number, found " + c.str() + " in " + token.str());
        if (int(k) < Dim)
            v[int(k)] = c.number();
        else if (c.number() != 0.0)
            throw dict.error("table", "component " + std::to_string(k + 1) + " of " + token.str() +
                                          " is non-zero, but the grid is " + std::to_string(Dim) + "D");
    }
    return v;
}

}  // namespace

template <int Dim>
KeywordSchema GridPrescribedVelocity<Dim>::keywords() {
    return KeywordSchema("gridBoundaryCondition", "prescribedVelocity")
        .vector("velocity", "m/s", "the node velocity, constant in time (or table)")
        .optional()
        .table("table", "s, m/s",
               "the node velocity against time: rows (t (vx vy vz)), times increasing, linear between "
               "rows and constant beyond them (instead of velocity)")
        .optional()
        .example("((0 (0 0 0)) (1e-3 (0 -1 0)))")
        .append(componentKeywords())
        .append(commonGridBoundaryConditionKeywords());
}

template <int Dim>
GridPrescribedVelocity<Dim>::GridPrescribedVelocity(const Dictionary& dict, const CartesianGrid<Dim>& grid)
    : GridPrescribedVelocity(keywords().read(dict), grid) {}

template <int Dim>
GridPrescribedVelocity<Dim>::GridPrescribedVelocity(const KeywordValues& values,
                                                    const CartesianGrid<Dim>& grid)
    : GridBoundaryCondition<Dim>(values, grid), prescribed_(readComponents(values, Dim)) {
    const Dictionary& dict = values.dict();
    const bool hasConstant = values.given("velocity"), hasTable = values.given("table");
    if (hasConstant == hasTable)
        throw InputError(
            dict.where(), dict.scope(),
            std::string(hasConstant ? "both" : "neither") +
                " of `velocity` and `table` given: give exactly one, `velocity (vx vy vz);` [m/s] "
                "or `table ((t (vx vy vz)) ...);`");
    if (hasConstant) {
        times_ = {0.0};
        values_ = {dict.get<Vector<Dim>>("velocity")};
        return;
    }
    const Entry& entry = dict.entry("table");
    if (entry.tokens.size() != 1 || entry.tokens[0].kind != Token::Kind::list || entry.tokens[0].list.empty())
        throw dict.error("table", "expected a list of rows (t (vx vy vz))");
    for (const Token& row : entry.tokens[0].list) {
        if (row.kind != Token::Kind::list || row.list.size() != 2 || !row.list[0].isNumber() ||
            !std::isfinite(row.list[0].number()))
            throw dict.error("table",
                             "expected a row (t (vx vy vz)) with a finite time t, found " + row.str());
        const double t = row.list[0].number();
        if (!times_.empty() && !(t > times_.back()))
            throw dict.error("table", "the times must increase; " + row.list[0].str() + " follows " +
                                          formatKeywordNumber(times_.back()));
        times_.push_back(t);
        values_.push_back(rowVector<Dim>(row.list[1], dict));
    }
}

template <int Dim>
Vector<Dim> GridPrescribedVelocity<Dim>::velocity(double t) const {
    if (!(t > times_.front())) return values_.front();
    if (t >= times_.back()) return values_.back();
    // The row pair [k, k+1] with times_[k] < t < times_[k+1].
    const std::size_t k = std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    const double w = (t - times_[k]) / (times_[k + 1] - times_[k]);
    return values_[k] + w * (values_[k + 1] - values_[k]);
}

template <int Dim>
Vector<Dim> GridPrescribedVelocity<Dim>::acceleration(double t) const {
    // Outside the table the velocity is held, so its rate is zero; at a row time the slope of
    // the interval that starts there (the one the step ending after it lies in).
    if (times_.size() < 2 || t < times_.front() || t >= times_.back()) return Vector<Dim>::Zero();
    const std::size_t k = std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    return (values_[k + 1] - values_[k]) / (times_[k + 1] - times_[k]);
}

template <int Dim>
void GridPrescribedVelocity<Dim>::apply(const CartesianGrid<Dim>&, std::vector<Vector<Dim>>& velocity,
                                        std::vector<Vector<Dim>>* acceleration, double t, double) const {
    const Vector<Dim> v = this->velocity(t), a = this->acceleration(t);
    for (const auto node : this->selection().nodes())
        for (int d = 0; d < Dim; ++d)
            if (prescribed_[d]) {
                velocity[node][d] = v[d];
                if (acceleration) (*acceleration)[node][d] = a[d];
            }
}

template <int Dim>
std::string GridPrescribedVelocity<Dim>::describe() const {
    std::string s = GridBoundaryCondition<Dim>::describe();
    if (times_.size() == 1) {
        s += ", velocity (";
        for (int d = 0; d < Dim; ++d) s += (d ? " " : "") + formatKeywordNumber(values_[0][d]);
        s += ")";
    } else {
        s += ", table of " + std::to_string(times_.size()) + " rows";
    }
    const std::string components = componentsText(prescribed_);
    return s + (components.empty() ? "" : ", " + components);
}

MFDYN_REGISTER_DIM(GridBoundaryCondition, GridPrescribedVelocity, "prescribedVelocity",
                   "chosen components of the grid node velocity follow a constant or a table in time");

}  // namespace mfdyn
