// The clamped impact (force max(0, f), impact/clamped_impact.hpp) against truths
// from other methods: the linear law's closed form (exact/exact_linear_clamped.hpp)
// and, for the Hertz-type laws, Boost.Odeint's Runge-Kutta-Fehlberg 7(8) in long
// double written here (a different method, code and precision from the GBS solver).
#include <viscor/exact/exact_linear_clamped.hpp>
#include <viscor/impact/clamped_impact.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <boost/numeric/odeint.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numeric>

namespace {

using viscor::clamped_impact_result;
using viscor::impact_outcome;

// RKF78 reference for a law (alpha, beta) with alpha >= beta: the first contact
// phase in s = tau^(1/q) up to tau = 1/2 (u is analytic in s there), then tau;
// the switch located by re-stepping the step with a fixed RKF78 step and bisection.
struct rkf_reference {
  long double e = 0;
  bool sticks = false;
  int contact_phases = 0;
};

rkf_reference rkf_clamped(long double alpha, long double beta, int q, long double gamma, long double g) {
  using state = std::array<long double, 2>;
  namespace ode = boost::numeric::odeint;
  const long double gb = gamma * beta, p = alpha - beta + 1;
  bool in_s = true;
  auto rhs = [&](const state& y, state& dy, long double t) {
    const long double u = y[0] > 0 ? y[0] : 0.0L;
    const long double a = g - std::pow(u, alpha) - gb * std::pow(u, beta - 1) * y[1];
    const long double jac = in_s ? q * std::pow(t, static_cast<long double>(q - 1)) : 1.0L;
    dy[0] = jac * y[1];
    dy[1] = jac * a;
  };
  auto h_of = [&](const state& y) { return std::pow(y[0] > 0 ? y[0] : 0.0L, p) + gb * y[1]; };
  auto energy = [&](const state& y) {
    return y[1] * y[1] / 2 + std::pow(y[0], alpha + 1) / (alpha + 1) - g * y[0];
  };
  ode::runge_kutta_fehlberg78<state, long double> stepper;
  auto controlled = ode::make_controlled<ode::runge_kutta_fehlberg78<state, long double>>(1e-17L, 1e-17L);
  rkf_reference r;
  state y{0, 1};
  long double t = 0;
  const long double s_end = std::pow(0.5L, 1.0L / q);
  while (true) {
    ++r.contact_phases;
    long double dt = in_s ? s_end / 64 : 1.0L / 64;
    while (true) {
      if (in_s && t + dt > s_end) dt = s_end - t;
      const state y0 = y;
      const long double t0 = t;
      if (controlled.try_step(rhs, y, t, dt) != ode::success) continue;
      if (h_of(y) > 0) {
        if (energy(y) < 0) {
          r.sticks = true;
          return r;
        }
        if (in_s && t >= s_end) t = 0.5L, in_s = false, dt = 1.0L / 64;
        continue;
      }
      long double lo = 0, hi = t - t0;  // h > 0 at lo, <= 0 at hi
      for (int i = 0; i < 80; ++i) {
        const long double mid = (lo + hi) / 2;
        state out;
        stepper.do_step(rhs, y0, t0, out, mid);
        (h_of(out) > 0 ? lo : hi) = mid;
      }
      stepper.do_step(rhs, y0, t0, y, (lo + hi) / 2);
      t = in_s ? std::pow(t0 + (lo + hi) / 2, static_cast<long double>(q)) : t0 + (lo + hi) / 2;
      in_s = false;
      break;
    }
    const long double u = y[0], v = y[1];
    if (!(g > 0) || v * v > 2 * g * u) {
      r.e = std::sqrt(v * v - 2 * g * u);
      return r;
    }
    // Falls back: bisect h along the parabola between a point where h < 0 and the apex.
    auto h_flight = [&](long double s) {
      return h_of(state{u + s * (v + g * s / 2), v + g * s});
    };
    long double hi = -v / g, lo = hi;
    while (h_flight(lo) >= 0 && lo > 1e-40L) lo /= 2;
    for (int i = 0; i < 100; ++i) {
      const long double mid = (lo + hi) / 2;
      (h_flight(mid) < 0 ? lo : hi) = mid;
    }
    const long double s = (lo + hi) / 2;
    y = {u + s * (v + g * s / 2), v + g * s};
    t += s;
    if (energy(y) < 0) {
      r.sticks = true;
      return r;
    }
  }
}

TEST(ClampedImpact, LinearMatchesClosedFormOnAGrid) {
  const auto law = viscor::law_by_name("linear");
  int resumed = 0, stuck = 0, rebounds = 0;
  // gamma = 1.75, g = 0.05 and gamma = 2, g = 0.04: the bead falls back after the
  // switch and the contact resumes (then sticks: every resumption found by a scan
  // of gamma in [0.1, 4], g in [0, 3] ended in a stick).
  for (double gamma : {0.01, 0.1, 0.3, 0.7, 1.0, 1.5, 1.75, 1.99, 2.0, 2.5, 4.0}) {
    for (double g : {-0.3, 0.0, 0.001, 0.04, 0.05, 0.2, 0.5, 1.0, 2.0, 5.0}) {  // g < 0: a pulling load
      const auto exact = viscor::exact_linear_clamped<long double>(gamma, g);
      const auto solved = viscor::solve_clamped_impact<double>(law, gamma, g);
      SCOPED_TRACE("gamma = " + std::to_string(gamma) + ", g = " + std::to_string(g));
      EXPECT_EQ(solved.outcome == impact_outcome::stick, exact.sticks);
      EXPECT_NEAR(solved.e, static_cast<double>(exact.e), 1e-12);
      if (!exact.sticks) EXPECT_EQ(solved.contact_phases, exact.contact_phases);
      resumed += exact.contact_phases > 1;
      stuck += exact.sticks;
      rebounds += !exact.sticks;
    }
  }
  // The grid must exercise every branch: rebounds, sticks and resumed contacts.
  EXPECT_GT(rebounds, 20);
  EXPECT_GT(stuck, 2);
  EXPECT_GT(resumed, 0);
}

TEST(ClampedImpact, LinearLongDoubleMatchesClosedForm) {
  const auto law = viscor::law_by_name("linear");
  for (long double gamma : {0.2L, 1.3L, 3.0L})
    for (long double g : {0.0L, 0.1L, 0.8L}) {
      const auto exact = viscor::exact_linear_clamped<long double>(gamma, g);
      const auto solved = viscor::solve_clamped_impact<long double>(law, gamma, g);
      EXPECT_NEAR(static_cast<double>(solved.e), static_cast<double>(exact.e), 1e-14) << gamma << " " << g;
    }
}

TEST(ClampedImpact, HertzTypeLawsMatchAnIndependentIntegrator) {
  struct law_case { const char* name; long double alpha, beta; int q; };
  for (const law_case c : {law_case{"tsuji", 1.5L, 1.25L, 4}, law_case{"hertz_linear_damping", 1.5L, 1.0L, 2},
                           law_case{"kuwabara_kono", 1.5L, 1.5L, 2}}) {
    const auto law = viscor::law_by_name(c.name);
    for (double gamma : {0.05, 0.3, 1.0, 2.5})
      for (double g : {-0.2, 0.0, 0.02, 0.3, 1.5}) {
        SCOPED_TRACE(std::string(c.name) + " gamma = " + std::to_string(gamma) + ", g = " + std::to_string(g));
        const rkf_reference ref = rkf_clamped(c.alpha, c.beta, c.q, gamma, g);
        const auto d = viscor::solve_clamped_impact<double>(law, gamma, g);
        const auto ld = viscor::solve_clamped_impact<long double>(law, (long double)gamma, (long double)g);
        EXPECT_EQ(d.outcome == impact_outcome::stick, ref.sticks);
        EXPECT_NEAR(d.e, static_cast<double>(ref.e), 1e-12);
        EXPECT_NEAR(static_cast<double>(ld.e), static_cast<double>(ref.e), 1e-13);
        if (!ref.sticks) EXPECT_EQ(d.contact_phases, ref.contact_phases);
      }
  }
}

TEST(ClampedImpact, ClampingRaisesEAboveTheUnclampedLaw) {
  // The clamp removes only pulling forces, which slow the outgoing bead.
  for (const char* name : {"linear", "tsuji"}) {
    const auto law = viscor::law_by_name(name);
    for (double gamma : {0.1, 0.5})
      for (double g : {0.0, 0.2}) {
        const auto clamped = viscor::solve_clamped_impact<double>(law, gamma, g);
        const auto free = viscor::solve_impact<double>(law, gamma, g);
        EXPECT_GT(clamped.e, free.e + 1e-6) << name << " " << gamma << " " << g;
        EXPECT_GT(clamped.first_release_time, 0.0);
      }
  }
}

TEST(ClampedImpact, ElasticAndBadInput) {
  EXPECT_EQ(viscor::solve_clamped_impact<double>(viscor::law_by_name("tsuji"), 0.0, 0.5).e, 1.0);
  EXPECT_THROW(viscor::solve_clamped_impact<double>(viscor::law_by_name("hunt_crossley"), 0.1, 0.0),
               viscor::invalid_parameter);
  EXPECT_THROW(viscor::solve_clamped_impact<double>(viscor::law_by_name("tsuji"), -0.1, 0.0),
               viscor::invalid_parameter);
}

}  // namespace
