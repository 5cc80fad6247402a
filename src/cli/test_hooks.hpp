// Test seams of the command-line tool. The released `viscor` links
// test_hooks/release.cpp, in which every seam is inert; the test-only binary
// `viscor_test_hooks` (built with the tests, never installed) links
// test_hooks/enabled.cpp instead. So no environment variable changes what a
// released viscor does.
#pragma once

#include <string>

namespace viscor::cli::test_hooks {

/// Rows of this session after which `viscor table` interrupts itself (raise(SIGINT),
/// like a Ctrl-C); -1: never. Enabled binary: the environment variable
/// VISCOR_TABLE_STOP_AFTER.
long long table_stop_after_rows();

/// A decimal added to the certified e of every row of a `proven` table before it is
/// checked against the proof (proven_rows.hpp), so that tests can show the check
/// stops a run; "" (none). Enabled binary: VISCOR_TABLE_SHIFT_CERTIFIED_E.
std::string certified_e_shift();

}  // namespace viscor::cli::test_hooks
