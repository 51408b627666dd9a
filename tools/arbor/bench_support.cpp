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
  std::vector<double> cpu, gpu;
  TimedFrames t;
  const auto frame = [&] { return instances ? session.render(camera, settings, *instances) : session.render(camera, settings); };
  t.last = frame();  // warm-up: pipelines, caches
  t.firstCpuMs = t.last.cpuMilliseconds;
  for (int f = 0; f < frames; ++f) {
    t.last = frame();
    cpu.push_back(t.last.cpuMilliseconds);
    if (t.last.gpu.hasTime) gpu.push_back(t.last.gpu.gpuMilliseconds);
  }
  t.cpu = summarize(cpu);
  t.gpu = summarize(gpu);
  t.hasGpu = !gpu.empty();
  return t;
}

}  // namespace arbor::cli
