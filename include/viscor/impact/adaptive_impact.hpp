// The impact problem solved by the GBS integrator (adaptive_integrator.hpp):
// viscor's second, independent method, with its own phase logic and event location.
//
// Formulation (endpoint-regularised, shared with the Taylor method because the
// exact solutions validate it): for rational alpha = p1/q1, beta = p2/q2 and
// Q = lcm(q1, q2), v = u^(1/Q) makes every power of u an integer power of v.
//  * Near u = 0, while u is monotone, v = s is the independent variable
//    (report eq. (4) divided by u' = ds/dtau * Q s^(Q-1)):
//        dtau/ds = Q s^(Q-1)/u',  dw/ds = (g - s^(Q alpha)) dtau/ds,  u' = w - gamma s^(Q beta),
//    analytic at s = 0 while u' != 0: contact starts at s = 0 and ends exactly at s = 0.
//  * Around maximal compression (u' = 0) tau is the independent variable with
//    state v: v' = u'/(Q v^(Q-1)), w' = g - v^(Q alpha), analytic while v > 0.
//  * The dissipated energy (eq. 6) rides along as Dt = int u'^2 u^(beta-1) dtau
//    (dDt/ds = Q u' s^(Q beta - 1)), so 1 - e^2 = 2 gamma beta Dt and
//    1 - e = 2 gamma beta Dt/(1 + e) keep full relative precision as gamma -> 0.
// The modes switch on r = u |u''|/u'^2, the ratio of how near the tau-mode
// singularity (u = 0) and the s-mode singularity (u' = 0) are: s -> tau when r > 1/2,
// tau -> s (on the way out) when r < 1/8.
//
// Events: sign changes of u' are detected on the nodes of the finest midpoint
// column of each tau step and located by Newton's method on the step length,
// each iterate a fixed-order GBS step from the step's start. Sticking: u' = 0 again
// with u > 0 after maximal compression (e = 0, contact_time = that time); the
// energy E = u'^2/2 + u^(alpha+1)/(alpha+1) - g u never increases and equals
// e^2/2 at u = 0, so E < 0 proves sticking and sqrt(2E) bounds e; creeping into
// the equilibrium u* = g^(1/alpha) without turning back gives contact_time = +inf.
//
// Exponents that are not such rationals (or need Q > max_regularising_denominator)
// use Q = 1 and real powers: u^alpha is then not analytic at u = 0, the error
// estimates near the end points lose their asymptotic footing and fewer digits
// come out; error_estimate still reports what the steps measured.
//
// Precision: GBS extrapolation amplifies rounding (adaptive_integrator.hpp), so the
// solve runs in detail::gbs_work<Real> (guard digits) and rounds the result to Real.
#pragma once

#include <viscor/ode/adaptive_integrator.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/widen.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

namespace viscor {

namespace detail {

/// Largest Q = lcm(q1, q2) for which the integer-power formulation is used.
inline constexpr std::int64_t max_regularising_denominator = 360;

/// result = x^n (n >= 0) by binary powering; `base` is scratch (no allocation
/// when both are reused, which matters for mpfr in the right-hand side).
template <class Real>
void integer_power(const Real& x, std::int64_t n, Real& result, Real& base) {
  result = 1;
  base = x;
  for (; n > 0; n >>= 1) {
    if (n & 1) result *= base;
    if (n > 1) base *= base;
  }
}

/// The contact law's powers of v = u^(1/Q), in the work type.
template <class W>
struct regularised_law {
  bool rational = false;
  std::int64_t Q = 1, Qa = 1, Qb = 1;  // Q, Q alpha, Q beta (rational case)
  W alpha, beta, gamma, g, gamma_beta, inv_alpha_plus_one;

  // NOTE: cost. eval runs once per right-hand side, i.e. hundreds of times per GBS
  // step. The powers the right-hand sides read, v^(Q-1), v^Q, v^(Q alpha),
  // v^(Q beta - Q), v^(Q beta) and v^(Q beta - 1), share one table v^0..v^M: v^k is
  // (v^(k/2))^2 for even k and v^(k-1) v for odd k, computed only when needed
  // (Kuwabara-Kono: 2 operations, Tsuji: 5, instead of 7 and 13 by separate binary
  // powering). Exponents above max_table fall back to binary powering per power.
  static constexpr std::int64_t max_table = 24;
  enum slot { s_vq1, s_u, s_ua, s_ub1, s_ub, s_diss, s_count };
  std::array<std::int64_t, s_count> exponent_of{};  // rational case: the power of v in each slot
  std::vector<unsigned char> needed;                 // needed[k]: v^k is computed (table case)
  bool table = false;

