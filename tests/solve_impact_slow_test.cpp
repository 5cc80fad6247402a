// Heavy checks of solve_impact (label "slow"): 1000 digits against an exact
// solution, the full precision-escalation grid, and wide sweeps of
// laws and loads at 50 and 100 digits.
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <gtest/gtest.h>

#include "test_utils.hpp"

#include <string>
#include <vector>

namespace viscor {
namespace {

using test::absolute_close;
using test::relative_close;

// One run at 1000 digits: Hunt-Crossley form (alpha = 3/2, beta = 5/2), g = 0.
TEST(SolveImpactSlow, ThousandDigitsAgainstExactHuntCrossley) {
  scoped_precision digits(1000);
  const contact_law law = law_by_name("hunt_crossley");
  const mpfr_real gamma("0.1"), g(0);
  const impact_result<mpfr_real> r = solve_impact<mpfr_real>(law, gamma, g);
  const auto exact = exact_cor<mpfr_real>(law, gamma, g);
  ASSERT_TRUE(exact.has_value());
  const mpfr_real tol("1e-997");
  EXPECT_EQ(r.outcome, impact_outcome::rebound);
  EXPECT_PRED_FORMAT3(absolute_close<mpfr_real>, r.e, exact->e, tol);
  EXPECT_PRED_FORMAT3(relative_close<mpfr_real>, r.one_minus_e, exact->one_minus_e, tol);
  using std::abs;
  EXPECT_LE(abs(r.e - exact->e), r.error_estimate + epsilon<mpfr_real>());
}

// At 100 digits the result agrees with 50 digits to >= 47 digits for all
// named laws at g in {0, 0.05, 1, 10}, gamma in {1e-4, 1e-2, 0.1}.
TEST(SolveImpactSlow, PrecisionEscalationGrid) {
  for (const auto& named : named_laws)
    for (const char* g : {"0", "0.05", "1", "10"})
      for (const char* gamma : {"1e-4", "1e-2", "0.1"}) {
        SCOPED_TRACE(std::string(named.name) + ", gamma = " + gamma + ", g = " + g);
        const contact_law law = law_by_name(named.name);
        const auto lo = solve_impact<mpfr_50>(law, mpfr_50(gamma), mpfr_50(g));
        const auto hi = solve_impact<mpfr_100>(law, mpfr_100(gamma), mpfr_100(g));
        ASSERT_EQ(lo.outcome, hi.outcome);
        if (lo.outcome == impact_outcome::stick) {
          EXPECT_EQ(lo.e, 0);
          EXPECT_GE(test::agreeing_digits(test::convert<mpfr_100>(lo.contact_time.value()), hi.contact_time.value()), 40.0);
          continue;
        }
        EXPECT_GE(test::agreeing_digits(test::convert<mpfr_100>(lo.e), hi.e), 47.0);
        EXPECT_GE(test::agreeing_digits(test::convert<mpfr_100>(lo.one_minus_e), hi.one_minus_e), 47.0);
        // the 50-digit error estimate covers the 50-digit error
        using std::abs;
        EXPECT_LE(abs(test::convert<mpfr_100>(lo.e) - hi.e), test::convert<mpfr_100>(lo.error_estimate));
      }
}

// Wide sweep at 50 digits, checked against 100 digits: every case either agrees
// to the claimed accuracy or raises a typed error.
TEST(SolveImpactSlow, WideSweepAgreesAcrossPrecisions) {
  const std::vector<contact_law> laws{
      law_by_name("linear"), law_by_name("hertz_linear_damping"), law_by_name("tsuji"),
      law_by_name("kuwabara_kono"), law_by_name("hunt_crossley"),
      make_law(exponent::rational(1, 1), exponent::rational(3, 1)),
      make_law(exponent::rational(3, 1), exponent::rational(1, 1)),
      make_law(exponent::rational(5, 2), exponent::rational(5, 2)),
      make_law(exponent::parse("1.3", "alpha"), exponent::parse("1.7", "beta")),
      make_law(exponent::parse("1.2345678901234", "alpha"), exponent::parse("1.0987654321098", "beta"))};
  for (const auto& law : laws)
    for (const char* gamma : {"1e-30", "1e-3", "0.5", "10"})
      for (const char* g : {"-0.9", "0", "1e-12", "0.5", "1e6"}) {
        SCOPED_TRACE(law.describe() + ", gamma = " + gamma + ", g = " + g);
        impact_result<mpfr_50> lo;
        impact_result<mpfr_100> hi;
        try {
          lo = solve_impact<mpfr_50>(law, mpfr_50(gamma), mpfr_50(g));
          hi = solve_impact<mpfr_100>(law, mpfr_100(gamma), mpfr_100(g));
        } catch (const error& e) {
          ADD_FAILURE() << "typed error (allowed, but unexpected at 50 digits): " << e.what();
          continue;
        }
        ASSERT_EQ(lo.outcome, hi.outcome);
        using std::abs;
        const mpfr_100 diff = abs(test::convert<mpfr_100>(lo.e) - hi.e);
        EXPECT_LE(diff, test::convert<mpfr_100>(lo.error_estimate) + mpfr_100("1e-49"));
        if (lo.outcome == impact_outcome::rebound && lo.one_minus_e > 0)
          EXPECT_GE(test::agreeing_digits(test::convert<mpfr_100>(lo.one_minus_e), hi.one_minus_e), 40.0);
      }
}

// Against every exact solution at 100 digits, with g = 1e3 on the linear law.
TEST(SolveImpactSlow, LinearLawLargeLoadAt100Digits) {
  scoped_precision guard(130);
  const contact_law law = law_by_name("linear");
  for (const char* gamma : {"1e-30", "1e-3", "0.5"}) {
    SCOPED_TRACE(gamma);
    const auto r = solve_impact<mpfr_100>(law, mpfr_100(gamma), mpfr_100(1000));
    const auto exact = exact_cor<mpfr_real>(law, mpfr_real(gamma), mpfr_real(1000));
    EXPECT_PRED_FORMAT3(absolute_close<mpfr_100>, r.e, test::convert<mpfr_100>(exact->e), mpfr_100("1e-97"));
    EXPECT_PRED_FORMAT3(relative_close<mpfr_100>, r.one_minus_e, test::convert<mpfr_100>(exact->one_minus_e),
                        mpfr_100("1e-97"));
  }
}

}  // namespace
}  // namespace viscor
