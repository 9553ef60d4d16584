#pragma once
// Small fixed-size types used for particle fields, templated on the space dimension Dim = 1, 2, 3.
// Vectors and tensors are Eigen types; a symmetric tensor stores its Dim(Dim+1)/2 independent
// components (xx, yy, zz, xy, yz, xz order as in VTK, truncated to Dim).
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"

#include <Eigen/Core>
#include <array>

namespace mfdyn {

template <int Dim>
using Vector = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Tensor = Eigen::Matrix<double, Dim, Dim>;

template <int Dim>
struct SymmTensor {
    static constexpr int size = Dim * (Dim + 1) / 2;
    std::array<double, size> c{};

    // Component order: 1D (xx); 2D (xx, yy, xy); 3D (xx, yy, zz, xy, yz, xz).
    static constexpr int index(int i, int j) {
        if (i == j) return i;
        if (i > j) std::swap(i, j);
        if constexpr (Dim == 2) return 2;
        return (i == 0 && j == 1) ? 3 : (i == 1 && j == 2) ? 4 : 5;
    }
    double operator()(int i, int j) const { return c[index(i, j)]; }
    double& operator()(int i, int j) { return c[index(i, j)]; }
    Tensor<Dim> full() const {
        Tensor<Dim> t;
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) t(i, j) = (*this)(i, j);
        return t;
    }
    static SymmTensor fromFull(const Tensor<Dim>& t) {
        SymmTensor s;
        for (int i = 0; i < Dim; ++i)
            for (int j = i; j < Dim; ++j) s(i, j) = 0.5 * (t(i, j) + t(j, i));
        return s;
    }
};

// Dictionary conversion for fixed-size Eigen vectors/matrices: `g (0 -9.81 0);`. A vector entry
// with more components than the case's dimension is accepted when the extra ones are zero, so one
// dictionary serves 1D, 2D and 3D runs of the same case.
template <int Rows, int Cols>
struct ValueTraits<Eigen::Matrix<double, Rows, Cols>> {
    static Eigen::Matrix<double, Rows, Cols> convert(const Entry& entry, const Dictionary& scope) {
        auto values = ValueTraits<std::vector<double>>::convert(entry, scope);
        constexpr int n = Rows * Cols;
        if (int(values.size()) < n)
            throw scope.error(
                entry.key, "expected " + describe() + ", found " + std::to_string(values.size()) + " values");
        for (std::size_t k = n; k < values.size(); ++k)
            if (values[k] != 0.0)
                throw scope.error(entry.key, "expected " + describe() + ": component " +
                                                 std::to_string(k + 1) +
                                                 " is non-zero but the case has fewer dimensions");
        Eigen::Matrix<double, Rows, Cols> m;
        for (int k = 0; k < n; ++k) m(k / Cols, k % Cols) = values[k];  // row-major in the file
        return m;
    }
    static std::string describe() {
        return "a list of " + std::to_string(Rows * Cols) + " reals" + (Cols > 1 ? " (row by row)" : "");
    }
};

// A vector keyword read through a schema (KeywordSchema::vector) as a Dim-vector, by the rule of
// the conversion above: at least Dim components, those beyond Dim zero.
template <int Dim>
Vector<Dim> keywordVector(const KeywordValues& values, std::string_view name) {
    const std::vector<double>& list = values.vector(name);
    const std::string expected = "expected a list of " + std::to_string(Dim) + " reals";
    if (int(list.size()) < Dim)
        throw values.error(name, expected + ", found " + std::to_string(list.size()) + " values");
    for (std::size_t k = Dim; k < list.size(); ++k)
        if (list[k] != 0.0)
            throw values.error(name, expected + ": component " + std::to_string(k + 1) +
                                         " is non-zero but the case has fewer dimensions");
    Vector<Dim> v;
    for (int k = 0; k < Dim; ++k) v[k] = list[std::size_t(k)];
    return v;
}

}  // namespace mfdyn
