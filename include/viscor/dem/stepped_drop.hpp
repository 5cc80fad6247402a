// The drop as the code steps it: viscor's force law with the code's conventions (the
// deck's gamma0, dem_calibration.hpp) integrated by the code's own update at a finite
// time step, and the rebound e read off as the drop deck reads it (drop_deck.hpp). At
// the steps DEM practice uses (T/20 to T/50, T the time scale of eq. 2) the e a
// simulation gets drifts from the continuous impact's; calibrate_at_time_step finds the
// gamma0 whose stepped drop gives the target, so the deck's entries give it at that step.
//
// The updates, read from the installed versions' sources:
// - LAMMPS fix nve/sphere and LIGGGHTS fix nve/sphere (velocity Verlet): v += dt/2 f/m,
//   x += dt v, then the forces at the new x with that half-step v (fix wall/gran's
//   damping reads it), then v += dt/2 f/m. The drop deck fits v = v_e + A delta^beta
//   to the last two in-contact steps.
// - YADE NewtonIntegrator (leapfrog): the forces at x(t) with the velocity v(t - dt/2),
//   v(t + dt/2) = v(t - dt/2) + dt (f/m + gravity), x(t + dt) = x(t) + dt v(t + dt/2);
//   the force clamped at zero (impact/clamped_impact.hpp). The drop script reads e from
//   the parabola through the last three positions.
// The bead starts touching the wall (zero overlap) moving in at v0; the contact force
// acts while the overlap is positive (LAMMPS: from zero overlap on).
#pragma once

#include <viscor/dem/dem_calibration.hpp>

#include <boost/math/tools/precision.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace viscor::dem {

/// The rebound of one stepped drop.
template <class Real>
struct stepped_drop {
  bool rebound = false;  ///< false: no exit within the step budget (the bead sticks)
  Real e = 0;            ///< the rebound e as the drop deck reads it
  long contact_steps = 0;
};

/// How many contact times of the continuous impact a stepped drop may take (as the decks allow).
inline constexpr long stepped_drop_budget = 50;

namespace detail {

/// d(overlap rate)/dt of the code's contact: the load minus F/m, F = k x^alpha +
/// gamma0 k beta x^(beta-1) u at overlap x and overlap rate u (u > 0: into the wall).
template <class Real>
struct overlap_acceleration {
  const dem_model& model;
  const physical_parameters<Real>& p;
  Real alpha, beta, load;
  // LAMMPS's wall/gran counts a contact from zero overlap on (it skips only rsq > R^2), which
  // matters where the damping force does not vanish there (beta = 1): at the set-up the bead
  // touches the wall and already feels D v0. YADE's Law2 drops a contact without overlap.
  bool touching_counts;

  overlap_acceleration(const dem_model& m, const physical_parameters<Real>& in)
      : model(m), p(in), alpha(law_of(m).alpha.template value<Real>()), beta(law_of(m).beta.template value<Real>()),
        load(in.gravity + in.force / in.m), touching_counts(m.code != dem_code::yade) {}

