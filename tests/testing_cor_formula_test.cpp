// Checks of an outside CoR formula (scenes/formula_check.hpp, jobs/formula_job.hpp)
// and the GoogleTest assertions built on them (viscor/testing/cor_formula.hpp).
// Truth: statistics worked out by hand on a small grid; the committed error map of
// Kuwabara-Kono (built by `viscor errormap` from the certified tables, its provenance
// in its header) for the report's Prop. 2 written as an outside formula.
#include <viscor/testing/cor_formula.hpp>

#include <viscor/approx/approximations.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

namespace {

using viscor::formula_quantity;
using viscor::formula_region;
using viscor::reference_point;

// Five points of the cell [0, 1] x [0, 1]: its corners and its centre.
std::vector<reference_point> small_grid() {
  return {{"0", "0", "0.5", viscor::impact_outcome::rebound, "0.5"},
          {"1", "0", "0.4", viscor::impact_outcome::rebound, "0.6"},
          {"0", "1", "0.3", viscor::impact_outcome::rebound, "0.7"},
          {"1", "1", "0.2", viscor::impact_outcome::rebound, "0.8"},
          {"0.5", "0.5", "0.35", viscor::impact_outcome::rebound, "0.65"}};
}

viscor::error_map_spec unit_cell() {
  viscor::error_map_spec spec;
  spec.gamma_edges = {"0", "1"};
  spec.g_edges = {"0", "1"};
  spec.min_samples = 4;
  return spec;
}

TEST(FormulaCheck, StatisticsOfOneCellWorkedOutByHand) {
  // errors 0.01, -0.02, 0, 0.03, 0.005: max 0.03 (the fourth point), median 0.01;
  // relative on 1 - e: 0.02, 0.0333.., 0, 0.0375, 0.00769..: max 0.0375, median 0.02.
  const std::vector<double> values{0.51, 0.38, 0.3, 0.23, 0.355};
  const viscor::formula_comparison c =
      viscor::compare_formula_values(small_grid(), values, formula_quantity::e, unit_cell(), 0.025);
  ASSERT_EQ(c.cells.size(), 1u);
  const viscor::formula_cell& cell = c.cells[0];
  EXPECT_EQ(cell.samples, 5u);
  EXPECT_NEAR(cell.max_abs_e, 0.03, 1e-15);
  EXPECT_NEAR(cell.median_abs_e, 0.01, 1e-15);
  EXPECT_NEAR(cell.max_rel_one_minus_e, 0.0375, 1e-15);
  EXPECT_NEAR(cell.median_rel_one_minus_e, 0.02, 1e-15);
  EXPECT_EQ(cell.worst.index, 3u);
  EXPECT_FALSE(cell.pass);
  EXPECT_FALSE(c.pass);
  EXPECT_EQ(c.failed_cells, 1u);
  EXPECT_TRUE(viscor::compare_formula_values(small_grid(), values, formula_quantity::e, unit_cell(), 0.03).pass);
  // The same values given as 1 - e.
  std::vector<double> one_minus(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) one_minus[k] = 1 - values[k];
  EXPECT_NEAR(viscor::compare_formula_values(small_grid(), one_minus, formula_quantity::one_minus_e, unit_cell(), 0.5)
                  .cells[0]
                  .max_abs_e,
              0.03, 1e-15);
  // A region that leaves the cell out checks nothing, and a check of nothing does not pass.
  const viscor::formula_comparison none =
      viscor::compare_formula_values(small_grid(), values, formula_quantity::e, unit_cell(), 0.5, formula_region{2, 3, 0, 1});
  EXPECT_TRUE(none.cells.empty());
  EXPECT_EQ(none.cells_in_region, 0u);
  EXPECT_FALSE(none.judged_any());
  EXPECT_FALSE(none.pass);
}

// Coverage: the cells of the region judged, and the points of the region in no judged cell.
TEST(FormulaCheck, ACheckThatJudgedNothingFailsAndSaysWhatItCovered) {
  // Two cells [0, 1] and [1, 2] in gamma; the second has one corner only, so it is not judged.
  std::vector<reference_point> points = small_grid();
  points.push_back({"2", "0", "0.1", viscor::impact_outcome::rebound, "0.9"});
  viscor::error_map_spec spec = unit_cell();
  spec.gamma_edges = {"0", "1", "2"};
  const std::vector<double> values{0.5, 0.4, 0.3, 0.2, 0.35, 0.3};  // the last point is off by 0.2
  const viscor::formula_comparison c = viscor::compare_formula_values(points, values, formula_quantity::e, spec, 0.01);
  EXPECT_EQ(c.cells.size(), 1u);
  EXPECT_EQ(c.cells_in_region, 2u);
  EXPECT_EQ(c.points_not_judged, 1u);
  EXPECT_NEAR(c.max_abs_e_not_judged, 0.2, 1e-15);
  EXPECT_TRUE(c.pass);  // the judged cell is exact
  EXPECT_EQ(viscor::jobs::formula_coverage_text(c),
            "1 of 2 cells in the region judged; 1 points in no judged cell (largest |de| 2.00e-01)");
  // Only the corners of the first cell but too few samples: nothing judged, no verdict.
  spec.min_samples = 6;
  const viscor::formula_comparison none = viscor::compare_formula_values(points, values, formula_quantity::e, spec, 0.01);
  EXPECT_FALSE(none.judged_any());
  EXPECT_FALSE(none.pass);
  EXPECT_EQ(none.points_not_judged, 6u);
  // No values at all (a values file with a header only): nothing judged.
  const viscor::formula_comparison empty =
      viscor::compare_formula_values({}, {}, formula_quantity::e, unit_cell(), 0.01);
  EXPECT_FALSE(empty.pass);
  EXPECT_EQ(empty.cells_in_region, 1u);
}

TEST(FormulaCheck, RegionBoundsAndTolerancesAreRefusedNamingTheValue) {
  using viscor::jobs::formula_region_of;
  using viscor::jobs::formula_tolerance_of;
  const auto message_of = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const viscor::invalid_parameter& e) {
      return e.what();
    }
    return "(no error)";
  };
  for (const char* bad : {"nan", "inf", "-inf", "0x10", "1e-400", "abc", ""}) {
    if (*bad == 0) continue;  // "" is an unbounded side
    EXPECT_THAT(message_of([&] { formula_region_of("", bad, "", ""); }), ::testing::HasSubstr("gamma_max"));
    EXPECT_THAT(message_of([&] { formula_region_of("", "", bad, ""); }), ::testing::HasSubstr("g_min"));
    EXPECT_THAT(message_of([&] { formula_tolerance_of(bad); }), ::testing::HasSubstr("tolerance"));
  }
  EXPECT_THAT(message_of([&] { formula_region_of("0.1", "0.01", "", ""); }),
              ::testing::HasSubstr("the region is empty: gamma_min = 0.1 is not below gamma_max = 0.01"));
  EXPECT_THAT(message_of([&] { formula_region_of("", "", "1", "1"); }),
              ::testing::HasSubstr("g_min = 1 is not below g_max = 1"));
  EXPECT_THAT(message_of([&] { formula_tolerance_of("1"); }), ::testing::HasSubstr("in [0, 1), got 1"));
  EXPECT_THAT(message_of([&] { formula_tolerance_of("-1e-3"); }), ::testing::HasSubstr("got -0.001"));
  EXPECT_EQ(formula_tolerance_of("0"), 0.0);
  const formula_region r = formula_region_of("", "1e-3", "0", "");
  EXPECT_EQ(r.gamma_min, 0.0);
  EXPECT_EQ(r.gamma_max, 1e-3);
  EXPECT_EQ(r.g_min, 0.0);
  EXPECT_TRUE(std::isinf(r.g_max));
  // compare_formula_values itself refuses them too (the C++ entry of EXPECT_COR_WITHIN).
  const std::vector<double> values{0.5, 0.4, 0.3, 0.2, 0.35};
  EXPECT_THROW(viscor::compare_formula_values(small_grid(), values, formula_quantity::e, unit_cell(), 1),
               viscor::invalid_parameter);
  EXPECT_THROW(viscor::compare_formula_values(small_grid(), values, formula_quantity::e, unit_cell(), 0.1,
                                              formula_region{0, 1, std::nan(""), 1}),
               viscor::invalid_parameter);
}

