// Maximal compression of the undamped impact (gamma = 0), report eq. (13):
// u_M is the positive root of  u^(alpha+1)/(alpha+1) - g u = 1/2,  where the
// velocity (11) of the conservative motion vanishes.
//
// NOTE: for g >= 0 the left side f(u) is convex with f(0) < 0. With
//   A = ((alpha+1)/2)^(1/(alpha+1))  (the root at g = 0, eq. 20) and
//   B = ((alpha+1) g)^(1/alpha)      (where u^(alpha+1)/(alpha+1) = g u),
// f(max(A, B)) <= 0 and, because (A + B)^alpha >= A^alpha + B^alpha for
// alpha >= 1, f(A + B) >= 0: the bracket [max(A, B), A + B] is analytic and
// tight (width < a factor 2) for every g from 0 to 1e12 and beyond.
// For g < 0 (a load pulling the bead off) f is increasing and the root lies in
// (0, min(A, 1/(2|g|))].
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/root_finding.hpp>
#include <viscor/core/parameters.hpp>

#include <cmath>
#include <string>
#include <utility>

namespace viscor {

namespace detail {

/// Throws invalid_parameter unless the exponent x is finite and >= 1 (Assumption 1).
template <class Real>
void require_exponent(const Real& x, const std::string& name) {
  require_finite(x, name);
  if (!(x >= 1))
    throw invalid_parameter("contact law exponent " + name + " must be >= 1, got " + name + " = " +
                            to_decimal_string(x));
}

/// Analytic bracket [lo, hi] of u_M(g) (see the header comment).
template <class Real>
std::pair<Real, Real> u_max_bracket(const Real& alpha, const Real& g) {
  using std::pow;
  using std::abs;
  const Real a = pow((alpha + 1) / 2, 1 / (alpha + 1));
  if (g == 0) return {a, a};
  if (g < 0) {
    const Real hi = 1 / (2 * abs(g));
    return {Real(0), hi < a ? hi : a};
  }
  const Real b = pow((alpha + 1) * g, 1 / alpha);
  return {a > b ? a : b, a + b};
}

/// Widens [lo, hi] (0 <= lo <= hi) by a few ulps at a time until the increasing
/// function f is <= 0 at lo and >= 0 at hi: the analytic bracket holds exactly,
/// but f at its ends is rounded, and at g = 1e12 or g -> 0 an end lies within
/// rounding of the root.
template <class Real, class F>
void widen_bracket(F f, Real& lo, Real& hi, const char* what) {
  const Real eps = epsilon<Real>();
  Real step = 4 * eps;
  for (int i = 0; f(lo) > 0; ++i, step *= 4) {
    if (i > 64) throw convergence_error(std::string(what) + ": cannot bracket the root");
    lo *= 1 - step;
  }
  step = 4 * eps;
  for (int i = 0; f(hi) < 0; ++i, step *= 4) {
    if (i > 64) throw convergence_error(std::string(what) + ": cannot bracket the root");
    hi *= 1 + step;
  }
}

}  // namespace detail

/// u_M(g): maximal compression of the undamped motion, the root of eq. (13),
/// to working precision, for any finite g (g >= 0 in the report).
template <class Real>
Real u_max(const Real& alpha, const Real& g) {
  detail::require_exponent(alpha, "alpha");
  require_finite(g, "g");
  using std::pow;
  auto [lo, hi] = detail::u_max_bracket(alpha, g);
  if (lo == hi) return lo;  // g = 0: eq. (20)
  const Real a1 = alpha + 1;
  // NOTE: written as u (u^alpha/(alpha+1) - g) - 1/2, one pow per evaluation.
  auto f = [&](const Real& u) -> Real { return u * (pow(u, alpha) / a1 - g) - Real(1) / 2; };
  auto df = [&](const Real& u) -> Real { return pow(u, alpha) - g; };
  detail::widen_bracket(f, lo, hi, "u_max: root of eq. (13)");
  // NOTE: a fixed message: formatting g here would cost more than the root itself.
  static const std::string what = "u_max: root of eq. (13)";
  return detail::monotone_root(f, df, lo, hi, what);
}

/// u_M(g) for a contact law (only alpha matters).
template <class Real>
Real u_max(const contact_law& law, const Real& g) {
  law.validate();
  return u_max(law.alpha.value<Real>(), g);
}

}  // namespace viscor
