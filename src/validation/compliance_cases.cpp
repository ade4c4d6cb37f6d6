// Reference cases of contact laws beyond the unilateral one: normal compliance against the
// Winkler foundation's closed form, and its stiff limit against the unilateral contact.
#include <algorithm>
#include <cmath>
#include <string>

#include "bemcontact/contact/contact_solver.hpp"
#include "bemcontact/reference/winkler.hpp"
#include "bemcontact/validation/case_groups.hpp"
#include "bemcontact/validation/contact_support.hpp"

namespace bemcontact::validation {
namespace {

// Largest |p - p_Winkler| over the Winkler p0, over every pair (open ones included: their
// closed form is 0).
double winkler_profile_error(const std::vector<contact::PairResult>& pairs, const reference::WinklerCylinder& exact) {
  double worst = 0.0;
  for (const auto& pair : pairs)
    worst = std::max(worst, std::abs(-pair.p_n - exact.pressure(pair.coordinate)));
  return worst / exact.max_pressure();
}

reference::WinklerCylinder winkler_of(const io::ContactFile& file) {
  const auto& law = file.problem.contacts.front().law.compliance;
  return {file.parameters.at("P"), file.parameters.at("R"), law.stiffness, law.exponent};
}

// examples/contact_compliant_cylinder.toml: a rigid cylinder on a block 10^5 times stiffer
// than the interface (the block's deflection, about p a / E, is 1e-6 of the approach), so
// the Winkler foundation (reference/winkler.hpp, the circle's exact gap) holds to that:
// (i) m = 1 on 60, 120, 240 zone elements: each pair's pressure is the law at its own
// interpenetration, so the error is the approach's, set by the force balance over the zone
// (the pressure's kink at the edge inside an element: O((h/a)^2) = 2.5e-3 at 60 elements,
// the bound); a within 0.5 % (the edge located to a tenth of the spacing h = a/20); the
// profile error falling under refinement (measured 3.8e-4, 8.2e-5, 1.5e-5); (ii) m = 2.2 (c_n
// chosen for the same p0 scale) on 120; (iii) on an elastic block (E = 70 000, the
// unilateral Hertz case of the rigid cylinder, P = 148) c_n = 1e5 ... 1e8: the centre
// pressure tends to the unilateral contact's on the same mesh, its difference shrinking with
// every decade (toward a rate of 1/c_n: the interface adds p / c_n to the approach) and
// within 1 % at 1e8.
std::vector<Record> run_normal_compliance(const Context& context) {
  std::vector<Record> records;
  std::vector<double> errors;
  for (const int n : {60, 120, 240}) {
    const std::size_t first = records.size();
    const auto file = load_contact_example(context, "contact_compliant_cylinder.toml", {{"n", n}});
    const auto exact = winkler_of(file);
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    errors.push_back(winkler_profile_error(result.pairs, exact));
    records.push_back(compare_scaled("pressure_profile_max_error", errors.back(), 0.0, 1.0, 2.5e-3));
    records.push_back(compare_relative("a", result.summary.contact_radius, exact.half_width(), 0.005));
    records.push_back(compare_relative("approach", -result.summary.approach, exact.approach(), 2.5e-3));
    tag(records, first, "normal-compliance", {{"m", "1"}, {"contact_elements", std::to_string(n)}});
  }
  {
    const std::size_t first = records.size();
    records.push_back(require_at_least("profile_error_60_over_120", errors[0] / errors[1], 1.0));
    records.push_back(require_at_least("profile_error_120_over_240", errors[1] / errors[2], 1.0));
    tag(records, first, "normal-compliance", {{"m", "1"}, {"contact_elements", "60 -> 120 -> 240"}});
  }
  {
    const std::size_t first = records.size();
    const auto file = load_contact_example(context, "contact_compliant_cylinder.toml", {{"m", 2.2}, {"cn", 5.8e6}});
    const auto exact = winkler_of(file);
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    records.push_back(compare_scaled("pressure_profile_max_error", winkler_profile_error(result.pairs, exact), 0.0, 1.0,
                                     2.5e-3));
    records.push_back(compare_relative("a", result.summary.contact_radius, exact.half_width(), 0.005));
    records.push_back(compare_relative("approach", -result.summary.approach, exact.approach(), 2.5e-3));
    tag(records, first, "normal-compliance", {{"m", "2.2"}, {"contact_elements", "120"}});
  }
  // The stiff limit, on an elastic block.
  auto unilateral_file = load_contact_example(context, "contact_compliant_cylinder.toml", {{"E_block", 70000.0}, {"P", 148.0}});
  unilateral_file.problem.contacts.front().law = contact::ContactLaw{};
  const double unilateral =
      contact::solve_contact(with_operator(context, unilateral_file.problem), context.progress).summary.centre_pressure;
  double previous = 1.0;
  for (const double cn : {1e5, 1e6, 1e7, 1e8}) {
    const std::size_t first = records.size();
    const auto file =
        load_contact_example(context, "contact_compliant_cylinder.toml", {{"E_block", 70000.0}, {"P", 148.0}, {"cn", cn}});
    const auto result = contact::solve_contact(with_operator(context, file.problem), context.progress);
    const double difference = std::abs(result.summary.centre_pressure / unilateral - 1.0);
    records.push_back(report_only("centre_pressure", result.summary.centre_pressure, unilateral));
    records.push_back(require_at_least("difference_shrinks", previous - difference, 0.0));
    if (cn == 1e8) records.push_back(compare_relative("centre_pressure_stiff", result.summary.centre_pressure, unilateral, 0.01));
    previous = difference;
    tag(records, first, "normal-compliance", {{"limit", "unilateral"}, {"c_n", std::to_string(static_cast<long>(cn))}});
  }
  return records;
}

}  // namespace

std::vector<Case> compliance_cases() {
  return {
      {"normal-compliance", "Oden-Martins 1985",
       "rigid cylinder through a compliant interface: Winkler closed form (m = 1, 2.2), the unilateral limit",
       run_normal_compliance},
  };
}

}  // namespace bemcontact::validation
