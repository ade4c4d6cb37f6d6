// The expression evaluator: precedence and associativity, every function against the
// C library, parameters, canonical text, deep nesting, concurrency and the messages.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <numbers>
#include <thread>

#include "bemcontact/io/input/expression.hpp"
#include "bemcontact/io/text_format.hpp"

namespace bemcontact::io {
namespace {

const SourceLocation where{"case.toml", 7, "boundary[2].t2"};

double eval(const std::string& text, double x = 0.0, double y = 0.0, ExpressionScope scope = {}) {
  return Expression::parse(text, scope, where).evaluate(x, y);
}

std::string error_of(const std::string& text, ExpressionScope scope = {}) {
  try {
    Expression::parse(text, scope, where);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

// Operations folded at parse time and run at evaluation time use the same C functions
// in the same order, so results are compared exactly.
TEST(IoExpression, PrecedenceAndAssociativity) {
  EXPECT_EQ(eval("1+2*3"), 7.0);
  EXPECT_EQ(eval("(1+2)*3"), 9.0);
  EXPECT_EQ(eval("10-4-3"), 3.0);    // left associative
  EXPECT_EQ(eval("8/4/2"), 1.0);     // left associative
  EXPECT_EQ(eval("2^3^2"), 512.0);   // right associative: 2^(3^2)
  EXPECT_EQ(eval("-2^2"), -4.0);     // ^ binds tighter than unary minus
  EXPECT_EQ(eval("2^-1"), 0.5);      // unary minus in the exponent
  EXPECT_EQ(eval("--2"), 2.0);
  EXPECT_EQ(eval("+3"), 3.0);
  EXPECT_EQ(eval("2*-3"), -6.0);
  EXPECT_EQ(eval("1 - (2*3)^2 / 4"), -8.0);
  EXPECT_EQ(eval("  4 /\t2 "), 2.0);
}

TEST(IoExpression, Numbers) {
  EXPECT_EQ(eval("1e-3"), 1e-3);
  EXPECT_EQ(eval("2.5E+2"), 250.0);
  EXPECT_EQ(eval(".5"), 0.5);
  EXPECT_EQ(eval("5."), 5.0);
  EXPECT_EQ(eval("0.1"), 0.1);
  EXPECT_EQ(eval("1e3*x", 2.0), 2000.0);  // "e3" is the exponent, not a name
}

TEST(IoExpression, Coordinates) {
  EXPECT_EQ(eval("x*y", 2.0, 3.0), 6.0);
  EXPECT_EQ(eval("0.001*x", 2.0, 0.0), 0.002);
  ExpressionScope axisymmetric;
  axisymmetric.axisymmetric = true;
  EXPECT_EQ(eval("r + 10*z", 2.0, 3.0, axisymmetric), 32.0);
  EXPECT_EQ(eval("x + 10*y", 2.0, 3.0, axisymmetric), 32.0);
  const Expression e = Expression::parse("x^2 + y", {}, where);
  EXPECT_EQ(e(Vec2(3.0, 1.0)), 10.0);
  EXPECT_EQ(e.field()(Vec2(3.0, 1.0)), 10.0);
}

TEST(IoExpression, FunctionsMatchTheCLibrary) {
  const double a = 0.3, b = -1.7;
  struct Case {
    std::string text;
    double expected;
  };
  const Case cases[] = {
      {"sqrt(x)", std::sqrt(a)},       {"sin(x)", std::sin(a)},          {"cos(x)", std::cos(a)},
      {"tan(x)", std::tan(a)},         {"asin(x)", std::asin(a)},        {"acos(x)", std::acos(a)},
      {"atan(x)", std::atan(a)},       {"exp(x)", std::exp(a)},          {"log(x)", std::log(a)},
      {"abs(y)", std::fabs(b)},        {"atan2(y, x)", std::atan2(b, a)}, {"pow(x, y)", std::pow(a, b)},
      {"min(x, y)", b},                {"max(x, y)", a},                 {"min(3, x, 2, y)", b},
      {"max(y, 1, x)", 1.0},           {"x^y", std::pow(a, b)},          {"round(y)", std::round(b)},
      {"floor(y)", std::floor(b)},     {"ceil(y)", std::ceil(b)},        {"round(x)", 0.0},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(eval(c.text, a, b), c.expected) << c.text;
    // The same with constants only: folded at parse time.
    // x, y (standalone, not inside "exp") become the parameters X, Y.
    std::string folded = c.text;
    for (std::size_t i = 0; i < folded.size(); ++i) {
      const bool alone = (i == 0 || !std::isalpha(static_cast<unsigned char>(folded[i - 1]))) &&
                         (i + 1 == folded.size() || !std::isalpha(static_cast<unsigned char>(folded[i + 1])));
      if (alone && folded[i] == 'x') folded[i] = 'X';
      if (alone && folded[i] == 'y') folded[i] = 'Y';
    }
    ExpressionScope scope;
    scope.parameters = {{"X", a}, {"Y", b}};
    const Expression constant = Expression::parse(folded, scope, where);
    EXPECT_TRUE(constant.is_constant()) << folded;
    EXPECT_EQ(constant.value(), c.expected) << folded;
  }
  EXPECT_EQ(eval("pi"), std::numbers::pi);
  EXPECT_EQ(eval("cos(pi)"), -1.0);
}

TEST(IoExpression, ParametersAndConstantFolding) {
  ExpressionScope scope;
  scope.parameters = {{"L", 100.0}, {"H", 100.0}, {"P", 2.0}};
  // The cantilever's end load p2 = 1 - (2y/H)^2 (II.7.2).
  const Expression load = Expression::parse("1 - (2*y/H)^2", scope, where);
  EXPECT_FALSE(load.is_constant());
  EXPECT_EQ(load.evaluate(0.0, 25.0), 0.75);
  EXPECT_EQ(load.evaluate(0.0, 50.0), 0.0);
  const Expression shear = Expression::parse("8*L*y/H^2", scope, where);
  EXPECT_EQ(shear.evaluate(0.0, 50.0), 4.0);
  const Expression constant = Expression::parse("P*L/2", scope, where);
  EXPECT_TRUE(constant.is_constant());
  EXPECT_EQ(constant.value(), 100.0);
  EXPECT_FALSE(Expression::parse("0*x", scope, where).is_constant());  // no algebra, only folding
}

TEST(IoExpression, CanonicalTextIdentifiesEqualExpressions) {
  ExpressionScope scope;
  scope.parameters = {{"P", 1.0}, {"k", 0.001}};
  const auto canonical = [&](const std::string& text) {
    return Expression::parse(text, scope, where).canonical();
  };
  EXPECT_EQ(canonical("0.001*x"), canonical("0.001 * x"));
  EXPECT_EQ(canonical("0.001*x"), canonical("k*x"));
  EXPECT_EQ(canonical("(0.001*x)"), canonical("k * (x)"));
  EXPECT_EQ(canonical("P"), "1");
  EXPECT_EQ(canonical("2*P + 1"), "3");
  EXPECT_NE(canonical("x+1"), canonical("x-1"));
  EXPECT_NE(canonical("x*y"), canonical("y*x"));  // only syntactic equality is claimed
  ExpressionScope axisymmetric = scope;
  axisymmetric.axisymmetric = true;
  EXPECT_EQ(Expression::parse("r+z", axisymmetric, where).canonical(), canonical("x+y"));
}

TEST(IoExpression, DeepNestingBeyondTheFixedStack) {
  // 40 nested sums keep 41 values on the stack (more than the 32 kept on the C stack).
  std::string text = "x";
  for (int i = 0; i < 40; ++i) text = "1+(" + text + ")";
  std::string right = "x";
  for (int i = 0; i < 40; ++i) right = "(" + std::to_string(i) + "+" + right + ")";
  EXPECT_EQ(eval(text, 0.5), 40.5);
  EXPECT_EQ(eval("x" + std::string(40, '+') + "1", 1.0), 2.0);  // many unary plus signs
  EXPECT_EQ(eval(right, 0.0), 780.0);
}

TEST(IoExpression, FieldsEvaluateConcurrently) {
  const bem::ScalarField field = Expression::parse("sin(x)*y + x^2", {}, where).field();
  std::vector<double> results(4, 0.0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      double sum = 0.0;
      for (int i = 0; i < 20000; ++i) sum += field(Vec2(0.001 * i, 0.5));
      results[t] = sum;
    });
  for (auto& thread : threads) thread.join();
  double expected = 0.0;
  for (int i = 0; i < 20000; ++i) expected += std::sin(0.001 * i) * 0.5 + std::pow(0.001 * i, 2.0);
  for (const double r : results) EXPECT_EQ(r, expected);
}

TEST(IoExpression, ErrorsNameTheLocationTheColumnAndWhatIsExpected) {
  std::string message = error_of("1 +");
  EXPECT_NE(message.find("case.toml:7: key 'boundary[2].t2'"), std::string::npos) << message;
  EXPECT_NE(message.find("column 4"), std::string::npos) << message;
  EXPECT_NE(message.find("expected a number, a name or '('"), std::string::npos) << message;
  EXPECT_NE(message.find("end of the expression"), std::string::npos) << message;

  message = error_of("(1+2");
  EXPECT_NE(message.find("column 5"), std::string::npos) << message;
  EXPECT_NE(message.find("expected ')' to close the '(' at column 1"), std::string::npos) << message;

  message = error_of("2x");
  EXPECT_NE(message.find("column 2"), std::string::npos) << message;
  EXPECT_NE(message.find("write '*'"), std::string::npos) << message;

  EXPECT_NE(error_of("").find("empty"), std::string::npos);
  EXPECT_NE(error_of("2**3").find("'^'"), std::string::npos);
  EXPECT_NE(error_of("1e").find("exponent"), std::string::npos);
  EXPECT_NE(error_of("3 # 4").find("unexpected character '#'"), std::string::npos);
  EXPECT_NE(error_of("1)").find("column 2"), std::string::npos);
  EXPECT_NE(error_of("sin").find("write sin(...)"), std::string::npos);
  EXPECT_NE(error_of("atan2(1)").find("takes 2 arguments, found 1"), std::string::npos);
  EXPECT_NE(error_of("sqrt(1, 2)").find("takes 1 argument, found 2"), std::string::npos);
  EXPECT_NE(error_of("min(1)").find("2 or more"), std::string::npos);
  EXPECT_NE(error_of("sin()").find("arguments of 'sin'"), std::string::npos);
  EXPECT_NE(error_of("atan2(1 2)").find("expected ',' or ')'"), std::string::npos);
}

TEST(IoExpression, UnknownNamesListTheValidOnes) {
  ExpressionScope scope;
  scope.parameters = {{"Pressure", 1.0}};
  std::string message = error_of("Presure*2", scope);
  EXPECT_NE(message.find("unknown name 'Presure'"), std::string::npos) << message;
  EXPECT_NE(message.find("Did you mean 'Pressure'?"), std::string::npos) << message;
  EXPECT_NE(message.find("Valid names: x, y, pi, Pressure"), std::string::npos) << message;
  EXPECT_NE(message.find("functions: sqrt, sin"), std::string::npos) << message;
  EXPECT_NE(message.find("column 1"), std::string::npos) << message;

  message = error_of("sinh(x)");
  EXPECT_NE(message.find("unknown function 'sinh'"), std::string::npos) << message;
  EXPECT_NE(message.find("Did you mean 'sin'?"), std::string::npos) << message;

  message = error_of("Pressure(2)", scope);
  EXPECT_NE(message.find("'Pressure' is not a function"), std::string::npos) << message;

  // r, z only in axisymmetric problems: in a plane problem "r" could be taken for a radius.
  message = error_of("r*2");
  EXPECT_NE(message.find("axisymmetric"), std::string::npos) << message;

  ExpressionScope constants;
  constants.coordinates = false;
  message = error_of("2*x", constants);
  EXPECT_NE(message.find("'x' cannot be used here"), std::string::npos) << message;
  EXPECT_NE(message.find("column 3"), std::string::npos) << message;
}

TEST(IoExpression, FiniteCheckNamesThePosition) {
  const bem::ScalarField field = Expression::parse("sqrt(x)", {}, where).field();
  EXPECT_EQ(evaluate_finite(field, Vec2(4.0, 0.0), where), 2.0);
  EXPECT_EQ(evaluate_finite(bem::ScalarField{}, Vec2(4.0, 0.0), where), 0.0);
  try {
    evaluate_finite(field, Vec2(-1.0, 0.5), where);
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("case.toml:7: key 'boundary[2].t2'"), std::string::npos) << message;
    EXPECT_NE(message.find("nan at (-1, 0.5)"), std::string::npos) << message;
  }
  const bem::ScalarField pole = Expression::parse("1/x", {}, where).field();
  EXPECT_THROW(evaluate_finite(pole, Vec2(0.0, 0.0), where), InputError);
}

TEST(IoExpression, NumbersFormatToRoundTrip) {
  for (const double value : {0.1, 1.0 / 3.0, 1e-300, -2.5, 100000.0, 6.02214076e23, -0.0, 1e-5,
                             0.0001, 9.999999999999998e15, 1e16, 5e-324, 1.7976931348623157e308}) {
    const std::string text = format_number(value);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;  // stod rejects subnormals
  }
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(-0.0), "0");
  EXPECT_EQ(format_number(100000.0), "100000");
  EXPECT_EQ(format_number(1e-5), "1e-05");
  EXPECT_EQ(format_number(0.00012), "0.00012");
  EXPECT_EQ(format_number(1e16), "1e+16");
}

// Element counts from lengths: round half away from zero, floor and ceil toward -inf, +inf.
TEST(IoExpression, RoundFloorCeilGiveCounts) {
  ExpressionScope scope;
  scope.parameters = {{"Lh", 10.0}, {"h", 0.8}};
  EXPECT_EQ(Expression::parse("round(Lh/h)", scope, where).value(), 13.0);  // 12.5
  EXPECT_EQ(Expression::parse("floor(Lh/h)", scope, where).value(), 12.0);
  EXPECT_EQ(Expression::parse("ceil(Lh/h)", scope, where).value(), 13.0);
  EXPECT_EQ(eval("round(-2.5)"), -3.0);
  EXPECT_EQ(eval("floor(-0.5)"), -1.0);
  EXPECT_EQ(eval("ceil(-0.5)"), 0.0);
  EXPECT_EQ(eval("ceil(x)", 2.0000001), 3.0);  // a field, evaluated per point
  EXPECT_NE(error_of("round(1, 2)").find("round"), std::string::npos);
}

TEST(IoExpression, ReservedNamesAndIdentifiers) {
  for (const char* name : {"x", "y", "r", "z", "pi", "sin", "atan2", "max", "round", "floor", "ceil"}) EXPECT_TRUE(is_reserved_name(name)) << name;
  for (const char* name : {"P", "L", "sigma_0", "xx"}) EXPECT_FALSE(is_reserved_name(name)) << name;
  EXPECT_TRUE(is_identifier("_a1"));
  EXPECT_FALSE(is_identifier("1a"));
  EXPECT_FALSE(is_identifier("a-b"));
  EXPECT_FALSE(is_identifier(""));
}

// RFC 4180: quoted when needed, quotes doubled; names that read as numbers quoted too.
TEST(IoCsvField, QuotesWhatCouldBeMisread) {
  EXPECT_EQ(csv_field("interface"), "interface");
  EXPECT_EQ(csv_field("top, left"), "\"top, left\"");
  EXPECT_EQ(csv_field("the \"glued\" one"), "\"the \"\"glued\"\" one\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field(" padded"), "\" padded\"");
  EXPECT_EQ(csv_field(""), "\"\"");
  EXPECT_EQ(csv_field("nan"), "\"nan\"");
  EXPECT_EQ(csv_field("1e5"), "\"1e5\"");
  EXPECT_EQ(csv_field("-inf"), "\"-inf\"");
  EXPECT_EQ(csv_field("1e5a"), "1e5a");
}

}  // namespace
}  // namespace bemcontact::io
