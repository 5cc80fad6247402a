// Proven enclosures of the linear law, checked against
// the closed-form solution (include/viscor/exact/exact_linear.hpp, an independent
// formula evaluated in MPFR at twice the digits plus 20), never against the proof
// itself:
// - every enclosure of e, 1 - e and T_f contains the exact value and outcomes
//   agree, over 200 fixed-seed points (enclose_test_points.hpp) at 30, 50 and 100
//   digits;
// - enclosures are tight (relative width of e <= 1e-40 at 50 digits where
//   e >= 1e-10);
// - the proof can fail: with the remainder under-estimated (test seam), some exact
//   values fall outside their enclosures, so the containment check has teeth
//   (tests/enclose_proof_mutation_test.cpp, the program built with the seam).
#include <viscor/enclose/proven_linear.hpp>

#include <gtest/gtest.h>

#include "enclose_test_points.hpp"

namespace {

using namespace viscor;
using namespace viscor::proofs;

TEST(Enclose, ContainsTheClosedFormAt30And50And100Digits) {
  for (int digits : {30, 50, 100}) {
    const auto summary = check_against_closed_form(sample_points(200, 17), digits);
    EXPECT_EQ(summary.outside, 0) << digits << " digits: " << summary.first_problem;
    EXPECT_EQ(summary.outcome_mismatch, 0) << digits << " digits: " << summary.first_problem;
    EXPECT_EQ(summary.undecided, 0) << digits << " digits: " << summary.first_problem;
    EXPECT_GE(summary.rebounds, 100) << digits;
    EXPECT_GE(summary.sticks, 50) << digits;
    // Tight: where e >= 1e-10, the relative width of e is <= 10^-(digits - 10)
    // (1e-40 at 50 digits).
    EXPECT_GE(summary.tight_candidates, 100) << digits;
    EXPECT_EQ(summary.tight, summary.tight_candidates)
        << digits << " digits: least relative digits of e " << summary.least_digits;
  }
}

TEST(Enclose, RefusesBadInput) {
  EXPECT_THROW(prove_linear_impact("-0.1", "0", 30), invalid_parameter);
  EXPECT_THROW(prove_linear_impact("nan", "0", 30), invalid_parameter);
  EXPECT_THROW(prove_linear_impact("0.1", "", 30), invalid_parameter);
  EXPECT_THROW(prove_linear_impact("0.1", "0", 2), invalid_parameter);
}

}  // namespace
