#include "bemcontact/validation/case_groups.hpp"

namespace bemcontact::validation {

const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    std::vector<Case> list;
    for (auto group : {plane_cases, axisymmetric_cases, decomposition_cases, contact_cases, multibody_cases, fretting_cases,
                       rough_cases, compliance_cases, wear_cases, plasticity_cases, plastic_contact_cases,
                       large_contact_cases})
      for (auto& c : group()) list.push_back(std::move(c));
    return list;
  }();
  return all;
}

}  // namespace bemcontact::validation
