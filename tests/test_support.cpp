#include "test_support.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "common/atomic_file.hpp"
#include "growth/weber_penn/species_io.hpp"

namespace arbor::test {

namespace fs = std::filesystem;

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(ARBOR_ASSET_DIR) / "presets")) {
    // Weber-Penn species only: other models' presets (space colonization) are tested by their own tests.
    if (e.path().extension() != ".json") continue;
    const std::string text = readFile(e.path().string());
    if (text.find("\"model\"") == std::string::npos || text.find("\"weber-penn\"") != std::string::npos) names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

SpeciesParams loadPreset(const std::string& name) {
  return loadSpeciesFile((fs::path(ARBOR_ASSET_DIR) / "presets" / (name + ".json")).string());
}

SpeciesParams steadySpecies() {
  SpeciesParams p;
  p.name = "steady";
  p.shape = 4;
  p.levels = 3;
  p.scale = 10;
  p.baseSize = 0.3;
  p.ratio = 0.02;
  p.ratioPower = 1.2;
  p.attractionUp = 0;
  p.leaves = 6;
  p.leafScale = 0.1;
  p.leafScaleX = 0.5;
  StemLevelParams trunk;
  trunk.branches = 1;
  trunk.length = 1;
  trunk.taper = 1;
  trunk.curveRes = 5;
  StemLevelParams l1 = trunk;
  l1.branches = 12;
  l1.length = 0.4;
  l1.taper = 0.5;  // never thin enough near the tip for a child to be dropped
  l1.curveRes = 4;
  l1.curve = 20;
  l1.rotate = 140;
  l1.branchRatio = 0.3;
  l1.branchRatioGiven = true;
  StemLevelParams l2 = l1;
  l2.branches = 8;
  l2.length = 0.5;
  l2.curveRes = 3;
  l2.branchRatio = 0.4;
  l2.taper = 1.0;
  p.stemLevels = {trunk, l1, l2};
  return p;
}

double angleBetween(const Vec3& a, const Vec3& b) {
  // atan2 keeps full precision near 0 and pi, where acos of a dot product loses half the digits.
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

std::string tempPath(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("arbor-tests-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

std::vector<std::string> arbaroSpeciesFiles(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    WARN("Arbaro's species files are not beside this checkout (" << dir << "); skipped");
    return files;
  }
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".xml") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

CommandResult runCommand(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed: " + command);
  CommandResult r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace arbor::test
