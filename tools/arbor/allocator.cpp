// The CLI allocates with jemalloc on transparent huge pages (where CMake found jemalloc): a one-shot export
// touches some 100 MB of fresh memory, and on a virtual machine a 4 KiB page fault costs more than filling the
// page (Arbaro's tupelo file to OBJ: 23,000 faults and 0.60 s with glibc's malloc, 3,300 and 0.28 s here).
extern "C" {
// jemalloc reads its options from this symbol at start-up (MALLOC_CONF in the environment still overrides).
const char* malloc_conf = "thp:always,metadata_thp:auto";
}