  regularised_law(const contact_law& law, const W& gamma_, const W& g_) : gamma(gamma_), g(g_) {
    if (law.alpha.is_rational() && law.beta.is_rational()) {
      const std::int64_t q1 = law.alpha.denominator(), q2 = law.beta.denominator();
      const std::int64_t q = std::lcm(q1, q2);
      if (q <= max_regularising_denominator) {
        rational = true;
        Q = q;
        Qa = law.alpha.numerator() * (q / q1);
        Qb = law.beta.numerator() * (q / q2);
      }
    }
    alpha = law.alpha.template value<W>();
    beta = law.beta.template value<W>();
    gamma_beta = gamma * beta;
    inv_alpha_plus_one = 1 / (alpha + 1);
    if (rational) {
      // alpha, beta >= 1 (contact_law::validate): every exponent is >= 0.
      exponent_of = {Q - 1, Q, Qa, Qb - Q, Qb, Qb - 1};
      const std::int64_t top = *std::max_element(exponent_of.begin(), exponent_of.end());
      table = top <= max_table;
      if (table) {
        needed.assign(static_cast<std::size_t>(top) + 1, 0);
        for (std::int64_t e : exponent_of) needed[static_cast<std::size_t>(e)] = 1;
        for (std::int64_t k = top; k > 1; --k)
          if (needed[static_cast<std::size_t>(k)]) needed[static_cast<std::size_t>(k % 2 == 0 ? k / 2 : k - 1)] = 1;
      }
    }
  }

  /// v^(Q-1), u = v^Q, u^alpha, u^beta, u^(beta-1) and v^(Q beta - 1) for v >= 0,
  /// read through the accessors after regularised_law::eval.
  struct powers {
    const W& vq1() const { return *slots[s_vq1]; }
    const W& u() const { return *slots[s_u]; }
    const W& ua() const { return *slots[s_ua]; }
    const W& ub() const { return *slots[s_ub]; }
    const W& ub1() const { return *slots[s_ub1]; }
    const W& diss() const { return *slots[s_diss]; }

    powers() = default;
    powers(const powers&) = delete;  // slots point into the own table
    powers& operator=(const powers&) = delete;

    std::vector<W> v;  // v[k] = v^k (table case) or the slots' own values
    std::array<const W*, s_count> slots{};
    W scratch;
  };

  void eval(const W& x, powers& p) const {
    using std::pow;
    if (rational && table) {
      if (p.v.size() != needed.size()) {
        p.v.assign(needed.size(), W(0));
        p.v[0] = 1;
      }
      if (needed.size() > 1) p.v[1] = x;
      for (std::size_t k = 2; k < needed.size(); ++k) {
        if (!needed[k]) continue;
        if (k % 2 == 0)
          p.v[k] = p.v[k / 2] * p.v[k / 2];
        else
          p.v[k] = p.v[k - 1] * x;
      }
      for (int i = 0; i < s_count; ++i) p.slots[i] = &p.v[static_cast<std::size_t>(exponent_of[i])];
      return;
    }
    if (p.v.size() != s_count) p.v.assign(s_count, W(0));
    for (int i = 0; i < s_count; ++i) p.slots[i] = &p.v[i];
    if (rational) {
      for (int i = 0; i < s_count; ++i) integer_power(x, exponent_of[i], p.v[i], p.scratch);
    } else {
      p.v[s_vq1] = 1;
      p.v[s_u] = x;
      p.v[s_ua] = pow(x, alpha);
      p.v[s_ub1] = pow(x, beta - 1);
      p.v[s_ub] = p.v[s_ub1] * x;
      p.v[s_diss] = p.v[s_ub1];  // Q = 1: s^(Q beta - 1) = u^(beta-1)
    }
  }
  /// x *= Q in place (an exponent shift when Q is a power of two, as for every named law).
  void times_Q(W& x) const {
    using std::ldexp;
    if (Q == 1) return;
    if ((Q & (Q - 1)) == 0) {
      int shift = 0;
      while ((std::int64_t{1} << shift) < Q) ++shift;
      x = ldexp(x, shift);
    } else {
      x *= Q;
    }
  }
  /// s^(Q beta - 1) (the s-mode dissipation integrand's power).
  const W& s_power_for_dissipation(const powers& p) const { return p.diss(); }
  /// Energy u'^2/2 + u^(alpha+1)/(alpha+1) - g u.
  W energy(const W& du, const powers& p) const {
    return du * du / 2 + p.ua() * p.u() * inv_alpha_plus_one - g * p.u();
  }
  /// u |u''| with u'' = g - u^alpha - gamma beta u^(beta-1) u'.
  W u_times_abs_acceleration(const W& du, const powers& p) const {
    using std::abs;
    return abs(p.u() * (g - p.ua()) - gamma_beta * p.ub() * du);
  }
};

template <class W>
using impact_state = std::array<W, 3>;

/// The adaptive solve in the work type W. eps_e: absolute tolerance on e (Real's epsilon).
template <class W>
class adaptive_impact_solver {
 public:
  adaptive_impact_solver(const contact_law& law, const W& gamma, const W& g, const W& rtol, const W& eps_e,
                         std::size_t max_steps, int max_columns, std::string where)
      : m_law(law, gamma, g),
        m_rtol(rtol),
        m_eps_e(eps_e),
        m_max_steps(max_steps),
        m_s_int(rtol, impact_state<W>{W(0), rtol, W(0)}, max_columns),
        m_t_int(rtol, impact_state<W>{W(0), rtol, W(0)}, max_columns),
        m_where(std::move(where)) {
    m_s_int.set_keep_nodes(false);  // s steps cannot cross u' = 0: no events to detect
    m_t_int.set_autonomous(true);   // t_rhs does not read tau
    m_s_int.set_read_components(2);  // s_rhs and t_rhs never read Dt
    m_t_int.set_read_components(2);
  }

