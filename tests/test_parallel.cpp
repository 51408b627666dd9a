// inParallel: every item once, on the threads asked for; a task's exception reaches the caller after every thread
// has joined (a throwing task used to end the process with std::terminate).
#include <catch2/catch.hpp>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "common/parallel.hpp"

using namespace arbor;

TEST_CASE("inParallel hands every item to exactly one of its threads", "[parallel]") {
  for (unsigned threads : {1u, 2u, 5u}) {
    std::vector<std::atomic<int>> seen(10000);
    std::vector<std::atomic<int>> byThread(threads);
    std::atomic<bool> threadInRange{true};
    inParallel(seen.size(), threads, [&](std::size_t k, unsigned t) {
      if (t >= threads) threadInRange = false;
      else ++byThread[t];
      ++seen[k];
    });
    CHECK(threadInRange);
    for (const auto& s : seen) REQUIRE(s == 1);
    int total = 0;
    for (const auto& b : byThread) total += b;
    CHECK(total == 10000);
  }
}

TEST_CASE("inParallel rethrows a task's exception once its threads have joined", "[parallel]") {
  try {
    inParallel(100000, 4, [&](std::size_t k, unsigned) {
      if (k == 37) throw std::runtime_error("item 37 failed");
    });
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "item 37 failed");
  }
}
