#include <cmath>
#include <limits>
#include <sstream>

#include "bemcontact/validation/validation.hpp"

namespace bemcontact::validation {

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

Record compare_relative(std::string quantity, double computed, double reference, double tolerance) {
  Record r;
  r.quantity = std::move(quantity);
  r.computed = computed;
  r.reference = reference;
  r.tolerance = tolerance;
  r.comparison = Comparison::relative;
  r.error = std::abs(computed - reference) / std::abs(reference);
  r.passed = std::isfinite(r.error) && r.error <= tolerance;
  return r;
}

Record compare_scaled(std::string quantity, double computed, double reference, double scale,
                      double tolerance) {
  Record r = compare_relative(std::move(quantity), computed, reference, tolerance);
  r.comparison = Comparison::scaled;
  r.error = std::abs(computed - reference) / scale;
  r.passed = std::isfinite(r.error) && r.error <= tolerance;
  return r;
}

Record require_at_least(std::string quantity, double computed, double minimum) {
  Record r;
  r.quantity = std::move(quantity);
  r.computed = computed;
  r.reference = minimum;
  r.tolerance = 0.0;
  r.comparison = Comparison::at_least;
  r.error = std::max(0.0, minimum - computed);
  r.passed = std::isfinite(computed) && computed >= minimum;
  return r;
}

Record report_only(std::string quantity, double computed, double published) {
  Record r;
  r.quantity = std::move(quantity);
  r.computed = computed;
  r.reference = published;
  r.comparison = Comparison::report;
  r.error = std::abs(computed - published) / std::abs(published);
  r.passed = true;  // not counted
  return r;
}

Record report_value(std::string quantity, double computed) {
  Record r = report_only(std::move(quantity), computed, std::numeric_limits<double>::quiet_NaN());
  r.error = std::numeric_limits<double>::quiet_NaN();
  return r;
}

void tag(std::vector<Record>& records, std::size_t from, const std::string& case_name, const Params& params) {
  for (std::size_t k = from; k < records.size(); ++k) {
    records[k].case_name = case_name;
    records[k].params = params;
  }
}

double observed_order(double coarse_error, double fine_error, double ratio) {
  return std::log(coarse_error / fine_error) / std::log(ratio);
}

}  // namespace bemcontact::validation
