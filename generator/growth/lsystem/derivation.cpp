#include "derivation.hpp"

#include <limits>

#include "common/input_error.hpp"

namespace arbor::lsys {

namespace {

constexpr std::uint32_t kNoPartner = std::numeric_limits<std::uint32_t>::max();

// Index of each bracket's partner (kNoPartner for the others and unbalanced ones), so that contexts skip
// whole branches in one jump.
std::vector<std::uint32_t> bracketPartners(const ModuleString& s) {
  std::vector<std::uint32_t> partner(s.size(), kNoPartner), open;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    const char c = s.modules[i].symbol;
    if (c == '[') {
      open.push_back(i);
    } else if (c == ']' && !open.empty()) {
      partner[i] = open.back();
      partner[open.back()] = i;
      open.pop_back();
    }
  }
  return partner;
}

// Matches one production's contexts around a module of `str`, binding formal parameters into `bound`.
class ContextMatcher {
 public:
  ContextMatcher(const Lsystem& system, const ModuleString& str, const std::vector<std::uint32_t>& partner)
      : system_(system), str_(str), partner_(partner) {}

  // Left context: the nearest earlier modules on the path to the root (closed branches and ignored modules
  // skipped; an opening bracket leads to the parent axis). `slot` is where the left context's parameters begin.
  bool left(const Production& p, std::size_t i, double* bound) const {
    std::size_t slot = 0;
    for (const PatternModule& m : p.left) slot += m.names.size();
    std::ptrdiff_t j = static_cast<std::ptrdiff_t>(i) - 1;
    for (std::size_t k = p.left.size(); k-- > 0;) {
      for (;; --j) {
        if (j < 0) return k == 0 && atBoundary(p.left[0]);  // the invisible boundary at the start
        const Module& m = str_.modules[static_cast<std::size_t>(j)];
        if (m.symbol == ']') {
          if (partner_[static_cast<std::size_t>(j)] == kNoPartner) return false;
          j = partner_[static_cast<std::size_t>(j)];
          continue;
        }
        if (m.symbol != '[' && !ignored(m.symbol)) break;
      }
      const PatternModule& pattern = p.left[k];
      slot -= pattern.names.size();
      if (!bind(pattern, str_.modules[static_cast<std::size_t>(j)], bound + slot)) return false;
      --j;
    }
    return true;
  }

  // Right context: the next modules on the same axis (sub-branches and ignored modules skipped); a '[' of
  // the pattern enters the branch starting there and its ']' skips the rest of that branch.
  bool right(const Production& p, std::size_t i, double* bound) const {
    std::size_t j = i + 1;
    std::uint32_t opened[64];
    std::size_t depth = 0;
    for (std::size_t k = 0; k < p.right.size(); ++k) {
      const PatternModule& pattern = p.right[k];
      const bool last = k + 1 == p.right.size();
      if (pattern.symbol == ']') {
        const std::uint32_t end = partner_[opened[--depth]];
        if (end == kNoPartner) return false;
        j = end + 1;
        continue;
      }
      for (;; ++j) {
        if (j >= str_.size()) return last && atBoundary(pattern);  // the invisible boundary at the end
        const char c = str_.modules[j].symbol;
        if (pattern.symbol == '[' && c == '[') break;
        if (c == '[') {
          if (partner_[j] == kNoPartner) return false;
          j = partner_[j];
          continue;
        }
        if (c == ']') return last && atBoundary(pattern);  // the axis ends here, at the boundary too
        if (!ignored(c)) break;
      }
      if (pattern.symbol == '[') {
        if (depth == 64) return false;
        opened[depth++] = static_cast<std::uint32_t>(j++);
        continue;
      }
      if (!bind(pattern, str_.modules[j], bound)) return false;
      bound += pattern.names.size();
      ++j;
    }
    return true;
  }

 private:
  // Whether the boundary (string ends, branch ends) reads as this pattern: the grammar's environment module.
  bool atBoundary(const PatternModule& pattern) const {
    return system_.environment != 0 && pattern.symbol == system_.environment && pattern.names.empty();
  }

  bool ignored(char c) const { return system_.ignored[static_cast<unsigned char>(c)]; }

  bool bind(const PatternModule& pattern, const Module& m, double* bound) const {
    if (m.symbol != pattern.symbol || m.count != pattern.names.size()) return false;
    const double* values = str_.parametersOf(m);
    for (std::uint8_t k = 0; k < m.count; ++k) bound[k] = values[k];
    return true;
  }

