#include "bemcontact/io/input/expression.hpp"
#include "bemcontact/io/text_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "bemcontact/io/input/suggestions.hpp"

namespace bemcontact::io {

// The compiled form is a member of Expression::Program, which has external linkage: its
// types stay out of the anonymous namespace.
namespace expression_detail {

enum class Op { constant, x, y, negate, add, subtract, multiply, divide, power, call1, call2 };

using Unary = double (*)(double);
using Binary = double (*)(double, double);

struct Instruction {
  Op op;
  double value;
  Unary unary;
  Binary binary;
};

}  // namespace expression_detail

namespace {

using expression_detail::Binary;
using expression_detail::Instruction;
using expression_detail::Op;
using expression_detail::Unary;

struct Function {
  const char* name;
  int arity;  // 1, 2, or -2 for "two or more" (min, max fold pairwise)
  Unary unary = nullptr;
  Binary binary = nullptr;
};

// Lambdas rather than &std::sqrt: the standard functions are overloaded.
const Function functions[] = {
    {"sqrt", 1, [](double a) { return std::sqrt(a); }},
    {"sin", 1, [](double a) { return std::sin(a); }},
    {"cos", 1, [](double a) { return std::cos(a); }},
    {"tan", 1, [](double a) { return std::tan(a); }},
    {"asin", 1, [](double a) { return std::asin(a); }},
    {"acos", 1, [](double a) { return std::acos(a); }},
    {"atan", 1, [](double a) { return std::atan(a); }},
    {"exp", 1, [](double a) { return std::exp(a); }},
    {"log", 1, [](double a) { return std::log(a); }},
    {"abs", 1, [](double a) { return std::fabs(a); }},
    // Counts from lengths, e.g. elements = "round(L/h)"; round takes halves away from zero.
    {"round", 1, [](double a) { return std::round(a); }},
    {"floor", 1, [](double a) { return std::floor(a); }},
    {"ceil", 1, [](double a) { return std::ceil(a); }},
    {"atan2", 2, nullptr, [](double a, double b) { return std::atan2(a, b); }},
    {"pow", 2, nullptr, [](double a, double b) { return std::pow(a, b); }},
    {"min", -2, nullptr, [](double a, double b) { return std::fmin(a, b); }},
    {"max", -2, nullptr, [](double a, double b) { return std::fmax(a, b); }},
};

const Function* find_function(std::string_view name) {
  for (const auto& function : functions)
    if (name == function.name) return &function;
  return nullptr;
}

double apply(Op op, double a, double b) {
  switch (op) {
    case Op::add: return a + b;
    case Op::subtract: return a - b;
    case Op::multiply: return a * b;
    case Op::divide: return a / b;
    case Op::power: return std::pow(a, b);
    default: return 0.0;
  }
}

char op_symbol(Op op) {
  switch (op) {
    case Op::add: return '+';
    case Op::subtract: return '-';
    case Op::multiply: return '*';
    case Op::divide: return '/';
    case Op::power: return '^';
    default: return '?';
  }
}

struct Node {
  Op op = Op::constant;
  double value = 0.0;
  const Function* function = nullptr;
  int left = -1, right = -1;
  int height = 1;  // of the subtree: evaluation and printing recurse this deep
};

// Deeper expressions than this are refused: the parser, the compiler and the printer
// recurse once per level, and no real boundary value needs more.
constexpr int max_expression_depth = 200;

enum class TokenKind { number, name, op, open, close, comma, end };

struct Token {
  TokenKind kind = TokenKind::end;
  std::size_t column = 0;  // 0-based offset in the text
  std::string_view text;
  double value = 0.0;
};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string describe(const Token& token) {
  if (token.kind == TokenKind::end) return "the end of the expression";
  return "'" + std::string(token.text) + "'";
}

class Parser {
 public:
  Parser(std::string_view text, const ExpressionScope& scope, const SourceLocation& where)
      : text_(text), scope_(scope), where_(where) {
    advance();
  }

