// The committed CoR surrogates exported as self-contained C99 (a header and a source,
// for every law in one pair): e(gamma, g), 1 - e, the outcome and the sticking
// threshold, the inverse gamma(e, g), the stated bound, and physical entry points
// (mass, stiffness, impact speed, gravity or force, target e -> damping coefficient).
// The C evaluation is the library's (surrogate/cor_surrogate.hpp, chebyshev.hpp)
// operation for operation: every Clenshaw step one fma, the patch found by the
// walk down the same k-d tree (the library's grid returns the same patch), the
// same libm calls, so the results are the library's to the last bit wherever the
// C compiler does not contract a product and a sum on its own (docs/surrogate.md,
// "Exporting to C"). The export is deterministic: no date, path or commit, only the
// source files' names and SHA-256, so a committed export can be checked against a
// fresh one (examples/c_export/). Defined in src/jobs/surrogate_export.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace viscor::jobs {

/// What to export: the laws (empty or {"all"}: every named law with a committed
/// surrogate), from which directory, in which language, to which directory.
struct surrogate_export_options {
  std::string language = "c";          ///< only "c" (C99, also valid C++)
  std::vector<std::string> laws;       ///< law names; empty or {"all"}: all named laws with a surrogate file
  std::string surrogate_directory;     ///< where <law>.surrogate and its verification table are
  std::string output_directory;        ///< created if absent
};

/// One exported file: its name (no directory) and its content.
struct exported_file {
  std::string name;  ///< e.g. viscor_surrogates.h
  std::string text;  ///< the whole file
};

/// The exported files (header first) for `options`, without writing anything: a C99
/// header and source holding every requested law (docs/surrogate.md, "Exporting to C").
/// Throws invalid_parameter for an unknown language or law, parse_error for a bad file.
std::vector<exported_file> surrogate_export_files(const surrogate_export_options& options);

/// The first bytes of an exported file named `name`: with its seal, what
/// export_surrogates takes as proof that viscor wrote the file it replaces.
std::string exported_file_marker(const std::string& name);

/// The largest exported file (all five laws: about 2 MB).
inline constexpr std::uintmax_t max_exported_file_size = std::uintmax_t(64) << 20;

/// Writes the files of surrogate_export_files into options.output_directory (created
/// if absent). A file there is replaced only when it is an unedited export (its seal
/// matches: is_unedited_viscor_file); the .h and the .c are checked before either is
/// written and published together (write_together). Returns their paths.
std::vector<std::string> export_surrogates(const surrogate_export_options& options);

}  // namespace viscor::jobs
