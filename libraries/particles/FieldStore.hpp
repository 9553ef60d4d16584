#pragma once
// Named particle fields, all of the same length, created when first asked for. A model asks for
// what it reads and writes in its constructor and keeps the returned reference: the reference
// stays valid while the field exists (adding other fields does not move it), the data pointer
// only until the next resize().
#include "core/Error.hpp"
#include "particles/Field.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class FieldStore {
public:
    explicit FieldStore(int dimension, std::size_t size = 0);
    FieldStore(const FieldStore& other);
    FieldStore& operator=(const FieldStore& other);
    FieldStore(FieldStore&&) noexcept = default;
    FieldStore& operator=(FieldStore&&) noexcept = default;
    virtual ~FieldStore();

    int dimension() const { return dimension_; }
    std::size_t size() const { return size_; }
    virtual void resize(std::size_t n);

    // Particles that come and go (issue 15). Each is O(N) over all fields and, within the
    // capacity reserve() made, allocates nothing.
    //   append(n): n new particles at the end, every field extended with zero (a field created
    //              later is zero-filled too); returns the index of the first new one.
    //   keep(indices): every particle not in `indices` (strictly ascending, all < size())
    //              removed, the others kept in their order, every field compacted in place.
    // ParticleSetBase overrides both to issue and retire global ids.
    virtual std::size_t append(std::size_t n);
    virtual void keep(const std::vector<std::size_t>& indices);
    void reserve(std::size_t n);
    // Changes whenever particles are appended, removed, reordered or resized: index lists made
    // earlier (a Verlet list, a selection) compare it with the value they were made for
    // (VerletList::track, Selection::refresh) to know they must be rebuilt.
    std::uint64_t topologyVersion() const { return topologyVersion_; }

    // The field `name` of element type T, created (zero-filled) on first request. `kind` only
    // matters for a 1D tensor, whose C++ type is that of a 1D vector. Throws Error when `name`
    // exists with another type, naming both.
    template <class T>
    std::vector<T>& field(const std::string& name, FieldKind kind = FieldTraits<T>::kind);
    // Existing field only: throws Error listing the fields there are when it is missing.
    template <class T>
    std::vector<T>& requireField(const std::string& name) const;
    // Existing field only, or nullptr; a type clash still throws.
    template <class T>
    std::vector<T>* findField(const std::string& name) const;
    bool hasField(const std::string& name) const { return findField(name) != nullptr; }

    // Type-erased look-up.
    FieldBase* findField(const std::string& name) const;
    FieldBase& field(const std::string& name) const;
    // Adopt a field made elsewhere (the reader); it must have this store's size and dimension.
    FieldBase& addField(std::unique_ptr<FieldBase> field);
    bool removeField(const std::string& name);

    // In creation order.
    const std::vector<std::unique_ptr<FieldBase>>& fields() const { return fields_; }
    std::vector<std::string> fieldNames() const;

    std::size_t bytesPerParticle() const;
    // Table of name, kind, components and bytes per particle, for the log.
    std::string fieldSummary() const;
    // Apply one permutation to every field (see FieldBase::reorder).
    virtual void reorder(const std::vector<std::size_t>& order);

    // The particle file the fields there are now were read from (the reader sets it). A field
    // of the file asked for with another type is then the file's fault, not the code's: an
    // InputError naming the file, what it holds and what was expected, instead of an Error.
    void setSource(const std::string& file);
    const std::string& source() const { return source_; }

private:
    template <class T>
    Field<T>* typed(FieldBase* base, FieldKind kind) const;
    void checkDimension(const std::string& name, int typeDim, const std::string& typeName) const;
    [[noreturn]] void typeClash(const FieldBase& existing, const std::string& requested,
                                FieldKind requestedKind) const;
    [[noreturn]] void missing(const std::string& name) const;
    static std::string typeName(FieldKind kind, int dim);

    int dimension_;
    std::size_t size_;
    std::uint64_t topologyVersion_ = 0;
    std::vector<std::unique_ptr<FieldBase>> fields_;
    std::string source_;                     // see setSource()
    std::vector<std::string> sourceFields_;  // the fields read from source_
};

template <class T>
Field<T>* FieldStore::typed(FieldBase* base, FieldKind kind) const {
    if (!base) return nullptr;
    if (base->elementType() != typeid(T)) typeClash(*base, typeName(kind, FieldTraits<T>::dim), kind);
    return static_cast<Field<T>*>(base);
}

template <class T>
std::vector<T>& FieldStore::field(const std::string& name, FieldKind kind) {
    if (auto* f = typed<T>(findField(name), kind)) return f->values;
    checkDimension(name, FieldTraits<T>::dim, typeName(kind, FieldTraits<T>::dim));
    if (kind != FieldTraits<T>::kind && !(kind == FieldKind::tensor && FieldTraits<T>::dim == 1))
        throw Error("field '" + name + "': a " + typeName(FieldTraits<T>::kind, FieldTraits<T>::dim) +
                    " cannot hold a " + kindName(kind));
    auto created = std::make_unique<Field<T>>(name, kind, dimension_, size_);
    auto& values = created->values;
    fields_.push_back(std::move(created));
    return values;
}

template <class T>
std::vector<T>& FieldStore::requireField(const std::string& name) const {
    if (auto* f = findField<T>(name)) return *f;
    missing(name);
}

template <class T>
std::vector<T>* FieldStore::findField(const std::string& name) const {
    auto* f = typed<T>(findField(name), FieldTraits<T>::kind);
    return f ? &f->values : nullptr;
}

}  // namespace mfdyn
