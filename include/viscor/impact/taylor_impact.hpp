// One impact, integrated by Taylor series to the working precision, with exact
// treatment of both ends of the contact (issue 3). The phases:
//
// 1. Start (u = 0, v = 1): the endpoint system in sigma (u = s^Q for rational
//    exponents, u = exp(sigma) otherwise; detail/impact_systems.hpp), forward
//    until v has fallen to half its peak, so that it stays far from the
//    turning point v = 0, where dtau/dsigma = J/v is singular.
// 2. Around maximal compression: tau as independent variable, u > 0 bounded
//    away from 0, so u^alpha, u^beta are analytic. Events on the step
//    polynomial: v = 0 (maximal compression), v = 0 again with u > 0 (the bead
//    sticks). Leaves for phase 3 as soon as the rest of the path provably keeps
//    v <= v1/2 < 0 down to u = 0: with V = -v, over [0, u1]
//        V(0) >= V1 - g+ u1 / min V - gamma u1^beta,
//    so 4 g+ u1 + 2 gamma u1^beta V1 <= V1^2 is enough.
// 2b. g = 0 and alpha + 1 = 2 beta (linear, Tsuji), underdamped: after maximal
//    compression, the scale-free spiral_system in ln u (impact_systems.hpp),
//    so that near critical damping, where the bead creeps back along a slow
//    spiral and e = exp(-pi xi/sqrt(1 - xi^2)) is tiny, e keeps its relative
//    digits; phase 3 then runs on the problem rescaled to u = 1.
// 3. End: the endpoint system backwards to u = 0 exactly (s = 0), or to a
//    tiny u_eps and the leading terms of the generalized series
//        v(u) = v0 + g u/v0 - gamma u^beta - u^(alpha+1)/((alpha+1) v0) + O(u^2)
//    (u_eps is chosen so that each retained term is below tol |v|, hence the
//    neglected ones below tol^2).
// Then e = -v(T_f), and 1 - e = D/(1 + e) from the dissipated energy
// D = 2 gamma beta int v^2 u^(beta-1) dtau (eq. 6), integrated along as a state,
// so 1 - e keeps full relative precision as gamma -> 0. Energy balance: with
// E = v^2/2 + u^(alpha+1)/(alpha+1) - g u, dE/dtau = -D', so 1 - 2E - D = 0 at
// every point of the path; its value at the end is energy_residual.
//
// Sticking (e = 0) is an outcome: v returns to 0 with u > 0 (an event), or the
// state enters a region it provably never leaves without reaching u = 0:
// * g = 0, after maximal compression, w = v + gamma u^beta > 0: the curve
//   w = c gamma u^beta is a barrier if u^(alpha+1-2 beta) <= c(1-c) gamma^2 beta
//   on (0, u] (possible when alpha + 1 >= 2 beta); the bead creeps into (0, 0)
//   (for alpha = beta = 1 this is exactly gamma >= 2).
// * g > 0, equilibrium u_eq = g^(1/alpha): the sector between v = 0 and
//   v = -+kappa (u - u_eq) traps the state when kappa^2 - Gamma kappa + A <= 0,
//   Gamma the least damping gamma beta u^(beta-1), A the largest stiffness
//   alpha u^(alpha-1) over the remaining range; the bead creeps to u_eq.
// * g > 0, the state equals u_eq up to rounding (at_rest): the turn, if any,
//   is below the working precision.
// All three report contact_time = +infinity; stop_overlap is the turning point
// u_s, or the rest position u_eq (0 for g = 0).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/impact/detail/impact_systems.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/ode/taylor_integrator.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace viscor {

namespace detail {

template <class Real>
class taylor_impact_solver {
  using ts = time_system<Real>;
  using es = endpoint_system<Real>;
  using ss = spiral_system<Real>;

 public:
  taylor_impact_solver(const contact_law& law, const Real& gamma, const Real& g, const solve_options<Real>& options)
      : m_law(law), m_options(options), m_c(make_impact_constants(law, gamma, g)) {
    m_tol = options.tolerance > 0 ? options.tolerance : epsilon<Real>();
    if (m_tol < epsilon<Real>()) m_tol = epsilon<Real>();
    const auto& c = m_c;
    if (c.alpha > 1) {
      using std::pow;
      m_u_growth = pow(Real(4), 1 / (c.alpha - 1));
    }
    if (law.alpha.is_rational() && law.beta.is_rational()) {
      // alpha + 1 = 2 beta, g = 0, underdamped: the spiral variables (impact_systems.hpp).
      const long p1 = law.alpha.numerator(), q1 = law.alpha.denominator();
      const long p2 = law.beta.numerator(), q2 = law.beta.denominator();
      m_spiral = g == 0 && gamma > 0 && (p1 + q1) * q2 == 2 * p2 * q1 &&
                 c.gamma_beta * c.gamma_beta < 4 * c.beta;
    }
  }

