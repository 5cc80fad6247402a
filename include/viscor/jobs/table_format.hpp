// Tables of method "proven" (docs/tables.md): a CoR table whose rows
// carry, after the certified columns, those of a proof by viscor::enclose:
//   ...,digits,method,e_lower,e_upper,one_minus_e_lower,one_minus_e_upper,proven_digits,outcome_proven
// This header is the file format only (the columns, their reader, and the choice
// between the formats in table_format); it needs no Arb, so `table merge` reads
// proven tables in any build. The rows are computed in proven_rows.hpp.
//
// NOTE: in jobs/ on purpose: include/viscor/tables/ may not depend on the proofs
// (tools/check_layers.py), and the plain CoR format stays as it is.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/tables/reference_table.hpp>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace viscor::jobs {

/// The proof's columns, after the CoR columns.
inline const std::vector<std::string>& proven_columns() {
  static const std::vector<std::string> names{"e_lower",           "e_upper",       "one_minus_e_lower",
                                              "one_minus_e_upper", field::proven_digits, "outcome_proven"};
  return names;
}

/// Every column of a proven table: the CoR columns, then proven_columns().
inline const std::vector<std::string>& proven_table_columns() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> c = table_columns(table_kind::cor);
    c.insert(c.end(), proven_columns().begin(), proven_columns().end());
    return c;
  }();
  return all;
}

/// The header line of a proven table (without '\n').
inline std::string proven_table_header() {
  std::string s;
  for (const auto& c : proven_table_columns()) s += (s.empty() ? "" : ",") + c;
  return s;
}

/// Refuses (invalid_parameter, exit 2) a law the proof cannot handle, naming the
/// exponent (contact_law::why_not_provable), before any work.
inline void require_provable(const contact_law& law, const std::string& where) {
  if (const std::string why = law.why_not_provable(); !why.empty())
    throw invalid_parameter(where + ": " + why + "; use method \"certify\" for this law");
}

namespace detail {

/// The decimal exponent of the leading non-zero digit of a decimal text
/// ("9.6e-01" -> -1, "0.05" -> -2, "12" -> 1); nullopt for zero.
inline std::optional<int> leading_exponent(const std::string& text) {
  const std::size_t e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
  int integer_digits = 0;
  for (char c : mantissa) {
    if (c == '.') break;
    integer_digits += c >= '0' && c <= '9';
  }
  int k = 0;  // position among the digits
  for (char c : mantissa) {
    if (c < '0' || c > '9') continue;
    if (c != '0') return exponent + integer_digits - 1 - k;
    ++k;
  }
  return std::nullopt;
}

/// Whether the decimal `value`, certified to `digits` significant digits, lies within
/// one unit of its last digit of [lower, upper] (a zero value: inside it). The
/// certificate claims less than half a unit of error after rounding, so a value
/// further out means that the certificate or the proof is wrong.
inline bool within_last_digit(const std::string& value, int digits, const std::string& lower,
                              const std::string& upper) {
  using viscor::detail::exact_decimal;
  const exact_decimal x = exact_decimal::parse(value, "certified value");
  const std::optional<int> lead = leading_exponent(value);
  const exact_decimal unit = lead ? exact_decimal(1, *lead - digits + 1) : exact_decimal(0, 0);
  return exact_decimal::parse(lower, "lower bound") - unit <= x && x <= exact_decimal::parse(upper, "upper bound") + unit;
}

/// Checks the proof's fields of one row (columns from `first` on); errors name file, line and field.
inline void check_proven_fields(const viscor::detail::row_checker& c, std::size_t first) {
  const std::size_t e_lo = first, e_hi = first + 1, d_lo = first + 2, d_hi = first + 3, digits = first + 4,
                    outcome = first + 5;
  c.one_of(outcome, {"rebound", "stick", "undecided"});
  c.integer(digits, max_working_digits);
  if (c.at(outcome) == "undecided") {
    for (std::size_t k = e_lo; k <= d_hi; ++k)
      if (!c.at(k).empty()) c.fail(k, "an undecided proof has no bounds (empty field)");
    if (c.at(digits) != "0") c.fail(digits, "an undecided proof has 0 proven digits");
    return;
  }
  if (c.at(outcome) != c.at(6)) c.fail(outcome, "contradicts the certified outcome '" + c.at(6) + "'");
  for (const auto& [lo, hi] : {std::pair{e_lo, e_hi}, std::pair{d_lo, d_hi}})
    if (!(c.decimal(lo) <= c.decimal(hi))) c.fail(hi, "the upper bound is below the lower bound");
  // The row must agree with itself: the certified e and 1 - e lie in their proven
  // enclosures to within a unit of their last certified digit (as proven_rows.hpp
  // checks when it writes them), and the enclosure is narrow enough for the proven
  // digits it claims (both ends round to the same d-digit decimal, so they are
  // within one unit of the d-th digit).
  const int certified = static_cast<int>(c.integer(11, max_working_digits));
  for (const auto& [value, lo, hi] : {std::tuple{std::size_t(7), e_lo, e_hi}, std::tuple{std::size_t(8), d_lo, d_hi}})
    if (!within_last_digit(c.at(value), certified, c.at(lo), c.at(hi)))
      c.fail(value, "lies outside its own proven enclosure [" + c.at(lo) + ", " + c.at(hi) + "] by more than a unit "
                    "of its last certified digit");
  const int proven = static_cast<int>(c.integer(digits, max_working_digits));
  if (proven > 0) {
    using viscor::detail::exact_decimal;
    const std::optional<int> lead = leading_exponent(c.at(e_hi));
    const exact_decimal unit = lead ? exact_decimal(1, *lead - proven + 1) : exact_decimal(0, 0);
    if (exact_decimal::parse(c.at(e_hi), "e_upper") - exact_decimal::parse(c.at(e_lo), "e_lower") > unit)
      c.fail(digits, "claims " + c.at(digits) + " proven digits, but the enclosure of e is wider than a unit of "
                     "that digit");
  }
}

}  // namespace detail

