// The GBS integrator alone, on ODEs with known solutions, at double and at 50
// and 100 digits (integrating in detail::gbs_work<Real>, as solve_impact_adaptive does).
#include <viscor/ode/adaptive_integrator.hpp>

#include "test_utils.hpp"

#include <boost/math/constants/constants.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace {

using namespace viscor;
using viscor::test::relative_close;

template <class Real>
class adaptive_integrator_test : public ::testing::Test {};

using integrator_types = ::testing::Types<double
#if VISCOR_HAS_MPFR
                                          , mpfr_50, mpfr_100
#endif
                                          >;
TYPED_TEST_SUITE(adaptive_integrator_test, integrator_types);

struct run_stats {
  int accepted = 0, rejected = 0, max_columns_used = 0;
};

// Integrates y' = f(t, y) from t0 to t1 in the work type of Real and returns y(t1) in Real.
template <class Real, std::size_t N, class F>
std::array<Real, N> integrate(F f, const std::array<Real, N>& y0, const Real& t0, const Real& t1, run_stats& stats) {
  using W = typename detail::gbs_work<Real>::type;
  const int guard = detail::gbs_work<Real>::guard_digits();
  scoped_precision precision(decimal_digits<Real>() + guard);
  const W rtol = W(epsilon<Real>()) / 64;
  std::array<W, N> atol{}, y{};
  for (std::size_t i = 0; i < N; ++i) atol[i] = rtol, y[i] = W(y0[i]);
  gbs_integrator<W, N> gbs(rtol, atol, detail::gbs_max_columns(decimal_digits<W>(), guard));
  W t = W(t0), end = W(t1), h = W(1) / 10;
  for (int attempt = 0; t < end; ++attempt) {
    if (attempt > 100000) throw std::runtime_error("integration did not finish");
    if (h > end - t) h = end - t;
    const gbs_status status = gbs.try_step(f, t, y, h);
    if (status == gbs_status::accepted) {
      ++stats.accepted;
      stats.max_columns_used = std::max(stats.max_columns_used, gbs.last_columns());
    } else {
      ++stats.rejected;
    }
  }
  std::array<Real, N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<Real>(y[i]);
  return out;
}

TYPED_TEST(adaptive_integrator_test, harmonic_oscillator_to_working_precision) {
  using Real = TypeParam;
  using W = typename detail::gbs_work<Real>::type;
  auto f = [](const W&, const std::array<W, 2>& y, std::array<W, 2>& d) {
    d[0] = y[1];
    d[1] = -y[0];
    return true;
  };
  run_stats stats;
  const Real T = 10;
  const auto y = integrate<Real, 2>(f, {Real(0), Real(1)}, Real(0), T, stats);
  using std::cos;
  using std::sin;
  const Real tol = 20 * epsilon<Real>();
  // |y| stays <= 1: compare absolutely, in Real.
  EXPECT_PRED_FORMAT3(viscor::test::absolute_close, y[0], Real(sin(T)), tol);
  EXPECT_PRED_FORMAT3(viscor::test::absolute_close, y[1], Real(cos(T)), tol);
  EXPECT_LT(stats.accepted, 120) << "ten time units should take tens of steps";
}

TYPED_TEST(adaptive_integrator_test, exponential_growth_relative_precision) {
  using Real = TypeParam;
  using W = typename detail::gbs_work<Real>::type;
  auto f = [](const W&, const std::array<W, 1>& y, std::array<W, 1>& d) {
    d[0] = y[0];
    return true;
  };
  run_stats stats;
  const auto y = integrate<Real, 1>(f, {Real(1)}, Real(0), Real(5), stats);
  using std::exp;
  EXPECT_PRED_FORMAT3(relative_close, y[0], Real(exp(Real(5))), Real(20 * epsilon<Real>()));
}

TYPED_TEST(adaptive_integrator_test, time_dependent_right_hand_side) {
  // y' = cos(t) y, y(0) = 1: y(t) = exp(sin t); checks the sub-step times.
  using Real = TypeParam;
  using W = typename detail::gbs_work<Real>::type;
  auto f = [](const W& t, const std::array<W, 1>& y, std::array<W, 1>& d) {
    using std::cos;
    d[0] = cos(t) * y[0];
    return true;
  };
  run_stats stats;
  const Real T = 4;
  const auto y = integrate<Real, 1>(f, {Real(1)}, Real(0), T, stats);
  using std::exp;
  using std::sin;
  EXPECT_PRED_FORMAT3(relative_close, y[0], Real(exp(sin(T))), Real(20 * epsilon<Real>()));
}

#if VISCOR_HAS_MPFR
TEST(adaptive_integrator, order_grows_with_the_digits) {
  // NOTE: the reason GBS reaches 100 digits: the column count is not capped at
  // Odeint's 8 (order 16); it grows with the precision.
  auto columns_used = [](auto zero) {
    using Real = decltype(zero);
    using W = typename detail::gbs_work<Real>::type;
    auto f = [](const W&, const std::array<W, 2>& y, std::array<W, 2>& d) {
      d[0] = y[1];
      d[1] = -y[0];
      return true;
    };
    run_stats stats;
    integrate<Real, 2>(f, {Real(0), Real(1)}, Real(0), Real(3), stats);
    return stats.max_columns_used;
  };
  const int at16 = columns_used(0.0), at50 = columns_used(mpfr_50(0)), at100 = columns_used(mpfr_100(0));
  // double integrates in long double with 3 guard digits: up to 12 columns (by_need).
  EXPECT_LE(at16, 12);
  EXPECT_LT(at16, at50);
  EXPECT_GT(at50, 8);
  EXPECT_GT(at100, at50);
  EXPECT_GE(at100, 20);
}

