// Running a table (include/viscor/jobs/table_runner.hpp), compiled once: the files,
// the lock, resume, the rows in threads, interruption and publishing.
#include <viscor/jobs/table_runner.hpp>

#include <viscor/jobs/files.hpp>
#include <viscor/jobs/netcdf_file.hpp>
#include <viscor/jobs/table_dataset.hpp>
#include <viscor/jobs/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <unistd.h>

namespace viscor::jobs {

namespace detail {

// Ctrl-C / SIGTERM: the first asks the workers to stop after their current row;
// a second one exits at once (finished rows are already on disk).
inline std::atomic<int> interrupts{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free counter");

inline void on_interrupt(int) {
  if (++interrupts >= 2) _exit(130);
  static const char message[] =
      "\nviscor table: interrupted: finishing the rows in progress (interrupt again to stop at once)\n";
  const ssize_t ignored = ::write(2, message, sizeof message - 1);
  (void)ignored;
}

/// Installs on_interrupt for SIGINT and SIGTERM for its lifetime.
class interrupt_guard {
 public:
  interrupt_guard() {
    interrupts = 0;
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &m_old_int);
    sigaction(SIGTERM, &sa, &m_old_term);
  }
  ~interrupt_guard() {
    sigaction(SIGINT, &m_old_int, nullptr);
    sigaction(SIGTERM, &m_old_term, nullptr);
  }
  interrupt_guard(const interrupt_guard&) = delete;
  interrupt_guard& operator=(const interrupt_guard&) = delete;

 private:
  struct sigaction m_old_int {}, m_old_term {};
};

/// Progress on standard error: a bar redrawn in place on a terminal, plain
/// lines every `interval` seconds otherwise.
class progress_meter {
 public:
  progress_meter(std::size_t total, std::size_t done_before, bool quiet)
      : m_total(total), m_before(done_before), m_quiet(quiet), m_tty(isatty(2) != 0),
        m_start(std::chrono::steady_clock::now()), m_last(m_start) {}

  /// Call often; draws when due.
  void update(std::size_t done_now, bool final = false) {
    if (m_quiet) return;
    const auto now = std::chrono::steady_clock::now();
    const double since_last = std::chrono::duration<double>(now - m_last).count();
    if (!final && since_last < (m_tty ? 0.2 : 5.0)) return;
    m_last = now;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const std::size_t done = m_before + done_now;
    const double rate = elapsed > 0 ? static_cast<double>(done_now) / elapsed : 0;
    const double eta = rate > 0 ? static_cast<double>(m_total - done) / rate : -1;
    std::ostringstream s;
    s << done << '/' << m_total << " rows";
    if (m_total > 0) s << " (" << std::fixed << std::setprecision(1) << 100.0 * static_cast<double>(done) / static_cast<double>(m_total) << "%)";
    s << std::setprecision(rate >= 10 ? 0 : 2) << std::fixed << ", " << rate << " rows/s";
    s << ", elapsed " << duration_text(elapsed) << ", ETA " << (done == m_total ? "00:00" : duration_text(eta));
    if (m_tty) {
      constexpr int width = 30;
      const int filled = m_total ? static_cast<int>(width * done / m_total) : width;
      std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
                << std::string(static_cast<std::size_t>(width - filled), '.') << "] " << s.str() << "   "
                << (final ? "\n" : "") << std::flush;
    } else {
      std::cerr << "viscor table: " << s.str() << '\n' << std::flush;
    }
  }

 private:
  std::size_t m_total, m_before;
  bool m_quiet, m_tty;
  std::chrono::steady_clock::time_point m_start, m_last;
};

/// Appends whole lines to a file with one write(2) each: a line is either
/// entirely in the file or (if the process dies inside write) cut short at the end.
class line_appender {
 public:
  explicit line_appender(const std::string& path) : m_path(path) {
    m_fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (m_fd < 0) throw error("cannot open '" + path + "' for appending");
  }
  ~line_appender() { ::close(m_fd); }
  line_appender(const line_appender&) = delete;
  line_appender& operator=(const line_appender&) = delete;

  void append(const std::string& line) {
    const std::string data = line + "\n";
    std::size_t written = 0;
    while (written < data.size()) {
      const ssize_t n = ::write(m_fd, data.data() + written, data.size() - written);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw error("writing to '" + m_path + "' failed");
      }
      written += static_cast<std::size_t>(n);
    }
  }

