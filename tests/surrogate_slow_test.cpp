// Every row of each committed surrogate's certified verification table within the
// stated bound (the default suite takes every 10th row: surrogate_test.cpp).
#include "surrogate_test_utils.hpp"

#include <gtest/gtest.h>

namespace {

class CommittedSurrogateAllPoints : public ::testing::TestWithParam<const char*> {};

TEST_P(CommittedSurrogateAllPoints, MeetsItsBoundOnEveryVerificationPoint) {
  const auto s = viscor::test::load_committed_surrogate(GetParam());
  if (!s) VISCOR_SKIP_OR_FAIL_MISSING("no committed surrogate for " << GetParam());
  const auto refs = viscor::test::load_verification_table(GetParam(), 1);
  ASSERT_GE(refs.size(), 20000u);
  const auto failures = viscor::test::bound_violations(*s, refs);
  EXPECT_TRUE(failures.empty()) << failures.size() << " violations; first: " << failures.front();
}

INSTANTIATE_TEST_SUITE_P(Laws, CommittedSurrogateAllPoints,
                         ::testing::Values("linear", "hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"));

}  // namespace
