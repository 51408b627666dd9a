#pragma once
// Shared by the Vulkan benchmarks (bench tess, bench leaves): list options, timing a setting over frames.
#include <string>
#include <vector>

#include "cli_values.hpp"
#include "render/render_session.hpp"

namespace arbor::cli {

struct Figures {
  double median = 0.0, lo = 0.0, hi = 0.0;
};

struct TimedFrames {
  Figures cpu, gpu;             // milliseconds: host (between completions, two frames in flight) and timestamps (the last frame)
  double firstCpuMs = 0.0;      // the warm-up frame's host time
  bool hasGpu = false;
  render::FrameResult last;
};

// One warm-up frame waited for, then `frames` timed ones two in flight: the session's tree, or the renderer's
// trees at `instances`.
TimedFrames timeFrames(render::RenderSession& session, const render::Camera& camera, const render::RenderSettings& settings, int frames,
                       const std::vector<render::TreeInstance>* instances = nullptr);

}  // namespace arbor::cli