 private:
  std::string m_path;
  int m_fd = -1;
};

inline void remove_file(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

}  // namespace detail

namespace detail {

/// The files of one run: the table and its sidecar, and while it runs the partial
/// table and what it is computing (for resume).
struct run_files {
  explicit run_files(const std::string& output)
      : table(output), sidecar(output + ".json"), partial(output + ".partial"), partial_meta(output + ".partial.json") {}
  std::string table, sidecar, partial, partial_meta;
};

/// Before any work: every file the run writes is a regular file or absent, and none
/// is committed data (refused before hours of work, not at the end).
inline void check_run_files(const run_files& files) {
  for (const std::string& path : {files.table, files.sidecar, files.partial, files.partial_meta}) {
    refuse_unless_regular_or_absent(path);
    refuse_committed_unless_allowed(path);
  }
}

/// What earlier sessions left: the rows done (kept in the partial table), the partial
/// run's metadata, or a table that is already complete.
struct earlier_sessions {
  std::set<std::int64_t> done;
  json meta;
  bool already_complete = false;
};

/// Reads back the rows of an interrupted run (resume: each row checked to be one of
/// this run's, once, at its grid point), or starts the partial files afresh; a
/// resume of a table that is complete does nothing.
inline earlier_sessions resume_or_start(const table_job& job, const table_format& format, const json& fingerprint,
                                        const run_files& files) {
  const std::string& partial = files.partial;
  const std::string& partial_meta = files.partial_meta;
  const std::set<std::int64_t> wanted(job.indices.begin(), job.indices.end());
  earlier_sessions earlier;
  std::set<std::int64_t>& done = earlier.done;
  json& meta = earlier.meta;
  const bool have_partial = std::filesystem::exists(partial);
  if (have_partial && !job.resume)
    throw error("'" + partial + "' exists: an interrupted run of this table. Add " VISCOR_FIELD("resume")
                " to continue it, or "
                "delete it (and '" + partial_meta + "') to start afresh");
  if (have_partial) {
    if (!std::filesystem::exists(partial_meta))
      throw error("cannot resume: '" + partial_meta + "' (what the partial run was computing) is missing");
    meta = read_json_file(partial_meta);
    if (meta.value("fingerprint", json()) != fingerprint)
      throw error("cannot resume: '" + partial + "' was made from a different spec, shard or viscor version "
                  "(see '" + partial_meta + "'); delete both files to start afresh");
    const csv_table table = format.read(partial, /*allow_truncated_tail=*/true);
    if (table.kind != job.kind) throw parse_error(partial + ":1: wrong columns for this kind of table");
    std::vector<csv_record> rows;
    for (const auto& row : table.rows) {
      if (!wanted.count(row.index))
        throw parse_error(partial + ":" + std::to_string(row.line) + ": field index: row " +
                          std::to_string(row.index) + " is not part of this run");
      if (!done.insert(row.index).second)
        throw parse_error(partial + ":" + std::to_string(row.line) + ": field index: row " +
                          std::to_string(row.index) + " appears twice");
      if (job.expected_grid_key) {  // a row kept must be the grid point its index names
        const auto at = std::lower_bound(job.indices.begin(), job.indices.end(), row.index);
        const std::string expected = job.expected_grid_key(static_cast<std::size_t>(at - job.indices.begin()));
        const std::string found = format.key(row);
        if (found != expected)
          throw parse_error(partial + ":" + std::to_string(row.line) + ": fields law..g: row " +
                            std::to_string(row.index) + " is (" + found + "), not the grid point (" + expected +
                            ") of this spec; delete the partial files to start afresh");
      }
      rows.push_back(row);
    }
    // Rewrite without a line cut short by a kill, so appends start on a fresh line.
    std::string clean = format.header() + "\n";
    for (const auto& row : rows) clean += row.text + "\n";
    write_atomically(partial, clean);
    if (!job.quiet)
      std::cerr << "viscor table: resuming: " << done.size() << " of " << job.indices.size()
                << " rows already done" << (table.truncated_tail ? " (dropped one row cut short)" : "") << '\n';
    return earlier;
  }
  // --resume of a run that already finished (a resubmitted batch job): nothing to do.
  if (job.resume && std::filesystem::exists(files.table) && std::filesystem::exists(files.sidecar)) {
    bool complete = false;
    try {
      complete = table_fingerprint(read_json_file(files.sidecar)) == fingerprint &&
                 format.read(files.table).rows.size() == job.indices.size();
    } catch (const error&) {
      complete = false;  // unreadable: compute it again
    }
    if (complete) {
      if (!job.quiet) std::cerr << "viscor table: '" << files.table << "' is already complete; nothing to do\n";
      earlier.already_complete = true;
      return earlier;
    }
  }
  if (job.resume && !job.quiet) std::cerr << "viscor table: nothing to resume; computing every row\n";
  meta["fingerprint"] = fingerprint;
  meta["note"] = "an interrupted viscor table run: rerun the same command with --resume";
  write_together({{partial_meta, meta.dump(2) + "\n"}, {partial, format.header() + "\n"}});
  return earlier;
}

/// Computes the rows not done yet on the job's threads, appending each to the partial
/// table as it is finished, with progress, Ctrl-C/SIGTERM and should_stop polled.
/// On a failure or an interruption it saves the session's time in the partial
/// metadata and throws (table_interrupted when stopped), the rows done kept.
inline void compute_pending_rows(const table_job& job, const earlier_sessions& earlier, const run_files& files,
                                 std::chrono::steady_clock::time_point wall_start) {
  const std::set<std::int64_t>& done = earlier.done;
  std::vector<std::size_t> pending;  // positions in job.indices
  for (std::size_t i = 0; i < job.indices.size(); ++i)
    if (!done.count(job.indices[i])) pending.push_back(i);

  const long long stop_after = job.stop_after_rows;
  detail::interrupts = 0;
  std::optional<detail::interrupt_guard> guard;
  if (job.handle_signals) guard.emplace();
  std::atomic<bool> stop_requested{false};  // by should_stop, or by the test seam without signals
  detail::line_appender out(files.partial);
  detail::progress_meter progress(job.indices.size(), done.size(), job.quiet);
  std::mutex mutex;  // guards out and finished
  std::size_t finished = 0;
  parallel_for_options options;
  options.threads = static_cast<unsigned>(std::max(1, job.threads));
  options.keep_going = [&] { return !stop_requested && detail::interrupts == 0; };
  const auto report = [&](std::size_t rows_finished) {
    if (job.on_progress) job.on_progress(done.size() + rows_finished, job.indices.size());
  };
  options.poll = [&] {
    std::size_t rows_finished = 0;
    {
      std::lock_guard lock(mutex);
      progress.update(finished);
      rows_finished = finished;
    }
    report(rows_finished);
    if (job.should_stop && !stop_requested && job.should_stop()) stop_requested = true;
    return !stop_requested && detail::interrupts == 0;
  };
  const parallel_for_result run = parallel_for(
      pending.size(),
      [&](std::size_t k) {
        const std::string line = job.compute_line(pending[k]);
        std::lock_guard lock(mutex);
        out.append(line);
        ++finished;
        if (stop_after >= 0 && static_cast<long long>(finished) == stop_after) {
          if (job.handle_signals) std::raise(SIGINT);  // exactly what a Ctrl-C does
          else stop_requested = true;
        }
      },
      options);
  progress.update(finished, /*final=*/true);
  report(finished);

  const bool interrupted = detail::interrupts > 0 || stop_requested;
  if (!run.failed() && !interrupted) return;
  json meta = earlier.meta;
  meta["wall_time_seconds"] = meta.value("wall_time_seconds", 0.0) +
                              std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  meta["sessions"] = meta.value("sessions", 0) + 1;
  write_atomically(files.partial_meta, meta.dump(2) + "\n");
  const std::string kept = std::to_string(done.size() + finished) + " of " + std::to_string(job.indices.size()) +
                           " rows are done and kept in '" + files.partial + "'";
  if (run.failed()) {
    try {
      std::rethrow_exception(run.failure);
    } catch (const error& e) {
      throw error(e.marked() + "\n  " + kept + "; fix the cause and rerun with " VISCOR_FIELD("resume"));
    } catch (const std::exception& e) {
      throw error(std::string("internal error: ") + e.what() + "\n  " + kept);
    }
  }
  throw table_interrupted(done.size() + finished, job.indices.size(), files.partial);
}

/// The NetCDF form of a table's text and sidecar (jobs/netcdf_file.hpp).
inline output_file netcdf_output(const table_job& job, const std::string& table_text, const std::string& sidecar_text) {
  return {netcdf_path_for(job.output), netcdf_file_bytes(table_dataset_of(table_text, sidecar_text, job.output))};
}

/// A NetCDF form is asked for where it can be written: a whole CoR table, a build with libnetcdf.
inline void check_netcdf_request(const table_job& job) {
  if (!job.netcdf) return;
  if (job.kind != table_kind::cor)
    throw invalid_parameter("format netcdf: a sticking-threshold table has no grid of e; NetCDF is for CoR tables");
  if (job.provenance.contains("shard") && !job.provenance["shard"].is_null())
    throw invalid_parameter("format netcdf: a shard is not the whole grid; write the NetCDF form of the merged "
                            "table (viscor table netcdf)");
  require_netcdf();
}

/// Every row done: sorts them into grid order and publishes the table and its sidecar
/// together, then removes the partial files.
inline table_run_summary publish_table(const table_job& job, const table_format& format,
                                       const earlier_sessions& earlier, const run_files& files, std::time_t started,
                                       std::chrono::steady_clock::time_point wall_start) {
  const csv_table table = format.read(files.partial);
  const std::string text = format.text(table.rows, files.partial);
  if (table.rows.size() != job.indices.size())
    throw error("internal error: '" + files.partial + "' holds " + std::to_string(table.rows.size()) +
                " rows, expected " + std::to_string(job.indices.size()));
  std::size_t exact_rows = 0, certified_rows = 0;
  for (const auto& row : table.rows) (row.fields[format.method_column()] == "exact" ? exact_rows : certified_rows)++;

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  json sidecar;
  sidecar["table"] = std::filesystem::path(job.output).filename().string();
  for (auto it = job.provenance.begin(); it != job.provenance.end(); ++it) sidecar[it.key()] = it.value();
  sidecar["rows"] = table.rows.size();
  sidecar["rows_by_method"] = {{"exact", exact_rows}, {"certified", certified_rows}};
  if (format.proven) sidecar["proofs"] = proof_summary(table.rows);
  sidecar["command_line"] = command_line();
  sidecar["host"] = host_name();
  sidecar["date"] = iso_time_utc(started);
  sidecar["threads"] = job.threads;
  sidecar["wall_time_seconds"] = earlier.meta.value("wall_time_seconds", 0.0) + wall;
  sidecar["sessions"] = earlier.meta.value("sessions", 0) + 1;
  sidecar["rows_from_earlier_sessions"] = earlier.done.size();

  std::vector<output_file> outputs{{files.table, text}, {files.sidecar, sidecar.dump(2) + "\n"}};
  if (job.netcdf) outputs.push_back(netcdf_output(job, outputs[0].body, outputs[1].body));
  write_together(outputs);
  detail::remove_file(files.partial);
  detail::remove_file(files.partial_meta);
  if (!job.quiet)
    std::cerr << "viscor table: wrote " << job.output << " (" << table.rows.size() << " rows) and " << job.output
              << ".json in " << std::fixed << std::setprecision(2) << wall << " s\n";
  table_run_summary summary;
  summary.rows = table.rows.size();
  summary.rows_from_earlier_sessions = earlier.done.size();
  summary.wall_time_seconds = wall;
  return summary;
}

}  // namespace detail

/// Runs the job in its named steps: check the files, take the lock, resume or start,
/// compute the rows left, publish. Throws viscor::error on failure and
/// table_interrupted on interruption (the partial file is then kept for resume).
table_run_summary run_table_job(const table_job& job) {
  const auto wall_start = std::chrono::steady_clock::now();
  const std::time_t started = std::time(nullptr);
  const table_format format{job.kind, job.proven, job.physical};
  const detail::run_files files(job.output);
  detail::check_run_files(files);
  detail::check_netcdf_request(job);
  const output_lock lock(job.output);  // no other run may be writing these files
  const detail::earlier_sessions earlier = detail::resume_or_start(job, format, table_fingerprint(job.provenance), files);
  if (earlier.already_complete) {
    if (job.netcdf) {  // the NetCDF form of the finished table
      const std::string table_text = read_checked_file<error>(files.table, "table");
      write_together({detail::netcdf_output(job, table_text, read_checked_file<error>(files.sidecar, "table sidecar"))});
    }
    table_run_summary summary;
    summary.rows = job.indices.size();
    summary.already_complete = true;
    return summary;
  }
  detail::compute_pending_rows(job, earlier, files, wall_start);
  return detail::publish_table(job, format, earlier, files, started, wall_start);
}

}  // namespace viscor::jobs
