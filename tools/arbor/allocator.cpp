// The CLI allocates with jemalloc on transparent huge pages (where CMake found jemalloc): a one-shot export
// touches some 100 MB of fresh memory, and on a virtual machine a 4 KiB page fault costs more than filling the
// page (Arbaro's tupelo file to OBJ: 23,000 faults and 0.60 s with glibc's malloc, 3,300 and 0.28 s here).
#include <jemalloc/jemalloc.h>

#include <cstddef>

extern "C" {
// jemalloc reads its options from this symbol at start-up (MALLOC_CONF in the environment still overrides).
// One arena for all threads: an arena per thread (the export's printers, the card and texture threads) left a
// partly used huge page in each (tupelo to OBJ: 45 huge-page and 2,300 small faults, 40 and 1,470 with one).
const char* malloc_conf = "thp:always,metadata_thp:auto,narenas:1";
}

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

extent_hooks_t* jemallocHooks = nullptr;
extent_hooks_t alignedHooks;

// jemalloc's own mapping, aligned to a huge page when it is one or more: mmap aligns to 4 KiB, and the unaligned
// head of a mapping was faulted in 4 KiB pages (shave-grass.xml to OBJ: 340 -> 294 faults).
void* alignedAlloc(extent_hooks_t*, void* at, std::size_t size, std::size_t alignment, bool* zero, bool* commit, unsigned arena) {
  if (at == nullptr && size >= kHugePage && alignment < kHugePage) alignment = kHugePage;
  return jemallocHooks->alloc(jemallocHooks, at, size, alignment, zero, commit, arena);
}

// Arena 0 (the only one) maps through alignedAlloc; everything else stays jemalloc's. Without it, allocation works
// as before.
bool alignArenaMappings() {
  std::size_t size = sizeof(jemallocHooks);
  if (mallctl("arena.0.extent_hooks", &jemallocHooks, &size, nullptr, 0) != 0 || jemallocHooks == nullptr) return false;
  alignedHooks = *jemallocHooks;
  alignedHooks.alloc = alignedAlloc;
  extent_hooks_t* hooks = &alignedHooks;
  return mallctl("arena.0.extent_hooks", nullptr, nullptr, &hooks, sizeof(hooks)) == 0;
}

[[maybe_unused]] const bool arenaMappingsAligned = alignArenaMappings();

}  // namespace
