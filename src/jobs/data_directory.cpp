// Where viscor's data is found (include/viscor/jobs/data_directory.hpp). The two
// built-in places come from the build: VISCOR_INSTALLED_DATA_DIR and
// VISCOR_SOURCE_DATA_DIR (CMakeLists.txt, target viscor_jobs).
#include <viscor/jobs/data_directory.hpp>

#include <viscor/core/exceptions.hpp>

#include <cstdlib>
#include <system_error>

namespace viscor::jobs {

// The directory of the running executable ("" if unknown).
std::filesystem::path executable_directory() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

// The data directory (see the file comment); throws naming every place tried.
std::string data_directory(const std::string& given) {
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

// The error maps directory: <data>/error_maps, or "" when there is none.
std::string default_error_maps() {
  try {
    const std::filesystem::path maps = std::filesystem::path(data_directory()) / "error_maps";
    return std::filesystem::is_directory(maps) ? maps.string() : std::string();
  } catch (const invalid_parameter&) {
    return "";
  }
}

}  // namespace viscor::jobs
