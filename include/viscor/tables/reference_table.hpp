// Reference tables as CSV: the row format, the writer, and a reader that
// validates every field and names file, line and field in its errors.
//
// Format (RFC 4180 subset: no quoting, no field ever holds a comma or a quote):
//   line 1  the header, exactly the column names below
//   then    one row per grid point, sorted by `index`, each ending in '\n'
// CoR tables:
//   index,law,alpha,beta,gamma,g,outcome,e,one_minus_e,contact_time,max_compression,digits,method
// Sticking-threshold tables:
//   index,law,alpha,beta,solve_for,gamma,g,rebound_at,stick_at,digits,method
// `index` is the row's position in the full grid of the spec, so shards and
// resumed runs sort into the same table. alpha and beta are exact ("3/2"),
// gamma and g exact decimals (except the solved-for threshold column); results
// are rounded to `digits` certified significant digits. "0" and "1" are exact
// (e = 0 for a certified stick, e = 1 at gamma = 0); an empty field means "not
// available"; "inf" is a contact that never ends. The CSV holds no timing, so a
// table is a deterministic function of its spec and the viscor version.
// NOTE: this header only reads and writes tables; computing rows is
// table_row.hpp, so readers of committed tables do not compile the solvers.
#pragma once

#include <viscor/core/checksums.hpp>
#include <viscor/core/field_names.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/core/text_fields.hpp>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace viscor {

/// Where a row's numbers come from ("exact" or "certified" in the CSV).
enum class row_source { exact, certified };

/// The source's name as in a table's source column.
inline std::string to_string(row_source s) { return s == row_source::exact ? "exact" : "certified"; }

/// Human-readable method, for sidecars.
inline std::string describe(row_source s) {
  return s == row_source::exact ? "exact closed form evaluated at the working precision (viscor::exact_cor); "
                                  "certified digits = working digits - 2"
                                : "viscor::certify: Taylor and adaptive integrators at two precisions (the linear law: its closed form at "
                                  "two precisions)";
}

/// One row of a CoR table, every number as a decimal string rounded to its
/// certified digits (computed by compute_row, table_row.hpp).
struct table_row {
  std::int64_t index = 0;
  std::string law, alpha, beta, gamma, g;
  impact_outcome outcome = impact_outcome::rebound;
  std::string e, one_minus_e, contact_time, max_compression;  ///< empty: not available
  int certified_digits = 0;  ///< the CSV column `digits`
  row_source source = row_source::exact;
};

/// One row of a sticking-threshold table (computed by compute_threshold_row,
/// sticking_threshold.hpp).
struct threshold_row {
  std::int64_t index = 0;
  std::string law, alpha, beta;
  threshold_variable solve_for = threshold_variable::g;
  std::string gamma, g;  ///< the fixed input (exact decimal) and the threshold (rounded to `certified_digits`)
  std::string rebound_at, stick_at;  ///< the certified bracket, at round-trip precision
  int certified_digits = 0;  ///< the CSV column `digits`
  row_source source = row_source::exact;
};

enum class table_kind { cor, sticking };

/// The column names of a table of kind `k`, in order.
inline const std::vector<std::string>& table_columns(table_kind k) {
  static const std::vector<std::string> cor{"index", "law", "alpha", "beta", "gamma", "g",
                                            field::outcome, field::e, field::one_minus_e, field::contact_time,
                                            field::max_compression, field::certified_digits_column, field::method};
  static const std::vector<std::string> sticking{"index", "law", "alpha", "beta", "solve_for", "gamma", "g",
                                                 "rebound_at", "stick_at", field::certified_digits_column,
                                                 field::method};
  return k == table_kind::cor ? cor : sticking;
}

/// The header line (without '\n').
inline std::string table_header(table_kind k) {
  std::string s;
  for (const auto& c : table_columns(k)) s += (s.empty() ? "" : ",") + c;
  return s;
}

/// A row as one CSV line (without '\n').
inline std::string csv_line(const table_row& r) {
  std::ostringstream s;
  s << r.index << ',' << r.law << ',' << r.alpha << ',' << r.beta << ',' << r.gamma << ',' << r.g << ','
    << to_string(r.outcome) << ',' << r.e << ',' << r.one_minus_e << ',' << r.contact_time << ','
    << r.max_compression << ',' << r.certified_digits << ',' << to_string(r.source);
  return s.str();
}

/// A threshold row as one CSV line (without '\n').
inline std::string csv_line(const threshold_row& r) {
  std::ostringstream s;
  s << r.index << ',' << r.law << ',' << r.alpha << ',' << r.beta << ',' << to_string(r.solve_for) << ','
    << r.gamma << ',' << r.g << ',' << r.rebound_at << ',' << r.stick_at << ',' << r.certified_digits << ','
    << to_string(r.source);
  return s.str();
}

