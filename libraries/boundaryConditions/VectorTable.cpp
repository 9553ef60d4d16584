#include "boundaryConditions/VectorTable.hpp"

#include "core/Error.hpp"

#include <algorithm>

namespace mfdyn {

namespace {

// A `(x y z)` token as a Dim-vector; extra components must be zero, as for dictionary vectors.
template <int Dim>
Vector<Dim> vectorOf(const Token& token, const Dictionary& dict) {
    if (token.kind != Token::Kind::list)
        throw dict.error("table", "expected a vector (x y z), found " + token.str());
    Vector<Dim> v = Vector<Dim>::Zero();
    for (std::size_t k = 0; k < token.list.size(); ++k) {
        if (!token.list[k].isNumber())
            throw dict.error("table", "expected a number, found " + token.list[k].str());
        const double x = token.list[k].number();
        if (int(k) < Dim)
            v[k] = x;
        else if (x != 0.0)
            throw dict.error("table", "component " + std::to_string(k + 1) + " of " + token.str() +
                                          " is non-zero but the case has fewer dimensions");
    }
    if (int(token.list.size()) < Dim)
        throw dict.error("table", "expected " + std::to_string(Dim) + " components, found " + token.str());
    return v;
}

}  // namespace

KeywordSchema vectorTableKeywords(const std::string& key, const std::string& unit,
                                  const std::string& meaning) {
    return KeywordSchema("boundaryCondition", "vectorTable")
        .vector(key, unit, meaning + ", constant in time")
        .optional()
        .table("table", "s, " + unit,
               meaning +
                   " against time: rows (t (x y z)), times increasing, linear between rows and "
                   "constant beyond them (instead of " +
                   key + ")")
        .example("((0 (0 0 0)) (1e-3 (0 -1 0)))")
        .optional();
}

template <int Dim>
VectorTable<Dim>::VectorTable(const KeywordValues& values, const std::string& key, const std::string& unit) {
    const Dictionary& dict = values.dict();
    const bool hasConstant = values.given(key), hasTable = values.given("table");
    if (hasConstant == hasTable)
        throw InputError(
            dict.where(), dict.scope(),
            "give exactly one of `" + key + " (x y z);` [" + unit + "] and `table ((t (x y z)) ...);`");
    if (hasConstant) {
        times_ = {0.0};
        values_ = {keywordVector<Dim>(values, key)};
        return;
    }
    const Entry& entry = dict.entry("table");
    if (entry.tokens.size() != 1 || entry.tokens[0].kind != Token::Kind::list || entry.tokens[0].list.empty())
        throw dict.error("table", "expected a list of (time (x y z)) pairs");
    for (const Token& row : entry.tokens[0].list) {
        if (row.kind != Token::Kind::list || row.list.size() != 2 || !row.list[0].isNumber())
            throw dict.error("table", "expected (time (x y z)), found " + row.str());
        const double t = row.list[0].number();
        if (!times_.empty() && !(t > times_.back()))
            throw dict.error("table", "times must increase, found " + row.list[0].str() + " after " +
                                          std::to_string(times_.back()));
        times_.push_back(t);
        values_.push_back(vectorOf<Dim>(row.list[1], dict));
    }
}

template <int Dim>
Vector<Dim> VectorTable<Dim>::value(double t) const {
    if (t <= times_.front()) return values_.front();
    if (t >= times_.back()) return values_.back();
    const auto k = std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    const double w = (t - times_[k]) / (times_[k + 1] - times_[k]);
    return (1.0 - w) * values_[k] + w * values_[k + 1];
}

template <int Dim>
Vector<Dim> VectorTable<Dim>::rate(double t) const {
    if (t < times_.front() || t >= times_.back()) return Vector<Dim>::Zero();
    const auto k = std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    return (values_[k + 1] - values_[k]) / (times_[k + 1] - times_[k]);
}

template class VectorTable<1>;
template class VectorTable<2>;
template class VectorTable<3>;

}  // namespace mfdyn
