// Command-line parameter overrides (bemcontact run FILE --set NAME=VALUE): the value
// replaces the file's, later expressions see it, and mistakes are named.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "bemcontact/io/input/problem_file.hpp"

namespace bemcontact::io {
namespace {

const std::string plate = R"(analysis = "plane_stress"
[parameters]
L = 2.0
P = "3 * L"
[material]
E = 1000.0
nu = 0.3
[vertices]
A = [0.0, 0.0]
B = ["L", 0.0]
C = ["L", 1.0]
D = [0.0, 1.0]
[[boundary]]
from = "A"
to = "B"
u1 = 0.0
u2 = 0.0
[[boundary]]
from = "B"
to = "C"
t1 = "P"
[[boundary]]
from = "C"
to = "D"
[[boundary]]
from = "D"
to = "A"
)";

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(IoParameterOverrides, ReplaceTheValueAndLaterExpressions) {
  const auto file = parse_problem(plate, "plate.toml", {{"L", 5.0}});
  EXPECT_EQ(file.parameters.at("L"), 5.0);
  EXPECT_EQ(file.parameters.at("P"), 15.0);  // "3 * L" sees the new L
  EXPECT_EQ(file.problem.body.pieces[0].end.x(), 5.0);
  const auto unchanged = parse_problem(plate, "plate.toml");
  EXPECT_EQ(unchanged.parameters.at("P"), 6.0);
}

TEST(IoParameterOverrides, AnExpressionParameterCanBeReplaced) {
  EXPECT_EQ(parse_problem(plate, "plate.toml", {{"P", 1.5}}).parameters.at("P"), 1.5);
}

TEST(IoParameterOverrides, UnknownNameIsNamedWithTheFileAndItsParameters) {
  const std::string message = error_of([] { parse_problem(plate, "plate.toml", {{"Q", 1.0}}); });
  EXPECT_NE(message.find("plate.toml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("parameters.Q"), std::string::npos) << message;
  EXPECT_NE(message.find("its parameters: L, P"), std::string::npos) << message;
}

TEST(IoParameterOverrides, AssignmentsAreChecked) {
  ParameterOverrides overrides;
  add_parameter_override(overrides, "R=4");
  add_parameter_override(overrides, "E_ball=4.32e5");
  EXPECT_EQ(overrides.at("R").number, 4.0);
  EXPECT_EQ(overrides.at("E_ball").number, 432000.0);
  EXPECT_NE(error_of([&] { add_parameter_override(overrides, "R=5"); }).find("set twice"), std::string::npos);
  // Anything but a number is an expression, evaluated (and checked) where the parameter stands.
  ParameterOverrides expression;
  add_parameter_override(expression, "P=2*L");
  EXPECT_EQ(expression.at("P").expression, "2*L");
  EXPECT_EQ(parse_problem(plate, "plate.toml", expression).parameters.at("P"), 4.0);  // the file's L = 2
  const std::string bad = error_of([] {
    ParameterOverrides o;
    add_parameter_override(o, "P=1.5e");
    parse_problem(plate, "plate.toml", o);
  });
  EXPECT_NE(bad.find("--set P=1.5e"), std::string::npos) << bad;
  const std::string infinite = error_of([] {
    ParameterOverrides o;
    add_parameter_override(o, "P=1/0");
    parse_problem(plate, "plate.toml", o);
  });
  EXPECT_NE(infinite.find("--set P=1/0: the value is inf"), std::string::npos) << infinite;
  EXPECT_NE(error_of([&] { add_parameter_override(overrides, "Y="); }).find("no value"), std::string::npos);
  EXPECT_NE(error_of([&] { add_parameter_override(overrides, "=1"); }).find("NAME=VALUE"), std::string::npos);
  EXPECT_NE(error_of([&] { add_parameter_override(overrides, "Z"); }).find("NAME=VALUE"), std::string::npos);
}

// A replacing value may be an expression, evaluated where the parameter stands (the Python
// module's keyword arguments); its errors name the parameter and how it was given.
TEST(IoParameterOverrides, AnExpressionReplacesAsTheFileWritesIt) {
  const auto file = parse_problem(plate, "plate.toml", {{"L", ParameterValue("2 * 3")}});
  EXPECT_EQ(file.parameters.at("L"), 6.0);
  EXPECT_EQ(file.parameters.at("P"), 18.0);
  EXPECT_EQ(parse_problem(plate, "plate.toml", {{"P", ParameterValue("L / 4")}}).parameters.at("P"), 0.5);
  ParameterValue later("P + 1");
  later.origin = "keyword argument L='P + 1'";
  const std::string order = error_of([&] { parse_problem(plate, "plate.toml", {{"L", later}}); });
  EXPECT_NE(order.find("plate.toml:3: key 'parameters.L': keyword argument L='P + 1': parameter 'L' uses 'P', which "
                       "is defined later"), std::string::npos) << order;
  ParameterValue bad("3 *");
  bad.origin = "keyword argument P='3 *'";
  const std::string syntax = error_of([&] { parse_problem(plate, "plate.toml", {{"P", bad}}); });
  EXPECT_NE(syntax.find("plate.toml:4: key 'parameters.P': keyword argument P='3 *': in expression \"3 *\""),
            std::string::npos) << syntax;
  const std::string infinite = error_of([] { parse_problem(plate, "plate.toml", {{"P", ParameterValue("1/0")}}); });
  EXPECT_NE(infinite.find("--set P: the value is inf"), std::string::npos) << infinite;
  const std::string unknown = error_of([] { parse_problem(plate, "plate.toml", {{"Q", 1.0}}); });
  EXPECT_NE(unknown.find("--set Q: the file has no parameter 'Q'"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace bemcontact::io
