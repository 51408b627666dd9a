#include "expression.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "growth/math.hpp"

namespace arbor::lsys {

namespace {

constexpr std::size_t kMaxStack = 64;

struct FunctionName {
  const char* name;
  ExprFunction function;
  int arity;
};

constexpr std::array<FunctionName, 14> kFunctions{{
    {"sin", ExprFunction::Sin, 1},   {"cos", ExprFunction::Cos, 1},     {"tan", ExprFunction::Tan, 1},
    {"asin", ExprFunction::Asin, 1}, {"acos", ExprFunction::Acos, 1},   {"atan", ExprFunction::Atan, 1},
    {"sqrt", ExprFunction::Sqrt, 1}, {"exp", ExprFunction::Exp, 1},     {"log", ExprFunction::Log, 1},
    {"abs", ExprFunction::Abs, 1},   {"floor", ExprFunction::Floor, 1}, {"ceil", ExprFunction::Ceil, 1},
    {"min", ExprFunction::Min, 2},   {"max", ExprFunction::Max, 2},
}};

int arityOf(ExprFunction f) { return f == ExprFunction::Min || f == ExprFunction::Max ? 2 : 1; }

double apply(ExprFunction f, double a, double b) {
  switch (f) {
    case ExprFunction::Sin: return std::sin(radians(a));
    case ExprFunction::Cos: return std::cos(radians(a));
    case ExprFunction::Tan: return std::tan(radians(a));
    case ExprFunction::Asin: return degrees(std::asin(a));
    case ExprFunction::Acos: return degrees(std::acos(a));
    case ExprFunction::Atan: return degrees(std::atan(a));
    case ExprFunction::Sqrt: return std::sqrt(a);
    case ExprFunction::Exp: return std::exp(a);
    case ExprFunction::Log: return std::log(a);
    case ExprFunction::Abs: return std::fabs(a);
    case ExprFunction::Floor: return std::floor(a);
    case ExprFunction::Ceil: return std::ceil(a);
    case ExprFunction::Min: return std::min(a, b);
    case ExprFunction::Max: return std::max(a, b);
  }
  return 0;
}

// Recursive descent, lowest precedence first: || && (== !=) (< <= > >=) (+ -) (* /) unary (- !) ^ atom.
class Parser {
 public:
  Parser(const std::string& text, std::size_t& pos, const ExprNames& names) : text_(text), pos_(pos), names_(names) {}

  Expression parse() {
    skipSpace();
    if (atEnd()) fail("an expression is missing");
    parseOr();
    return std::move(out_);
  }