  impact_result<Real> solve() {
    using std::abs;
    es end_sys(m_c, taylor_order(m_tol), m_tol);
    ts time_sys(m_c, taylor_order(m_tol), m_tol);
    taylor_integrator<Real, es> end_int(end_sys, m_tol);
    taylor_integrator<Real, ts> time_int(time_sys, m_tol);
    m_result.method = integration_method::taylor;

    if (!start_phase(end_sys, end_int)) return finish();
    if (!time_phase(time_int)) return finish();
    if (m_in_spiral) {
      ss spiral_sys(m_c, taylor_order(m_tol));
      taylor_integrator<Real, ss> spiral_int(spiral_sys, m_tol);
      spiral_phase(spiral_int);
    }
    end_phase(end_int);
    return finish();
  }

 private:
  // ---- phase 1: from u = 0 until v has dropped to half its peak ----
  bool start_phase(es& sys, taylor_integrator<Real, es>& integ) {
    using std::log;
    using std::pow;
    const auto& c = m_c;
    std::vector<Real> x(3), x1(3);
    Real sigma;
    if (c.use_root_variable) {
      sigma = 0;
      x[es::v] = 1, x[es::tau] = 0, x[es::D] = 0;
    } else {
      const Real u = gap(Real(1));
      sigma = log(u);
      x[es::v] = 1 + c.g * u - c.gamma * pow(u, c.beta) - pow(u, c.alpha_plus_one) / c.alpha_plus_one;
      x[es::tau] = u;
      x[es::D] = c.two_gamma * pow(u, c.beta);
    }
    const Real u_scale = natural_scale();
    const Real sigma_scale = c.use_root_variable ? Real(pow(u_scale, Real(1) / Real(c.Q))) : Real(log(u_scale));
    Real v_peak = x[es::v];
    note_speed(v_peak);
    for (;;) {
      // Cap: at most double s (or add max(1, half the way to the natural scale) to ln u)
      // per step, for series so sparse that the Jorba-Zou estimate sees no terms.
      Real cap;
      if (c.use_root_variable) {
        cap = sigma > 0 ? sigma : Real(sigma_scale / 16);
      } else {
        cap = (sigma_scale - sigma) / 2;
        if (cap < 1) cap = 1;
      }
      Real h = integ.expand(sigma, x, cap);
      for (int tries = 0;; ++tries) {
        integ.values(x1, h);
        if (isfinite_(x1[es::v]) && x1[es::v] > x[es::v] / 4) break;
        h /= 2;
        check_tries(tries, "compression phase");
      }
      count_step();
      sigma += h;
      x.swap(x1);
      if (x[es::v] > v_peak) v_peak = x[es::v];
      note_speed(x[es::v]);
      if (x[es::v] < v_peak * m_switch_speed) break;
    }
    m_tau = x[es::tau];
    m_u = sys.u_of(sigma);
    m_v = x[es::v];
    m_D = x[es::D];
    return true;
  }

