// One impact, integrated by Taylor series to the working precision, with exact
// treatment of both ends of the contact. solve() runs the phases below in order
// (named as in core/impact_phase.hpp); each is a function from the state it starts at
// to what happened (an outcome) and the state it ends at (core/contact_state.hpp:
// overlap u, velocity v = u', time tau, dissipated energy D). sigma is the variable
// of the endpoint system: s = u^(1/Q) for rational exponents, ln u otherwise.
//
// 1. compress_phase (u = 0, v = 1): the endpoint system in sigma
//    (detail/impact_systems.hpp), forward until v has fallen to 4/5 of its
//    peak, so that it stays far from the turning point v = 0, where
//    dtau/dsigma = J/v is singular.
// 2. turn_phase, around maximal compression: tau as independent variable, u > 0
//    bounded away from 0, so u^alpha, u^beta are analytic. Events on the step
//    polynomial: v = 0 (maximal compression), v = 0 again with u > 0 (the bead
//    turns back: it sticks). It leaves for the exit as soon as the rest of the
//    path provably keeps v <= v1/2 < 0 down to u = 0: with V = -v, over [0, u1]
//        V(0) >= V1 - g+ u1 / min V - gamma u1^beta,
//    so 4 g+ u1 + 2 gamma u1^beta V1 <= V1^2 is enough. Outcomes: leaves,
//    spirals (2b), turns_back, creeps or sticks_at_unknown_time (sticking, below),
//    undamped (gamma = 0), undecided (a stiff creep out of reach, 2c).
// 2b. spiral_phase, g = 0 and alpha + 1 = 2 beta (linear, Tsuji), underdamped:
//    after maximal compression, the scale-free spiral_system in ln u
//    (impact_systems.hpp), so that near critical damping, where the bead creeps
//    back along a slow spiral and e = exp(-pi xi/sqrt(1 - xi^2)) is tiny, e keeps
//    its relative digits; the exit then runs on the problem rescaled to u = 1.
// 3. exit_phase: the endpoint system backwards to u = 0 exactly (s = 0), or to a
//    tiny u_eps; then close_by_series: [0, u_eps] by the leading terms of the
//    generalized series
//        v(u) = v0 + g u/v0 - gamma u^beta - u^(alpha+1)/((alpha+1) v0) + O(u^2)
//    (u_eps is chosen so that each retained term is below tol |v|, hence the
//    neglected ones below tol^2); unscale_spiral (after 2b); choose_e.
// choose_e: e = -v(T_f), or 1 - e = D/(1 + e) from the dissipated energy
// D = 2 gamma beta int v^2 u^(beta-1) dtau (eq. 6), integrated along as a state,
// so 1 - e keeps full relative precision as gamma -> 0. Energy balance: with
// E = v^2/2 + u^(alpha+1)/(alpha+1) - g u, dE/dtau = -D', so 1 - 2E - D = 0 at
// every point of the path; its value at the end is energy_residual.
//
// Sticking (e = 0) is an outcome: v returns to 0 with u > 0 (an event), or the
// state enters a region it provably never leaves without reaching u = 0 (the
// sticking proofs, each returning the sticking_proof it established):
// * creeps_to_origin, g = 0, after maximal compression, w = v + gamma u^beta > 0:
//   the curve w = c gamma u^beta is a barrier if u^(alpha+1-2 beta) <=
//   c(1-c) gamma^2 beta on (0, u] (possible when alpha + 1 >= 2 beta); the bead
//   creeps into (0, 0) (for alpha = beta = 1 this is exactly gamma >= 2).
// * creeps_to_equilibrium_from_above/below, g > 0, equilibrium u_eq = g^(1/alpha):
//   the sector between v = 0 and v = -+kappa (u - u_eq) traps the state when
//   kappa^2 - Gamma kappa + A <= 0, Gamma the least damping gamma beta u^(beta-1),
//   A the largest stiffness alpha u^(alpha-1) over the remaining range; the bead
//   creeps to u_eq.
// * at_rest, g > 0: the state equals u_eq up to rounding: the turn, if any, is
//   below the working precision.
// The two creeps end the turn as creeps, contact_time = +infinity (proven: the bead
// never turns); at_rest as sticks_at_unknown_time, contact_time unknown (the bead may
// still turn back, later than the precision can follow: linear law, gamma = 1.9999,
// g = 0.5 turns at tau = 316). stop_overlap is the turning point u_s, or the rest
// position u_eq (0 for g = 0).
//
// 2c. creep_phase: past maximal compression a strongly damped bead can creep along
//    the slow manifold for far longer than the damping time that bounds the Taylor
//    steps (creep_out_of_reach). For g <= 0 (no turn back is possible) the creep is
//    followed by the L-stable Radau IIA method (ode/radau_integrator.hpp; in ln u for
//    g < 0 and work types wider than long double) until the exit test of the turn
//    holds. For g > 0, or if those steps fail, the solve ends at once as undecided,
//    with error_estimate a bound on e from the energy, which never increases:
//    e <= sqrt(2E) (energy_bound_on_e).
//
// The GBS solver (adaptive_impact.hpp) makes its own exit, barrier and energy
// arguments on purpose: the two solvers share no phase code (a shared proof
// would be a shared blind spot).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/contact_state.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_phase.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/impact/detail/impact_systems.hpp>
#include <viscor/ode/radau_integrator.hpp>
#include <viscor/ode/taylor_integrator.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/precision.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace viscor {

namespace detail {

/// What a sticking proof of taylor_impact_solver established (file comment).
enum class sticking_proof {
  none,                   ///< nothing
  creeps_to_origin,       ///< g = 0: under the barrier w = c gamma u^beta the bead creeps into (0, 0)
  creeps_to_equilibrium,  ///< g > 0: in a sector about u_eq the bead creeps to u_eq
  at_rest,                ///< g > 0: the state is u_eq up to rounding
};

/// Which identity choose_e took e from.
enum class e_source { trajectory, dissipated_energy };

template <class Real>
struct restitution {
  Real e, one_minus_e, error_estimate, energy_residual;
  e_source source = e_source::trajectory;
};

template <class Real>
class taylor_impact_solver {
  using ts = time_system<Real>;
  using es = endpoint_system<Real>;
  using ss = spiral_system<Real>;
  using state = contact_state<Real>;

