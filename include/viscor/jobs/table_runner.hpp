// Running a table: rows computed in parallel threads, each finished row appended
// (one write(2) of one whole line) to OUT.partial, so a kill, Ctrl-C or a batch
// scheduler's SIGTERM never loses or corrupts a finished row; --resume reads the
// partial file back (dropping a line cut short) and computes only what is
// missing. At the end the rows are sorted into grid order and the CSV and its
// JSON sidecar are written to temporaries and renamed into place, so the CSV is
// byte-identical however the run was split, interrupted or threaded.
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/provenance.hpp>
#include <viscor/jobs/table_format.hpp>

#include <viscor/config.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/tables/reference_table.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace viscor::jobs {

/// What to compute and where to put it.
struct table_job {
  table_kind kind = table_kind::cor;
  /// The rows carry the proof's columns (method "proven", table_format.hpp); compute_line adds them.
  bool proven = false;
  /// The rows carry the physical columns (a spec in SI, table_format.hpp).
  bool physical = false;
  std::string output;                   ///< OUT.csv
  std::vector<std::int64_t> indices;    ///< grid indices of the rows of this run (its shard), ascending
  std::function<std::string(std::size_t)> compute_line;  ///< CSV line of row indices[i] (thread-safe)
  /// The key (table_format::key) row indices[i] must have: --resume checks the
  /// rows it keeps against it. Empty: not checked.
  std::function<std::string(std::size_t)> expected_grid_key;
  /// Sidecar fields (version, kind, spec, shard, scalar, method, ...); the
  /// table_fingerprint of them must match for --resume and merge.
  json provenance;
  bool resume = false;
  int threads = 1;
  bool quiet = false;
  /// Ctrl-C and SIGTERM stop the run after the rows in progress (a second one at
  /// once); the command-line tool sets it. Off, the caller's own handlers stay.
  bool handle_signals = false;
  /// Asked about every 0.2 s from the calling thread: true stops the run like an
  /// interrupt (the finished rows are kept). The Python module checks Ctrl-C here.
  std::function<bool()> should_stop;
  /// Called with (rows done, rows of the run) from the calling thread when should_stop
  /// is asked, and once at the end: a front end's own progress display (Python's tqdm).
  std::function<void(std::size_t, std::size_t)> on_progress;
  /// Also publish the table's NetCDF form (jobs/netcdf_file.hpp) at
  /// netcdf_path_for(output), together with the table and its sidecar.
  bool netcdf = false;
  /// A test seam: after this many rows of this session the run interrupts itself,
  /// as a Ctrl-C would; -1: never.
  long long stop_after_rows = -1;
};

/// A job writing `output` with the run settings of `run` (any options struct with
/// resume, threads, quiet, handle_signals, should_stop and stop_after_rows: the
/// table jobs' and the surrogate build's), and the sidecar fields every table has:
/// version, commit, kind, columns, rows_total, shard, spec_file. The caller adds
/// the spec, scalar and method, and the rows.
template <class RunOptions>
table_job new_table_job(const RunOptions& run, table_kind kind, bool proven, const std::string& output,
                        std::int64_t rows_total, const shard& part, const std::string& spec_file) {
  table_job j;
  j.kind = kind;
  j.proven = proven;
  j.output = output;
  j.resume = run.resume;
  j.threads = run.threads;
  j.quiet = run.quiet;
  j.handle_signals = run.handle_signals;
  j.should_stop = run.should_stop;
  if constexpr (requires { run.on_progress; }) j.on_progress = run.on_progress;
  if constexpr (requires { run.netcdf; }) j.netcdf = run.netcdf;
  j.stop_after_rows = run.stop_after_rows;
  json& p = j.provenance;
  p["viscor_version"] = VISCOR_VERSION;
  p["git_commit"] = git_commit();
  p["kind"] = kind == table_kind::cor ? "cor" : "sticking";
  p["columns"] = table_format{kind, proven}.header();
  p["rows_total"] = rows_total;
  p["shard"] = part.whole() ? json(nullptr) : json{{"index", part.index}, {"count", part.count}};
  p["spec_file"] = spec_file;
  return j;
}

/// What must agree between a partial run and its resumption, and (without
/// "shard") between the shards of one table: everything that decides the rows.
inline json table_fingerprint(const json& provenance) {
  json f;
  for (const char* key : {"viscor_version", "git_commit", "kind", "rows_total", "shard", "spec", "threshold"})
    if (provenance.contains(key)) f[key] = provenance[key];
  if (provenance.contains("scalar")) f["scalar"] = provenance["scalar"].value("type", "");
  if (provenance.contains("method")) f["certify_available"] = provenance["method"].value("certify_available", false);
  return f;
}

/// What a finished run did.
struct table_run_summary {
  std::size_t rows = 0;                       ///< rows in the output table
  std::size_t rows_from_earlier_sessions = 0;  ///< rows an interrupted run had already finished
  bool already_complete = false;               ///< --resume of a finished table: nothing was computed
  double wall_time_seconds = 0;                ///< of this session
};

/// A table run stopped by an interruption (Ctrl-C, SIGTERM, a front end's stop): how
/// many rows are kept, and where, so that each front end can say how to go on.
struct table_interrupted : error {
  /// rows_done of rows_total rows are kept in partial_file; the message is the CLI's.
  table_interrupted(std::size_t rows_done, std::size_t rows_total, std::string partial_file)
      : error("interrupted: " + std::to_string(rows_done) + " of " + std::to_string(rows_total) +
              " rows are done and kept in '" + partial_file + "'; rerun the same command with "
              VISCOR_FIELD("resume") " to continue"),
        done(rows_done),
        total(rows_total),
        partial(std::move(partial_file)) {}
  std::size_t done;     ///< rows finished and kept
  std::size_t total;    ///< rows of the run
  std::string partial;  ///< the file that keeps them
};

/// Runs the job in its named steps: check the files, take the lock, resume or start,
/// compute the rows left, publish. Throws viscor::error on failure and
/// table_interrupted on interruption (the partial file is then kept for resume).
table_run_summary run_table_job(const table_job& job);

}  // namespace viscor::jobs