  // ---- phase 2: tau around maximal compression; false when the bead sticks ----
  bool time_phase(taylor_integrator<Real, ts>& integ) {
    using std::abs;
    using std::sqrt;
    std::vector<Real> y{m_u, m_v, m_D}, y1(3);
    bool compressing = true;
    for (;;) {
      // NOTE: for integer exponents nothing stops a step at u = 0, so after
      // maximal compression a step may not more than halve u at the initial speed.
      Real h_cap = 1 / epsilon<Real>();
      if (!compressing && y[ts::v] < 0) h_cap = y[ts::u] / (2 * abs(y[ts::v]));
      Real h = integ.expand(m_tau, y, h_cap);
      // Events are found from the signs of v at the ends of a step, so a step
      // must not span two zeros of v. NOTE: for entire solutions (linear law)
      // the Jorba-Zou step grows like p/e^3 with the order p (12 time units at
      // 210 digits, two periods: the bead "stuck"); one radian of the fastest
      // oscillation, omega^2 = alpha u^(alpha-1), keeps a zero of v about
      // pi/omega from the next (Sturm comparison). omega grows with u: at the
      // end of the step 2 radians are allowed (cheap test: u grew less than
      // m_u_growth, i.e. omega at most 2-fold).
      const Real& omega2 = integ.system().stiffness();
      if (h * h * omega2 > 1) h = 1 / sqrt(omega2);
      for (int tries = 0;; ++tries) {
        integ.values(y1, h);
        if (isfinite_(y1[ts::u]) && isfinite_(y1[ts::v]) && y1[ts::u] > y[ts::u] / 4 &&
            (!(y1[ts::u] > m_u_growth * y[ts::u]) || h * h * stiffness_at(y1[ts::u]) <= 4))
          break;
        h /= 2;
        check_tries(tries, "maximal compression phase");
      }
      count_step();
      if (compressing && y1[ts::v] <= 0) {
        const Real t = y[ts::v] == 0 ? Real(0) : integ.locate(ts::v, Real(0), h, "maximal compression (v = 0)");
        m_result.time_of_max_compression = m_tau + t;
        m_result.max_compression = integ.value(ts::u, t);
        compressing = false;
        if (m_c.gamma == 0) {
          // NOTE: without damping the motion is time-reversible: T_f = 2 tau_max
          // and e = 1 exactly, however ill-conditioned the way back is (g = 1e12).
          m_result.outcome = impact_outcome::rebound;
          m_result.e = 1, m_result.one_minus_e = 0, m_result.energy_residual = 0;
          m_result.contact_time = 2 * m_result.time_of_max_compression;
          m_result.error_estimate = 0;
          return false;
        }
      } else if (!compressing && y1[ts::v] >= 0) {
        const Real t = integ.locate(ts::v, Real(0), h, "sticking (v = 0)");
        m_tau += t;
        integ.values(y, t);
        y[ts::v] = 0;
        set_state(y);
        stick(m_tau, true);
        return false;
      }
      m_tau += h;
      y.swap(y1);
      note_speed(y[ts::v]);
      set_state(y);
      if (compressing) {
        if (creeps_to_equilibrium_from_below() || at_rest()) {
          m_result.time_of_max_compression = std::numeric_limits<Real>::infinity();
          m_result.max_compression = m_u_eq;
          stick(std::numeric_limits<Real>::infinity());
          return false;
        }
      } else {
        if (leaves_without_turning()) return true;
        if (creeps_to_rest()) {
          stick(std::numeric_limits<Real>::infinity());
          return false;
        }
        if (at_rest()) {
          // NOTE: the energy check of a turn applies: E = P(u_eq) < 0.
          stick(std::numeric_limits<Real>::infinity(), true);
          m_result.stop_overlap = m_u_eq;
          return false;
        }
        if (enters_spiral()) return true;
      }
    }
  }

  // ---- phase 2b (spiral_system): g = 0, alpha + 1 = 2 beta, underdamped ----
  // Entered after maximal compression once r = v/u^c <= -1/(2 sqrt c), left
  // for phase 3 when the exit test of phase 2 holds (for g = 0 and beta = c it
  // reads r <= -2 gamma, with u <= u_max/2). r falls monotonically.
  bool enters_spiral() {
    using std::pow;
    using std::sqrt;
    if (!m_spiral || !(m_v < 0)) return false;
    const Real r = m_v / pow(m_u, m_c.beta);
    if (!(4 * m_c.beta * r * r >= 1)) return false;
    m_in_spiral = true;
    return true;
  }