  /// How the compress phase ended: the state where it stopped, and whether a sticking
  /// proof (creeps_to_equilibrium_from_below) already holds there.
  struct compress_end {
    state at{};
    bool creeps = false;
  };

  /// How the turn phase ended (the GBS solver's turn outcomes, and two of its own:
  /// spirals and undamped).
  enum class turn_outcome {
    leaves,      ///< past maximal compression, v <= v1/2 < 0 provably down to u = 0: the exit follows
    spirals,     ///< g = 0, alpha + 1 = 2 beta, underdamped, past maximal compression: the spiral phase follows
    turns_back,  ///< v = 0 again with u > 0: the bead sticks at the turning point
    creeps,      ///< a barrier or a trapping sector holds: the bead sticks, contact_time = +infinity
    sticks_at_unknown_time,  ///< at rest at u_eq up to rounding: it sticks, contact_time unknown (empty)
    undamped,    ///< gamma = 0: time-reversible, e = 1 exactly
    undecided,   ///< creeping out on the slow manifold, out of reach of explicit steps, g > 0 or the creep failed
  };

  struct turn_end {
    turn_outcome outcome = turn_outcome::leaves;
    state at{};  ///< where the phase ended (unused for undamped)
    bool past_max_compression = false;
    bool at_contact_end = false;  ///< leaves: the state is already at u = 0 (the creep landed there)
    /// tau and u at maximal compression (+infinity and u_eq when the bead creeps before it)
    Real tau_max = 0, u_max = 0;
  };

  /// Where the spiral phase hands over to the exit: the state of the problem
  /// rescaled to u = 1, and what unscale_spiral needs to scale back.
  struct spiral_end {
    state scaled;               ///< u = 1, v = r = v/u^c, tau = 0, D = 0
    Real log_scale;             ///< ln lambda, lambda the overlap at the exit
    Real tau_before, D_before;  ///< tau and D of the path up to the exit
    Real error;                 ///< relative error of e so far (the exit adds tol per step)
  };

 public:
  taylor_impact_solver(const contact_law& law, const Real& gamma, const Real& g, const solve_options<Real>& options)
      : m_law(law), m_options(options), m_c(make_impact_constants(law, gamma, g)) {
    using std::pow;
    m_tol = options.tolerance > 0 ? options.tolerance : epsilon<Real>();
    if (m_tol < epsilon<Real>()) m_tol = epsilon<Real>();
    if (m_c.alpha > 1) m_u_growth = pow(Real(4), 1 / (m_c.alpha - 1));
    if (m_c.g > 0) m_u_eq = pow(m_c.g, 1 / m_c.alpha);
    if (law.alpha.is_rational() && law.beta.is_rational()) {
      // alpha + 1 = 2 beta, g = 0, underdamped: the spiral variables (impact_systems.hpp).
      // In 128 bits: exact for any 64-bit numerators and denominators.
      const __int128 p1 = law.alpha.numerator(), q1 = law.alpha.denominator();
      const __int128 p2 = law.beta.numerator(), q2 = law.beta.denominator();
      m_spiral_possible = g == 0 && gamma > 0 && (p1 + q1) * q2 == 2 * p2 * q1 &&
                          m_c.gamma_beta * m_c.gamma_beta < 4 * m_c.beta;
    }
  }

  /// The phases below in order; a working type whose exponent range cannot hold the
  /// Taylor series is reported with the problem named (with_working_precision reruns
  /// double-double there in a wider type).
  impact_result<Real> solve() {
    try {
      return solve_phases();
    } catch (const exponent_range_exceeded& e) {
      throw exponent_range_exceeded(std::string("solve_impact (taylor): ") + e.what() + " " + describe());
    }
  }

  impact_result<Real> solve_phases() {
    es end_sys(m_c, taylor_order(m_tol), m_tol);
    ts time_sys(m_c, taylor_order(m_tol), m_tol);
    taylor_integrator<Real, es> end_int(end_sys, m_tol);
    taylor_integrator<Real, ts> time_int(time_sys, m_tol);
    impact_result<Real> result;
    result.method = integration_method::taylor;

    const compress_end start = compress_phase(end_sys, end_int);
    const turn_end around = start.creeps ? creeps_while_compressing(start.at) : turn_phase(time_int, start.at);
    result.time_of_max_compression = around.tau_max;
    result.max_compression = around.u_max;
    if (around.outcome != turn_outcome::leaves && around.outcome != turn_outcome::spirals) {
      ends_in_turn(result, around);
      return finish(result);
    }

    std::optional<spiral_end> spiral;
    if (around.outcome == turn_outcome::spirals) {
      ss spiral_sys(m_c, taylor_order(m_tol));
      taylor_integrator<Real, ss> spiral_int(spiral_sys, m_tol);
      spiral = spiral_phase(spiral_int, around.at, around.u_max);
    }
    Real* spiral_error = spiral ? &spiral->error : nullptr;
    state end = around.at;
    if (!around.at_contact_end) {
      end = exit_phase(end_int, spiral ? spiral->scaled : around.at, spiral_error);
      if (!m_c.use_root_variable) end = close_by_series(end);
    }
    if (spiral) end = unscale_spiral(end, *spiral);
    const restitution<Real> e = choose_e(end, spiral_error);
    result.outcome = impact_outcome::rebound;
    result.contact_time = end.tau;
    result.energy_residual = e.energy_residual;
    result.e = e.e;
    result.one_minus_e = e.one_minus_e;
    result.error_estimate = e.error_estimate;
    return finish(result);
  }

 private:
  // The result of an impact that ends in the turn phase (any outcome but leaves and spirals).
  void ends_in_turn(impact_result<Real>& result, const turn_end& around) const {
    switch (around.outcome) {
      case turn_outcome::undamped:
        // NOTE: without damping the motion is time-reversible: T_f = 2 tau_max
        // and e = 1 exactly, however ill-conditioned the way back is (g = 1e12).
        result.outcome = impact_outcome::rebound;
        result.e = 1, result.one_minus_e = 0, result.energy_residual = 0;
        result.contact_time = Real(2 * around.tau_max);
        result.error_estimate = 0;
        return;
      case turn_outcome::turns_back:
        stick(result, around.at, around.at.tau, around.at.u, true);
        return;
      case turn_outcome::creeps:
        stick(result, around.at, std::numeric_limits<Real>::infinity(), m_u_eq, false);
        return;
      case turn_outcome::sticks_at_unknown_time:
        // NOTE: at rest after maximal compression the energy check of a turn applies: E = P(u_eq) < 0.
        stick(result, around.at, std::nullopt, m_u_eq, around.past_max_compression);
        return;
      case turn_outcome::undecided:
        result.outcome = impact_outcome::undecided;
        result.e = 0, result.one_minus_e = 1, result.energy_residual = 0;
        result.contact_time = std::nullopt;
        result.error_estimate = energy_bound_on_e(around.at);
        return;
      case turn_outcome::leaves:
      case turn_outcome::spirals:
        return;
    }
  }

