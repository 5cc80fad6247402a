// Heavy high-precision sweeps of integrals.hpp (label "slow"): the two independent
// quadratures at 100 digits over the acceptance grid (docs/approximations.md), and the primary
// method up to g = 1e12 by precision escalation (50 against 100 digits).
#include <viscor/approx/chebyshev_beta.hpp>
#include <viscor/approx/closed_form.hpp>
#include <viscor/approx/integrals.hpp>

#include "test_utils.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

TEST(IntegralsSlow, TwoQuadraturesAgreeToNinetyFiveDigits) {
  using Real = viscor::mpfr_100;
  for (const auto& n : viscor::named_laws) {
    const auto law = viscor::law_by_name(n.name);
    const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
    for (const double gd : {0.0, 0.05, 1.0, 10.0, 1e3, 1e6}) {
      SCOPED_TRACE(std::string(n.name) + ", g = " + std::to_string(gd));
      const Real g = gd;
      const auto v = viscor::integrals_IQ(a, b, g);
      const Real theta = viscor::theta_of_g(a, g);
      VISCOR_EXPECT_REL(v.I, Real(viscor::k_factor(a, b, theta) * viscor::j_integral(a, b, theta)), Real(1e-95));
      VISCOR_EXPECT_REL(v.Q, Real(viscor::l_factor(a, b, theta) * viscor::m_integral(a, b, theta)), Real(1e-95));
      if (gd == 0) {
        VISCOR_EXPECT_REL(v.I, viscor::integral_I_at_zero(a, b), Real(1e-97));
        VISCOR_EXPECT_REL(v.Q, viscor::integral_Q_at_zero(a, b), Real(1e-97));
      }
    }
  }
}

TEST(IntegralsSlow, PrimaryMethodHoldsFiftyDigitsUpToHugeLoads) {
  for (const auto& n : viscor::named_laws) {
    const auto law = viscor::law_by_name(n.name);
    for (const double gd : {1e3, 1e6, 1e9, 1e12}) {
      SCOPED_TRACE(std::string(n.name) + ", g = " + std::to_string(gd));
      const auto v50 = viscor::integrals_IQ<viscor::mpfr_50>(law, viscor::mpfr_50(gd));
      const auto v100 = viscor::integrals_IQ<viscor::mpfr_100>(law, viscor::mpfr_100(gd));
      VISCOR_EXPECT_REL(viscor::mpfr_100(v50.I), v100.I, viscor::mpfr_100(1e-47));
      VISCOR_EXPECT_REL(viscor::mpfr_100(v50.Q), v100.Q, viscor::mpfr_100(1e-47));
      const auto vd = viscor::integrals_IQ<double>(law, gd);
      VISCOR_EXPECT_REL(viscor::mpfr_100(vd.I), v100.I, viscor::mpfr_100(2e-14));
      VISCOR_EXPECT_REL(viscor::mpfr_100(vd.Q), v100.Q, viscor::mpfr_100(2e-14));
    }
  }
}

}  // namespace
