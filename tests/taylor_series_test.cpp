// Taylor-series recurrences (detail/taylor_series.hpp) against series known in
// closed form, and the Taylor integrator on an exactly solvable ODE.
#include <viscor/ode/detail/taylor_series.hpp>
#include <viscor/ode/taylor_integrator.hpp>

#include <boost/math/special_functions/binomial.hpp>
#include <boost/math/special_functions/factorials.hpp>

#include <gtest/gtest.h>

#include "test_utils.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace viscor {
namespace {

using test::relative_close;
using test::absolute_close;

template <class Real>
class TaylorSeries : public ::testing::Test {};
TYPED_TEST_SUITE(TaylorSeries, test::all_real_types);

constexpr std::size_t order = 24;

// a = 1 + h: 1/a = sum (-h)^k, a^p = sum binomial(p, k) h^k, a * a = 1 + 2h + h^2.
TYPED_TEST(TaylorSeries, ProductQuotientReciprocalPowerOfLinear) {
  using Real = TypeParam;
  const Real tol = 16 * epsilon<Real>();
  std::vector<Real> a(order + 1, Real(0)), ja(order + 1, Real(0)), r(order + 1), q(order + 1), c(order + 1),
      pw(order + 1), sq(order + 1);
  a[0] = 1, a[1] = 1;
  ja[1] = 1;
  r[0] = 1;
  q[0] = 1;
  const Real p = Real(5) / 4;
  pw[0] = 1;
  Real scratch;
  for (std::size_t k = 0; k <= order; ++k) {
    if (k > 0) {
      detail::reciprocal(r[k], a.data(), r.data(), k);
      detail::quotient(q[k], a.data(), a.data(), q.data(), k);  // a / a = 1
      detail::real_power(pw[k], scratch, Real(p + 1), a.data(), ja.data(), pw.data(), k);
    }
    detail::product(sq[k], a.data(), a.data(), k);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, r[k], Real(k % 2 ? -1 : 1), tol);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, q[k], Real(k == 0 ? 1 : 0), tol);
    // binomial(p, k) = prod_{j<k} (p - j) / k!
    Real binomial = 1;
    for (std::size_t j = 0; j < k; ++j) binomial *= (p - Real(static_cast<long>(j))) / Real(static_cast<long>(j + 1));
    EXPECT_PRED_FORMAT3(absolute_close<Real>, pw[k], binomial, tol);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, sq[k], Real(k == 0 ? 1 : k == 1 ? 2 : k == 2 ? 1 : 0), tol);
  }
}

// (x0 + h)^m with x0 = 0 (a monomial) and x0 = 3/2 (binomial), exactly.
TYPED_TEST(TaylorSeries, IntegerPowerOfLinearIncludingZeroBase) {
  using Real = TypeParam;
  std::vector<Real> c(order + 1), powers;
  detail::integer_power_of_linear(c, powers, Real(0), 5, order);
  for (std::size_t j = 0; j <= order; ++j) EXPECT_EQ(c[j], Real(j == 5 ? 1 : 0)) << j;
  const Real x0 = Real(3) / 2;
  detail::integer_power_of_linear(c, powers, x0, 7, order);
  for (std::size_t j = 0; j <= order; ++j) {
    using std::pow;
    const Real expected = j > 7 ? Real(0)
                                : Real(boost::math::binomial_coefficient<double>(7, static_cast<unsigned>(j)) *
                                       pow(x0, static_cast<int>(7 - j)));
    EXPECT_PRED_FORMAT3(absolute_close<Real>, c[j], expected, Real(64 * epsilon<Real>()));
  }
}