  // e <= sqrt(2E): E = v^2/2 + u^(alpha+1)/(alpha+1) - g u never increases and is
  // e^2/2 at u = 0; E is taken with the error the steps carry (choose_e's rule), and
  // the bound doubled.
  Real energy_bound_on_e(const state& at) const {
    using std::pow;
    using std::sqrt;
    const Real two_E = at.v * at.v + 2 * pow(at.u, m_c.alpha_plus_one) / m_c.alpha_plus_one - 2 * m_c.g * at.u;
    const Real carried = Real(m_steps) * m_tol * m_speed_scale * m_speed_scale;
    return 2 * sqrt(Real((two_E > 0 ? two_E : Real(0)) + carried));
  }

  // ---- compress ----
  // Takes the endpoint system and its integrator; starts at first contact
  // (u = 0, v = 1, tau = D = 0) and returns the state where v has fallen below
  // m_switch_speed times its peak (u > 0, v > 0: still compressing), or where the
  // bead provably creeps up to u_eq (creeps: creeps_to_equilibrium_from_below);
  // a step it cannot take throws convergence_error.
  // NOTE: under a load g > 0 with strong damping the bead is pushed in at the
  // terminal speed ~ g/(gamma beta u^(beta-1)) and creeps up to u_eq, v never
  // falling to 4/5 of its peak: the steps, bounded by the fast damping scale, would
  // number ~ gamma^2 (linear law, gamma = 1e4, g = 1e6: over 1e8). The trapping
  // sector proves the creep as soon as the state enters it, here as in the turn.
  compress_end compress_phase(const es& sys, taylor_integrator<Real, es>& integ) {
    using std::log;
    using std::pow;
    const auto& c = m_c;
    std::vector<Real> x(3), x1(3);
    Real sigma;
    if (c.use_root_variable) {
      sigma = 0;
      x[es::v] = 1, x[es::tau] = 0, x[es::D] = 0;
    } else {
      const Real u = series_limit(Real(1));
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
      if (m_c.g > 0) {
        const state here{sys.u_of(sigma), x[es::v], x[es::tau], x[es::D]};
        if (creeps_to_equilibrium_from_below(here) != sticking_proof::none) return {here, true};
      }
    }
    return {state{sys.u_of(sigma), x[es::v], x[es::tau], x[es::D]}, false};
  }

  // The compress phase ended in the trapping sector below u_eq: the bead creeps up to
  // u_eq without reaching it (no maximal compression at finite time) and sticks.
  turn_end creeps_while_compressing(const state& at) const {
    turn_end end;
    end.outcome = turn_outcome::creeps;
    end.at = at;
    end.tau_max = std::numeric_limits<Real>::infinity();
    end.u_max = m_u_eq;
    return end;
  }

  // ---- turn ----
  // Takes the state compress_phase returned (u > 0, v > 0) and integrates in tau
  // through maximal compression. Returns how the phase ended (turn_outcome), the
  // state there, whether it had passed maximal compression, and tau and u at
  // maximal compression.
  turn_end turn_phase(taylor_integrator<Real, ts>& integ, const state& from) {
    std::vector<Real> y{from.u, from.v, from.D}, y1(3);
    Real tau = from.tau;
    turn_end end;
    std::size_t creep_steps = 0;  // steps since maximal compression
    for (;;) {
      const Real h = time_step(integ, tau, y, y1, !end.past_max_compression);
      count_step();
      if (!end.past_max_compression && y1[ts::v] <= 0) {
        const Real t = y[ts::v] == 0 ? Real(0) : integ.locate(ts::v, Real(0), h, "maximal compression (v = 0)");
        end.tau_max = tau + t;
        end.u_max = integ.value(ts::u, t);
        end.past_max_compression = true;
        if (m_c.gamma == 0) {
          end.outcome = turn_outcome::undamped;
          return end;
        }
      } else if (end.past_max_compression && y1[ts::v] >= 0) {
        const Real t = integ.locate(ts::v, Real(0), h, "sticking (v = 0)");
        tau += t;
        integ.values(y, t);
        y[ts::v] = 0;
        end.at = state{y[ts::u], y[ts::v], tau, y[ts::D]};
        end.outcome = turn_outcome::turns_back;
        return end;
      }
      tau += h;
      y.swap(y1);
      note_speed(y[ts::v]);
      end.at = state{y[ts::u], y[ts::v], tau, y[ts::D]};
      if (!end.past_max_compression ? sticks_before_compression(end) : ends_after_compression(end, h, creep_steps))
        return end;
    }
  }

  // After a turn step before maximal compression: whether the bead sticks at end.at
  // (creeps up to u_eq, or rests there); if so, end says how.
  bool sticks_before_compression(turn_end& end) const {
    sticking_proof proof = creeps_to_equilibrium_from_below(end.at);
    if (proof == sticking_proof::none) proof = at_rest(end.at);
    if (proof == sticking_proof::none) return false;
    end.tau_max = std::numeric_limits<Real>::infinity();
    end.u_max = m_u_eq;
    end.outcome = proof == sticking_proof::at_rest ? turn_outcome::sticks_at_unknown_time : turn_outcome::creeps;
    return true;
  }

