#pragma once
// Arithmetic expressions of parametric L-systems (ABOP ch. 1.10), compiled once to postfix code and
// evaluated per module during derivation: numbers, #define constants, formal parameters, + - * / ^,
// comparisons, && || !, and cpfg's functions (trigonometry in degrees).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace arbor::lsys {

enum class ExprOp : std::uint8_t {
  Number, Parameter, Constant, Negate, Not, Add, Subtract, Multiply, Divide, Power,
  Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual, And, Or, Function
};

enum class ExprFunction : std::uint8_t { Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Exp, Log, Abs, Floor, Ceil, Min, Max };

struct ExprInstruction {
  ExprOp op = ExprOp::Number;
  ExprFunction function = ExprFunction::Sin;
  std::uint32_t index = 0;  // parameter or constant slot
  double value = 0;         // the number of a Number
};

struct Expression {
  std::vector<ExprInstruction> code;  // postfix
  bool usesParameters = false;
};

// A value that cannot be computed (division by zero, a result that is not finite); the derivation names
// the production it came from.
class EvaluationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws EvaluationError on division by zero or a non-finite result.
double evaluate(const Expression& expression, const double* parameters, const double* constants);

// Names an expression may use while it is parsed: formal parameters (slot = position) and constants.
struct ExprNames {
  const std::vector<std::string>* parameters = nullptr;
  const std::vector<std::string>* constants = nullptr;
};

// An expression that does not parse or names something unknown: `column` is 0-based in the parsed text.
class ExprSyntaxError : public std::runtime_error {
 public:
  ExprSyntaxError(std::size_t at, const std::string& message) : std::runtime_error(message), column(at) {}
  std::size_t column;
};

// Parses text[pos, end) from `pos`, stopping before the first character at depth 0 that cannot continue the
// expression (',' or ')' of the enclosing list); `pos` is left there.
Expression parseExpression(const std::string& text, std::size_t& pos, const ExprNames& names);

}  // namespace arbor::lsys
