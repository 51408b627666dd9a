#include "bench_support.hpp"

#include <algorithm>
#include <sstream>

#include "species/species_io.hpp"

namespace arbor::cli {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

std::vector<float> parseNumbers(const std::string& text, const std::string& field, float lo, float hi) {
  std::vector<float> values;
  for (const std::string& item : splitList(text)) {
    float v = 0.0f;
    std::size_t used = 0;
    try {
      v = std::stof(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !(v >= lo && v <= hi)) {
      throw SpeciesError(item, field, "allowed: comma-separated numbers from " + std::to_string(lo) + " to " + std::to_string(hi));
    }
    values.push_back(v);
  }
  return values;
}

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
