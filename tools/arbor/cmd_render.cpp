// arbor render: a tree rendered offscreen with the tessellation pipelines, written as PNG, with the frame
// time and the number of triangles the GPU generated.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "assets.hpp"
#include "cli_values.hpp"
#include "commands.hpp"
#include "common/text_util.hpp"
#include "growth/growth_model.hpp"
#include "tree/build_tree.hpp"
#include "image/png_io.hpp"
#include "mesh/impostor_segments.hpp"
#include "mesh/tree_mesh.hpp"
#include "render/render_session.hpp"
#include "export_options.hpp"
#include "render_options.hpp"

namespace arbor::cli {

namespace {

struct RenderOptions {
  AngleChoice angles = AngleChoice::File;
  std::string species;
  std::uint64_t seed = 1;
  int levels = 0;
  std::string mode = "acc";
  float tess = 8.0f;
  float adaptive = 0.0f;
  float displace = 0.0f;
  float anisotropy = 0.0f;  // 0: TreeTextures' default
  std::string size = "640x800";
  std::string camera;
  float azimuth = 25.0f, elevation = 6.0f;
  std::string out;
  int msaa = 1;
  int frames = 1;
  std::string device;
  bool validation = false;
  bool wireframe = false;
  bool noGround = false;
  bool meshDisplaced = false;  // mesh the twigs MeshOptions::fakeDisplaced draws as fake branches
  bool leaves = false;
  float leafDensity = 1.0f;
  float leafLod = 0.0f;
  int shadowLeaves = 0;
  bool impostors = false;
  int impostorLevels = 0;
  std::string light;
  WindSettings wind;
  double windTime = 1.0;
  bool quiet = false;
};


int runRender(const RenderOptions& o) {
  render::RenderSettings settings;
  settings.mode = parseMode(o.mode);
  settings.tessLevel = o.tess;
  settings.adaptivePixels = o.adaptive;
  settings.displacement = o.displace;
  settings.wireframe = o.wireframe;
  settings.ground = !o.noGround;
  settings.leaves = o.leaves;
  settings.leafDensity = o.leafDensity;
  settings.leafLodDistance = o.leafLod;
  settings.shadowLeaves = static_cast<std::uint32_t>(o.shadowLeaves);
  const int impostorLevels = o.impostorLevels > 0 ? o.impostorLevels : (o.impostors ? 1 : 0);
  settings.impostors = impostorLevels > 0;
  if (!o.light.empty()) settings.lightDirection = parseLight(o.light);
  settings.wind = o.wind;
  settings.windSeconds = o.windTime;
  std::uint32_t width = 0, height = 0;
  parseSize(o.size, width, height);
  if (!endsWith(o.out, ".png")) throw InputError(o.out, "--out", "the picture is written as PNG; use a .png name");
  requireOutputFile(o.out);

  const TreeSource source = loadTreeArgument(o.species, nullptr, o.angles);
  // The mesh keeps --levels (or the species'); impostor levels grow beyond them (breadth-first: the same tree
  // below), are drawn as fake branches, and carry the leaves.
  const int meshLevels = o.levels > 0 ? o.levels : source.levels();
  if (meshLevels + impostorLevels > 8) {
    throw InputError(std::to_string(impostorLevels), "--impostor-levels",
                       "mesh levels (" + std::to_string(meshLevels) + ") plus impostor levels may be at most 8");
  }
  GrowthOptions growth;
  growth.seed = o.seed;
  growth.levels = meshLevels + impostorLevels;
  const Skeleton skeleton = source.grow(growth);
  BuildOptions build;
  build.mesh.levels = meshLevels;
  build.mesh.fakeDisplaced = !o.meshDisplaced;
  build.wind = settings.wind.on();
  const TreeGeometry geometry = buildTree(skeleton, build);
  const TreeMesh& tree = geometry.mesh;
  const PatchSet& patches = geometry.patches;
  const std::vector<ImpostorSegment>& impostors = geometry.impostors;

  vk::VulkanContext context(vulkanOptions(o.validation, o.device));
  const auto textures = treeTextures(o.anisotropy);
  const auto samples = static_cast<VkSampleCountFlagBits>(o.msaa);
  render::RenderSession session(context, width, height, samples, textures);
  session.setTree(tree.mesh, patches, skeleton.leaves, impostors, build.wind ? &geometry.wind : nullptr);
  // Stubs (too short or thin for the mesh) are fake branches at every level.
  if (!impostors.empty()) settings.impostors = true;

  render::Camera camera;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  if (!o.camera.empty()) {
    try {
      camera = render::parseCamera(o.camera);
    } catch (const std::invalid_argument& e) {
      throw InputError(o.camera, "--camera", e.what());
    }
  } else {
    camera = render::frameBounds(render::plantedBounds(*session.tree()), o.azimuth, o.elevation, aspect);
  }

  std::vector<double> gpu, cpu;
  render::FrameResult last;
  const auto started = std::chrono::steady_clock::now();
  // The first frame also builds the control points: large trees take seconds before anything else is said.
  if (!o.quiet && tree.mesh.quads.size() > 20000) {
    std::fprintf(stderr, "arbor render: %zu quads, %d frame(s) at %ux%u on %s...\n", tree.mesh.quads.size(), o.frames, width, height,
                 context.deviceDescription().c_str());
  }
  for (int f = 0; f < o.frames; ++f) {
    // A whole tessellated tree takes seconds a frame on a CPU device: once a second has passed, say where it is.
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (!o.quiet && elapsed > 1.0) std::fprintf(stderr, "arbor render: frame %d of %d (%.1f s so far)\n", f + 1, o.frames, elapsed);
    last = session.render(camera, settings);
    if (f > 0 || o.frames == 1) {  // the first of several frames warms caches up and is not counted
      gpu.push_back(last.gpu.gpuMilliseconds);
      cpu.push_back(last.cpuMilliseconds);
    }
  }
  writePng(o.out, session.image());
  if (reportValidationErrors(context)) return kExitFailure;
  if (o.quiet) return 0;
  std::sort(gpu.begin(), gpu.end());
  std::sort(cpu.begin(), cpu.end());
  const render::GpuTree& gpuTree = *session.tree();
  std::printf("%s on %s%s\n", source.name().c_str(), context.deviceDescription().c_str(),
              context.validationEnabled() ? ", validation on" : "");
  std::printf("  mode             %s", render::renderModeName(settings.mode));
  if (render::isTessellated(settings.mode)) {
    if (settings.adaptivePixels > 0.0f) std::printf(", adaptive to %.1f px edges", static_cast<double>(settings.adaptivePixels));
    else std::printf(", tessellation factor %g", static_cast<double>(settings.tessLevel));
  }
  if (settings.displacement != 0.0f) std::printf(", displacement %g", static_cast<double>(settings.displacement));
  if (settings.wind.on()) std::printf(", wind %g at %g s", settings.wind.strength, settings.windSeconds);
  std::printf("\n  mesh             %zu quads: %u regular, %u extraordinary, %u fallback patches; %.1f MiB on the GPU\n",
              tree.mesh.quads.size(), gpuTree.regular, gpuTree.extraordinary, gpuTree.fallback,
              static_cast<double>(gpuTree.bytes) / (1024.0 * 1024.0));
  if (settings.leaves || settings.impostors) {
    std::printf("  points           %u leaves%s, %u fake-branch segments%s\n", gpuTree.leafCount, settings.leaves ? "" : " (not drawn)",
                gpuTree.impostorCount, settings.impostors ? "" : " (not drawn)");
  }
  if (last.gpu.hasTriangles) {
    std::printf("  triangles        %llu generated (clipping primitives), %u draws\n",
                static_cast<unsigned long long>(last.gpu.triangles), last.gpu.draws);
  }
  if (last.gpu.hasTime) std::printf("  frame            %.2f ms GPU (tree, median of %zu)", gpu[gpu.size() / 2], gpu.size());
  std::printf("%s%.2f ms CPU (record, submit, wait)\n", last.gpu.hasTime ? ", " : "  frame            ", cpu[cpu.size() / 2]);
  std::printf("wrote %s (%ux%u)\n", o.out.c_str(), width, height);
  return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, Action& action) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a tree offscreen with GPU tessellation (Vulkan) to a PNG.");
  cmd->add_option("species", o->species, "Preset name, or a model (.json, Arbaro .xml), skeleton or graph file")->required();
  addAnglesOption(cmd, o->angles);
  cmd->add_option("--seed", o->seed, "Random seed")->check(Seed())->capture_default_str();
  cmd->add_option("--levels", o->levels, "Stem levels to grow and mesh (default: the species' Levels)")->check(Whole(1, 8));
  cmd->add_option("--mode", o->mode, modeHelp())
      ->capture_default_str();
  cmd->add_option("--tess", o->tess, "Uniform tessellation factor")->check(Number(1.0, 64.0))->capture_default_str();
  cmd->add_option("--adaptive", o->adaptive, "Adaptive tessellation: target edge length in pixels (overrides --tess)")
      ->check(Number(0.5, 1000.0));
  cmd->add_option("--displace", o->displace, "Displacement scale s in (d - b) r s (0: off)")->check(Number(-10.0, 10.0));
  addAnisotropyOption(cmd, o->anisotropy, "8");
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--camera", o->camera, "Camera as ex,ey,ez,tx,ty,tz[,fov degrees] (default: framed on the tree)");
  cmd->add_option("--azimuth", o->azimuth, "Framing camera azimuth in degrees")->check(Number(-3600.0, 3600.0))->capture_default_str();
  cmd->add_option("--elevation", o->elevation, "Framing camera elevation in degrees")->check(Number(-89.0, 89.0))->capture_default_str();
  cmd->add_option("--msaa", o->msaa, "Samples per pixel (1, 2, 4, 8)")->check(CLI::IsMember({1, 2, 4, 8}))->capture_default_str();
  cmd->add_option("--frames", o->frames, "Frames to render; timings are medians after the first")->check(Whole(1, 10000))->capture_default_str();
  cmd->add_option("--device", o->device, "Prefer the Vulkan device whose name contains this");
  cmd->add_flag("--validation", o->validation, "Enable the Khronos validation layer (also ARBOR_VALIDATION=1); errors fail the run");
  cmd->add_flag("--wireframe", o->wireframe, "Outline the tessellated triangles");
  cmd->add_flag("--no-ground", o->noGround, "Leave out the ground");
  cmd->add_flag("--mesh-displaced", o->meshDisplaced,
                kMeshDisplacedHelp);
  cmd->add_flag("--leaves", o->leaves, "Draw the leaves (textured quads from the leaf atlas, back-lit, self-shadowed)");
  cmd->add_option("--leaf-density", o->leafDensity, "Share of the leaves drawn, 0 to 1")->check(Number(0.0f, 1.0f))->capture_default_str();
  cmd->add_option("--leaf-lod", o->leafLod, "All leaves up to this distance in metres, then fewer with distance squared, grown to keep the leaf area (0: all)")
      ->check(Number(0.0f, 10000.0f))
      ->capture_default_str();
  cmd->add_option("--shadow-leaves", o->shadowLeaves, "Self-shadowing: each leaf tests this many others (0: off)")
      ->check(Whole(0, 4096))
      ->capture_default_str();
  cmd->add_flag("--impostors", o->impostors, "Grow --impostor-levels more levels and draw them as fake branches (textured, view-facing)");
  cmd->add_option("--impostor-levels", o->impostorLevels, "Levels beyond the mesh drawn as fake branches; they carry the leaves (implies --impostors; default 1)")
      ->check(Whole(1, 3));
  cmd->add_option("--light", o->light, "Sun direction as AZIMUTH,ELEVATION in degrees (azimuth 0: from -y, the default camera's side)");
  addWindOptions(cmd, o->wind, "the control cage is posed before tessellation");
  cmd->add_option("--wind-time", o->windTime, "The moment shown, in seconds")->check(Number(0.0, 1e6))->capture_default_str();
  cmd->add_option("--out", o->out, "Output PNG")->required();
  cmd->add_flag("--quiet", o->quiet, "Print nothing on success");
  cmd->callback([o, &action] { action = [o] { return runRender(*o); }; });
}

}  // namespace arbor::cli
