// The impact problem solved by the GBS integrator (adaptive_integrator.hpp):
// viscor's second, independent method, with its own phase logic and event location.
//
// Names as in taylor_impact.hpp and core/contact_state.hpp: u the overlap, v = u' the
// velocity, tau the time, s = u^(1/Q); w = v + gamma u^beta. D is the dissipated energy
// of core/contact_state.hpp; this solver carries reduced_D = D/(2 gamma beta) =
// int v^2 u^(beta-1) dtau and applies the factor once, at the end.
//
// Formulation (endpoint-regularised, shared with the Taylor method because the
// exact solutions validate it): for rational alpha = p1/q1, beta = p2/q2 and
// Q = lcm(q1, q2), s = u^(1/Q) makes every power of u an integer power of s.
//  * Near u = 0, while u is monotone, s is the independent variable
//    (report eq. (4) divided by v = ds/dtau * Q s^(Q-1)):
//        dtau/ds = Q s^(Q-1)/v,  dw/ds = (g - s^(Q alpha)) dtau/ds,  v = w - gamma s^(Q beta),
//    analytic at s = 0 while v != 0: contact starts at s = 0 and ends exactly at s = 0.
//  * Around maximal compression (v = 0) tau is the independent variable with
//    state s: s' = v/(Q s^(Q-1)), w' = g - s^(Q alpha), analytic while s > 0.
//  * reduced_D rides along (dreduced_D/ds = Q v s^(Q beta - 1)), so 1 - e^2 =
//    2 gamma beta reduced_D and 1 - e = 2 gamma beta reduced_D/(1 + e) keep full
//    relative precision as gamma -> 0.
// The modes switch on r = u |u''|/v^2, the ratio of how near the tau-mode
// singularity (u = 0) and the s-mode singularity (v = 0) are: s -> tau when r > 1/2,
// tau -> s (on the way out) when r < 1/8.
//
// Phases (adaptive_impact_solver::solve; named as in core/impact_phase.hpp):
// compress_phase (s from 0 up) -> turn_phase (tau), which ends in {turns_back, creeps,
// sticks_at_unknown_time, undecided, leaves}, with creep_phase (Lobatto IIIC in u)
// inside it where creep_out_of_reach holds; leaves -> exit_phase (s down to 0), which
// ends in {done, back_to_tau, undecided}; back_to_tau -> turn_phase again.
//
// Events: sign changes of v are detected on the nodes of the finest midpoint
// column of each tau step and located by Newton's method on the step length,
// each iterate a fixed-order GBS step from the step's start. Sticking: v = 0 again
// with u > 0 after maximal compression (e = 0, contact_time = that time); the
// energy E = v^2/2 + u^(alpha+1)/(alpha+1) - g u never increases and equals
// e^2/2 at u = 0, so E < 0 proves sticking and sqrt(2E) bounds e; creeping into
// the equilibrium u* = g^(1/alpha) (g > 0, a trapping sector) or into u = 0
// (g = 0, a barrier) without turning back gives contact_time = +inf.
// Undecided (impact_outcome::undecided, contact_time unknown): what the solver cannot
// prove at its working precision: g = 0 with e <= sqrt(2E) below the tolerance but
// no barrier, or a state at rest to half the precision without a trapping sector
// or an energy proven negative (a turn back, if any, is below the precision); or a
// stiff creep past maximal compression that the steps cannot follow in reasonable
// time (creep_out_of_reach) at g > 0, or that creep_phase cannot follow, with e
// bounded by the energy.
// A non-finite state or derivative at the start of a GBS step is an error
// (convergence_error), not a step to retry.
//
// Exponents that are not such rationals (or need Q > max_regularising_denominator)
// use Q = 1 and real powers: u^alpha is then not analytic at u = 0, the error
// estimates near the end points lose their asymptotic footing and fewer digits
// come out; error_estimate still reports what the steps measured.
//
// Precision: GBS extrapolation amplifies rounding (adaptive_integrator.hpp), so the
// solve runs in detail::gbs_work<Real> (guard digits) and rounds the result to Real.
// Measurements behind the choices below: docs/performance.md, "impact/adaptive_impact.hpp".
#pragma once

#include <viscor/core/real_types.hpp>
#include <viscor/ode/adaptive_integrator.hpp>
#include <viscor/ode/lobatto_integrator.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/contact_state.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_phase.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/widen.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace viscor {

namespace detail {

/// Largest Q = lcm(q1, q2) for which the integer-power formulation is used.
inline constexpr std::int64_t max_regularising_denominator = 360;

/// result = x^n (n >= 0) by repeated squaring; `base` is scratch (no allocation
/// when both are reused, which matters for mpfr in the right-hand side). A scalar
/// power, not a series: taylor_series.hpp's powers are Taylor coefficients.
template <class Real>
void power_by_squaring(const Real& x, std::int64_t n, Real& result, Real& base) {
  result = 1;
  base = x;
  for (; n > 0; n >>= 1) {
    if (n & 1) result *= base;
    if (n > 1) base *= base;
  }
}

/// The contact law's powers of s = u^(1/Q), in the work type.
template <class W>
struct regularised_law {
  bool rational = false;
  std::int64_t Q = 1, Qa = 1, Qb = 1;  // Q, Q alpha, Q beta (rational case)
  W alpha, beta, gamma, g, gamma_beta, inv_alpha_plus_one;

  // NOTE: eval runs hundreds of times per GBS step, so the powers the right-hand
  // sides read, s^(Q-1), s^Q, s^(Q alpha), s^(Q beta - Q), s^(Q beta) and
  // s^(Q beta - 1), share one table s^0..s^M: s^k is (s^(k/2))^2 for even k and
  // s^(k-1) s for odd k, computed only when needed. Exponents above max_table fall
  // back to repeated squaring per power.
  static constexpr std::int64_t max_table = 24;
  enum slot { slot_sq1, slot_u, slot_ua, slot_ub1, slot_ub, slot_diss, slot_count };
  std::array<std::int64_t, slot_count> exponent_of{};  // rational case: the power of s in each slot
  std::vector<unsigned char> needed;                    // needed[k]: s^k is computed (table case)
  bool table = false;

