// A CoR table as a gridded dataset: the one layout behind Python's
// Table.to_xarray() and `viscor table --format netcdf` (docs/tables.md, "NetCDF and
// xarray"). The rows of a table file become arrays over (law, g, gamma), or for a
// table from a spec in SI over (law, bead, wall, gravity, force, gamma0 or target_e,
// v0); the sidecar's provenance becomes attributes. Defined in src/jobs/table_dataset.cpp; the NetCDF
// form in jobs/netcdf_file.hpp.
#pragma once

#include <viscor/jobs/table_format.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace viscor::jobs {

/// One named array of the dataset, stored outermost dimension first.
struct dataset_array {
  /// What the values are.
  enum class type { float64, int32, text };
  std::string name;
  std::vector<std::string> dims;     ///< dimension names, outermost first
  type kind = type::float64;
  std::vector<double> numbers;       ///< kind float64: NaN where the table's field is empty
  std::vector<std::int32_t> integers;  ///< kind int32: -1 where the table's field is empty
  std::vector<std::string> texts;    ///< kind text
  std::vector<std::pair<std::string, std::string>> attributes;  ///< long_name, units, ...
};

/// A global attribute: text or a whole number.
using dataset_attribute = std::variant<std::string, std::int64_t>;

/// A complete CoR table over its axes.
struct table_dataset {
  std::vector<std::pair<std::string, std::size_t>> dimensions;  ///< law, g, gamma (or the axes in SI)
  std::vector<dataset_array> coordinates;  ///< the axes, and what rides on them (alpha, beta, exact decimals)
  std::vector<dataset_array> variables;    ///< over every dimension
  std::vector<std::pair<std::string, dataset_attribute>> attributes;  ///< provenance
};

/// The dataset of a table's text and its sidecar's text (both as published): every
/// row checked by the table's reader; refused (parse_error, naming the file) for a
/// sticking-threshold table, a shard or any table that is not a complete grid.
table_dataset table_dataset_of(const std::string& table_text, const std::string& sidecar_text,
                               const std::string& table_name);

/// The dataset of a table file and its sidecar (FILE.json), read and checked.
table_dataset read_table_dataset(const std::string& table_path);

/// How a decimal becomes a double: to nearest, or downwards or upwards (the bounds of
/// an enclosure stay bounds).
enum class rounding { nearest, down, up };
/// A decimal as a double, correctly rounded in `direction`; "inf" is infinite, "" is
/// NaN; anything else throws parse_error.
double decimal_to_double(const std::string& text, rounding direction);

}  // namespace viscor::jobs