  // After a turn step past maximal compression, at end.at after a step h, creep_steps
  // such steps so far: whether the turn ends here (it leaves, sticks, spirals, or a
  // stiff creep follows); if so, end says how.
  bool ends_after_compression(turn_end& end, const Real& h, std::size_t& creep_steps) {
    if (leaves_without_turning(end.at, end.u_max)) {
      end.outcome = turn_outcome::leaves;
      return true;
    }
    sticking_proof proof = m_c.g > 0 ? creeps_to_equilibrium_from_above(end.at) : creeps_to_origin(end.at);
    if (proof == sticking_proof::none) proof = at_rest(end.at);
    if (proof != sticking_proof::none) {
      end.outcome = proof == sticking_proof::at_rest ? turn_outcome::sticks_at_unknown_time : turn_outcome::creeps;
      return true;
    }
    if (enters_spiral(end.at)) {
      end.outcome = turn_outcome::spirals;
      return true;
    }
    if (++creep_steps > m_creep_min_steps) m_crept = true;  // a long creep: see choose_e
    if (!(creep_steps > m_creep_min_steps && creep_out_of_reach(end.at, h))) return false;
    // g <= 0: the bead cannot turn back (u'' = g - u^alpha < 0 at v = 0), so no
    // event is missed by the implicit steps; g > 0 is left undecided.
    const std::optional<state> out = m_c.g <= 0 ? creep_phase(end.at, end.u_max) : std::nullopt;
    if (!out) {
      end.outcome = turn_outcome::undecided;
      return true;
    }
    end.at = *out;
    end.at_contact_end = out->u == 0;
    end.outcome = turn_outcome::leaves;
    return true;
  }

  // One step of the turn phase from (tau, y): the Jorba-Zou step, capped so that
  // it cannot span two zeros of v (nor, past maximal compression, more than halve
  // u), halved until the state y1 it reaches is acceptable. Returns the step h;
  // y1 holds the state at tau + h.
  Real time_step(taylor_integrator<Real, ts>& integ, const Real& tau, const std::vector<Real>& y,
                 std::vector<Real>& y1, bool compressing) {
    using std::abs;
    using std::sqrt;
    // NOTE: for integer exponents nothing stops a step at u = 0, so after
    // maximal compression a step may not more than halve u at the initial speed.
    Real h_cap = 1 / epsilon<Real>();
    if (!compressing && y[ts::v] < 0) h_cap = y[ts::u] / (2 * abs(y[ts::v]));
    Real h = integ.expand(tau, y, h_cap);
    // Events are found from the signs of v at the ends of a step, so a step
    // must not span two zeros of v. NOTE: for entire solutions (linear law)
    // the Jorba-Zou step grows like p/e^3 with the order p (docs/performance.md);
    // one radian of the fastest oscillation, omega^2 = alpha u^(alpha-1), keeps
    // a zero of v about pi/omega from the next (Sturm comparison). omega grows
    // with u: at the end of the step 2 radians are allowed (cheap test: u grew
    // less than m_u_growth, i.e. omega at most 2-fold).
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
    return h;
  }

  // turn -> exit: the rest of the path keeps v <= v1/2 < 0 (see the file comment).
  bool leaves_without_turning(const state& s, const Real& u_max) const {
    using std::pow;
    if (!(s.v < 0) || s.u > u_max * m_switch_overlap) return false;
    const Real V = -s.v;
    Real lhs = 2 * m_c.gamma * pow(s.u, m_c.beta) * V;
    if (m_c.g > 0) lhs += 4 * m_c.g * s.u;
    return lhs <= V * V;
  }

  // turn -> creep: after maximal compression with strong damping the bead creeps out
  // (or in) along the slow manifold v ~ (g - u^alpha)/(gamma beta u^(beta-1)) over the
  // slow time u/|v|, while the steps stay bounded by the fast damping time
  // 1/(gamma beta u^(beta-1)): a stiff motion. When that ratio exceeds 1000 and the
  // steps still needed at the current step h and speed, (u/|v|)/h, exceed
  // m_creep_step_limit, the explicit steps stop here, rather than exhausting the step
  // budget or running for minutes (linear law, gamma = 1e10, g = -1: ~1e10 steps).
  bool creep_out_of_reach(const state& s, const Real& h) const {
    using std::abs;
    using std::pow;
    if (!(s.v < 0) || m_c.gamma == 0) return false;
    const Real slow_time = s.u / abs(s.v);
    const Real damping = m_c.beta_is_one ? m_c.gamma_beta : Real(m_c.gamma_beta * pow(s.u, m_c.beta - 1));
    // NOTE: u/|v| is the slow time of one e-fold; a creep to u = 0 at g = 0 lasts many
    // (Kuwabara-Kono, gamma = 1e3: 19411 explicit steps at 50 digits, none of them with
    // 20000 to go), so where the implicit steps take over (g <= 0) a tenth of the limit
    // starts them; for g > 0 the test ends the solve, so it stays.
    const Real limit = m_c.g <= 0 ? m_creep_step_limit / 10 : m_creep_step_limit;
    return slow_time * damping > 1000 && slow_time > h * limit;
  }

  // ---- creep: the stiff creep out, g <= 0 ----
  // Takes the state where creep_out_of_reach held (past maximal compression, v < 0) and
  // u_max; integrates the creep by Radau IIA (ode/radau_integrator.hpp, order 2s - 1
  // with s = max(3, (digits + 2)/3) stages) until the exit test of the turn holds, and
  // returns that state; nothing if the steps fail (a step shorter than the rounding of
  // its variable): the solve is then undecided.
  // The variable: tau, on (u, v, D); or, for g < 0 in work types wider than long
  // double, rho = -ln u, on (u, v, D, tau) with y' = (tau' = u/|v|) times the rates in
  // tau. Pulled out, the bead reaches u = 0 on the slow manifold in finite time
  // (u^beta ~ the time left, for beta > 1): in tau the Taylor radius is that time
  // left and the steps a few per cent of it, while the creep is smooth in ln u.
  // NOTE: rho takes about a quarter of the steps of tau at 50 digits and g < 0 (Tsuji,
  // gamma = 1e10, g = -1e-3), the same e to 52 digits; at g = 0 rho was slower, and
  // carrying tau as a fourth component in tau cost more steps, hence two forms. Double
  // and long double keep tau, where the whole creep is short (not tried in rho: the GBS
  // solver's creep in ln u stalls in long double, see adaptive_impact.hpp).
  // Measurements: docs/performance.md.
  std::optional<state> creep_phase(const state& from, const Real& u_max) {
    if (m_c.g < 0 && binary_digits<Real>() > std::numeric_limits<long double>::digits)
      return creep_steps<4>(from, u_max);
    return creep_steps<3>(from, u_max);
  }

