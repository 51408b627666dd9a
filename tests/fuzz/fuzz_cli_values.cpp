// Command-line values: the text checks every numeric option goes through (numbers, whole numbers, seeds,
// lists, sizes, sun angles). What they accept must be what they promise.
#include <cmath>

#include "cli_values.hpp"
#include "fuzz_target.hpp"

namespace {

// Each check on its own: one refusal must not hide what the next would do with the same text.
template <class Check>
void attempt(Check&& check) {
  try {
    check();
  } catch (const arbor::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    using namespace arbor::cli;
    for (CLI::Validator v : {Number(-10.0, 10.0), OffOrNumber(0.01, 1000.0), Whole(1, 64)}) {
      std::string copy = text;
      if (v(copy).empty()) {
        const double x = std::strtod(text.c_str(), nullptr);
        if (!std::isfinite(x) || std::abs(x) > 1000.0) std::abort();
      }
    }
    std::string seed = text;
    if (Seed()(seed).empty() && (text.empty() || text.size() > 20 || text.find_first_not_of("0123456789") != std::string::npos)) std::abort();
    attempt([&] {
      for (float x : parseNumbers(text, "--factors", 1.0f, 64.0f)) {
        if (!(x >= 1.0f && x <= 64.0f)) std::abort();
      }
    });
    attempt([&] {
      std::uint32_t w = 0, h = 0;
      parseSize(text, w, h);
      if (w < 16 || h < 16 || w > 8192 || h > 8192) std::abort();
    });
    attempt([&] {
      const glm::vec2 sun = parseSunAngles(text);
      if (!std::isfinite(sun.x) || !(sun.y >= -90.0f && sun.y <= 90.0f)) std::abort();
    });
  });
}
