// arbor textures: write the procedural bark maps (colour and height) the renderer samples on stems.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli_values.hpp"
#include "commands.hpp"
#include "image/bark_texture.hpp"
#include "image/leaf_atlas.hpp"
#include "common/input_error.hpp"

namespace arbor::cli {

namespace {

struct TexturesOptions {
  int size = 512;
  std::uint32_t seed = 1;
  std::string out;
};

constexpr int kMinSize = 64, kMaxSize = 4096;

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

int runTextures(const TexturesOptions& o) {
  // Powers of two so the renderer can build a full mip chain; bounded so a typo cannot fill the disk.
  if (!isPowerOfTwo(o.size) || o.size < kMinSize || o.size > kMaxSize) {
    throw InputError("arbor textures", "--size",
                       std::to_string(o.size) + " is not allowed; allowed: a power of two from " +
                           std::to_string(kMinSize) + " to " + std::to_string(kMaxSize));
  }
  requireOutputFolder(o.out);
  namespace fs = std::filesystem;
  const fs::path dir(o.out);
  std::error_code error;
  if (fs::exists(dir, error) && !fs::is_directory(dir, error)) {
    throw InputError(o.out, "--out", "exists and is not a directory");
  }
  fs::create_directories(dir, error);
  if (error) throw std::runtime_error(o.out + ": cannot create the directory (" + error.message() + ")");

  const auto t0 = std::chrono::steady_clock::now();
  const BarkTextures maps = makeBarkTextures(o.size, o.seed);
  const Image leaves = makeLeafAtlas(o.size, o.seed);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const std::string colorPath = (dir / "bark_color.png").string(), heightPath = (dir / "bark_height.png").string();
  const std::string leafPath = (dir / "leaf_atlas.png").string(), normalPath = (dir / "bark_normal.png").string();
  writePng(colorPath, maps.color);
  writePng(heightPath, maps.height);
  writePng(normalPath, maps.normal);
  writePng(leafPath, leaves);
  std::printf("bark and leaves %d x %d, seed %u: generated in %.0f ms\nwrote %s\nwrote %s\nwrote %s\nwrote %s\n", o.size, o.size,
              o.seed, ms, colorPath.c_str(), heightPath.c_str(), normalPath.c_str(), leafPath.c_str());
  return 0;
}

}  // namespace

void addTexturesCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<TexturesOptions>();
  CLI::App* cmd = app.add_subcommand("textures", "Write the procedural textures: bark colour and height maps (tileable) and the leaf atlas (PNG).");
  cmd->add_option("--size", o->size, "Width and height in pixels: a power of two from 64 to 4096")->capture_default_str();
  cmd->add_option("--seed", o->seed, "Random seed; the same size and seed give byte-identical files")->check(Whole(0, 4294967295LL))->capture_default_str();
  cmd->add_option("--out", o->out, "Directory for bark_color.png, bark_height.png, bark_normal.png and leaf_atlas.png (created if missing)")->required();
  cmd->callback([o, &action] { action = [o] { return runTextures(*o); }; });
}

}  // namespace arbor::cli
