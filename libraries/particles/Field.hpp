#pragma once
// Typed storage of one particle field: one contiguous std::vector of the element type, so loops
// run over plain arrays and a field can be handed to the writer as one block of memory.
#include "core/Parallel.hpp"
#include "core/Tensor.hpp"
#include "particles/FieldBase.hpp"

#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace mfdyn {

// Kind and dimension of each element type a field may hold. `dim` is 0 for types that exist in
// every dimension (scalar, integer).
template <class T>
struct FieldTraits {
    static constexpr bool valid = false;
};

template <>
struct FieldTraits<double> {
    static constexpr bool valid = true;
    static constexpr FieldKind kind = FieldKind::scalar;
    static constexpr int dim = 0;
};

template <>
struct FieldTraits<std::int64_t> {
    static constexpr bool valid = true;
    static constexpr FieldKind kind = FieldKind::integer;
    static constexpr int dim = 0;
};

// Vector<Dim> and Tensor<Dim>. In 1D both are Eigen::Matrix<double, 1, 1>: the type alone says
// "vector", so a 1D tensor field is created with an explicit FieldKind::tensor (tensorField()).
template <int Rows, int Cols, int Options, int MaxRows, int MaxCols>
struct FieldTraits<Eigen::Matrix<double, Rows, Cols, Options, MaxRows, MaxCols>> {
    static_assert(Cols == 1 || Rows == Cols, "particle fields hold vectors or square tensors");
    static_assert(Rows >= 1 && Rows <= 3, "particle fields are 1D, 2D or 3D");
    static constexpr bool valid = true;
    static constexpr FieldKind kind = Cols == 1 ? FieldKind::vector : FieldKind::tensor;
    static constexpr int dim = Rows;
};

template <int Dim>
struct FieldTraits<SymmTensor<Dim>> {
    static constexpr bool valid = true;
    static constexpr FieldKind kind = FieldKind::symmTensor;
    static constexpr int dim = Dim;
};

template <class T>
class Field final : public FieldBase {
    static_assert(FieldTraits<T>::valid, "not a particle field type");
    // The type-erased view reads elements as packed doubles/int64; Eigen fixed-size types and
    // SymmTensor have no padding, which this checks.
    static_assert(sizeof(T) % 8 == 0, "field elements must be packed 8-byte values");

public:
    Field(std::string name, FieldKind kind, int dimension, std::size_t n = 0)
        : FieldBase(std::move(name), kind, dimension), values(n, zero()) {}

    std::vector<T> values;

    std::size_t size() const override { return values.size(); }
    void resize(std::size_t n) override { values.resize(n, zero()); }
    void* data() override { return values.data(); }
    const void* data() const override { return values.data(); }
    const std::type_info& elementType() const override { return typeid(T); }
    std::unique_ptr<FieldBase> clone() const override {
        auto copy = std::make_unique<Field<T>>(name(), kind(), dimension());
        copy->values = values;
        return copy;
    }
    void reorder(const std::vector<std::size_t>& order) override {
        std::vector<T> sorted(order.size());
        parallelFor(order.size(), [&](std::size_t i) { sorted[i] = values[order[i]]; });
        values.swap(sorted);
    }
    void reserve(std::size_t n) override { values.reserve(n); }
    // Ascending indices (checked by FieldStore::keep): element k moves down to k <= indices[k],
    // so one forward pass compacts in place; resize() to a smaller size keeps the capacity.
    void keep(const std::vector<std::size_t>& indices) override {
        for (std::size_t k = 0; k < indices.size(); ++k) values[k] = values[indices[k]];
        values.resize(indices.size());
    }
    void copyElements(const std::vector<std::size_t>& source, std::size_t first) override {
        for (std::size_t k = 0; k < source.size(); ++k) values[first + k] = values[source[k]];
    }

private:
    // New particles start at zero, not at Eigen's uninitialised value.
    static T zero() {
        if constexpr (std::is_arithmetic_v<T>)
            return T(0);
        else if constexpr (FieldTraits<T>::kind == FieldKind::symmTensor)
            return T{};
        else
            return T::Zero();
    }
};

}  // namespace mfdyn
