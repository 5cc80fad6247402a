// The bench jobs' results (jobs/bench_job.hpp) as readable text (Markdown tables) and
// as JSON, for `viscor bench`.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/bench_job.hpp>
#include <viscor/jobs/json_fields.hpp>

#include <cstdio>
#include <sstream>
#include <string>

namespace viscor::render {

/// The object of `viscor bench --json`.
inline jobs::json bench_json(const jobs::bench_result& r) {
  jobs::json j;
  j["command"] = "bench";
  j["laws"] = r.laws;
  j["reference"] = r.reference;
  j["points_per_law"] = r.points_per_law;
  j["reference_seconds"] = r.reference_seconds;
  jobs::json rows = jobs::json::array();
  for (const auto& row : r.rows) {
    jobs::json o;
    o[field::method] = row.method, o["scalar"] = row.scalar, o["median_seconds"] = row.median_seconds;
    o["max_abs_error"] = row.max_abs_error, o["median_abs_error"] = row.median_abs_error;
    o["max_rel_error"] = row.max_rel_error, o["median_rel_error"] = row.median_rel_error, o["points"] = row.points;
    rows.push_back(o);
  }
  j["rows"] = rows;
  return j;
}

/// The readable table of `viscor bench`.
inline std::string bench_text(const jobs::bench_result& r) {
  std::ostringstream text;
  char buffer[64];
  text << "| method | precision | median time per CoR | max abs error | median abs error | max rel error | "
          "median rel error | points |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& row : r.rows) {
    std::snprintf(buffer, sizeof buffer, "%.3g s", row.median_seconds);
    text << "| " << row.method << " | " << row.scalar << " | " << (row.points ? buffer : "-") << " | "
         << row.max_abs_error << " | " << row.median_abs_error << " | " << row.max_rel_error << " | "
         << row.median_rel_error << " | " << row.points << " |\n";
  }
  text << "\nreference: " << r.reference << "; points gamma in {1e-3, 1e-2, 0.1} x g in {0, 0.05, 1} for " << r.laws
       << " (" << r.points << " points, " << r.reference_seconds << " s); relative errors over the rebounding points\n";
  return text.str();
}

/// The object of `viscor bench --surrogate --json`.
inline jobs::json surrogate_bench_json(const jobs::surrogate_bench_result& r) {
  jobs::json rows = jobs::json::array();
  for (const auto& row : r.rows)
    rows.push_back({{"law", row.law}, {"stream", row.stream}, {"points", row.points}, {"median_ns", row.median_ns},
                    {"p99_ns", row.p99_ns}, {"max_ns", row.max_ns}, {"raw_max_ns", row.raw_max_ns},
                    {"stream_mean_ns", row.stream_mean_ns}, {"taylor_double_mean_ns", row.taylor_double_mean_ns},
                    {"taylor_points", row.taylor_points}, {"taylor_over_surrogate", row.taylor_over_surrogate}});
  jobs::json j;
  j["command"] = "bench";
  j["mode"] = "surrogate";
  j["points_per_law"] = r.points_per_law;
  j[field::method] = r.method;
  j["fma_path"] = r.fma_path;
  j["rows"] = rows;
  j["skipped_without_surrogate"] = r.skipped_without_surrogate;
  return j;
}

/// The readable table of `viscor bench --surrogate`.
inline std::string surrogate_bench_text(const jobs::surrogate_bench_result& r) {
  std::ostringstream text;
  text << "| law | points | stream | median | p99 | max (slowest point) | mean in a stream | Taylor double (mean) | "
          "Taylor / surrogate |\n|---|---|---|---|---|---|---|---|---|\n";
  char buffer[256];
  for (const auto& row : r.rows) {
    std::snprintf(buffer, sizeof buffer, "| %s | %zu | %s | %.0f ns | %.0f ns | %.0f ns | %.0f ns | %.3g us | %.0fx |\n",
                  row.law.c_str(), row.points, row.stream.c_str(), row.median_ns, row.p99_ns, row.max_ns,
                  row.stream_mean_ns, row.taylor_double_mean_ns / 1000, row.taylor_over_surrogate);
    text << buffer;
  }
  text << "\n" << r.points_per_law << " fixed-seed random points per law (gamma uniform in [0, gamma_max], g half "
       << "log-uniform in [1e-3, g_max], half uniform in [g_min, 10]); 'mixed' is all of them, 'rebound' the "
       << "rebounds among them. " << r.method << "; FMA path: " << (r.fma_path ? "yes" : "no") << "\n";
  for (const auto& name : r.skipped_without_surrogate) text << "no committed surrogate for " << name << " (skipped)\n";
  return text.str();
}

}  // namespace viscor::render
