// u_M(g) and the integrals I(g), Q(g), dI/dg(g) of integrals.hpp, checked against
// exact solutions (alpha = 1; g = 0 Beta closed forms) and against the independent
// quadrature of the theta form (I = K J, Q = L M).
#include <viscor/approx/chebyshev_beta.hpp>
#include <viscor/approx/closed_form.hpp>
#include <viscor/approx/integrals.hpp>
#include <viscor/approx/u_max.hpp>

#include "test_utils.hpp"

#include <boost/math/constants/constants.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using viscor::test::ulps;

template <class Real>
class Integrals : public ::testing::Test {};

using Reals = ::testing::Types<double, long double, viscor::quad, viscor::mpfr_50>;
TYPED_TEST_SUITE(Integrals, Reals);

// g values of the acceptance list (all exactly representable in double).
const double acceptance_g[] = {0, 0.05, 1, 10, 1e3, 1e6};

TYPED_TEST(Integrals, UMaxSolvesEq13FromZeroToHugeLoads) {
  using Real = TypeParam;
  using std::pow;
  using std::abs;
  for (const auto& n : viscor::named_laws) {
    SCOPED_TRACE(std::string(n.name));
    const Real alpha = viscor::law_by_name(n.name).alpha.value<Real>();
    EXPECT_EQ(viscor::u_max(alpha, Real(0)), Real(pow((alpha + 1) / 2, 1 / (alpha + 1))));  // eq. (20)
    for (const Real g : {Real(1) / 1024, Real(1), Real(1e3), Real(1e6), Real(1e9), Real(1e12), -Real(1) / 4,
                         -Real(1e3)}) {
      SCOPED_TRACE(viscor::to_decimal_string(g));
      const Real u = viscor::u_max(alpha, g);
      // Residual of eq. (13), relative to the size of its terms.
      const Real lhs = pow(u, alpha + 1) / (alpha + 1), rhs = g * u + Real(1) / 2;
      EXPECT_LE(Real(abs(lhs - rhs) / (abs(lhs) + abs(g * u) + 1)), ulps<Real>(16));
    }
  }
}

TYPED_TEST(Integrals, UMaxOfTheLinearLawIsExact) {
  // alpha = 1: u^2/2 - g u = 1/2 gives u_M = g + sqrt(1 + g^2) = 1/(sqrt(1 + g^2) - g).
  using Real = TypeParam;
  using std::sqrt;
  for (const Real g : {Real(0), Real(1) / 20, Real(1), Real(1e3), Real(1e12), -Real(1) / 2, -Real(1e6)}) {
    const Real expected = g >= 0 ? Real(g + sqrt(1 + g * g)) : Real(1 / (sqrt(1 + g * g) - g));
    VISCOR_EXPECT_REL(viscor::u_max(Real(1), g), expected, ulps<Real>(8));
  }
}

TYPED_TEST(Integrals, LinearLawIntegralsAreCircleSegments) {
  // alpha = beta = 1: F = R^2 - (u - g)^2 with R^2 = 1 + g^2, so
  //   Q = pi/2 + atan(g),  I = 2 int sqrt(F) = (1 + g^2)(pi/2 + atan g) + g,  dI/dg = 2 (g Q + 1).
  using Real = TypeParam;
  using std::atan2;
  const Real one = 1;
  for (const Real g : {Real(0), Real(1) / 20, Real(1), Real(10), Real(1e3), Real(1e6), -Real(1) / 2}) {
    SCOPED_TRACE(viscor::to_decimal_string(g));
    const Real q = atan2(one, Real(-g));  // = pi/2 + atan(g) without cancellation for g < 0
    const auto v = viscor::integrals_IQ(one, one, g);
    const Real tol = ulps<Real>(256);
    VISCOR_EXPECT_REL(v.Q, q, tol);
    VISCOR_EXPECT_REL(v.I, Real((1 + g * g) * q + g), tol);
    VISCOR_EXPECT_REL(viscor::integral_dI_dg(one, one, g), Real(2 * (g * q + 1)), tol);
  }
}

TYPED_TEST(Integrals, TwoIndependentQuadraturesAgree) {
  // Primary: r = u/u_M, pieces in r, ln r and t (r = 1 - t^2), tanh-sinh. Independent:
  // theta form (45)-(47), exp-sinh, Gauss-Kronrod and two-argument tanh-sinh.
  // mpfr_50: 1000 eps = 1.1e-47, i.e. more than the 45 digits asked for.
  using Real = TypeParam;
  for (const auto& n : viscor::named_laws) {
    const auto law = viscor::law_by_name(n.name);
    const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
    for (const double gd : acceptance_g) {
      SCOPED_TRACE(std::string(n.name) + ", g = " + std::to_string(gd));
      const Real g = gd;
      const auto v = viscor::integrals_IQ(a, b, g);
      const Real theta = viscor::theta_of_g(a, g);
      const Real tol = ulps<Real>(1000);
      VISCOR_EXPECT_REL(v.I, Real(viscor::k_factor(a, b, theta) * viscor::j_integral(a, b, theta)), tol);
      VISCOR_EXPECT_REL(v.Q, Real(viscor::l_factor(a, b, theta) * viscor::m_integral(a, b, theta)), tol);
      if (gd == 0) {
        VISCOR_EXPECT_REL(v.I, viscor::integral_I_at_zero(a, b), ulps<Real>(256));
        VISCOR_EXPECT_REL(v.Q, viscor::integral_Q_at_zero(a, b), ulps<Real>(256));
      }
    }
  }
}

