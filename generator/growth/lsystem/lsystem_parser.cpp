// Reads .lsys grammars (docs/lsystem-format.md): one statement a line, errors at line and column.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

#include "common/input_error.hpp"
#include "common/text_util.hpp"
#include "lsystem.hpp"
#include "growth/tree_limits.hpp"

namespace arbor::lsys {

namespace {

constexpr std::size_t kMaxFormalParameters = 64;  // the derivation binds them in a fixed buffer
constexpr std::size_t kMaxArguments = 255;        // a module's parameter count is one byte

const std::vector<std::string> kKeys{"name", "n", "delta", "d", "width", "width-factor", "seed", "tropism",
                                     "axiom", "size", "tip-radius", "leaf-kind", "limit", "environment"};

bool isModuleSymbol(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 128 && std::isgraph(u) && std::string_view("()<>,:#").find(c) == std::string_view::npos;
}

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// One line being read; every error names its line and the column it points at.
struct LineReader {
  const std::string& file;
  const std::string& text;  // the line without its comment
  int line;
  std::size_t pos = 0;

  [[noreturn]] void fail(const std::string& message, std::size_t at) const {
    throw InputError(file, "line " + std::to_string(line) + ", column " + std::to_string(at + 1), message);
  }
  [[noreturn]] void fail(const std::string& message) const { fail(message, pos); }
  void skipSpace(std::size_t end) {
    while (pos < end && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
  }

  Expression expression(const std::string& source, const ExprNames& names) {
    try {
      return parseExpression(source, pos, names);
    } catch (const ExprSyntaxError& e) {
      fail(e.what(), e.column);
    }
  }

  std::string name(std::size_t end) {
    skipSpace(end);
    if (pos >= end || !isNameStart(text[pos])) fail("a name expected");
    const std::size_t start = pos;
    while (pos < end && isNameChar(text[pos])) ++pos;
    return text.substr(start, pos - start);
  }

  // Modules of a predecessor or context in [pos, end): symbols with optional (names).
  std::vector<PatternModule> patterns(std::size_t end, bool brackets) {
    std::vector<PatternModule> out;
    for (skipSpace(end); pos < end; skipSpace(end)) {
      const char c = text[pos];
      if (!isModuleSymbol(c)) fail(std::string("'") + c + "' is not a module name");
      if (!brackets && (c == '[' || c == ']')) fail("brackets are allowed in right contexts only");
      PatternModule m{c, {}};
      ++pos;
      skipSpace(end);
      if (pos < end && text[pos] == '(') {
        if (c == '[' || c == ']') fail("brackets take no parameters");
        ++pos;
        for (;;) {
          m.names.push_back(name(end));
          skipSpace(end);
          if (pos < end && text[pos] == ',') { ++pos; continue; }
          if (pos < end && text[pos] == ')') { ++pos; break; }
          fail("',' or ')' expected in a list of formal parameters");
        }
      }
      out.push_back(std::move(m));
    }
    return out;
  }

  // Modules with actual parameters from pos to the end of the line.
  std::vector<SuccessorModule> successors(const ExprNames& names) {
    std::vector<SuccessorModule> out;
    const std::size_t end = text.size();
    for (skipSpace(end); pos < end; skipSpace(end)) {
      const char c = text[pos];
      if (!isModuleSymbol(c)) fail(std::string("'") + c + "' is not a module name");
      SuccessorModule m{c, {}};
      ++pos;
      skipSpace(end);
      if (pos < end && text[pos] == '(') {
        ++pos;
        for (;;) {
          m.arguments.push_back(expression(text, names));
          skipSpace(end);
          if (pos < end && text[pos] == ',') { ++pos; continue; }
          if (pos < end && text[pos] == ')') { ++pos; break; }
          fail("',' or ')' expected after a module's argument");
        }
        if (m.arguments.size() > kMaxArguments) fail("a module takes at most 255 parameters");
      }
      out.push_back(std::move(m));
    }
    return out;
  }
};

// Where `token` first occurs in text[0, end) outside parentheses, or npos.
std::size_t findOutside(const std::string& text, const std::string& token, std::size_t end) {
  int depth = 0;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '(') ++depth;
    else if (text[i] == ')') --depth;
    else if (depth == 0 && text.compare(i, token.size(), token) == 0 && i + token.size() <= end) return i;
  }
  return std::string::npos;
}

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::string withoutSpaces(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != ' ' && c != '\t') out += c;
  return out;
}

