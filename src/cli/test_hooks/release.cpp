// The test seams of src/cli/test_hooks.hpp, inert: linked into the released viscor.
#include "../test_hooks.hpp"

namespace viscor::cli::test_hooks {

long long table_stop_after_rows() { return -1; }

std::string certified_e_shift() { return ""; }

}  // namespace viscor::cli::test_hooks