/// One validated row of a table file: its index, its exact text, its fields.
struct csv_record {
  std::int64_t index = 0;
  std::string text;  ///< the line without '\n'
  std::vector<std::string> fields;
  std::size_t line = 0;  ///< 1-based line number in its file
};

/// The grid columns of a CoR row ("law,alpha,beta,gamma,g"): what names its grid point.
inline std::string grid_key(const grid_point& p) {
  return p.law.name + "," + p.law.alpha.to_string() + "," + p.law.beta.to_string() + "," + p.gamma + "," + p.g;
}

/// The grid columns of a threshold row ("law,alpha,beta,solve_for,fixed value"); the
/// solved-for value is the row's result, not part of its grid point.
inline std::string grid_key(const threshold_point& p) {
  return p.law.name + "," + p.law.alpha.to_string() + "," + p.law.beta.to_string() + "," + to_string(p.solve_for) +
         "," + p.fixed;
}

/// The same key read from a row of a table of kind `k`, to compare with the
/// grid_key of the point its index names (resume and merge).
inline std::string grid_key(const csv_record& row, table_kind k) {
  const auto& f = row.fields;
  if (k == table_kind::cor) return f.at(1) + "," + f.at(2) + "," + f.at(3) + "," + f.at(4) + "," + f.at(5);
  const bool for_g = f.at(4) == to_string(threshold_variable::g);  // the fixed value is gamma
  return f.at(1) + "," + f.at(2) + "," + f.at(3) + "," + f.at(4) + "," + (for_g ? f.at(5) : f.at(6));
}

/// A parsed and validated table.
struct csv_table {
  table_kind kind = table_kind::cor;
  std::vector<csv_record> rows;  ///< in file order
  bool truncated_tail = false;   ///< a last line without '\n' was dropped (allow_truncated_tail)

  /// The CSV header of this table's kind.
  const std::string& header() const {
    static const std::string cor = table_header(table_kind::cor), sticking = table_header(table_kind::sticking);
    return kind == table_kind::cor ? cor : sticking;
  }
};

namespace detail {

/// Field checks for one row; every error names file, line and field.
class row_checker {
 public:
  row_checker(const std::string& file, std::size_t line, const std::vector<std::string>& columns,
              const std::vector<std::string>& fields)
      : m_file(file), m_line(line), m_columns(columns), m_fields(fields) {}

  [[noreturn]] void fail(std::size_t column, const std::string& message) const {
    throw parse_error(m_file + ":" + std::to_string(m_line) + ": field " + m_columns[column] + ": " + message +
                      ", got '" + m_fields[column] + "'");
  }
  const std::string& at(std::size_t c) const { return m_fields[c]; }