  regularised_law(const contact_law& law, const W& gamma_, const W& g_) : gamma(gamma_), g(g_) {
    if (law.alpha.is_rational() && law.beta.is_rational()) {
      const exponent_multiples m = law.multiples();  // checked: refuses Q alpha beyond 64 bits
      if (m.Q <= max_regularising_denominator) {
        rational = true;
        Q = m.Q;
        Qa = m.Q_alpha;
        Qb = m.Q_beta;
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

  /// s^(Q-1), u = s^Q, u^alpha, u^beta, u^(beta-1) and s^(Q beta - 1) for s >= 0,
  /// read through the accessors after regularised_law::eval.
  struct powers {
    const W& sq1() const { return *slots[slot_sq1]; }
    const W& u() const { return *slots[slot_u]; }
    const W& ua() const { return *slots[slot_ua]; }
    const W& ub() const { return *slots[slot_ub]; }
    const W& ub1() const { return *slots[slot_ub1]; }
    const W& diss() const { return *slots[slot_diss]; }

    powers() = default;
    powers(const powers&) = delete;  // slots point into the own table
    powers& operator=(const powers&) = delete;

    std::vector<W> s_power;  // s_power[k] = s^k (table case) or the slots' own values
    std::array<const W*, slot_count> slots{};
    W scratch;
  };

  void eval(const W& s, powers& p) const {
    using std::pow;
    if (rational && table) {
      if (p.s_power.size() != needed.size()) {
        p.s_power.assign(needed.size(), W(0));
        p.s_power[0] = 1;
      }
      if (needed.size() > 1) p.s_power[1] = s;
      for (std::size_t k = 2; k < needed.size(); ++k) {
        if (!needed[k]) continue;
        if (k % 2 == 0)
          p.s_power[k] = p.s_power[k / 2] * p.s_power[k / 2];
        else
          p.s_power[k] = p.s_power[k - 1] * s;
      }
      for (int i = 0; i < slot_count; ++i) p.slots[i] = &p.s_power[static_cast<std::size_t>(exponent_of[i])];
      return;
    }
    if (p.s_power.size() != slot_count) p.s_power.assign(slot_count, W(0));
    for (int i = 0; i < slot_count; ++i) p.slots[i] = &p.s_power[i];
    if (rational) {
      for (int i = 0; i < slot_count; ++i) power_by_squaring(s, exponent_of[i], p.s_power[i], p.scratch);
    } else {
      p.s_power[slot_sq1] = 1;
      p.s_power[slot_u] = s;
      p.s_power[slot_ua] = pow(s, alpha);
      p.s_power[slot_ub1] = pow(s, beta - 1);
      p.s_power[slot_ub] = p.s_power[slot_ub1] * s;
      p.s_power[slot_diss] = p.s_power[slot_ub1];  // Q = 1: s^(Q beta - 1) = u^(beta-1)
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
  /// The velocity v = u' = w - gamma u^beta.
  W velocity(const W& w, const powers& p) const { return w - gamma * p.ub(); }
  /// Energy v^2/2 + u^(alpha+1)/(alpha+1) - g u.
  W energy(const W& v, const powers& p) const {
    return v * v / 2 + p.ua() * p.u() * inv_alpha_plus_one - g * p.u();
  }
  /// u |u''| with u'' = g - u^alpha - gamma beta u^(beta-1) v.
  W u_times_abs_acceleration(const W& v, const powers& p) const {
    using std::abs;
    return abs(p.u() * (g - p.ua()) - gamma_beta * p.ub() * v);
  }
};

/// A state of the three-component systems: (tau, w, reduced_D) in the s mode,
/// (s, w, reduced_D) in the tau mode (adaptive_impact_solver::in_s and in_tau name
/// the components).
template <class W>
using impact_state = std::array<W, 3>;

/// The s mode's independent variable s and its state y = (tau, w, reduced_D).
template <class W>
struct s_point {
  W s = 0;
  impact_state<W> y{};
};

/// The tau mode's time tau and its state z = (s, w, reduced_D).
template <class W>
struct tau_point {
  W tau = 0;
  impact_state<W> z{};
};

/// The adaptive solve in the work type W. eps_e: absolute tolerance on e (Real's epsilon).
template <class W>
class adaptive_impact_solver {
  // The components of the modes' states. reduced_D = D/(2 gamma beta), D the
  // dissipated energy of core/contact_state.hpp: the factor is applied once, at the
  // end (solve_impact_adaptive_in), not in every right-hand side.
  struct in_s {  // y, independent variable s = u^(1/Q)
    static constexpr std::size_t tau = 0, w = 1, reduced_D = 2;
  };
  struct in_tau {  // z, independent variable tau
    static constexpr std::size_t s = 0, w = 1, reduced_D = 2;
  };
  struct in_u {  // the creep's y, independent variable u (or ln u)
    static constexpr std::size_t u = 0, tau = 1, v = 2, reduced_D = 3;
  };
  static_assert(in_s::w == in_tau::w, "accumulate_error reads w at one index in both modes");

  /// What the turn phase has learnt about maximal compression; carried from one
  /// visit to the next (the exit may hand back to the turn).
  struct compression_record {
    bool passed = false;      ///< v has changed sign from + to - (maximal compression located)
    W time = 0, overlap = 0;  ///< tau and u there (+inf and u* = g^(1/alpha) for a creep that never turns)
    /// The energy shows e = 0 to the tolerance (E < 0, or g = 0 and 2E <= eps_e^2):
    /// the exit is closed.
    bool energy_stuck = false;
  };

  /// How the compress phase ended: where it stopped, and whether the bead is already
  /// trapped in the sector below u* (it creeps up to u* and sticks).
  struct compress_end {
    s_point<W> at;
    bool creeps = false;
  };

  /// How a visit to the turn phase ends (the Taylor solver's turn outcomes, but for
  /// its spirals and undamped).
  enum class turn_outcome {
    turns_back,  ///< v = 0 again with u > 0 after maximal compression: the bead sticks at that time
    creeps,      ///< the bead creeps to rest without turning back: it sticks, contact_time = +inf
    sticks_at_unknown_time,  ///< at rest with the energy proven negative: it sticks, contact_time unknown
    undecided,   ///< at rest, or e below the tolerance, without a proof of how the contact ends
    leaves,      ///< nearing u = 0 on the way out: the exit takes over
  };

  /// What a state near the equilibrium shows (creeps_to_equilibrium).
  enum class rest_verdict {
    moving,   ///< nothing proven: keep integrating
    trapped,  ///< inside a trapping sector: the bead creeps to u* and never turns back
    at_rest,  ///< at u* to half the precision, but not trapped: a turn back would be unresolvable
  };

  struct turn_end {
    turn_outcome outcome = turn_outcome::leaves;
    tau_point<W> at;  ///< where the turn phase stopped (leaves: where the exit starts)
    compression_record compression;
    std::optional<W> contact_time = W(0);  ///< turns_back: the time v = 0 again; creeps: +inf; undecided: empty
    W error = 0;         ///< undecided with g = 0: the energy bound sqrt(2|E|) on e
  };

  /// How the exit in s ends.
  enum class exit_outcome {
    done,         ///< s = 0 reached: y = (T_f, -e, reduced_D) at u = 0
    back_to_tau,  ///< v came too close to 0 again: the turn phase takes over at `at`
    undecided,    ///< a stiff creep out of reach of the steps (creep_out_of_reach)
  };

  struct exit_end {
    exit_outcome outcome = exit_outcome::done;
    s_point<W> at;  ///< done: s = 0 (or the series' end point) with y at u = 0
    W error = 0;    ///< undecided: the energy bound on e
  };

  /// What the nodes of a tau step show (scan_turning_points).
  enum class turn_scan { none, turned_back, not_located, passed_zero_overlap };

 public:
  adaptive_impact_solver(const contact_law& law, const W& gamma, const W& g, const W& rtol, const W& eps_e,
                         std::size_t max_steps, int max_columns, std::string where)
      : m_law(law, gamma, g),
        m_rtol(rtol),
        m_eps_e(eps_e),
        m_max_steps(max_steps),
        // absolute tolerances: on w only (tau or s, and reduced_D, are judged relative)
        m_s_int(rtol, impact_state<W>{W(0), rtol, W(0)}, max_columns),
        m_t_int(rtol, impact_state<W>{W(0), rtol, W(0)}, max_columns),
        m_where(std::move(where)) {
    m_s_int.set_keep_nodes(false);  // s steps cannot cross v = 0: no events to detect
    m_t_int.set_autonomous(true);   // t_rhs does not read tau
    m_s_int.set_read_components(2);  // s_rhs and t_rhs never read reduced_D
    m_t_int.set_read_components(2);
  }

  struct raw_result {
    W e = 0, reduced_D = 0, max_compression = 0, time_of_max = 0, error = 0;
    std::optional<W> contact_time = W(0);  ///< empty: unknown
    impact_outcome outcome = impact_outcome::rebound;
    std::size_t steps = 0;
  };

  /// The whole impact: compress, then turn and exit until the bead leaves (rebound)
  /// or sticks.
  raw_result solve() {
    const compress_end start = compress_phase();
    if (start.creeps) {
      // Creeps up to u* while still compressing: never reaches it, never turns back.
      raw_result r;
      r.outcome = impact_outcome::stick;
      r.contact_time = r.time_of_max = std::numeric_limits<W>::infinity();
      r.max_compression = pow(m_law.g, 1 / m_law.alpha);
      r.steps = m_steps;
      return r;
    }
    tau_point<W> at = to_tau(start.at);
    compression_record compression;
    for (;;) {
      const turn_end t = turn_phase(at, compression);
      compression = t.compression;
      raw_result r;
      r.max_compression = compression.overlap, r.time_of_max = compression.time;
      if (t.outcome != turn_outcome::leaves) {
        r.outcome = t.outcome == turn_outcome::undecided ? impact_outcome::undecided : impact_outcome::stick;
        r.contact_time = t.contact_time, r.error = t.error, r.steps = m_steps;
        return r;
      }
      const exit_end x = exit_phase(t.at);
      if (x.outcome == exit_outcome::undecided) {
        r.outcome = impact_outcome::undecided;
        r.contact_time = std::nullopt, r.error = x.error, r.steps = m_steps;
        return r;
      }
      if (x.outcome == exit_outcome::done) {
        r.e = -x.at.y[in_s::w], r.reduced_D = x.at.y[in_s::reduced_D], r.contact_time = x.at.y[in_s::tau];
        r.steps = m_steps;
        return r;
      }
      // NOTE: the 4x hysteresis between the switching ratios prevents ping-pong;
      // this guard keeps a pathological case from spinning through the budget.
      if (++m_switches > 64)
        throw convergence_error("solve_impact_adaptive: no progress between the s and tau modes for " + m_where);
      at = to_tau(x.at);
    }
  }

  const W& accumulated_error() const { return m_error; }

 private:
  static tau_point<W> to_tau(const s_point<W>& p) {
    return {p.y[in_s::tau], {p.s, p.y[in_s::w], p.y[in_s::reduced_D]}};
  }
  static s_point<W> to_s(const tau_point<W>& p) {
    return {p.z[in_tau::s], {p.tau, p.z[in_tau::w], p.z[in_tau::reduced_D]}};
  }

  // ---- compress: s up from 0 ----
  // Takes nothing (contact starts at u = 0 with v = 1); steps s up from 0 until
  // u |u''| > v^2/2, where the turn phase takes over in tau, or (g > 0) until the
  // state is in the trapping sector below u* (creeps: the bead creeps up to u* and
  // sticks). Returns the state where it stopped.
  // NOTE: with strong damping under a load the bead is pushed in at its terminal
  // speed and creeps up to u* without u |u''| ever exceeding v^2/2; the steps, bounded
  // by the fast damping scale, would exhaust any budget.
  compress_end compress_phase() {
    using std::abs;
    using std::pow;
    compress_end out;
    s_point<W>& p = out.at;
    p = {W(0), {W(0), W(1), W(0)}};
    // reduced_D ~ s^(Q beta) near s = 0, and a pure power of degree above the starting
    // extrapolation order has a step-size-independent relative error: start from the
    // series then (and always for real exponents). The order that counts is the one
    // GBS starts at (it only climbs on accepted steps), not the most it may use.
    if (!m_law.rational || m_law.Qb + m_law.Q > 2 * m_s_int.columns() - 2) start_by_series(p.s, p.y);
    const W scale = 1 + abs(m_law.g) + m_law.gamma;
    W h = pow(scale, -W(1) / W(m_law.Q)) / 8;
    auto rhs_s_up = [this](const W& s_, const impact_state<W>& y_, impact_state<W>& d) { return s_rhs(s_, y_, d, 1); };
    for (;;) {
      step_guard(h, p.s);
      if (!accepted(m_s_int.try_step(rhs_s_up, p.s, p.y, h), p.s)) continue;
      accumulate_error(m_s_int);
      if (switch_to_tau(p.s, p.y[in_s::w])) return out;
      if (m_law.g > 0) {
        typename regularised_law<W>::powers q;
        m_law.eval(p.s, q);
        if (creeps_to_equilibrium(p.s, m_law.velocity(p.y[in_s::w], q)) == rest_verdict::trapped) {
          out.creeps = true;
          return out;
        }
      }
    }
  }

  // ---- turn: tau, around maximal compression ----
  // Takes the state where an s mode handed over and what is known of maximal
  // compression; steps in tau until the bead turns back, creeps to rest, cannot be
  // decided at the precision, or nears u = 0 on the way out. Returns that outcome, the
  // state at the end, the updated compression record, the contact time and energy bound.
  turn_end turn_phase(tau_point<W> at, compression_record compression) {
    turn_end out;
    W h = initial_tau_step(at.z);
    for (;;) {
      W turned_back_at = 0;
      const std::optional<turn_scan> scan = turn_step(at, h, compression, turned_back_at);
      if (!scan) continue;  // rejected, or retried shorter
      if (*scan == turn_scan::turned_back) {
        out.outcome = turn_outcome::turns_back, out.contact_time = turned_back_at;
        break;
      }
      if (*scan == turn_scan::not_located) {
        // The bead turned back within the step (v > 0 at its accurate end after
        // maximal compression), but the turn could not be told from maximal compression.
        out.outcome = turn_outcome::undecided, out.contact_time = std::nullopt;
        break;
      }
      typename regularised_law<W>::powers p;
      m_law.eval(at.z[in_tau::s], p);
      const W v = m_law.velocity(at.z[in_tau::w], p);
      if (!compression.passed) {
        if (sticks_before_compression(at.z[in_tau::s], v, compression, out)) break;
        continue;
      }
      if (ends_after_compression(at, p, v, h, compression, out)) break;
    }
    out.at = at;
    out.compression = compression;
    return out;
  }

  // One tau step of the turn phase from `at` over h, its turning points scanned
  // (scan_turning_points); nothing if the step was rejected or must be retried
  // shorter (then `at` is unchanged and h shorter).
  std::optional<turn_scan> turn_step(tau_point<W>& at, W& h, compression_record& compression, W& turned_back_at) {
    auto rhs_t = [this](const W& t_, const impact_state<W>& z_, impact_state<W>& d) { return t_rhs(t_, z_, d); };
    const tau_point<W> start = at;
    step_guard(h, at.tau);
    if (!accepted(m_t_int.try_step(rhs_t, at.tau, at.z, h), at.tau)) return std::nullopt;
    if (!(at.z[in_tau::s] > 0)) {
      // NOTE: with integer exponents the stages may all stay in u > 0 while the
      // extrapolated end crosses u = 0: retry shorter (the exit takes over).
      h = (at.tau - start.tau) / 4;
      at = start;
      return std::nullopt;
    }
    const turn_scan scan = scan_turning_points(start, at.z, compression, turned_back_at);
    if (scan == turn_scan::passed_zero_overlap) {  // as above: retry shorter
      h = (at.tau - start.tau) / 4;
      at = start;
      return std::nullopt;
    }
    accumulate_error(m_t_int);
    return scan;
  }

  // After a turn step before maximal compression, at s with velocity v: whether the
  // bead rests at u* (g > 0); if so, out and compression say how.
  bool sticks_before_compression(const W& s, const W& v, compression_record& compression, turn_end& out) {
    using std::pow;
    const W inf = std::numeric_limits<W>::infinity(), nan = std::numeric_limits<W>::quiet_NaN();
    const rest_verdict rest = m_law.g > 0 ? creeps_to_equilibrium(s, v) : rest_verdict::moving;
    if (rest == rest_verdict::moving) return false;
    const bool trapped = rest == rest_verdict::trapped;
    compression.overlap = pow(m_law.g, 1 / m_law.alpha), compression.time = trapped ? inf : nan;
    out.outcome = trapped ? turn_outcome::creeps : turn_outcome::undecided;
    out.contact_time = trapped ? std::optional<W>(inf) : std::nullopt;
    return true;
  }

  // After a turn step past maximal compression, at `at` (powers p, velocity v, next
  // step h): whether the turn ends here (it creeps, sticks, is undecided, or leaves for
  // the exit, possibly after the creep phase); if so, out says how.
  bool ends_after_compression(tau_point<W>& at, const typename regularised_law<W>::powers& p, const W& v,
                              const W& h, compression_record& compression, turn_end& out) {
    using std::abs;
    using std::sqrt;
    const W inf = std::numeric_limits<W>::infinity();
    if (m_law.g == 0 && creeps_to_origin(at.z[in_tau::s], at.z[in_tau::w])) {
      out.outcome = turn_outcome::creeps, out.contact_time = inf;
      return true;
    }
    // NOTE: the trapping sector is a proof at any time, not only once the energy is
    // spent: a strongly damped bead pressed past u* creeps back down to it on the
    // slow manifold, inside the sector from the start, while E > 0 still bounds e
    // by ~1e-2 (Hunt-Crossley, gamma = 1e4, g = 1e-3: else undecided by
    // creep_out_of_reach at every precision).
    if (m_law.g > 0 && creeps_to_equilibrium(at.z[in_tau::s], v) == rest_verdict::trapped) {
      out.outcome = turn_outcome::creeps, out.contact_time = inf;
      return true;
    }
    if (creep_out_of_reach(p, v, p.u() / abs(v) / h)) {
      // g <= 0: no turn back is possible (u'' = g - u^alpha < 0 at v = 0): implicit steps
      const std::optional<tau_point<W>> crept = m_law.g <= 0 ? creep_phase(at) : std::nullopt;
      if (crept) {
        at = *crept;
        out.outcome = turn_outcome::leaves;
        return true;
      }
      out.outcome = turn_outcome::undecided, out.contact_time = std::nullopt, out.error = energy_bound_on_e(v, p);
      return true;
    }
    const W energy = m_law.energy(v, p);
    if (m_law.g >= 0 && 2 * energy <= m_eps_e * m_eps_e) {
      // e <= sqrt(2E) is below the tolerance: the exit is closed to it. With g = 0
      // nothing more can be learnt: the bead cannot turn back (u'' = -u^alpha < 0 at
      // v = 0), and whether it leaves with such an e or creeps into u = 0 (no barrier
      // above) is beyond the precision.
      if (m_law.g == 0 || energy < 0) compression.energy_stuck = true;
      if (m_law.g == 0) {
        out.outcome = turn_outcome::undecided, out.contact_time = std::nullopt, out.error = sqrt(2 * abs(energy));
        return true;
      }
    }
    if (compression.energy_stuck && m_law.g > 0) {
      const rest_verdict rest = creeps_to_equilibrium(at.z[in_tau::s], v);
      if (rest != rest_verdict::moving) {
        // NOTE: E never increases and is v^2/2 >= 0 at u = 0, so E < 0 beyond its
        // error proves the stick even where the settling is not trapped (nearly
        // critically damped: Hunt-Crossley, gamma = 0.0063, g = 426). When it turns
        // back (the contact time) is below the precision: unknown, not +inf (linear law,
        // gamma = 1.9999, g = 0.5 turns back at tau = 316).
        const bool trapped = rest == rest_verdict::trapped;
        out.outcome = trapped                                  ? turn_outcome::creeps
                      : energy_proven_negative(energy, v, p) ? turn_outcome::sticks_at_unknown_time
                                                               : turn_outcome::undecided;
        out.contact_time = trapped ? std::optional<W>(inf) : std::nullopt;
        return true;
      }
    }
    if (!compression.energy_stuck && v < 0 && m_law.u_times_abs_acceleration(v, p) * 8 < v * v) {
      out.outcome = turn_outcome::leaves;
      return true;
    }
    return false;
  }

  // A root of v in the last tau step (between nodes m - 1 and m), located and
  // checked: net_load = g - u^alpha there (u'' at v = 0: <= 0 at maximal
  // compression, > 0 where the bead turns back), noise its rounding level.
  struct located_turn {
    W time, overlap, net_load, noise;
    bool confirmed = false;
  };
  located_turn locate_turn(const tau_point<W>& start, std::size_t m) {
    using std::abs;
    located_turn turn;
    impact_state<W> at;
    turn.time = locate_turning_point(start.tau, start.z, m, at, &turn.confirmed);
    typename regularised_law<W>::powers p;
    m_law.eval(at[in_tau::s], p);
    turn.overlap = p.u();
    turn.net_load = m_law.g - p.ua();
    turn.noise = 64 * epsilon<W>() * (abs(m_law.g) + p.ua());
    return turn;
  }

  // Sign changes of v on the last tau step's nodes (the last replaced by the
  // accurate end state): maximal compression (+ to -) updates `compression`;
  // turning back (- to +) after it returns turned_back with its time in `turned_back_at`;
  // a sign change located at u <= 0 returns passed_zero_overlap (the step is too long).
  turn_scan scan_turning_points(const tau_point<W>& start, const impact_state<W>& end,
                                compression_record& compression, W& turned_back_at) {
    const auto& nodes = m_t_int.nodes();
    m_v_nodes.resize(nodes.size());
    for (std::size_t m = 0; m + 1 < nodes.size(); ++m) m_v_nodes[m] = velocity_of(nodes[m]);
    m_v_nodes.back() = velocity_of(end);
    for (std::size_t m = 1; m < nodes.size(); ++m) {
      const W& v_prev = m_v_nodes[m - 1];
      const W& v_next = m_v_nodes[m];
      if (!compression.passed && v_prev > 0 && v_next <= 0) {
        // As for a turn back (below): the nodes may show a sign change the accurate
        // states do not have. Maximal compression needs u'' = g - u^alpha <= 0 at v = 0;
        // a sign change of the accurate v over the step is one whatever Newton found.
        const located_turn turn = locate_turn(start, m);
        const bool accurate_sign_change = velocity_of(start.z) > 0 && !(m_v_nodes.back() > 0);
        if (!accurate_sign_change && !(turn.confirmed && turn.net_load <= turn.noise)) continue;
        compression.time = turn.time;
        compression.overlap = turn.overlap;
        compression.passed = true;
      } else if (compression.passed && v_prev < 0 && v_next >= 0) {
        // NOTE: the nodes are low-order midpoint values, not the step's accurate result:
        // where |v| is far below their error (a nearly critically damped settling, linear
        // law, gamma = 1.9999, g = 0.5: |v| ~ 1e-11 at tau ~ 27) they show sign changes
        // that the accurate states do not have. A turn counts only if locating it confirms it.
        // A turn back is also where u'' = g - u^alpha > 0 at v = 0 (u below u*): a
        // root found above u* is maximal compression again (same step) or noise.
        const located_turn turn = locate_turn(start, m);
        // A turn at u <= 0 is no turn back: the step went through u = 0 (the bead
        // left with a tiny e) and on along the continued motion below the wall.
        if (!(turn.overlap > 0)) return turn_scan::passed_zero_overlap;
        if (turn.confirmed && turn.time > compression.time && turn.net_load > turn.noise) {
          turned_back_at = turn.time;
          return turn_scan::turned_back;
        }
        // The accurate v went from < 0 (after maximal compression, at the step's
        // start) to > 0 at its end: a turn back that Newton could not isolate.
        if (compression.time <= start.tau && velocity_of(start.z) < 0 && m_v_nodes.back() > 0)
          return turn_scan::not_located;
      }
    }
    return turn_scan::none;
  }

  // ---- exit: s down to 0 ----
  // Takes the state where the turn phase left (v < 0, nearing u = 0); steps s down to
  // 0 (to the series' end point for real exponents, then close_by_series). Returns
  // done with y = (T_f, -e, reduced_D) at u = 0, or back_to_tau with the state where v
  // came too close to 0 again for the s mode.
  exit_end exit_phase(const tau_point<W>& from) {
    exit_end out;
    s_point<W>& p = out.at;
    p = to_s(from);
    // NOTE: a short first step (s/8): a rejection costs a whole step, a short first step half of one.
    W h = -p.s / 8;
    auto rhs_s_down = [this](const W& s_, const impact_state<W>& y_, impact_state<W>& d) {
      return s_rhs(s_, y_, d, -1);
    };
    W s_end = m_law.rational ? W(0) : series_end_point(p.y[in_s::w]);
    for (;;) {
      if (-h > p.s - s_end) h = s_end - p.s;
      step_guard(h, p.s);
      if (!accepted(m_s_int.try_step(rhs_s_down, p.s, p.y, h), p.s)) continue;
      accumulate_error(m_s_int);
      if (!m_law.rational) s_end = series_end_point(p.y[in_s::w]);
      if (p.s <= s_end) {
        if (!m_law.rational) close_by_series(p.s, p.y);
        out.outcome = exit_outcome::done;
        return out;
      }
      if (switch_to_tau(p.s, p.y[in_s::w])) {
        out.outcome = exit_outcome::back_to_tau;
        return out;
      }
      typename regularised_law<W>::powers q;
      m_law.eval(p.s, q);
      const W v = m_law.velocity(p.y[in_s::w], q);
      using std::abs;
      if (creep_out_of_reach(q, v, p.s / abs(h))) {
        const std::optional<tau_point<W>> crept = m_law.g <= 0 ? creep_phase(to_tau(p)) : std::nullopt;
        if (!crept) {
          out.outcome = exit_outcome::undecided, out.error = energy_bound_on_e(v, q);
          return out;
        }
        p = to_s(*crept);
        h = -p.s / 8;
        if (!m_law.rational) s_end = series_end_point(p.y[in_s::w]);
      }
    }
  }

  // turn or exit -> creep: past maximal compression with strong damping the bead moves
  // along the slow manifold v ~ (g - u^alpha)/(gamma beta u^(beta-1)), over a time u/|v|
  // far longer than the damping time 1/(gamma beta u^(beta-1)) that bounds the GBS steps
  // (in tau, and in s as well): a stiff motion. Called once per accepted step past
  // maximal compression with the state's powers p, its velocity v and the number of
  // steps still to go at the current step (remaining distance over step); true when,
  // after creep_min_steps such steps, the motion is stiff (ratio above 1000) and more
  // than creep_step_limit steps are still to go: the solve then hands the creep to
  // creep_phase (g <= 0) or ends as undecided (g > 0), instead of exhausting the
  // budget (linear law, gamma = 1e10, g = -1). NOTE: for g <= 0 the limit is 2000: a
  // 50-digit GBS step is costly, Tsuji at gamma = 1e2, g = -1e-3 took 12,873 of them
  // with never more than 20,000 to go; the Lobatto creep takes it in a few hundred.
  bool creep_out_of_reach(const typename regularised_law<W>::powers& p, const W& v, const W& steps_to_go) {
    using std::abs;
    constexpr std::size_t creep_min_steps = 256;
    const W creep_step_limit = m_law.g <= 0 ? 2000 : 20000;
    if (++m_creep_steps <= creep_min_steps || !(v < 0) || !(m_law.gamma > 0)) return false;
    const W damping_time = 1 / (m_law.gamma_beta * p.ub1());
    const W slow_time = p.u() / abs(v);
    return slow_time > 1000 * damping_time && steps_to_go > creep_step_limit;
  }

  // The creep's equations in u for the Lobatto steps (creep_phase), y = (u, tau, v,
  // reduced_D) with u' = 1; rates_in_u() are those in u, step_rates() those in the step
  // variable (u, or sigma = ln u: d/dsigma = u d/du); jacobian() is that of step_rates.
  class creep_system {
   public:
    using vec = std::array<W, 4>;

    creep_system(const regularised_law<W>& law, bool in_log) : m_law(law), m_in_log(in_log) {
      const W& a = m_law.alpha;
      const W& b = m_law.beta;
      p_b1 = plan(b - 1), p_a = plan(a), p_b2 = plan(b - 2), p_a1 = plan(a - 1);
    }

    bool rates_in_u(const vec& y, vec& d) const {
      const W& a = m_law.alpha;
      const W& b = m_law.beta;
      if (!(y[in_u::u] > 0) || !(y[in_u::v] < 0)) return false;
      const W ub1 = raise(y[in_u::u], b - 1, p_b1);
      d[in_u::u] = 1;
      d[in_u::tau] = 1 / y[in_u::v];
      d[in_u::v] = (m_law.g - raise(y[in_u::u], a, p_a)) / y[in_u::v] - m_law.gamma_beta * ub1;
      d[in_u::reduced_D] = y[in_u::v] * ub1;
      return true;
    }

    bool step_rates(const vec& y, vec& d) const {
      if (!rates_in_u(y, d)) return false;
      if (m_in_log)
        for (W& x : d) x *= y[in_u::u];
      return true;
    }

    void jacobian(const vec& y, std::array<vec, 4>& J) const {
      jacobian_in_u(y, J);
      if (!m_in_log) return;
      vec d;
      rates_in_u(y, d);  // d(u f)/dy = u df/dy + f e_u^T
      for (std::size_t i = 0; i < 4; ++i) {
        for (W& x : J[i]) x *= y[in_u::u];
        J[i][in_u::u] += d[i];
      }
    }

   private:
    // u^x for the four exponents used here. NOTE: when 2 alpha and 2 beta are whole
    // (every named law but Tsuji) and for Tsuji's 4 beta, from sqrt(u), sqrt(sqrt(u))
    // and products rather than pow (exp of log): pow was a third of a 50-digit creep.
    struct root_power {
      int quarters = 0;  // x = quarters / 4
      bool exact = false;
    };
    static root_power plan(const W& x) {
      using std::floor;
      root_power r;
      const W q = x * 4;
      r.exact = q == floor(q) && q >= -64 && q <= 64;
      if (r.exact) r.quarters = static_cast<int>(q);
      return r;
    }
    static W raise(const W& u, const W& x, const root_power& r) {
      using std::pow;
      using std::sqrt;
      if (!r.exact) return pow(u, x);
      int k = r.quarters < 0 ? -r.quarters : r.quarters;
      W out = 1;
      if (k % 4 != 0) {
        const W half = sqrt(u);
        if (k % 4 >= 2) out = half;
        if (k % 2 != 0) out *= sqrt(half);
      }
      for (k /= 4; k > 0; --k) out *= u;
      return r.quarters < 0 ? W(1 / out) : out;
    }
    // Rows and columns in the order of in_u: u, tau, v, reduced_D.
    void jacobian_in_u(const vec& y, std::array<vec, 4>& J) const {
      const W& a = m_law.alpha;
      const W& b = m_law.beta;
      const W u = y[in_u::u], v = y[in_u::v];
      const W ub2 = raise(u, b - 2, p_b2), ua1 = raise(u, a - 1, p_a1);
      const W zero = 0;
      J[in_u::u] = vec{zero, zero, zero, zero};
      J[in_u::tau] = vec{zero, zero, W(-1 / (v * v)), zero};
      J[in_u::v] = vec{W(-a * ua1 / v - m_law.gamma_beta * (b - 1) * ub2), zero, W(-(m_law.g - ua1 * u) / (v * v)), zero};
      J[in_u::reduced_D] = vec{W(v * (b - 1) * ub2), zero, W(ub2 * u), zero};
    }

    const regularised_law<W>& m_law;
    bool m_in_log;
    root_power p_b1, p_a, p_b2, p_a1;
  };

  // ---- creep: the stiff creep out, g <= 0 ----
  // The stiff creep out (g <= 0, past maximal compression, v < 0) by Lobatto IIIC
  // (ode/lobatto_integrator.hpp; s = max(3, digits/3 + 2) stages, order 2s - 2), with
  // the overlap u as the independent variable (u falls monotonically: v < 0 throughout,
  // as u'' = g - u^alpha < 0 wherever v = 0) and states (tau, v, reduced_D), carried as
  // y = (u, tau, v, reduced_D) with u' = 1:
  //   dtau/du = 1/v,  dv/du = (g - u^alpha)/v - gamma beta u^(beta-1),  dreduced_D/du = v u^(beta-1),
  // until the motion is no longer stiff: the damping time 1/(gamma beta u^(beta-1))
  // exceeds the slow time u/|v|. NOTE: v, not w = v + gamma u^beta: on the creep |v| is
  // far below gamma u^beta, and v = w - gamma u^beta would lose the digits of that ratio.
  // For a work type wider than long double the steps are taken in sigma = ln u instead
  // (d/dsigma = u d/du, u' = u): the solution has powers of u, whose Taylor radius in u
  // is u itself (steps of u/20 at 50 digits), but is entire in sigma (steps of 0.3, a
  // factor 1.35 in u): about a sixth of the steps (Kuwabara-Kono, gamma = 1e10, g = 0,
  // 50 digits). NOTE: not in long double (double results): there the sigma steps stall
  // at a step-doubling difference of ~100 ulps in v that does not fall with the step
  // (measured: Kuwabara-Kono, gamma 1e3..1e8, g = 0; 60,000+ steps); not understood, so
  // the proven u form is kept there.
  // Returns the turn phase's state there, or nothing if the steps fail (then undecided).
  std::optional<tau_point<W>> creep_phase(const tau_point<W>& from) {
    using std::abs;
    using std::pow;
    using vec = std::array<W, 4>;
    const W& b = m_law.beta;
    const int stages = std::max(3, decimal_digits<W>() / 3 + 2);
    // NOTE: the step-doubling difference carries rounding of a few ulps: a tolerance
    // below 32 ulps would shrink the steps to underflow.
    const W floor = 32 * epsilon<W>();
    lobatto_integrator<W, 4> lobatto(stages, m_rtol > floor ? m_rtol : floor);
    const bool in_log = binary_digits<W>() > std::numeric_limits<long double>::digits;
    const creep_system sys(m_law, in_log);
    auto f = [&sys](const vec& y, vec& d) { return sys.step_rates(y, d); };
    auto jacobian = [&sys](const vec& y, std::array<vec, 4>& J) { sys.jacobian(y, J); };
    typename regularised_law<W>::powers q;
    m_law.eval(from.z[in_tau::s], q);
    vec y{q.u(), from.tau, m_law.velocity(from.z[in_tau::w], q), from.z[in_tau::reduced_D]};
    W h = in_log ? W(-1) / 64 : W(-y[in_u::u] / 64), taken = 0;
    for (;;) {
      if (!(y[in_u::v] < 0)) return std::nullopt;  // cannot happen for g <= 0: the steps went wrong
      const W damping = m_law.gamma_beta * pow(y[in_u::u], b - 1);
      if (damping * y[in_u::u] <= abs(y[in_u::v])) {
        // hand back in the turn phase's variables: s = u^(1/Q), w = v + gamma u^beta
        const W s = m_law.Q == 1 ? y[in_u::u] : W(pow(y[in_u::u], 1 / W(m_law.Q)));
        return tau_point<W>{y[in_u::tau],
                            {s, W(y[in_u::v] + m_law.gamma * pow(y[in_u::u], b)), y[in_u::reduced_D]}};
      }
      // the stages stay in u >= u/2 > 0; in sigma, u falls by at most e per step
      const W longest = in_log ? W(1) : W(y[in_u::u] / 2);
      if (-h > longest) h = -longest;
      const vec scales{y[in_u::u], abs(y[in_u::tau]), abs(y[in_u::v]),
                       abs(y[in_u::reduced_D]) > 0 ? abs(y[in_u::reduced_D]) : W(1)};
      step_guard(h, in_log ? W(1) : y[in_u::u]);
      if (!lobatto.try_step(f, jacobian, y, h, scales, taken)) continue;
      m_error += m_rtol * abs(y[in_u::v]);
    }
  }

  // e <= sqrt(2E): E = v^2/2 + u^(alpha+1)/(alpha+1) - g u never increases and is
  // e^2/2 at u = 0; E is raised by its rounding and the error carried in w (as in
  // energy_proven_negative), and the bound doubled.
  W energy_bound_on_e(const W& v, const typename regularised_law<W>::powers& p) const {
    using std::abs;
    using std::sqrt;
    const W terms = v * v / 2 + p.ua() * p.u() * m_law.inv_alpha_plus_one + abs(m_law.g) * p.u();
    const W margin = 64 * (epsilon<W>() * terms + m_error * (abs(v) + abs(p.ua() - m_law.g) + 1));
    const W two_E = 2 * (m_law.energy(v, p) + margin);
    return 2 * sqrt(two_E > 0 ? two_E : W(0));
  }

  // ---- the end points for real exponents ----
  // NOTE: real (non-rational) exponents, u = s: u^alpha is not analytic at u = 0,
  // so the first and last stretch [0, u_eps] use the generalized series of the
  // solution in powers u, u^beta, u^(alpha+1) to first order. With every first-order
  // term x in {g u/w^2, gamma u^beta/w, u^(alpha+1)/w^2} kept below sqrt(tol)/4, the
  // neglected products of two of them are below tol/16 relative.
  // Deliberately the same first-order series argument as taylor_impact.hpp's exit
  // phase, written independently (a shared proof is a shared blind spot).
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
  // Contact start (w = 1 at u = 0): tau, w, reduced_D at u = u_eps, s = u_eps^(1/Q).
  void start_by_series(W& s, impact_state<W>& y) const {
    using std::pow;
    const W& a = m_law.alpha;
    const W& b = m_law.beta;
    typename regularised_law<W>::powers p;
    s = m_law.Q == 1 ? series_limit(W(1)) : W(pow(series_limit(W(1)), W(1) / W(m_law.Q)));
    m_law.eval(s, p);
    const W u = p.u();
    const W ua1 = p.ua() * u, ub = p.ub();
    y[in_s::tau] = u - m_law.g * u * u / 2 + m_law.gamma * ub * u / (b + 1) + ua1 * u / ((a + 1) * (a + 2));
    y[in_s::w] = 1 + m_law.g * u - ua1 / (a + 1);
    y[in_s::reduced_D] = ub / b + m_law.g * ub * u / (b + 1) - m_law.gamma * ub * ub / (2 * b) - ua1 * ub / ((a + 1) * (a + b + 1));
  }
  // Where the way out may hand over to the series (w ~ v there).
  W series_end_point(const W& w) const {
    using std::abs;
    return series_limit(W(abs(w)));
  }
  // Contact end: from (tau, w, reduced_D) at u = s to u = 0, where w0 = v = -e.
  void close_by_series(const W& u, impact_state<W>& y) const {
    using std::pow;
    const W& a = m_law.alpha;
    const W& b = m_law.beta;
    const W ua1 = pow(u, a + 1), ub = pow(u, b);
    const W c = m_law.g * u - ua1 / (a + 1);  // w(u) = w0 + c/w0 + ...
    const W w0 = y[in_s::w] - c / y[in_s::w];
    const W w0_2 = w0 * w0;
    y[in_s::tau] -= (u - (m_law.g * u * u / 2 - ua1 * u / ((a + 1) * (a + 2))) / w0_2 + m_law.gamma * ub * u / ((b + 1) * w0)) / w0;
    y[in_s::reduced_D] += -w0 * ub / b - (m_law.g * ub * u / (b + 1) - ua1 * ub / ((a + 1) * (a + b + 1))) / w0 +
            m_law.gamma * ub * ub / (2 * b);
    y[in_s::w] = w0;
  }

  // ---- right-hand sides ----
  // s mode on (tau, w, reduced_D); direction +1 on the way in (v > 0), -1 on the way out.
  bool s_rhs(const W& s, const impact_state<W>& y, impact_state<W>& d, int direction) {
    if (s < 0) return false;
    // NOTE: written as in-place single operations (no fused multiply-adds, no
    // expression temporaries); runs hundreds of times per step.
    m_law.eval(s, m_p);
    m_tmp = m_law.gamma * m_p.ub();
    m_v = y[in_s::w] - m_tmp;
    if (direction > 0 ? !(m_v > 0) : !(m_v < 0)) return false;
    d[in_s::tau] = m_p.sq1();
    m_law.times_Q(d[in_s::tau]);
    d[in_s::tau] /= m_v;  // dtau/ds = Q s^(Q-1) / v
    d[in_s::w] = m_law.g - m_p.ua();
    d[in_s::w] *= d[in_s::tau];
    d[in_s::reduced_D] = m_v * m_law.s_power_for_dissipation(m_p);
    m_law.times_Q(d[in_s::reduced_D]);
    return true;
  }

  // tau mode on (s, w, reduced_D).
  bool t_rhs(const W&, const impact_state<W>& z, impact_state<W>& d) {
    if (!(z[in_tau::s] > 0)) return false;
    m_law.eval(z[in_tau::s], m_p);
    m_tmp = m_law.gamma * m_p.ub();
    m_v = z[in_tau::w] - m_tmp;
    m_tmp = m_p.sq1();
    m_law.times_Q(m_tmp);
    d[in_tau::s] = m_v / m_tmp;  // s' = v / (Q s^(Q-1))
    d[in_tau::w] = m_law.g - m_p.ua();
    d[in_tau::reduced_D] = m_v * m_v;
    d[in_tau::reduced_D] *= m_p.ub1();
    return true;
  }

  // v at a tau-mode state (s, w, reduced_D).
  W velocity_of(const impact_state<W>& z) {
    m_law.eval(z[in_tau::s], m_p);
    return z[in_tau::w] - m_law.gamma * m_p.ub();
  }

  // s -> tau when u |u''| > v^2/2 (or v is no longer safely away from 0).
  bool switch_to_tau(const W& s, const W& w) {
    typename regularised_law<W>::powers p;
    m_law.eval(s, p);
    const W v = m_law.velocity(w, p);
    return 2 * m_law.u_times_abs_acceleration(v, p) > v * v;
  }

  // First tau step: u/(8|v|), capped at 1/8 (a short first step costs less than a rejection).
  W initial_tau_step(const impact_state<W>& z) {
    using std::abs;
    typename regularised_law<W>::powers p;
    m_law.eval(z[in_tau::s], p);
    const W v = m_law.velocity(z[in_tau::w], p);
    W h = p.u() / (8 * abs(v));
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

  // The error estimate of w (component in_s::w = in_tau::w) of the last accepted step.
  void accumulate_error(const gbs_integrator<W, 3>& integ) { m_error += integ.last_error_vector()[in_s::w]; }

  // Whether a GBS step was accepted; a non-finite state or derivative at its start is
  // an error, since no shorter step can cure it.
  bool accepted(gbs_status st, const W& t) const {
    if (st == gbs_status::non_finite)
      throw convergence_error("solve_impact_adaptive: non-finite state or derivative at t = " +
                              to_decimal_string(t, 20) + " for " + m_where);
    return st == gbs_status::accepted;
  }

  // ---- events and rest ----
  // Newton on the step length for v = 0 between nodes m-1 and m of the last tau
  // step from (tau0, z0). Returns the time of the turning point and the state there in `at`;
  // `confirmed` (if given) says whether the accurate states show the root: Newton
  // converged, an iterate has v of the other sign than at tau0, or the best |v| is
  // within the rounding noise of v = w - gamma u^beta.
  W locate_turning_point(const W& tau0, const impact_state<W>& z0, std::size_t m, impact_state<W>& at,
                         bool* confirmed = nullptr) {
    using std::abs;
    using std::sqrt;
    auto rhs_t = [this](const W& t_, const impact_state<W>& z_, impact_state<W>& d) { return t_rhs(t_, z_, d); };
    const auto& times = m_t_int.node_times();
    const int columns = m_t_int.last_columns();
    const W H = times.back() - tau0;
    const W a = times[m - 1] - tau0, b = times[m] - tau0;
    const W fa = m_v_nodes[m - 1], fb = m_v_nodes[m];
    W h = (fa == fb) ? W((a + b) / 2) : W(a + (b - a) * fa / (fa - fb));
    // NOTE: Newton converges quadratically until rounding noise in the fixed step
    // dominates; then the corrections stop shrinking and the best iterate is kept.
    // Each iterate costs a whole GBS step, so it stops as soon as the correction
    // delta is below sqrt(eps)/16 of the time scale: the next iterate is then right
    // to O(delta^2) (quadratic convergence), and the state is taken where it was
    // computed, at distance delta from the root, where v = O(delta) and u is off by
    // O(u'' delta^2) <= eps/256 relative: no further step is needed for either.
    const int budget = 4 * binary_digits<W>() + 20;
    const W sqrt_eps = sqrt(epsilon<W>());
    // NOTE: where u'' is tiny at the root (a turn back into a nearly critically
    // damped settling: linear law, gamma = 1.93, g = 87) v is rounding noise over a
    // band of ~noise/|u''| and Newton wanders inside it with corrections far above
    // sqrt(eps); eight iterates without a smaller |v| end the search at the best one.
    W best_h = h, best_v = -1, previous_delta = -1, noise = 0;
    int since_best = 0;
    const bool starts_positive = velocity_of(z0) > 0;
    bool crossed = false;
    auto found = [&](bool sure) {
      if (confirmed) *confirmed = sure || crossed || best_v <= noise;
    };
    for (int it = 0; it < budget; ++it) {
      if (!m_t_int.fixed_step(rhs_t, tau0, z0, h, columns, at))
        throw convergence_error("solve_impact_adaptive: event location left the domain for " + m_where);
      typename regularised_law<W>::powers p;
      m_law.eval(at[in_tau::s], p);
      const W v = m_law.velocity(at[in_tau::w], p);
      if (v == 0 || (v > 0) != starts_positive) crossed = true;
      // Rounding of v = w - gamma u^beta (64 ulps of the larger term) and the error carried in w.
      noise = 64 * (epsilon<W>() * (abs(at[in_tau::w]) + m_law.gamma * p.ub()) + m_error);
      if (best_v < 0 || abs(v) < best_v) {
        best_v = abs(v), best_h = h, since_best = 0;
      } else if (++since_best >= 8) {
        h = best_h;
        m_t_int.fixed_step(rhs_t, tau0, z0, h, columns, at);
        found(false);
        return tau0 + h;
      }
      const W u_acc = m_law.g - p.ua() - m_law.gamma_beta * p.ub1() * v;  // u''
      if (v == 0 || u_acc == 0) {
        found(v == 0);
        return tau0 + h;
      }
      W next = h - v / u_acc;
      if (next < 0) next = h / 2;
      if (next > H) next = (h + H) / 2;
      const W delta = abs(next - h);
      const W scale = abs(tau0) + abs(h);
      if (delta <= sqrt_eps * scale / 16) {
        found(true);
        return tau0 + next;
      }
      const bool stalled = previous_delta >= 0 && delta >= previous_delta / 2 && delta <= sqrt_eps * scale;
      if (stalled) {
        h = best_h;
        m_t_int.fixed_step(rhs_t, tau0, z0, h, columns, at);
        found(false);
        return tau0 + h;
      }
      previous_delta = delta;
      h = next;
    }
    throw convergence_error("solve_impact_adaptive: turning point not located for " + m_where);
  }

  // Whether E = v^2/2 + u^(alpha+1)/(alpha+1) - g u is negative beyond its rounding
  // and the error carried in the state (dE = v dw + (u^alpha - g) du, both taken at
  // the accumulated error of w).
  bool energy_proven_negative(const W& energy, const W& v, const typename regularised_law<W>::powers& p) const {
    using std::abs;
    const W terms = v * v / 2 + p.ua() * p.u() * m_law.inv_alpha_plus_one + abs(m_law.g) * p.u();
    const W margin = 64 * (epsilon<W>() * terms + m_error * (abs(v) + abs(p.ua() - m_law.g) + 1));
    return energy < -margin;
  }

  // Creeping into the equilibrium u* = g^(1/alpha) (g > 0) without turning back,
  // at the tau-mode position s with velocity v.
  // Trapping sector: with x = u - u*, Gamma the least damping gamma beta u^(beta-1)
  // and A the largest stiffness alpha u^(alpha-1) between u and u*, and Gamma^2 >= 4A,
  // the set {x v <= 0, |v| <= (Gamma/2)|x|} is invariant (on |v| = kappa|x|,
  // d/dtau(v + kappa x) has the sign of x (Gamma kappa - kappa^2 - A) >= 0; at v = 0,
  // u'' = -(u^alpha - u*^alpha) points inside), so v never vanishes again: contact_time = inf.
  // Deliberately the same sector argument as taylor_impact.hpp's creep checks, written independently.
  rest_verdict creeps_to_equilibrium(const W& s, const W& v) {
    using std::abs;
    using std::pow;
    using std::sqrt;
    typename regularised_law<W>::powers p;
    m_law.eval(s, p);
    const W u_star = pow(m_law.g, 1 / m_law.alpha);
    const W x = p.u() - u_star;
    if (x == 0 || (x > 0) == (v > 0)) return x == 0 && v == 0 ? rest_verdict::at_rest : rest_verdict::moving;
    const W lower = x > 0 ? u_star : p.u(), upper = x > 0 ? p.u() : u_star;
    const W damping = m_law.gamma_beta * pow(lower, m_law.beta - 1);
    const W stiffness = m_law.alpha * pow(upper, m_law.alpha - 1);
    if (damping * damping >= 4 * stiffness && 2 * abs(v) <= damping * abs(x)) return rest_verdict::trapped;
    // At rest to half the precision: no further turning point can be resolved.
    const W k = m_law.alpha * m_law.g / u_star;
    return abs(x) / u_star + abs(v) / (sqrt(k) * u_star) <= sqrt(epsilon<W>()) ? rest_verdict::at_rest
                                                                                : rest_verdict::moving;
  }

  // g = 0, after maximal compression, at the tau-mode state (s, w): whether the bead
  // provably creeps into u = 0 without leaving (contact_time = +inf). Barrier: for
  // 0 < c < 1 on the curve w = c gamma u^beta (v = -(1-c) gamma u^beta < 0),
  //     d/dtau (w - c gamma u^beta) = -u^alpha + c(1-c) gamma^2 beta u^(2 beta - 1) >= 0
  // while q(u) = u^(alpha+1-2 beta)/(gamma^2 beta) <= c(1-c), which holds on all of
  // (0, u] when alpha + 1 >= 2 beta (q grows with u). Above the curve v >= -(1-c) gamma
  // u^beta, and with beta >= 1 u reaches 0 only as tau -> inf; v cannot turn positive
  // (u'' = -u^alpha < 0 at v = 0). The least c is (1 - sqrt(1 - 4q))/2.
  // Deliberately the same barrier as taylor_impact.hpp's and the proof's, written independently.
  bool creeps_to_origin(const W& s, const W& w) {
    using std::abs;
    using std::pow;
    using std::sqrt;
    if (!(m_law.gamma > 0)) return false;
    const W exponent = m_law.alpha + 1 - 2 * m_law.beta;
    if (exponent < 0) return false;
    typename regularised_law<W>::powers p;
    m_law.eval(s, p);
    const W v = m_law.velocity(w, p);
    if (!(v < 0)) return false;
    // u a little above its computed value (q grows with u; u^0 = 1 stays exact).
    const W u_up = p.u() * (1 + W(1) / 1048576);
    const W q = pow(u_up, exponent) / (m_law.gamma * m_law.gamma * m_law.beta);
    if (!(4 * q <= 1)) return false;
    const W c = (1 - sqrt(1 - 4 * q)) / 2;
    // Above the curve by a margin far beyond the state's error (accumulated error of w).
    const W curve = m_law.gamma * p.ub();
    const W gap = w - c * curve;
    return gap >= curve / 1024 && gap > 64 * (m_error + epsilon<W>() * abs(w));
  }

  // The problem and the tolerances.
  regularised_law<W> m_law;
  W m_rtol, m_eps_e;
  // Bookkeeping over the whole solve (each means one thing throughout).
  std::size_t m_max_steps, m_steps = 0;  // step budget and steps taken
  int m_switches = 0;                    // tau -> s -> tau round trips
  std::size_t m_creep_steps = 0;         // steps past maximal compression (creep_out_of_reach)
  W m_error = 0;                         // accumulated error estimate of w
  gbs_integrator<W, 3> m_s_int, m_t_int;
  std::string m_where;
  // Scratch of the right-hand sides and the event search (no meaning between calls).
  typename regularised_law<W>::powers m_p;
  W m_v = 0, m_tmp = 0;
  std::vector<W> m_v_nodes;  // v at the nodes of the last tau step
};

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
  if (raw.contact_time) r.contact_time = narrow<Real>(*raw.contact_time, caller_digits);
  else r.contact_time = std::nullopt;
  r.max_compression = narrow<Real>(raw.max_compression, caller_digits);
  r.time_of_max_compression = narrow<Real>(raw.time_of_max, caller_digits);
  W err = solver.accumulated_error() + raw.error + tol.eps_e;
  if (raw.outcome != impact_outcome::rebound) {
    // stick: e = 0; undecided: e = 0 to within error_estimate, contact_time unknown.
    r.e = 0, r.one_minus_e = 1, r.energy_residual = 0;
  } else {
    const W beta = law.beta.template value<W>();
    const W dissipated = 2 * w_gamma * beta * raw.reduced_D;  // D = 1 - e^2 by eq. (6)
    const W one_minus_e = dissipated / (1 + raw.e);
    const W residual = (1 - raw.e) * (1 + raw.e) - dissipated;
    // NOTE: e from the velocity when it is small (relative digits near sticking),
    // from the dissipated energy when near 1 (no cancellation as gamma -> 0).
    const bool small = raw.e < W(1) / 2;
    r.e = narrow<Real>(small ? raw.e : W(1 - one_minus_e), caller_digits);
    r.one_minus_e = narrow<Real>(small ? W(1 - raw.e) : one_minus_e, caller_digits);
    r.energy_residual = narrow<Real>(residual, caller_digits);
    err += abs(residual);
  }
  r.error_estimate = narrow<Real>(err, caller_digits);
  return r;
}

}  // namespace detail

}  // namespace viscor

// solve_impact_adaptive is compiled once per scalar type into libviscor (src/instantiation.cpp.in):
// declared extern here, so that no unit including this header instantiates it again.
#define VISCOR_ADAPTIVE_TEMPLATES(PREFIX, Real) \
  PREFIX template impact_result<Real> solve_impact_adaptive<Real>(const contact_law&, const Real&, const Real&, \
                                                                  const solve_options<Real>&);
#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_REAL_WITH(VISCOR_ADAPTIVE_TEMPLATES, extern)
}
#endif