  // The creep's equations for the Radau steps: N = 3, (u, v, D) in tau; N = 4,
  // (u, v, D, tau) in rho = -ln u. rates() are those in tau, step_rates() those in the
  // step variable; jacobian() is that of step_rates.
  template <std::size_t N>
  class creep_system {
   public:
    using vec = std::array<Real, N>;
    static constexpr bool in_log = N == 4;

    explicit creep_system(const impact_constants<Real>& c) : m_c(c) {
      qa = in_quarters(c.alpha - 1), qb = in_quarters(c.beta - 2);
      by_roots = qa != std::numeric_limits<int>::min() && qb != std::numeric_limits<int>::min();
      fourth_root = by_roots && ((qa % 2) != 0 || (qb % 2) != 0);
    }

    bool rates(const vec& y, vec& d) {
      if (!(y[0] > 0) || (in_log && !(y[1] < 0))) return false;
      powers(y[0]);
      d[0] = y[1];
      d[1] = m_c.g - u_a * y[0] - damping * y[1];
      d[2] = 2 * damping * y[1] * y[1];
      if constexpr (in_log) d[3] = 1;
      return true;
    }

    bool step_rates(const vec& y, vec& d) {
      if (!rates(y, d)) return false;
      if constexpr (in_log) {
        const Real dtau = -y[0] / y[1];
        for (Real& x : d) x *= dtau;
      }
      return true;
    }

    void jacobian(const vec& y, std::array<vec, N>& J) {
      powers(y[0]);
      const Real damping_slope = m_c.gamma_beta * (m_c.beta - 1) * u_b2;  // d/du of gamma beta u^(beta-1)
      for (vec& row : J) row.fill(Real(0));
      J[0][1] = 1;
      J[1][0] = -m_c.alpha * u_a - damping_slope * y[1];
      J[1][1] = -damping;
      J[2][0] = 2 * damping_slope * y[1] * y[1];
      J[2][1] = 4 * damping * y[1];
      if constexpr (in_log) {
        // d(r tau')/dy = tau' dr/dy + r (dtau'/dy)^T, tau' = -u/v
        vec r;
        rates(y, r);
        const Real dtau = -y[0] / y[1], by_u = -1 / y[1], by_v = y[0] / (y[1] * y[1]);
        for (std::size_t i = 0; i < N; ++i) {
          for (Real& x : J[i]) x *= dtau;
          J[i][0] += r[i] * by_u;
          J[i][1] += r[i] * by_v;
        }
      }
    }

   private:
    // NOTE: exponents that are multiples of 1/4 (every named law) from square roots
    // and products, a few roundings instead of pow's exp and log: pow was over a third
    // of a 50-digit creep.
    static int in_quarters(const Real& p) {
      using std::abs;
      using std::floor;
      const Real q = 4 * p;
      return q == floor(q) && abs(q) <= 64 ? static_cast<int>(q) : std::numeric_limits<int>::min();
    }
    static Real quarter_power(const Real& u, const Real& r2, const Real& r4, int k) {
      const int m = k < 0 ? -k : k;
      Real x = 1;
      for (int i = 0; i < m / 4; ++i) x *= u;
      if (m % 4 >= 2) x *= r2;
      if (m % 2 == 1) x *= r4;
      return k < 0 ? Real(1 / x) : x;
    }
    // damping = gamma beta u^(beta-1), u_a = u^(alpha-1), u_b2 = u^(beta-2).
    void powers(const Real& u) {
      using std::pow;
      using std::sqrt;
      if (by_roots) {
        const Real r2 = sqrt(u), r4 = fourth_root ? Real(sqrt(r2)) : Real(0);
        u_a = quarter_power(u, r2, r4, qa);
        u_b2 = quarter_power(u, r2, r4, qb);
      } else {
        u_a = m_c.alpha_is_one ? Real(1) : Real(pow(u, m_c.alpha - 1));
        u_b2 = m_c.beta_is_one ? Real(1 / u) : Real(pow(u, m_c.beta - 2));
      }
      damping = m_c.gamma_beta * u_b2 * u;
    }

    const impact_constants<Real>& m_c;
    int qa, qb;
    bool by_roots, fourth_root;
    Real damping, u_a, u_b2;  // scratch of powers()
  };

  // N = 3: (u, v, D) in tau; N = 4: (u, v, D, tau) in rho = -ln u (creep_phase).
  template <std::size_t N>
  std::optional<state> creep_steps(const state& from, const Real& u_max) {
    using std::abs;
    using vec = std::array<Real, N>;
    constexpr bool in_log = N == 4;
    const int stages = std::max(3, (decimal_digits<Real>() + 2) / 3);
    // NOTE: the step-doubling difference carries rounding of a few ulps: a tolerance
    // below 16 ulps would shrink the steps to nothing.
    const Real floor = 16 * epsilon<Real>();
    radau_integrator<Real, N> radau(stages, m_tol > floor ? m_tol : floor);
    creep_system<N> sys(m_c);
    auto f = [&sys](const vec& y, vec& d) { return sys.step_rates(y, d); };
    auto jacobian = [&sys](const vec& y, std::array<vec, N>& J) { sys.jacobian(y, J); };
    vec y;
    y[0] = from.u, y[1] = from.v, y[2] = from.D;
    Real tau = from.tau, h = in_log ? Real(1) / 64 : Real(from.u / abs(from.v) / 64), taken = 0;
    if constexpr (in_log) y[3] = tau;
    // Landing: past the exit test, where the endpoint series would overflow, the creep
    // is followed on to u = 0 (endpoint_series_overflow).
    bool landing = false;
    for (;;) {
      vec scales;
      for (std::size_t i = 0; i < N; ++i) scales[i] = abs(y[i]) > 0 ? Real(abs(y[i])) : Real(1);
      // NOTE: at most half the slow time u/|v| per step (in rho: ln 2): u falls at
      // most about halfway, and the exit does not start at a u too tiny for its steps.
      const Real cap = in_log ? Real(boost::math::constants::ln_two<Real>()) : Real(y[0] / (2 * abs(y[1])));
      if (h > cap) h = cap;
      count_step();
      if (!radau.try_step(f, jacobian, y, h, scales, taken)) {
        if (!(h > 64 * epsilon<Real>() * (in_log ? Real(1) : abs(tau)))) return std::nullopt;
        continue;
      }
      if constexpr (in_log)
        tau = y[3];
      else
        tau += taken;
      note_speed(y[1]);
      const state here{y[0], y[1], tau, y[2]};
      if (!(y[1] < 0)) return std::nullopt;  // cannot happen for g <= 0: the steps went wrong
      if (!landing && leaves_without_turning(here, u_max)) {
        if (!endpoint_series_overflow(here)) return here;
        landing = true;
      }
      if (landing)
        if (const std::optional<state> end = landed(sys, y, tau)) return end;
    }
  }

