// The impact with the contact force clamped at zero (no attraction), as DEM codes
// such as YADE compute it. Scaled:
//   u'' = g - max(0, f),   f = u^alpha + gamma d/dtau(u^beta) = u^(beta-1) h,
//   h = u^p + gamma beta u',  p = alpha - beta + 1,
// while u > 0, from u(0) = 0, u'(0) = 1; e = -u' at the return to u = 0, 0 if the bead sticks.
//
// Phases. Contact (f > 0): integrated by the GBS extrapolation stepper
// (ode/adaptive_integrator.hpp); the first contact phase starts at u = 0 where
// u^(beta-1) and u^alpha are not smooth in tau, so it runs in s with tau = s^Q
// (Q the least common denominator of alpha and beta), in which u = s^Q w(s) with w
// analytic, until tau = 1/4. The switch to the force-free phase is the root of h
// in the step (TOMS 748 over the step length, each trial a fixed GBS step).
// Force-free (f <= 0): free flight u'' = g in closed form. Near u = 0 with u' < 0,
// h -> gamma beta u' < 0, so every contact phase ends in a switch at u > 0.
//
// Resumption. In free flight h(t) = u^p + gamma beta u' with h(0) = 0, h'(0) <= 0 and
//   h'' = p (p - 1) u^(p-2) u'^2 + p u^(p-1) g.
// For p >= 1 (alpha >= beta: linear, hertz_linear_damping, tsuji, kuwabara_kono)
// and g >= 0, h is convex while u > 0. If the parabola reaches u = 0 (u'^2 > 2 g u at
// the switch) then h < 0 there (h = gamma beta u' < 0), so by convexity h < 0 on the
// whole flight: no resumption, the bead leaves with e = sqrt(u'^2 - 2 g u). If it
// falls back (u'^2 <= 2 g u), h > 0 at the apex (h = u^p), so contact resumes at
// the unique root of h before the apex and the next contact phase starts there.
// For g < 0, h' = p u^(p-1) u' + gamma beta g < 0 in flight: no resumption.
// Laws with alpha < beta (hunt_crossley) are refused.
//
// Sticking: W = u'^2/2 + u^(alpha+1)/(alpha+1) - g u never increases (contact:
// dW/dtau = -gamma beta u^(beta-1) u'^2; flight: dW/dtau = u' u^alpha <= 0), and at a
// return to u = 0, W = e^2/2 >= 0. So W < 0 at any time means the bead sticks.
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/root_finding.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/ode/adaptive_integrator.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>

namespace viscor {

/// What solve_clamped_impact found.
template <class Real>
struct clamped_impact_result {
  Real e = 0;  ///< rebound speed -u' at the return to u = 0; 0 when the bead sticks
  impact_outcome outcome = impact_outcome::rebound;
  Real contact_time = 0;        ///< tau at the return to u = 0 (rebound; 0 for gamma = 0); where W < 0 was seen (stick)
  Real first_release_time = 0;  ///< tau of the first switch to zero force (0 if none)
  Real release_overlap = 0;     ///< u at the last switch to zero force (0 if none)
  Real release_speed = 0;       ///< u' at the last switch to zero force
  int contact_phases = 0;       ///< contact phases (more than 1: the contact resumed after a force-free phase)
  std::size_t steps = 0;        ///< accepted integrator steps
};

/// Options of solve_clamped_impact.
template <class Real>
struct clamped_options {
  Real tolerance = 0;  ///< GBS relative tolerance per step; 0: epsilon<Real>() (the integration runs with guard digits)
  std::size_t max_steps = 200000;  ///< step budget; exhausting it throws convergence_error
};

namespace detail {

/// The free flight u'' = g from a switch (u > 0, v = u' < 0): where it goes.
template <class Real>
struct clamped_flight {
  bool leaves = false;  ///< reaches u = 0 (else falls back and the contact resumes)
  Real duration = 0;    ///< to u = 0, or to the resumption
  Real u = 0, v = 0;    ///< state at the end of the flight
};

/// Flight from (u, v) under g for a law with p = alpha - beta + 1 >= 1, damping gamma beta.
template <class Real>
clamped_flight<Real> clamped_free_flight(const Real& u, const Real& v, const Real& g, const Real& p,
                                         const Real& gamma_beta) {
  using std::pow;
  using std::sqrt;
  clamped_flight<Real> r;
  const Real discriminant = v * v - 2 * g * u;
  if (!(g > 0) || discriminant > 0) {
    r.leaves = true;
    const Real speed = sqrt(discriminant);
    r.duration = 2 * u / (speed - v);  // the smaller root of u + v t + g t^2/2, cancellation-free
    r.u = 0, r.v = -speed;
    return r;
  }
  // Falls back: h(t) = u(t)^p + gamma beta u'(t) has one root in (0, apex] (header comment).
  const Real apex = -v / g;
  auto h = [&](const Real& t) {
    const Real ut = u + t * (v + g * t / 2);
    return Real(pow(ut > 0 ? ut : Real(0), p) + gamma_beta * (v + g * t));
  };
  Real lo = apex;
  for (int i = 0; i < binary_digits<Real>() && h(lo) >= 0; ++i) lo /= 2;
  r.duration = h(lo) >= 0 ? Real(0) : bracketed_root(h, lo, apex, "clamped impact: contact resumption");
  r.u = u + r.duration * (v + g * r.duration / 2), r.v = v + g * r.duration;
  return r;
}

/// The clamped impact integrated in Real throughout (solve_clamped_impact runs it in a
/// wider type): contact phases (contact_phase, in s then tau, or tau alone) until the
/// force switches off, each followed by a free flight (clamped_free_flight), until the
/// bead leaves or the energy W proves a stick (header comment).
template <class Real>
class clamped_impact_solver {
 public:
  using state = std::array<Real, 2>;  // u, u'