  struct raw_result {
    W e_w = 0, dt = 0, contact_time = 0, max_compression = 0, time_of_max = 0, error = 0;
    impact_outcome outcome = impact_outcome::rebound;
    bool creep = false;
    std::size_t steps = 0;
  };

  raw_result solve() {
    using std::abs;
    using std::pow;
    using std::sqrt;
    raw_result r;
    const W inf = std::numeric_limits<W>::infinity();
    // ---- compression in s: s from 0 up, state (tau, w, Dt)
    W s = 0;
    impact_state<W> y{W(0), W(1), W(0)};
    // NOTE: Dt ~ s^(Q beta) near s = 0, and a pure power of degree above the
    // extrapolation order has a step-size-independent relative error: start from the
    // series then (and always for real exponents).
    // The order that counts is the one GBS starts at (it only climbs on accepted
    // steps), not the most it may use: with a wider cap the start could stall.
    if (!m_law.rational || m_law.Qb + m_law.Q > 2 * m_s_int.columns() - 2) start_by_series(s, y);
    const W scale = 1 + abs(m_law.g) + m_law.gamma;
    W h = pow(scale, -W(1) / W(m_law.Q)) / 8;
    auto rhs_s_up = [this](const W& s_, const impact_state<W>& y_, impact_state<W>& d) { return s_rhs(s_, y_, d, 1); };
    for (;;) {
      step_guard(h, s);
      const gbs_status st = m_s_int.try_step(rhs_s_up, s, y, h);
      if (st != gbs_status::accepted) continue;
      accumulate_error(m_s_int);
      if (switch_to_tau(s, y[1])) break;
    }
    // ---- tau mode, state (v, w, Dt)
    W tau = y[0];
    impact_state<W> z{s, y[1], y[2]};
    bool compressed = false, energy_stuck = false;
    auto rhs_t = [this](const W& t_, const impact_state<W>& z_, impact_state<W>& d) { return t_rhs(t_, z_, d); };
    h = initial_tau_step(z);
    for (;;) {
      // tau mode until the bead turns around twice (stick), creeps, or nears u = 0 on the way out.
      for (;;) {
        const W tau0 = tau;
        const impact_state<W> z0 = z;
        step_guard(h, tau);
        const gbs_status st = m_t_int.try_step(rhs_t, tau, z, h);
        if (st != gbs_status::accepted) continue;
        if (!(z[0] > 0)) {
          // NOTE: with integer exponents the stages may all stay in u > 0 while the
          // extrapolated end crosses u = 0: retry shorter (the s mode takes over).
          h = (tau - tau0) / 4;
          tau = tau0, z = z0;
          continue;
        }
        accumulate_error(m_t_int);
        // Sign changes of u' on the step's nodes (the last replaced by the accurate
        // end state): maximal compression (+ to -), turning back (- to +).
        const auto& nodes = m_t_int.nodes();
        m_du_nodes.resize(nodes.size());
        for (std::size_t m = 0; m + 1 < nodes.size(); ++m) m_du_nodes[m] = du_of(nodes[m]);
        m_du_nodes.back() = du_of(z);
        for (std::size_t m = 1; m < nodes.size(); ++m) {
          const W& du_prev = m_du_nodes[m - 1];
          const W& du_next = m_du_nodes[m];
          if (!compressed && du_prev > 0 && du_next <= 0) {
            impact_state<W> at;
            r.time_of_max = locate_turning_point(tau0, z0, m, at);
            typename regularised_law<W>::powers p;
            m_law.eval(at[0], p);
            r.max_compression = p.u();
            compressed = true;
          } else if (compressed && du_prev < 0 && du_next >= 0) {
            impact_state<W> at;
            r.contact_time = locate_turning_point(tau0, z0, m, at);
            r.outcome = impact_outcome::stick;
            r.steps = m_steps;
            return r;
          }
        }
        typename regularised_law<W>::powers p;
        m_law.eval(z[0], p);
        const W du = z[1] - m_law.gamma * p.ub();
        if (!compressed) {
          if (m_law.g > 0 && creeps_to_equilibrium(z[0], du)) {
            r.outcome = impact_outcome::stick, r.creep = true;
            r.max_compression = pow(m_law.g, 1 / m_law.alpha);
            r.time_of_max = inf, r.contact_time = inf, r.steps = m_steps;
            return r;
          }
          continue;
        }
        const W energy = m_law.energy(du, p);
        if (m_law.g >= 0 && 2 * energy <= m_eps_e * m_eps_e) {
          // e <= sqrt(2E) is below the tolerance: e = 0. With g = 0 the bead cannot
          // turn back (u'' = -u^alpha < 0 at u' = 0), it creeps into u = 0.
          if (m_law.g == 0 || energy < 0) energy_stuck = true;
          if (m_law.g == 0) {
            r.outcome = impact_outcome::stick, r.creep = true, r.contact_time = inf, r.steps = m_steps;
            r.error = sqrt(2 * abs(energy));
            return r;
          }
        }
        if (energy_stuck && m_law.g > 0 && creeps_to_equilibrium(z[0], du)) {
          r.outcome = impact_outcome::stick, r.creep = true, r.contact_time = inf, r.steps = m_steps;
          return r;
        }
        if (!energy_stuck && du < 0 && m_law.u_times_abs_acceleration(du, p) * 8 < du * du) break;
      }
      // ---- the way out in s: s from v down to 0, state (tau, w, Dt)
      s = z[0];
      y = {tau, z[1], z[2]};
      // NOTE: s/4 was rejected at both benchmark points (the accepted step was 3.5x
      // shorter); a rejection costs a whole step, a short first step half of one.
      h = -s / 8;
      auto rhs_s_down = [this](const W& s_, const impact_state<W>& y_, impact_state<W>& d) {
        return s_rhs(s_, y_, d, -1);
      };
      bool back_to_tau = false;
      W s_end = m_law.rational ? W(0) : series_end_point(y[1]);
      for (;;) {
        if (-h > s - s_end) h = s_end - s;
        step_guard(h, s);
        const gbs_status st = m_s_int.try_step(rhs_s_down, s, y, h);
        if (st != gbs_status::accepted) continue;
        accumulate_error(m_s_int);
        if (!m_law.rational) s_end = series_end_point(y[1]);
        if (s <= s_end) {
          if (!m_law.rational) finish_by_series(s, y);
          r.e_w = -y[1], r.dt = y[2], r.contact_time = y[0], r.steps = m_steps;
          return r;
        }
        if (switch_to_tau(s, y[1])) {
          back_to_tau = true;
          break;
        }
      }
      if (back_to_tau) {
        // NOTE: the 4x hysteresis between the switching ratios prevents ping-pong;
        // this guard keeps a pathological case from spinning through the budget.
        if (++m_switches > 64)
          throw convergence_error("solve_impact_adaptive: no progress between the s and tau modes for " + m_where);
        tau = y[0];
        z = {s, y[1], y[2]};
        h = initial_tau_step(z);
      }
    }
  }

