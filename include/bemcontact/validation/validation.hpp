#pragma once
// Built-in reference cases (`bemcontact validate`): each solves a bundled example problem
// and compares quantities with a closed-form solution (reference/), producing records.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "bemcontact/bem/problem.hpp"
#include "bemcontact/bem/progress.hpp"

namespace bemcontact::validation {

enum class Comparison {
  relative,  // error = |computed - reference| / |reference|
  scaled,    // error = |computed - reference| / scale (reference may be 0)
  at_least,  // passes when computed >= reference - tolerance (e.g. a convergence order)
  report,    // shown next to a published number whose set-up is not known exactly: neither
             // passes nor fails (e.g. the thesis' flat punch, whose geometry is lost)
};

struct Record {
  std::string case_name;
  std::vector<std::pair<std::string, std::string>> params;
  std::string quantity;
  double computed = 0.0;
  double reference = 0.0;
  double error = 0.0;
  double tolerance = 0.0;
  Comparison comparison = Comparison::relative;
  bool passed = false;
};

struct Context {
  std::string examples_dir;
  bem::ProgressCallback progress;
  // `validate --operator`: the operator of every problem whose case leaves it to "auto"
  // (with_operator below); cases that compare dense with compressed keep theirs.
  bem::OperatorKind operator_kind = bem::OperatorKind::automatic;
  double operator_accuracy = 0.0;  // `validate --accuracy` with it (0: the problem's own)
};

struct Case {
  std::string name;
  std::string section;      // thesis section
  std::string description;
  std::function<std::vector<Record>(const Context&)> run;
};

const std::vector<Case>& cases();

// The problem (one body, decomposition or contact) with the operator of `validate
// --operator` where the case leaves it to "auto". Every case solves through it.
template <class Problem>
Problem with_operator(const Context& context, Problem problem) {
  if (problem.operator_choice.kind != bem::OperatorKind::automatic) return problem;
  problem.operator_choice.kind = context.operator_kind;
  if (context.operator_accuracy > 0.0) problem.operator_choice.accuracy = context.operator_accuracy;
  return problem;
}

// Record constructors that fill error and passed.
Record compare_relative(std::string quantity, double computed, double reference, double tolerance);
Record compare_scaled(std::string quantity, double computed, double reference, double scale,
                      double tolerance);
Record require_at_least(std::string quantity, double computed, double minimum);
Record report_only(std::string quantity, double computed, double published);
// A value reported without a reference (a step count, a time): reference and error are
// NaN, printed "-" and written null.
Record report_value(std::string quantity, double computed);

using Params = std::vector<std::pair<std::string, std::string>>;
// Sets case name and params of records[from...].
void tag(std::vector<Record>& records, std::size_t from, const std::string& case_name, const Params& params);

// A number as a case parameter ("0.3").
std::string number_text(double value);

// Observed order of convergence between two meshes whose sizes differ by `ratio`.
double observed_order(double coarse_error, double fine_error, double ratio);

}  // namespace bemcontact::validation
