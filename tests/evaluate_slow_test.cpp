// Acceptance: evaluate never violates its bound over 500 random scene
// points (fixed seed) with tolerances from 1e-2 to 1e-40, compared with certified
// values (certify at 25+ digits beyond the tolerance; a reduced sample of 20 points
// runs in the default suite, evaluate_test.cpp).
#include "evaluate_test_utils.hpp"

#include <iostream>

namespace viscor {
namespace {

TEST(evaluate_slow, never_violates_its_bound_on_500_points_to_1e_40) {
  const auto maps = test::test_maps(2);
  test::check_counts counts;
  int failures = 0;
  for (const test::scene_point& p : test::random_points(20240607, 500, 2, 40)) {
    const ::testing::AssertionResult ok = test::check_point(p, maps.at(p.law.name).get(), test::certified_reference, counts);
    EXPECT_TRUE(ok);
    if (!ok) ++failures;
  }
  EXPECT_EQ(counts.checked, 500);
  std::cout << "checked " << counts.checked << " points, " << failures << " violations; references: "
            << test::references_used().certified << " certified, " << test::references_used().adaptive
            << " adaptive at 2x digits\n  methods:";
  for (const auto& [method, n] : counts.by_method) std::cout << " " << method << " " << n;
  std::cout << "\n";
  EXPECT_GE(test::references_used().certified, 450);
}

}  // namespace
}  // namespace viscor
