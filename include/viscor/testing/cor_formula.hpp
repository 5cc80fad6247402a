// GoogleTest assertions for a CoR formula of your own, checked against viscor's
// certified tables (jobs/formula_job.hpp; docs/formulas.md):
//
//   #include <viscor/testing/cor_formula.hpp>
//   TEST(MyFormula, WithinTolerance) {
//     EXPECT_COR_WITHIN(my_e, "kuwabara_kono", 1e-3);  // my_e: double(double gamma, double g)
//     EXPECT_COR_WITHIN_REGION(my_e, "kuwabara_kono", (viscor::formula_region{0, 0.1, 0, 1}), 1e-4);
//   }
//
// A failure names the worst point (gamma, g), the formula's value and the certified
// one, and the failing cells. CMake: link viscor::testing and GTest::gtest (this
// header includes <gtest/gtest.h>; projects without GoogleTest never include it).
#pragma once

#include <viscor/jobs/formula_job.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <string>

namespace viscor::testing {

/// The check of `formula` (e as a function of gamma and g, in double) against the
/// certified tables of the named law, per cell of its committed error map.
inline formula_comparison check_cor_formula(const std::function<double(double, double)>& formula,
                                            const std::string& law, double tolerance,
                                            const formula_region& region = {}) {
  const jobs::formula_reference r = jobs::committed_formula_reference(law_by_name(law));
  return compare_formula(r.points, formula, formula_quantity::e, r.grid, tolerance, region);
}

/// The predicate-format of EXPECT_COR_WITHIN_REGION: passes when every cell of the
/// region passes; the failure message names the worst point and the failing cells.
inline ::testing::AssertionResult cor_formula_within_region(const char* formula_text, const char* law_text,
                                                            const char* region_text, const char* tolerance_text,
                                                            const std::function<double(double, double)>& formula,
                                                            const std::string& law, const formula_region& region,
                                                            double tolerance) {
  const jobs::formula_reference r = jobs::committed_formula_reference(law_by_name(law));
  const formula_comparison c = compare_formula(r.points, formula, formula_quantity::e, r.grid, tolerance, region);
  if (c.pass) return ::testing::AssertionSuccess();
  std::ostringstream m;
  m << formula_text << " is not within " << tolerance_text << " (" << tolerance << ") of the certified e of "
    << law_text << " in " << region_text << ":\n"
    << jobs::formula_comparison_text(c, r);
  return ::testing::AssertionFailure() << m.str();
}

/// The predicate-format of EXPECT_COR_WITHIN (every cell of the law's tables).
inline ::testing::AssertionResult cor_formula_within(const char* formula_text, const char* law_text,
                                                     const char* tolerance_text,
                                                     const std::function<double(double, double)>& formula,
                                                     const std::string& law, double tolerance) {
  return cor_formula_within_region(formula_text, law_text, "every cell", tolerance_text, formula, law, {}, tolerance);
}

}  // namespace viscor::testing

/// Expects |formula(gamma, g) - e| <= tol at every certified point of the law (by cell).
#define EXPECT_COR_WITHIN(formula, law, tol) EXPECT_PRED_FORMAT3(::viscor::testing::cor_formula_within, formula, law, tol)
/// The same, fatal.
#define ASSERT_COR_WITHIN(formula, law, tol) ASSERT_PRED_FORMAT3(::viscor::testing::cor_formula_within, formula, law, tol)
/// Expects it in the cells inside a viscor::formula_region.
#define EXPECT_COR_WITHIN_REGION(formula, law, region, tol) \
  EXPECT_PRED_FORMAT4(::viscor::testing::cor_formula_within_region, formula, law, region, tol)