  clamped_impact_solver(const contact_law& law, const Real& gamma, const Real& g, const Real& rtol,
                        std::size_t max_steps, int columns)
      : m_g(g), m_rtol(rtol), m_max_steps(max_steps), m_columns(columns) {
    using std::pow;
    m_alpha = law.alpha.value<Real>(), m_beta = law.beta.value<Real>();
    m_p = m_alpha - m_beta + 1, m_gamma_beta = gamma * m_beta;
    m_q = law.multiples().Q;
    m_s_end = pow(Real(1) / 4, Real(1) / Real(m_q));  // the first part in s up to tau = 1/4
  }

  clamped_impact_result<Real> solve() {
    clamped_impact_result<Real> r;
    state y{Real(0), Real(1)};
    Real tau = 0;
    for (bool first = true;; first = false) {
      ++r.contact_phases;
      if (contact_phase(first, y, tau, r)) return r;  // stuck
      if (r.first_release_time == 0) r.first_release_time = tau;
      r.release_overlap = y[0], r.release_speed = y[1];
      const clamped_flight<Real> flight = clamped_free_flight(y[0], y[1], m_g, m_p, m_gamma_beta);
      tau += flight.duration;
      y = {flight.u, flight.v};
      if (flight.leaves) {
        r.e = -flight.v, r.contact_time = tau;
        return r;
      }
      if (energy(y) < 0) {
        r.outcome = impact_outcome::stick, r.e = 0, r.contact_time = tau;
        return r;
      }
    }
  }

 private:
  // h = u^p + gamma beta u': the force is u^(beta-1) h.
  Real h_of(const state& y) const {
    using std::pow;
    return Real(pow(y[0], m_p) + m_gamma_beta * y[1]);
  }
  // W = u'^2/2 + u^(alpha+1)/(alpha+1) - g u, which never increases.
  Real energy(const state& y) const {
    using std::pow;
    return Real(y[1] * y[1] / 2 + pow(y[0], m_alpha + 1) / (m_alpha + 1) - m_g * y[0]);
  }
  // u'' in contact; false outside u >= 0.
  bool accel(const state& y, Real& a) const {
    using std::pow;
    if (!(y[0] >= 0)) return false;
    a = m_g - (pow(y[0], m_alpha) + m_gamma_beta * pow(y[0], m_beta - 1) * y[1]);
    return true;
  }
  // d/dtau (u, u') in contact.
  bool rates_in_tau(const state& y, state& dy) const {
    dy[0] = y[1];
    return accel(y, dy[1]);
  }
  // d/ds (u, u') with tau = s^q: dtau/ds = q s^(q-1).
  bool rates_in_s(const Real& s, const state& y, state& dy) const {
    using std::pow;
    const Real jac = m_q == 1 ? Real(1) : Real(m_q * pow(s, Real(m_q - 1)));
    if (!accel(y, dy[1])) return false;
    dy[0] = jac * y[1];
    dy[1] *= jac;
    return true;
  }
  Real tau_of(bool use_s, const Real& t) const {
    using std::pow;
    return use_s ? Real(pow(t, Real(m_q))) : t;
  }

  // One contact phase from (tau, y) until h < 0 (the force switches off: y and tau
  // where it does) or W < 0 (stuck: returns true, r says so). The first phase starts
  // in s (first).
  bool contact_phase(bool first, state& y, Real& tau, clamped_impact_result<Real>& r) {
    for (int part = first ? 0 : 1; part < 2; ++part) {
      const contact_part end = integrate_part(part == 0, y, tau, r);
      if (end == contact_part::stuck) return true;
      if (end == contact_part::switched) return false;
    }
    return false;
  }

  enum class contact_part { on_to_tau, switched, stuck };

