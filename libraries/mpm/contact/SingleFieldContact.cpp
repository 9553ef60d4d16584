// contact `singleField` (SingleFieldContact.hpp): one node field shared by every body, the thesis's
// coupling (doc/methods/mpm.md note 2.3: contact one or two cells early, and sticky). The solver
// allocates nothing for it; this file only registers it.
#include "mpm/contact/SingleFieldContact.hpp"

namespace mfdyn {

MFDYN_REGISTER_DIM(Contact, SingleFieldContact, "singleField",
                   "one node field shared by every body (the thesis): contact one or two cells early, sticky");

}  // namespace mfdyn
