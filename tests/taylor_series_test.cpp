// Taylor-series recurrences (detail/taylor_series.hpp) against series known in
// closed form, and the Taylor integrator on an exactly solvable ODE.
#include <viscor/ode/detail/taylor_series.hpp>
#include <viscor/ode/taylor_integrator.hpp>

#include <boost/math/special_functions/binomial.hpp>
#include <boost/math/special_functions/factorials.hpp>

#include <gtest/gtest.h>

#include "test_utils.hpp"

#include <cmath>
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