/// The physical columns of a table from a spec in SI (physical_grid.hpp), after the
/// CoR columns: the row's inputs as given (empty: not given) and, last, the contact
/// time and the maximal compression in seconds and metres.
inline const std::vector<std::string>& physical_columns() {
  static const std::vector<std::string> names{
      "bead",          "m",           "k",           "youngs_modulus", "poisson_ratio", "radius",
      "density",       "contact",     "wall",        "wall_youngs_modulus", "wall_poisson_ratio",
      "other_youngs_modulus", "other_poisson_ratio", "other_radius", "other_density", "v0",
      "gamma0",        "target_e",    "gravity",     "force",       "contact_time_s", "max_compression_m"};
  return names;
}

/// How many of physical_columns() are the row's inputs (the rest are its results in SI).
inline constexpr std::size_t physical_input_columns = 20;
/// The positions of gamma0 and target_e among physical_columns(): with a target,
/// gamma0 is the row's calibrated result, not an input.
inline constexpr std::size_t physical_gamma0_column = 16, physical_target_e_column = 17;

namespace detail {

/// The CoR columns followed by `extra`.
inline std::vector<std::string> cor_columns_and(const std::vector<std::string>& extra) {
  std::vector<std::string> c = table_columns(table_kind::cor);
  c.insert(c.end(), extra.begin(), extra.end());
  return c;
}

inline std::string header_of(const std::vector<std::string>& columns) {
  std::string s;
  for (const auto& c : columns) s += (s.empty() ? "" : ",") + c;
  return s;
}

/// Checks the physical fields of one row (columns from `first` on).
inline void check_physical_fields(const viscor::detail::row_checker& c, std::size_t first) {
  const auto name = [&](std::size_t k) {
    if (c.at(k).empty() ||
        c.at(k).find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.+-") !=
            std::string::npos)
      c.fail(k, "must be a name of letters, digits, '_', '.', '+' or '-'");
  };
  const auto optional_decimal = [&](std::size_t k) {
    if (!c.at(k).empty()) c.decimal(k);
  };
  name(first);
  for (std::size_t k = first + 1; k <= first + 6; ++k) optional_decimal(k);  // m .. density
  c.one_of(first + 7, {"wall", "pair"});
  name(first + 8);
  for (std::size_t k = first + 9; k <= first + 14; ++k) optional_decimal(k);  // wall_* and other_*
  for (std::size_t k = first + 15; k < first + physical_input_columns; ++k)  // v0, gamma0, target_e, gravity, force
    if (k != first + physical_target_e_column) c.decimal(k);
  optional_decimal(first + physical_target_e_column);
  c.optional_non_negative(first + physical_input_columns);
  c.optional_non_negative(first + physical_input_columns + 1);
}

/// Parses a CoR table whose rows carry `columns` (the CoR ones, then others): the
/// CoR fields checked by parse_table, the others by check_extra(row_checker, first
/// column), then the sum e + (1 - e). `what` names the format in errors.
template <class CheckExtra>
csv_table parse_extended_table(const std::string& text, const std::string& file, bool allow_truncated_tail,
                               const std::vector<std::string>& columns, const std::string& what,
                               CheckExtra check_extra) {
  const std::size_t n_cor = table_columns(table_kind::cor).size();
  const std::string header = header_of(columns);
  std::string cor_text;  // the same lines cut to the CoR columns, for parse_table
  std::vector<std::string> lines;
  bool have_header = false;
  const bool truncated = viscor::detail::for_each_table_line(
      text, file, allow_truncated_tail, [&](std::string line, std::size_t, const std::string& where) {
        if (!have_header) {
          if (line != header)
            throw parse_error(where + ": wrong columns: expected '" + header + "' (" + what + "), got '" + line + "'");
          cor_text += table_header(table_kind::cor) + "\n";
          have_header = true;
          return;
        }
        const std::vector<std::string> fields = viscor::split_fields(line);
        if (fields.size() != columns.size())
          throw parse_error(where + ": expected " + std::to_string(columns.size()) + " fields (" + header +
                            "), got " + std::to_string(fields.size()) +
                            (fields.size() < columns.size() ? " (truncated row?)" : ""));
        std::string cor_line;
        for (std::size_t k = 0; k < n_cor; ++k) cor_line += (k ? "," : "") + fields[k];
        cor_text += cor_line + "\n";
        lines.push_back(std::move(line));
      });
  if (!have_header) throw parse_error(file + ":1: empty file: no header line");
  csv_table table = parse_table(cor_text, file, false, cor_sum_check::by_caller);
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    csv_record& row = table.rows[i];
    row.text = lines[i];
    row.fields = viscor::split_fields(row.text);
    const viscor::detail::row_checker check(file, row.line, columns, row.fields);
    check_extra(check, n_cor);  // first: a value outside its enclosure says more than a sum
    viscor::detail::check_cor_sum(check);
  }
  table.truncated_tail = truncated;
  return table;
}

}  // namespace detail

