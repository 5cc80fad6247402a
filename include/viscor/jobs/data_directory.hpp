// Where viscor's committed data is found (the certified tables, error maps and
// surrogates), the same for the command-line tool, the Python module and a C++
// program linked to viscor::jobs:
//   1. the directory given (--data, --error-maps, a scene's error_maps, an argument),
//   2. $VISCOR_DATA,
//   3. <prefix>/share/viscor next to the running executable (<prefix>/bin/viscor),
//   4. the installed share/viscor of the viscor a program was built against
//      (VISCOR_INSTALLED_DATA_DIR, set by the installed target viscor::jobs),
//   5. the source tree's reference_data/ for programs of the build tree
//      (VISCOR_SOURCE_DATA_DIR, set by viscor::jobs in the build tree only).
#pragma once

#include <viscor/core/exceptions.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace viscor::jobs {

/// The directory of the running executable ("" if unknown).
inline std::filesystem::path executable_directory() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

/// The data directory (see the file comment); throws naming every place tried.
inline std::string data_directory(const std::string& given = "") {
  namespace fs = std::filesystem;
  if (!given.empty()) {
    if (!fs::is_directory(given)) throw invalid_parameter(VISCOR_FIELD("data") ": '" + given + "' is not a directory");
    return given;
  }
  if (const char* env = std::getenv("VISCOR_DATA"); env && *env) {
    if (!fs::is_directory(env)) throw invalid_parameter(std::string("VISCOR_DATA: '") + env + "' is not a directory");
    return env;
  }
  std::string tried;
  if (const fs::path bin = executable_directory(); !bin.empty()) {
    const fs::path installed = bin.parent_path() / "share" / "viscor";
    if (fs::is_directory(installed)) return installed.string();
    tried = installed.string();
  }
#ifdef VISCOR_INSTALLED_DATA_DIR
  if (fs::is_directory(VISCOR_INSTALLED_DATA_DIR)) return VISCOR_INSTALLED_DATA_DIR;
  tried += std::string(tried.empty() ? "" : ", ") + VISCOR_INSTALLED_DATA_DIR;
#endif
#ifdef VISCOR_SOURCE_DATA_DIR
  if (fs::is_directory(VISCOR_SOURCE_DATA_DIR)) return VISCOR_SOURCE_DATA_DIR;
  tried += std::string(tried.empty() ? "" : ", ") + VISCOR_SOURCE_DATA_DIR;
#endif
  throw invalid_parameter("no data directory found (tried " + tried + "): give " VISCOR_FIELD("data")
                          " DIR or set VISCOR_DATA");
}

/// The error maps directory: <data>/error_maps, or "" when there is none.
inline std::string default_error_maps() {
  try {
    const std::filesystem::path maps = std::filesystem::path(data_directory()) / "error_maps";
    return std::filesystem::is_directory(maps) ? maps.string() : std::string();
  } catch (const invalid_parameter&) {
    return "";
  }
}

}  // namespace viscor::jobs
