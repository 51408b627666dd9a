#include "background_thread.hpp"

#include <sys/resource.h>
#include <unistd.h>

namespace arbor {

namespace {
// Weight 335 against the default's 1024: two such threads beside one at the default leave it its whole core, and one
// that a thread waits on is at worst a third as fast on a loaded machine, not a seventieth as at nice 19.
constexpr int kBackgroundNice = 5;
}  // namespace

void runInBackground() {
  // On Linux a thread id names one thread to setpriority, not its whole process.
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kBackgroundNice);
}

}  // namespace arbor
