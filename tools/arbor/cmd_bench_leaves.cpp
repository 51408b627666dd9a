// arbor bench leaves: frame time against the number of leaves drawn, with and without self-shadowing, over
// the ACC-tessellated tree (Nystad 6.5: 50,000 leaves with 250-leaf self-shadowing).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <fstream>
#include <memory>

#include "assets.hpp"
#include "bench_support.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "growth/growth_model.hpp"
#include "tree/build_tree.hpp"
#include "mesh/tree_mesh.hpp"
#include "render_options.hpp"

namespace arbor::cli {

namespace {

struct BenchLeavesOptions {
  AngleChoice angles = AngleChoice::File;
  std::string species = "quaking-aspen";
  std::uint64_t seed = 1;
  std::string counts = "10000,50000,200000";
  std::string shadows = "0,250";
  std::string mode = "acc";
  float tess = 4.0f;
  std::string size = "1920x1080";
  int frames = 5;
  std::string device;
  bool validation = false;
  std::string csv;
};

int runBenchLeaves(const BenchLeavesOptions& o) {
  std::uint32_t width = 0, height = 0;
  parseSize(o.size, width, height);
  std::vector<std::uint32_t> counts, shadows;
  for (float c : parseNumbers(o.counts, "--counts", 1.0f, 4.0e6f)) counts.push_back(static_cast<std::uint32_t>(c));
  for (float c : parseNumbers(o.shadows, "--shadow-leaves", 0.0f, 4096.0f)) shadows.push_back(static_cast<std::uint32_t>(c));
  if (counts.empty()) throw InputError(o.counts, "--counts", "give at least one leaf count");
  if (shadows.empty()) shadows.push_back(0);
  render::RenderSettings base;
  base.mode = parseMode(o.mode, "--mode");
  base.tessLevel = o.tess;
  base.leaves = true;
  if (!o.csv.empty()) requireOutputFile(o.csv, "--csv");
  // Rows are collected and the file written whole at the end: a refused or interrupted run leaves an old CSV alone.
  std::ostringstream csv;
  csv << "leaves,shadow_leaves,triangles,cpu_ms_median,cpu_ms_min,cpu_ms_max,gpu_ms_median,gpu_ms_min,gpu_ms_max,fps\n";

  // The mesh keeps the species' levels; more levels are grown (the same tree below, breadth-first) until the
  // deepest carries enough leaves for the largest count.
  const TreeSource source = loadTreeArgument(o.species, nullptr, o.angles);
  const std::uint32_t most = *std::max_element(counts.begin(), counts.end());
  GrowthOptions growth;
  growth.seed = o.seed;
  growth.levels = source.levels();
  Skeleton skeleton = source.grow(growth);
  // Deeper levels are not always leafier (children that run out of wood are not grown): keep the leafiest.
  int leafiestLevels = growth.levels;
  while (skeleton.leaves.size() < most && growth.levels < 8) {
    std::fprintf(stderr, "arbor bench leaves: %zu leaves at %d levels; growing one more\n", skeleton.leaves.size(), growth.levels);
    ++growth.levels;
    Skeleton deeper;
    try {
      deeper = source.grow(growth);
    } catch (const GenerationError& e) {
      std::fprintf(stderr, "arbor bench leaves: not at %d levels: %s\n", growth.levels, e.what());
      break;
    }
    if (deeper.leaves.size() > skeleton.leaves.size()) {
      skeleton = std::move(deeper);
      leafiestLevels = growth.levels;
    }
  }
  growth.levels = leafiestLevels;
  if (skeleton.leaves.size() < most) {
    throw InputError(std::to_string(most), "--counts", o.species + " grows at most " + std::to_string(skeleton.leaves.size()) +
                                                           " leaves (at " + std::to_string(leafiestLevels) + " levels); give counts up to that");
  }
  // The tree's own levels meshed; the deeper ones grown for their leaves are not drawn as fake branches here.
  BuildOptions build;
  build.mesh.levels = source.levels();
  const TreeGeometry built = buildTree(skeleton, build);
  const TreeMesh& tree = built.mesh;
  const PatchSet& patches = built.patches;

  vk::VulkanContext context(vulkanOptions(o.validation, o.device));
  render::RenderSession session(context, width, height, VK_SAMPLE_COUNT_1_BIT, render::loadTreeTextures(assetDirectory()));
  session.setTree(tree.mesh, patches, skeleton.leaves);
  const render::Camera camera = render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f,
                                                    static_cast<float>(width) / static_cast<float>(height));
  const bool hostTimed = context.isLavapipe();  // its timestamps miss the deferred rasterisation

