#pragma once
// A point as text for the operators' diagnostics ("(0.1 0.2 0.3)"): one definition for every
// operator that names the point where its fit failed.
#include "core/Tensor.hpp"

#include <sstream>
#include <string>

namespace mfdyn {

template <int Dim>
std::string pointText(const Vector<Dim>& x) {
    std::ostringstream out;
    out.precision(9);
    out << '(';
    for (int i = 0; i < Dim; ++i) out << (i ? " " : "") << x[i];
    out << ')';
    return out.str();
}

}  // namespace mfdyn