  // Landing on u = 0 (creep_steps), u about halving per step: once the rest of the
  // way, u/|v| in time, changes v and D by less than tol relative to first order
  // (their rates times u/|v|), the state at u = 0 by the first-order close.
  template <std::size_t N>
  std::optional<state> landed(creep_system<N>& sys, const std::array<Real, N>& y, const Real& tau) const {
    using std::abs;
    std::array<Real, N> d{};  // rates() fills it; initialised so the compiler can see that
    sys.rates(y, d);
    const Real rest = y[0] / abs(y[1]);
    if (abs(d[1]) * rest <= m_tol * abs(y[1]) && abs(d[2]) * rest <= m_tol * abs(y[2]))
      return state{Real(0), Real(y[1] + d[1] * rest), Real(tau + rest), Real(y[2] + d[2] * rest)};
    return std::nullopt;
  }

  // Whether the endpoint system's jet about this state would overflow Real: its
  // coefficients grow like |v|/s^k, s = u^(1/Q) (linear law in double at gamma = 1e10,
  // g = -1: the creep ends at u ~ 1e-21, and |v|/s^20 ~ 1e410).
  bool endpoint_series_overflow(const state& at) const {
    using std::abs;
    using std::log;
    if (!m_c.use_root_variable) return false;  // sigma = ln u: scale-free
    const Real log_s = log(at.u) / Real(m_c.Q);
    const Real p = Real(taylor_order(m_tol));
    return log(abs(at.v)) - p * log_s > boost::math::tools::log_max_value<Real>() * 3 / 4;  // to spare
  }


  // turn -> spiral: entered after maximal compression once r = v/u^c <= -1/(2 sqrt c).
  bool enters_spiral(const state& s) const {
    using std::pow;
    if (!m_spiral_possible || !(s.v < 0)) return false;
    const Real r = s.v / pow(s.u, m_c.beta);
    return 4 * m_c.beta * r * r >= 1;
  }

  // ---- spiral (spiral_system): g = 0, alpha + 1 = 2 beta, underdamped ----
  // Takes the state where the turn phase entered the spiral and the maximal
  // compression u_max; integrates in sigma = ln u until the exit test of the turn
  // holds (for g = 0 and beta = c it reads r <= -2 gamma, with u <= u_max/2; r
  // falls monotonically). Returns the exit rescaled to u = 1, with the scale and
  // the relative error of e so far.
  spiral_end spiral_phase(taylor_integrator<Real, ss>& integ, const state& from, const Real& u_max) {
    using std::abs;
    using std::exp;
    using std::log;
    using std::pow;
    const auto& c = m_c;
    std::vector<Real> x{Real(from.v / pow(from.u, c.beta)), Real(from.tau * pow(from.u, c.beta - 1)), from.D}, x1(3);
    Real sigma = log(from.u);
    const Real sigma_exit = log(Real(u_max * m_switch_overlap));
    const Real r_exit = -2 * c.gamma;
    spiral_end out;
    // Relative error of e = |r| u^c at the exit: an error dr in r at r shifts
    // the exit sigma by c r^2/den(r) dr/r, den = 1 + gamma beta r + c r^2
    // (the sensitivity of int r dr/den); large on the slow spiral near critical
    // damping. Errors before the spiral enter relative to the motion's size.
    out.error = m_tol * static_cast<long>(m_steps) * (1 + sensitivity(x[ss::r]));
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
      out.error += m_tol * (1 + sensitivity(x[ss::r])) + c.beta * epsilon<Real>() * abs(sigma);
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
      out.error += 2 * boost::math::constants::pi<Real>() * xi * epsilon<Real>() / (gap * sqrt(gap));
    }
    // The exit runs on the problem scaled to u = 1 (u -> u/lambda, v -> v/lambda^c,
    // tau -> tau lambda^(c-1), D -> D/lambda^(2c), lambda = exp(sigma)), which
    // the equation does not see; unscale_spiral scales back. NOTE: unscaled, the
    // series in s about a tiny u overflow, and exp(sigma) itself may underflow
    // (docs/performance.md).
    out.log_scale = sigma;
    out.tau_before = x[ss::theta] * exp((1 - c.beta) * sigma);
    out.D_before = x[ss::D];
    out.scaled = state{Real(1), x[ss::r], Real(0), Real(0)};
    return out;
  }

  Real sensitivity(const Real& r) const {
    using std::abs;
    const Real den = 1 + m_c.gamma_beta * r + m_c.beta * r * r;
    return m_c.beta * r * r / abs(den);
  }

  // ---- exit: back to u = 0 in sigma ----
  // Takes the state where the turn left (v < 0, u <= u_max/2), or the spiral's
  // rescaled end (then spiral_error is its error, and each step adds tol to it);
  // integrates the endpoint system backwards to s = 0 (rational exponents) or to
  // u_eps = series_limit(|v|/2) (u = exp(sigma)). Returns the state there (u = 0 or u_eps).
  state exit_phase(taylor_integrator<Real, es>& integ, const state& from, Real* spiral_error) {
    using std::abs;
    using std::log;
    using std::pow;
    const auto& c = m_c;
    std::vector<Real> x{from.v, from.tau, from.D}, x1(3);
    Real sigma, target, u_eps = 0;
    if (c.use_root_variable) {
      sigma = pow(from.u, Real(1) / Real(c.Q));
      target = 0;
    } else {
      sigma = log(from.u);
      u_eps = series_limit(Real(abs(from.v) / 2));
      if (u_eps > from.u) u_eps = from.u;
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
      if (spiral_error) *spiral_error += m_tol;
      sigma = h == distance ? target : Real(sigma + h);
      x.swap(x1);
      if (!spiral_error) note_speed(x[es::v]);
    }
    return state{u_eps, x[es::v], x[es::tau], x[es::D]};
  }

