#pragma once
// Arithmetic expressions for boundary values in problem files, e.g. "1 - (2*y/H)^2".
// Parsed once into a small stack program (constants folded, parameters substituted),
// then evaluated many times without allocation; safe to evaluate from several threads.
//
// Grammar (usual precedence; ^ binds tighter than unary minus and is right associative,
// so -2^2 = -4 and 2^3^2 = 2^9):
//   expression := term (('+' | '-') term)*
//   term       := unary (('*' | '/') unary)*
//   unary      := ('-' | '+') unary | power
//   power      := primary ('^' unary)?
//   primary    := number | name | name '(' expression (',' expression)* ')' | '(' expression ')'
// Numbers: 12, 1.5, .5, 1e-3, 2.5E+4. Names: x, y (r, z as aliases in axisymmetric
// problems), pi, the parameters in scope, and the functions listed by function_names().
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bemcontact/bem/problem.hpp"
#include "bemcontact/core/error.hpp"

namespace bemcontact::io {

// What names an expression may use besides pi and the functions.
struct ExpressionScope {
  std::map<std::string, double> parameters;  // named constants, substituted at parse time
  bool coordinates = true;    // false: x, y are not allowed (parameter definitions, geometry)
  bool axisymmetric = false;  // r, z are accepted as aliases of x, y
};

class Expression {
 public:
  // Throws InputError naming `where`, the column in `text` and what was expected.
  static Expression parse(std::string_view text, const ExpressionScope& scope,
                          const SourceLocation& where);

  double evaluate(double x, double y) const;
  double operator()(const Vec2& position) const { return evaluate(position.x(), position.y()); }

  // True when the value does not depend on the position (then value() is it).
  bool is_constant() const;
  double value() const { return evaluate(0.0, 0.0); }

  const std::string& text() const;  // as written
  // Normalised text (no spaces, constants folded, parameters replaced by their values,
  // r, z written x, y): two expressions with equal canonical text are equal functions.
  const std::string& canonical() const;

  bem::ScalarField field() const;

 private:
  struct Program;
  explicit Expression(std::shared_ptr<const Program> program) : program_(std::move(program)) {}
  std::shared_ptr<const Program> program_;
};

// The built-in function names, for messages and to keep parameters from shadowing them.
const std::vector<std::string>& function_names();
// Names a parameter may not take: functions, pi, x, y, r, z.
bool is_reserved_name(std::string_view name);
// A valid name: a letter or '_' followed by letters, digits or '_'.
bool is_identifier(std::string_view name);

// The value of `field` at `position`; throws InputError naming `where` and the position
// when it is NaN or infinite (e.g. sqrt of a negative number, division by zero).
double evaluate_finite(const bem::ScalarField& field, const Vec2& position,
                       const SourceLocation& where);


}  // namespace bemcontact::io
