#pragma once
// A vector that a boundary condition prescribes as a function of time, given either as a
// constant or as a table, linear between its rows and constant beyond them:
//
//     velocity (0 -10 0);                                   // constant (key chosen by the condition)
//     table    ((0 (0 0 0)) (1e-3 (0 -100 0)) (0.01 (0 -100 0)));   // (time (x y z)) rows, times increasing
//
// Exactly one of the two must be given. Components beyond the case's dimension must be zero.
#include "core/KeywordSchema.hpp"
#include "core/Tensor.hpp"

#include <string>
#include <vector>

namespace mfdyn {

// The constant `key` [unit] and `table`, both optional (exactly one is checked when read).
KeywordSchema vectorTableKeywords(const std::string& key, const std::string& unit,
                                  const std::string& meaning);

template <int Dim>
class VectorTable {
public:
    // From values read through a schema that includes vectorTableKeywords(key, unit, ...).
    VectorTable(const KeywordValues& values, const std::string& key, const std::string& unit);
    Vector<Dim> value(double t) const;
    // d value/dt: zero for a constant and outside the table, the slope of the row pair inside.
    Vector<Dim> rate(double t) const;

private:
    std::vector<double> times_;
    std::vector<Vector<Dim>> values_;
};

extern template class VectorTable<1>;
extern template class VectorTable<2>;
extern template class VectorTable<3>;

}  // namespace mfdyn
