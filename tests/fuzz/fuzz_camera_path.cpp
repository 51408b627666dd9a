// Camera path files: parsed; every accepted camera gives finite view and projection matrices.
#include <cmath>

#include "fuzz_target.hpp"
#include "view_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    for (const arbor::render::Camera& c : arbor::viewer::parseCameraPath(text, "fuzz-path.txt")) {
      const glm::mat4 m = arbor::render::projectionMatrix(c, 1.5f) * arbor::render::viewMatrix(c);
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
          if (!std::isfinite(m[i][j])) std::abort();
        }
      }
    }
  });
}
