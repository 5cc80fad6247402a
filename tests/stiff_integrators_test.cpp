// The stiff integrators, Radau IIA (ode/radau_integrator.hpp) and Lobatto IIIC
// (ode/lobatto_integrator.hpp): each tableau satisfies the conditions that define it
// (and the known 2- and 3-stage ones), and a very stiff problem with a known solution
// is followed with steps set by the slow motion, not by the fast rate.
#include <viscor/ode/lobatto_integrator.hpp>
#include <viscor/ode/radau_integrator.hpp>
#include <viscor/core/real_types.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace {

using namespace viscor;

template <class Real>
void check_tableau(int s, const Real& tol) {
  SCOPED_TRACE("s = " + std::to_string(s));
  using std::abs;
  using std::pow;
  const detail::radau_tableau<Real> t(s);
  EXPECT_EQ(t.c.back(), Real(1));
  for (int i = 0; i < s; ++i) {
    if (i > 0) EXPECT_LT(t.c[i - 1], t.c[i]);
    // C(s): sum_j a_ij c_j^(k-1) = c_i^k / k
    for (int k = 1; k <= s; ++k) {
      Real sum = 0;
      for (int j = 0; j < s; ++j) sum += t.a[static_cast<std::size_t>(i * s + j)] * pow(t.c[j], k - 1);
      EXPECT_LE(abs(sum - pow(t.c[i], k) / k), tol) << "i = " << i << ", k = " << k;
    }
  }
  // B(2s - 1) for the weights b = the last row of A (stiffly accurate)
  for (int k = 1; k <= 2 * s - 1; ++k) {
    Real sum = 0;
    for (int j = 0; j < s; ++j) sum += t.a[static_cast<std::size_t>((s - 1) * s + j)] * pow(t.c[j], k - 1);
    EXPECT_LE(abs(sum - Real(1) / k), tol) << "k = " << k;
  }
}

TEST(radau_integrator, tableau_conditions_double) {
  for (int s = 1; s <= 9; ++s) check_tableau<double>(s, 1e-13);
  const detail::radau_tableau<double> two(2), three(3);
  EXPECT_NEAR(two.c[0], 1.0 / 3, 1e-15);
  EXPECT_NEAR(three.c[0], (4 - std::sqrt(6.0)) / 10, 1e-15);
  EXPECT_NEAR(three.c[1], (4 + std::sqrt(6.0)) / 10, 1e-15);
}

#if VISCOR_HAS_MPFR
TEST(radau_integrator, tableau_conditions_50_digits) {
  check_tableau<mpfr_50>(17, mpfr_50("1e-46"));
}
#endif

// Lobatto IIIC: a_i1 = b_1, C(s - 1) and B(2s - 2) for b = the last row.
template <class Real>
void check_lobatto_tableau(int s, const Real& tol) {
  SCOPED_TRACE("s = " + std::to_string(s));
  using std::abs;
  using std::pow;
  const detail::lobatto_iiic_tableau<Real> t(s);
  auto a = [&](int i, int j) { return t.a[static_cast<std::size_t>(i * s + j)]; };
  EXPECT_EQ(t.c.front(), Real(0));
  EXPECT_EQ(t.c.back(), Real(1));
  for (int i = 0; i < s; ++i) {
    EXPECT_LE(abs(a(i, 0) - a(s - 1, 0)), tol);
    for (int k = 1; k <= s - 1; ++k) {
      Real sum = 0;
      for (int j = 0; j < s; ++j) sum += a(i, j) * (k == 1 ? Real(1) : Real(pow(t.c[j], k - 1)));
      EXPECT_LE(abs(sum - pow(t.c[i], k) / k), tol) << "i = " << i << ", k = " << k;
    }
  }
  for (int k = 1; k <= 2 * s - 2; ++k) {
    Real sum = 0;
    for (int j = 0; j < s; ++j) sum += a(s - 1, j) * (k == 1 ? Real(1) : Real(pow(t.c[j], k - 1)));
    EXPECT_LE(abs(sum - Real(1) / k), tol) << "k = " << k;
  }
}

TEST(lobatto_integrator, tableau_conditions_double) {
  for (int s = 2; s <= 9; ++s) check_lobatto_tableau<double>(s, 1e-13);
  const detail::lobatto_iiic_tableau<double> three(3);
  const double known[] = {1.0 / 6, -1.0 / 3, 1.0 / 6, 1.0 / 6, 5.0 / 12, -1.0 / 12, 1.0 / 6, 2.0 / 3, 1.0 / 6};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(three.a[static_cast<std::size_t>(i)], known[i], 1e-15) << i;
  EXPECT_NEAR(three.c[1], 0.5, 1e-16);
}

#if VISCOR_HAS_MPFR
TEST(lobatto_integrator, tableau_conditions_50_digits) {
  check_lobatto_tableau<mpfr_50>(19, mpfr_50("1e-46"));
}
#endif

// x' = lambda (x - sin t) + cos t with t' = 1, x(0) = 0: x = sin t for every lambda.
template <class Real, class Integrator>
void follow_stiff(Integrator radau, const Real& lambda, const Real& accuracy, int max_steps) {
  using std::abs;
  using std::cos;
  using std::sin;
  using vec = std::array<Real, 2>;
  auto f = [&](const vec& y, vec& d) {
    d[0] = 1;
    d[1] = lambda * (y[1] - sin(y[0])) + cos(y[0]);
    return true;
  };
  auto jacobian = [&](const vec& y, std::array<vec, 2>& J) {
    J[0] = vec{Real(0), Real(0)};
    J[1] = vec{Real(-lambda * cos(y[0]) - sin(y[0])), lambda};
  };
  vec y{Real(0), Real(0)};
  Real h = Real(1) / 16, taken = 0;
  int steps = 0;
  while (y[0] < 2) {
    if (y[0] + h > 2) h = 2 - y[0];
    const vec scales{Real(1), Real(1)};
    ++steps;
    ASSERT_LT(steps, max_steps);
    if constexpr (requires { radau.try_step(f, jacobian, y, h, scales, taken); })
      radau.try_step(f, jacobian, y, h, scales, taken);
    else
      radau.step(f, jacobian, y, h, scales, taken);
  }
  EXPECT_LE(abs(y[1] - sin(y[0])), accuracy);
}

TEST(radau_integrator, follows_a_very_stiff_problem_with_slow_steps) {
  follow_stiff<double>(radau_integrator<double, 2>(5, 1e-14), -1e10, 1e-12, 200);
  follow_stiff<double>(radau_integrator<double, 2>(5, 1e-14), -1.0, 1e-12, 200);
#if VISCOR_HAS_MPFR
  follow_stiff<mpfr_50>(radau_integrator<mpfr_50, 2>(17, mpfr_50("1e-49")), mpfr_50(-1e10), mpfr_50("1e-46"), 400);
#endif
}

TEST(lobatto_integrator, follows_a_very_stiff_problem_with_slow_steps) {
  follow_stiff<double>(lobatto_integrator<double, 2>(6, 1e-14), -1e10, 1e-12, 200);
  follow_stiff<double>(lobatto_integrator<double, 2>(6, 1e-14), -1.0, 1e-12, 200);
#if VISCOR_HAS_MPFR
  follow_stiff<mpfr_50>(lobatto_integrator<mpfr_50, 2>(19, mpfr_50("1e-49")), mpfr_50(-1e10), mpfr_50("1e-46"), 400);
#endif
}

}  // namespace
