#include "particles/FieldBase.hpp"

#include "core/Error.hpp"

namespace mfdyn {

std::string kindName(FieldKind kind) {
    switch (kind) {
        case FieldKind::scalar:
            return "scalar";
        case FieldKind::vector:
            return "vector";
        case FieldKind::tensor:
            return "tensor";
        case FieldKind::symmTensor:
            return "symmTensor";
        case FieldKind::integer:
            return "integer";
    }
    return "unknown";
}

int componentCount(FieldKind kind, int dim) {
    switch (kind) {
        case FieldKind::scalar:
        case FieldKind::integer:
            return 1;
        case FieldKind::vector:
            return dim;
        case FieldKind::tensor:
            return dim * dim;
        case FieldKind::symmTensor:
            return dim * (dim + 1) / 2;
    }
    return 0;
}

std::vector<std::string> componentNames(FieldKind kind, int dim) {
    static const char* axis[] = {"x", "y", "z"};
    std::vector<std::string> names;
    switch (kind) {
        case FieldKind::scalar:
        case FieldKind::integer:
            names.push_back("");
            break;
        case FieldKind::vector:
            for (int i = 0; i < dim; ++i) names.push_back(axis[i]);
            break;
        case FieldKind::tensor:
            // Eigen stores column by column: memory index i + j*dim holds row i, column j.
            for (int j = 0; j < dim; ++j)
                for (int i = 0; i < dim; ++i) names.push_back(std::string(axis[i]) + axis[j]);
            break;
        case FieldKind::symmTensor: {
            static const char* order[] = {"xx", "yy", "zz", "xy", "yz", "xz"};
            if (dim == 1)
                names = {"xx"};
            else if (dim == 2)
                names = {"xx", "yy", "xy"};
            else
                names.assign(order, order + 6);
            break;
        }
    }
    return names;
}

FieldBase::FieldBase(std::string name, FieldKind kind, int dimension)
    : name_(std::move(name)), kind_(kind), dimension_(dimension) {
    if (dimension < 1 || dimension > 3)
        throw Error("field '" + name_ + "': dimension " + std::to_string(dimension) + " is not 1, 2 or 3");
}

FieldBase::~FieldBase() = default;

std::string FieldBase::typeName() const {
    if (kind_ == FieldKind::scalar || kind_ == FieldKind::integer) return kindName(kind_);
    return kindName(kind_) + "<" + std::to_string(dimension_) + ">";
}

}  // namespace mfdyn
