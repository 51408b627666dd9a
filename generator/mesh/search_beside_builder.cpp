#include "search_beside_builder.hpp"

#include <system_error>

#include "common/background_thread.hpp"

namespace arbor {

SearchBesideBuilder::SearchBesideBuilder(const TreeMesh& tree, const Skeleton& skeleton, PairsToMendSearch& search)
    : tree_(tree), skeleton_(skeleton), search_(search) {}

SearchBesideBuilder::~SearchBesideBuilder() { stop(); }

void SearchBesideBuilder::settled(const MeshProgress& progress) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return;
    next_.push_back(progress);
  }
  if (!thread_.joinable() && std::thread::hardware_concurrency() >= 2) {
    try {
      thread_ = std::thread([this] { run(); });
    } catch (const std::system_error&) {
      // No thread to be had: the search is done after the mesher, as without this.
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
      return;
    }
  }
  wake_.notify_one();
}

void SearchBesideBuilder::stop() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
  if (failed_) search_ = PairsToMendSearch{};
}

void SearchBesideBuilder::run() {
  runInBackground();
  for (;;) {
    MeshProgress part;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !next_.empty(); });
      if (stopping_) return;
      part = next_.front();
      next_.pop_front();
    }
    try {
      search_.advance(tree_, skeleton_, part);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      failed_ = true;
      stopping_ = true;
      return;
    }
  }
}

}  // namespace arbor
