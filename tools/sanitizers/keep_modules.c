/* Preloaded into sanitizer test runs (tools/test.sh --asan): dlclose does nothing, so that the Vulkan driver and
   LLVM stay mapped until the process ends and LeakSanitizer can name them in its reports (an unloaded library
   shows as "<unknown module>", which no suppression in lsan.supp can match). */
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
