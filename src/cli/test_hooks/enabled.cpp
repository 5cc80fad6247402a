// The test seams of src/cli/test_hooks.hpp, enabled: linked only into the test
// binary viscor_test_hooks (tests/table_cli_test.cpp interrupts and resumes tables).
#include "../test_hooks.hpp"

#include <cstdlib>

namespace viscor::cli::test_hooks {

long long table_stop_after_rows() {
  const char* s = std::getenv("VISCOR_TABLE_STOP_AFTER");
  return s ? std::atoll(s) : -1;
}

std::string certified_e_shift() {
  const char* s = std::getenv("VISCOR_TABLE_SHIFT_CERTIFIED_E");
  return s ? s : "";
}

}  // namespace viscor::cli::test_hooks