  // Exit, u = exp(sigma) only: takes the state at u = u_eps and returns the
  // state at u = 0, from the leading terms of the generalized series (file comment).
  state close_by_series(state s) const {
    using std::pow;
    const auto& c = m_c;
    const Real u = s.u, V = -s.v;
    const Real u_beta = pow(u, c.beta);
    s.v = s.v - c.g * u / s.v + c.gamma * u_beta + pow(u, c.alpha_plus_one) / (c.alpha_plus_one * s.v);
    s.tau += u / V;
    s.D += c.two_gamma * V * u_beta;
    s.u = 0;
    return s;
  }

  // Exit, after the spiral: takes the state at u = 0 of the problem rescaled
  // at the spiral's end and returns it in the original units.
  state unscale_spiral(state s, const spiral_end& spiral) {
    using std::exp;
    const auto& c = m_c;
    s.v *= exp(c.beta * spiral.log_scale);
    s.tau = spiral.tau_before + s.tau * exp((1 - c.beta) * spiral.log_scale);
    s.D = spiral.D_before + s.D * exp(2 * c.beta * spiral.log_scale);
    note_speed(s.v);
    return s;
  }

  // Exit, last: takes the state at u = 0 (original units) and the spiral's
  // relative error of e (nullptr without a spiral); returns e, 1 - e, their
  // error estimate, the energy residual, and which identity e came from.
  // Two values of e: e_v = -v(T_f) from the trajectory and e_D = sqrt(1 - D)
  // from the energy identity. Their errors: e^2 from the trajectory is wrong by
  // about the energy residual plus the local errors (tol per step relative to
  // the energy scale, speed_scale^2); D has relative error tol per step.
  // An error d in e^2 is an error d / (e + sqrt(d)) in e.
  restitution<Real> choose_e(const state& end, const Real* spiral_error) const {
    using std::abs;
    using std::sqrt;
    restitution<Real> out;
    const Real e_v = -end.v;
    // NOTE: (1 - e)(1 + e) avoids the cancellation of 1 - e^2 for e near 0.
    out.energy_residual = (1 - e_v) * (1 + e_v) - end.D;
    const Real steps = Real(m_steps);
    const Real d_v = abs(out.energy_residual) + steps * m_tol * m_speed_scale * m_speed_scale;
    Real err_v = d_v / (e_v + sqrt(d_v));
    if (spiral_error) {
      // relative digits of a tiny e (see spiral_phase)
      Real err_s = e_v * *spiral_error;
      // underflowed to a subnormal or 0: relative digits are lost, absolute ones are not
      if (e_v < boost::math::tools::min_value<Real>()) err_s += boost::math::tools::min_value<Real>();
      if (err_s < err_v) err_v = err_s;
    }
    const Real one_minus_D = 1 - end.D;
    Real err_D = std::numeric_limits<Real>::infinity(), e_D = 0;
    const Real d_D = steps * m_tol * end.D + epsilon<Real>();
    if (one_minus_D > 0) {
      e_D = sqrt(one_minus_D);
      err_D = d_D / (e_D + sqrt(d_D));
    }
    // NOTE: e_D is used only where it resolves e (1 - D above its error): near
    // e = 0 it is the square root of rounding noise, while e_v may still be right.
    // NOTE: after a long creep (over m_creep_min_steps steps past maximal compression,
    // or the creep phase) e is small and D, summed over the creep, resolves e^2 = 1 - D only
    // to the sum of its steps' errors (linear law, gamma = 1e3, g = -1e-3: e = 1e-6
    // from D was off by 2e-4 relative), while the trajectory keeps v to relative
    // precision: there e_v is taken below e = 1/2.
    const bool trajectory_better = m_crept && e_v <= Real(1) / 2;
    if (err_D <= err_v && one_minus_D > d_D && !trajectory_better) {
      // 1 - e = D / (1 + e): full relative precision as gamma -> 0.
      out.source = e_source::dissipated_energy;
      out.one_minus_e = end.D / (1 + e_D);
      out.e = e_D > Real(1) / 2 ? Real(1 - out.one_minus_e) : e_D;
      if (e_D <= Real(1) / 2) out.one_minus_e = 1 - e_D;
      out.error_estimate = err_D;
    } else {
      out.source = e_source::trajectory;
      out.e = e_v;
      out.one_minus_e = 1 - e_v;
      out.error_estimate = err_v;
    }
    return out;
  }

  // ---- sticking ----
  // The stick outcome where the bead stopped (`at`): e = 0, the contact time and
  // stop overlap given. With check_energy (it turned at u_s > 0, 2E = 2P(u_s),
  // P(u) = u^(alpha+1)/(alpha+1) - g u) the energy identity must hold to within a
  // quarter of |P(u_s)|: reaching u = 0 instead would need an error that large.
  void stick(impact_result<Real>& result, const state& at, const std::optional<Real>& contact_time,
             const Real& stop_overlap, bool check_energy) const {
    using std::abs;
    using std::pow;
    result.outcome = impact_outcome::stick;
    result.e = 0;
    result.one_minus_e = 1;
    result.contact_time = contact_time;
    result.stop_overlap = stop_overlap;
    const Real two_E = at.v * at.v + 2 * pow(at.u, m_c.alpha_plus_one) / m_c.alpha_plus_one - 2 * m_c.g * at.u;
    result.energy_residual = 1 - two_E - at.D;
    result.error_estimate = 0;
    // NOTE: g = 1e12 in double loses all of e^2 ~ 1 against g u ~ 1e16: then
    // the energy identity fails by O(1) and no outcome can be certified.
    const Real budget = abs(two_E - at.v * at.v) / 4;
    if (check_energy && !(abs(result.energy_residual) < budget))
      throw certification_error("solve_impact (taylor): the energy identity (6) fails by " +
                                to_decimal_string(result.energy_residual, 3) +
                                " where the bead stops: the working precision (" +
                                std::to_string(decimal_digits<Real>()) + " digits) is too low for " + describe());
  }

