#pragma once
// The crossing-twig search (PairsToMendSearch) on another core while the mesher builds: told which part of the mesh
// is final, it searches that part while the mesher goes on with the next (the search had 45 ms of the tupelo file's
// 200 after the mesher's 80, while the second core idled through most of them).
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "growth/skeleton.hpp"
#include "self_intersection.hpp"
#include "tree_mesh.hpp"

namespace arbor {

class SearchBesideBuilder {
 public:
  // `tree` is the mesh being built; it stays where it is until stop() (the search keeps only indices).
  SearchBesideBuilder(const TreeMesh& tree, const Skeleton& skeleton, PairsToMendSearch& search);
  ~SearchBesideBuilder();
  SearchBesideBuilder(const SearchBesideBuilder&) = delete;
  SearchBesideBuilder& operator=(const SearchBesideBuilder&) = delete;

  // The mesh up to `progress` is final (PairsToMendSearch::advance's promise): searched after the parts settled
  // before it. The first call starts the thread (none on a one-core machine).
  void settled(const MeshProgress& progress);
  // Waits for the part in hand and searches nothing more: before the mesher moves a vector the search reads, and
  // once it is done. A search that failed (out of memory) is dropped, so finish() searches the whole mesh.
  void stop();

 private:
  void run();

  const TreeMesh& tree_;
  const Skeleton& skeleton_;
  PairsToMendSearch& search_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<MeshProgress> next_;  // one part at a time: a part in hand when the mesher ends is waited for
  bool stopping_ = false;
  bool failed_ = false;
  std::thread thread_;
};

}  // namespace arbor