TEST(FormulaCheck, OutcomeMismatchesAndNonFiniteValuesFail) {
  std::vector<reference_point> points = small_grid();
  points[3].e = "0", points[3].one_minus_e = "1", points[3].outcome = viscor::impact_outcome::stick;
  const std::vector<double> rebounds_everywhere{0.5, 0.4, 0.3, 0.01, 0.35};
  const auto c = viscor::compare_formula_values(points, rebounds_everywhere, formula_quantity::e, unit_cell(), 0.5);
  EXPECT_EQ(c.cells[0].outcome, viscor::cell_outcome::mixed);
  EXPECT_EQ(c.cells[0].rebound_where_truth_sticks, 1u);
  EXPECT_FALSE(c.pass);
  const std::vector<double> sticks_at_a_rebound{0.5, 0.4, 0.3, 0.2, 0};
  EXPECT_EQ(viscor::compare_formula_values(small_grid(), sticks_at_a_rebound, formula_quantity::e, unit_cell(), 0.5)
                .cells[0]
                .stick_where_truth_rebounds,
            1u);
  const std::vector<double> nan_somewhere{0.5, 0.4, std::nan(""), 0.2, 0.35};
  const auto n = viscor::compare_formula_values(small_grid(), nan_somewhere, formula_quantity::e, unit_cell(), 0.5);
  EXPECT_EQ(n.cells[0].non_finite, 1u);
  EXPECT_FALSE(n.pass);
  EXPECT_THROW(viscor::compare_formula_values(small_grid(), {0.5}, formula_quantity::e, unit_cell(), 0.5),
               viscor::invalid_parameter);
}

