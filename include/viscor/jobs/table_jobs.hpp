// The table jobs (docs/tables.md): a certified CoR table or a table of sticking
// thresholds from a grid spec, sharded, threaded and resumable, and the merge of
// shard tables into the whole one. Rows come from compute_row and
// compute_threshold_row (tables/), and for method "proven" also from
// viscor::enclose (proven_rows.hpp, when VISCOR_WITH_ENCLOSE); files, threads,
// progress and resume from table_runner.hpp. The command-line tool's `viscor table`,
// the Python module's viscor.table and C++ programs all call these.
#pragma once

#include <viscor/jobs/table_runner.hpp>
#include <viscor/jobs/table_spec.hpp>

#include <algorithm>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace viscor::jobs {

/// How to run a table: where it goes, which shard, how many threads, resume or not.
struct table_run_options {
  std::string output;      ///< OUT.csv (its sidecar is OUT.csv.json)
  std::string spec_file;   ///< recorded in the sidecar ("" for a spec given as text)
  shard part;              ///< the whole table by default
  bool resume = false;     ///< continue from OUT.csv.partial
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool quiet = false;      ///< no progress or summary on standard error
  bool handle_signals = false;      ///< see table_job
  std::function<bool()> should_stop;  ///< see table_job
  std::function<void(std::size_t, std::size_t)> on_progress;  ///< see table_job
  bool netcdf = false;                ///< see table_job
  long long stop_after_rows = -1;     ///< test seam, see table_job
  std::string certified_e_shift;      ///< test seam, see proven_fields
};

/// Computes the CoR table of `table` (or its shard) into run.output and its sidecar.
table_run_summary make_cor_table(const table_spec& table, const table_run_options& run);
/// Computes the sticking-threshold table of `table` (or its shard) into run.output.
table_run_summary make_sticking_table(const table_spec& table, const table_run_options& run);
/// Joins shard tables (each with its sidecar) into the whole table `output`:
/// every grid row exactly once, all from one spec, precision and viscor version. Holds
/// the output's lock (output_lock) as a table run does.
std::size_t merge_tables(const std::vector<std::string>& input_paths, const std::string& output,
                         bool quiet = false);

}  // namespace viscor::jobs