  // One part of a contact phase, in s (use_s, up to tau = 1/4) or in tau: steps until
  // the part ends (on_to_tau), the force switches off within a step (switched: the
  // switch located, y and tau there) or W < 0 (stuck, r says so).
  contact_part integrate_part(bool use_s, state& y, Real& tau, clamped_impact_result<Real>& r) {
    auto in_s = [this](const Real& s, const state& y_, state& dy) { return rates_in_s(s, y_, dy); };
    auto in_tau = [this](const Real&, const state& y_, state& dy) { return rates_in_tau(y_, dy); };
    viscor::gbs_integrator<Real, 2> integ(m_rtol, state{m_rtol, m_rtol}, m_columns);
    Real t = use_s ? Real(0) : tau;  // s in the first part
    Real step = use_s ? Real(m_s_end / 16) : Real(1) / 16;
    while (true) {
      if (r.steps >= m_max_steps)
        throw convergence_error("clamped impact: step budget of " + std::to_string(m_max_steps) + " exhausted");
      const bool clipped = use_s && t + step >= m_s_end;
      if (clipped) step = m_s_end - t;
      const Real t0 = t;
      const state y0 = y;
      const gbs_status status = use_s ? integ.try_step(in_s, t, y, step) : integ.try_step(in_tau, t, y, step);
      if (status == gbs_status::non_finite) throw convergence_error("clamped impact: state is not finite");
      if (status != gbs_status::accepted) continue;
      if (clipped) t = m_s_end;  // exactly, so the s part ends
      ++r.steps;
      if (y[0] > 0 && h_of(y) > 0) {
        if (energy(y) < 0) {
          r.outcome = impact_outcome::stick, r.e = 0;
          r.contact_time = tau_of(use_s, t);
          return contact_part::stuck;
        }
        if (use_s && !(t < m_s_end)) {  // on to tau
          tau = tau_of(use_s, t);
          return contact_part::on_to_tau;
        }
        continue;
      }
      // The switch h = 0 lies in this step: find the step length that reaches it.
      const int cols = integ.last_columns();
      auto h_after = [&](const Real& len) {
        state out;
        const bool ok = use_s ? integ.fixed_step(in_s, t0, y0, len, cols, out)
                              : integ.fixed_step(in_tau, t0, y0, len, cols, out);
        return ok && out[0] > 0 ? h_of(out) : Real(-1);
      };
      const Real len = bracketed_root(h_after, Real(0), Real(t - t0), "clamped impact: force-zero switch");
      const bool ok = use_s ? integ.fixed_step(in_s, t0, y0, len, cols, y) : integ.fixed_step(in_tau, t0, y0, len, cols, y);
      if (!ok) throw convergence_error("clamped impact: switch step left the contact");
      t = t0 + len;
      tau = tau_of(use_s, t);
      return contact_part::switched;
    }
  }

  Real m_g, m_rtol;
  std::size_t m_max_steps;
  int m_columns;
  Real m_alpha, m_beta, m_p, m_gamma_beta, m_s_end;
  std::int64_t m_q;
};

/// The clamped impact integrated in Real throughout (solve_clamped_impact calls it in a wider type).
template <class Real>
clamped_impact_result<Real> solve_clamped_impact_in(const contact_law& law, const Real& gamma, const Real& g,
                                                    const Real& rtol, std::size_t max_steps, int columns) {
  law.validate();
  require_non_negative(gamma, "gamma");
  require_finite(g, "g");
  if (!law.alpha.is_rational() || !law.beta.is_rational() ||
      __int128(law.alpha.numerator()) * law.beta.denominator() < __int128(law.beta.numerator()) * law.alpha.denominator())
    throw invalid_parameter("clamped impact needs rational exponents with alpha >= beta, got " + law.describe());
  clamped_impact_solver<Real> solver(law, gamma, g, rtol, max_steps, columns);
  if (gamma == 0) {  // f = u^alpha >= 0 never clamps, and energy conservation gives e = 1
    clamped_impact_result<Real> r;
    r.e = 1, r.contact_phases = 1;
    return r;
  }
  return solver.solve();
}

}  // namespace detail

/// The clamped impact u'' = g - max(0, u^alpha + gamma d/dtau(u^beta)) from u = 0,
/// u' = 1 (header comment): e, the outcome and the phases. Needs alpha >= beta.
/// NOTE: integrated in detail::gbs_work<Real> (guard digits): GBS extrapolation in
/// Real itself loses about 2 digits to rounding (measured: 1.8e-12 in e in double).
template <class Real>
clamped_impact_result<Real> solve_clamped_impact(const contact_law& law, const Real& gamma, const Real& g,
                                                 const clamped_options<Real>& options = {}) {
  using work = typename detail::gbs_work<Real>::type;
  const Real rtol = options.tolerance > 0 ? options.tolerance : epsilon<Real>();
  // decimal_digits, not numeric_limits::digits10 (INT_MAX for run-time MPFR: the sum overflowed).
  const int columns = detail::gbs_max_columns(decimal_digits<Real>() + detail::gbs_work<Real>::guard_digits(),
                                              detail::gbs_work<Real>::guard_digits());
  const clamped_impact_result<work> w =
      detail::solve_clamped_impact_in<work>(law, work(gamma), work(g), work(rtol), options.max_steps, columns);
  clamped_impact_result<Real> r;
  r.e = Real(w.e), r.outcome = w.outcome, r.contact_time = Real(w.contact_time);
  r.first_release_time = Real(w.first_release_time), r.release_overlap = Real(w.release_overlap);
  r.release_speed = Real(w.release_speed), r.contact_phases = w.contact_phases, r.steps = w.steps;
  return r;
}

}  // namespace viscor