// The power recurrence for a series with a0 != 1: (2 + h^2)^(-1/2) against
// the same series built from exp and log series... checked through b^2 * a = 1.
TYPED_TEST(TaylorSeries, RealPowerSatisfiesItsDefiningIdentity) {
  using Real = TypeParam;
  std::vector<Real> a(order + 1, Real(0)), ja(order + 1, Real(0)), b(order + 1), b2(order + 1), check(order + 1);
  a[0] = 2, a[2] = 1, a[3] = Real(-1) / 3;
  for (std::size_t j = 0; j <= order; ++j) ja[j] = a[j] * Real(static_cast<long>(j));
  using std::pow;
  const Real p = Real(-1) / 2;
  b[0] = pow(a[0], p);
  Real scratch;
  for (std::size_t k = 1; k <= order; ++k) detail::real_power(b[k], scratch, Real(p + 1), a.data(), ja.data(), b.data(), k);
  for (std::size_t k = 0; k <= order; ++k) detail::product(b2[k], b.data(), b.data(), k);
  for (std::size_t k = 0; k <= order; ++k) {
    detail::product(check[k], b2.data(), a.data(), k);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, check[k], Real(k == 0 ? 1 : 0), Real(64 * epsilon<Real>()));
  }
}

// The variant with 1/a0 and the table 1/k given (no divisions in the jets),
// and divide_by, on the same series: the identity b^2 a = 1 again.
TYPED_TEST(TaylorSeries, RealPowerWithReciprocalTable) {
  using Real = TypeParam;
  std::vector<Real> a(order + 1, Real(0)), ja(order + 1, Real(0)), b(order + 1), b2(order + 1), check(order + 1);
  a[0] = 2, a[2] = 1, a[3] = Real(-1) / 3;
  for (std::size_t j = 0; j <= order; ++j) ja[j] = a[j] * Real(static_cast<long>(j));
  using std::pow;
  const Real p = Real(-1) / 2;
  const std::vector<Real> inv = detail::integer_reciprocals<Real>(order);
  const Real inv_a0 = 1 / a[0];
  b[0] = pow(a[0], p);
  Real scratch;
  for (std::size_t k = 1; k <= order; ++k)
    detail::real_power(b[k], scratch, Real(p + 1), a.data(), ja.data(), b.data(), k, inv_a0, inv);
  for (std::size_t k = 0; k <= order; ++k) detail::product(b2[k], b.data(), b.data(), k);
  for (std::size_t k = 0; k <= order; ++k) {
    detail::product(check[k], b2.data(), a.data(), k);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, check[k], Real(k == 0 ? 1 : 0), Real(64 * epsilon<Real>()));
  }
  Real x = 6;
  detail::divide_by(x, 3, inv);
  EXPECT_PRED_FORMAT3(absolute_close<Real>, x, Real(2), Real(2 * epsilon<Real>()));
}

TYPED_TEST(TaylorSeries, ExponentialOfLinearAndHorner) {
  using Real = TypeParam;
  const std::size_t n = 80;  // (0.15)^80 / 80! < 1e-180: no truncation at any tested type
  std::vector<Real> c(n + 1);
  const Real lambda = Real(3) / 2, x0 = Real(-1) / 3;
  detail::exponential_of_linear(c, lambda, x0, n);
  Real value, slope;
  const Real h = Real(1) / 10;
  detail::horner(value, c.data(), n, h);
  detail::horner_derivative(slope, c.data(), n, h);
  using std::exp;
  const Real expected = exp(lambda * (x0 + h));
  const Real tol = 16 * epsilon<Real>();
  EXPECT_PRED_FORMAT3(relative_close<Real>, value, expected, tol);
  EXPECT_PRED_FORMAT3(relative_close<Real>, slope, Real(lambda * expected), tol);
}

// y' = -y^2 (y = 1/(1 + t)), integrated with the adaptive Taylor stepper to t = 3:
// the step must respect the pole at t = -1 and still reach working precision.
template <class Real>
struct pole_system {
  std::size_t size() const { return 1; }
  Real step_scale(std::size_t, const Real& x0) const {
    using std::abs;
    return abs(x0) < 1 ? Real(1) : Real(abs(x0));
  }
  void jet(const Real&, taylor_jet<Real>& x) {
    Real* y = x[0];
    for (std::size_t k = 0; k < x.order(); ++k) {
      Real s;
      detail::product(s, y, y, k);
      y[k + 1] = -s / Real(static_cast<long>(k + 1));
    }
  }
};

