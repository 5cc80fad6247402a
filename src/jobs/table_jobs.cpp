// The table jobs (include/viscor/jobs/table_jobs.hpp), compiled once.
#include <viscor/jobs/table_jobs.hpp>

#include <viscor/config.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/table_format.hpp>
#include <viscor/tables/grid_spec.hpp>
#include <viscor/tables/reference_table.hpp>
#include <viscor/tables/sticking_threshold.hpp>
#include <viscor/tables/table_row.hpp>
#include <viscor/jobs/physical_table.hpp>
#include <viscor/jobs/proven_rows.hpp>

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#ifdef VISCOR_WITH_ENCLOSE
#include <viscor/jobs/proven_rows.hpp>
#endif

namespace viscor::jobs {

namespace detail {

inline json scalar_provenance(int digits) {
  return with_working_precision(digits, [&]<class Real>() {
    json j;
    j["type"] = to_string(scalar_for_digits(digits));
    j["requested_digits"] = digits;
    j["decimal_digits"] = decimal_digits<Real>();
    j["binary_digits"] = binary_digits<Real>();
#if VISCOR_HAS_QD && VISCOR_HAS_FLOAT128
    if constexpr (std::is_same_v<Real, double_double>)
      j["below_range"] = "a row with a value below 2^-939 is computed in float128 (docs/precision.md)";
#endif
    return j;
  });
}

/// The digits a row of method "proven" is proven at: those of the working type the
/// row is certified in (the spec's digits, or more: float128 carries 33 at 30), so
/// that the proof's cap on proven digits is never below the certificate's arithmetic.
inline int proof_digits(int digits) {
  return std::max(digits, with_working_precision(digits, []<class Real>() { return decimal_digits<Real>(); }));
}

inline json method_provenance(const table_spec& table) {
  const grid_spec& spec = table.grid;
  json j;
  j["requested"] = table.proven ? std::string("proven") : to_string(spec.method);
  j["exact"] = describe(row_source::exact);
  j["certified"] = describe(row_source::certified);
  j["tolerances"] =
      "exact: closed forms, with TOMS748 root finding to the working precision where a time is implicit; "
      "certified: the tolerances of viscor::certify at the working precision";
  j["min_digits"] = spec.min_digits;
  if (spec.certified_digits > 0)
    j["certified_digits"] = {
        {"requested", spec.certified_digits},
        {"rule", "every row certified to at least this many digits: computed at the scalar's requested_digits "
                 "(the goal + the safety margin, + 1 in MPFR), and a row that falls short again at a precision "
                 "raised by its shortfall + 1 (at most doubled, at most " + std::to_string(max_precision_runs) +
                 " runs; include/viscor/certify/certified_digits_goal.hpp)"}};
  if (spec.method != row_method::exact) {
    const certify_options defaults;
    j["certify"] = {
        {"computations", "taylor at the working precision; taylor at the reference precision; adaptive (GBS) at "
                         "the working precision, and again at the reference precision where it is undecided at the "
                         "working one (the linear law: its closed form at the working and the reference precision)"},
        {"reference_digits",
         with_working_precision(spec.digits, []<class Real>() { return viscor::detail::reference_digits<Real>(); })},
        {"safety_margin", defaults.safety_margin},
        {"step_tolerance", "the epsilon of each computation's precision (solve_options default)"},
        {"digits", "the least agreement of the taylor run at the working precision and of the adaptive run (at "
                   "the reference precision where that one is used) with the reference over e, 1 - e, T_f and "
                   "u_max, minus the safety margin"}};
  }
  if (table.proven)
    j["proof"] = {
        {"what", "viscor::enclose (include/viscor/enclose/, docs/proofs.md) on the exact decimal gamma and g of each "
                 "certified row: validated Taylor integration in Arb ball arithmetic"},
        {"digits", proof_digits(spec.digits)},
        {"ball_bits", "ceil(digits log2 10) + 24, rounded up to a multiple of 64"},
        {"columns", "e_lower <= e <= e_upper and one_minus_e_lower <= 1 - e <= one_minus_e_upper (decimals rounded "
                    "outwards); proven_digits: the correctly rounded digits of e on which both bounds agree (at most "
                    "digits); outcome_proven: rebound, stick, or undecided (empty bounds, 0 digits)"},
        {"checks", "a proof that contradicts its certified row (outcome, or e or 1 - e outside the enclosure by more "
                   "than a unit of the last certified digit) stops the run"}};
  return j;
}

/// Checks the options; nothing is read or written yet.
inline void check_run_options(const table_run_options& run, const std::string& command) {
  if (run.output.empty()) throw invalid_parameter(command + " needs an output file: -o OUT.csv");
  if (run.threads < 1 || run.threads > 4096)
    throw invalid_parameter(VISCOR_FIELD("threads") " must be from 1 to 4096, got " + std::to_string(run.threads));
}

/// The job of a table: everything but the rows and how to compute them.
inline table_job make_job(const table_run_options& run, table_kind kind, const table_spec& table,
                          std::int64_t rows_total) {
  const grid_spec& spec = table.grid;
  table_job j = new_table_job(run, kind, table.proven, run.output, rows_total, run.part, run.spec_file);
  json& p = j.provenance;
  p["spec"] = spec_to_json(table);  // method "proven" in it: a proven and a certified run never mix
  p["scalar"] = scalar_provenance(spec.digits);
  p["method"] = method_provenance(table);
  return j;
}

/// Method "proven": refuses (exit 2), before any work, a build without Arb, too
/// few digits for a proof, or a law with an exponent that is not rational.
inline void require_proof(const table_spec& table) {
#ifndef VISCOR_WITH_ENCLOSE
  throw invalid_parameter(table.method_where + ": field method: \"proven\" needs a viscor built with Arb "
                          "(apt-get install libflint-arb-dev)");
#endif
  const grid_spec& spec = table.grid;
  // A row raised to more digits than the proof's would be checked against a wider enclosure.
  if (spec.certified_digits > 0)
    throw parse_error(spec.source + ": field certified_digits: method \"proven\" proves every row at one "
                      "precision: give the working digits as digits");
  if (spec.digits < 5)
    throw parse_error(spec.source + ": field digits: method \"proven\" needs at least 5 digits, got " +
                      std::to_string(spec.digits));
  for (const auto& law : spec.laws) require_provable(law, spec.source + ": field laws: " + law.describe());
}

/// The rows of a spec in SI (all of them, or those of `part`).
inline std::vector<physical_point> physical_points_of(const table_spec& table, shard part = {}) {
  const physical_axes& axes = *table.physical;
  const expanded_physical_axes values = expand(axes);
  refuse_too_many_rows(table.grid, {static_cast<std::int64_t>(table.grid.laws.size()),
                                    physical_rows_per_law(axes, values)});
  return physical_points(table.grid.laws, axes, values, part);
}

/// The key (table_format::key) of every row of a table of kind `k` made from `table`, by index.
inline std::vector<std::string> grid_keys(const table_spec& table, table_kind k) {
  std::vector<std::string> keys;
  if (table.physical) {
    for (const auto& p : physical_points_of(table)) keys.push_back(physical_key(*table.physical, p));
    return keys;
  }
  const expanded_axes axes = expand(table.grid);
  auto put = [&keys](std::int64_t index, std::string key) {
    if (index >= static_cast<std::int64_t>(keys.size())) keys.resize(static_cast<std::size_t>(index) + 1);
    keys[static_cast<std::size_t>(index)] = std::move(key);
  };
  if (k == table_kind::cor)
    for (const auto& p : grid_points(table.grid, axes)) put(p.index, grid_key(p));
  else
    for (const auto& p : threshold_points(table.grid, axes)) put(p.index, grid_key(p));
  return keys;
}

}  // namespace detail

namespace detail {

/// A CoR table from a spec in SI: each row `viscor cor` of its inputs (physical_table.hpp).
inline table_run_summary make_physical_table(const table_spec& table, const table_run_options& run) {
  const grid_spec& spec = table.grid;
  const auto points = std::make_shared<std::vector<physical_point>>(physical_points_of(table, run.part));
  check_physical_rows(table, *points);  // every row's inputs before anything is written
  const std::int64_t rows_total =
      static_cast<std::int64_t>(spec.laws.size()) * physical_rows_per_law(*table.physical, expand(*table.physical));
  table_job job = make_job(run, table_kind::cor, table, rows_total);
  job.physical = true;
  job.provenance["columns"] = table_format{table_kind::cor, false, true}.header();
  job.provenance["scaling"] = "each row as viscor cor scales the same physical inputs (include/viscor/core/scaling.hpp); "
                              "gamma and g are the scaled values in the digits that round-trip at the row's working "
                              "precision";
  for (const auto& p : *points) job.indices.push_back(p.index);
  const auto axes = std::make_shared<physical_axes>(*table.physical);
  const table_settings settings = table_settings::from(spec);
  job.compute_line = [points, axes, settings](std::size_t i) { return physical_row_line(*axes, (*points)[i], settings); };
  job.expected_grid_key = [points, axes](std::size_t i) { return physical_key(*axes, (*points)[i]); };
  return run_table_job(job);
}

}  // namespace detail

table_run_summary make_cor_table(const table_spec& table, const table_run_options& run) {
  detail::check_run_options(run, "viscor table");
  if (table.physical) return detail::make_physical_table(table, run);
  const shard& part = run.part;
  const std::string& where = table.grid.source;
  const grid_spec& spec = table.grid;
  if (spec.threshold_digits > 0)
    throw parse_error(where + ": field threshold_digits: this is a sticking-threshold spec; run it with "
                      "'viscor table sticking'");
  const expanded_axes axes = expand(spec);
  const auto points = std::make_shared<std::vector<grid_point>>(grid_points(spec, axes, part));
  // Every point must be computable before anything is written.
  for (const auto& p : *points)
    require_computable(p.law, p.gamma == "0", p.g == "0", spec.method,
                       where + ": row " + std::to_string(p.index) + " (" + p.law.describe() +
                           ", gamma = " + p.gamma + ", g = " + p.g + ")");
  if (table.proven) detail::require_proof(table);
  table_job job = detail::make_job(run, table_kind::cor, table, grid_size(spec, axes));
  for (const auto& p : *points) job.indices.push_back(p.index);
  const table_settings settings = table_settings::from(spec);
  job.compute_line = [points, settings](std::size_t i) { return csv_line(compute_row((*points)[i], settings)); };
  job.expected_grid_key = [points](std::size_t i) { return grid_key((*points)[i]); };
#ifdef VISCOR_WITH_ENCLOSE
  if (table.proven)
    job.compute_line = [points, settings, digits = detail::proof_digits(spec.digits), shift = run.certified_e_shift](std::size_t i) {
      const grid_point& p = (*points)[i];
      const table_row row = compute_row(p, settings);
      return csv_line(row) + proven_fields(p, digits, row, shift);
    };
#endif
  return run_table_job(job);
}

table_run_summary make_sticking_table(const table_spec& table, const table_run_options& run) {
  detail::check_run_options(run, "viscor table sticking");
  const shard& part = run.part;
  const std::string& where = table.grid.source;
  const grid_spec& spec = table.grid;
  if (table.proven)
    throw parse_error(table.method_where + ": field method: \"proven\" is a method of CoR tables (viscor table); "
                      "sticking thresholds are certified (\"auto\", \"certify\" or \"exact\")");
  if (spec.certified_digits > 0)
    throw parse_error(where + ": field certified_digits: a sticking-threshold spec asks for its digits as "
                      "threshold_digits (and the working precision as digits)");
  if (spec.threshold_digits < 1)
    throw parse_error(where + ": field threshold_digits: missing: a sticking-threshold spec gives the "
                      "digits wanted, e.g. \"threshold_digits\": 30");
  if (spec.threshold_digits > spec.digits - 5)
    throw parse_error(where + ": field threshold_digits: must be at most digits - 5 = " +
                      std::to_string(spec.digits - 5) + ", got " + std::to_string(spec.threshold_digits));
  const expanded_axes axes = expand(spec);
  const std::int64_t rows_total = static_cast<std::int64_t>(spec.laws.size()) *
      static_cast<std::int64_t>((spec.solve_for == threshold_variable::g ? axes.gamma : axes.g).size());
  const auto points = std::make_shared<std::vector<threshold_point>>(threshold_points(spec, axes, part));
  const bool for_g = spec.solve_for == threshold_variable::g;
  for (const auto& p : *points)  // the search moves the solved-for parameter away from 0
    require_computable(p.law, false, !for_g && p.fixed == "0", spec.method,
                       where + ": row " + std::to_string(p.index) + " (" + p.law.describe() +
                           (for_g ? ", gamma = " : ", g = ") + p.fixed + ")");
  table_job job = detail::make_job(run, table_kind::sticking, table, rows_total);
  for (const auto& p : *points) job.indices.push_back(p.index);
  job.expected_grid_key = [points](std::size_t i) { return grid_key((*points)[i]); };
  job.provenance["threshold"] = {
      {"solve_for", to_string(spec.solve_for)},
      {"requested_digits", spec.threshold_digits},
      {"algorithm", "bracket by doubling from 0, then bisection on the certified outcome (rebound or stick) until "
                    "the bracket [rebound_at, stick_at] is 10^-(digits+1) of the threshold; the threshold column is "
                    "the bracket's midpoint rounded to 'digits' digits"}};
  const table_settings settings = table_settings::from(spec);
  const int digits = spec.threshold_digits;
  job.compute_line = [points, settings, digits](std::size_t i) {
    return csv_line(compute_threshold_row((*points)[i], digits, settings));
  };
  return run_table_job(job);
}

std::size_t merge_tables(const std::vector<std::string>& input_paths, const std::string& output,
                         bool quiet) {
  if (input_paths.empty()) throw invalid_parameter("viscor table merge needs the shard tables to merge");
  if (output.empty()) throw invalid_parameter("viscor table merge needs an output file: -o OUT.csv");
  // Before any reading: the outputs must be ours to write, and no other viscor may be
  // writing them (a table run or another merge of the same output).
  for (const std::string& path : {output, output + ".json"}) {
    refuse_unless_regular_or_absent(path);
    refuse_committed_unless_allowed(path);
  }
  const output_lock lock(output);
  struct input {
    std::string path;
    table_format format;
    csv_table table;
    json sidecar;
  };
  std::vector<input> inputs;
  for (const auto& path : input_paths) {
    if (std::filesystem::exists(path + ".partial"))
      throw error("'" + path + "' is unfinished ('" + path + ".partial' exists): complete it with "
                  VISCOR_FIELD("resume") " first");
    const table_format format = table_format::of_file(path);
    input in{path, format, format.read(path), json()};
    if (!std::filesystem::exists(path + ".json"))
      throw error("'" + path + ".json' (the sidecar of '" + path +
                  "') is missing: merge needs it to check that the shards come from the same spec and version");
    in.sidecar = read_json_file(path + ".json");
    for (const char* key : {"viscor_version", "kind", "spec", "rows_total"})
      if (!in.sidecar.contains(key))
        throw parse_error(path + ".json: field " + std::string(key) + ": missing; not a viscor table sidecar");
    inputs.push_back(std::move(in));
  }
  // Same spec, kind, precision and viscor version everywhere; shards may differ.
  auto common = [](const json& sidecar) {
    json f = table_fingerprint(sidecar);
    f.erase("shard");
    return f;
  };
  const json reference = common(inputs.front().sidecar);
  const std::int64_t rows_total = reference.value("rows_total", std::int64_t(-1));
  for (const auto& in : inputs) {
    if (in.table.kind != inputs.front().table.kind || in.format.proven != inputs.front().format.proven ||
        in.format.physical != inputs.front().format.physical)
      throw parse_error(in.path + ":1: wrong columns: the tables to merge must be of one kind");
    if (common(in.sidecar) != reference)
      throw error("cannot merge '" + in.path + "' with '" + inputs.front().path +
                  "': their sidecars record a different spec, precision, method or viscor version");
  }
  // Every row is the grid point its index names in the spec the sidecars record
  // (a surrogate's verification table holds drawn points, no grid: not checked).
  const table_kind kind = inputs.front().table.kind;
  const bool on_grid = !reference["spec"].contains("surrogate_spec");
  const std::vector<std::string> keys =
      on_grid ? detail::grid_keys(parse_normalised_spec(reference["spec"], inputs.front().path + ".json"), kind)
              : std::vector<std::string>{};
  if (on_grid && static_cast<std::int64_t>(keys.size()) != rows_total)
    throw parse_error(inputs.front().path + ".json: field rows_total: " + std::to_string(rows_total) +
                      ", but its spec has " + std::to_string(keys.size()) + " grid points");
  // Every grid row exactly once, each in the shard that claims it.
  std::map<std::int64_t, std::pair<const input*, std::size_t>> seen;  // index -> (file, line)
  std::vector<csv_record> rows;
  for (const auto& in : inputs) {
    const json s = in.sidecar.value("shard", json(nullptr));
    const shard part = s.is_object() ? shard{s.value("index", std::int64_t(0)), s.value("count", std::int64_t(1))}
                                     : shard{};
    for (const auto& row : in.table.rows) {
      if (row.index >= rows_total)
        throw parse_error(in.path + ":" + std::to_string(row.line) + ": field index: " + std::to_string(row.index) +
                          " is beyond the grid's " + std::to_string(rows_total) + " rows");
      if (!part.contains(row.index))
        throw parse_error(in.path + ":" + std::to_string(row.line) + ": field index: row " +
                          std::to_string(row.index) + " does not belong to shard " + part.to_string());
      if (on_grid && in.format.key(row) != keys[static_cast<std::size_t>(row.index)])
        throw parse_error(in.path + ":" + std::to_string(row.line) + ": fields law..g: row " +
                          std::to_string(row.index) + " is (" + in.format.key(row) + "), not the grid point (" +
                          keys[static_cast<std::size_t>(row.index)] + ") of the spec its sidecar records");
      const auto [it, fresh] = seen.emplace(row.index, std::make_pair(&in, row.line));
      if (!fresh)
        throw parse_error(in.path + ":" + std::to_string(row.line) + ": field index: row " +
                          std::to_string(row.index) + " is also in " + it->second.first->path + ":" +
                          std::to_string(it->second.second));
      rows.push_back(row);
    }
  }
  if (static_cast<std::int64_t>(rows.size()) != rows_total) {
    std::int64_t missing = 0;
    while (seen.count(missing)) ++missing;
    throw error("cannot merge: the tables hold " + std::to_string(rows.size()) + " of the grid's " +
                std::to_string(rows_total) + " rows; row " + std::to_string(missing) +
                " is missing (a shard not given, or not finished?)");
  }
  const table_format& format = inputs.front().format;
  const std::string text = format.text(rows, output);

  json sidecar = inputs.front().sidecar;
  double wall_total = 0;
  json parts = json::array();
  for (const auto& in : inputs) {
    const double w = in.sidecar.value("wall_time_seconds", 0.0);
    wall_total += w;
    parts.push_back({{"table", in.path},
                     {"shard", in.sidecar.value("shard", json(nullptr))},
                     {"rows", in.table.rows.size()},
                     {"host", in.sidecar.value("host", "")},
                     {"date", in.sidecar.value("date", "")},
                     {"threads", in.sidecar.value("threads", 0)},
                     {"wall_time_seconds", w},
                     {"command_line", in.sidecar.value("command_line", "")}});
  }
  sidecar["table"] = std::filesystem::path(output).filename().string();
  sidecar["rows"] = rows.size();
  sidecar["shard"] = nullptr;
  std::size_t exact_rows = 0;
  for (const auto& row : rows) exact_rows += row.fields[format.method_column()] == "exact";
  sidecar["rows_by_method"] = {{"exact", exact_rows}, {"certified", rows.size() - exact_rows}};
  if (format.proven) sidecar["proofs"] = proof_summary(rows);
  sidecar["command_line"] = command_line();
  sidecar["host"] = host_name();
  sidecar["date"] = iso_time_utc(std::time(nullptr));
  sidecar["wall_time_seconds"] = wall_total;
  sidecar["merged_from"] = parts;
  for (const char* k : {"threads", "sessions", "rows_from_earlier_sessions"}) sidecar.erase(k);

  write_together({{output, text}, {output + ".json", sidecar.dump(2) + "\n"}});
  if (!quiet)
    std::cerr << "viscor table merge: wrote " << output << " (" << rows.size() << " rows from "
              << inputs.size() << " tables)\n";
  return rows.size();
}

}  // namespace viscor::jobs
