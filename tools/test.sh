#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, runs every test (CTest, 2 jobs).
#   bash tools/test.sh           the suite in build/ (RelWithDebInfo)
#   bash tools/test.sh --asan    the same suite under AddressSanitizer and UndefinedBehaviorSanitizer, in build-asan/:
#                                any sanitizer report fails the test that caused it
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/tools/install-deps.sh"
if [[ "${1:-}" == "--asan" ]]; then
  # -O1 -g1: sanitized code compiles in about half the time of -O2 -g and still runs at a useful speed.
  cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DARBOR_SANITIZE=ON
  cmake --build "$root/build-asan" -j"$(nproc)"
  # Leaks are checked in Arbor's code only: the Vulkan driver, LLVM and X11 keep their own allocations for the
  # process's life (tools/sanitizers/lsan.supp); keep_modules.c keeps them loaded so that reports can name them,
  # and grow_geometrically.c spares lavapipe's per-patch reallocations a copy each under ASan's allocator.
  cc -shared -fPIC -O1 -o "$root/build-asan/sanitizer_preload.so" "$root/tools/sanitizers/keep_modules.c" \
    "$root/tools/sanitizers/grow_geometrically.c" -ldl
  export LD_PRELOAD="$root/build-asan/sanitizer_preload.so"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1:verify_asan_link_order=0"
  export LSAN_OPTIONS="suppressions=$root/tools/sanitizers/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  cd "$root/build-asan"
  ctest --output-on-failure -j"$(nproc)" --timeout 1500
  exit 0
fi
bash "$root/tools/build.sh"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)"
