// Where viscor's committed data is found (the certified tables, error maps and
// surrogates), the same for the command-line tool, the Python module and a C++
// program linked to viscor::jobs:
//   1. the directory given (--data, --error-maps, a scene's error_maps, an argument),
//   2. $VISCOR_DATA,
//   3. <prefix>/share/viscor next to the running executable (<prefix>/bin/viscor),
//   4. share/viscor under the install prefix viscor was configured with
//      (CMAKE_INSTALL_PREFIX; an install elsewhere with `cmake --install --prefix`
//      needs 1, 2 or 3),
//   5. the source tree's reference_data/, for the programs of the build tree.
// Compiled into viscor::jobs (src/jobs/data_directory.cpp), which knows 4 and 5.
#pragma once

#include <filesystem>
#include <string>

namespace viscor::jobs {

/// The directory of the running executable ("" if unknown).
std::filesystem::path executable_directory();

/// The data directory (see the file comment); throws naming every place tried.
std::string data_directory(const std::string& given = "");

/// The error maps directory: <data>/error_maps, or "" when there is none.
std::string default_error_maps();

}  // namespace viscor::jobs
