#include "tlSph/Formulation.hpp"

namespace mfdyn {

Formulation::~Formulation() = default;

std::unique_ptr<Formulation> Formulation::New(const Dictionary& dict) {
    return Selector::New(dict);
}

}  // namespace mfdyn
