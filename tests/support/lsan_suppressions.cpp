// CLN (Debian 1.3.6) leaks 26 bytes while it initialises; LeakSanitizer must not count that.
// Linked into every test executable (and the `unidyn` command has the same).
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libcln.so\n";
}
#endif
