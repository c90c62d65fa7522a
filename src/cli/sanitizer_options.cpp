// LeakSanitizer settings for sanitizer builds, linked into the `unidyn` command, every test and
// the fuzz targets: CLN (Debian 1.3.6) leaks 26 bytes while it initialises, which must not count
// as a leak, and the report of suppressions used must not reach standard error (the CLI's tests
// read it).
#include "sanitizers.hpp"

#if defined(UNIDYN_ADDRESS_SANITIZER)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libcln.so\n";
}
extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
#endif
