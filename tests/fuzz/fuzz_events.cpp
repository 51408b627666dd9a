// The viewer's --events list: parsed; every accepted event has a frame from 1 and a size within limits.
#include "fuzz_target.hpp"
#include "view_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return arbor::fuzz::guarded(data, size, [](const std::string& text) {
    for (const arbor::viewer::WindowEvent& e : arbor::viewer::parseEvents(text)) {
      if (e.frame < 1 || (e.action == "resize" && (e.width < 1 || e.height < 1 || e.width > 8192 || e.height > 8192))) std::abort();
    }
  });
}