  void spiral_phase(taylor_integrator<Real, ss>& integ) {
    using std::abs;
    using std::exp;
    using std::log;
    using std::pow;
    const auto& c = m_c;
    std::vector<Real> x{Real(m_v / pow(m_u, c.beta)), Real(m_tau * pow(m_u, c.beta - 1)), m_D}, x1(3);
    Real sigma = log(m_u);
    const Real sigma_exit = log(Real(m_result.max_compression * m_switch_overlap));
    const Real r_exit = -2 * c.gamma;
    // Relative error of e = |r| u^c at the exit: an error dr in r at r shifts
    // the exit sigma by c r^2/den(r) dr/r, den = 1 + gamma beta r + c r^2
    // (the sensitivity of int r dr/den); large on the slow spiral near critical
    // damping. Errors before the spiral enter relative to the motion's size.
    m_spiral_error = m_tol * static_cast<long>(m_steps) * (1 + sensitivity(x[ss::r]));
    const Real cap = -1 / epsilon<Real>();
    while (!(x[ss::r] <= r_exit && sigma <= sigma_exit)) {
      Real h = integ.expand(sigma, x, cap);
      for (int tries = 0;; ++tries) {
        integ.values(x1, h);
        // NOTE: r falls (up to rounding: near critical damping its drift per unit
        // sigma can be below eps) and at most fourfold per step.
        if (isfinite_(x1[ss::r]) && x1[ss::r] <= x[ss::r] - 8 * epsilon<Real>() * x[ss::r] &&
            x1[ss::r] >= 4 * x[ss::r])
          break;
        h /= 2;
        check_tries(tries, "creeping (spiral) phase");
      }
      count_step();
      sigma += h;
      x.swap(x1);
      m_spiral_error += m_tol * (1 + sensitivity(x[ss::r])) + c.beta * epsilon<Real>() * abs(sigma);
    }
    // Rounding in the slow drift 1 + gamma beta r + c r^2 acts like a relative
    // error eps in 1 - xi^2, xi = gamma beta/(2 sqrt c) the damping ratio, and
    // ln e = -pi xi/sqrt(1 - xi^2) (the linear oscillator's; Tsuji maps onto it)
    // answers with pi xi eps/(1 - xi^2)^(3/2).
    {
      using std::sqrt;
      const Real xi = c.gamma_beta / (2 * sqrt(c.beta));
      const Real gap = (1 - xi) * (1 + xi);
      // NOTE: 2 pi, not pi: the drift's three terms (~1 each) and gamma beta
      // are each rounded, an absolute error of up to ~3 eps, not 1.
      m_spiral_error += 2 * boost::math::constants::pi<Real>() * xi * epsilon<Real>() / (gap * sqrt(gap));
    }
    // Phase 3 runs on the problem scaled to u = 1 (u -> u/lambda, v -> v/lambda^c,
    // tau -> tau lambda^(c-1), D -> D/lambda^(2c), lambda = exp(sigma)), which
    // the equation does not see; end_phase scales back. NOTE: unscaled, the
    // series in s about s ~ u = 1e-44 have coefficients ~ 1e44^k, which overflow
    // a double at order 7; and exp(sigma) itself underflows a double after ~745
    // e-folds (gamma = 2 - 1e-8: e ~ 1e-13644 rounds to 0, as it should).
    m_lambda_log = sigma;
    m_tau_before = x[ss::theta] * exp((1 - c.beta) * sigma);
    m_D_before = x[ss::D];
    m_u = 1;
    m_v = x[ss::r];
    m_tau = 0;
    m_D = 0;
  }

  Real sensitivity(const Real& r) const {
    using std::abs;
    const Real den = 1 + m_c.gamma_beta * r + m_c.beta * r * r;
    return m_c.beta * r * r / abs(den);
  }

