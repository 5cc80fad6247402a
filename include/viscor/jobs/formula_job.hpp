// Regression tests of an outside CoR formula against the certified tables, as
// `viscor errormap points|compare`, viscor.compare and viscor/testing/ run them
// (scenes/formula_check.hpp does the statistics).
//
// The truth for a named law is what its committed error map was built from
// (reference_data/error_maps/<law>.csv): the certified tables its metadata names
// and the grid of its command line (cell edges, fewest samples per cell). So a
// formula checked here is judged on the same points and cells as the report's
// formulas in that map.
#pragma once

#include <viscor/jobs/data_directory.hpp>
#include <viscor/jobs/errormap_job.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/json_fields.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/text_fields.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/scenes/formula_check.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>

namespace viscor::jobs {

/// The certified truth a formula of one law is checked against.
struct formula_reference {
  contact_law law;
  error_map_spec grid;                  ///< the committed map's cell edges and fewest samples per cell
  std::vector<std::string> tables;      ///< the certified tables (paths in the data directory)
  std::vector<reference_point> points;  ///< their rows of the law, in order
};

namespace detail {

// The words after `option` in a recorded command line ("" when absent).
inline std::string option_value(const std::string& command, const std::string& option) {
  std::istringstream in(command);
  for (std::string word; in >> word;)
    if (word == option && in >> word) return word;
  return {};
}

}  // namespace detail

/// The truth for `law` from the committed error map of the data directory (`data`:
/// "" for the default): the tables and the grid the map records. Laws without a
/// committed map are refused, naming where the map was looked for.
inline formula_reference committed_formula_reference(const contact_law& law, const std::string& data = "") {
  const std::string dir = data_directory(data);
  if (law.name.empty())
    throw invalid_parameter("formula check: the certified truth exists for the named laws only (got " + law.describe() +
                            ")");
  const std::filesystem::path map_path = std::filesystem::path(dir) / "error_maps" / (law.name + ".csv");
  if (!std::filesystem::exists(map_path))
    throw invalid_parameter("formula check: no committed error map of " + law.name + " ('" + map_path.string() + "')");
  const error_map map = read_error_map(map_path.string());
  std::string reference, command;
  for (const auto& [key, value] : map.metadata) {
    if (key == "reference") reference = value;
    if (key == "command") command = value;
  }
  const std::string prefix = "certified tables ";
  if (reference.rfind(prefix, 0) != 0)
    throw parse_error(map_path.string() + ": the map was not built from certified tables (reference=" + reference + ")");
  formula_reference r;
  r.law = law;
  std::istringstream names(reference.substr(prefix.size()));
  for (std::string name; names >> name;)
    r.tables.push_back((std::filesystem::path(dir) / std::filesystem::path(name).filename()).string());
  const auto edges = [&](const char* option) {  // a missing option: no edges, refused by the grid's check
    const std::string text = detail::option_value(command, option);
    return text.empty() ? std::vector<std::string>{} : split_fields(text);
  };
  r.grid.gamma_edges = edges("--gamma-edges");
  r.grid.g_edges = edges("--g-edges");
  const std::string min_samples = detail::option_value(command, "--min-samples");
  if (!min_samples.empty()) {
    if (min_samples.size() > 6 || min_samples.find_first_not_of("0123456789") != std::string::npos ||
        std::stoi(min_samples) < 1)
      throw parse_error(map_path.string() + ": its command line gives --min-samples '" + min_samples.substr(0, 40) +
                        "', not a whole number from 1 to 999999");
    r.grid.min_samples = std::stoi(min_samples);
  }
  if (r.grid.gamma_edges.size() < 2 || r.grid.g_edges.size() < 2)
    throw parse_error(map_path.string() + ": its command line records no --gamma-edges and --g-edges");
  r.points = reference_from_tables(law, r.tables);
  return r;
}

/// The distinct (gamma, g) of the reference points, in order, as the tables print them.
inline std::vector<std::pair<std::string, std::string>> distinct_points(const std::vector<reference_point>& points) {
  std::vector<std::pair<std::string, std::string>> out;
  std::set<std::pair<double, double>> seen;
  for (const auto& p : points)
    if (seen.emplace(std::strtod(p.gamma.c_str(), nullptr), std::strtod(p.g.c_str(), nullptr)).second)
      out.emplace_back(p.gamma, p.g);
  return out;
}

/// A formula's values read from a file: a CSV with a header naming gamma, g and
/// one of e or one_minus_e ('#' lines are comments).
struct formula_values {
  formula_quantity quantity = formula_quantity::e;
  std::map<std::pair<double, double>, double> at;  ///< (gamma, g) -> value
};

namespace detail {

// At most the first 60 bytes of `text`, for messages that quote what a file holds.
inline std::string quoted_start(const std::string& text) {
  return "'" + (text.size() > 60 ? text.substr(0, 60) + "...'" : text + "'");
}

// The text of a values file ("-": standard input).
inline std::string read_values_text(const std::string& path) {
  if (path != "-") {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
      throw invalid_parameter("formula check: the values file '" + path + "' is not a regular file");
    return read_file(path);
  }
  std::ostringstream s;
  s << std::cin.rdbuf();
  return s.str();
}

}  // namespace detail

/// The values in `text`, the content of the values file `name` (for messages); refuses
/// text that is not UTF-8, a missing or repeated column and any field that is not a
/// number, naming the line.
inline formula_values parse_formula_values(const std::string& text, const std::string& name) {
  const std::size_t bad = first_invalid_utf8(text);
  if (bad != std::string::npos)
    throw parse_error(name + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(bad), '\n')) +
                      ": not UTF-8 text (byte " + std::to_string(bad) + "); the values are a CSV with the header gamma,g,e");
  std::istringstream in(text);
  formula_values v;
  std::vector<std::string> header;
  int gamma_col = -1, g_col = -1, value_col = -1;
  std::size_t line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = split_fields(line);
    const std::string where = name + ":" + std::to_string(line_number) + ": ";
    if (header.empty()) {
      header = fields;
      for (int k = 0; k < static_cast<int>(fields.size()); ++k) {
        int* slot = fields[k] == "gamma" ? &gamma_col
                    : fields[k] == "g"   ? &g_col
                    : fields[k] == "e" || fields[k] == "one_minus_e" ? &value_col
                                                                      : nullptr;
        if (!slot) continue;
        if (*slot >= 0)
          throw parse_error(where + "column " + detail::quoted_start(fields[k]) + " given twice (or both e and one_minus_e)");
        *slot = k;
        if (fields[k] == "one_minus_e") v.quantity = formula_quantity::one_minus_e;
      }
      if (gamma_col < 0 || g_col < 0 || value_col < 0)
        throw parse_error(where + "the header needs the columns gamma, g and e (or one_minus_e), got " +
                          detail::quoted_start(line));
      continue;
    }
    if (fields.size() != header.size())
      throw parse_error(where + std::to_string(fields.size()) + " fields, the header has " + std::to_string(header.size()));
    const auto number_at = [&](int col, const std::string& what) {
      if (fields[col].size() > 100)
        throw parse_error(where + what + " is not a number: " + detail::quoted_start(fields[col]));
      return parse_real<double>(fields[col], what + " (" + where + ")");
    };
    const double gamma = number_at(gamma_col, "gamma");
    const double g = number_at(g_col, "g");
    const double value = number_at(value_col, header[value_col]);
    if (!v.at.emplace(std::make_pair(gamma, g), value).second)
      throw parse_error(where + "the point gamma = " + fields[gamma_col] + ", g = " + fields[g_col] + " is given twice");
  }
  if (header.empty()) throw parse_error(name + ": no header and no values (formula check needs gamma,g,e)");
  return v;
}

/// Reads a values file ("-": standard input) and parses it (parse_formula_values).
inline formula_values read_formula_values(const std::string& path) {
  return parse_formula_values(detail::read_values_text(path), path == "-" ? "<stdin>" : path);
}

/// The values of `given` at the reference points; the points without a value are
/// dropped from `r` (their cells may then lose their corners). Refuses a value at a
/// point that is not a reference point, naming it.
inline std::vector<double> values_at_reference(formula_reference& r, const formula_values& given) {
  std::set<std::pair<double, double>> known;
  std::vector<reference_point> kept;
  std::vector<double> values;
  for (const auto& p : r.points) {
    const std::pair<double, double> key{std::strtod(p.gamma.c_str(), nullptr), std::strtod(p.g.c_str(), nullptr)};
    known.insert(key);
    const auto it = given.at.find(key);
    if (it == given.at.end()) continue;
    kept.push_back(p);
    values.push_back(it->second);
  }
  for (const auto& [key, value] : given.at)
    if (!known.count(key))
      throw invalid_parameter("formula check: gamma = " + viscor::detail::shortest(key.first) + ", g = " +
                              viscor::detail::shortest(key.second) + " is not a point of the certified tables of " +
                              r.law.name + " (`viscor formula points --model " + r.law.name + "` lists them)");
  r.points = std::move(kept);
  return values;
}

/// The region of a check from its bounds as text ("" for an unbounded side), through
/// the one number parser: NaN, infinities, hexadecimal and underflowing bounds are
/// refused naming the bound, and so is an empty or inverted region.
inline formula_region formula_region_of(const std::string& gamma_min, const std::string& gamma_max,
                                        const std::string& g_min, const std::string& g_max) {
  formula_region r;
  const auto bound = [](const std::string& text, const char* name, double& slot) {
    if (!text.empty()) slot = parse_real<double>(text, name);
  };
  bound(gamma_min, "gamma_min", r.gamma_min);
  bound(gamma_max, "gamma_max", r.gamma_max);
  bound(g_min, "g_min", r.g_min);
  bound(g_max, "g_max", r.g_max);
  r.validate();
  return r;
}

/// The tolerance on |de| from text, through the one number parser, in [0, 1).
inline double formula_tolerance_of(const std::string& text) {
  const double t = parse_real<double>(text, "tolerance");
  validate_formula_tolerance(t);
  return t;
}

/// What a check covered: "12 of 40 cells in the region judged; 3 points in no judged
/// cell (largest |de| 2.1e-03)".
inline std::string formula_coverage_text(const formula_comparison& c) {
  std::string t = std::to_string(c.cells.size()) + " of " + std::to_string(c.cells_in_region) +
                  " cells in the region judged; " + std::to_string(c.points_not_judged) + " points in no judged cell";
  if (c.points_not_judged) t += " (largest |de| " + to_decimal_string(c.max_abs_e_not_judged, 3) + ")";
  return t;
}

/// Why a check judged no cell (empty when it judged one): `given` points had a value.
inline std::string formula_nothing_judged(const formula_comparison& c, const formula_reference& r) {
  if (c.judged_any()) return {};
  if (c.cells_in_region == 0) return "the region holds no cell of the map";
  return "none of the " + std::to_string(c.cells_in_region) + " cells in the region has its four corners and " +
         std::to_string(r.grid.min_samples) + " samples among the " + std::to_string(r.points.size()) +
         " certified points with a value";
}

/// The statistics of one cell (or all cells), as JSON.
inline json formula_cell_json(const formula_cell& c, const std::vector<reference_point>& points) {
  json j;
  if (!c.gamma_lo.empty()) {
    j["gamma_lo"] = c.gamma_lo, j["gamma_hi"] = c.gamma_hi, j["g_lo"] = c.g_lo, j["g_hi"] = c.g_hi;
    j["outcome"] = to_string(c.outcome);
  }
  j["samples"] = c.samples;
  j["max_abs_e"] = number(c.max_abs_e);
  j["median_abs_e"] = number(c.median_abs_e);
  j["max_rel_one_minus_e"] = number(c.max_rel_one_minus_e);
  j["median_rel_one_minus_e"] = number(c.median_rel_one_minus_e);
  if (c.worst.abs_error >= 0)
    j["worst"] = {{"gamma", points[c.worst.index].gamma}, {"g", points[c.worst.index].g},
                  {"value", number(c.worst.value)}, {"truth", points[c.worst.index].e},
                  {"abs_error", number(c.worst.abs_error)}};
  j["rebound_where_truth_sticks"] = c.rebound_where_truth_sticks;
  j["stick_where_truth_rebounds"] = c.stick_where_truth_rebounds;
  j["non_finite"] = c.non_finite;
  j["pass"] = c.pass;
  return j;
}

/// A whole check as JSON (docs/formulas.md): the truth it used and every cell.
inline json formula_comparison_json(const formula_comparison& c, const formula_reference& r, formula_quantity quantity) {
  json j;
  j["law"] = law_json(r.law);
  j["truth"] = {{"kind", "certified"}, {"tables", json::array()}, {"min_samples", r.grid.min_samples}};
  for (const auto& t : r.tables) j["truth"]["tables"].push_back(std::filesystem::path(t).filename().string());
  j["quantity"] = quantity == formula_quantity::e ? "e" : "one_minus_e";
  j["tolerance"] = number(c.tolerance);
  j["points"] = r.points.size();
  j["pass"] = c.pass;
  j["failed_cells"] = c.failed_cells;
  j["coverage"] = {{"cells_judged", c.cells.size()}, {"cells_in_region", c.cells_in_region},
                   {"points_not_judged", c.points_not_judged},
                   {"max_abs_e_not_judged", number(c.max_abs_e_not_judged)}};
  if (!c.judged_any()) j["reason"] = "no cell judged: " + formula_nothing_judged(c, r);
  j["overall"] = formula_cell_json(c.overall, r.points);
  j["cells"] = json::array();
  for (const auto& cell : c.cells) j["cells"].push_back(formula_cell_json(cell, r.points));
  return j;
}

/// The readable summary: the verdict, the overall figures and the failing cells.
inline std::string formula_comparison_text(const formula_comparison& c, const formula_reference& r) {
  std::ostringstream t;
  const formula_cell& a = c.overall;
  t << "law        " << r.law.describe() << "\n"
    << "truth      " << r.points.size() << " certified points of " << r.tables.size() << " tables, "
    << c.cells.size() << " cells\n"
    << "coverage   " << formula_coverage_text(c) << "\n"
    << "verdict    " << (c.pass ? "pass" : "FAIL") << " (|de| <= " << to_decimal_string(c.tolerance, 3)
    << " in every cell, outcomes right)";
  if (!c.judged_any()) t << ": no cell judged: " << formula_nothing_judged(c, r);
  else if (!c.pass) t << ": " << c.failed_cells << " cell(s) fail";
  t << "\nmax |de|   " << to_decimal_string(a.max_abs_e, 3) << " (median " << to_decimal_string(a.median_abs_e, 3)
    << ")\nmax rel    " << to_decimal_string(a.max_rel_one_minus_e, 3) << " on 1 - e (median "
    << to_decimal_string(a.median_rel_one_minus_e, 3) << ")\n";
  if (a.worst.abs_error >= 0)
    t << "worst      gamma = " << r.points[a.worst.index].gamma << ", g = " << r.points[a.worst.index].g
      << ": formula " << to_decimal_string(a.worst.value, 17) << ", certified " << r.points[a.worst.index].e << "\n";
  t << "outcomes   " << a.rebound_where_truth_sticks << " rebound where the truth sticks, "
    << a.stick_where_truth_rebounds << " stick where it rebounds; " << a.non_finite << " non-finite values\n";
  for (const auto& cell : c.cells) {
    if (cell.pass) continue;
    t << "fails      gamma " << cell.gamma_lo << ".." << cell.gamma_hi << ", g " << cell.g_lo << ".." << cell.g_hi
      << ": max |de| " << to_decimal_string(cell.max_abs_e, 3);
    if (cell.worst.abs_error >= 0)
      t << " at gamma = " << r.points[cell.worst.index].gamma << ", g = " << r.points[cell.worst.index].g;
    if (cell.rebound_where_truth_sticks + cell.stick_where_truth_rebounds)
      t << "; " << cell.rebound_where_truth_sticks + cell.stick_where_truth_rebounds << " wrong outcome(s)";
    if (cell.non_finite) t << "; " << cell.non_finite << " non-finite";
    t << "\n";
  }
  return t.str();
}

}  // namespace viscor::jobs
