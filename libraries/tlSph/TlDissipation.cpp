#include "tlSph/TlDissipation.hpp"

namespace mfdyn {

TlDissipation::~TlDissipation() = default;

std::unique_ptr<TlDissipation> TlDissipation::New(const Dictionary& dict) {
    return Selector::New(dict);
}

}  // namespace mfdyn
