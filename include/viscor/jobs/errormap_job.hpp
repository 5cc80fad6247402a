// The error map of the approximations for one contact law (scenes/error_map_builder.hpp),
// as `viscor errormap` builds it: from certified reference tables (the
// tables/reference_table.hpp format), or from references computed here by
// solve_impact (for laws or regions without tables; the map records which).
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/core/text_fields.hpp>
#include <viscor/jobs/files.hpp>

#include <viscor/config.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/scenes/error_map_builder.hpp>
#include <viscor/tables/reference_table.hpp>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

namespace viscor::jobs {

/// The law, the cells, where the reference values come from, and the output file.
struct errormap_request {
  contact_law law;
  std::vector<std::string> tables;  ///< certified CoR tables; or none, with reference_digits
  std::string output;               ///< the map file to write (replaced only if viscor may)
  std::string gamma_edges, g_edges; ///< cell edges, comma-separated exact decimals
  int reference_digits = 0;         ///< instead of tables: solve_impact at this many digits (>= 30)
  int per_interval = 2;             ///< with reference_digits: samples per edge interval
  int min_samples = 4;              ///< reference points a cell needs
  double safety_factor = 4;         ///< bound = factor x worst sampled error + floor
  double floor = 1e-14;             ///< added to every bound (rounding in double)
  std::string command;              ///< how the map was asked for, recorded in its metadata
};

/// What building the map did.
struct errormap_summary {
  std::string reference;     ///< where the reference values came from
  std::size_t points = 0;    ///< reference points used
  std::size_t cells = 0;     ///< cells mapped
  std::size_t grid = 0;      ///< cells of the grid
  std::size_t mixed = 0;     ///< cells crossed by the sticking threshold (no bounds)
  double seconds = 0;        ///< wall time
};

namespace detail {

inline std::vector<std::string> edge_list(const std::string& text, const std::string& name) {
  const std::vector<std::string> out = text.empty() ? std::vector<std::string>{} : split_fields(text);
  if (out.size() < 2) throw invalid_parameter("--" + name + " needs at least two comma-separated edges, got '" + text + "'");
  return out;
}

}  // namespace detail

/// The rows of `law` in certified CoR tables (those with a value of e), as reference
/// points in the tables' order: gamma, g, e and 1 - e as the tables print them.
inline std::vector<reference_point> reference_from_tables(const contact_law& law, const std::vector<std::string>& tables) {
  std::vector<reference_point> points;
  for (const auto& path : tables) {
    const csv_table t = read_table(path);
    if (t.kind != table_kind::cor) throw invalid_parameter(VISCOR_FIELD("table") " " + path + " is not a CoR table");
    const auto& cols = table_columns(table_kind::cor);
    auto col = [&](const char* name) {
      return static_cast<std::size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
    };
    for (const auto& row : t.rows) {
      if (row.fields[col("alpha")] != law.alpha.to_string() || row.fields[col("beta")] != law.beta.to_string())
        continue;
      const std::string& e = row.fields[col(field::e)];
      if (e.empty()) continue;
      reference_point p;
      p.gamma = row.fields[col("gamma")], p.g = row.fields[col("g")], p.e = e;
      p.one_minus_e = row.fields[col(field::one_minus_e)];
      p.outcome = row.fields[col(field::outcome)] == "stick" ? impact_outcome::stick : impact_outcome::rebound;
      points.push_back(p);
    }
  }
  return points;
}

/// Builds the map and writes it to q.output; returns what it did.
inline errormap_summary make_error_map(const errormap_request& q) {
  if (q.output.empty())
    throw invalid_parameter("errormap needs -o FILE (e.g. reference_data/error_maps/" +
                            (q.law.name.empty() ? std::string("LAW") : q.law.name) + ".csv)");
  if (q.tables.empty() == (q.reference_digits == 0))
    throw invalid_parameter("errormap needs either " VISCOR_FIELD("table") " FILE... (certified tables) or "
                            VISCOR_FIELD("reference_digits") " N");
  if (q.reference_digits != 0 && (q.reference_digits < 30 || q.reference_digits > max_working_digits))
    throw invalid_parameter(VISCOR_FIELD("reference_digits")
                            " must be from 30 to " + std::to_string(max_working_digits) + ", got " +
                            std::to_string(q.reference_digits));
  if (q.per_interval < 1) throw invalid_parameter(VISCOR_FIELD("per_interval")
                                                  " must be >= 1, got " + std::to_string(q.per_interval));
  if (q.min_samples < 1) throw invalid_parameter(VISCOR_FIELD("min_samples")
                                                 " must be >= 1, got " + std::to_string(q.min_samples));
  refuse_unless_regular_or_absent(q.output);
  error_map_spec spec;
  spec.gamma_edges = detail::edge_list(q.gamma_edges, "gamma-edges");
  spec.g_edges = detail::edge_list(q.g_edges, "g-edges");
  spec.safety_factor = q.safety_factor, spec.floor = q.floor, spec.min_samples = q.min_samples;

  const auto start = std::chrono::steady_clock::now();
  errormap_summary s;
  std::vector<reference_point> points;
  if (!q.tables.empty()) {
    points = reference_from_tables(q.law, q.tables);
    for (const auto& path : q.tables) s.reference += (s.reference.empty() ? "" : " ") + path;
    s.reference = "certified tables " + s.reference;
  } else {
    points = reference_by_solve(q.law, grid_nodes(spec.gamma_edges, q.per_interval),
                                grid_nodes(spec.g_edges, q.per_interval), q.reference_digits);
    s.reference = "solve_impact (Taylor) at " + std::to_string(q.reference_digits) + " digits on the cell edges with " +
                  std::to_string(q.per_interval) + " samples per edge interval (not certified)";
  }
  spec.metadata = {{"reference", s.reference},
                   {"command", q.command},
                   {"viscor", std::string(VISCOR_VERSION) + " (" + git_commit() + ")"}};
  const error_map map = build_error_map(q.law, points, spec);
  write_atomically(q.output, error_map_text(map));
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.points = points.size();
  s.cells = map.cells().size();
  s.grid = (spec.gamma_edges.size() - 1) * (spec.g_edges.size() - 1);
  for (const auto& c : map.cells()) s.mixed += c.outcome == cell_outcome::mixed;
  return s;
}

}  // namespace viscor::jobs
