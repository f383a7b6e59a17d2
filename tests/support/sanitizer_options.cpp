// Sanitizer builds: the options every test program runs with, whether ctest
// or a person starts it. ctest's ENVIRONMENT property cannot carry these to
// the tests gtest_discover_tests adds (its PROPERTIES lose a list's
// separators, so only the first variable arrived and tests/lsan.supp was never
// read), so the sanitizers' runtimes take them from these functions instead.
extern "C" const char* __asan_default_options() { return "intercept_tls_get_addr=0"; }
extern "C" const char* __lsan_default_options() { return "suppressions=" ATRIUM_LSAN_SUPPRESSIONS ":print_suppressions=0"; }
extern "C" const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }
