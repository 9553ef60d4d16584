#pragma once
// contact `singleField` (Contact.hpp): the thesis's coupling of every body through one node field
// (doc/methods/mpm.md note 2.3): nothing to correct, contact comes from the shared velocity.
//
//     contact          singleField;   // the default; no keywords
#include "mpm/contact/Contact.hpp"

namespace mfdyn {

template <int Dim>
class SingleFieldContact final : public Contact<Dim> {
public:
    explicit SingleFieldContact(const Dictionary&) {}
    static KeywordSchema keywords() { return KeywordSchema(Contact<Dim>::familyName, "singleField"); }
    bool multiField() const override { return false; }
};

}  // namespace mfdyn
