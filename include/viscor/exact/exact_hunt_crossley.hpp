// Exact CoR of the Hunt-Crossley form beta = alpha + 1 at g = 0 (any alpha >= 1).
// With v = u' and p = gamma beta the equation is u'' = -u^alpha (1 + p v), which
// separates in the phase plane: with U = u^(alpha+1)/(alpha+1), dU/dv = -v/(1 + p v).
// Contact starts at (U, v) = (0, 1) and ends at (0, -e), so
//     int_{-e}^{1} v/(1 + p v) dv = 0   <=>   (1 + e) p = ln((1 + p)/(1 - p e)),
// independent of alpha; u_max^(alpha+1)/(alpha+1) = int_0^1 v/(1+pv) dv.
// NOTE: as p -> 0, e -> 1 and the log form cancels. For p <= 1/4 we solve instead
// for d = 1 - e the series  sum_{k>=2} p^(k-2) ((-1)^k - e^k)/k = 0  (the log form
// divided by p^2), whose terms carry d exactly; for p > 1/4 we solve for
// y = -ln(1 - p e), which stays well scaled even when p e -> 1 for large p:
//     y = p + 1 - exp(-y) - ln(1 + p),   e = (1 - exp(-y))/p.
#pragma once

#include <viscor/core/detail/root_finding.hpp>
#include <viscor/exact/exact_result.hpp>
#include <viscor/core/parameters.hpp>


#include <cmath>

namespace viscor {

namespace detail {
// sum_{k>=0} (-p)^k/(k+2) = (p - ln(1+p))/p^2 for |p| < 1, to working precision.
template <class Real>
Real p_minus_log1p_over_p2(const Real& p) {
  using std::abs;
  const Real eps = epsilon<Real>();
  Real sum = 0, power = 1;
  for (int k = 0;; ++k, power *= -p) {
    const Real term = power / (k + 2);
    sum += term;
    if (abs(term) <= eps * abs(sum)) break;
    if (k > 16 * binary_digits<Real>()) throw convergence_error("Hunt-Crossley series did not converge");
  }
  return sum;
}

// The series in d = 1 - e, for p <= 1/4.
template <class Real>
Real hunt_crossley_series(const Real& p, const Real& d) {
  using std::abs;
  const Real e = 1 - d, eps = epsilon<Real>();
  Real sum = 0, p_power = 1;   // p^(k-2)
  Real geometric = 1 + e;      // S_k = 1 + e + ... + e^(k-1), so 1 - e^k = d S_k
  for (int k = 2;; ++k) {
    const Real one_minus_ek = d * geometric;
    const Real term = p_power * ((k % 2 == 0) ? one_minus_ek : Real(-(2 - one_minus_ek))) / k;
    sum += term;
    if (abs(term) <= eps * eps + eps * abs(sum) && k > 3) break;
    if (k > 16 * binary_digits<Real>()) throw convergence_error("Hunt-Crossley series did not converge");
    p_power *= p;
    geometric = 1 + e * geometric;
  }
  return sum;
}
}  // namespace detail

/// Exact CoR for beta = alpha + 1, g = 0 (Hunt-Crossley form); p = gamma (alpha + 1).
template <class Real>
exact_result<Real> exact_hunt_crossley(const Real& alpha, const Real& gamma) {
  require_finite(alpha, "alpha");
  if (alpha < 1) throw invalid_parameter("parameter alpha must be >= 1, got " + to_decimal_string(alpha));
  require_non_negative(gamma, "gamma");
  using std::exp;
  using std::pow;
  using std::expm1;
  using std::log1p;
  exact_result<Real> r;
  r.formula = "Hunt-Crossley form beta = alpha + 1, g = 0: (1 + e) p = ln((1 + p)/(1 - p e))";
  r.outcome = impact_outcome::rebound;  // e > 0 for every p: the line v = -1/p is never crossed
  const Real p = gamma * (alpha + 1);
  if (p == 0) {
    r.e = 1, r.one_minus_e = 0;
    r.max_compression = pow((alpha + 1) / 2, 1 / (alpha + 1));
    return r;
  }
  Real energy_at_max;  // u_max^(alpha+1)/(alpha+1)
  if (p <= Real(1) / 4) {
    auto f = [&](const Real& d) { return detail::hunt_crossley_series(p, d); };
    r.one_minus_e = detail::bracketed_root(f, Real(0), Real(1), "Hunt-Crossley relation");
    r.e = 1 - r.one_minus_e;
    energy_at_max = detail::p_minus_log1p_over_p2(p);  // = 1/p - ln(1+p)/p^2 without cancellation
  } else {
    const Real log_1p = log1p(p);
    auto h = [&](const Real& y) { return p + 1 - exp(-y) - log_1p - y; };
    const Real y = detail::bracketed_root(h, Real(0), Real(p + 1), "Hunt-Crossley relation");
    r.e = -expm1(-y) / p;
    r.one_minus_e = 1 - r.e;
    energy_at_max = 1 / p - log_1p / (p * p);
  }
  r.max_compression = pow((alpha + 1) * energy_at_max, 1 / (alpha + 1));
  return r;
}

}  // namespace viscor
