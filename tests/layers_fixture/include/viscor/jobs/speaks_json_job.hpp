// Fixture for check_layers: a job whose result is JSON instead of a typed result.
#pragma once

#include <nlohmann/json.hpp>

namespace viscor::jobs {
inline nlohmann::ordered_json run_speaks_json() { return {}; }
}  // namespace viscor::jobs
