#pragma once
// One fuzz target per parser. Each file defines LLVMFuzzerTestOneInput; the same source builds twice:
// with libFuzzer (tools/fuzz.sh, clang, -fsanitize=fuzzer,address,undefined) to search for new inputs, and
// with replay_main.cpp (every build, the suite) to run the kept corpus as regression inputs.
//
// The contract for every input: the parser returns or throws the project's own refusals (InputError for bad
// input, LimitError for a request past the limits). Anything else escaping is a finding: the target aborts.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "common/input_error.hpp"

namespace arbor::fuzz {

template <class Body>
int guarded(const std::uint8_t* data, std::size_t size, Body&& body) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    body(text);
  } catch (const InputError&) {
  } catch (const LimitError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: an exception the contract does not allow: %s\n", e.what());
    std::abort();
  }
  return 0;
}

}  // namespace arbor::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
