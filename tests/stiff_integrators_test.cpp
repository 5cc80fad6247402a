// The stiff integrators, Radau IIA (ode/radau_integrator.hpp) and Lobatto IIIC
// (ode/lobatto_integrator.hpp): each tableau satisfies the conditions that define it
// (and the known 2- and 3-stage ones), and a very stiff problem with a known solution
// is followed with steps set by the slow motion, not by the fast rate.
#include <viscor/ode/lobatto_integrator.hpp>
#include <viscor/ode/radau_integrator.hpp>
#include <viscor/core/real_io.hpp>
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

#if VISCOR_HAS_MPFR
// Where Real is wider than long double, Newton's matrix is factored in
// double and only the corrections come from it (the residual stays in Real), with
// the matrix rebuilt at the stages when Newton contracts slowly. It must reach the
// same collocation solution as Newton with the LU in Real (the truth here: the same
// step with the double path switched off), and follow a nonlinear stiff problem
// to the closed form. x' = lambda (x + x^3 - sin t - sin^3 t) + cos t, t' = 1: x = sin t,
// with a Jacobian lambda (1 + 3 x^2) that changes over a step.
template <class Real>
struct nonlinear_stiff {
  Real lambda;
  using vec = std::array<Real, 2>;
  bool operator()(const vec& y, vec& d) const {
    using std::cos;
    using std::sin;
    const Real st = sin(y[0]);
    d[0] = 1;
    d[1] = lambda * (y[1] + y[1] * y[1] * y[1] - st - st * st * st) + cos(y[0]);
    return true;
  }
  void operator()(const vec& y, std::array<vec, 2>& J) const {
    using std::cos;
    using std::sin;
    const Real st = sin(y[0]);
    J[0] = vec{Real(0), Real(0)};
    J[1] = vec{Real(-lambda * (1 + 3 * st * st) * cos(y[0]) - st), Real(lambda * (1 + 3 * y[1] * y[1]))};
  }
};

template <class Integrator, class Step>
void compare_decompositions(Integrator low, Integrator real, Step step) {
  using Real = mpfr_50;
  using std::abs;
  using std::sin;
  nonlinear_stiff<Real> sys{Real(-1e10)};
  auto f = [&](const std::array<Real, 2>& y, std::array<Real, 2>& d) { return sys(y, d); };
  auto jacobian = [&](const std::array<Real, 2>& y, std::array<std::array<Real, 2>, 2>& J) { sys(y, J); };
  // off the solution, so that Newton has work to do; steps short enough for simplified
  // Newton in Real (the Jacobian at y0 for the whole step) to converge: at h = 0.5,
  // where 1 + 3 x^2 doubles over the step, only the double path's rebuilt matrix does.
  for (const char* h_text : {"0.02", "1e-3"}) {
    SCOPED_TRACE(std::string("h = ") + h_text);
    const std::array<Real, 2> y0{Real("0.3"), Real(sin(Real("0.3")) + Real("1e-12"))};
    std::array<Real, 2> y_low, y_real;
    ASSERT_TRUE(step(low, f, jacobian, y0, Real(h_text), y_low));
    ASSERT_TRUE(step(real, f, jacobian, y0, Real(h_text), y_real));
    EXPECT_EQ(y_low[0], y_real[0]);
    EXPECT_LE(abs(y_low[1] - y_real[1]), Real("1e-48") * abs(y_real[1])) << to_decimal_string(Real(y_low[1] - y_real[1]));
  }
}

TEST(radau_integrator, double_lu_reaches_the_real_lu_collocation_solution) {
  radau_integrator<mpfr_50, 2> low(17, mpfr_50("1e-49")), real(17, mpfr_50("1e-49"));
  real.set_low_precision_lu(false);
  ASSERT_TRUE(low.low_precision_lu());
  ASSERT_FALSE(real.low_precision_lu());
  auto step = [](auto& r, auto& f, auto& jac, const auto& y0, const mpfr_50& h, auto& y1) {
    return r.fixed_step(f, jac, y0, h, y1);
  };
  compare_decompositions(low, real, step);
  // and it was the double path that answered
  radau_integrator<mpfr_50, 2> probe(17, mpfr_50("1e-49"));
  nonlinear_stiff<mpfr_50> sys{mpfr_50(-1e10)};
  auto f = [&](const std::array<mpfr_50, 2>& y, std::array<mpfr_50, 2>& d) { return sys(y, d); };
  auto jacobian = [&](const std::array<mpfr_50, 2>& y, std::array<std::array<mpfr_50, 2>, 2>& J) { sys(y, J); };
  std::array<mpfr_50, 2> y1;
  ASSERT_TRUE(probe.fixed_step(f, jacobian, {mpfr_50("0.3"), mpfr_50(sin(mpfr_50("0.3")))}, mpfr_50("0.5"), y1));
  EXPECT_EQ(probe.low_precision_solves(), 1u);
  EXPECT_EQ(probe.real_precision_solves(), 0u);
}