/// Every column of a table from a spec in SI: the CoR columns, then physical_columns().
inline const std::vector<std::string>& physical_table_columns() {
  static const std::vector<std::string> all = detail::cor_columns_and(physical_columns());
  return all;
}

/// Parses and validates a proven table (see parse_table of reference_table.hpp:
/// the same rules, the CoR fields checked by it, the proof's fields here).
inline csv_table parse_proven_table(const std::string& text, const std::string& file,
                                    bool allow_truncated_tail = false) {
  return detail::parse_extended_table(text, file, allow_truncated_tail, proven_table_columns(),
                                      "a table of method proven", detail::check_proven_fields);
}

/// Parses and validates a table from a spec in SI (the CoR fields by parse_table, the
/// physical fields here).
inline csv_table parse_physical_table(const std::string& text, const std::string& file,
                                      bool allow_truncated_tail = false) {
  return detail::parse_extended_table(text, file, allow_truncated_tail, physical_table_columns(),
                                      "a table from a spec in SI", detail::check_physical_fields);
}

/// The sidecar's summary of a proven table's rows: the proven outcomes, and the
/// proven digits of e against the certified digits.
inline json proof_summary(const std::vector<csv_record>& rows) {
  const std::size_t n_cor = table_columns(table_kind::cor).size(), certified_digits = n_cor - 2;
  std::size_t rebound = 0, stick = 0, undecided = 0, at_least_certified = 0;
  int least = -1;
  for (const auto& row : rows) {
    const std::string& outcome = row.fields[n_cor + 5];
    const int proven = std::stoi(row.fields[n_cor + 4]), certified = std::stoi(row.fields[certified_digits]);
    if (outcome == "undecided") {
      ++undecided;
      continue;
    }
    ++(outcome == "rebound" ? rebound : stick);
    least = least < 0 ? proven : std::min(least, proven);
    at_least_certified += proven >= certified;
  }
  return {{"rows_by_outcome_proven", {{"rebound", rebound}, {"stick", stick}, {"undecided", undecided}}},
          {"least_proven_digits", least < 0 ? json(nullptr) : json(least)},
          {"rows_with_proven_digits_at_least_certified", at_least_certified}};
}

