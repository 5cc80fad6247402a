// Calibration, the inverse problem: the damping that produces a measured CoR.
//
// Scaled: find gamma >= 0 with e(gamma; g) = target_e at a fixed load g, where
// e is the exact solve (solve_impact, Taylor) at the working precision of Real.
// Physical: the same at the g of (m, k, v0, gravity, F) by eq. (2), then
// gamma0 = gamma / (gamma / gamma0 factor of eq. 2).
//
// Method: bracket, then TOMS 748 on f(gamma) = e(gamma) - target_e.
//   * e(0) = 1 for every law and load (no dissipation), so gamma = 0 is the
//     lower end of every bracket and target_e = 1 gives gamma = 0 exactly.
//   * First guess from eq. (22): gamma_1 = (1 - target_e)/(C0 + g C1) (when
//     positive); then steps by factors of 4 up until e <= target_e, or down
//     while e < target_e, so the bracket is within a factor 4 of the root.
//   * Stop as soon as a solve meets |e(gamma) - target_e| + 10 x its error
//     estimate <= tolerance: the tolerance is on e, the quantity measured, so a
//     calibrated gamma reproduces the target to the tolerance (round trip).
// NOTE: e decreases with gamma at fixed g for the named laws (checked on a grid
// of gamma from 1e-6 to 100 and g in {-0.5, 0, 0.05, 1, 10} in the tests);
// where it would not, the root found is one root in the first bracket, still
// with |e - target| <= tolerance. Beyond the sticking threshold e = 0, so
// f = -target_e < 0 there and the bracket stays valid.
//
// Unreachable targets throw unreachable_target: e > 1 (no damping gives more
// than the elastic rebound), e = 0 (a threshold: every gamma >= gamma_c(g)
// sticks; see sticking_threshold), and targets below the smallest e reachable
// with gamma <= gamma_max (a pulling load g < 0 keeps e away from 0).
#pragma once

#include <viscor/approx/closed_form.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/scenes/detail/estimate_safety.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <string>

