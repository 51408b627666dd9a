#pragma once
// Blocks of fresh memory on transparent huge pages, for text printed once and then written out. On a virtual machine
// every 4 KiB page faulted in costs tens of microseconds; a 2 MiB page costs about as much as one of them.
#include <cstddef>
#include <memory>

namespace arbor {

inline constexpr std::size_t kHugePageBlockBytes = std::size_t{512} << 10;

struct HugePageBlockFree {
  void operator()(char* block) const noexcept;
};
using HugePageBlock = std::unique_ptr<char[], HugePageBlockFree>;

// kHugePageBlockBytes of memory, not yet touched, from 2 MiB-aligned regions advised for huge pages (plain pages
// where the system has them off). Thread-safe; throws std::bad_alloc. The regions go back to the system when the
// last block is freed, so a long-lived process keeps none between exports.
HugePageBlock hugePageBlock();

// Bytes of regions mapped now (for tests: 0 once every block is freed).
std::size_t hugePageBlockBytesMapped();

}  // namespace arbor
