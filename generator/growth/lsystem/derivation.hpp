#pragma once
// Derivation: n steps of parallel rewriting (ABOP 1.1), with bracket-aware contexts (1.8), stochastic
// choice from a seeded generator (1.7) and parametric conditions (1.10).
#include <cstdint>
#include <optional>
#include <random>

#include "lsystem.hpp"

namespace arbor::lsys {

struct DeriveOptions {
  std::optional<int> steps;               // default: the grammar's n
  std::optional<std::uint64_t> seed;      // default: the grammar's seed
  std::optional<std::size_t> moduleLimit; // default: the grammar's limit
};

// The axiom with its arguments evaluated (L(0)).
ModuleString axiomString(const Lsystem& system);

// One derivation step from `current`; `random` draws the stochastic choices. Throws LimitError naming `step`
// before the result passes `moduleLimit`, InputError naming the production's line when an expression
// cannot be evaluated.
ModuleString deriveStep(const Lsystem& system, const ModuleString& current, std::mt19937_64& random, int step,
                        std::size_t moduleLimit);

// L(n): the axiom rewritten n times.
ModuleString derive(const Lsystem& system, const DeriveOptions& options = {});

}  // namespace arbor::lsys
