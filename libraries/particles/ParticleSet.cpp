#include "particles/ParticleSet.hpp"

namespace mfdyn {

template <int Dim>
ParticleSet<Dim>::ParticleSet(std::size_t n) : ParticleSetBase(Dim, n) {
    position();
    globalId();
    region();
}

template <int Dim>
FieldBase& ParticleSet<Dim>::addField(const std::string& name, FieldKind kind) {
    if (hasField(name)) throw Error("field '" + name + "' exists already");
    switch (kind) {
        case FieldKind::scalar:
            scalarField(name);
            break;
        case FieldKind::vector:
            vectorField(name);
            break;
        case FieldKind::tensor:
            tensorField(name);
            break;
        case FieldKind::symmTensor:
            symmTensorField(name);
            break;
        case FieldKind::integer:
            integerField(name);
            break;
    }
    return field(name);
}

template class ParticleSet<1>;
template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace mfdyn
