#pragma once
// Work started beside the thread a result waits on (the crossing-twig search and the leaves' OBJ lines beside the
// mesher) runs at a lower priority: with more threads than cores it takes what that thread leaves, not a third of
// its core.
namespace arbor {

// Lowers the calling thread's priority (its nice value) for the rest of its life; nothing where the system refuses.
void runInBackground();

}  // namespace arbor