  Real operator()(const Real& x, const Real& u) const {
    using std::pow;
    if (!(x > 0) && !(touching_counts && x == 0)) return load;
    Real force = p.k * pow(x, alpha) + p.gamma0 * p.k * beta * pow(x, beta - 1) * u;
    if (model.clamped && force < 0) force = 0;
    return Real(load - force / p.m);
  }
};

/// YADE's leapfrog from zero overlap at v0; e from the parabola through the last three positions.
template <class Real>
stepped_drop<Real> leapfrog_drop(const overlap_acceleration<Real>& acceleration, const Real& v0, const Real& dt,
                                 long max_steps) {
  using std::sqrt;
  stepped_drop<Real> out;
  Real x = 0, u = v0, x0 = 0, x1 = 0;
  for (long n = 0; n < max_steps; ++n) {
    u += dt * acceleration(x, u);
    x0 = x1, x1 = x;
    x += dt * u;
    if (x > 0) {
      ++out.contact_steps;
      continue;
    }
    if (n < 2 || !(x1 > 0)) continue;  // still at the start, or out of contact before (a free flight)
    const Real a = (x - 2 * x1 + x0) / (dt * dt), b = (x - x0) / (2 * dt);
    out.rebound = true;
    out.e = sqrt(b * b - 2 * a * x1) / v0;
    return out;
  }
  return out;
}

/// LAMMPS's and LIGGGHTS's velocity Verlet from zero overlap at v0; e from v = v_e + A x^beta
/// through the last two in-contact steps, as the drop deck fits it.
template <class Real>
stepped_drop<Real> verlet_drop(const overlap_acceleration<Real>& acceleration, const Real& v0, const Real& dt,
                               long max_steps) {
  using std::pow;
  stepped_drop<Real> out;
  Real x = 0, u = v0;
  Real a = acceleration(x, u);  // the forces of the set-up, at zero overlap
  Real x1 = 0, u1 = u, x2 = 0, u2 = u;
  for (long n = 0; n < max_steps; ++n) {
    x2 = x1, u2 = u1, x1 = x, u1 = u;
    u += dt / 2 * a;
    x += dt * u;
    a = acceleration(x, u);
    u += dt / 2 * a;
    if (x > 0) {
      ++out.contact_steps;
      continue;
    }
    if (!(u < 0) || !(x1 > 0) || !(x2 > 0)) continue;  // not on the way out of a contact of two steps or more
    const Real xa = pow(x2, acceleration.beta), xb = pow(x1, acceleration.beta);
    out.rebound = true;
    // the deck's fit in its velocities v = -u: e = (v1 - (v2 - v1)/(xa - xb) xb)/v0
    out.e = (-u1 - (u1 - u2) / (xa - xb) * xb) / v0;
    return out;
  }
  return out;
}

}  // namespace detail

/// The drop of the impact's bead at the damping p.gamma0, stepped with dt by the model's code.
template <class Real>
stepped_drop<Real> step_drop(const dem_model& model, const physical_parameters<Real>& p, const Real& dt,
                             long max_steps) {
  const detail::overlap_acceleration<Real> acceleration(model, p);
  return model.code == dem_code::yade ? detail::leapfrog_drop(acceleration, p.v0, dt, max_steps)
                                      : detail::verlet_drop(acceleration, p.v0, dt, max_steps);
}

/// The time step of a request: a number of seconds, "T/N" (T the impact's time scale of
/// eq. 2, as the decks' dt = T/400) or "contact/N" (the continuous contact time / N).
template <class Real>
Real time_step_of(const std::string& text, const Real& time_scale, const Real& contact_time) {
  for (const auto& [prefix, base] : {std::pair<std::string, Real>{"T/", time_scale}, {"contact/", contact_time}})
    if (text.rfind(prefix, 0) == 0) {
      const Real n = parse_real<Real>(text.substr(prefix.size()), "timestep");
      if (!(n >= 1))
        throw invalid_parameter(VISCOR_FIELD("timestep") " " + text + ": N of " + prefix + "N must be at least 1");
      return Real(base / n);
    }
  const Real dt = parse_real<Real>(text, "timestep");
  require_positive(dt, "timestep");
  return dt;
}

/// The steps a stepped drop may take: 50 times 20 T (the contact lasts about 3.3 T), so
/// that a slow, damped or loaded contact still ends within them. From T alone, without a
/// solve, so that the C export states the same cap.
template <class Real>
long stepped_drop_steps(const Real& time_scale, const Real& dt) {
  return static_cast<long>(static_cast<double>(stepped_drop_budget * 20 * time_scale / dt)) + 100;
}

