// An outside formula of e(gamma, g) checked against certified reference values,
// cell by cell of an error-map grid: the regression test of a formula developer.
//
// The reference points are rows of certified tables (error_map_builder.hpp's
// reference_point); the formula's values at those points are given by the caller
// (a callable, or values computed elsewhere, in the points' order). A cell is
// judged by the same samples an error map would use (mappable_cells: four corners
// and min_samples), so a built-in approximation passed as an outside formula gives
// exactly the worst errors behind the committed error map's bounds.
//
// Per cell: the largest and median absolute error of e, the largest and median
// relative error of 1 - e (where the truth rebounds), the worst point, outcome
// mismatches (the formula rebounds where the truth sticks, or the reverse: e > 0
// against e = 0), non-finite values, and pass or fail against a tolerance on |de|.
// Cells the sticking threshold crosses are reported but not judged on |de| there
// (e ~ sqrt(distance to the threshold): no formula is smooth across it), only on
// the outcomes of their samples.
#pragma once

#include <viscor/scenes/error_map.hpp>
#include <viscor/scenes/error_map_builder.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace viscor {

/// What the caller's values are: e itself, or 1 - e (more digits near e = 1).
enum class formula_quantity { e, one_minus_e };

/// The part of the (gamma, g) plane a check covers: cells wholly inside it. An
/// unbounded side is infinite; a bound a caller gives is finite (formula_region_of).
struct formula_region {
  double gamma_min = 0, gamma_max = std::numeric_limits<double>::infinity();
  double g_min = -std::numeric_limits<double>::infinity(), g_max = std::numeric_limits<double>::infinity();

  /// Whether the cell [gamma_lo, gamma_hi] x [g_lo, g_hi] lies inside.
  bool contains(double gamma_lo, double gamma_hi, double g_lo, double g_hi) const {
    return gamma_min <= gamma_lo && gamma_hi <= gamma_max && g_min <= g_lo && g_hi <= g_max;
  }
  /// Whether the point (gamma, g) lies inside.
  bool contains(double gamma, double g) const { return contains(gamma, gamma, g, g); }

  /// Refuses a NaN bound and an empty or inverted region (min >= max), naming the bounds:
  /// a check over such a region could judge nothing.
  void validate() const {
    const auto check = [](double lo, double hi, const char* lo_name, const char* hi_name) {
      if (std::isnan(lo) || std::isnan(hi))
        throw invalid_parameter(std::string("formula check: the region bound ") + (std::isnan(lo) ? lo_name : hi_name) +
                                " is not a number");
      if (!(lo < hi))
        throw invalid_parameter(std::string("formula check: the region is empty: ") + lo_name + " = " +
                                detail::shortest(lo) + " is not below " + hi_name + " = " + detail::shortest(hi));
    };
    check(gamma_min, gamma_max, "gamma_min", "gamma_max");
    check(g_min, g_max, "g_min", "g_max");
  }
};

/// Refuses a tolerance on |de| outside [0, 1) (e lies in [0, 1]: a tolerance of 1
/// passes every formula), naming it.
inline void validate_formula_tolerance(double tolerance) {
  if (!(tolerance >= 0 && tolerance < 1))
    throw invalid_parameter("formula check: the tolerance must be in [0, 1), got " + detail::shortest(tolerance));
}

/// The worst point of a cell (or of the whole check) for |de|.
struct formula_worst_point {
  std::size_t index = 0;      ///< into the reference points
  double value = 0;           ///< the formula's e there
  double truth = 0;           ///< the certified e there
  double abs_error = -1;      ///< |value - truth|; < 0 when there is no point
};

/// The statistics of one cell.
struct formula_cell {
  std::string gamma_lo, gamma_hi, g_lo, g_hi;  ///< the cell's edges, as the grid gives them
  cell_outcome outcome = cell_outcome::rebound;  ///< of the certified samples
  std::size_t samples = 0;
  double max_abs_e = 0, median_abs_e = 0;      ///< |e_formula - e|
  double max_rel_one_minus_e = 0, median_rel_one_minus_e = 0;  ///< |d(1 - e)| / (1 - e), rebound samples
  formula_worst_point worst;                    ///< the sample of max_abs_e
  std::size_t rebound_where_truth_sticks = 0;   ///< formula e > 0 at a certified stick
  std::size_t stick_where_truth_rebounds = 0;   ///< formula e <= 0 at a certified rebound
  std::size_t non_finite = 0;                   ///< NaN or infinite formula values
  bool pass = true;  ///< max_abs_e <= tolerance (not judged in mixed cells), no mismatch, all finite
};

/// The check of one formula: per cell, and over all cells. A check that judged no
/// cell does not pass: a verdict over nothing is no verdict.
struct formula_comparison {
  double tolerance = 0;            ///< on |de|
  std::vector<formula_cell> cells; ///< the judged cells (corners and min_samples given)
  formula_cell overall;            ///< every judged sample together (edges empty)
  bool pass = false;               ///< at least one cell judged, and every judged cell passes
  std::size_t failed_cells = 0;
  std::size_t cells_in_region = 0;     ///< cells of the grid wholly inside the region, judged or not
  std::size_t points_not_judged = 0;   ///< points inside the region that are samples of no judged cell
  double max_abs_e_not_judged = 0;     ///< their largest |de| (NaN when one is not finite)

  /// Whether any cell was judged.
  bool judged_any() const { return !cells.empty(); }
};

namespace detail {

inline double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  const std::size_t n = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n), v.end());
  if (v.size() % 2) return v[n];
  const double upper = v[n];
  return (*std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n)) + upper) / 2;
}

