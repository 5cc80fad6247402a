// Test seams of the command-line tool. The released `viscor` links
// test_hooks/release.cpp, in which every seam is inert; the test-only binary
// `viscor_test_hooks` (built with the tests, never installed) links
// test_hooks/enabled.cpp instead. So no environment variable changes what a
// released viscor does.
#pragma once

namespace viscor::cli::test_hooks {

/// Rows of this session after which `viscor table` interrupts itself (raise(SIGINT),
/// like a Ctrl-C); -1: never. Enabled binary: the environment variable
/// VISCOR_TABLE_STOP_AFTER.
long long table_stop_after_rows();

}  // namespace viscor::cli::test_hooks
