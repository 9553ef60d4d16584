#include "particles/FieldStore.hpp"

#include "particles/VtpWriter.hpp"

#include <algorithm>
#include <cstdio>

namespace mfdyn {

FieldStore::FieldStore(int dimension, std::size_t size) : dimension_(dimension), size_(size) {
    if (dimension < 1 || dimension > 3)
        throw InputError("particle dimension " + std::to_string(dimension) + " is not 1, 2 or 3");
}

FieldStore::FieldStore(const FieldStore& other)
    : dimension_(other.dimension_),
      size_(other.size_),
      topologyVersion_(other.topologyVersion_),
      source_(other.source_),
      sourceFields_(other.sourceFields_) {
    for (const auto& f : other.fields_) fields_.push_back(f->clone());
}

FieldStore& FieldStore::operator=(const FieldStore& other) {
    if (this != &other) {
        FieldStore copy(other);
        *this = std::move(copy);
    }
    return *this;
}

FieldStore::~FieldStore() = default;

void FieldStore::resize(std::size_t n) {
    for (auto& f : fields_) f->resize(n);
    size_ = n;
    ++topologyVersion_;
}

std::size_t FieldStore::append(std::size_t n) {
    const std::size_t first = size_;
    FieldStore::resize(size_ + n);
    return first;
}

void FieldStore::keep(const std::vector<std::size_t>& indices) {
    // Checked before anything moves: a bad list must not leave the fields half compacted.
    for (std::size_t k = 0; k < indices.size(); ++k) {
        if (indices[k] >= size_)
            throw Error("keep: index " + std::to_string(indices[k]) + " of a set of " +
                        std::to_string(size_) + " particles");
        if (k > 0 && indices[k] <= indices[k - 1])
            throw Error("keep: indices must be strictly ascending (" + std::to_string(indices[k - 1]) +
                        " then " + std::to_string(indices[k]) + " at position " + std::to_string(k) + ")");
    }
    for (auto& f : fields_) f->keep(indices);
    size_ = indices.size();
    ++topologyVersion_;
}

void FieldStore::reserve(std::size_t n) {
    for (auto& f : fields_) f->reserve(n);
}

FieldBase* FieldStore::findField(const std::string& name) const {
    for (const auto& f : fields_)
        if (f->name() == name) return f.get();
    return nullptr;
}

FieldBase& FieldStore::field(const std::string& name) const {
    if (FieldBase* f = findField(name)) return *f;
    missing(name);
}

FieldBase& FieldStore::addField(std::unique_ptr<FieldBase> field) {
    if (findField(field->name())) throw Error("field '" + field->name() + "' exists already");
    if (field->size() != size_ || field->dimension() != dimension_)
        throw Error("field '" + field->name() + "' has " + std::to_string(field->size()) + " values in " +
                    std::to_string(field->dimension()) + "D; the particle set has " + std::to_string(size_) +
                    " particles in " + std::to_string(dimension_) + "D");
    fields_.push_back(std::move(field));
    return *fields_.back();
}

bool FieldStore::removeField(const std::string& name) {
    auto it = std::find_if(fields_.begin(), fields_.end(), [&](const auto& f) { return f->name() == name; });
    if (it == fields_.end()) return false;
    fields_.erase(it);
    // A field made again under this name later is the code's, not the file's.
    std::erase(sourceFields_, name);
    return true;
}

std::vector<std::string> FieldStore::fieldNames() const {
    std::vector<std::string> names;
    for (const auto& f : fields_) names.push_back(f->name());
    return names;
}

std::size_t FieldStore::bytesPerParticle() const {
    std::size_t bytes = 0;
    for (const auto& f : fields_) bytes += f->elementBytes();
    return bytes;
}

std::string FieldStore::fieldSummary() const {
    std::size_t width = 5;
    for (const auto& f : fields_) width = std::max(width, f->name().size());
    auto row = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d) {
        char line[256];
        std::snprintf(line, sizeof line, "    %-*s  %-10s  %10s  %8s\n", int(width), a.c_str(), b.c_str(),
                      c.c_str(), d.c_str());
        return std::string(line);
    };
    std::string s = row("field", "kind", "components", "bytes");
    for (const auto& f : fields_)
        s += row(f->name(), kindName(f->kind()), std::to_string(f->components()),
                 std::to_string(f->elementBytes()));
    s += row("total", "", "", std::to_string(bytesPerParticle()));
    return s;
}

void FieldStore::reorder(const std::vector<std::size_t>& order) {
    if (order.size() != size_)
        throw Error("reorder: permutation of " + std::to_string(order.size()) + " for " +
                    std::to_string(size_) + " particles");
    for (auto& f : fields_) f->reorder(order);
    ++topologyVersion_;
}

void FieldStore::checkDimension(const std::string& name, int typeDim, const std::string& typeName) const {
    if (typeDim != 0 && typeDim != dimension_)
        throw Error("field '" + name + "' asked for as " + typeName + " in a " + std::to_string(dimension_) +
                    "D particle set");
}

void FieldStore::setSource(const std::string& file) {
    source_ = file;
    sourceFields_ = fieldNames();
}

void FieldStore::typeClash(const FieldBase& existing, const std::string& requested,
                           FieldKind requestedKind) const {
    if (std::find(sourceFields_.begin(), sourceFields_.end(), existing.name()) != sourceFields_.end()) {
        auto components = [](FieldKind kind) {
            const int n = vtkComponents(kind);
            return std::to_string(n) + (n == 1 ? " component" : " components");
        };
        throw InputError("particle file '" + source_ + "': field '" + existing.name() + "' is a " +
                         existing.typeName() + " (" + components(existing.kind()) +
                         " in the file) but is needed as a " + requested + " (" + components(requestedKind) +
                         " in a particle file)");
    }
    throw Error("field '" + existing.name() + "' is a " + existing.typeName() + " but was asked for as a " +
                requested);
}

void FieldStore::missing(const std::string& name) const {
    std::string list;
    for (const auto& f : fields_) list += (list.empty() ? "" : ", ") + f->name();
    throw Error("no particle field '" + name + "'; the fields are: " + list);
}

std::string FieldStore::typeName(FieldKind kind, int dim) {
    if (dim == 0) return kindName(kind);
    return kindName(kind) + "<" + std::to_string(dim) + ">";
}

}  // namespace mfdyn