 private:
  // NOTE: real (non-rational) exponents, u = s: u^alpha is not analytic at u = 0,
  // so the first and last stretch [0, u_eps] use the generalized series of the
  // solution in powers u, u^beta, u^(alpha+1) to first order. With every first-order
  // term x in {g u/w^2, gamma u^beta/w, u^(alpha+1)/w^2} kept below sqrt(tol)/4, the
  // neglected products of two of them are below tol/16 relative.
  W series_limit(const W& w_abs) const {
    using std::abs;
    using std::pow;
    using std::sqrt;
    const W small = sqrt(m_rtol) / 4;
    W u = pow(small * w_abs * w_abs, 1 / (m_law.alpha + 1));
    if (m_law.g != 0) {
      const W by_load = small * w_abs * w_abs / abs(m_law.g);
      if (by_load < u) u = by_load;
    }
    if (m_law.gamma > 0) {
      const W by_damping = pow(small * w_abs / m_law.gamma, 1 / m_law.beta);
      if (by_damping < u) u = by_damping;
    }
    return u;
  }
  // Contact start (w = 1 at u = 0): tau, w, Dt at u = u_eps, s = u_eps^(1/Q).
  void start_by_series(W& s, impact_state<W>& y) const {
    using std::pow;
    const W& a = m_law.alpha;
    const W& b = m_law.beta;
    typename regularised_law<W>::powers p;
    s = m_law.Q == 1 ? series_limit(W(1)) : W(pow(series_limit(W(1)), W(1) / W(m_law.Q)));
    m_law.eval(s, p);
    const W u = p.u();
    const W ua1 = p.ua() * u, ub = p.ub();
    y[0] = u - m_law.g * u * u / 2 + m_law.gamma * ub * u / (b + 1) + ua1 * u / ((a + 1) * (a + 2));
    y[1] = 1 + m_law.g * u - ua1 / (a + 1);
    y[2] = ub / b + m_law.g * ub * u / (b + 1) - m_law.gamma * ub * ub / (2 * b) - ua1 * ub / ((a + 1) * (a + b + 1));
  }
  // Where the way out may hand over to the series (w ~ u' there).
  W series_end_point(const W& w) const {
    using std::abs;
    return series_limit(W(abs(w)));
  }
  // Contact end: from (tau, w, Dt) at u = s to u = 0, where w0 = u' = -e.
  void finish_by_series(const W& u, impact_state<W>& y) const {
    using std::pow;
    const W& a = m_law.alpha;
    const W& b = m_law.beta;
    const W ua1 = pow(u, a + 1), ub = pow(u, b);
    const W c = m_law.g * u - ua1 / (a + 1);  // w(u) = w0 + c/w0 + ...
    const W w0 = y[1] - c / y[1];
    const W w0_2 = w0 * w0;
    y[0] -= (u - (m_law.g * u * u / 2 - ua1 * u / ((a + 1) * (a + 2))) / w0_2 + m_law.gamma * ub * u / ((b + 1) * w0)) / w0;
    y[2] += -w0 * ub / b - (m_law.g * ub * u / (b + 1) - ua1 * ub / ((a + 1) * (a + b + 1))) / w0 +
            m_law.gamma * ub * ub / (2 * b);
    y[1] = w0;
  }

