// Reference cases of this group (to be filled by its module's author).
#include "bemcontact/validation/case_groups.hpp"

namespace bemcontact::validation {

std::vector<Case> axisymmetric_cases() { return {}; }

}  // namespace bemcontact::validation
