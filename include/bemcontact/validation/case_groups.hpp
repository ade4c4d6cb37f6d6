#pragma once
// Each group of reference cases lives in its own file and registers here.
#include "bemcontact/validation/validation.hpp"

namespace bemcontact::validation {
std::vector<Case> plane_cases();          // src/validation/plane_cases.cpp
std::vector<Case> axisymmetric_cases();   // src/validation/axisymmetric_cases.cpp
std::vector<Case> decomposition_cases();  // src/validation/decomposition_cases.cpp
std::vector<Case> contact_cases();        // src/validation/contact_cases.cpp
std::vector<Case> multibody_cases();      // src/validation/multibody_cases.cpp
std::vector<Case> fretting_cases();       // src/validation/fretting_cases.cpp
std::vector<Case> rough_cases();          // src/validation/wavy_cases.cpp
std::vector<Case> large_contact_cases();  // src/validation/large_contact_cases.cpp
std::vector<Case> compliance_cases();     // src/validation/compliance_cases.cpp
std::vector<Case> wear_cases();           // src/validation/wear_cases.cpp
std::vector<Case> plasticity_cases();     // src/validation/plasticity_cases.cpp
std::vector<Case> plastic_contact_cases();  // src/validation/plastic_contact_cases.cpp
}  // namespace bemcontact::validation
