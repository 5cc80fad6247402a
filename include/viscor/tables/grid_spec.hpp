// Grid specification of a reference table: the contact laws, the gamma and g
// axes (explicit values and linear or logarithmic ranges), the working
// precision and the method. The spec expands into grid points in one fixed
// order, so a table, its shards and a resumed run all agree on row numbers.
//
// Reading a spec from a file is the jobs' business (jobs/table_spec.hpp); this
// header is free of any file format. Every value is kept as an exact decimal.
#pragma once

#include <viscor/core/checked_arithmetic.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/precision.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace viscor {

/// One item of an axis: a single value, or a range of `count` values from
/// `from` to `to` (both included), evenly spaced (linear) or geometrically
/// spaced (log), or a linear range with a given `step`.
struct axis_item {
  enum class kind { value, linear, log };
  kind type = kind::value;
  std::string from;   ///< the value, or the first value of a range (exact decimal text)
  std::string to;     ///< last value of a range
  std::string step;   ///< linear ranges: step instead of count (empty: use count)
  std::int64_t count = 0;
  /// log ranges: interior points 10^t are rounded to this many significant
  /// digits, so that every grid value is an exact (short) decimal.
  int log_digits = 6;
  std::string where;  ///< where the item was given ("spec.json:7"), for error messages
  std::map<std::string, std::string> field_where;  ///< where each of its fields was given ("count" -> "spec.json:9")

  /// Where `field` was given, else where the item was.
  const std::string& where_of(const std::string& field) const {
    const auto it = field_where.find(field);
    return it == field_where.end() ? where : it->second;
  }
};

/// A grid axis (gamma or g): the sorted union of its items' values.
struct grid_axis {
  std::vector<axis_item> items;
  /// Whether the axis has no items.
  bool empty() const { return items.empty(); }
};

/// How a row is computed: `certify` = viscor::certify (two methods, two
/// precisions); `exact` = closed forms only; `automatic` = certify when the build
/// has it, else closed forms where they exist.
enum class row_method { automatic, exact, certify };

/// The method's name as in a spec's "method" field.
inline std::string to_string(row_method m) {
  switch (m) {
    case row_method::automatic: return "auto";
    case row_method::exact: return "exact";
    case row_method::certify: return "certify";
  }
  return "?";
}

/// For `viscor table sticking`: which parameter the threshold is solved for.
enum class threshold_variable { g, gamma };

/// "g" or "gamma".
inline std::string to_string(threshold_variable v) { return v == threshold_variable::g ? "g" : "gamma"; }

/// A parsed table spec: the laws, the gamma and g axes, digits, method, and (sticking tables) the threshold asked for.
struct grid_spec {
  std::string description;
  std::vector<contact_law> laws;
  grid_axis gamma, g;
  int digits = 40;                    ///< working precision, decimal digits (with certified_digits: the first one)
  int certified_digits = 0;           ///< certified digits asked of every row (0: none; digits is the precision)
  row_method method = row_method::automatic;
  int min_digits = 0;                 ///< a row certified to fewer digits fails the run
  // Sticking thresholds only:
  threshold_variable solve_for = threshold_variable::g;
  int threshold_digits = 0;           ///< requested digits of g_c or gamma_c (0: not a sticking spec)
  std::string source = "spec";        ///< file name, for messages
};

/// A point of the grid; `index` is its position in the full grid.
struct grid_point {
  std::int64_t index = 0;
  contact_law law;
  std::string gamma, g;  ///< exact canonical decimals
};

/// Largest number of values one axis may expand to.
inline constexpr std::int64_t max_axis_values = 10'000'000;

namespace detail {

inline exact_decimal axis_decimal(const std::string& text, const std::string& where, const std::string& field) {
  try {
    return exact_decimal::parse(text, field);
  } catch (const invalid_parameter& e) {
    throw parse_error(where + ": field " + field + ": " + e.what());
  }
}

/// The interior values of a log range of n values from a to b (a > 0):
/// 10^(log10 a + k (log10 b - log10 a)/(n - 1)), k = 1..n-2, each rounded to `digits`
/// significant digits. NOTE: evaluated in cpp_bin_float_50 (software arithmetic,
/// identical on every platform), so the grid does not depend on the host's libm; the
/// two logarithms are taken once per range (a pow per value is the cost that remains).
inline void append_log_interior(std::vector<exact_decimal>& values, const exact_decimal& a, const exact_decimal& b,
                                std::int64_t n, int digits) {
  using big = boost::multiprecision::cpp_bin_float_50;
  const big la = log10(big(a.to_string())), lb = log10(big(b.to_string()));
  const big span = lb - la;
  std::ostringstream out;
  out << std::scientific << std::setprecision(digits - 1);
  for (std::int64_t k = 1; k + 1 < n; ++k) {
    out.str("");
    out << big(pow(big(10), big(la + span * big(k) / big(n - 1))));
    values.push_back(exact_decimal::parse(out.str(), "log grid value"));
  }
}

}  // namespace detail

