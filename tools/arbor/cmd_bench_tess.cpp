// arbor bench tess: frame time and triangles generated per mode and tessellation factor, on one tree or a
// forest; against the device's ceiling (trivial stages) and against subdividing on the CPU with OpenSubdiv.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numeric>
#include <sstream>

#include "assets.hpp"
#include "bench_support.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/atomic_file.hpp"
#include "export/subdivide.hpp"
#include "grow_forest.hpp"
#include "growth/growth_model.hpp"
#include "tree/build_tree.hpp"
#include "image/plot.hpp"
#include "mesh/tree_mesh.hpp"
#include "render/forest.hpp"
#include "render/render_session.hpp"
#include "render_options.hpp"

namespace arbor::cli {

namespace {

struct BenchTessOptions {
  AngleChoice angles = AngleChoice::File;
  std::string species = "black-tupelo";
  std::uint64_t seed = 1;
  int levels = 0;
  std::string modes = "flat,pn,acc,acc+disp";
  std::string factors = "1,2,4,8,16,32,64";
  std::string adaptive;
  std::string size = "1280x720";
  int frames = 5;
  float anisotropy = 0.0f;  // 0: by device, as the viewer
  std::string device;
  bool validation = false;
  std::string csv;
  std::string plot;
  std::vector<std::string> scene;  // "tree" or "forest" [N]
  bool noCeiling = false;
  int subdivideUpTo = 8;           // CPU-subdivision comparison up to this ACC factor (0: none)
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
  for (const std::string& name : splitList(o.modes, "--modes")) {
    // Any tessellated mode may be displaced: NAME+disp.
    const bool displaced = name.size() > 5 && name.compare(name.size() - 5, 5, "+disp") == 0;
    Cell base;
    base.settings.mode = parseMode(displaced ? name.substr(0, name.size() - 5) : name, "--modes");
    base.settings.displacement = displaced ? 0.5f : 0.0f;
    if (displaced && !render::isTessellated(base.settings.mode)) throw InputError(name, "--modes", "only tessellated modes are displaced");
    if (!render::isTessellated(base.settings.mode)) {
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
  if (cells.empty()) throw InputError(o.modes, "--modes", "no mode given; allowed: " + render::renderModeList() + ", each tessellated one also +disp");
  return cells;
}

// One measured cell: what the table, the CSV and the plot show.
struct Measured {
  std::string label, mode;
  float factor = 0.0f, adaptive = 0.0f, displacement = 0.0f;
  std::uint64_t triangles = 0;
  TimedFrames timed;
  double seconds = 0.0;  // the frame time used for rates: GPU timestamps, or the host's on lavapipe
  double rate = 0.0;     // M triangles/s
  std::size_t bytes = 0;  // on the GPU: the trees' buffers and the control points this mode built
};

double mib(std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

double msSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// The scene: one tree framed, or a forest of instanced trees seen from above its edge.
struct BenchScene {
  std::unique_ptr<render::Forest> forest;
  std::vector<render::TreeInstance> instances;
  render::Camera camera;
  std::size_t bytes = 0, quads = 0;
  std::string description;
};

int runBenchTess(const BenchTessOptions& o) {
  std::uint32_t width = 0, height = 0;
  parseSize(o.size, width, height);
  const std::vector<Cell> cells = makeCells(o);
  const bool forestScene = !o.scene.empty() && o.scene.front() == "forest";
  if (!o.scene.empty() && o.scene.front() != "tree" && !forestScene) {
    throw InputError(o.scene.front(), "--scene", "allowed: tree, or forest N (N trees, 1 to 1000)");
  }
  std::uint32_t forestTrees = 30;
  if (forestScene && o.scene.size() > 1) {
    const std::vector<float> n = parseNumbers(o.scene[1], "--scene", 1.0f, 1000.0f);
    if (n.size() != 1) throw InputError(o.scene[1], "--scene", "forest takes one tree count, 1 to 1000");
    forestTrees = static_cast<std::uint32_t>(n.front());
  }
  if (!o.csv.empty()) requireOutputFile(o.csv, "--csv");
  if (!o.plot.empty()) requireOutputFile(o.plot, "--plot");
  // Rows are collected and the file written whole at the end: a refused or interrupted run leaves an old CSV alone.
  std::ostringstream csv;
  csv << "mode,factor,adaptive_px,displacement,triangles,patches_drawn,patches_culled,draws,cpu_ms_median,cpu_ms_min,cpu_ms_max,gpu_ms_median,gpu_ms_min,"
         "gpu_ms_max,mtriangles_per_s,share_of_ceiling,gpu_bytes\n";

  const TreeSource source = loadTreeArgument(o.species, nullptr, o.angles);
  vk::VulkanContext context(vulkanOptions(o.validation, o.device));
  render::TreeTextures textures = treeTextures(o.anisotropy, context);
  const float barkAnisotropy = textures.barkAnisotropy;
  render::RenderSession session(context, width, height, VK_SAMPLE_COUNT_1_BIT, std::move(textures));
  const float aspect = static_cast<float>(width) / static_cast<float>(height);

  BenchScene scene;
  TreeMesh tree;
  double patchUploadMs = 0.0;  // the tessellated path's counterpart of subdividing and uploading
  if (forestScene) {
    scene.forest = growForest(context, ForestRequest{{o.species}, {source}, forestTrees, 3, o.seed}, "arbor bench tess");
    session.renderer().setTrees(scene.forest->gpuTrees());
    scene.camera = scene.forest->overview(aspect);
    // Every tree at its whole mesh, so that a factor means the same everywhere.
    scene.instances = scene.forest->frame(scene.camera, aspect, {1e9f, 1e9f}).instances;
    for (const render::ForestTree& t : scene.forest->trees()) scene.bytes += t.detail[0].bytes;
    for (const render::TreeInstance& i : scene.instances) scene.quads += scene.forest->trees()[i.tree / render::kDetailLevels].detail[0].patchCount;
    scene.description = std::to_string(scene.instances.size()) + " trees in view (" + std::to_string(scene.forest->trees().size()) +
                        " distinct), " + std::to_string(scene.quads) + " quads in all";
  } else {
    GrowthOptions growth;
    growth.seed = o.seed;
    growth.levels = o.levels;
    tree = buildTree(source.grow(growth), BuildOptions{{}, false}).mesh;  // patches are timed with the upload below
    const auto start = std::chrono::steady_clock::now();
    session.setTree(tree.mesh, buildPatches(tree.mesh));
    patchUploadMs = msSince(start);
    scene.instances = {{0, render::plantedModel(*session.tree())}};
    scene.camera = render::frameBounds(render::plantedBounds(*session.tree()), 25.0f, 6.0f, aspect);
    scene.bytes = session.tree()->bytes;
    scene.quads = tree.mesh.quads.size();
    scene.description = std::to_string(scene.quads) + " quads";
  }
  // Lavapipe rasterises when the render pass ends, after the timestamps: its whole frame is the host's wait.
  const bool hostTimed = context.isLavapipe();

  std::printf("%s: %s at %ux%u on %s, bark filtered at %gx anisotropy, %d frames per cell after one warm-up%s\n\n", source.name().c_str(),
              scene.description.c_str(), width, height, context.deviceDescription().c_str(), static_cast<double>(barkAnisotropy), o.frames,
              context.validationEnabled() ? ", validation on" : "");
  std::fflush(stdout);

  auto measure = [&](const std::string& label, const render::RenderSettings& s) {
    Measured m;
    m.label = label;
    m.mode = s.ceiling ? "ceiling" : render::renderModeName(s.mode);
    m.factor = render::isTessellated(s.mode) ? s.tessLevel : 1.0f;
    m.adaptive = s.adaptivePixels;
    m.displacement = s.displacement;
    m.timed = timeFrames(session, scene.camera, s, o.frames, &scene.instances);
    m.triangles = m.timed.last.gpu.triangles;
    m.seconds = (hostTimed || !m.timed.hasGpu ? m.timed.cpu.median : m.timed.gpu.median) * 1e-3;
    m.rate = m.seconds > 0.0 ? static_cast<double>(m.triangles) / m.seconds * 1e-6 : 0.0;
    m.bytes = scene.bytes + session.renderer().controlBytes(s.mode);
    return m;
  };

  // The ceiling first: ACC's patches with trivial stages at each uniform factor.
  std::vector<float> uniformFactors;
  for (const Cell& c : cells) {
    if (render::isTessellated(c.settings.mode) && c.settings.adaptivePixels <= 0.0f &&
        std::find(uniformFactors.begin(), uniformFactors.end(), c.settings.tessLevel) == uniformFactors.end()) {
      uniformFactors.push_back(c.settings.tessLevel);
    }
  }
  const std::size_t total = cells.size() + (o.noCeiling ? 0 : uniformFactors.size());
  std::size_t done = 0;
  std::vector<Measured> ceiling, results;
  if (!o.noCeiling) {
    for (float f : uniformFactors) {
      std::fprintf(stderr, "arbor bench tess: [%zu/%zu] ceiling x%g\n", ++done, total, static_cast<double>(f));
      render::RenderSettings s;
      s.mode = render::RenderMode::ACC;
      s.ceiling = true;
      s.tessLevel = f;
      ceiling.push_back(measure("ceiling x" + CLI::detail::to_string(f), s));
    }
  }
  const double bestCeiling = std::accumulate(ceiling.begin(), ceiling.end(), 0.0, [](double a, const Measured& m) { return std::max(a, m.rate); });
  for (const Cell& c : cells) {
    std::fprintf(stderr, "arbor bench tess: [%zu/%zu] %s\n", ++done, total, c.label.c_str());
    results.push_back(measure(c.label, c.settings));
  }

  auto shareOfCeiling = [&](const Measured& m) {
    if (m.mode == "ceiling") return 1.0;
    for (const Measured& c : ceiling) {
      if (m.adaptive <= 0.0f && m.mode != "flat" && c.factor == m.factor) return c.rate > 0.0 ? m.rate / c.rate : 0.0;
    }
    return bestCeiling > 0.0 ? m.rate / bestCeiling : 0.0;  // adaptive and flat cells: against the best ceiling
  };
  std::printf("| cell | triangles | patches drawn / culled | draws | CPU frame ms (min-max) | GPU frame ms (min-max) | M triangles/s | of ceiling | GPU MiB |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::vector<const Measured*> rows;
  for (const Measured& m : ceiling) rows.push_back(&m);
  for (const Measured& m : results) rows.push_back(&m);
  for (const Measured* m : rows) {
    const render::FrameStats& gpu = m->timed.last.gpu;
    std::printf("| %s | %llu | ", m->label.c_str(), static_cast<unsigned long long>(m->triangles));
    if (gpu.patchesDrawn + gpu.patchesCulled > 0) {
      std::printf("%llu / %llu | ", static_cast<unsigned long long>(gpu.patchesDrawn), static_cast<unsigned long long>(gpu.patchesCulled));
    } else {
      std::printf("- | ");
    }
    std::printf("%u | %.2f (%.2f-%.2f) | ", gpu.draws, m->timed.cpu.median, m->timed.cpu.lo, m->timed.cpu.hi);
    if (!m->timed.hasGpu) std::printf("- | ");
    else std::printf("%.3f (%.3f-%.3f)%s | ", m->timed.gpu.median, m->timed.gpu.lo, m->timed.gpu.hi, hostTimed ? " *" : "");
    std::printf("%.2f | %s | %.1f |\n", m->rate, o.noCeiling ? "-" : (std::to_string(static_cast<int>(std::lround(100.0 * shareOfCeiling(*m)))) + " %").c_str(),
                mib(m->bytes));
    {
      csv << m->mode << ',' << m->factor << ',' << m->adaptive << ',' << m->displacement << ',' << m->triangles << ','
          << m->timed.last.gpu.patchesDrawn << ',' << m->timed.last.gpu.patchesCulled << ',' << m->timed.last.gpu.draws << ',' << m->timed.cpu.median
          << ',' << m->timed.cpu.lo << ',' << m->timed.cpu.hi << ',' << m->timed.gpu.median << ',' << m->timed.gpu.lo << ',' << m->timed.gpu.hi
          << ',' << m->rate << ',' << (o.noCeiling ? 0.0 : shareOfCeiling(*m)) << ',' << m->bytes << '\n';
    }
  }
  std::fflush(stdout);

  // The alternative: Catmull-Clark on the CPU with OpenSubdiv to the level with ACC's triangles (factor 2^k
  // gives 2 * 4^k triangles per quad, as k uniform refinements do), uploaded and drawn flat.
  std::vector<Measured> subdivided;
  if (!forestScene && o.subdivideUpTo >= 1) {
    std::printf("\n| ACC factor = 2^levels | triangles | tessellated: first frame ms, frame ms, GPU MiB | CPU-subdivided: subdivide ms, "
                "first frame ms, frame ms, GPU MiB | GPU bytes, subdivided / tessellated |\n|---|---|---|---|---|\n");
    for (int levels = 0; (1 << levels) <= o.subdivideUpTo; ++levels) {
      const float factor = static_cast<float>(1 << levels);
      const auto acc = std::find_if(results.begin(), results.end(), [&](const Measured& m) {
        return m.mode == "acc" && m.adaptive <= 0.0f && m.displacement == 0.0f && m.factor == factor;
      });
      if (acc == results.end()) continue;
      constexpr double kMostRefinedQuads = 2.0e7;  // the comparison's own bound, above the export's quad limit
      if (static_cast<double>(scene.quads) * std::pow(4.0, levels) > kMostRefinedQuads) {
        std::printf("| %g | - | skipped: %zu quads x 4^%d is over 20 M refined quads |||\n", static_cast<double>(factor), scene.quads, levels);
        continue;
      }
      std::fprintf(stderr, "arbor bench tess: CPU subdivision, %d levels\n", levels);
      const auto start = std::chrono::steady_clock::now();
      const QuadMesh refined = levels > 0 ? subdivide(tree.mesh, levels, static_cast<std::size_t>(kMostRefinedQuads)) : tree.mesh;
      const double subdivideMs = msSince(start);
      session.setTree(refined, PatchSet{});  // the tessellated cells are done: the same pipelines draw it
      render::RenderSettings s;
      s.mode = render::RenderMode::Flat;
      const render::FrameResult first = session.render(scene.camera, s);
      const double firstFrameMs = msSince(start);
      const TimedFrames timed = timeFrames(session, scene.camera, s, o.frames);
      const double frameMs = hostTimed || !timed.hasGpu ? timed.cpu.median : timed.gpu.median;
      const double accFrameMs = acc->seconds * 1e3;
      const double accFirstMs = patchUploadMs + acc->timed.firstCpuMs;  // patches and upload, then its first frame
      const std::size_t bytes = session.tree()->bytes;
      std::printf("| %g | %llu | %.0f, %.2f, %.1f | %.0f, %.0f, %.2f, %.1f | %.1f |\n", static_cast<double>(factor),
                  static_cast<unsigned long long>(first.gpu.triangles), accFirstMs, accFrameMs, mib(acc->bytes), subdivideMs, firstFrameMs,
                  frameMs, mib(bytes), static_cast<double>(bytes) / static_cast<double>(acc->bytes));
      std::fflush(stdout);
      Measured m;
      m.label = "cpu-subdivided x" + CLI::detail::to_string(factor);
      m.mode = "cpu-subdivided";
      m.factor = factor;
      m.triangles = first.gpu.triangles;
      m.timed = timed;
      m.seconds = frameMs * 1e-3;
      m.rate = m.seconds > 0.0 ? static_cast<double>(m.triangles) / m.seconds * 1e-6 : 0.0;
      {
        csv << "cpu-subdivided," << factor << ",0,0," << m.triangles << ",0,0," << timed.last.gpu.draws << ',' << timed.cpu.median << ',' << timed.cpu.lo << ',' << timed.cpu.hi << ','
            << timed.gpu.median << ',' << timed.gpu.lo << ',' << timed.gpu.hi << ',' << m.rate << ",0," << bytes << '\n';
      }
      subdivided.push_back(m);
    }
  }

  if (!o.plot.empty()) {
    std::vector<std::string> modes;
    std::vector<const Measured*> all;
    for (const Measured* m : rows) all.push_back(m);
    for (const Measured& m : subdivided) all.push_back(&m);
    for (const Measured* m : all) {
      const std::string key = m->mode + (m->displacement != 0.0f ? "+disp" : "");
      if (m->adaptive <= 0.0f && std::find(modes.begin(), modes.end(), key) == modes.end()) modes.push_back(key);
    }
    PlotPanel time{"Frame time", "tessellation factor", std::string(hostTimed ? "CPU" : "GPU") + " ms per frame", {}};
    PlotPanel rate{"Throughput", "tessellation factor", "million triangles per second", {}};
    for (std::size_t k = 0; k < modes.size(); ++k) {
      PlotSeries t{modes[k], {}, {}, plotColor(k)}, r{modes[k], {}, {}, plotColor(k)};
      for (const Measured* m : all) {
        if (m->adaptive > 0.0f || m->mode + (m->displacement != 0.0f ? "+disp" : "") != modes[k]) continue;
        t.x.push_back(m->factor), t.y.push_back(m->seconds * 1e3);
        r.x.push_back(m->factor), r.y.push_back(m->rate);
      }
      time.series.push_back(t);
      rate.series.push_back(r);
    }
    writePng(o.plot, plotPanels({time, rate}));
  }
  if (hostTimed) {
    std::printf("\n* lavapipe: GPU timestamps miss its deferred rasterisation; rates and shares use the CPU frame time.\n");
  }
  if (reportValidationErrors(context)) return kExitFailure;
  if (!o.csv.empty()) {
    writeFileAtomically(o.csv, csv.str());
    std::printf("wrote %s\n", o.csv.c_str());
  }
  if (!o.plot.empty()) std::printf("wrote %s\n", o.plot.c_str());
  return 0;
}

}  // namespace

void addBenchTessCommand(CLI::App& bench, Action& action) {
  auto o = std::make_shared<BenchTessOptions>();
  CLI::App* cmd = bench.add_subcommand("tess", "Frame time and triangles generated per mode and tessellation factor (Vulkan).");
  cmd->add_option("species", o->species, "Preset, or model, skeleton or graph file")->capture_default_str();
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--seed", o->seed, "Random seed")->check(Seed())->capture_default_str();
  cmd->add_option("--levels", o->levels, "Stem levels (default: the species' Levels)")->check(Whole(1, 8));
  cmd->add_option("--modes", o->modes, "Comma-separated: " + render::renderModeList() + "; a tessellated mode with +disp is displaced")->capture_default_str();
  cmd->add_option("--factors", o->factors, "Uniform tessellation factors, 1 to 64 (empty: none)")->capture_default_str();
  cmd->add_option("--adaptive", o->adaptive, "Adaptive targets: edge lengths in pixels, 0.5 to 1000");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per cell, after one warm-up")->check(Whole(1, 10000))->capture_default_str();
  addAnisotropyOption(cmd, o->anisotropy, "8; lavapipe: 1, as the viewer draws there, where 8 made ACC at factor 16 four times slower");
  cmd->add_option("--device", o->device, "Prefer the Vulkan device whose name contains this");
  cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also ARBOR_VALIDATION=1)");
  cmd->add_option("--csv", o->csv, "Also write the figures as CSV");
  cmd->add_option("--plot", o->plot, "Also draw frame time and triangles/s against the factor, one line per mode, as PNG");
  cmd->add_option("--scene", o->scene, "tree (default) or forest N (N instanced trees, 1 to 1000, default 30)")->expected(1, 2);
  cmd->add_flag("--no-ceiling", o->noCeiling, "Skip the ceiling cells (ACC's patches with trivial shaders)");
  cmd->add_option("--subdivide-up-to", o->subdivideUpTo, "Compare with OpenSubdiv on the CPU up to this ACC factor, a power of two (0: skip)")
      ->check(Whole(0, 64))
      ->capture_default_str();
  cmd->callback([o, &action] { action = [o] { return runBenchTess(*o); }; });
}

}  // namespace arbor::cli
