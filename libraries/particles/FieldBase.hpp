#pragma once
// The type-erased face of one particle field, so that code which does not know the dimension or
// the element type at compile time (writers, function objects, particleInfo) can still list,
// size, read and copy fields. The typed storage is Field<T> (Field.hpp).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

namespace mfdyn {

// What a field holds per particle. Integer fields are std::int64_t; all others are doubles.
enum class FieldKind { scalar, vector, tensor, symmTensor, integer };

// "scalar", "vector", "tensor", "symmTensor", "integer".
std::string kindName(FieldKind kind);
// Values per particle in memory for a field of this kind in `dim` dimensions (1, Dim, Dim²,
// Dim(Dim+1)/2, 1).
int componentCount(FieldKind kind, int dim);
// Names of those components in memory order ("x", "y"; tensors are Eigen column-major, so the
// second component of a 2D tensor is "yx"; symmetric tensors "xx", "yy", "xy" as in SymmTensor).
std::vector<std::string> componentNames(FieldKind kind, int dim);

class FieldBase {
public:
    FieldBase(std::string name, FieldKind kind, int dimension);
    virtual ~FieldBase();
    FieldBase(const FieldBase&) = delete;
    FieldBase& operator=(const FieldBase&) = delete;

    const std::string& name() const { return name_; }
    FieldKind kind() const { return kind_; }
    int dimension() const { return dimension_; }
    // Values (doubles, or int64 for integer fields) per particle.
    int components() const { return componentCount(kind_, dimension_); }
    // Bytes of one element: components() * 8.
    std::size_t elementBytes() const { return std::size_t(components()) * 8; }
    bool isInteger() const { return kind_ == FieldKind::integer; }
    // "vector<3>", "scalar": the C++ element type in words, for messages.
    std::string typeName() const;

    virtual std::size_t size() const = 0;
    virtual void resize(std::size_t n) = 0;
    // size() * components() contiguous doubles (or std::int64_t for integer fields), each
    // particle's values in the memory order of componentNames().
    virtual void* data() = 0;
    virtual const void* data() const = 0;
    virtual const std::type_info& elementType() const = 0;
    // A deep copy (ParticleSet copies, snapshots for restart tests).
    virtual std::unique_ptr<FieldBase> clone() const = 0;
    // New order: element i becomes old element order[i] (cell sorting of the neighbour search).
    virtual void reorder(const std::vector<std::size_t>& order) = 0;
    virtual void reserve(std::size_t n) = 0;
    // Keep only the elements at `indices` (strictly ascending, checked by the caller), in that
    // order, compacted in place.
    virtual void keep(const std::vector<std::size_t>& indices) = 0;
    // Element first + k becomes a copy of element source[k] (ghosts from their sources).
    virtual void copyElements(const std::vector<std::size_t>& source, std::size_t first) = 0;

    // Component c of particle i as a double, for generic read-only code.
    double component(std::size_t i, int c) const {
        if (isInteger()) return double(static_cast<const std::int64_t*>(data())[i]);
        return static_cast<const double*>(data())[i * components() + c];
    }

private:
    std::string name_;
    FieldKind kind_;
    int dimension_;
};

}  // namespace mfdyn