  std::printf("%s: %zu quads (%s, factor %g), %zu leaves grown at %d levels; %ux%u on %s, %d frames per row after one warm-up%s\n\n",
              source.name().c_str(), tree.mesh.quads.size(), render::renderModeName(base.mode), static_cast<double>(base.tessLevel),
              skeleton.leaves.size(), growth.levels, width, height, context.deviceDescription().c_str(), o.frames,
              context.validationEnabled() ? ", validation on" : "");
  std::printf("| leaves | self-shadowing | triangles | CPU frame ms (min-max) | GPU frame ms (min-max) | frames/s |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  std::size_t row = 0;
  const std::size_t rows = counts.size() * shadows.size() + 1;
  auto measure = [&](std::uint32_t count, std::uint32_t shadowLeaves) {
    std::fprintf(stderr, "arbor bench leaves: [%zu/%zu] %u leaves, %u shadow leaves\n", ++row, rows, count, shadowLeaves);
    render::RenderSettings s = base;
    s.leaves = count > 0;
    s.leafDensity = static_cast<float>(static_cast<double>(count) / static_cast<double>(skeleton.leaves.size()));
    s.shadowLeaves = shadowLeaves;
    const TimedFrames t = timeFrames(session, camera, s, o.frames);
    const double ms = hostTimed || !t.hasGpu ? t.cpu.median : t.gpu.median;
    const double fps = ms > 0.0 ? 1000.0 / ms : 0.0;
    std::printf("| %u | %s | %llu | %.2f (%.2f-%.2f) | ", count, shadowLeaves > 0 ? std::to_string(shadowLeaves).c_str() : "off",
                static_cast<unsigned long long>(t.last.gpu.triangles), t.cpu.median, t.cpu.lo, t.cpu.hi);
    if (t.hasGpu) std::printf("%.3f (%.3f-%.3f)%s | ", t.gpu.median, t.gpu.lo, t.gpu.hi, hostTimed ? " *" : "");
    else std::printf("- | ");
    std::printf("%.1f |\n", fps);
    std::fflush(stdout);
    {
      csv << count << ',' << shadowLeaves << ',' << t.last.gpu.triangles << ',' << t.cpu.median << ',' << t.cpu.lo << ',' << t.cpu.hi << ','
          << t.gpu.median << ',' << t.gpu.lo << ',' << t.gpu.hi << ',' << fps << '\n';
    }
  };
  measure(0, 0);  // the tree alone: what the leaves add is the difference
  for (std::uint32_t count : counts) {
    for (std::uint32_t shadowLeaves : shadows) measure(count, shadowLeaves);
  }
  if (hostTimed) std::printf("\n* lavapipe: GPU timestamps miss its deferred rasterisation; frames/s use the CPU frame time.\n");
  if (reportValidationErrors(context)) return kExitFailure;
  if (!o.csv.empty()) {
    writeFileAtomically(o.csv, csv.str());
    std::printf("wrote %s\n", o.csv.c_str());
  }
  return 0;
}

}  // namespace

void addBenchLeavesCommand(CLI::App& bench, Action& action) {
  auto o = std::make_shared<BenchLeavesOptions>();
  CLI::App* cmd = bench.add_subcommand("leaves", "Frame time against leaves drawn, with and without self-shadowing (Vulkan).");
  cmd->add_option("species", o->species, "Preset or model file (grown to more levels until it has enough leaves)")->capture_default_str();
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--seed", o->seed, "Random seed")->check(Seed())->capture_default_str();
  cmd->add_option("--counts", o->counts, "Leaves drawn per row, comma-separated (the first of the random order)")->capture_default_str();
  cmd->add_option("--shadow-leaves", o->shadows, "Self-shadowing settings per count, comma-separated, 0 to 4096 (0: off)")->capture_default_str();
  cmd->add_option("--mode", o->mode, "How the tree is drawn: " + modeHelp())->capture_default_str();
  cmd->add_option("--tess", o->tess, "Tessellation factor of the tree")->check(Number(1.0, 64.0))->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per row, after one warm-up")->check(Whole(1, 10000))->capture_default_str();
  cmd->add_option("--device", o->device, "Prefer the Vulkan device whose name contains this");
  cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also ARBOR_VALIDATION=1)");
  cmd->add_option("--csv", o->csv, "Also write the figures as CSV");
  cmd->callback([o, &action] { action = [o] { return runBenchLeaves(*o); }; });
}

}  // namespace arbor::cli
