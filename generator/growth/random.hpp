#pragma once
// Deterministic random numbers: every stem owns streams keyed by its place in the tree, so the same seed
// gives the same stem whatever else is generated (breadth-first level invariance, Nystad 5.2.2).
#include <cstdint>

#include "common/mix64.hpp"

namespace arbor {


// Key of a child, clone or leaf from its parent's key, what it is and its index.
constexpr std::uint64_t childKey(std::uint64_t parent, std::uint64_t kind, std::uint64_t index) {
  return mix64(parent ^ mix64(kind * 0x9e3779b97f4a7c15ULL + index + 1));
}

class Rng {
 public:
  // One independent stream per (key, purpose): geometry, children, leaves, ...
  Rng(std::uint64_t key, std::uint64_t stream) : state_(mix64(key + 0x632be59bd9b4e019ULL * (stream + 1))) {}

  std::uint64_t next() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix64(state_);
  }
  // Uniform in [0, 1) with 53 random bits; no std:: distributions, whose output varies by library.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  // Uniform in [-1, 1): Weber-Penn's "value ± variation".
  double signedUnit() { return 2.0 * uniform() - 1.0; }
  double vary(double value, double variation) { return value + variation * signedUnit(); }

 private:
  std::uint64_t state_;
};

// Purposes of a stem's streams.
enum RngStream : std::uint64_t { kStreamGeometry = 0, kStreamChildren = 1, kStreamLeaves = 2, kStreamTree = 3 };
// Kinds used in childKey.
enum KeyKind : std::uint64_t { kKeyTrunk = 1, kKeyChild = 2, kKeyClone = 3 };

}  // namespace arbor
