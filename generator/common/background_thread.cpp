#include "background_thread.hpp"

#include <sys/resource.h>
#include <unistd.h>

namespace arbor {

namespace {
// Far enough below the default (0) that a thread waited on keeps its core; the most an unprivileged thread may take.
constexpr int kBackgroundNice = 19;
}  // namespace

void runInBackground() {
  // On Linux a thread id names one thread to setpriority, not its whole process.
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kBackgroundNice);
}

}  // namespace arbor