// The report's Prop. 2 with numeric coefficients, written as an outside formula as
// the error map evaluates it (clamped to [0, 1]).
double prop2_numeric(double gamma, double g) {
  static const viscor::cor_approximations<double> approx(viscor::law_by_name("kuwabara_kono"));
  return std::clamp(approx.prop2(gamma, g, viscor::coefficient_source::numeric).e, 0.0, 1.0);
}

// A bound as the map file prints it: three digits, rounded up (error_map_text).
double printed_bound(double b) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", b);
  if (std::strtod(text, nullptr) < b) std::snprintf(text, sizeof text, "%.2e", std::nextafter(b * (1 + 1e-2), 1e308));
  return std::strtod(text, nullptr);
}

TEST(FormulaCheck, ABuiltInFormulaGivesTheCommittedErrorMap) {
  // The committed map holds, per cell, 4 x the worst sampled |de| + 1e-14, printed
  // rounded up to three digits: the outside formula's worst error must give it.
  const std::string dir = viscor::jobs::data_directory();
  const viscor::error_map map = viscor::read_error_map(dir + "/error_maps/kuwabara_kono.csv");
  std::map<std::tuple<std::string, std::string, std::string, std::string>, const viscor::error_map_cell*> by_edges;
  for (const auto& cell : map.cells()) by_edges[{cell.gamma_lo, cell.gamma_hi, cell.g_lo, cell.g_hi}] = &cell;
  const viscor::formula_comparison c = viscor::testing::check_cor_formula(prop2_numeric, "kuwabara_kono", 0.5);
  ASSERT_EQ(c.cells.size(), map.cells().size());
  std::size_t compared = 0;
  for (const auto& cell : c.cells) {
    const auto it = by_edges.find({cell.gamma_lo, cell.gamma_hi, cell.g_lo, cell.g_hi});
    ASSERT_NE(it, by_edges.end()) << cell.gamma_lo << " " << cell.g_lo;
    const viscor::error_map_cell& m = *it->second;
    EXPECT_EQ(static_cast<int>(cell.samples), m.samples);
    EXPECT_EQ(cell.outcome, m.outcome);
    const auto& printed = m.bound[static_cast<std::size_t>(viscor::approximation::prop2_numeric)];
    if (!printed) continue;
    EXPECT_EQ(printed_bound(map.safety_factor * cell.max_abs_e + map.floor), *printed)
        << cell.gamma_lo << ".." << cell.gamma_hi << ", " << cell.g_lo << ".." << cell.g_hi;
    ++compared;
  }
  EXPECT_GT(compared, 50u);
}

// Prop. 2 made wrong by 1e-3 in one cell of the small-gamma region.
double wrong_in_one_cell(double gamma, double g) {
  const bool inside = 1e-4 <= gamma && gamma <= 2e-4 && 0.01 <= g && g <= 0.1;
  return prop2_numeric(gamma, g) + (inside ? 1e-3 : 0);
}

const formula_region small_gamma{0, 1e-3, 0, 10};

TEST(CorFormulaAssertions, PassWithinToleranceAndFailNamingTheWorstPoint) {
  EXPECT_COR_WITHIN_REGION(prop2_numeric, "kuwabara_kono", small_gamma, 1e-5);  // its worst there: 2.8e-6
  const ::testing::AssertionResult bad = viscor::testing::cor_formula_within_region(
      "wrong_in_one_cell", "kuwabara_kono", "small_gamma", "1e-5", wrong_in_one_cell, "kuwabara_kono", small_gamma,
      1e-5);
  ASSERT_FALSE(bad);
  EXPECT_THAT(bad.message(), ::testing::HasSubstr("wrong_in_one_cell is not within 1e-5"));
  EXPECT_THAT(bad.message(), ::testing::HasSubstr("worst      gamma = "));
  EXPECT_THAT(bad.message(), ::testing::HasSubstr("fails      gamma 1e-4..2e-4, g 0.01..0.1: max |de| "));
  EXPECT_NONFATAL_FAILURE(EXPECT_COR_WITHIN_REGION(wrong_in_one_cell, "kuwabara_kono", small_gamma, 1e-5),
                          "fails      gamma 1e-4..2e-4");
}

// The GoogleTest example of docs/formulas.md, as printed there: it must pass.
double exp_formula_of_the_docs(double gamma, double) { return std::exp(-1.72 * gamma); }

TEST(CorFormulaAssertions, TheExampleOfTheDocsPassesAsPrinted) {
  const auto mine = exp_formula_of_the_docs;
  EXPECT_COR_WITHIN_REGION(mine, "kuwabara_kono", (viscor::formula_region{0, 0.01, 0, 0.01}), 1e-3);
  EXPECT_COR_WITHIN_REGION(mine, "kuwabara_kono", (viscor::formula_region{0, 0.1, 0, 1e-3}), 2e-3);
  // ... and fails where the page says it does: up to g = 1, and over every cell.
  EXPECT_FALSE(viscor::testing::check_cor_formula(mine, "kuwabara_kono", 1e-3, formula_region{0, 0.01, 0, 1}).pass);
  EXPECT_FALSE(viscor::testing::check_cor_formula(mine, "kuwabara_kono", 0.5).pass);
}

}  // namespace