TEST(adaptive_integrator, extrapolation_converges_with_columns) {
  // One fixed step of length 1/2 on the harmonic oscillator: each extra column
  // gains about two orders; far more than a midpoint rule alone.
  using W = mpfr_100;
  auto f = [](const W&, const std::array<W, 2>& y, std::array<W, 2>& d) {
    d[0] = y[1];
    d[1] = -y[0];
    return true;
  };
  gbs_integrator<W, 2> gbs(epsilon<W>(), {W(0), W(0)}, 30);
  const W h = W(1) / 2;
  W previous = -1;
  for (int k : {2, 6, 10, 14}) {
    std::array<W, 2> out;
    ASSERT_TRUE(gbs.fixed_step(f, W(0), {W(0), W(1)}, h, k, out));
    using std::abs;
    using std::sin;
    const W err = abs(out[0] - sin(h));
    if (previous >= 0) EXPECT_LT(err, previous * W(1e-8)) << "columns " << k;
    previous = err;
  }
}
#endif

TEST(adaptive_integrator, domain_error_halves_the_step) {
  // A right-hand side that refuses y < 0.5 (as the impact solver refuses v <= 0).
  auto f = [](const double&, const std::array<double, 1>& y, std::array<double, 1>& d) {
    if (y[0] < 0.5) return false;
    d[0] = -1;
    return true;
  };
  gbs_integrator<double, 1> gbs(1e-14, {1e-14}, 6);
  double t = 0, h = 2;
  std::array<double, 1> y{1};
  EXPECT_EQ(gbs.try_step(f, t, y, h), gbs_status::domain_error);
  EXPECT_EQ(h, 1);
  EXPECT_EQ(t, 0);
  EXPECT_EQ(y[0], 1);
  h = 0.25;
  EXPECT_EQ(gbs.try_step(f, t, y, h), gbs_status::accepted);
  EXPECT_EQ(t, 0.25);
  EXPECT_NEAR(y[0], 0.75, 1e-13);  // double without guard digits: extrapolation rounding
}

TEST(adaptive_integrator, rejects_a_step_that_is_too_long) {
  // y' = -50 y over a step of 1: no extrapolation tableau of order <= 14 reaches 1e-14.
  auto f = [](const double&, const std::array<double, 1>& y, std::array<double, 1>& d) {
    d[0] = -50 * y[0];
    return true;
  };
  gbs_integrator<double, 1> gbs(1e-14, {0.0}, 6);
  double t = 0, h = 1;
  std::array<double, 1> y{1};
  EXPECT_EQ(gbs.try_step(f, t, y, h), gbs_status::rejected);
  EXPECT_LT(h, 1);
  EXPECT_EQ(t, 0);
}

// A non-finite state or derivative at a step's start is an error outcome
// (no step size can cure it), not a rejection retried until the step underflows.
TEST(adaptive_integrator, non_finite_start_is_an_error_outcome) {
  using state = std::array<double, 1>;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  gbs_integrator<double, 1> gbs(1e-12, state{1e-12}, 8);
  auto nan_rhs = [&](const double&, const state&, state& d) { d[0] = nan; return true; };
  double t = 0, h = 0.125;
  state y{1.0};
  EXPECT_EQ(gbs.try_step(nan_rhs, t, y, h), gbs_status::non_finite);
  EXPECT_EQ(t, 0.0);
  EXPECT_EQ(y[0], 1.0);
  EXPECT_EQ(h, 0.125);
  auto one = [](const double&, const state&, state& d) { d[0] = 1; return true; };
  state bad{inf};
  EXPECT_EQ(gbs.try_step(one, t, bad, h), gbs_status::non_finite);
  // Non-finite values further into the step are a matter of its length: shorter, then accepted.
  auto blows_up = [&](const double& s, const state&, state& d) { d[0] = s > 0.05 ? nan : 1.0; return true; };
  y = {0.0};
  gbs_status st = gbs_status::rejected;
  for (int tries = 0; tries < 20 && st != gbs_status::accepted; ++tries) {
    st = gbs.try_step(blows_up, t, y, h);
    EXPECT_NE(st, gbs_status::non_finite);
  }
  EXPECT_EQ(st, gbs_status::accepted);
  EXPECT_GT(t, 0.0);
  EXPECT_LE(t, 0.05);
  // y' = 1 from 0: y = t exactly, up to the step's tolerance (the extrapolation
  // weights amplify rounding: 8 ulps were seen, more than EXPECT_DOUBLE_EQ's 4).
  EXPECT_NEAR(y[0], t, 1e-12 * t);
}

}  // namespace