  int parse_all() {
    if (current_.kind == TokenKind::end) fail(0, "the expression is empty");
    const int root = parse_sum();
    if (current_.kind != TokenKind::end) {
      std::string what = "expected an operator (+ - * / ^) or the end of the expression, found " +
                         describe(current_);
      if (current_.kind == TokenKind::name || current_.kind == TokenKind::open ||
          current_.kind == TokenKind::number)
        what += " (write '*' for a product)";
      fail(current_.column, what);
    }
    return root;
  }

  std::vector<Node> nodes;
  bool uses_coordinates = false;

 private:
  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    std::string shown(text_.substr(0, 120));
    if (text_.size() > shown.size()) shown += "...";
    std::replace(shown.begin(), shown.end(), '\n', ' ');
    throw InputError(where_, "in expression \"" + shown + "\", column " + std::to_string(column + 1) +
                                 ": " + what + "\n    " + shown + "\n    " +
                                 std::string(column, ' ') + "^");
  }

  void advance() {
    std::size_t i = position_;
    while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
    Token token;
    token.column = i;
    if (i >= text_.size()) {
      token.kind = TokenKind::end;
      position_ = i;
      current_ = token;
      return;
    }
    const char c = text_[i];
    std::size_t end = i + 1;
    if (is_digit(c) || (c == '.' && i + 1 < text_.size() && is_digit(text_[i + 1]))) {
      end = i;
      while (end < text_.size() && is_digit(text_[end])) ++end;
      if (end < text_.size() && text_[end] == '.') {
        ++end;
        while (end < text_.size() && is_digit(text_[end])) ++end;
      }
      if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
        std::size_t exponent = end + 1;
        if (exponent < text_.size() && (text_[exponent] == '+' || text_[exponent] == '-')) ++exponent;
        if (exponent >= text_.size() || !is_digit(text_[exponent]))
          fail(exponent, "expected the digits of the exponent after '" +
                             std::string(text_.substr(i, exponent - i)) + "'");
        end = exponent;
        while (end < text_.size() && is_digit(text_[end])) ++end;
      }
      token.kind = TokenKind::number;
      // from_chars does not take a leading '.', so read ".5" as "0.5".
      std::string digits = c == '.' ? "0" + std::string(text_.substr(i, end - i))
                                    : std::string(text_.substr(i, end - i));
      const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), token.value);
      if (result.ec != std::errc() || result.ptr != digits.data() + digits.size())
        fail(i, "'" + digits + "' is not a valid number");
    } else if (is_name_start(c)) {
      while (end < text_.size() && is_name_char(text_[end])) ++end;
      token.kind = TokenKind::name;
    } else if (c == '*' && i + 1 < text_.size() && text_[i + 1] == '*') {
      fail(i, "'**' is not an operator; write '^' for a power");
    } else if (c == '+' || c == '-' || c == '*' || c == '/' || c == '^') {
      token.kind = TokenKind::op;
    } else if (c == '(') {
      token.kind = TokenKind::open;
    } else if (c == ')') {
      token.kind = TokenKind::close;
    } else if (c == ',') {
      token.kind = TokenKind::comma;
    } else {
      fail(i, "unexpected character '" + std::string(1, c) +
                  "'; expected a number, a name, an operator (+ - * / ^), '(' or ')'");
    }
    token.text = text_.substr(i, end - i);
    position_ = end;
    current_ = token;
  }

  bool at_op(char symbol) const {
    return current_.kind == TokenKind::op && current_.text[0] == symbol;
  }

  int add_node(Node node) {
    // Fold constants now so that evaluation never repeats work on parameters.
    const bool left_constant = node.left < 0 || nodes[node.left].op == Op::constant;
    const bool right_constant = node.right < 0 || nodes[node.right].op == Op::constant;
    if (node.op != Op::constant && node.op != Op::x && node.op != Op::y && left_constant &&
        right_constant) {
      const double a = nodes[node.left].value;
      const double b = node.right >= 0 ? nodes[node.right].value : 0.0;
      double value = 0.0;
      if (node.op == Op::negate) value = -a;
      else if (node.op == Op::call1) value = node.function->unary(a);
      else if (node.op == Op::call2) value = node.function->binary(a, b);
      else value = apply(node.op, a, b);
      node = Node{Op::constant, value};
    }
    if (node.op != Op::constant) {
      node.height = 1 + std::max(node.left >= 0 ? nodes[node.left].height : 0,
                                 node.right >= 0 ? nodes[node.right].height : 0);
      if (node.height > max_expression_depth) fail_too_deep();
    }
    nodes.push_back(node);
    return static_cast<int>(nodes.size()) - 1;
  }

  [[noreturn]] void fail_too_deep() const {
    fail(current_.column, "the expression nests more than " + std::to_string(max_expression_depth) +
                              " operations deep (the limit of the expression reader); split it into "
                              "named [parameters]");
  }

  // Counts the parser's own recursion (parentheses, signs, calls).
  struct Nesting {
    explicit Nesting(const Parser& parser) : parser_(parser) {
      // (a level of parentheses takes two: the parenthesis and the sign before it)
      if (++parser_.nesting_ > 2 * max_expression_depth) parser_.fail_too_deep();
    }
    ~Nesting() { --parser_.nesting_; }
    const Parser& parser_;
  };

  int parse_sum() {
    int left = parse_product();
    while (at_op('+') || at_op('-')) {
      const Op op = at_op('+') ? Op::add : Op::subtract;
      advance();
      const int right = parse_product();
      left = add_node(Node{op, 0.0, nullptr, left, right});
    }
    return left;
  }

  int parse_product() {
    int left = parse_unary();
    while (at_op('*') || at_op('/')) {
      const Op op = at_op('*') ? Op::multiply : Op::divide;
      advance();
      const int right = parse_unary();
      left = add_node(Node{op, 0.0, nullptr, left, right});
    }
    return left;
  }

  int parse_unary() {
    const Nesting nesting(*this);
    if (at_op('-')) {
      advance();
      const int operand = parse_unary();
      return add_node(Node{Op::negate, 0.0, nullptr, operand, -1});
    }
    if (at_op('+')) {
      advance();
      return parse_unary();
    }
    return parse_power();
  }

  int parse_power() {
    const int base = parse_primary();
    if (!at_op('^')) return base;
    advance();
    const int exponent = parse_unary();  // right associative: 2^3^2 = 2^(3^2)
    return add_node(Node{Op::power, 0.0, nullptr, base, exponent});
  }

  int parse_primary() {
    const Token token = current_;
    switch (token.kind) {
      case TokenKind::number:
        advance();
        return add_node(Node{Op::constant, token.value});
      case TokenKind::open: {
        const Nesting nesting(*this);
        advance();
        const int inner = parse_sum();
        if (current_.kind != TokenKind::close)
          fail(current_.column, "expected ')' to close the '(' at column " +
                                    std::to_string(token.column + 1) + ", found " + describe(current_));
        advance();
        return inner;
      }
      case TokenKind::name: {
        advance();
        if (current_.kind == TokenKind::open) return parse_call(token);
        return name_value(token);
      }
      default:
        fail(token.column, "expected a number, a name or '(', found " + describe(token));
    }
  }

  int parse_call(const Token& name) {
    const Function* function = find_function(name.text);
    if (!function) {
      if (scope_.parameters.count(std::string(name.text)) || name_is_coordinate(name.text))
        fail(name.column, "'" + std::string(name.text) + "' is not a function; functions: " +
                              function_list());
      fail(name.column, "unknown function '" + std::string(name.text) + "'." +
                            did_you_mean(name.text, function_names()) +
                            " Functions: " + function_list());
    }
    const std::size_t open_column = current_.column;
    advance();  // '('
    std::vector<int> arguments;
    if (current_.kind == TokenKind::close)
      fail(current_.column, "expected the arguments of '" + std::string(name.text) + "'");
    while (true) {
      arguments.push_back(parse_sum());
      if (current_.kind == TokenKind::comma) {
        advance();
        continue;
      }
      if (current_.kind == TokenKind::close) break;
      fail(current_.column, "expected ',' or ')' in the arguments of '" + std::string(name.text) +
                                "' opened at column " + std::to_string(open_column + 1) +
                                ", found " + describe(current_));
    }
    advance();  // ')'
    const int count = static_cast<int>(arguments.size());
    if (function->arity == 1 && count != 1)
      fail(name.column, "'" + std::string(name.text) + "' takes 1 argument, found " +
                            std::to_string(count));
    if (function->arity == 2 && count != 2)
      fail(name.column, "'" + std::string(name.text) + "' takes 2 arguments, found " +
                            std::to_string(count));
    if (function->arity == -2 && count < 2)
      fail(name.column, "'" + std::string(name.text) + "' takes 2 or more arguments, found " +
                            std::to_string(count));
    if (function->arity == 1)
      return add_node(Node{Op::call1, 0.0, function, arguments[0], -1});
    int result = arguments[0];
    for (int i = 1; i < count; ++i)
      result = add_node(Node{Op::call2, 0.0, function, result, arguments[i]});
    return result;
  }

  bool name_is_coordinate(std::string_view name) const {
    return name == "x" || name == "y" || (scope_.axisymmetric && (name == "r" || name == "z"));
  }

  std::string function_list() const {
    std::string list;
    for (const auto& name : function_names()) list += (list.empty() ? "" : ", ") + name;
    return list;
  }

  std::vector<std::string> valid_names() const {
    std::vector<std::string> names;
    if (scope_.coordinates) {
      names = {"x", "y"};
      if (scope_.axisymmetric) names.insert(names.end(), {"r", "z"});
    }
    names.push_back("pi");
    for (const auto& [name, value] : scope_.parameters) names.push_back(name);
    return names;
  }

  int name_value(const Token& token) {
    const std::string name(token.text);
    if (name == "pi") return add_node(Node{Op::constant, std::numbers::pi});
    if (auto found = scope_.parameters.find(name); found != scope_.parameters.end())
      return add_node(Node{Op::constant, found->second});
    if (name_is_coordinate(name)) {
      if (!scope_.coordinates)
        fail(token.column, "'" + name + "' cannot be used here: this value must be a constant "
                           "(numbers, pi and parameters only)");
      uses_coordinates = true;
      const bool first = name == "x" || name == "r";
      return add_node(Node{first ? Op::x : Op::y});
    }
    if (find_function(name))
      fail(token.column, "'" + name + "' is a function; write " + name + "(...)");
    std::string what = "unknown name '" + name + "'.";
    if (scope_.coordinates && !scope_.axisymmetric && (name == "r" || name == "z"))
      what += " r and z are the coordinates of axisymmetric problems; use x and y here.";
    else
      what += did_you_mean(name, valid_names());
    what += " Valid names: ";
    const auto names = valid_names();
    for (std::size_t i = 0; i < names.size(); ++i) what += (i ? ", " : "") + names[i];
    what += "; functions: " + function_list();
    fail(token.column, what);
  }

  std::string_view text_;
  const ExpressionScope& scope_;
  const SourceLocation& where_;
  std::size_t position_ = 0;
  Token current_;
  mutable int nesting_ = 0;
};

