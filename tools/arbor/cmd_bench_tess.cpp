// arbor bench tess: frame time and triangles generated per mode and tessellation factor, on one tree.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "assets.hpp"
#include "bench_support.hpp"
#include "commands.hpp"
#include "growth/weber_penn.hpp"
#include "mesh/tree_mesh.hpp"
#include "render/render_session.hpp"
#include "render_options.hpp"

namespace arbor::cli {

namespace {

struct BenchTessOptions {
  std::string species = "black-tupelo";
  std::uint64_t seed = 1;
  int levels = 0;
  std::string modes = "flat,pn,acc,acc+disp";
  std::string factors = "1,2,4,8,16,32,64";
  std::string adaptive;
  std::string size = "1280x720";
  int frames = 5;
  std::string device;
  bool validation = false;
  std::string csv;
};

// One column of the table: a mode with a uniform factor or an adaptive pixel target.
struct Cell {
  std::string label;
  render::RenderSettings settings;
};

std::vector<Cell> makeCells(const BenchTessOptions& o) {
  const std::vector<float> factors = parseNumbers(o.factors, "--factors", 1.0f, 64.0f);
  const std::vector<float> targets = parseNumbers(o.adaptive, "--adaptive", 0.5f, 1000.0f);
  std::vector<Cell> cells;
  for (const std::string& name : splitList(o.modes)) {
    const bool displaced = name == "acc+disp" || name == "pn+disp";
    Cell base;
    base.settings.mode = parseMode(displaced ? name.substr(0, name.size() - 5) : name, "--modes");
    base.settings.displacement = displaced ? 0.5f : 0.0f;
    if (base.settings.mode == render::RenderMode::Flat) {
      base.label = name;
      cells.push_back(base);
      continue;
    }
    for (float f : factors) {
      Cell c = base;
      c.settings.tessLevel = f;
      c.label = name + " x" + CLI::detail::to_string(f);
      cells.push_back(c);
    }
    for (float t : targets) {
      Cell c = base;
      c.settings.adaptivePixels = t;
      c.label = name + " adaptive " + CLI::detail::to_string(t) + " px";
      cells.push_back(c);
    }
  }
  if (cells.empty()) throw SpeciesError(o.modes, "--modes", "no mode given; allowed: flat, pn, acc, acc+disp, pn+disp");
  return cells;
}

int runBenchTess(const BenchTessOptions& o) {
  std::uint32_t width = 0, height = 0;
  parseSize(o.size, width, height);
  const std::vector<Cell> cells = makeCells(o);
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) throw std::runtime_error(o.csv + ": cannot open for writing");
    csv << "mode,factor,adaptive_px,displacement,triangles,cpu_ms_median,cpu_ms_min,cpu_ms_max,gpu_ms_median,gpu_ms_min,"
           "gpu_ms_max,mtriangles_per_s,gpu_bytes\n";
  }

  GrowthOptions growth;
  growth.seed = o.seed;
  growth.levels = o.levels;
  const TreeMesh tree = buildTreeMesh(generateSkeleton(loadSpeciesArgument(o.species), growth));
  const PatchSet patches = buildPatches(tree.mesh);
  vk::ContextOptions contextOptions;
  contextOptions.validation = validationWanted(o.validation);
  contextOptions.device = o.device;
  vk::VulkanContext context(contextOptions);
  const auto textures = render::loadTreeTextures(assetDirectory());
  render::RenderSession session(context, width, height, VK_SAMPLE_COUNT_1_BIT, textures);
  session.setTree(tree.mesh, patches);
  const render::Camera camera = render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f,
                                                    static_cast<float>(width) / static_cast<float>(height));
  // Lavapipe rasterises when the render pass ends, after the timestamps: its whole frame is the host's wait.
  const bool hostTimed = context.isLavapipe();

  std::printf("%s (%zu quads) at %ux%u on %s, %d frames per cell after one warm-up%s\n\n", o.species.c_str(),
              tree.mesh.quads.size(), width, height, context.deviceDescription().c_str(), o.frames,
              contextOptions.validation ? ", validation on" : "");
  std::printf("| cell | triangles | CPU frame ms (min-max) | GPU tree ms (min-max) | M triangles/s | GPU bytes |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& c = cells[i];
    std::fprintf(stderr, "arbor bench tess: [%zu/%zu] %s\n", i + 1, cells.size(), c.label.c_str());
    const TimedFrames timed = timeFrames(session, camera, c.settings, o.frames);
    const render::FrameResult& frame = timed.last;
    const Figures &fc = timed.cpu, &fg = timed.gpu;
    const double seconds = (hostTimed || !timed.hasGpu ? fc.median : fg.median) * 1e-3;
    const double rate = seconds > 0.0 ? static_cast<double>(frame.gpu.triangles) / seconds * 1e-6 : 0.0;
    std::printf("| %s | %llu | %.2f (%.2f-%.2f) | ", c.label.c_str(), static_cast<unsigned long long>(frame.gpu.triangles),
                fc.median, fc.lo, fc.hi);
    if (!timed.hasGpu) std::printf("- | ");
    else std::printf("%.3f (%.3f-%.3f)%s | ", fg.median, fg.lo, fg.hi, hostTimed ? " *" : "");
    std::printf("%.2f | %zu |\n", rate, session.tree()->bytes);
    std::fflush(stdout);
    if (csv) {
      const bool flat = c.settings.mode == render::RenderMode::Flat;
      csv << render::renderModeName(c.settings.mode) << ',' << (flat ? 1.0f : c.settings.tessLevel) << ',' << c.settings.adaptivePixels << ','
          << c.settings.displacement << ',' << frame.gpu.triangles << ',' << fc.median << ',' << fc.lo << ',' << fc.hi << ','
          << fg.median << ',' << fg.lo << ',' << fg.hi << ',' << rate << ',' << session.tree()->bytes << '\n';
    }
  }
  if (hostTimed) {
    std::printf("\n* lavapipe: GPU timestamps miss its deferred rasterisation; triangles/s use the CPU frame time.\n");
  }
  if (reportValidationErrors(context)) return kExitFailure;
  if (!o.csv.empty()) std::printf("wrote %s\n", o.csv.c_str());
  return 0;
}

}  // namespace

void addBenchTessCommand(CLI::App& bench, Action& action) {
  auto o = std::make_shared<BenchTessOptions>();
  CLI::App* cmd = bench.add_subcommand("tess", "Frame time and triangles generated per mode and tessellation factor (Vulkan).");
  cmd->add_option("species", o->species, "Preset or species file")->capture_default_str();
  cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
  cmd->add_option("--levels", o->levels, "Stem levels (default: the species' Levels)")->check(CLI::Range(1, 8));
  cmd->add_option("--modes", o->modes, "Comma-separated: flat, pn, acc, acc+disp, pn+disp")->capture_default_str();
  cmd->add_option("--factors", o->factors, "Uniform tessellation factors, 1 to 64 (empty: none)")->capture_default_str();
  cmd->add_option("--adaptive", o->adaptive, "Adaptive targets: edge lengths in pixels, 0.5 to 1000");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per cell, after one warm-up")->check(CLI::Range(1, 10000))->capture_default_str();
  cmd->add_option("--device", o->device, "Prefer the Vulkan device whose name contains this");
  cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also ARBOR_VALIDATION=1)");
  cmd->add_option("--csv", o->csv, "Also write the figures as CSV");
  cmd->callback([o, &action] { action = [o] { return runBenchTess(*o); }; });
}

}  // namespace arbor::cli
