// The viscosity family (Viscosity.hpp): the selector entry point.
#include "materials/viscosity/Viscosity.hpp"

namespace mfdyn {

std::unique_ptr<Viscosity> Viscosity::New(const Dictionary& dict) {
    return Selector::New(dict);
}

Viscosity::Viscosity(const Dictionary& dict) : type_(dict.get<std::string>("type")) {}

}  // namespace mfdyn