  std::int64_t integer(std::size_t c, std::int64_t most) const {
    const std::string& s = at(c);
    if (s.empty() || s.size() > 15 || s.find_first_not_of("0123456789") != std::string::npos ||
        (s.size() > 1 && s[0] == '0'))
      fail(c, "must be a non-negative integer");
    const std::int64_t v = std::stoll(s);
    if (v > most) fail(c, "must be at most " + std::to_string(most));
    return v;
  }
  exact_decimal decimal(std::size_t c) const {
    try {
      return exact_decimal::parse(at(c), m_columns[c]);
    } catch (const invalid_parameter&) {
      fail(c, "must be a decimal number");
    }
  }
  /// A decimal in [lo, hi] (bounds inclusive; empty strings mean unbounded).
  exact_decimal decimal_in(std::size_t c, const std::string& lo, const std::string& hi) const {
    const exact_decimal x = decimal(c);
    if ((!lo.empty() && x < exact_decimal::parse(lo, "lo")) || (!hi.empty() && x > exact_decimal::parse(hi, "hi")))
      fail(c, "must be in [" + (lo.empty() ? "-inf" : lo) + ", " + (hi.empty() ? "inf" : hi) + "]");
    return x;
  }
  /// Empty ("not available"), "inf", or a decimal >= 0.
  void optional_non_negative(std::size_t c) const {
    if (at(c).empty() || at(c) == "inf") return;
    decimal_in(c, "0", "");
  }
  exponent exponent_field(std::size_t c) const {
    try {
      const exponent x = exponent::parse(at(c), m_columns[c]);
      if (!x.at_least_one()) fail(c, "a contact-law exponent must be >= 1");
      return x;
    } catch (const parse_error&) {
      throw;
    } catch (const invalid_parameter&) {
      fail(c, "must be a number or a fraction p/q");
    }
  }
  void one_of(std::size_t c, std::initializer_list<const char*> allowed) const {
    std::string list;
    for (const char* a : allowed) {
      if (at(c) == a) return;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    fail(c, "must be one of " + list);
  }
  /// law, alpha, beta (columns 1-3): a named law must carry its own exponents.
  void law() const {
    const exponent alpha = exponent_field(2), beta = exponent_field(3);
    if (at(1).empty()) return;
    contact_law named;
    try {
      named = law_by_name(at(1));
    } catch (const invalid_parameter& e) {
      fail(1, e.what());
    }
    if (!(named.alpha == alpha) || !(named.beta == beta))
      fail(1, "the named law has alpha = " + named.alpha.to_string() + ", beta = " + named.beta.to_string() +
                  ", not " + alpha.to_string() + ", " + beta.to_string());
  }

 private:
  const std::string& m_file;
  std::size_t m_line;
  const std::vector<std::string>& m_columns;
  const std::vector<std::string>& m_fields;
};

/// The number of significant digits written in a decimal text ("5.920e-01" -> 4, "0.05" -> 1).
inline int significant_digits(const std::string& text) {
  const std::string mantissa = text.substr(0, text.find_first_of("eE"));
  int count = 0;
  bool leading = true;
  for (char c : mantissa) {
    if (c < '0' || c > '9') continue;
    if (c != '0') leading = false;
    if (!leading) ++count;
  }
  return count;
}

// One unit of the last digit of x (written as `text`) that is both printed and among
// the `digits` certified significant digits: how far a correctly rounded value may be
// from the truth, with room to spare. Zero for x = 0 (printed exactly).
inline exact_decimal last_digit_unit(const exact_decimal& x, const std::string& text, std::int64_t digits) {
  if (x.is_zero()) return exact_decimal();
  const long long kept = std::max<long long>(1, std::min<long long>(digits, significant_digits(text)));
  return exact_decimal(1, static_cast<int>(x.leading_exponent() - kept + 1));
}

inline void check_cor_row(const row_checker& c) {
  // index,law,alpha,beta,gamma,g,outcome,e,one_minus_e,contact_time,max_compression,digits,method
  c.law();
  c.decimal_in(4, "0", "");
  c.decimal(5);
  c.one_of(6, {"rebound", "stick"});
  if (c.at(6) == "stick") {
    if (c.at(7) != "0") c.fail(7, "a sticking row has e = 0");
    if (c.at(8) != "1") c.fail(8, "a sticking row has one_minus_e = 1");
  } else {
    c.decimal_in(7, "0", "1");
    c.decimal_in(8, "0", "1");
  }
  c.optional_non_negative(9);
  c.optional_non_negative(10);
  const std::int64_t certified = c.integer(11, max_working_digits);
  c.one_of(12, {"exact", "certified"});
  // A certified e carries its certified digits: a row that claims more than it prints
  // contradicts itself (an edited digits field).
  if (c.at(12) == "certified" && c.at(6) == "rebound" && c.at(7) != "1" && significant_digits(c.at(7)) < certified)
    c.fail(11, "claims " + c.at(11) + " certified digits, but e = " + c.at(7) + " is written with " +
                   std::to_string(significant_digits(c.at(7))));
}

/// e and 1 - e of a rebound row (checked by check_cor_row) are computed and rounded
/// apart: they add up to 1 within the row's certified digits (one unit of the last
/// such digit of each), or one of them was changed after viscor wrote it.
inline void check_cor_sum(const row_checker& c) {
  if (c.at(6) != "rebound") return;
  const std::int64_t certified = c.integer(11, max_working_digits);
  const exact_decimal e = c.decimal(7), one_minus_e = c.decimal(8);
  const exact_decimal miss = e + one_minus_e - exact_decimal(1, 0);
  const exact_decimal allowed = last_digit_unit(e, c.at(7), certified) + last_digit_unit(one_minus_e, c.at(8), certified);
  if (miss > allowed || exact_decimal() - miss > allowed)
    c.fail(8, "e + one_minus_e must be 1 within the row's " + c.at(11) + " certified digits, but e = " + c.at(7) +
                  " and one_minus_e add up to 1 + (" + miss.to_string() + ")");
}

inline void check_sticking_row(const row_checker& c) {
  // index,law,alpha,beta,solve_for,gamma,g,rebound_at,stick_at,digits,method
  c.law();
  c.one_of(4, {"g", "gamma"});
  c.decimal_in(5, "0", "");
  c.decimal(6);
  const exact_decimal lo = c.decimal(7), hi = c.decimal(8);
  if (!(lo < hi)) c.fail(8, "the bracket needs rebound_at < stick_at");
  c.integer(9, max_working_digits);
  c.one_of(10, {"exact", "certified"});
}

/// Walks the lines of a table file's text: calls on_line(line, line_no, where) for
/// each '\n'-terminated line (where = "file:line"), refusing CR-LF line ends. A last
/// line without '\n' (a write cut short by a kill) is an error, or with
/// allow_truncated_tail is dropped and reported by returning true. Shared by the
/// readers of every table format (here and the CLI's proven tables).
template <class OnLine>
bool for_each_table_line(const std::string& text, const std::string& file, bool allow_truncated_tail,
                         OnLine&& on_line) {
  std::size_t pos = 0, line_no = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    ++line_no;
    const std::string where = file + ":" + std::to_string(line_no);
    if (end == std::string::npos) {
      if (allow_truncated_tail) return true;
      throw parse_error(where + ": truncated row (the file does not end with a newline)");
    }
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r') throw parse_error(where + ": CR-LF line ends are not allowed");
    on_line(std::move(line), line_no, where);
  }
  return false;
}

}  // namespace detail

