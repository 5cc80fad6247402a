// Acceptance (issue 7): evaluate never violates its bound over 500 random scene
// points (fixed seed) with tolerances from 1e-2 to 1e-40, compared with certified
// values (certify at 25+ digits beyond the tolerance).
#include "evaluate_test_utils.hpp"

#include <iostream>

namespace viscor {
namespace {

int certified_references = 0, taylor_references = 0;

// certify at `digits`; where it certifies too few digits for the comparison
// (close to the sticking threshold), a Taylor solve at twice the digits instead.
std::pair<std::string, std::string> certified_reference(const test::scene_point& p, int digits) {
  const int needed = std::max(p.tolerance_exponent, 16) + 5;
  const auto certified = with_working_precision(digits, [&]<class Ref>() -> std::optional<std::pair<std::string, std::string>> {
    const certified_result<Ref> c = certify(p.law, parse_real<Ref>(p.gamma, "gamma"), parse_real<Ref>(p.g, "g"));
    if (!c.outcome_certified) return std::nullopt;
    if (c.outcome == impact_outcome::rebound && c.digits < needed && c.absolute_digits_e < needed) return std::nullopt;
    return std::pair<std::string, std::string>(to_decimal_string(c.e), to_decimal_string(c.one_minus_e));
  });
  if (certified) {
    ++certified_references;
    return *certified;
  }
  ++taylor_references;
  return test::taylor_reference(p, 2 * digits);
}

TEST(evaluate_slow, never_violates_its_bound_on_500_points_to_1e_40) {
  const auto maps = test::test_maps(2);
  test::check_counts counts;
  int failures = 0;
  for (const test::scene_point& p : test::random_points(20240607, 500, 2, 40)) {
    const ::testing::AssertionResult ok = test::check_point(p, maps.at(p.law.name).get(), certified_reference, counts);
    EXPECT_TRUE(ok);
    if (!ok) ++failures;
  }
  EXPECT_EQ(counts.checked, 500);
  std::cout << "checked " << counts.checked << " points, " << failures << " violations; references: "
            << certified_references << " certified, " << taylor_references << " Taylor at 2x digits\n  methods:";
  for (const auto& [method, n] : counts.by_method) std::cout << " " << method << " " << n;
  std::cout << "\n";
  EXPECT_GE(certified_references, 450);
}

}  // namespace
}  // namespace viscor