  // ---- phase 3: back to u = 0 in sigma ----
  void end_phase(taylor_integrator<Real, es>& integ) {
    using std::abs;
    using std::exp;
    using std::log;
    using std::pow;
    const auto& c = m_c;
    std::vector<Real> x{m_v, m_tau, m_D}, x1(3);
    Real sigma, target, u_eps = 0;
    if (c.use_root_variable) {
      sigma = pow(m_u, Real(1) / Real(c.Q));
      target = 0;
    } else {
      sigma = log(m_u);
      u_eps = gap(Real(abs(m_v) / 2));
      if (u_eps > m_u) u_eps = m_u;
      target = log(u_eps);
    }
    while (sigma != target) {
      const Real distance = target - sigma;  // < 0
      Real cap = distance;
      if (!c.use_root_variable) {
        // at most half the remaining way (at least 1) per step in ln u
        Real half = distance / 2;
        if (half > -1) half = -1;
        if (half > distance) cap = half;
      }
      Real h = integ.expand(sigma, x, cap);
      for (int tries = 0;; ++tries) {
        integ.values(x1, h);
        if (isfinite_(x1[es::v]) && x1[es::v] < 0 && abs(x1[es::v]) > abs(x[es::v]) / 4) break;
        h /= 2;
        check_tries(tries, "restitution phase");
      }
      count_step();
      if (m_in_spiral) m_spiral_error += m_tol;
      sigma = h == distance ? target : Real(sigma + h);
      x.swap(x1);
      if (!m_in_spiral) note_speed(x[es::v]);
    }
    m_v = x[es::v], m_tau = x[es::tau], m_D = x[es::D];
    if (!c.use_root_variable) {
      // Close [0, u_eps] with the leading terms of the generalized series.
      const Real u = u_eps, V = -m_v;
      const Real u_beta = pow(u, c.beta);
      m_v = m_v - c.g * u / m_v + c.gamma * u_beta + pow(u, c.alpha_plus_one) / (c.alpha_plus_one * m_v);
      m_tau += u / V;
      m_D += c.two_gamma * V * u_beta;
    }
    m_u = 0;
    if (m_in_spiral) {
      m_v *= exp(c.beta * m_lambda_log);
      m_tau = m_tau_before + m_tau * exp((1 - c.beta) * m_lambda_log);
      m_D = m_D_before + m_D * exp(2 * c.beta * m_lambda_log);
      note_speed(m_v);
    }
    // Two values of e: e_v = -v(T_f) from the trajectory and e_D = sqrt(1 - D)
    // from the energy identity. Their errors: e^2 from the trajectory is wrong by
    // about the energy residual plus the local errors (tol per step relative to
    // the energy scale, speed_scale^2); D has relative error tol per step.
    // An error d in e^2 is an error d / (e + sqrt(d)) in e.
    using std::sqrt;
    const Real e_v = -m_v;
    m_result.outcome = impact_outcome::rebound;
    m_result.contact_time = m_tau;
    // NOTE: (1 - e)(1 + e) avoids the cancellation of 1 - e^2 for e near 0.
    m_result.energy_residual = (1 - e_v) * (1 + e_v) - m_D;
    const Real steps = Real(m_steps);
    const Real d_v = abs(m_result.energy_residual) + steps * m_tol * m_speed_scale * m_speed_scale;
    Real err_v = d_v / (e_v + sqrt(d_v));
    if (m_in_spiral) {
      // relative digits of a tiny e (see spiral_phase)
      Real err_s = e_v * m_spiral_error;
      // underflowed to a subnormal or 0: relative digits are lost, absolute ones are not
      if (e_v < boost::math::tools::min_value<Real>()) err_s += boost::math::tools::min_value<Real>();
      if (err_s < err_v) err_v = err_s;
    }
    const Real one_minus_D = 1 - m_D;
    Real err_D = std::numeric_limits<Real>::infinity(), e_D = 0;
    const Real d_D = steps * m_tol * m_D + epsilon<Real>();
    if (one_minus_D > 0) {
      e_D = sqrt(one_minus_D);
      err_D = d_D / (e_D + sqrt(d_D));
    }
    // NOTE: e_D is used only where it resolves e (1 - D above its error): near
    // e = 0 it is the square root of rounding noise, while e_v may still be right.
    if (err_D <= err_v && one_minus_D > d_D) {
      // 1 - e = D / (1 + e): full relative precision as gamma -> 0.
      m_result.one_minus_e = m_D / (1 + e_D);
      m_result.e = e_D > Real(1) / 2 ? Real(1 - m_result.one_minus_e) : e_D;
      if (e_D <= Real(1) / 2) m_result.one_minus_e = 1 - e_D;
      m_result.error_estimate = err_D;
    } else {
      m_result.e = e_v;
      m_result.one_minus_e = 1 - e_v;
      m_result.error_estimate = err_v;
    }
  }

  // ---- sticking ----
  void stick(const Real& time, bool turned = false) {
    using std::pow;
    m_result.outcome = impact_outcome::stick;
    m_result.e = 0;
    m_result.one_minus_e = 1;
    m_result.contact_time = time;
    // Where the bead stops separating: the turning point, or (creeping) the static equilibrium.
    m_result.stop_overlap = turned ? m_u : Real(m_c.g > 0 ? equilibrium() : Real(0));
    const Real two_E =
        m_v * m_v + 2 * pow(m_u, m_c.alpha_plus_one) / m_c.alpha_plus_one - 2 * m_c.g * m_u;
    m_result.energy_residual = 1 - two_E - m_D;
    m_result.error_estimate = 0;
    // The bead turned at u_s > 0 with 2E = 2P(u_s), P(u) = u^(alpha+1)/(alpha+1) - g u;
    // reaching u = 0 instead would need an energy error comparable to |P(u_s)|.
    // NOTE: g = 1e12 in double loses all of e^2 ~ 1 against g u ~ 1e16: then
    // the energy identity fails by O(1) and no outcome can be certified.
    using std::abs;
    const Real budget = abs(two_E - m_v * m_v) / 4;
    if (turned && !(abs(m_result.energy_residual) < budget))
      throw certification_error("solve_impact (taylor): the energy identity (6) fails by " +
                                to_decimal_string(m_result.energy_residual, 3) +
                                " where the bead stops: the working precision (" +
                                std::to_string(decimal_digits<Real>()) + " digits) is too low for " + describe());
  }