/// Who checks that e + (1 - e) = 1 in a CoR row (detail::check_cor_sum): parse_table,
/// or a caller with rules of its own to check first (the proven table's enclosures).
enum class cor_sum_check { here, by_caller };

/// Parses and validates the text of a table file named `file` (for messages).
/// With allow_truncated_tail, a last line without '\n' (a write cut short by a
/// kill) is dropped instead of being an error: used when resuming a run.
/// Throws parse_error naming file, line and field.
inline csv_table parse_table(const std::string& text, const std::string& file, bool allow_truncated_tail = false,
                             cor_sum_check sums = cor_sum_check::here) {
  csv_table table;
  bool have_header = false;
  std::vector<std::string> columns;
  auto on_line = [&](std::string line, std::size_t line_no, const std::string& where) {
    if (!have_header) {
      if (line == table_header(table_kind::cor))
        table.kind = table_kind::cor;
      else if (line == table_header(table_kind::sticking))
        table.kind = table_kind::sticking;
      else
        throw parse_error(where + ": wrong columns: expected '" + table_header(table_kind::cor) + "' (CoR table) or '" +
                          table_header(table_kind::sticking) + "' (sticking thresholds), got '" + line + "'");
      columns = table_columns(table.kind);
      have_header = true;
      return;
    }
    csv_record record;
    record.fields = split_fields(line);
    record.line = line_no;
    if (record.fields.size() != columns.size())
      throw parse_error(where + ": expected " + std::to_string(columns.size()) + " fields (" +
                        table_header(table.kind) + "), got " + std::to_string(record.fields.size()) +
                        (record.fields.size() < columns.size() ? " (truncated row?)" : ""));
    const detail::row_checker check(file, line_no, columns, record.fields);
    record.index = check.integer(0, std::int64_t(1) << 50);
    if (table.kind == table_kind::cor) {
      detail::check_cor_row(check);
      if (sums == cor_sum_check::here) detail::check_cor_sum(check);
    } else
      detail::check_sticking_row(check);
    record.text = std::move(line);
    table.rows.push_back(std::move(record));
  };
  table.truncated_tail = detail::for_each_table_line(text, file, allow_truncated_tail, on_line);
  if (!have_header) throw parse_error(file + ":1: empty file: no header line");
  return table;
}

/// Reads and validates a table file; see parse_table.
/// A table listed in a checksum manifest beside it is checked first (core/checksums.hpp).
inline csv_table read_table(const std::string& path, bool allow_truncated_tail = false) {
  return parse_table(read_checked_file<error>(path, "table"), path, allow_truncated_tail);
}

/// The canonical text of a table: header, then rows sorted by index. Throws
/// parse_error for a duplicated index.
inline std::string table_text(table_kind kind, std::vector<csv_record> rows, const std::string& file) {
  std::sort(rows.begin(), rows.end(), [](const csv_record& a, const csv_record& b) { return a.index < b.index; });
  std::string out = table_header(kind) + "\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && rows[i].index == rows[i - 1].index)
      throw parse_error(file + ":" + std::to_string(rows[i].line) + ": field index: row " +
                        std::to_string(rows[i].index) + " appears twice");
    out += rows[i].text + "\n";
  }
  return out;
}

/// A row's numeric field as Real (correctly rounded from its exact decimal text).
template <class Real>
Real field_value(const csv_table& table, const csv_record& row, const std::string& column) {
  const auto& cols = table_columns(table.kind);
  const auto it = std::find(cols.begin(), cols.end(), column);
  if (it == cols.end()) throw invalid_parameter("no column '" + column + "' in a table of this kind");
  return parse_real<Real>(row.fields[static_cast<std::size_t>(it - cols.begin())], column);
}

}  // namespace viscor