TYPED_TEST(TaylorSeries, IntegratorReachesWorkingPrecision) {
  using Real = TypeParam;
  pole_system<Real> system;
  taylor_integrator<Real, pole_system<Real>> integrator(system, epsilon<Real>());
  EXPECT_GE(integrator.order(), 2u);
  std::vector<Real> y{Real(1)};
  Real t = 0;
  const Real end = 3;
  int steps = 0;
  while (t < end) {
    const Real h = integrator.expand(t, y, Real(end - t));
    ASSERT_GT(h, 0);
    integrator.values(y, h);
    t = h == end - t ? end : Real(t + h);
    ASSERT_LT(++steps, 1000);
  }
  EXPECT_PRED_FORMAT3(relative_close<Real>, y[0], Real(Real(1) / 4), Real(64 * epsilon<Real>()));
  // Event location on the step polynomial: y = 1/(1 + t*) at t* = h/2.
  y[0] = 1;
  const Real h = integrator.expand(Real(0), y, Real(4));
  const Real t_star = h / 2;
  const Real root = integrator.locate(0, Real(1 / (1 + t_star)), h, "y = 1/(1 + t*)");
  EXPECT_PRED_FORMAT3(relative_close<Real>, root, t_star, Real(64 * epsilon<Real>()));
}

TEST(TaylorOrder, JorbaZouRule) {
  EXPECT_EQ(taylor_order(1e-16), 20u);  // ceil(18.42 + 1)
  EXPECT_EQ(taylor_order(0.5), 2u);
#if VISCOR_HAS_MPFR
  EXPECT_EQ(taylor_order(mpfr_100("1e-100")), 117u);  // ceil(115.13 + 1)
#endif
}

}  // namespace
}  // namespace viscor

