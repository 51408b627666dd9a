#include "huge_page_blocks.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <mutex>
#include <new>
#include <vector>

namespace arbor {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kRegionBytes = 4 * kHugePage;  // 16 blocks: a large export maps a few regions, a small one one

struct Pool {
  std::mutex lock;
  std::vector<char*> regions;
  std::vector<char*> free;  // blocks of the regions not in use
  std::size_t inUse = 0;
};

// Never destroyed: a block freed by a static destructor still finds its pool.
Pool& pool() {
  static Pool* const p = new Pool;
  return *p;
}

// A region aligned to a huge page, so every one of its 2 MiB pages can be one (mmap aligns to 4 KiB only).
char* mapRegion() {
  void* raw = ::mmap(nullptr, kRegionBytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHugePage - 1) & ~(kHugePage - 1);
  if (aligned > start) ::munmap(raw, aligned - start);
  const std::uintptr_t end = start + kRegionBytes + kHugePage;
  if (end > aligned + kRegionBytes) ::munmap(reinterpret_cast<void*>(aligned + kRegionBytes), end - (aligned + kRegionBytes));
  char* region = reinterpret_cast<char*>(aligned);
  ::madvise(region, kRegionBytes, MADV_HUGEPAGE);  // advice only: without huge pages the blocks still work
  return region;
}

}  // namespace

void HugePageBlockFree::operator()(char* block) const noexcept {
  Pool& p = pool();
  const std::lock_guard<std::mutex> guard(p.lock);
  p.free.push_back(block);  // never grows: it had room for every block of the regions when they were mapped
  if (--p.inUse > 0) return;
  for (char* region : p.regions) ::munmap(region, kRegionBytes);
  p.regions.clear();
  p.free.clear();
}

HugePageBlock hugePageBlock() {
  Pool& p = pool();
  const std::lock_guard<std::mutex> guard(p.lock);
  if (p.free.empty()) {
    p.regions.reserve(p.regions.size() + 1);
    p.free.reserve((p.regions.size() + 1) * (kRegionBytes / kHugePageBlockBytes));  // the free list never allocates
    char* region = mapRegion();
    p.regions.push_back(region);
    for (std::size_t at = kRegionBytes; at > 0; at -= kHugePageBlockBytes) p.free.push_back(region + at - kHugePageBlockBytes);
  }
  char* block = p.free.back();
  p.free.pop_back();
  ++p.inUse;
  return HugePageBlock(block);
}

std::size_t hugePageBlockBytesMapped() {
  Pool& p = pool();
  const std::lock_guard<std::mutex> guard(p.lock);
  return p.regions.size() * kRegionBytes;
}

}  // namespace arbor
