// What a CoR table will cost, before any of it is computed (`viscor table SPEC
// --estimate`, Python's viscor.table(spec, estimate=True)): its rows, the CPU time
// they are expected to take at the measured cost per row (by law, working digits and
// table method: tools/cost_data/row_cost_by_digits.csv, made by
// tools/cost_by_digits.py), and the wall time at the given threads and shards. The
// costs were measured on one machine (docs/performance.md "Cost before work", which
// compares estimates with real runs); another machine scales them by its speed.
#pragma once

#include <viscor/jobs/table_spec.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace viscor::jobs {

/// The rows of one law and what they are expected to cost.
struct law_estimate {
  contact_law law;
  std::int64_t rows = 0;               ///< of this run (its shard)
  double cpu_time_per_row_s = 0;       ///< the model's CPU seconds per row
  double cpu_time_s = 0;               ///< rows x cpu_time_per_row_s
};

/// What a table run (one shard, or the whole table) is expected to cost.
struct table_estimate {
  std::int64_t rows = 0;          ///< rows of this run
  std::int64_t rows_total = 0;    ///< rows of the whole table
  shard part;                     ///< the run's shard (the whole table by default)
  int working_digits = 0;         ///< the precision the rows start at (the spec's, or chosen for certified_digits)
  std::string method;             ///< the spec's table method
  double cpu_time_s = 0;          ///< this run's rows, one after the other
  int threads = 1;
  double wall_time_s = 0;         ///< this run at `threads` threads
  std::vector<law_estimate> laws;  ///< per law, in the spec's order
};

/// The model's CPU seconds of one row of `law` at `digits` working digits, for a
/// certified row (`proven`: certified and proven). A law that is not named costs as the
/// named law nearest to it in (alpha, beta).
double row_cpu_time_s(const contact_law& law, int digits, bool proven);

/// The estimate of make_cor_table(table, run) at run.part and run.threads, computing
/// nothing. Throws parse_error for a sticking-threshold spec.
table_estimate estimate_cor_table(const table_spec& table, const shard& part, int threads);

}  // namespace viscor::jobs