std::string canonical_text(const std::vector<Node>& nodes, int index) {
  const Node& node = nodes[index];
  switch (node.op) {
    case Op::constant: {
      const std::string number = format_number(node.value);
      return node.value < 0 ? "(" + number + ")" : number;
    }
    case Op::x: return "x";
    case Op::y: return "y";
    case Op::negate: return "(-" + canonical_text(nodes, node.left) + ")";
    case Op::call1: return std::string(node.function->name) + "(" + canonical_text(nodes, node.left) + ")";
    case Op::call2:
      return std::string(node.function->name) + "(" + canonical_text(nodes, node.left) + "," +
             canonical_text(nodes, node.right) + ")";
    default:
      return "(" + canonical_text(nodes, node.left) + op_symbol(node.op) +
             canonical_text(nodes, node.right) + ")";
  }
}

}  // namespace

struct Expression::Program {
  std::string text;
  std::string canonical;
  std::vector<Instruction> code;  // postfix
  int stack_size = 0;
  bool constant = true;

  void emit(const std::vector<Node>& nodes, int index, int& depth) {
    const Node& node = nodes[index];
    if (node.left >= 0) emit(nodes, node.left, depth);
    if (node.right >= 0) emit(nodes, node.right, depth);
    code.push_back(Instruction{node.op, node.value, node.function ? node.function->unary : nullptr,
                               node.function ? node.function->binary : nullptr});
    if (node.op == Op::constant || node.op == Op::x || node.op == Op::y) ++depth;
    else if (node.right >= 0) --depth;  // two operands in, one out
    stack_size = std::max(stack_size, depth);
  }