  const Lsystem& system_;
  const ModuleString& str_;
  const std::vector<std::uint32_t>& partner_;
};

[[noreturn]] void limitPassed(int step, std::size_t limit) {
  throw LimitError("derivation step " + std::to_string(step) + " would pass the limit of " + std::to_string(limit) +
                   " modules (lower n or the productions' growth, or raise 'limit:')");
}

// A uniform number in [0, 1) from 53 random bits: the same sequence on every platform.
double uniform(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

}  // namespace

ModuleString axiomString(const Lsystem& system) {
  ModuleString out;
  for (const SuccessorModule& m : system.axiom) {
    out.modules.push_back({m.symbol, static_cast<std::uint8_t>(m.arguments.size()), static_cast<std::uint32_t>(out.parameters.size())});
    for (const Expression& e : m.arguments) {
      try {
        out.parameters.push_back(evaluate(e, nullptr, system.constants.data()));
      } catch (const EvaluationError& error) {
        throw InputError(system.file, "axiom", error.what());
      }
    }
  }
  return out;
}

ModuleString deriveStep(const Lsystem& system, const ModuleString& current, std::mt19937_64& random, int step,
                        std::size_t moduleLimit) {
  bool contexts = false;
  for (const Production& p : system.productions) contexts = contexts || !p.contextFree();
  const std::vector<std::uint32_t> partner = contexts ? bracketPartners(current) : std::vector<std::uint32_t>{};
  const ContextMatcher matcher(system, current, partner);
  const double* constants = system.constants.data();
  constexpr std::size_t kParameterLimit = std::numeric_limits<std::uint32_t>::max() - 256;

  ModuleString out;
  out.modules.reserve(std::min(moduleLimit, current.size() + current.size() / 2));
  double bound[64];
  for (std::size_t i = 0; i < current.size(); ++i) {
    const Module& module = current.modules[i];
    const Successor* chosen = nullptr;
    const Production* applied = nullptr;
    for (const std::uint32_t index : system.bySymbol[static_cast<unsigned char>(module.symbol)]) {
      const Production& p = system.productions[index];
      if (module.count != p.predecessor.names.size()) continue;
      if (!p.left.empty() && !matcher.left(p, i, bound)) continue;
      std::size_t leftCount = 0;
      for (const PatternModule& m : p.left) leftCount += m.names.size();
      const double* values = current.parametersOf(module);
      for (std::uint8_t k = 0; k < module.count; ++k) bound[leftCount + k] = values[k];
      if (!p.right.empty() && !matcher.right(p, i, bound + leftCount + module.count)) continue;
      try {
        if (p.hasCondition && evaluate(p.condition, bound, constants) == 0) continue;
      } catch (const EvaluationError& e) {
        throw InputError(system.file, "line " + std::to_string(p.line),
                         "derivation step " + std::to_string(step) + ", the condition of the production for '" +
                             p.predecessor.symbol + "': " + e.what());
      }
      applied = &p;
      chosen = &p.successors.front();
      if (p.successors.size() > 1) {
        double u = uniform(random);
        for (const Successor& s : p.successors) {
          chosen = &s;
          if (u < s.probability) break;
          u -= s.probability;
        }
      }
      break;
    }
    if (!chosen) {  // no production applies: the module stays (identity production)
      if (out.size() + 1 > moduleLimit) limitPassed(step, moduleLimit);
      out.modules.push_back({module.symbol, module.count, static_cast<std::uint32_t>(out.parameters.size())});
      if (module.count) {
        if (out.parameters.size() > kParameterLimit) limitPassed(step, moduleLimit);
        const double* values = current.parametersOf(module);
        out.parameters.insert(out.parameters.end(), values, values + module.count);
      }
      continue;
    }
    if (out.size() + chosen->modules.size() > moduleLimit) limitPassed(step, moduleLimit);
    if (chosen->plain) {
      const auto first = static_cast<std::uint32_t>(out.parameters.size());
      for (const SuccessorModule& m : chosen->modules) out.modules.push_back({m.symbol, 0, first});
      continue;
    }
    if (out.parameters.size() > kParameterLimit) limitPassed(step, moduleLimit);
    try {
      for (const SuccessorModule& m : chosen->modules) {
        out.modules.push_back({m.symbol, static_cast<std::uint8_t>(m.arguments.size()), static_cast<std::uint32_t>(out.parameters.size())});
        for (const Expression& e : m.arguments) out.parameters.push_back(evaluate(e, bound, constants));
      }
    } catch (const EvaluationError& e) {
      throw InputError(system.file, "line " + std::to_string(chosen->line),
                       "derivation step " + std::to_string(step) + ", the successor of the production for '" +
                           applied->predecessor.symbol + "': " + e.what());
    }
  }
  return out;
}

ModuleString derive(const Lsystem& system, const DeriveOptions& options) {
  const std::size_t limit = options.moduleLimit.value_or(system.moduleLimit);
  std::mt19937_64 random(options.seed.value_or(system.seed));
  ModuleString str = axiomString(system);
  if (str.size() > limit) limitPassed(0, limit);
  const int steps = options.steps.value_or(system.derivationLength);
  for (int step = 1; step <= steps; ++step) str = deriveStep(system, str, random, step, limit);
  return str;
}

}  // namespace arbor::lsys