TEST(lobatto_integrator, double_decomposition_reaches_the_real_stage_values) {
  lobatto_integrator<mpfr_50, 2> low(19, mpfr_50("1e-49")), real(19, mpfr_50("1e-49"));
  real.set_low_precision_lu(false);
  ASSERT_TRUE(low.low_precision_lu());
  ASSERT_FALSE(real.low_precision_lu());
  auto step = [](auto& r, auto& f, auto& jac, const auto& y0, const mpfr_50& h, auto& y1) {
    return r.fixed_step(f, jac, y0, h, y1);
  };
  compare_decompositions(low, real, step);
  lobatto_integrator<mpfr_50, 2> probe(19, mpfr_50("1e-49"));
  nonlinear_stiff<mpfr_50> sys{mpfr_50(-1e10)};
  auto f = [&](const std::array<mpfr_50, 2>& y, std::array<mpfr_50, 2>& d) { return sys(y, d); };
  auto jacobian = [&](const std::array<mpfr_50, 2>& y, std::array<std::array<mpfr_50, 2>, 2>& J) { sys(y, J); };
  std::array<mpfr_50, 2> y1;
  ASSERT_TRUE(probe.fixed_step(f, jacobian, {mpfr_50("0.3"), mpfr_50(sin(mpfr_50("0.3")))}, mpfr_50("0.5"), y1));
  EXPECT_EQ(probe.low_precision_solves(), 1u);
  EXPECT_EQ(probe.real_precision_solves(), 0u);
}

// After the matrix is rebuilt at the stages, the first update through it is about as
// large as the last through the old one, and may exceed it; that is not divergence.
// Here (h = 1, 1e-12 off the solution) the double path rebuilds the matrix and the
// next update grows (4.4e-8 -> 7.5e-8) before Newton converges; judged as divergence,
// both decompositions gave up and the step was refused. Truth: x = sin t, which the
// stiffly accurate step reaches to ~7e-31 (the start's offset, damped).
TEST(lobatto_integrator, a_renewed_matrix_is_not_judged_by_its_first_update) {
  using Real = mpfr_50;
  using std::abs;
  using std::sin;
  lobatto_integrator<Real, 2> lobatto(19, Real("1e-49"));
  nonlinear_stiff<Real> sys{Real(-1e10)};
  auto f = [&](const std::array<Real, 2>& y, std::array<Real, 2>& d) { return sys(y, d); };
  auto jacobian = [&](const std::array<Real, 2>& y, std::array<std::array<Real, 2>, 2>& J) { sys(y, J); };
  const std::array<Real, 2> y0{Real("0.3"), Real(sin(Real("0.3")) + Real("1e-12"))};
  std::array<Real, 2> y1;
  ASSERT_TRUE(lobatto.fixed_step(f, jacobian, y0, Real(1), y1));
  EXPECT_EQ(lobatto.low_precision_solves(), 1u);
  EXPECT_EQ(lobatto.real_precision_solves(), 0u);
  EXPECT_LE(abs(y1[0] - Real("1.3")), Real("1e-48"));
  EXPECT_LE(abs(y1[1] - sin(y1[0])), Real("1e-29")) << to_decimal_string(Real(y1[1] - sin(y1[0])));
}

// The whole adaptive path (half steps started from the whole step's polynomial, the
// double LU, the rebuilt matrix) on the nonlinear problem, against x = sin t.
template <class Integrator>
void follow_nonlinear(Integrator integrator, int max_steps) {
  using Real = mpfr_50;
  using std::abs;
  using std::sin;
  nonlinear_stiff<Real> sys{Real(-1e10)};
  auto f = [&](const std::array<Real, 2>& y, std::array<Real, 2>& d) { return sys(y, d); };
  auto jacobian = [&](const std::array<Real, 2>& y, std::array<std::array<Real, 2>, 2>& J) { sys(y, J); };
  std::array<Real, 2> y{Real(0), Real(0)};
  Real h = Real(1) / 16, taken = 0;
  int steps = 0;
  while (y[0] < 2) {
    if (y[0] + h > 2) h = 2 - y[0];
    const std::array<Real, 2> scales{Real(1), Real(1)};
    ++steps;
    ASSERT_LT(steps, max_steps);
    if constexpr (requires { integrator.try_step(f, jacobian, y, h, scales, taken); })
      integrator.try_step(f, jacobian, y, h, scales, taken);
    else
      integrator.step(f, jacobian, y, h, scales, taken);
  }
  EXPECT_LE(abs(y[1] - sin(y[0])), Real("1e-46")) << to_decimal_string(Real(y[1] - sin(y[0])));
}

TEST(stiff_integrators, follow_a_nonlinear_stiff_problem_at_50_digits) {
  follow_nonlinear(radau_integrator<mpfr_50, 2>(17, mpfr_50("1e-49")), 400);
  follow_nonlinear(lobatto_integrator<mpfr_50, 2>(19, mpfr_50("1e-49")), 400);
}
#endif

}  // namespace
