// Under AddressSanitizer, leak checking is off for programs that load a Vulkan driver: lavapipe's LLVM and the
// loader keep allocations alive to exit on purpose, in code without frame pointers that no suppression can
// name. Only compiled into sanitizer builds (GCC and clang define __SANITIZE_ADDRESS__ / has_feature).
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }
#endif
