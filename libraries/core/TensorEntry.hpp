#pragma once
// A Dim x Dim tensor read from a dictionary entry, written row by row as `((G11 G12 G13) (G21 ..) ..)`
// or as a flat list of n^2 values, n = Dim or 3 (so that one dictionary serves 2D and 3D runs: the
// components outside the case's dimension must then be 0). An error names the file, the line and
// what was expected.
#include "core/Dictionary.hpp"
#include "core/Tensor.hpp"

#include <string>

namespace mfdyn {

template <int Dim>
Tensor<Dim> readTensor(const Dictionary& dict, const std::string& key);

extern template Tensor<1> readTensor<1>(const Dictionary&, const std::string&);
extern template Tensor<2> readTensor<2>(const Dictionary&, const std::string&);
extern template Tensor<3> readTensor<3>(const Dictionary&, const std::string&);

}  // namespace mfdyn