TYPED_TEST(Integrals, DerivativeMatchesCentredDifference) {
  using Real = TypeParam;
  using std::pow;
  using std::sqrt;
  using std::cbrt;
  // Centred difference with h ~ eps^(1/3): error ~ eps^(2/3) relative.
  const Real h = cbrt(viscor::epsilon<Real>());
  for (const char* name : {"tsuji", "hunt_crossley"}) {
    const auto law = viscor::law_by_name(name);
    const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
    for (const Real g : {Real(1) / 2, Real(10)}) {
      SCOPED_TRACE(std::string(name) + ", g = " + viscor::to_decimal_string(g));
      const Real hg = h * g;
      const Real difference = (viscor::integral_I(a, b, Real(g + hg)) - viscor::integral_I(a, b, Real(g - hg))) / (2 * hg);
      VISCOR_EXPECT_REL(viscor::integral_dI_dg(a, b, g), difference, Real(64 * h * h));
    }
  }
}

TEST(IntegralsPrecision, FiftyAndHundredDigitsAgreeBeyondDouble) {
  // A double slipping into the templated code would cap the agreement near 1e-16.
  const auto law = viscor::law_by_name("kuwabara_kono");
  for (const double gd : {0.05, 1e3}) {
    const auto v50 = viscor::integrals_IQ<viscor::mpfr_50>(law, viscor::mpfr_50(gd));
    const auto v100 = viscor::integrals_IQ<viscor::mpfr_100>(law, viscor::mpfr_100(gd));
    VISCOR_EXPECT_REL(viscor::mpfr_100(v50.I), v100.I, viscor::mpfr_100(1e-48));
    VISCOR_EXPECT_REL(viscor::mpfr_100(v50.Q), v100.Q, viscor::mpfr_100(1e-48));
  }
}

TEST(IntegralsPrecision, HundredDigitsAgainstClosedFormAndTheIndependentMethod) {
  using Real = viscor::mpfr_100;
  const auto law = viscor::law_by_name("tsuji");
  const Real a = law.alpha.value<Real>(), b = law.beta.value<Real>();
  const auto v0 = viscor::integrals_IQ(a, b, Real(0));
  VISCOR_EXPECT_REL(v0.I, viscor::integral_I_at_zero(a, b), Real(1e-95));
  VISCOR_EXPECT_REL(v0.Q, viscor::integral_Q_at_zero(a, b), Real(1e-95));
  const Real g = 1;
  const auto v = viscor::integrals_IQ(a, b, g);
  const Real theta = viscor::theta_of_g(a, g);
  VISCOR_EXPECT_REL(v.Q, Real(viscor::l_factor(a, b, theta) * viscor::m_integral(a, b, theta)), Real(1e-95));
}

TEST(IntegralsPrecision, RunTimePrecisionGetsItsOwnIntegrator) {
  // The cached integrator of mpfr_real is keyed by precision: 30 then 80 digits.
  using Real = viscor::mpfr_real;
  const auto law = viscor::law_by_name("kuwabara_kono");
  Real q30, q80, ref80;
  {
    viscor::scoped_precision digits(30);
    q30 = viscor::integrals_IQ<Real>(law, Real(0)).Q;
  }
  {
    viscor::scoped_precision digits(80);
    q80 = viscor::integrals_IQ<Real>(law, Real(0)).Q;
    ref80 = viscor::integral_Q_at_zero(Real(3) / 2, Real(3) / 2);
    VISCOR_EXPECT_REL(q80, ref80, Real(1e-77));
    VISCOR_EXPECT_REL(Real(q30), ref80, Real(1e-28));
  }
}

TEST(IntegralsErrors, BadInputIsRejectedWithTheValue) {
  EXPECT_THROW(viscor::u_max(0.5, 1.0), viscor::invalid_parameter);
  EXPECT_THROW(viscor::u_max(1.5, std::nan("")), viscor::invalid_parameter);
  EXPECT_THROW(viscor::integrals_IQ(1.5, 0.9, 1.0), viscor::invalid_parameter);
  EXPECT_THROW(viscor::integral_dI_dg(1.5, 1.5, double(INFINITY)), viscor::invalid_parameter);
  try {
    viscor::m_integral(1.5, 1.5, 1.25);
    FAIL() << "theta = 1.25 accepted";
  } catch (const viscor::invalid_parameter& e) {
    EXPECT_NE(std::string(e.what()).find("theta = 1.25"), std::string::npos) << e.what();
  }
  EXPECT_THROW(viscor::j_integral(1.5, 1.5, -0.5), viscor::invalid_parameter);
}

}  // namespace
