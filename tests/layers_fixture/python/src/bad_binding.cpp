// A binding that reaches into the command-line tool (check_layers must refuse it).
#include "cli_common.hpp"