  // s-mode right-hand side; direction +1 on the way in (u' > 0), -1 on the way out.
  bool s_rhs(const W& s, const impact_state<W>& y, impact_state<W>& d, int direction) {
    if (s < 0) return false;
    // NOTE: written as in-place single operations (no fused multiply-adds, no
    // expression temporaries); runs hundreds of times per step.
    m_law.eval(s, m_p);
    m_tmp = m_law.gamma * m_p.ub();
    m_du = y[1] - m_tmp;
    if (direction > 0 ? !(m_du > 0) : !(m_du < 0)) return false;
    d[0] = m_p.vq1();
    m_law.times_Q(d[0]);
    d[0] /= m_du;  // dtau/ds = Q s^(Q-1) / u'
    d[1] = m_law.g - m_p.ua();
    d[1] *= d[0];
    d[2] = m_du * m_law.s_power_for_dissipation(m_p);
    m_law.times_Q(d[2]);
    return true;
  }

  // tau-mode right-hand side on (v, w, Dt).
  bool t_rhs(const W&, const impact_state<W>& z, impact_state<W>& d) {
    if (!(z[0] > 0)) return false;
    m_law.eval(z[0], m_p);
    m_tmp = m_law.gamma * m_p.ub();
    m_du = z[1] - m_tmp;
    m_tmp = m_p.vq1();
    m_law.times_Q(m_tmp);
    d[0] = m_du / m_tmp;  // v' = u' / (Q v^(Q-1))
    d[1] = m_law.g - m_p.ua();
    d[2] = m_du * m_du;
    d[2] *= m_p.ub1();
    return true;
  }