/// The gamma0 whose drop, stepped with dt by the model's code, rebounds with target_e:
/// from the bracket [0, 2 gamma0 of the continuous calibration] (doubled while it is
/// not one), bisection down to neighbouring numbers, then the end whose e is nearer.
/// unreachable_target when no damping gives the target at this step.
// NOTE: plain bisection, not TOMS 748, so that the C export (jobs/dem_export) states the
// same steps: its step-aware entries are these bits.
template <class Real>
physical_calibration<Real> calibrate_at_time_step(const dem_model& model, const physical_parameters<Real>& p,
                                                  const physical_calibration<Real>& continuous, const Real& target_e,
                                                  const Real& dt) {
  using std::abs;
  const long max_steps = stepped_drop_steps(continuous.time_scale, dt);
  int solves = 0;
  auto miss = [&](const Real& gamma0) {
    physical_parameters<Real> at = p;
    at.gamma0 = gamma0;
    ++solves;
    const stepped_drop<Real> d = step_drop(model, at, dt, max_steps);
    return Real((d.rebound ? d.e : Real(0)) - target_e);
  };
  Real lo = 0, hi = 2 * continuous.gamma0;
  const Real lo_miss = miss(lo);
  if (!(lo_miss > 0))
    throw unreachable_target("target_e = " + to_decimal_string(target_e) + " is unreachable at this time step: " +
                             "the undamped drop stepped with dt = " + to_decimal_string(dt) + " s rebounds with " +
                             to_decimal_string(Real(lo_miss + target_e)));
  for (int i = 0; miss(hi) > 0; ++i) {
    if (i == 60 || !(hi > 0))
      throw unreachable_target("target_e = " + to_decimal_string(target_e) + " is unreachable at this time step");
    lo = hi, hi *= 2;
  }
  for (int i = 0; i < 4 * boost::math::tools::digits<Real>() + 1100; ++i) {
    const Real mid = (lo + hi) / 2;
    if (mid == lo || mid == hi) break;
    if (miss(mid) > 0)
      lo = mid;
    else
      hi = mid;
  }
  const Real lo_e = miss(lo), hi_e = miss(hi);
  physical_calibration<Real> c = continuous;
  c.gamma0 = abs(hi_e) < abs(lo_e) ? hi : lo;
  c.scaled.gamma = c.gamma0 * (continuous.scaled.gamma / continuous.gamma0);
  c.scaled.gamma_lo = lo, c.scaled.gamma_hi = hi;
  c.scaled.e = (abs(hi_e) < abs(lo_e) ? hi_e : lo_e) + target_e;
  c.scaled.target_bound = abs(c.scaled.e - target_e);
  c.scaled.solves = solves;
  return c;
}

/// The stepped drop's e at a deck damping entry (0 when the bead does not come back).
template <class Real>
Real stepped_e_for_deck(const dem_model& model, const dem_impact<Real>& impact, const dem_deck<Real>& d,
                        const Real& deck_damping, const Real& dt) {
  physical_parameters<Real> at = physical_impact(d.contact, impact, Real(0));
  at.gamma0 = damping_number(model, deck_damping) * damping_scale(model, d.contact);
  const stepped_drop<Real> s = step_drop(model, at, dt, stepped_drop_steps(d.calibration.time_scale, dt));
  return s.rebound ? s.e : Real(0);
}

/// The deck that gives target_e when the code steps the drop with dt (s), from the
/// continuous calibration's deck (dem_deck_for, or dem_deck_by_surrogate as the C export
/// does): calibrate_at_time_step, then the entries as complete_deck makes them, the
/// built-in conversion's e also at that step.
template <class Real>
dem_deck<Real> dem_deck_at_time_step(const dem_model& model, const dem_impact<Real>& impact, const Real& target_e,
                                     const Real& dt, const dem_deck<Real>& continuous) {
  dem_deck<Real> d = continuous;
  const physical_parameters<Real> p = physical_impact(d.contact, impact, Real(0));
  d.calibration = calibrate_at_time_step(model, p, continuous.calibration, target_e, dt);
  complete_deck(model, impact, target_e, d,
                [&](const Real& entry) { return stepped_e_for_deck(model, impact, d, entry, dt); });
  return d;
}

}  // namespace viscor::dem
