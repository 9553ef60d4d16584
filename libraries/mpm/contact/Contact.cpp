// contact (Contact.hpp): `singleField`, the thesis's coupling of every body through one node
// field (doc/methods/mpm.md note 2.3): nothing to correct, contact comes from the shared velocity.
#include "mpm/contact/Contact.hpp"

namespace mfdyn {

namespace {

template <int Dim>
class SingleFieldContact final : public Contact<Dim> {
public:
    explicit SingleFieldContact(const Dictionary&) {}
    static KeywordSchema keywords() { return KeywordSchema(Contact<Dim>::familyName, "singleField"); }
    bool multiField() const override { return false; }
};

}  // namespace

template class Contact<1>;
template class Contact<2>;
template class Contact<3>;

MFDYN_REGISTER_DIM(
    Contact, SingleFieldContact, "singleField",
    "one node field shared by every body (the thesis): contact one or two cells early, sticky");

}  // namespace mfdyn