#if VISCOR_HAS_MPFR
// The MPFR sums of products (mpfr_dot) are exact fixed-point sums rounded once up to
// fixed_point_dot_limbs limbs: against the same sum computed at 2000 bits and then
// rounded (the truth, by another route: MPFR's own products and sums, exact at that
// width for these inputs), every result is the correctly rounded one or within one
// ulp of it; inputs with zeros, mixed signs, exponents 2^-60..2^2 apart and terms
// built to cancel. Above the limit it falls back to one rounding per product and
// sum (checked against the same truth and the bound of those roundings).
/// Sums of products by mpfr_dot against the same sums at 2000 bits: how many results
/// are the correctly rounded ones, the worst distance in ulps of the others, and the
/// worst error as a fraction of the bound of one rounding per product and sum,
/// (terms + 1) 2^(1 - precision) sum |a[j] b[k - j]|.
template <class Real>
void check_dot_against_wide_sum(unsigned seed, int trials, int& correctly_rounded, int& worst_ulps,
                                double& worst_of_bound) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 2);
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t k = 1 + gen() % 45;
    std::vector<Real> a(k + 1), b(k + 1);
    for (std::size_t i = 0; i <= k; ++i) {
      a[i] = ldexp(Real(unit(gen)) / 3 + Real(unit(gen)) / 7, exponent(gen));
      b[i] = ldexp(Real(unit(gen)) / 11 + Real(unit(gen)) / 13, exponent(gen));
      if (gen() % 10 == 0) a[i] = 0;
    }
    if (trial % 3 == 0)  // pairs of products that cancel to their last bits
      for (std::size_t i = 0; 2 * i < k; ++i)  // a[i] b[k-i] = -a[k-i] b[i]
        if (a[i] != 0) b[k - i] = -a[k - i] * b[i] / a[i];
    const std::size_t lo = gen() % 2, hi = k - gen() % 2;
    Real got;
    viscor::detail::mpfr_dot(got.backend().data(), a.data(), b.data(), k, lo, hi);
    mpfr_t wide, product, magnitude, rounded, ulps;
    mpfr_inits2(2000, wide, product, magnitude, (mpfr_ptr)0);
    mpfr_init2(rounded, mpfr_get_prec(got.backend().data()));
    mpfr_init2(ulps, 64);
    mpfr_set_zero(wide, 1), mpfr_set_zero(magnitude, 1);
    for (std::size_t j = lo; j <= hi; ++j) {
      mpfr_mul(product, a[j].backend().data(), b[k - j].backend().data(), MPFR_RNDN);
      mpfr_add(wide, wide, product, MPFR_RNDN);
      mpfr_abs(product, product, MPFR_RNDN);
      mpfr_add(magnitude, magnitude, product, MPFR_RNDN);
    }
    if (!mpfr_zero_p(magnitude)) {
      mpfr_sub(product, got.backend().data(), wide, MPFR_RNDN);
      mpfr_div(product, product, magnitude, MPFR_RNDN);
      mpfr_mul_2si(product, product, mpfr_get_prec(rounded) - 1, MPFR_RNDN);
      worst_of_bound = std::max(worst_of_bound, std::abs(mpfr_get_d(product, MPFR_RNDN)) / static_cast<double>(hi - lo + 2));
    }
    mpfr_set(rounded, wide, MPFR_RNDN);
    if (mpfr_equal_p(rounded, got.backend().data())) {
      ++correctly_rounded;
    } else {
      mpfr_sub(ulps, got.backend().data(), rounded, MPFR_RNDN);
      mpfr_mul_2si(ulps, ulps, mpfr_get_prec(rounded) - mpfr_get_exp(rounded), MPFR_RNDN);
      worst_ulps = std::max(worst_ulps, static_cast<int>(std::ceil(std::abs(mpfr_get_d(ulps, MPFR_RNDN)))));
    }
    mpfr_clears(wide, product, magnitude, rounded, ulps, (mpfr_ptr)0);
  }
}

TEST(MpfrDot, FixedPointSumIsCorrectlyRoundedAt50Digits) {
  int correctly_rounded = 0, worst_ulps = 0;
  double worst_of_bound = 0;
  check_dot_against_wide_sum<viscor::mpfr_50>(7, 3000, correctly_rounded, worst_ulps, worst_of_bound);
  EXPECT_LE(worst_ulps, 1);
  EXPECT_GE(correctly_rounded, 2970) << "of 3000";
}

TEST(MpfrDot, FixedPointSumIsCorrectlyRoundedAt100Digits) {
  int correctly_rounded = 0, worst_ulps = 0;
  double worst_of_bound = 0;
  check_dot_against_wide_sum<viscor::mpfr_100>(11, 2000, correctly_rounded, worst_ulps, worst_of_bound);
  EXPECT_LE(worst_ulps, 1);
  EXPECT_GE(correctly_rounded, 1980) << "of 2000";
}

TEST(MpfrDot, AboveTheLimbLimitSumsAsBefore) {
  // 200 digits: 11 limbs, past fixed_point_dot_limbs: one rounding per product and sum.
  viscor::scoped_precision digits(200);
  const viscor::mpfr_real probe = 1;
  ASSERT_GT((mpfr_get_prec(probe.backend().data()) + 63) / 64, static_cast<long>(viscor::detail::fixed_point_dot_limbs));
  int correctly_rounded = 0, worst_ulps = 0;
  double worst_of_bound = 0;
  check_dot_against_wide_sum<viscor::mpfr_real>(13, 300, correctly_rounded, worst_ulps, worst_of_bound);
  EXPECT_LE(worst_of_bound, 1.0);  // within one rounding per product and sum
  EXPECT_GT(worst_ulps, 1);        // and not the fixed-point sum: cancellations cost it ulps
}
#endif
