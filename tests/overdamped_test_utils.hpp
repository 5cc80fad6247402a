// Shared by overdamped_test.cpp and overdamped_slow_test.cpp (issue 18 item 8).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/impact/adaptive_impact.hpp>
#include <viscor/impact/taylor_impact.hpp>

#include <boost/math/special_functions/fpclassify.hpp>
#include <gtest/gtest.h>

#include <string>

namespace viscor::test {

inline constexpr const char* overdamped_laws[] = {"linear", "hertz_linear_damping", "tsuji", "kuwabara_kono",
                                                  "hunt_crossley"};

/// g > 0, gamma large: both methods say stick, within a step budget far below the
/// default, and agree with each other (contact time both +inf or within `rel`; u_max
/// within `rel`, at least u*); the linear law's closed form says the same.
template <class Real>
void check_creep_up(const char* law_name, const char* gamma_text, const char* g_text) {
  SCOPED_TRACE(std::string(law_name) + ", gamma = " + gamma_text + ", g = " + g_text);
  using boost::math::isinf;
  using std::abs;
  using std::pow;
  const contact_law law = law_by_name(law_name);
  const Real gamma = parse_real<Real>(gamma_text, "gamma"), g = parse_real<Real>(g_text, "g");
  const Real rel = 1e-8;
  solve_options<Real> options;
  options.max_steps = 100000;  // before the fix: over 1e6 steps (a refusal) at gamma >= 1e4, g >= 1e6
  const Real u_star = pow(g, 1 / law.alpha.template value<Real>());
  const impact_result<Real> t = solve_impact_taylor<Real>(law, gamma, g, options);
  const impact_result<Real> a = solve_impact_adaptive<Real>(law, gamma, g, options);
  for (const impact_result<Real>* r : {&t, &a}) {
    SCOPED_TRACE(std::string(to_string(r->method)));
    EXPECT_EQ(r->outcome, impact_outcome::stick);
    EXPECT_EQ(r->e, 0);
    EXPECT_GE(r->max_compression, u_star * (1 - rel)) << to_decimal_string(r->max_compression);
  }
  auto agree = [&](const Real& x, const Real& y) {
    if (isinf(x) || isinf(y)) return x == y;
    return abs(x - y) <= rel * abs(y);
  };
  EXPECT_TRUE(agree(t.contact_time, a.contact_time))
      << to_decimal_string(t.contact_time) << " vs " << to_decimal_string(a.contact_time);
  EXPECT_TRUE(agree(t.max_compression, a.max_compression))
      << to_decimal_string(t.max_compression) << " vs " << to_decimal_string(a.max_compression);
  if (std::string(law_name) == "linear") {
    const exact_result<Real> x = exact_linear(gamma, g);
    EXPECT_EQ(x.outcome, impact_outcome::stick);
    ASSERT_TRUE(x.contact_time.has_value());
    EXPECT_TRUE(agree(t.contact_time, *x.contact_time)) << to_decimal_string(*x.contact_time);
    ASSERT_TRUE(x.max_compression.has_value());
    EXPECT_TRUE(agree(t.max_compression, *x.max_compression)) << to_decimal_string(*x.max_compression);
  }
}

}  // namespace viscor::test