// Accumulates the samples of one cell (or of all cells) into `c`.
struct formula_accumulator {
  std::vector<double> abs_e, rel;
  formula_cell c;

  void add(const reference_sample& p, const reference_point& ref, double formula_e, double formula_one_minus_e,
           bool judge_abs) {
    ++c.samples;
    if (!std::isfinite(formula_e) || !std::isfinite(formula_one_minus_e)) {
      ++c.non_finite;
      return;
    }
    if (p.outcome == impact_outcome::stick && formula_e > 0) ++c.rebound_where_truth_sticks;
    if (p.outcome == impact_outcome::rebound && formula_e <= 0) ++c.stick_where_truth_rebounds;
    if (!judge_abs) return;
    const double err = std::abs(formula_e - p.e);
    abs_e.push_back(err);
    if (err > c.worst.abs_error) c.worst = {p.index, formula_e, p.e, err};
    if (p.outcome == impact_outcome::rebound) {
      const double truth = ref.one_minus_e.empty() ? 1 - p.e : std::strtod(ref.one_minus_e.c_str(), nullptr);
      if (truth > 0) rel.push_back(std::abs(formula_one_minus_e - truth) / truth);
    }
  }

  formula_cell finish(double tolerance) {
    if (!abs_e.empty()) c.max_abs_e = *std::max_element(abs_e.begin(), abs_e.end());
    c.median_abs_e = median_of(abs_e);
    if (!rel.empty()) c.max_rel_one_minus_e = *std::max_element(rel.begin(), rel.end());
    c.median_rel_one_minus_e = median_of(rel);
    c.pass = c.max_abs_e <= tolerance && c.rebound_where_truth_sticks == 0 && c.stick_where_truth_rebounds == 0 &&
             c.non_finite == 0;
    return c;
  }
};

}  // namespace detail

/// Compares `values` (the formula's e, or 1 - e, at each of `points`, in order)
/// with the certified values, per cell of the grid `spec` (its edges and
/// min_samples) inside `region`, against `tolerance` on |de|.
inline formula_comparison compare_formula_values(const std::vector<reference_point>& points,
                                                 const std::vector<double>& values, formula_quantity quantity,
                                                 const error_map_spec& spec, double tolerance,
                                                 const formula_region& region = {}) {
  if (values.size() != points.size())
    throw invalid_parameter("formula check: " + std::to_string(values.size()) + " values for " +
                            std::to_string(points.size()) + " reference points");
  validate_formula_tolerance(tolerance);
  region.validate();
  const std::vector<double> gx = detail::parse_edges(spec.gamma_edges, "gamma_edges");
  const std::vector<double> gy = detail::parse_edges(spec.g_edges, "g_edges");
  const std::vector<reference_sample> s = reference_samples(points);
  const auto e_of = [&](std::size_t k) { return quantity == formula_quantity::e ? values[k] : 1 - values[k]; };
  const auto one_minus_e_of = [&](std::size_t k) { return quantity == formula_quantity::e ? 1 - values[k] : values[k]; };

  formula_comparison out;
  out.tolerance = tolerance;
  for (std::size_t i = 0; i + 1 < gx.size(); ++i)
    for (std::size_t j = 0; j + 1 < gy.size(); ++j) out.cells_in_region += region.contains(gx[i], gx[i + 1], gy[j], gy[j + 1]);
  std::vector<bool> judged(points.size(), false);
  detail::formula_accumulator all;
  for (const mappable_cell& m : mappable_cells(s, gx, gy, spec.min_samples)) {
    if (!region.contains(gx[m.i], gx[m.i + 1], gy[m.j], gy[m.j + 1])) continue;
    for (const reference_sample* p : m.samples) judged[p->index] = true;
    detail::formula_accumulator cell;
    cell.c.gamma_lo = spec.gamma_edges[m.i], cell.c.gamma_hi = spec.gamma_edges[m.i + 1];
    cell.c.g_lo = spec.g_edges[m.j], cell.c.g_hi = spec.g_edges[m.j + 1];
    cell.c.outcome = m.outcome;
    const bool judge_abs = m.outcome != cell_outcome::mixed;
    for (const reference_sample* p : m.samples) {
      cell.add(*p, points[p->index], e_of(p->index), one_minus_e_of(p->index), judge_abs);
      all.add(*p, points[p->index], e_of(p->index), one_minus_e_of(p->index), judge_abs);
    }
    out.cells.push_back(cell.finish(tolerance));
    if (!out.cells.back().pass) ++out.failed_cells;
  }
  out.overall = all.finish(tolerance);
  for (const reference_sample& p : s) {
    if (judged[p.index] || !region.contains(p.gamma, p.g)) continue;
    ++out.points_not_judged;
    const double err = std::abs(e_of(p.index) - p.e);
    out.max_abs_e_not_judged = std::isnan(err) || std::isnan(out.max_abs_e_not_judged)
                                   ? std::numeric_limits<double>::quiet_NaN()
                                   : std::max(out.max_abs_e_not_judged, err);
  }
  out.pass = out.judged_any() && out.failed_cells == 0;
  return out;
}

/// The same for a formula given as a callable e(gamma, g) in double (or 1 - e with
/// `quantity`), evaluated at every reference point.
inline formula_comparison compare_formula(const std::vector<reference_point>& points,
                                          const std::function<double(double, double)>& formula,
                                          formula_quantity quantity, const error_map_spec& spec, double tolerance,
                                          const formula_region& region = {}) {
  std::vector<double> values;
  values.reserve(points.size());
  for (const reference_sample& p : reference_samples(points)) values.push_back(formula(p.gamma, p.g));
  return compare_formula_values(points, values, quantity, spec, tolerance, region);
}

}  // namespace viscor