  W du_of(const impact_state<W>& z) {
    m_law.eval(z[0], m_p);
    return z[1] - m_law.gamma * m_p.ub();
  }

  // s -> tau when u |u''| > u'^2/2 (or u' is no longer safely away from 0).
  bool switch_to_tau(const W& s, const W& w) {
    typename regularised_law<W>::powers p;
    m_law.eval(s, p);
    const W du = w - m_law.gamma * p.ub();
    return 2 * m_law.u_times_abs_acceleration(du, p) > du * du;
  }

  W initial_tau_step(const impact_state<W>& z) {
    using std::abs;
    typename regularised_law<W>::powers p;
    m_law.eval(z[0], p);
    const W du = z[1] - m_law.gamma * p.ub();
    // NOTE: u/(4|u'|) capped at 1/4 was rejected at both benchmark points (2x too long).
    W h = p.u() / (8 * abs(du));
    const W cap = W(1) / 8;
    if (!(h < cap)) h = cap;
    return h;
  }

  void step_guard(const W& h, const W& t) {
    using std::abs;
    using std::max;
    if (++m_steps > m_max_steps)
      throw convergence_error("solve_impact_adaptive: step budget of " + std::to_string(m_max_steps) +
                              " exhausted for " + m_where);
    if (!(abs(h) > 64 * epsilon<W>() * max(abs(t), W(epsilon<W>()))))
      throw convergence_error("solve_impact_adaptive: step size underflow at t = " + to_decimal_string(t, 20) +
                              " for " + m_where);
  }

  void accumulate_error(const gbs_integrator<W, 3>& integ) { m_error += integ.last_error_vector()[1]; }

  // Newton on the step length for u' = 0 between nodes m-1 and m of the last tau step.
  W locate_turning_point(const W& tau0, const impact_state<W>& z0, std::size_t m, impact_state<W>& at) {
    using std::abs;
    using std::sqrt;
    auto rhs_t = [this](const W& t_, const impact_state<W>& z_, impact_state<W>& d) { return t_rhs(t_, z_, d); };
    const auto& times = m_t_int.node_times();
    const int columns = m_t_int.last_columns();
    const W H = times.back() - tau0;
    const W a = times[m - 1] - tau0, b = times[m] - tau0;
    const W fa = m_du_nodes[m - 1], fb = m_du_nodes[m];
    W h = (fa == fb) ? W((a + b) / 2) : W(a + (b - a) * fa / (fa - fb));
    // NOTE: Newton converges quadratically until rounding noise in the fixed step
    // dominates; then the corrections stop shrinking and the best iterate is kept.
    // Each iterate costs a whole GBS step, so it stops as soon as the correction
    // delta is below sqrt(eps)/16 of the time scale: the next iterate is then right
    // to O(delta^2) (quadratic convergence), and the state is taken where it was
    // computed, at distance delta from the root, where u' = O(delta) and u is off by
    // O(u'' delta^2) <= eps/256 relative: no further step is needed for either.
    const int budget = 4 * binary_digits<W>() + 20;
    const W sqrt_eps = sqrt(epsilon<W>());
    // NOTE: where u'' is tiny at the root (a turn back into a nearly critically
    // damped settling: linear law, gamma = 1.93, g = 87) u' is rounding noise over a
    // band of ~noise/|u''| and Newton wanders inside it with corrections far above
    // sqrt(eps); eight iterates without a smaller |u'| end the search at the best one.
    W best_h = h, best_du = -1, previous_delta = -1;
    int since_best = 0;
    for (int it = 0; it < budget; ++it) {
      if (!m_t_int.fixed_step(rhs_t, tau0, z0, h, columns, at))
        throw convergence_error("solve_impact_adaptive: event location left the domain for " + m_where);
      typename regularised_law<W>::powers p;
      m_law.eval(at[0], p);
      const W du = at[1] - m_law.gamma * p.ub();
      if (best_du < 0 || abs(du) < best_du) {
        best_du = abs(du), best_h = h, since_best = 0;
      } else if (++since_best >= 8) {
        h = best_h;
        m_t_int.fixed_step(rhs_t, tau0, z0, h, columns, at);
        return tau0 + h;
      }
      const W ddu = m_law.g - p.ua() - m_law.gamma_beta * p.ub1() * du;  // u''
      if (du == 0 || ddu == 0) return tau0 + h;
      W next = h - du / ddu;
      if (next < 0) next = h / 2;
      if (next > H) next = (h + H) / 2;
      const W delta = abs(next - h);
      const W scale = abs(tau0) + abs(h);
      if (delta <= sqrt_eps * scale / 16) return tau0 + next;
      const bool stalled = previous_delta >= 0 && delta >= previous_delta / 2 && delta <= sqrt_eps * scale;
      if (stalled) {
        h = best_h;
        m_t_int.fixed_step(rhs_t, tau0, z0, h, columns, at);
        return tau0 + h;
      }
      previous_delta = delta;
      h = next;
    }
    throw convergence_error("solve_impact_adaptive: turning point not located for " + m_where);
  }