  double run(double x, double y) const {
    constexpr int small = 32;
    double fixed[small] = {};  // zeroed: keeps -Wmaybe-uninitialized quiet, costs little
    std::vector<double> large;
    double* stack = fixed;
    if (stack_size > small) {
      large.resize(stack_size);
      stack = large.data();
    }
    int top = -1;
    for (const Instruction& instruction : code) {
      switch (instruction.op) {
        case Op::constant: stack[++top] = instruction.value; break;
        case Op::x: stack[++top] = x; break;
        case Op::y: stack[++top] = y; break;
        case Op::negate: stack[top] = -stack[top]; break;
        case Op::call1: stack[top] = instruction.unary(stack[top]); break;
        case Op::call2:
          --top;
          stack[top] = instruction.binary(stack[top], stack[top + 1]);
          break;
        default:
          --top;
          stack[top] = apply(instruction.op, stack[top], stack[top + 1]);
          break;
      }
    }
    return stack[0];
  }
};

Expression Expression::parse(std::string_view text, const ExpressionScope& scope,
                             const SourceLocation& where) {
  Parser parser(text, scope, where);
  const int root = parser.parse_all();
  auto program = std::make_shared<Program>();
  program->text = std::string(text);
  program->canonical = canonical_text(parser.nodes, root);
  program->constant = parser.nodes[root].op == Op::constant;
  int depth = 0;
  program->emit(parser.nodes, root, depth);
  return Expression(std::move(program));
}

