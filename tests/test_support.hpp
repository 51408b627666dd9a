#pragma once
// Shared helpers for the tests: presets, a variation-free species, angles between directions.
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "growth/math.hpp"
#include "growth/weber_penn/species.hpp"

namespace arbor::test {

std::vector<std::string> presetNames();
SpeciesParams loadPreset(const std::string& name);

// A small three-level species with every random variation zero, for exact-count tests.
SpeciesParams steadySpecies();

double angleBetween(const Vec3& a, const Vec3& b);  // radians

std::string tempPath(const std::string& name);

// The message of the InputError `work` throws ("" if it throws none).
template <class Work>
std::string refusal(Work&& work) {
  try {
    work();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}  // in a per-run scratch directory

// The Arbaro species files (*.xml) in `dir`, sorted; empty, with a warning in the test's report, when the
// folder is not there (a checkout without ../shared: the callers skip).
std::vector<std::string> arbaroSpeciesFiles(const std::string& dir);

// A shell command's exit status and what it printed (add 2>&1 to the command for stderr too).
struct CommandResult {
  int exitCode = -1;  // -1: it did not exit normally (killed by a signal)
  std::string output;
};
CommandResult runCommand(const std::string& command);

}  // namespace arbor::test