  // Phase 2 -> 3: the rest of the path keeps v <= v1/2 < 0 (see the file comment).
  bool leaves_without_turning() const {
    using std::pow;
    if (!(m_v < 0) || m_u > m_result.max_compression * m_switch_overlap) return false;
    const Real V = -m_v;
    Real lhs = 2 * m_c.gamma * pow(m_u, m_c.beta) * V;
    if (m_c.g > 0) lhs += 4 * m_c.g * m_u;
    return lhs <= V * V;
  }

  // g = 0 barrier w = c gamma u^beta (file comment).
  bool creeps_to_rest() {
    using std::pow;
    using std::sqrt;
    const auto& c = m_c;
    if (c.g > 0) return creeps_to_equilibrium_from_above();
    if (c.g < 0 || c.gamma == 0 || !(m_v < 0)) return false;
    const Real k = c.alpha_plus_one - 2 * c.beta;
    if (k < 0) return false;
    const Real damping = c.gamma * pow(m_u, c.beta);
    const Real w = m_v + damping;
    if (!(w > 0)) return false;
    Real ratio = w / damping;
    if (ratio > Real(1) / 2) ratio = Real(1) / 2;
    return pow(m_u, k) <= ratio * (1 - ratio) * c.gamma * c.gamma * c.beta;
  }

  // g > 0: the state is the equilibrium u_eq up to rounding. NOTE: near
  // critical damping a turn (v = 0) can come when the motion about u_eq is far
  // below the rounding of u (linear law, gamma = 1.999, g = 1e-3 in double:
  // |u - u_eq| ~ 1e-44 at the turn back); v then only decays or jitters at
  // rounding level, and no event would ever be seen.
  bool at_rest() {
    using std::abs;
    using std::pow;
    using std::sqrt;
    if (!(m_c.g > 0)) return false;
    const Real u_eq = equilibrium();
    const Real du = 64 * epsilon<Real>() * u_eq;
    if (!(abs(m_u - u_eq) <= du)) return false;
    // |v| against the speed of an oscillation of amplitude du: omega du, omega^2 = alpha u_eq^(alpha-1)
    return abs(m_v) <= du * sqrt(m_c.alpha * pow(u_eq, m_c.alpha - 1));
  }

  // g > 0, u > u_eq, v < 0: trapped in the sector -kappa (u - u_eq) <= v < 0.
  bool creeps_to_equilibrium_from_above() {
    using std::pow;
    using std::sqrt;
    const auto& c = m_c;
    const Real u_eq = equilibrium();
    if (!(m_u > u_eq) || !(m_v < 0)) return false;
    const Real Gamma = c.gamma_beta * pow(u_eq, c.beta - 1);
    const Real A = c.alpha * pow(m_u, c.alpha - 1);
    const Real disc = Gamma * Gamma - 4 * A;
    if (disc < 0) return false;
    const Real kappa = (Gamma + sqrt(disc)) / 2;
    return -m_v <= kappa * (m_u - u_eq);
  }

  // g > 0, u < u_eq, v > 0: trapped in 0 < v <= kappa (u_eq - u); u creeps up to u_eq.
  bool creeps_to_equilibrium_from_below() {
    using std::pow;
    using std::sqrt;
    const auto& c = m_c;
    if (!(c.g > 0) || c.gamma == 0) return false;
    const Real u_eq = equilibrium();
    if (!(m_u < u_eq) || !(m_v > 0)) return false;
    const Real Gamma = c.gamma_beta * pow(m_u, c.beta - 1);
    const Real A = c.alpha * pow(u_eq, c.alpha - 1);
    const Real disc = Gamma * Gamma - 4 * A;
    if (disc < 0) return false;
    const Real kappa = (Gamma + sqrt(disc)) / 2;
    return m_v <= kappa * (u_eq - m_u);
  }