class GrammarReader {
 public:
  explicit GrammarReader(const std::string& file) : file_(file) { system_.file = file; }

  Lsystem read(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    int line = 0;
    while (std::getline(in, raw)) {
      ++line;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      readLine(raw, line);
    }
    finish();
    return std::move(system_);
  }

 private:
  void readLine(std::string raw, int line) {
    const std::size_t first = raw.find_first_not_of(" \t");
    if (first == std::string::npos) return;
    for (const char* directive : {"#define", "#ignore"}) {
      const std::size_t n = std::char_traits<char>::length(directive);
      if (raw.compare(first, n, directive) == 0 && (raw.size() == first + n || raw[first + n] == ' ' || raw[first + n] == '\t')) {
        const std::size_t comment = raw.find('#', first + n);
        if (comment != std::string::npos) raw.resize(comment);
        LineReader r{file_, raw, line, first + n};
        return directive[1] == 'd' ? readDefine(r) : readIgnore(r);
      }
    }
    const std::size_t comment = raw.find('#');
    if (comment != std::string::npos) raw.resize(comment);
    if (trimmed(raw).empty()) return;
    LineReader r{file_, raw, line, first};
    // A header is `key: value` with a known key; every other line is a production.
    std::size_t k = first;
    while (k < raw.size() && (isNameChar(raw[k]) || raw[k] == '-')) ++k;
    const std::string key = raw.substr(first, k - first);
    std::size_t colon = k;
    while (colon < raw.size() && (raw[colon] == ' ' || raw[colon] == '\t')) ++colon;
    const bool arrow = findOutside(raw, "->", raw.size()) != std::string::npos;
    if (colon < raw.size() && raw[colon] == ':' && std::find(kKeys.begin(), kKeys.end(), key) != kKeys.end() &&
        (!arrow || key == "name")) {
      r.pos = colon + 1;
      return readHeader(r, key);
    }
    if (!arrow) {
      const std::string near = closestName(key, kKeys);
      r.fail("neither a production 'predecessor -> successor' nor a header 'key: value' (keys: name, n, delta, d, width, "
             "width-factor, seed, tropism, axiom, size, tip-radius, leaf-kind, limit, environment)" +
             (near.empty() || near == key ? std::string() : "; did you mean '" + near + ":'?"));
    }
    readProduction(r);
  }

  ExprNames constantNames() const { return {nullptr, &system_.constantNames}; }

  double number(LineReader& r, std::size_t end) {
    const std::string source = r.text.substr(0, end);
    r.skipSpace(end);
    const std::size_t at = r.pos;
    const Expression e = r.expression(source, constantNames());
    try {
      return evaluate(e, nullptr, system_.constants.data());
    } catch (const EvaluationError& error) {
      r.fail(error.what(), at);
    }
  }

  // One header value running to the end of the line.
  double wholeValue(LineReader& r) {
    const double v = number(r, r.text.size());
    r.skipSpace(r.text.size());
    if (r.pos < r.text.size()) r.fail("unexpected text after the value");
    return v;
  }

  double wholeNumber(LineReader& r, double min, double max, const std::string& key) {
    const std::size_t at = r.pos;
    const double v = wholeValue(r);
    if (v != std::floor(v) || v < min || v > max)
      r.fail(key + " is " + formatNumber(v) + "; a whole number from " + formatNumber(min) + " to " + formatNumber(max) + " is allowed", at);
    return v;
  }

