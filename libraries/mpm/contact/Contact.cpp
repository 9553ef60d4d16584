// contact (Contact.hpp): the family's instantiations; its models are singleField
// (SingleFieldContact.cpp) and multiField (MultiFieldContact.cpp).
#include "mpm/contact/Contact.hpp"

namespace mfdyn {

template class Contact<1>;
template class Contact<2>;
template class Contact<3>;

}  // namespace mfdyn
