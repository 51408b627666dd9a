// The CLI allocates with jemalloc on transparent huge pages (where CMake found jemalloc): a one-shot export
// touches some 100 MB of fresh memory, and on a virtual machine a 4 KiB page fault costs more than filling the
// page (Arbaro's tupelo file to OBJ: 23,000 faults and 0.60 s with glibc's malloc, 3,300 and 0.28 s here).
#include <jemalloc/jemalloc.h>

extern "C" {
// jemalloc reads its options from this symbol at start-up (MALLOC_CONF in the environment still overrides).
// One arena for all threads: an arena per thread (the export's printers, the card and texture threads) left a
// partly used huge page in each (tupelo to OBJ: 45 huge-page and 2,300 small faults, 40 and 1,470 with one).
const char* malloc_conf = "thp:always,metadata_thp:auto,narenas:1";
}

// No extent hooks: jemalloc's own merge and alloc hooks, called as custom ones, look up the thread's state in full,
// and a thread freeing memory as it exited (after that state was torn down) built it again and locked a mutex it
// already held (barley.xml to OBJ hung 4 times in 60). Aligning jemalloc's mappings to huge pages that way had
// saved shave-grass about 50 of its 340 page faults.