  void readHeader(LineReader& r, const std::string& key) {
    if (std::find(seen_.begin(), seen_.end(), key) != seen_.end()) r.fail("'" + key + ":' is given twice", 0);
    seen_.push_back(key);
    r.skipSpace(r.text.size());
    const std::size_t at = r.pos;
    if (key == "name") {
      system_.name = trimmed(r.text.substr(r.pos));
      if (system_.name.empty()) r.fail("the name is empty");
    } else if (key == "axiom") {
      system_.axiom = r.successors(constantNames());
      if (system_.axiom.empty()) r.fail("the axiom is empty", at);
    } else if (key == "environment") {
      const std::vector<SuccessorModule> m = r.successors(constantNames());
      if (m.size() != 1 || !m[0].arguments.empty() || m[0].symbol == '[' || m[0].symbol == ']')
        r.fail("the environment is one module without parameters, not a bracket", at);
      system_.environment = m[0].symbol;
    } else if (key == "n") {
      system_.derivationLength = static_cast<int>(wholeNumber(r, 0, 1000, key));
    } else if (key == "seed") {
      system_.seed = static_cast<std::uint64_t>(wholeNumber(r, 0, 9007199254740991.0, key));
    } else if (key == "limit") {
      system_.moduleLimit = static_cast<std::size_t>(wholeNumber(r, 1, 4e9, key));
    } else if (key == "leaf-kind") {
      system_.leafKind = static_cast<int>(wholeNumber(r, 0, 3, key));
    } else if (key == "tropism") {
      double v[4];
      for (int i = 0; i < 4; ++i) {
        r.skipSpace(r.text.size());
        std::size_t end = r.pos;
        while (end < r.text.size() && r.text[end] != ' ' && r.text[end] != '\t' && r.text[end] != ',') ++end;
        if (r.pos == end) r.fail("tropism takes four numbers: the vector T and the susceptibility e");
        v[i] = number(r, end);
        r.skipSpace(r.text.size());
        if (r.pos < r.text.size() && r.text[r.pos] == ',') ++r.pos;
      }
      r.skipSpace(r.text.size());
      if (r.pos < r.text.size()) r.fail("tropism takes four numbers: the vector T and the susceptibility e");
      system_.tropism = Vec3(v[0], v[1], v[2]);
      system_.susceptibility = v[3];
      if (glm::length(system_.tropism) == 0 && v[3] != 0) r.fail("the tropism vector T is zero", at);
    } else {
      const double v = wholeValue(r);
      const auto positive = [&](double min) {
        if (!(v >= min)) r.fail(key + " is " + formatNumber(v) + "; at least " + formatNumber(min) + " is allowed", at);
      };
      if (key == "delta") system_.angle = v;
      else if (key == "d") { if (v == 0) r.fail("d is 0: the turtle would not move", at); system_.step = v; }
      else if (key == "width") positive(0), system_.width = v;
      else if (key == "width-factor") positive(0), system_.widthFactor = v;
      else if (key == "size") {
        positive(0);
        // The tree's extent: past kMaxCoordinate the mesh's float positions no longer resolve a twig.
        if (v > kMaxCoordinate) r.fail("size is " + formatNumber(v) + " m; at most " + formatNumber(kMaxCoordinate) + " m is allowed", at);
        system_.size = v;
      }
      else if (key == "tip-radius") { if (!(v > 0)) r.fail("tip-radius must be above 0", at); system_.tipRadius = v; }
    }
  }

  void readDefine(LineReader& r) {
    const std::size_t at = r.pos + 1;
    const std::string name = r.name(r.text.size());
    if (std::find(system_.constantNames.begin(), system_.constantNames.end(), name) != system_.constantNames.end())
      r.fail("'" + name + "' is defined twice", at);
    const double v = wholeValue(r);
    system_.constantNames.push_back(name);
    system_.constants.push_back(v);
  }

  void readIgnore(LineReader& r) {
    for (r.skipSpace(r.text.size()); r.pos < r.text.size(); ++r.pos, r.skipSpace(r.text.size())) {
      const char c = r.text[r.pos];
      if (!isModuleSymbol(c)) r.fail(std::string("'") + c + "' is not a module name");
      if (c == '[' || c == ']') r.fail("brackets cannot be ignored: they shape the contexts");
      system_.ignored[static_cast<unsigned char>(c)] = true;
    }
  }