double Expression::evaluate(double x, double y) const { return program_->run(x, y); }
bool Expression::is_constant() const { return program_->constant; }
const std::string& Expression::text() const { return program_->text; }
const std::string& Expression::canonical() const { return program_->canonical; }

bem::ScalarField Expression::field() const {
  // The program is immutable and run() keeps its stack local, so copies of the field
  // may be evaluated concurrently.
  return [program = program_](const Vec2& p) { return program->run(p.x(), p.y()); };
}

const std::vector<std::string>& function_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& function : functions) list.emplace_back(function.name);
    return list;
  }();
  return names;
}

bool is_reserved_name(std::string_view name) {
  return name == "x" || name == "y" || name == "r" || name == "z" || name == "pi" ||
         find_function(name) != nullptr;
}

bool is_identifier(std::string_view name) {
  if (name.empty() || !is_name_start(name[0])) return false;
  return std::all_of(name.begin(), name.end(), is_name_char);
}

double evaluate_finite(const bem::ScalarField& field, const Vec2& position,
                       const SourceLocation& where) {
  const double value = field ? field(position) : 0.0;
  if (!std::isfinite(value))
    throw InputError(where, "the value is " + format_number(value) + " at (" +
                                format_number(position.x()) + ", " + format_number(position.y()) +
                                "); check the expression there (square root or logarithm of a "
                                "negative number, division by zero, ...)");
  return value;
}

}  // namespace bemcontact::io
