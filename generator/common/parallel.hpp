#pragma once
// A loop over count items shared by a few threads, for work whose items differ widely in cost.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace arbor {

// task(k, t) for every k < count on thread t of `threads` (this one is thread 0), each taking the next k in turn.
// A task's exception stops the others at their next k and is rethrown here once all have joined.
template <class Task>
void inParallel(std::size_t count, unsigned threads, Task&& task) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureLock;
  auto work = [&](unsigned t) {
    try {
      for (std::size_t k = next++; k < count; k = next++) task(k, t);
    } catch (...) {
      next = count;
      const std::lock_guard<std::mutex> lock(failureLock);
      if (!failure) failure = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);  // before any thread starts: only a thread's own start can fail below
  try {
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
  } catch (const std::system_error&) {
    // No more threads to be had: those started and this one share the work.
  }
  work(0);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

// How many threads `items` items are worth: one below `threadsFrom` (starting threads would cost more), else every
// core.
inline unsigned threadsFor(std::size_t items, std::size_t threadsFrom) {
  return items < threadsFrom ? 1u : std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
}

// task(begin, end) for consecutive runs of `run` of count items, shared by the cores where there are four runs or
// more.
template <class Task>
void inParallelRuns(std::size_t count, std::size_t run, Task&& task) {
  const std::size_t runs = (count + run - 1) / run;
  inParallel(runs, threadsFor(runs, 4), [&](std::size_t r, unsigned) { task(r * run, std::min(count, (r + 1) * run)); });
}

}  // namespace arbor
