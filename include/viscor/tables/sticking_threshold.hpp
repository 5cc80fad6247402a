// Certified sticking thresholds: g_c(gamma), the smallest load at which the bead
// no longer rebounds (report Figs. 8-11), and gamma_c(g), the smallest damping
// at which it sticks. Found by bracketing and bisection on the certified
// outcome (e > 0 versus e = 0) of evaluate_point (table_row.hpp): every point
// evaluated is certified, so the returned bracket [rebound_at, stick_at] holds
// the threshold; its width gives the digits.
//
// NOTE: bisection rather than a root finder on e: e(g) has an infinite slope at
// the threshold (for the linear law e ~ sqrt(g_c - g)), and the certified
// outcome is the quantity that carries a guarantee. Each halving costs one
// certified solve; 30 digits take about 110 of them.
// The method assumes one threshold: rebound below it, sticking above it.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/tables/table_row.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace viscor {

/// A certified sticking threshold: a rebound point and a stick point bracketing it, and the digits they agree to.
template <class Real>
struct threshold_result {
  Real rebound_at = 0;  ///< a certified rebound point, below the threshold
  Real stick_at = 0;    ///< a certified sticking point, above it
  int certified_digits = 0;  ///< significant digits of the threshold given by the bracket
  row_source source = row_source::exact;
  int evaluations = 0;  ///< certified solves used
  /// The threshold estimate (midpoint of the bracket).
  Real value() const { return (rebound_at + stick_at) / 2; }
};

/// Smallest-bracket search for the sticking threshold of `variable` (g or gamma)
/// with the other parameter fixed at `fixed`, to `digits_wanted` significant
/// digits (fewer if an outcome can no longer be certified; `digits` says so).
template <class Real>
threshold_result<Real> sticking_threshold(const contact_law& law, threshold_variable variable, const Real& fixed,
                                          int digits_wanted, const table_settings& settings) {
  using std::abs;
  using std::pow;
  const bool for_g = variable == threshold_variable::g;
  const std::string what = for_g ? "g_c at gamma = " + to_decimal_string(fixed) : "gamma_c at g = " + to_decimal_string(fixed);
  if (digits_wanted < 1 || digits_wanted > settings.digits - 5)
    throw invalid_parameter("sticking threshold digits must be from 1 to the working digits - 5 = " +
                            std::to_string(settings.digits - 5) + ", got " + std::to_string(digits_wanted));
  threshold_result<Real> r;
  // Certified outcome at x (nullopt: not certifiable).
  // NOTE: a solver may refuse to decide (certification_error): within a hair of
  // the threshold the bead turns at u_s ~ 0, where the energy that separates a
  // stop from a return, P(u_s), is below the working precision. That point is
  // as uncertain as an uncertified one, not a failure of the whole search.
  auto sticks = [&](const Real& x) -> std::optional<bool> {
    ++r.evaluations;
    try {
      const point_result<Real> p =
          for_g ? evaluate_point(law, fixed, x, settings) : evaluate_point(law, x, fixed, settings);
      r.source = p.source;
      if (!p.outcome_certified) return std::nullopt;
      return p.outcome == impact_outcome::stick;
    } catch (const certification_error&) {
      return std::nullopt;
    }
  };
  auto certain = [&](const Real& x) -> bool {
    const std::optional<bool> s = sticks(x);
    if (!s)
      throw certification_error(what + ": the outcome at " + std::string(for_g ? "g" : "gamma") + " = " +
                                to_decimal_string(x) + " cannot be certified while bracketing the threshold");
    return *s;
  };

  // Bracket: rebound at lo, stick at hi, by doubling away from 0.
  constexpr int max_doublings = 64;
  Real lo = 0, hi = 0;
  if (!certain(Real(0))) {
    hi = 1;
    for (int i = 0; !certain(hi); ++i, lo = hi, hi *= 2)
      if (i == max_doublings)
        throw convergence_error(what + ": the bead rebounds up to " + std::string(for_g ? "g" : "gamma") + " = " +
                                to_decimal_string(hi) + "; no sticking threshold found");
  } else {
    if (!for_g) throw convergence_error(what + ": the bead sticks already at gamma = 0");
    lo = -1;
    for (int i = 0; certain(lo); ++i, hi = lo, lo *= 2)
      if (i == max_doublings)
        throw convergence_error(what + ": the bead sticks down to g = " + to_decimal_string(lo) +
                                "; no sticking threshold found");
  }

  // Bisection until the bracket is 10^-(digits + 1) of the threshold, so that the
  // midpoint rounded to `digits` digits is off by at most 0.6 in the last digit.
  auto bracket_digits = [&](int most) {
    const Real scale = abs(lo) > abs(hi) ? abs(lo) : abs(hi);
    const Real width = hi - lo;
    int k = 0;
    while (k < most && width <= scale * pow(Real(10), -(k + 2))) ++k;
    return k;
  };
  const int max_halvings = 4 * binary_digits<Real>();
  for (int i = 0; i < max_halvings && bracket_digits(digits_wanted) < digits_wanted; ++i) {
    // The midpoint, or if its outcome cannot be certified (it fell too close to
    // the threshold), points at 3/8, 5/8, 1/4, 3/4 of the bracket: any certified
    // point narrows it.
    bool narrowed = false;
    for (const int eighths : {4, 3, 5, 2, 6}) {
      const Real x = lo + (hi - lo) * eighths / 8;
      if (x == lo || x == hi) continue;  // working precision exhausted
      const std::optional<bool> s = sticks(x);
      if (!s) continue;
      (*s ? hi : lo) = x;
      narrowed = true;
      break;
    }
    if (!narrowed) break;  // too close to the threshold to certify: stop with fewer digits
  }
  r.rebound_at = lo, r.stick_at = hi;
  r.certified_digits = bracket_digits(digits_wanted);
  return r;
}

/// Computes one sticking-threshold row at the working precision of `settings`
/// (in the calling thread). Throws certification_error if fewer than
/// max(1, settings.min_digits) digits could be certified.
inline threshold_row compute_threshold_row(const threshold_point& p, int digits_wanted,
                                           const table_settings& settings) {
  return with_working_precision(settings.digits, [&]<class Real>() -> threshold_row {
    const bool for_g = p.solve_for == threshold_variable::g;
    const Real fixed = parse_real<Real>(p.fixed, for_g ? "gamma" : "g");
    const threshold_result<Real> t = sticking_threshold(p.law, p.solve_for, fixed, digits_wanted, settings);
    if (t.certified_digits < 1 || t.certified_digits < settings.min_digits)
      throw certification_error("row " + std::to_string(p.index) + " (" + p.law.describe() + ", " +
                                (for_g ? "gamma = " : "g = ") + p.fixed + "): threshold certified to " +
                                std::to_string(t.certified_digits) + " digits only (min_digits = " +
                                std::to_string(settings.min_digits) + ")");
    threshold_row row;
    row.index = p.index;
    row.law = p.law.name, row.alpha = p.law.alpha.to_string(), row.beta = p.law.beta.to_string();
    row.solve_for = p.solve_for;
    const std::string value = rounded_decimal(t.value(), t.certified_digits);
    row.gamma = for_g ? p.fixed : value;
    row.g = for_g ? value : p.fixed;
    row.rebound_at = rounded_decimal(t.rebound_at, roundtrip_digits<Real>());
    row.stick_at = rounded_decimal(t.stick_at, roundtrip_digits<Real>());
    row.certified_digits = t.certified_digits;
    row.source = t.source;
    return row;
  });
}

}  // namespace viscor