/// The values of one axis, sorted ascending without duplicates. `name` is the
/// axis ("gamma", "g") used in error messages; gamma must be >= 0.
inline std::vector<std::string> expand_axis(const grid_axis& axis, const std::string& name) {
  using detail::exact_decimal;
  std::vector<exact_decimal> values;
  for (std::size_t i = 0; i < axis.items.size(); ++i) {
    const axis_item& item = axis.items[i];
    const std::string field = name + (axis.items.size() > 1 ? "[" + std::to_string(i) + "]" : "");
    // gamma >= 0 (Assumption 1); a range's smallest value is its `from`.
    auto check_sign = [&](const exact_decimal& smallest, const std::string& where) {
      if (name == "gamma" && smallest.sign() < 0)
        throw parse_error(item.where_of("from") + ": field " + where + ": gamma must be >= 0, got " +
                          smallest.to_string());
    };
    if (item.type == axis_item::kind::value) {
      values.push_back(detail::axis_decimal(item.from, item.where, field));
      check_sign(values.back(), field);
      continue;
    }
    const exact_decimal a = detail::axis_decimal(item.from, item.where_of("from"), field + ".from");
    const exact_decimal b = detail::axis_decimal(item.to, item.where_of("to"), field + ".to");
    check_sign(a, field + ".from");
    if (!(a < b))
      throw parse_error(item.where + ": field " + field + ": a range needs from < to, got from = " + item.from +
                        ", to = " + item.to);
    if (item.type == axis_item::kind::linear && !item.step.empty()) {
      const exact_decimal h = detail::axis_decimal(item.step, item.where_of("step"), field + ".step");
      if (h.sign() <= 0)
        throw parse_error(item.where_of("step") + ": field " + field + ".step: must be > 0, got " + item.step);
      std::int64_t k = 0;
      for (exact_decimal x = a; x <= b; x = x + h, ++k) {
        if (k >= max_axis_values)
          throw parse_error(item.where + ": field " + field + ": more than " + std::to_string(max_axis_values) +
                            " values");
        values.push_back(x);
      }
      continue;
    }
    if (item.count < 2 || item.count > max_axis_values)
      throw parse_error(item.where_of("count") + ": field " + field + ".count: must be an integer from 2 to " +
                        std::to_string(max_axis_values) + ", got " + std::to_string(item.count));
    if (item.type == axis_item::kind::linear) {
      const std::optional<exact_decimal> h = (b - a).divided_exactly(item.count - 1);
      if (!h)
        throw parse_error(item.where_of("count") + ": field " + field + ".count: the step (to - from)/(count - 1) = (" +
                          item.to + " - " + item.from + ")/" + std::to_string(item.count - 1) +
                          " is not a terminating decimal; choose a count for which it is, or give 'step'");
      for (std::int64_t k = 0; k < item.count; ++k) values.push_back(a + h->times(k));
    } else {
      if (a.sign() <= 0)
        throw parse_error(item.where_of("from") + ": field " + field + ".from: a log range needs from > 0, got " +
                          item.from);
      if (item.log_digits < 1 || item.log_digits > 30)
        throw parse_error(item.where_of("digits") + ": field " + field + ".digits: must be from 1 to 30, got " +
                          std::to_string(item.log_digits));
      values.push_back(a);
      detail::append_log_interior(values, a, b, item.count, item.log_digits);
      values.push_back(b);
    }
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (static_cast<std::int64_t>(values.size()) > max_axis_values)
    throw parse_error(axis.items.front().where + ": field " + name + ": more than " +
                      std::to_string(max_axis_values) + " values");
  std::vector<std::string> text;
  text.reserve(values.size());
  for (const auto& v : values) text.push_back(v.to_string());
  return text;
}

/// Checks everything that does not need the grid values; throws parse_error.
inline void validate(const grid_spec& spec) {
  const std::string& f = spec.source;
  if (spec.laws.empty()) throw parse_error(f + ": field laws: at least one contact law is needed");
  for (const auto& law : spec.laws) {
    try {
      law.validate();
    } catch (const invalid_parameter& e) {
      throw parse_error(f + ": field laws: " + e.what());
    }
  }
  try {
    scalar_for_digits(spec.digits);
  } catch (const invalid_parameter& e) {
    throw parse_error(f + ": field digits: " + e.what());
  }
  if (spec.min_digits < 0 || spec.min_digits > spec.digits)
    throw parse_error(f + ": field min_digits: must be from 0 to digits = " + std::to_string(spec.digits) +
                      ", got " + std::to_string(spec.min_digits));
}

/// The sorted values of the gamma and g axes, after validation.
struct expanded_axes {
  std::vector<std::string> gamma, g;
};

/// Validates `spec` and expands its axes into sorted exact decimals.
inline expanded_axes expand(const grid_spec& spec) {
  validate(spec);
  expanded_axes axes;
  if (!spec.gamma.empty()) axes.gamma = expand_axis(spec.gamma, "gamma");
  if (!spec.g.empty()) axes.g = expand_axis(spec.g, "g");
  return axes;
}

/// Number of rows of the CoR table of `spec`.
inline std::int64_t grid_size(const grid_spec& spec, const expanded_axes& axes) {
  return static_cast<std::int64_t>(spec.laws.size()) * static_cast<std::int64_t>(axes.g.size()) *
         static_cast<std::int64_t>(axes.gamma.size());
}

/// `viscor table --shard i/N`: shard `index` of `count` (0 <= index < count)
/// holds the rows whose grid index is congruent to `index` mod `count`
/// (interleaved, so that every shard gets a similar mix of cheap and costly rows).
struct shard {
  std::int64_t index = 0, count = 1;

  /// Whether grid row `row` belongs to this shard.
  bool contains(std::int64_t row) const { return row % count == index; }
  /// Whether this is the whole table (count 1).
  bool whole() const { return count == 1; }
  /// "index/count".
  std::string to_string() const { return std::to_string(index) + "/" + std::to_string(count); }

  /// Parses "i/N"; throws invalid_parameter.
  static shard parse(const std::string& text) {
    const auto slash = text.find('/');
    auto is_count = [](const std::string& s) {
      return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
    };
    if (slash == std::string::npos || !is_count(text.substr(0, slash)) || !is_count(text.substr(slash + 1)))
      throw invalid_parameter(VISCOR_FIELD("shard") " must be i/N with integers 0 <= i < N, got '" + text + "'");
    shard s{std::stoll(text.substr(0, slash)), std::stoll(text.substr(slash + 1))};
    if (s.count < 1 || s.index >= s.count)
      throw invalid_parameter(VISCOR_FIELD("shard") " must be i/N with integers 0 <= i < N, got '" + text + "'");
    return s;
  }
};

/// The most rows one table may have (laws x g values x gamma values).
inline constexpr std::int64_t max_table_rows = 100'000'000;

/// Throws parse_error naming the spec when the product of `sizes` (checked
/// arithmetic) exceeds max_table_rows.
inline void refuse_too_many_rows(const grid_spec& spec, std::initializer_list<std::int64_t> sizes) {
  std::int64_t rows = 1;
  std::string product;
  for (const std::int64_t n : sizes) {
    product += (product.empty() ? "" : " x ") + std::to_string(n);
    rows = checked_product(rows, n, spec.source + ": the number of table rows " + product);
  }
  if (rows > max_table_rows)
    throw parse_error(spec.source + ": the table would have " + product + " = " + std::to_string(rows) +
                      " rows, more than " + std::to_string(max_table_rows));
}

/// The points of the CoR table in table order: laws in the order given, then g
/// ascending, then gamma ascending (so each e(gamma) curve at fixed g is one
/// block of rows); only those of `part`.
inline std::vector<grid_point> grid_points(const grid_spec& spec, const expanded_axes& axes, shard part = {}) {
  if (axes.gamma.empty()) throw parse_error(spec.source + ": field gamma: the table needs gamma values");
  if (axes.g.empty()) throw parse_error(spec.source + ": field g: the table needs g values");
  refuse_too_many_rows(spec, {static_cast<std::int64_t>(spec.laws.size()), static_cast<std::int64_t>(axes.g.size()),
                             static_cast<std::int64_t>(axes.gamma.size())});
  std::vector<grid_point> points;
  std::int64_t index = 0;
  for (const auto& law : spec.laws)
    for (const auto& g : axes.g)
      for (const auto& gamma : axes.gamma) {
        if (part.contains(index)) points.push_back({index, law, gamma, g});
        ++index;
      }
  return points;
}

/// A point of a sticking-threshold table: the law and the fixed parameter
/// (gamma when solving for g_c, g when solving for gamma_c).
struct threshold_point {
  std::int64_t index = 0;
  contact_law law;
  threshold_variable solve_for = threshold_variable::g;
  std::string fixed;  ///< exact canonical decimal
};

/// Threshold points in table order (laws as given, fixed values ascending).
inline std::vector<threshold_point> threshold_points(const grid_spec& spec, const expanded_axes& axes,
                                                     shard part = {}) {
  const bool for_g = spec.solve_for == threshold_variable::g;
  const auto& fixed = for_g ? axes.gamma : axes.g;
  if (fixed.empty())
    throw parse_error(spec.source + ": field " + std::string(for_g ? "gamma" : "g") +
                      ": a sticking table solving for " + to_string(spec.solve_for) + " needs " +
                      (for_g ? "gamma" : "g") + " values");
  if (!(for_g ? axes.g : axes.gamma).empty())
    throw parse_error(spec.source + ": field " + to_string(spec.solve_for) + ": a sticking table solves for " +
                      to_string(spec.solve_for) + "; remove its axis from the spec");
  refuse_too_many_rows(spec, {static_cast<std::int64_t>(spec.laws.size()), static_cast<std::int64_t>(fixed.size())});
  std::vector<threshold_point> points;
  std::int64_t index = 0;
  for (const auto& law : spec.laws)
    for (const auto& v : fixed) {
      if (part.contains(index)) points.push_back({index, law, spec.solve_for, v});
      ++index;
    }
  return points;
}

}  // namespace viscor
