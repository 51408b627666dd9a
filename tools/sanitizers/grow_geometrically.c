/* Preloaded into sanitizer test runs (tools/test.sh --asan): large reallocations grow by half again instead of
   by what was asked. Lavapipe grows a draw's tessellation output by one realloc per patch (4 KB onto 1.6 MB);
   glibc moves such blocks by remapping pages, but AddressSanitizer copies them into fresh pages every time,
   which made one render test run for 19 minutes instead of one. The spare tail is poisoned, so an overflow
   into it is still reported (as use-after-poison). In a process without AddressSanitizer (ctest, Blender) it
   is the next realloc unchanged: Blender's is jemalloc's, not glibc's. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>
#include <string.h>

void* malloc(size_t size);
void free(void* block);

/* Weak: absent (null) in processes without AddressSanitizer. */
extern void* __interceptor_realloc(void* block, size_t size) __attribute__((weak));
extern int __sanitizer_get_ownership(const volatile void* block) __attribute__((weak));
extern size_t __sanitizer_get_allocated_size(const volatile void* block) __attribute__((weak));
extern void __asan_poison_memory_region(const volatile void* start, size_t size) __attribute__((weak));
extern void __asan_unpoison_memory_region(const volatile void* start, size_t size) __attribute__((weak));

enum { kLargeBlock = 1 << 16 };  /* smaller blocks keep the sanitizer's exact realloc */

static void keepOnly(void* block, size_t size, size_t capacity) {
  __asan_unpoison_memory_region(block, size);
  __asan_poison_memory_region((char*)block + size, capacity - size);
}

void* realloc(void* block, size_t size) {
  if (__interceptor_realloc == NULL) {
    static void* (*next)(void*, size_t) = NULL;  /* threads may race to look it up; all find the same one */
    void* (*found)(void*, size_t) = __atomic_load_n(&next, __ATOMIC_ACQUIRE);
    if (found == NULL) {
      found = (void* (*)(void*, size_t))dlsym(RTLD_NEXT, "realloc");
      __atomic_store_n(&next, found, __ATOMIC_RELEASE);
    }
    return found(block, size);
  }
  if (block == NULL || size < kLargeBlock || !__sanitizer_get_ownership(block)) {
    return __interceptor_realloc(block, size);
  }
  /* The sanitizer's size of a block this grew is its capacity; the bytes past what was last asked are poisoned. */
  const size_t capacity = __sanitizer_get_allocated_size(block);
  if (size <= capacity) {
    keepOnly(block, size, capacity);
    return block;
  }
  const size_t grown = capacity + capacity / 2 > size ? capacity + capacity / 2 : size;
  void* moved = malloc(grown);
  if (moved == NULL) return NULL;
  __asan_unpoison_memory_region(block, capacity);
  memcpy(moved, block, capacity);
  free(block);
  keepOnly(moved, size, grown);
  return moved;
}
