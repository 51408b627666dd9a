// hugePageBlock: distinct, whole, huge-page-aligned blocks from any thread, and every region handed back to the
// system once the last block is freed (a viewer that exports keeps no printing memory afterwards).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <set>
#include <thread>
#include <vector>

#include "common/huge_page_blocks.hpp"

using namespace arbor;

TEST_CASE("huge-page blocks are distinct, whole and given back when the last is freed", "[parallel]") {
  REQUIRE(hugePageBlockBytesMapped() == 0);
  {
    // More blocks than one region holds, from two threads at once, each filled with its own byte.
    std::vector<HugePageBlock> blocks(40);
    std::thread other([&] {
      for (std::size_t i = 0; i < blocks.size(); i += 2) blocks[i] = hugePageBlock();
    });
    for (std::size_t i = 1; i < blocks.size(); i += 2) blocks[i] = hugePageBlock();
    other.join();
    std::set<const char*> starts;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      REQUIRE(blocks[i] != nullptr);
      starts.insert(blocks[i].get());
      CHECK(reinterpret_cast<std::uintptr_t>(blocks[i].get()) % kHugePageBlockBytes == 0);
      std::memset(blocks[i].get(), static_cast<int>(i), kHugePageBlockBytes);
    }
    CHECK(starts.size() == blocks.size());
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      const char* b = blocks[i].get();
      CHECK((b[0] == static_cast<char>(i) && b[kHugePageBlockBytes - 1] == static_cast<char>(i)));
    }
    CHECK(hugePageBlockBytesMapped() >= blocks.size() * kHugePageBlockBytes);
    // A freed block is handed out again while others are in use; the regions stay.
    const char* freed = blocks[7].get();
    blocks[7].reset();
    blocks[7] = hugePageBlock();
    CHECK(blocks[7].get() == freed);
  }
  CHECK(hugePageBlockBytesMapped() == 0);
  HugePageBlock again = hugePageBlock();
  CHECK(again != nullptr);
  again.reset();
  CHECK(hugePageBlockBytesMapped() == 0);
}