  // Creeping into the equilibrium u* = g^(1/alpha) (g > 0) without turning back.
  // Trapping sector: with x = u - u*, Gamma the least damping gamma beta u^(beta-1)
  // and A the largest stiffness alpha u^(alpha-1) between u and u*, and Gamma^2 >= 4A,
  // the set {x u' <= 0, |u'| <= (Gamma/2)|x|} is invariant (on |u'| = kappa|x|,
  // d/dtau(u' + kappa x) has the sign of x (Gamma kappa - kappa^2 - A) >= 0; at u' = 0,
  // u'' = -(u^alpha - u*^alpha) points inside), so u' never vanishes again: contact_time = inf.
  bool creeps_to_equilibrium(const W& v, const W& du) {
    using std::abs;
    using std::pow;
    using std::sqrt;
    typename regularised_law<W>::powers p;
    m_law.eval(v, p);
    const W u_star = pow(m_law.g, 1 / m_law.alpha);
    const W x = p.u() - u_star;
    if (x == 0 || (x > 0) == (du > 0)) return x == 0 && du == 0;
    const W lower = x > 0 ? u_star : p.u(), upper = x > 0 ? p.u() : u_star;
    const W damping = m_law.gamma_beta * pow(lower, m_law.beta - 1);
    const W stiffness = m_law.alpha * pow(upper, m_law.alpha - 1);
    if (damping * damping >= 4 * stiffness && 2 * abs(du) <= damping * abs(x)) return true;
    // At rest to half the precision: no further turning point can be resolved.
    const W k = m_law.alpha * m_law.g / u_star;
    return abs(x) / u_star + abs(du) / (sqrt(k) * u_star) <= sqrt(epsilon<W>());
  }

  regularised_law<W> m_law;
  W m_rtol, m_eps_e;
  std::size_t m_max_steps, m_steps = 0;
  int m_switches = 0;
  gbs_integrator<W, 3> m_s_int, m_t_int;
  std::string m_where;
  typename regularised_law<W>::powers m_p;
  W m_du = 0, m_tmp = 0, m_error = 0;
  std::vector<W> m_du_nodes;

