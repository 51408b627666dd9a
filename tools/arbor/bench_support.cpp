#include "bench_support.hpp"

#include <algorithm>


namespace arbor::cli {

namespace {

Figures summarize(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v.front(), v.back()};
}

}  // namespace

TimedFrames timeFrames(render::RenderSession& session, const render::Camera& camera, const render::RenderSettings& settings, int frames,
                       const std::vector<render::TreeInstance>* instances) {
  TimedFrames t;
  const std::vector<render::TreeInstance> drawn = instances ? *instances : session.treeInstances();
  t.last = session.render(camera, settings, drawn);  // warm-up, waited for: pipelines, control points, caches
  t.firstCpuMs = t.last.cpuMilliseconds;
  // The timed frames run as the viewer runs them, two in flight: each is the time between two completions.
  t.cpu = summarize(session.renderInFlight(camera, settings, drawn, frames, t.last));
  if (t.last.gpu.hasTime) t.gpu = summarize({t.last.gpu.gpuMilliseconds});  // timestamps of the last frame
  t.hasGpu = t.last.gpu.hasTime;
  return t;
}

}  // namespace arbor::cli