/// The file format of a table: a CoR or sticking table of reference_table.hpp, or a
/// CoR table with the proof's columns (method "proven").
struct table_format {
  table_kind kind = table_kind::cor;
  bool proven = false;
  bool physical = false;  ///< a CoR table from a spec in SI: physical_columns() after the CoR ones

  /// The header line (without '\n').
  std::string header() const {
    return proven ? proven_table_header() : physical ? detail::header_of(physical_table_columns()) : table_header(kind);
  }
  /// Index of the `method` column (exact or certified).
  std::size_t method_column() const { return table_columns(kind).size() - 1; }

  /// Parses and validates a table of this format.
  csv_table parse(const std::string& text, const std::string& file, bool allow_truncated_tail = false) const {
    return proven     ? parse_proven_table(text, file, allow_truncated_tail)
           : physical ? parse_physical_table(text, file, allow_truncated_tail)
                      : parse_table(text, file, allow_truncated_tail);
  }
  /// What names a row's point, to compare with the point its index names (resume,
  /// merge): grid_key of reference_table.hpp, or for a table in SI the law and the
  /// physical inputs (the scaled gamma and g follow from them).
  std::string key(const csv_record& row) const {
    if (!physical) return grid_key(row, kind);
    const std::size_t first = table_columns(table_kind::cor).size();
    const bool calibrated = !row.fields.at(first + physical_target_e_column).empty();
    std::string k = row.fields.at(1) + "," + row.fields.at(2) + "," + row.fields.at(3);
    for (std::size_t c = first; c < first + physical_input_columns; ++c)
      k += "," + (calibrated && c == first + physical_gamma0_column ? std::string() : row.fields.at(c));
    return k;
  }
  /// Reads and validates a table file of this format.
  csv_table read(const std::string& path, bool allow_truncated_tail = false) const {
    return parse(file_text(path), path, allow_truncated_tail);
  }
  /// The canonical text: header, then rows sorted by index (duplicates: parse_error).
  std::string text(std::vector<csv_record> rows, const std::string& file) const {
    const std::string body = table_text(kind, std::move(rows), file);
    return header() + body.substr(body.find('\n'));
  }

  /// The format of a table file, from its header line (the plain formats' reader
  /// reports any other header).
  static table_format of_file(const std::string& path) { return of_text(file_text(path)); }
  /// The format of a table's text, from its header line.
  static table_format of_text(const std::string& text) {
    const std::string first = text.substr(0, text.find('\n'));
    if (first == proven_table_header()) return {table_kind::cor, true};
    if (first == detail::header_of(physical_table_columns())) return {table_kind::cor, false, true};
    if (first == table_header(table_kind::sticking)) return {table_kind::sticking, false};
    return {table_kind::cor, false};  // read() names any other header
  }

 private:
  static std::string file_text(const std::string& path) {  // checked against a manifest (core/checksums.hpp)
    return read_checked_file<error>(path, "table");
  }
};

}  // namespace viscor::jobs
