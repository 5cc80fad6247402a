// `viscor bench`: the speed-accuracy trade, measured. For each method -- the double
// approximations, the Taylor solve in double, long double, double-double, float128 and MPFR at
// chosen digits, certify, and evaluate at a few tolerances -- the median time per
// CoR and the error against a reference, over a fixed point set per law.
//
// Point set per law: gamma in {1e-3, 1e-2, 0.1} x g in {0, 0.05, 1}, taken with
// their reference values from a committed certified table (`table`, by default
// reference_data/cor_report_grid.csv, 30-34 certified digits). Methods more
// precise than the table are measured against solve_impact at (largest digits
// benchmarked + 20) digits, which must first agree with the table to every
// certified digit: the table anchors the reference, the solve extends it.
// Relative errors are over the rebounding points (e > 0) only.
//
// run_surrogate_bench: per committed surrogate, the time of one evaluation on
// fixed-seed random points of the domain (median, 99th percentile, slowest point,
// each evaluation timed alone: surrogate/surrogate_timing.hpp) and the mean in a
// stream, for all the points (mixed) and for the rebounds only, next to the Taylor
// solve in double on the same kind of points, in the same run.
// Rendered by jobs/bench_render.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace viscor::jobs {

/// What to measure; the laws and precisions are comma-separated lists.
struct bench_request {
  std::string laws = "linear,hertz_linear_damping,tsuji,kuwabara_kono,hunt_crossley";
  std::string precisions = "30,50,100,200";  ///< MPFR digits to measure
  std::string error_maps;  ///< directory of error maps for the evaluate rows ("": none)
  std::string table;       ///< certified CoR table of the point set ("": the data directory's cor_report_grid.csv)
  bool certified = false;  ///< also measure certify
  double min_time = 0.02;  ///< seconds of repetitions per point and method
  /// run_surrogate_bench: random points per law, timings per point, points solved by Taylor.
  int surrogate_points = 16384, surrogate_passes = 9, taylor_points = 256;
};

/// One method's median time per CoR and its errors (decimal text, 2 digits; "" where none).
struct bench_row {
  std::string method, scalar;
  double median_seconds = 0;
  std::string max_abs_error, median_abs_error, max_rel_error, median_rel_error;
  int points = 0;  ///< points the method applies at
};

/// The speed-accuracy table.
struct bench_result {
  std::string laws;
  std::string reference;  ///< what the errors are measured against
  int points_per_law = 9;
  std::size_t points = 0;
  double reference_seconds = 0;  ///< time to compute the reference
  std::vector<bench_row> rows;
};

/// One surrogate's evaluation times on one stream of points.
struct surrogate_bench_row {
  std::string law, stream;  ///< stream: "mixed" (all points) or "rebound"
  std::size_t points = 0;
  double median_ns = 0, p99_ns = 0, max_ns = 0, raw_max_ns = 0, stream_mean_ns = 0;
  double taylor_double_mean_ns = 0;  ///< solve_impact<double> on the stream's first taylor_points points
  std::size_t taylor_points = 0;
  double taylor_over_surrogate = 0;
};

/// The surrogates' evaluation times.
struct surrogate_bench_result {
  int points_per_law = 0, passes = 0, taylor_points = 0;
  std::string method;  ///< how the times were taken
  bool fma_path = false;
  std::vector<surrogate_bench_row> rows;
  std::vector<std::string> skipped_without_surrogate;
};

/// The speed-accuracy table of every method over the point set.
bench_result run_bench(const bench_request& q);
/// The committed surrogates' evaluation times.
surrogate_bench_result run_surrogate_bench(const bench_request& q);

}  // namespace viscor::jobs