  const Real& equilibrium() {
    using std::pow;
    if (!m_have_u_eq) {
      m_u_eq = pow(m_c.g, 1 / m_c.alpha);
      m_have_u_eq = true;
    }
    return m_u_eq;
  }

  // omega^2 = alpha u^(alpha-1), the stiffness at overlap u.
  Real stiffness_at(const Real& u) const {
    using std::pow;
    if (m_c.alpha_is_one) return Real(1);
    return m_c.alpha * pow(u, m_c.alpha - 1);
  }

  // u where the first-order terms of the generalized series at speed V are all
  // below tol V: g u/V, gamma u^beta, u^(alpha+1)/((alpha+1) V) <= tol V (and u <= tol).
  Real gap(const Real& V) const {
    using std::abs;
    using std::pow;
    const auto& c = m_c;
    Real u = m_tol;
    const Real target = m_tol * V;
    if (c.g != 0) {
      const Real b = target * V / abs(c.g);
      if (b < u) u = b;
    }
    if (c.gamma != 0) {
      const Real b = pow(Real(target / c.gamma), 1 / c.beta);
      if (b < u) u = b;
    }
    const Real b = pow(Real(target * V * c.alpha_plus_one), 1 / c.alpha_plus_one);
    if (b < u) u = b;
    return u;
  }

  // The overlap at which the load, damping or stiffness first matter: min(1, 1/|g|, gamma^(-1/beta)).
  Real natural_scale() const {
    using std::abs;
    using std::pow;
    Real u = 1;
    if (abs(m_c.g) > 1) u = 1 / abs(m_c.g);
    if (m_c.gamma > 1) {
      const Real b = pow(m_c.gamma, -1 / m_c.beta);
      if (b < u) u = b;
    }
    return u;
  }

  void set_state(const std::vector<Real>& y) {
    m_u = y[ts::u];
    m_v = y[ts::v];
    m_D = y[ts::D];
  }

  void note_speed(const Real& v) {
    using std::abs;
    if (abs(v) > m_speed_scale) m_speed_scale = abs(v);
  }

  static bool isfinite_(const Real& x) {
    using boost::math::isfinite;
    return isfinite(x);
  }

  std::string describe() const {
    return "(" + m_law.describe() + ", gamma = " + to_decimal_string(m_c.gamma) +
           ", g = " + to_decimal_string(m_c.g) + ")";
  }

  void count_step() {
    if (++m_steps > m_options.max_steps)
      throw convergence_error("solve_impact (taylor): step budget of " + std::to_string(m_options.max_steps) +
                              " steps exhausted " + describe());
  }

  void check_tries(int tries, const char* phase) const {
    if (tries > 4 * binary_digits<Real>())
      throw convergence_error(std::string("solve_impact (taylor): no acceptable step in the ") + phase + " " +
                              describe());
  }

  impact_result<Real> finish() {
    m_result.steps = m_steps;
    return m_result;
  }

  const contact_law& m_law;
  const solve_options<Real>& m_options;
  impact_constants<Real> m_c;
  Real m_tol;
  Real m_tau = 0, m_u = 0, m_v = 1, m_D = 0;
  Real m_u_eq = 0;
  bool m_have_u_eq = false;
  Real m_speed_scale = 1;
  Real m_spiral_error = 0;
  Real m_lambda_log = 0, m_tau_before = 0, m_D_before = 0;  // spiral exit (scaling of phase 3)
  bool m_spiral = false, m_in_spiral = false;
  Real m_u_growth = std::numeric_limits<Real>::infinity();  // 4^(1/(alpha-1)): omega^2 grows at most 4-fold
  // Phase switches: leave phase 1 when v < m_switch_speed * peak v; enter phase 3
  // only once u < m_switch_overlap * u_max (away from the turning point, which
  // limits the sigma steps, as u = 0 limits the tau steps).
  Real m_switch_speed = Real(4) / 5, m_switch_overlap = Real(1) / 2;
  std::size_t m_steps = 0;
  impact_result<Real> m_result;
};

}  // namespace detail

/// The impact of (law, gamma, g) by Taylor series to the working precision of
/// Real (or options.tolerance). Inputs are assumed valid (solve_impact checks them).
template <class Real>
impact_result<Real> solve_impact_taylor(const contact_law& law, const Real& gamma, const Real& g,
                                        const solve_options<Real>& options) {
  return detail::taylor_impact_solver<Real>(law, gamma, g, options).solve();
}

}  // namespace viscor