 public:
  const W& accumulated_error() const { return m_error; }
};

}  // namespace detail

namespace detail {

/// The adaptive solver's tolerance rules in one place. The requested tolerance on e is
/// at least Real's epsilon (0 asks for exactly that); evaluate at the caller's precision.
template <class Real>
Real clamped_tolerance(const solve_options<Real>& options) {
  const Real eps_real = epsilon<Real>();
  return options.tolerance > 0 && options.tolerance > eps_real ? options.tolerance : eps_real;
}

/// The tolerances of a solve in the work type W (at its working precision).
template <class W>
struct adaptive_tolerances {
  W rtol;            ///< local tolerance per step
  W eps_e;           ///< absolute tolerance on e
  bool floored;      ///< rtol was raised to the rounding floor of W
};

/// Local tolerance well below the target: an impact takes tens of steps, and
/// under a load g the speed reaches ~|g| while e ~ 1 is what remains of it, so
/// the tolerance shrinks with 1 + |g|; never below the extrapolation's rounding floor.
template <class W, class Real>
adaptive_tolerances<W> adaptive_tolerances_for(const Real& tolerance, const Real& g) {
  using std::abs;
  W rtol = widen<W>(tolerance) / (64 * (1 + abs(widen<W>(g))));
  const W rounding_floor = gbs_rounding_floor(rtol);
  const bool floored = rtol < rounding_floor;
  if (floored) rtol = rounding_floor;
  return {rtol, widen<W>(tolerance), floored};
}

template <class W, class Real>
impact_result<Real> solve_impact_adaptive_in(const contact_law& law, const Real& gamma, const Real& g,
                                             const Real& tolerance, std::size_t max_steps, int guard);

template <class Work, class = void>
struct has_wide_work : std::false_type {};
template <class Work>
struct has_wide_work<Work, std::enable_if_t<Work::has_wide>> : std::true_type {};

/// Whether the local tolerance falls under the rounding floor of the work type W
/// with `guard` digits (then the wide work type is used).
template <class Real, class W>
bool needs_wide_work(const Real& tolerance, const Real& g, int guard) {
  scoped_precision precision(decimal_digits<Real>() + guard);
  return adaptive_tolerances_for<W>(tolerance, g).floored;
}

}  // namespace detail

/// CoR by the adaptive GBS method (integration_method::adaptive); see the header
/// comment. Contact ends at zero overlap u = 0, as in the report.
template <class Real>
impact_result<Real> solve_impact_adaptive(const contact_law& law, const Real& gamma, const Real& g,
                                          const solve_options<Real>& options = {}) {
  impact_parameters<Real>{law, gamma, g}.validate();
  require_non_negative(options.tolerance, "tolerance");
  if (options.max_steps == 0) throw invalid_parameter("parameter max_steps must be > 0, got 0");
  const Real tolerance = detail::clamped_tolerance(options);
  using work = detail::gbs_work<Real>;
  if constexpr (detail::has_wide_work<work>::value) {
    if (detail::needs_wide_work<Real, typename work::type>(tolerance, g, work::guard_digits()))
      return detail::solve_impact_adaptive_in<typename work::wide_type>(law, gamma, g, tolerance, options.max_steps,
                                                                       work::wide_guard_digits());
  }
  return detail::solve_impact_adaptive_in<typename work::type>(law, gamma, g, tolerance, options.max_steps,
                                                              work::guard_digits());
}

namespace detail {

/// One solve in the work type W with `guard` digits beyond Real's, rounded back to Real.
template <class W, class Real>
impact_result<Real> solve_impact_adaptive_in(const contact_law& law, const Real& gamma, const Real& g,
                                             const Real& tolerance, std::size_t max_steps, int guard) {
  const int real_digits = decimal_digits<Real>();
  const std::string where = law.describe() + ", gamma = " + to_decimal_string(gamma) + ", g = " + to_decimal_string(g);
#if VISCOR_HAS_MPFR
  const unsigned caller_digits = std::is_same_v<Real, mpfr_real> ? mpfr_real::thread_default_precision() : 0u;
#else
  const unsigned caller_digits = 0;
#endif
  // NOTE: run-time mpfr work type: precision for the whole solve, restored on exit.
  scoped_precision work_precision(real_digits + guard);
  const W w_gamma = widen<W>(gamma), w_g = widen<W>(g);
  using std::abs;
  const int max_columns = gbs_max_columns(decimal_digits<W>(), guard);
  const adaptive_tolerances<W> tol = adaptive_tolerances_for<W>(tolerance, g);
  adaptive_impact_solver<W> solver(law, w_gamma, w_g, tol.rtol, tol.eps_e, max_steps, max_columns, where);
  const auto raw = solver.solve();

  impact_result<Real> r;
  r.method = integration_method::adaptive;
  r.outcome = raw.outcome;
  r.steps = raw.steps;
  r.contact_time = narrow<Real>(raw.contact_time, caller_digits);
  r.max_compression = narrow<Real>(raw.max_compression, caller_digits);
  r.time_of_max_compression = narrow<Real>(raw.time_of_max, caller_digits);
  W err = solver.accumulated_error() + raw.error + tol.eps_e;
  if (raw.outcome == impact_outcome::stick) {
    r.e = 0, r.one_minus_e = 1, r.energy_residual = 0;
  } else {
    const W beta = law.beta.template value<W>();
    const W dissipated = 2 * w_gamma * beta * raw.dt;  // 1 - e^2 by eq. (6)
    const W one_minus_e = dissipated / (1 + raw.e_w);
    const W residual = (1 - raw.e_w) * (1 + raw.e_w) - dissipated;
    // NOTE: e from the velocity when it is small (relative digits near sticking),
    // from the dissipated energy when near 1 (no cancellation as gamma -> 0).
    const bool small = raw.e_w < W(1) / 2;
    r.e = narrow<Real>(small ? raw.e_w : W(1 - one_minus_e), caller_digits);
    r.one_minus_e = narrow<Real>(small ? W(1 - raw.e_w) : one_minus_e, caller_digits);
    r.energy_residual = narrow<Real>(residual, caller_digits);
    err += abs(residual);
  }
  r.error_estimate = narrow<Real>(err, caller_digits);
  return r;
}

}  // namespace detail

}  // namespace viscor
