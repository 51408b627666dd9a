#pragma once
// A Lindenmayer system as read from a .lsys file (docs/lsystem-format.md): axiom, productions (context-
// sensitive, stochastic, parametric with conditions, as in ABOP ch. 1-2) and the turtle's settings.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "expression.hpp"
#include "growth/math.hpp"

namespace arbor::lsys {

// A string of modules, stored compactly: per module its symbol and where its parameters start in one flat
// array (8 bytes a module plus 8 a parameter), so that tens of millions fit and copy fast.
struct Module {
  char symbol = 0;
  std::uint8_t count = 0;   // parameters
  std::uint32_t first = 0;  // index of the first parameter in ModuleString::parameters
};

struct ModuleString {
  std::vector<Module> modules;
  std::vector<double> parameters;

  std::size_t size() const { return modules.size(); }
  const double* parametersOf(const Module& m) const { return parameters.data() + m.first; }
  void push(char symbol) { modules.push_back({symbol, 0, static_cast<std::uint32_t>(parameters.size())}); }
  void push(char symbol, std::initializer_list<double> values);
  // As written in a grammar: "F(1,2.5)[+F]" (numbers as formatNumber writes them), no spaces.
  std::string text() const;
};

// A module of a predecessor or context: its symbol and the names of its formal parameters.
struct PatternModule {
  char symbol = 0;
  std::vector<std::string> names;
};

// A module of a successor: its symbol and one expression per actual parameter.
struct SuccessorModule {
  char symbol = 0;
  std::vector<Expression> arguments;
};

struct Successor {
  double probability = 1;
  int line = 0;
  std::vector<SuccessorModule> modules;
  bool plain = false;  // no module has arguments: copied without evaluating anything
};

// One production, or several sharing predecessor, contexts and condition (a stochastic choice among
// their successors, ABOP 1.7). Formal parameters are numbered left context, predecessor, right context.
struct Production {
  int line = 0;
  std::vector<PatternModule> left;   // in string order; the module nearest the predecessor is last
  PatternModule predecessor;
  std::vector<PatternModule> right;  // may hold '[' and ']' (ABOP's bracketed right contexts)
  bool hasCondition = false;
  Expression condition;
  std::vector<Successor> successors;
  std::size_t parameterCount = 0;
  bool contextFree() const { return left.empty() && right.empty(); }
};

struct Lsystem {
  std::string name;   // the `name:` line, else the file's stem
  std::string file;   // for messages
  std::vector<std::string> constantNames;  // #define, in file order
  std::vector<double> constants;
  std::array<bool, 256> ignored{};         // #ignore: skipped when matching contexts
  char environment = 0;                    // what the invisible boundary reads as in contexts (0: nothing)
  int derivationLength = 0;                // n
  double angle = 90;                       // delta, degrees
  double step = 1;                         // d
  double width = 0;                        // > 0: the initial width; 0: none (the pipe model decides radii)
  double widthFactor = 0.707;              // what '!' without an argument multiplies the width by
  std::uint64_t seed = 1;
  Vec3 tropism{0.0};                       // T
  double susceptibility = 0;               // e
  double size = 0;                         // > 0: the tree is scaled so its height is this many metres
  double tipRadius = 0.01;                 // the pipe model's tip radius, in metres after scaling
  int leafKind = 0;                        // LeafKind of the polygons' leaves
  std::size_t moduleLimit = 50'000'000;
  std::vector<SuccessorModule> axiom;      // arguments from constants only
  std::vector<Production> productions;     // in file order (a group at its first line)
  std::array<std::vector<std::uint32_t>, 256> bySymbol{};  // production indices per predecessor symbol
};

// Reads a grammar; syntax errors name the line and column, other errors the line (InputError, exit 2).
Lsystem parseLsystem(const std::string& text, const std::string& file);

}  // namespace arbor::lsys