  // g = 0, past maximal compression: the barrier w = c gamma u^beta (file comment)
  // proves creeps_to_origin. Deliberately the same barrier as the GBS solver's and the
  // proof's, written independently.
  sticking_proof creeps_to_origin(const state& s) const {
    using std::pow;
    const auto& c = m_c;
    if (c.g != 0 || c.gamma == 0 || !(s.v < 0)) return sticking_proof::none;
    const Real k = c.alpha_plus_one - 2 * c.beta;
    if (k < 0) return sticking_proof::none;
    const Real damping = c.gamma * pow(s.u, c.beta);
    const Real w = s.v + damping;
    if (!(w > 0)) return sticking_proof::none;
    Real ratio = w / damping;
    if (ratio > Real(1) / 2) ratio = Real(1) / 2;
    return pow(s.u, k) <= ratio * (1 - ratio) * c.gamma * c.gamma * c.beta ? sticking_proof::creeps_to_origin
                                                                              : sticking_proof::none;
  }

  // g > 0: the state is the equilibrium u_eq up to rounding. NOTE: near
  // critical damping a turn (v = 0) can come when the motion about u_eq is far
  // below the rounding of u (docs/performance.md); v then only decays or
  // jitters at rounding level, and no event would ever be seen.
  sticking_proof at_rest(const state& s) const {
    using std::abs;
    using std::pow;
    using std::sqrt;
    if (!(m_c.g > 0)) return sticking_proof::none;
    const Real du = 64 * epsilon<Real>() * m_u_eq;
    if (!(abs(s.u - m_u_eq) <= du)) return sticking_proof::none;
    // |v| against the speed of an oscillation of amplitude du: omega du, omega^2 = alpha u_eq^(alpha-1)
    return abs(s.v) <= du * sqrt(m_c.alpha * pow(m_u_eq, m_c.alpha - 1)) ? sticking_proof::at_rest
                                                                         : sticking_proof::none;
  }

  // g > 0, u > u_eq, v < 0: trapped in the sector -kappa (u - u_eq) <= v < 0.
  sticking_proof creeps_to_equilibrium_from_above(const state& s) const {
    using std::pow;
    using std::sqrt;
    const auto& c = m_c;
    if (!(s.u > m_u_eq) || !(s.v < 0)) return sticking_proof::none;
    const Real Gamma = c.gamma_beta * pow(m_u_eq, c.beta - 1);
    const Real A = c.alpha * pow(s.u, c.alpha - 1);
    const Real disc = Gamma * Gamma - 4 * A;
    if (disc < 0) return sticking_proof::none;
    const Real kappa = (Gamma + sqrt(disc)) / 2;
    return -s.v <= kappa * (s.u - m_u_eq) ? sticking_proof::creeps_to_equilibrium : sticking_proof::none;
  }

  // g > 0, u < u_eq, v > 0: trapped in 0 < v <= kappa (u_eq - u); u creeps up to u_eq.
  sticking_proof creeps_to_equilibrium_from_below(const state& s) const {
    using std::pow;
    using std::sqrt;
    const auto& c = m_c;
    if (!(c.g > 0) || c.gamma == 0) return sticking_proof::none;
    if (!(s.u < m_u_eq) || !(s.v > 0)) return sticking_proof::none;
    const Real Gamma = c.gamma_beta * pow(s.u, c.beta - 1);
    const Real A = c.alpha * pow(m_u_eq, c.alpha - 1);
    const Real disc = Gamma * Gamma - 4 * A;
    if (disc < 0) return sticking_proof::none;
    const Real kappa = (Gamma + sqrt(disc)) / 2;
    return s.v <= kappa * (m_u_eq - s.u) ? sticking_proof::creeps_to_equilibrium : sticking_proof::none;
  }

  // omega^2 = alpha u^(alpha-1), the stiffness at overlap u.
  Real stiffness_at(const Real& u) const {
    using std::pow;
    if (m_c.alpha_is_one) return Real(1);
    return m_c.alpha * pow(u, m_c.alpha - 1);
  }

  // u where the first-order terms of the generalized series at speed V are all
  // below tol V: g u/V, gamma u^beta, u^(alpha+1)/((alpha+1) V) <= tol V (and u <= tol).
  Real series_limit(const Real& V) const {
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

  impact_result<Real> finish(impact_result<Real>& result) const {
    result.steps = m_steps;
    return result;
  }

  // Fixed for the whole solve:
  const contact_law& m_law;
  const solve_options<Real>& m_options;
  const impact_constants<Real> m_c;
  Real m_tol;
  Real m_u_eq = 0;  // the static equilibrium g^(1/alpha) for g > 0, where a creeping bead rests; else 0
  Real m_u_growth = std::numeric_limits<Real>::infinity();  // 4^(1/(alpha-1)): omega^2 grows at most 4-fold
  bool m_spiral_possible = false;  // g = 0, alpha + 1 = 2 beta, underdamped: the spiral may follow the turn
  // Phase switches: leave the compress phase when v < m_switch_speed * peak v; enter
  // the exit only once u < m_switch_overlap * u_max (away from the turning point, which
  // limits the sigma steps, as u = 0 limits the tau steps).
  const Real m_switch_speed = Real(4) / 5, m_switch_overlap = Real(1) / 2;
  // The stiff-creep test (creep_out_of_reach) runs after m_creep_min_steps steps past maximal
  // compression (the fast transient has died) and gives up at m_creep_step_limit steps to go.
  const std::size_t m_creep_min_steps = 256;
  const Real m_creep_step_limit = 20000;
  // Accumulated by every phase, one meaning throughout:
  std::size_t m_steps = 0;  // steps taken so far (budget: m_options.max_steps)
  bool m_crept = false;     // a long creep past maximal compression: choose_e prefers the trajectory
  Real m_speed_scale = 1;   // largest |v| seen so far in original units: the scale of the local errors
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

// solve_impact_taylor is compiled once per scalar type into libviscor (src/instantiation.cpp.in):
// declared extern here, so that no unit including this header instantiates it again.
#define VISCOR_TAYLOR_TEMPLATES(PREFIX, Real) \
  PREFIX template impact_result<Real> solve_impact_taylor<Real>(const contact_law&, const Real&, const Real&, \
                                                                const solve_options<Real>&);
#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_REAL_WITH(VISCOR_TAYLOR_TEMPLATES, extern)
}
#endif
