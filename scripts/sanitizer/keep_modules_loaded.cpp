// Preloaded (LD_PRELOAD) into every process of the sanitize stage: dlclose() leaves the library
// mapped. The Vulkan loader unloads the driver and the validation layers at vkDestroyInstance;
// what they still hold then is reported by LeakSanitizer at exit with frames in "<unknown
// module>", which no suppression can name. Kept mapped, those frames name the library, and
// scripts/sanitizer/lsan.supp suppresses exactly those libraries. Built uninstrumented, because
// the tests' child processes (the shell, the CLI) inherit LD_PRELOAD.
extern "C" int dlclose(void*) { return 0; }