  void readProduction(LineReader& r) {
    const std::string& text = r.text;
    const std::size_t arrow = findOutside(text, "->", text.size());
    const std::size_t colon = findOutside(text, ":", arrow);
    const std::size_t predEnd = colon == std::string::npos ? arrow : colon;
    const std::size_t lt = findOutside(text, "<", predEnd);
    const std::size_t gt = findOutside(text, ">", predEnd);
    if (lt != std::string::npos && gt != std::string::npos && gt < lt) r.fail("'<' must come before '>'", gt);
    Production p;
    p.line = r.line;
    if (lt != std::string::npos) {
      p.left = r.patterns(lt, false);
      r.pos = lt + 1;
    }
    const std::size_t strictStart = r.pos;
    std::vector<PatternModule> strict = r.patterns(gt == std::string::npos ? predEnd : gt, false);
    if (strict.size() != 1) r.fail("the predecessor must be exactly one module", strictStart);
    p.predecessor = std::move(strict.front());
    if (gt != std::string::npos) {
      r.pos = gt + 1;
      p.right = r.patterns(predEnd, true);
      int depth = 0;
      for (const PatternModule& m : p.right) {
        depth += m.symbol == '[' ? 1 : m.symbol == ']' ? -1 : 0;
        if (depth < 0) r.fail("the right context closes a bracket it did not open", gt + 1);
      }
    }
    std::vector<std::string> formal;
    for (const auto* list : {&p.left}) for (const PatternModule& m : *list) formal.insert(formal.end(), m.names.begin(), m.names.end());
    formal.insert(formal.end(), p.predecessor.names.begin(), p.predecessor.names.end());
    for (const PatternModule& m : p.right) formal.insert(formal.end(), m.names.begin(), m.names.end());
    if (formal.size() > kMaxFormalParameters) r.fail("a production binds at most 64 formal parameters", 0);
    p.parameterCount = formal.size();
    const ExprNames names{&formal, &system_.constantNames};
    std::string conditionText;
    if (colon != std::string::npos) {
      conditionText = withoutSpaces(text.substr(colon + 1, arrow - colon - 1));
      if (conditionText.empty()) r.fail("a condition expected after ':' (or '*' for none)", colon + 1);
      if (conditionText != "*") {
        const std::string source = text.substr(0, arrow);
        r.pos = colon + 1;
        p.condition = r.expression(source, names);
        r.skipSpace(arrow);
        if (r.pos < arrow) r.fail("unexpected text after the condition");
        p.hasCondition = true;
      }
    }
    Successor s;
    s.line = r.line;
    r.pos = arrow + 2;
    r.skipSpace(text.size());
    bool stochastic = false;
    if (r.pos < text.size() && text[r.pos] == '(') {
      ++r.pos;
      const std::size_t at = r.pos;
      const Expression e = r.expression(text, {nullptr, &system_.constantNames});
      r.skipSpace(text.size());
      if (r.pos >= text.size() || text[r.pos] != ')') r.fail("')' expected after the probability");
      ++r.pos;
      s.probability = evaluate(e, nullptr, system_.constants.data());
      if (!(s.probability >= 0 && s.probability <= 1)) r.fail("a probability is from 0 to 1, not " + formatNumber(s.probability), at);
      stochastic = true;
    }
    s.modules = r.successors(names);
    s.plain = std::all_of(s.modules.begin(), s.modules.end(), [](const SuccessorModule& m) { return m.arguments.empty(); });
    // Productions sharing predecessor, contexts and condition are one stochastic production.
    const std::string key = withoutSpaces(text.substr(0, predEnd)) + ":" + (conditionText == "*" ? "" : conditionText);
    const auto found = groups_.find(key);
    if (found != groups_.end()) {
      Production& group = system_.productions[found->second];
      if (!stochastic || !stochastic_[found->second])
        r.fail("the same predecessor, context and condition as line " + std::to_string(group.line) +
               ": give each a probability in parentheses after '->' (a stochastic production) or remove one", 0);
      group.successors.push_back(std::move(s));
      return;
    }
    p.successors.push_back(std::move(s));
    groups_[key] = system_.productions.size();
    stochastic_.push_back(stochastic);
    system_.productions.push_back(std::move(p));
  }

  void finish() {
    if (system_.axiom.empty()) throw InputError(file_, "axiom", "missing: a line 'axiom: MODULES' is required");
    if (std::find(seen_.begin(), seen_.end(), "n") == seen_.end())
      throw InputError(file_, "n", "missing: a line 'n: STEPS' (the derivation length) is required");
    for (std::size_t i = 0; i < system_.productions.size(); ++i) {
      const Production& p = system_.productions[i];
      if (!stochastic_[i]) continue;
      double sum = 0;
      std::string lines;
      for (const Successor& s : p.successors) {
        sum += s.probability;
        lines += (lines.empty() ? "" : ", ") + std::to_string(s.line);
      }
      if (std::fabs(sum - 1) > 1e-9)
        throw InputError(file_, "line " + std::to_string(p.line),
                         std::string("the probabilities of the productions for '") + p.predecessor.symbol + "' at lines " + lines +
                             " sum to " + formatNumber(sum) + ", not 1");
    }
    for (std::size_t i = 0; i < system_.productions.size(); ++i)
      system_.bySymbol[static_cast<unsigned char>(system_.productions[i].predecessor.symbol)].push_back(static_cast<std::uint32_t>(i));
  }

  std::string file_;
  Lsystem system_;
  std::vector<std::string> seen_;
  std::map<std::string, std::size_t> groups_;
  std::vector<bool> stochastic_;
};

}  // namespace

Lsystem parseLsystem(const std::string& text, const std::string& file) { return GrammarReader(file).read(text); }

}  // namespace arbor::lsys