 private:
  bool atEnd() const { return pos_ >= text_.size(); }
  char peek(std::size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  void skipSpace() {
    while (!atEnd() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  [[noreturn]] void fail(const std::string& message) const { throw ExprSyntaxError(pos_, message); }
  void emit(ExprOp op) { out_.code.push_back({op, ExprFunction::Sin, 0, 0}); }

  // Consumes `token` (after spaces) when it is next.
  bool accept(const char* token) {
    skipSpace();
    const std::size_t n = std::char_traits<char>::length(token);
    if (text_.compare(pos_, n, token) != 0) return false;
    pos_ += n;
    return true;
  }

  void parseOr() {
    parseAnd();
    while (accept("||")) parseAnd(), emit(ExprOp::Or);
  }
  void parseAnd() {
    parseEquality();
    while (accept("&&")) parseEquality(), emit(ExprOp::And);
  }
  void parseEquality() {
    parseRelation();
    for (;;) {
      if (accept("==")) parseRelation(), emit(ExprOp::Equal);
      else if (accept("!=")) parseRelation(), emit(ExprOp::NotEqual);
      else return;
    }
  }
  void parseRelation() {
    parseSum();
    for (;;) {
      if (accept("<=")) parseSum(), emit(ExprOp::LessEqual);
      else if (accept(">=")) parseSum(), emit(ExprOp::GreaterEqual);
      else if (accept("<")) parseSum(), emit(ExprOp::Less);
      else if (accept(">")) parseSum(), emit(ExprOp::Greater);
      else return;
    }
  }
  void parseSum() {
    parseProduct();
    for (;;) {
      if (accept("+")) parseProduct(), emit(ExprOp::Add);
      else if (accept("-")) parseProduct(), emit(ExprOp::Subtract);
      else return;
    }
  }
  void parseProduct() {
    parseUnary();
    for (;;) {
      if (accept("*")) parseUnary(), emit(ExprOp::Multiply);
      else if (accept("/")) parseUnary(), emit(ExprOp::Divide);
      else return;
    }
  }
  // Nesting is bounded so that a hostile line cannot exhaust the call stack.
  struct Nest {
    Parser& p;
    explicit Nest(Parser& parser) : p(parser) {
      if (++p.depth_ > 100) p.fail("an expression nests deeper than 100 levels");
    }
    ~Nest() { --p.depth_; }
  };

  void parseUnary() {
    const Nest nest(*this);
    if (accept("-")) return parseUnary(), emit(ExprOp::Negate);
    skipSpace();
    if (peek() == '!' && peek(1) != '=') {
      ++pos_;
      return parseUnary(), emit(ExprOp::Not);
    }
    parsePower();
  }
  void parsePower() {
    parseAtom();
    if (accept("^")) parseUnary(), emit(ExprOp::Power);  // right-associative; 2^-1 allowed
  }
  void parseAtom() {
    skipSpace();
    if (atEnd()) fail("an expression ends too early");
    const char c = peek();
    if (c == '(') {
      ++pos_;
      parseOr();
      if (!accept(")")) fail("')' expected");
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return parseNumber();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return parseName();
    fail(std::string("unexpected '") + c + "' in an expression");
  }
  void parseNumber() {
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin) fail("a number expected");
    pos_ += static_cast<std::size_t>(end - begin);
    out_.code.push_back({ExprOp::Number, ExprFunction::Sin, 0, value});
  }
  void parseName() {
    const std::size_t start = pos_;
    while (!atEnd() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_')) ++pos_;
    const std::string name = text_.substr(start, pos_ - start);
    if (names_.parameters) {
      const auto& p = *names_.parameters;
      const auto it = std::find(p.rbegin(), p.rend(), name);  // the last binding of a name wins
      if (it != p.rend()) {
        out_.code.push_back({ExprOp::Parameter, ExprFunction::Sin, static_cast<std::uint32_t>(p.rend() - it - 1), 0});
        out_.usesParameters = true;
        return;
      }
    }
    if (names_.constants) {
      const auto& k = *names_.constants;
      const auto it = std::find(k.begin(), k.end(), name);
      if (it != k.end()) {
        out_.code.push_back({ExprOp::Constant, ExprFunction::Sin, static_cast<std::uint32_t>(it - k.begin()), 0});
        return;
      }
    }
    for (const FunctionName& f : kFunctions) {
      if (name != f.name) continue;
      if (!accept("(")) fail(name + " is a function: '(' expected");
      for (int a = 0; a < f.arity; ++a) {
        if (a > 0 && !accept(",")) fail(name + " takes " + std::to_string(f.arity) + " arguments: ',' expected");
        parseOr();
      }
      if (!accept(")")) fail(name + " takes " + std::to_string(f.arity) + " argument(s): ')' expected");
      out_.code.push_back({ExprOp::Function, f.function, 0, 0});
      return;
    }
    pos_ = start;
    fail("undefined name '" + name + "' (not a parameter of the predecessor, a #define constant or a function)");
  }

  const std::string& text_;
  std::size_t& pos_;
  const ExprNames& names_;
  Expression out_;
  int depth_ = 0;
};

// The most values evaluate() holds at once.
std::size_t stackDepth(const Expression& e) {
  std::size_t depth = 0, most = 0;
  for (const ExprInstruction& in : e.code) {
    switch (in.op) {
      case ExprOp::Number: case ExprOp::Parameter: case ExprOp::Constant: ++depth; break;
      case ExprOp::Negate: case ExprOp::Not: break;
      case ExprOp::Function: depth -= arityOf(in.function) - 1; break;
      default: --depth; break;
    }
    most = std::max(most, depth);
  }
  return most;
}

}  // namespace

Expression parseExpression(const std::string& text, std::size_t& pos, const ExprNames& names) {
  const std::size_t start = pos;
  Expression e = Parser(text, pos, names).parse();
  if (stackDepth(e) > kMaxStack) throw ExprSyntaxError(start, "the expression is too deep to evaluate");
  return e;
}

double evaluate(const Expression& expression, const double* parameters, const double* constants) {
  double stack[kMaxStack];  // deeper expressions are refused while parsing
  std::size_t top = 0;
  for (const ExprInstruction& in : expression.code) {
    switch (in.op) {
      case ExprOp::Number: stack[top++] = in.value; continue;
      case ExprOp::Parameter: stack[top++] = parameters[in.index]; continue;
      case ExprOp::Constant: stack[top++] = constants[in.index]; continue;
      case ExprOp::Negate: stack[top - 1] = -stack[top - 1]; continue;
      case ExprOp::Not: stack[top - 1] = stack[top - 1] == 0 ? 1 : 0; continue;
      case ExprOp::Function:
        if (arityOf(in.function) == 2) {
          --top;
          stack[top - 1] = apply(in.function, stack[top - 1], stack[top]);
        } else {
          stack[top - 1] = apply(in.function, stack[top - 1], 0);
        }
        if (!std::isfinite(stack[top - 1])) throw EvaluationError("a function's result is not a finite number");
        continue;
      default: break;
    }
    const double b = stack[--top];
    double& a = stack[top - 1];
    switch (in.op) {
      case ExprOp::Add: a += b; break;
      case ExprOp::Subtract: a -= b; break;
      case ExprOp::Multiply: a *= b; break;
      case ExprOp::Divide:
        if (b == 0) throw EvaluationError("division by zero");
        a /= b;
        break;
      case ExprOp::Power: a = std::pow(a, b); break;
      case ExprOp::Less: a = a < b; break;
      case ExprOp::LessEqual: a = a <= b; break;
      case ExprOp::Greater: a = a > b; break;
      case ExprOp::GreaterEqual: a = a >= b; break;
      case ExprOp::Equal: a = a == b; break;
      case ExprOp::NotEqual: a = a != b; break;
      case ExprOp::And: a = (a != 0) && (b != 0); break;
      case ExprOp::Or: a = (a != 0) || (b != 0); break;
      default: break;
    }
    if (!std::isfinite(a)) throw EvaluationError("the result is not a finite number");
  }
  return stack[0];
}

}  // namespace arbor::lsys
