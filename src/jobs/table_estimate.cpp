// The cost of a CoR table before it runs (include/viscor/jobs/table_estimate.hpp).
#include <viscor/jobs/table_estimate.hpp>

#include <viscor/core/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace viscor::jobs {

namespace {

// CPU seconds per row, measured by tools/cost_by_digits.py (tools/cost_data/
// row_cost_by_digits.csv; tests/table_estimate_test.cpp checks these equal it): the
// fixed-width types at 15, 18, 30 and 33 digits, MPFR from 40 to 150.
struct measured_cost {
  std::string_view law;
  int digits;
  double certify, proven;
};

// clang-format off
constexpr measured_cost measured[] = {
#include "row_cost_by_digits.inc"
};
// clang-format on

// The digits at which each arithmetic was measured.
int measured_digits_of(scalar_kind kind) {
  switch (kind) {
    case scalar_kind::double_: return 15;
    case scalar_kind::long_double: return 18;
    case scalar_kind::double_double: return 30;
    case scalar_kind::quad: return 33;
    case scalar_kind::mpfr: return 0;
  }
  return 0;
}

double cost_at(std::string_view law, int digits, bool proven) {
  for (const measured_cost& m : measured)
    if (m.law == law && m.digits == digits) return proven ? m.proven : m.certify;
  throw error("table estimate: no measured cost for " + std::string(law) + " at " + std::to_string(digits) +
              " digits");
}

// The named law nearest to `law` in (alpha, beta).
std::string_view nearest_named_law(const contact_law& law) {
  if (!law.name.empty()) return law.name;
  std::string_view best = named_laws[0].name;
  long double best_distance = 1e300L;
  for (const named_law& n : named_laws) {
    const long double d = std::fabs(law.alpha.approximate() - static_cast<long double>(n.alpha_num) / n.alpha_den) +
                          std::fabs(law.beta.approximate() - static_cast<long double>(n.beta_num) / n.beta_den);
    if (d < best_distance) best_distance = d, best = n.name;
  }
  return best;
}

// The rows of [first, first + count) in shard `part`.
std::int64_t rows_in_shard(std::int64_t first, std::int64_t count, const shard& part) {
  const auto below = [&](std::int64_t end) {  // rows < end with row % N == i
    return end <= part.index ? 0 : (end - 1 - part.index) / part.count + 1;
  };
  return below(first + count) - below(first);
}

// A row that calibrates its damping to a target e (a spec in SI with target_e) first
// runs viscor calibrate's root finding, some 30 to 40 uncertified solves, then the
// certified row: measured against the same rows at given gamma0 (docs/performance.md
// "Cost before work"), 1.3-1.6 times the certified row in the fixed-width types and
// 2.6-2.8 times in MPFR, where the certificate's reference run is relatively cheaper.
double calibration_factor(int digits) { return scalar_for_digits(digits) == scalar_kind::mpfr ? 2.7 : 1.5; }

}  // namespace

double row_cpu_time_s(const contact_law& law, int digits, bool proven) {
  const std::string_view name = nearest_named_law(law);
  const scalar_kind kind = scalar_for_digits(digits);
  if (kind != scalar_kind::mpfr) return cost_at(name, measured_digits_of(kind), proven);
  // MPFR: log-log interpolation between the measured precisions, the end segments extended.
  constexpr std::array<int, 5> mpfr_digits{40, 50, 70, 100, 150};
  std::size_t k = 0;
  while (k + 2 < mpfr_digits.size() && digits > mpfr_digits[k + 1]) ++k;
  if (digits == mpfr_digits[k] || digits == mpfr_digits[k + 1]) return cost_at(name, digits, proven);
  const double d0 = mpfr_digits[k], d1 = mpfr_digits[k + 1];
  const double c0 = cost_at(name, mpfr_digits[k], proven), c1 = cost_at(name, mpfr_digits[k + 1], proven);
  const double power = std::log(c1 / c0) / std::log(d1 / d0);
  return c0 * std::pow(static_cast<double>(digits) / d0, power);
}

table_estimate estimate_cor_table(const table_spec& table, const shard& part, int threads) {
  const grid_spec& spec = table.grid;
  if (spec.threshold_digits > 0)
    throw parse_error(spec.source + ": field threshold_digits: the estimate is for CoR tables (viscor table), not "
                      "sticking thresholds");
  // Rows per law: the grid's g x gamma, or the product of the physical axes (a row in SI
  // costs what a certified row at its scaled gamma and g does).
  std::int64_t per_law = 0;
  if (table.physical) {
    per_law = physical_rows_per_law(*table.physical, expand(*table.physical));
  } else {
    const expanded_axes axes = expand(spec);
    if (axes.gamma.empty()) throw parse_error(spec.source + ": field gamma: the table needs gamma values");
    if (axes.g.empty()) throw parse_error(spec.source + ": field g: the table needs g values");
    per_law = static_cast<std::int64_t>(axes.g.size() * axes.gamma.size());
  }
  refuse_too_many_rows(spec, {static_cast<std::int64_t>(spec.laws.size()), per_law});
  if (threads < 1 || threads > 4096)
    throw invalid_parameter(VISCOR_FIELD("threads") " must be from 1 to 4096, got " + std::to_string(threads));
  table_estimate out;
  out.part = part;
  out.working_digits = spec.digits;
  out.method = table.proven ? std::string("proven") : to_string(spec.method);
  out.threads = threads;
  for (std::size_t i = 0; i < spec.laws.size(); ++i) {
    law_estimate l;
    l.law = spec.laws[i];
    l.rows = rows_in_shard(static_cast<std::int64_t>(i) * per_law, per_law, part);
    // Closed forms (method exact) cost about what the linear law's certificate, itself a closed form, does.
    l.cpu_time_per_row_s = spec.method == row_method::exact
                               ? row_cpu_time_s(law_by_name("linear"), spec.digits, false)
                               : row_cpu_time_s(l.law, spec.digits, table.proven);
    if (table.physical && !table.physical->target_e.empty()) l.cpu_time_per_row_s *= calibration_factor(spec.digits);
    l.cpu_time_s = static_cast<double>(l.rows) * l.cpu_time_per_row_s;
    out.rows += l.rows;
    out.rows_total += per_law;
    out.cpu_time_s += l.cpu_time_s;
    out.laws.push_back(std::move(l));
  }
  // Rows are handed out one at a time: the threads finish together but for the last rows.
  const std::int64_t busy = std::min<std::int64_t>(threads, std::max<std::int64_t>(out.rows, 1));
  out.wall_time_s = out.cpu_time_s / static_cast<double>(busy);
  return out;
}

}  // namespace viscor::jobs