namespace viscor {

/// The requested CoR cannot be produced by any damping (the message says why).
struct unreachable_target : invalid_parameter {
  using invalid_parameter::invalid_parameter;
};

/// How calibrate_gamma and calibrate_gamma0 search: tolerance on e, bracket limit, solver options.
template <class Real>
struct calibration_options {
  /// Absolute tolerance on e; 0: 10^5 epsilon<Real>() (the Taylor solve's own
  /// estimate reaches 10^2..10^3 epsilon, more for small e).
  Real tolerance = 0;
  /// Largest scaled damping tried while bracketing. NOTE: at g = 0 and gamma
  /// >~ 1e3 the bead creeps back so slowly that the solve costs 1e5+ steps.
  Real gamma_max = 100;
  solve_options<Real> solve{};
};

/// The calibrated scaled damping with its bracket and the miss of the target.
template <class Real>
struct calibration_result {
  Real gamma = 0;    ///< the calibrated scaled damping
  Real g = 0;        ///< the scaled load it was calibrated at
  Real e = 1;        ///< e(gamma) by solve_impact
  Real target_bound = 0;  ///< |e - target_e| + 10 x estimate: a stated bound on the miss of the target
  Real gamma_lo = 0, gamma_hi = 0;  ///< final bracket: e(gamma_lo) >= target_e >= e(gamma_hi)
  int solves = 0;    ///< solve_impact calls
};

/// A calibration in physical units: gamma0 and the scaled calibration behind it.
template <class Real>
struct physical_calibration {
  Real gamma0 = 0;  ///< calibrated physical damping coefficient
  calibration_result<Real> scaled;  ///< the scaled calibration behind it
  Real time_scale = 0;              ///< T of eq. (2), s
};

namespace detail {
template <class Real>
Real default_calibration_tolerance() {
  return 100000 * epsilon<Real>();
}
}  // namespace detail

/// The scaled damping gamma with |e(gamma; g) - target_e| <= options.tolerance
/// (absolute on e; see the header comment). Throws unreachable_target when no
/// gamma in [0, gamma_max] gives target_e, invalid_parameter for bad input,
/// convergence_error when the working precision cannot resolve the tolerance.
template <class Real>
calibration_result<Real> calibrate_gamma(const contact_law& law, const Real& g, const Real& target_e,
                                         const calibration_options<Real>& options = {}) {
  using std::abs;
  law.validate();
  require_finite(g, "g");
  require_finite(target_e, "target_e");
  require_non_negative(options.tolerance, "tolerance");
  require_positive(options.gamma_max, "gamma_max");
  if (target_e > 1)
    throw unreachable_target("target_e = " + to_decimal_string(target_e) +
                             " is unreachable: no damping gives e > 1 (gamma = 0 gives e = 1 at every load)");
  if (target_e < 0) throw invalid_parameter("parameter target_e must be in [0, 1], got " + to_decimal_string(target_e));
  if (target_e == 0)
    throw unreachable_target("target_e = 0 is a threshold, not a point: every gamma >= gamma_c(g) sticks; "
                             "compute the sticking threshold instead (viscor table sticking)");
  const Real tol = options.tolerance > 0 ? options.tolerance : detail::default_calibration_tolerance<Real>();
  if (tol < 100 * epsilon<Real>())
    throw precision_unavailable("calibration tolerance " + to_decimal_string(tol, 3) + " is below what " +
                                std::to_string(decimal_digits<Real>()) +
                                " digits resolve (>= 100 epsilon); use a wider type or " VISCOR_FIELD("digits"));

  calibration_result<Real> r;
  r.g = g;
  if (target_e == 1) return r;  // gamma = 0 exactly

  bool done = false, have_best = false;
  Real best_miss = 0;
  auto f = [&](const Real& gamma) -> Real {
    const impact_result<Real> s = solve_impact(law, gamma, g, options.solve);
    ++r.solves;
    const Real miss = s.e - target_e;
    const Real bound = abs(miss) + detail::taylor_estimate_safety * s.error_estimate;
    if (!have_best || bound < best_miss) {
      have_best = true;
      best_miss = bound;
      r.gamma = gamma, r.e = s.e, r.target_bound = bound;
    }
    if (bound <= tol) done = true;
    return miss;
  };

  // Bracket [lo, hi] with f(lo) > 0 >= f(hi), starting from eq. (22).
  const Real alpha = law.alpha.value<Real>(), beta = law.beta.value<Real>();
  const Real slope = coefficient_C0(alpha, beta) + g * coefficient_C1(alpha, beta);
  Real guess = slope > 0 ? Real((1 - target_e) / slope) : Real(1 - target_e);
  if (guess > options.gamma_max) guess = options.gamma_max;
  Real lo = 0, f_lo = 1 - target_e, hi = guess, f_hi = f(hi);
  if (f_hi > 0) {
    while (f_hi > 0 && !done) {
      if (hi >= options.gamma_max)
        throw unreachable_target("target_e = " + to_decimal_string(target_e) + " is unreachable at g = " +
                                 to_decimal_string(g) + ": e = " + to_decimal_string(Real(f_hi + target_e), 6) +
                                 " > target_e still at gamma = " + to_decimal_string(hi, 6) +
                                 " (gamma_max); a pulling load g < 0 keeps e away from 0");
      lo = hi, f_lo = f_hi;
      hi = 4 * hi < options.gamma_max ? Real(4 * hi) : options.gamma_max;
      f_hi = f(hi);
    }
  } else {
    // The guess overshoots (large g): move hi down while it stays past the root.
    for (int i = 0; i < 64 && !done; ++i) {
      const Real mid = hi / 4;
      const Real f_mid = f(mid);
      if (f_mid > 0) {
        lo = mid, f_lo = f_mid;
        break;
      }
      hi = mid, f_hi = f_mid;
    }
  }
  r.gamma_lo = lo, r.gamma_hi = hi;
  if (!done) {
    // NOTE: the stopping test lives in f (it needs the solve's estimate); the
    // bracket-width test only ends the search when the precision runs out.
    const Real width_floor = 4 * epsilon<Real>();
    auto stop = [&](const Real& a, const Real& b) {
      r.gamma_lo = a, r.gamma_hi = b;
      return done || abs(b - a) <= width_floor * (abs(a) > abs(b) ? abs(a) : abs(b));
    };
    const std::uintmax_t budget = 4 * static_cast<std::uintmax_t>(binary_digits<Real>()) + 100;
    std::uintmax_t iterations = budget;
    boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, stop, iterations);
  }
  if (!done)
    throw convergence_error("calibrate_gamma: e can be matched to target_e = " + to_decimal_string(target_e) +
                            " only within " + to_decimal_string(best_miss, 3) + " > tolerance " +
                            to_decimal_string(tol, 3) + " at " + std::to_string(decimal_digits<Real>()) +
                            " digits (" + law.describe() + ", g = " + to_decimal_string(g) + ")");
  return r;
}

/// The physical damping gamma0 that gives target_e for a bead (m, k) hitting the
/// wall at v0 under gravity and a constant force F (eq. 2); see calibrate_gamma.
template <class Real>
physical_calibration<Real> calibrate_gamma0(const contact_law& law, const Real& m, const Real& k, const Real& v0,
                                            const Real& gravity, const Real& force, const Real& target_e,
                                            const calibration_options<Real>& options = {}) {
  physical_parameters<Real> p;
  p.m = m, p.k = k, p.v0 = v0, p.gravity = gravity, p.force = force, p.gamma0 = 0;
  const scaled_parameters<Real> s = to_scaled(law, p);  // validates law and bead
  physical_calibration<Real> out;
  out.scaled = calibrate_gamma(law, s.g, target_e, options);
  out.gamma0 = out.scaled.gamma / detail::damping_factor(law, m, k, v0);
  out.time_scale = s.time_scale;
  return out;
}

}  // namespace viscor
