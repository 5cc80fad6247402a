// Exact CoR of the linear spring-dashpot, alpha = beta = 1 (report App. D,
// eqs. 109-116, re-derived here): for u > 0, v = u - g solves v'' + gamma v' + v = 0,
// so with xi = gamma/2, lambda = 1 - xi^2 and
//   C(t) = cos(sqrt(lambda) t), S(t) = sin(sqrt(lambda) t)/sqrt(lambda)   (lambda > 0)
//   C(t) = cosh(s t),           S(t) = sinh(s t)/s, s = sqrt(-lambda)   (lambda < 0)
//   C(t) = 1,                   S(t) = t                                (lambda = 0)
// the motion is  u(t)  = g + exp(-xi t) (-g C(t) + (1 - xi g) S(t)),
//                u'(t) =     exp(-xi t) ( C(t) + (g - xi) S(t)).
// Maximal compression t0 is the first zero of u'; contact ends at the first zero
// of u after t0, found by root finding at working precision, unless u' vanishes
// again first (t1 = t0 + pi/omega when underdamped), which is sticking.
// 1 - e comes from the energy identity 1 - e^2 = 2 gamma int_0^T u'^2 dt, whose
// integral has a closed form, so it keeps full relative precision as gamma -> 0.
#pragma once

#include <viscor/core/detail/agreement_digits.hpp>
#include <viscor/core/detail/root_finding.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/widen.hpp>
#include <viscor/exact/exact_result.hpp>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

namespace viscor {

namespace detail {
template <class Real>
struct linear_oscillator {
  Real xi, g, lambda, root_lambda;  // root_lambda = sqrt(|lambda|)

  linear_oscillator(const Real& gamma, const Real& g_) : xi(gamma / 2), g(g_) {
    using std::sqrt;
    using std::abs;
    lambda = (1 - xi) * (1 + xi);  // NOTE: factored so lambda keeps its digits near xi = 1
    root_lambda = sqrt(abs(lambda));
  }
  bool underdamped() const { return lambda > 0; }
  // exp(-xi t) C(t) and exp(-xi t) S(t). NOTE: strongly overdamped, exp(-xi t)
  // underflows while cosh(s t) overflows; there we use the two real roots
  // r1 = -1/(xi + s), r2 = -(xi + s) of r^2 + 2 xi r + 1 = 0 instead.
  Real damped_c(const Real& t) const {
    using std::cos;
    using std::cosh;
    using std::exp;
    if (lambda > 0) return exp(-xi * t) * cos(root_lambda * t);
    if (lambda < 0 && root_lambda >= Real(1) / 2) return (exp(slow_root() * t) + exp(fast_root() * t)) / 2;
    if (lambda < 0) return exp(-xi * t) * cosh(root_lambda * t);
    return exp(-xi * t);
  }
  Real damped_s(const Real& t) const {
    using std::exp;
    using std::sin;
    using std::sinh;
    if (lambda > 0) return exp(-xi * t) * sin(root_lambda * t) / root_lambda;
    if (lambda < 0 && root_lambda >= Real(1) / 2)
      return (exp(slow_root() * t) - exp(fast_root() * t)) / (2 * root_lambda);
    if (lambda < 0) return exp(-xi * t) * sinh(root_lambda * t) / root_lambda;
    return exp(-xi * t) * t;
  }
  Real slow_root() const { return -1 / (xi + root_lambda); }
  Real fast_root() const { return -(xi + root_lambda); }
  // NOTE: strongly overdamped, u' = C + (g - xi) S cancels: its slow part has the
  // coefficient (1 + (g - xi)/s)/2, a difference of two numbers near 1 when the bead
  // creeps out (g < 0, large gamma: e ~ |g|/gamma, all digits lost at gamma = 1e10).
  // In the roots r1 = slow, r2 = fast (r1 r2 = 1, r1 - r2 = 2 s) the coefficients are
  //   u  = g + (1 + g r2)/(2s) e^{r1 t} - (1 + g r1)/(2s) e^{r2 t},
  //   u' = (g + r1)/(2s) e^{r1 t} - (g + r2)/(2s) e^{r2 t},
  // each a sum of like-signed terms for g <= 0 (strongly overdamped under a pull).
  bool by_roots() const { return lambda < 0 && root_lambda >= Real(1) / 2; }
  Real u(const Real& t) const {
    using std::exp;
    if (by_roots()) {
      const Real r1 = slow_root(), r2 = fast_root(), two_s = 2 * root_lambda;
      return g + (1 + g * r2) / two_s * exp(r1 * t) - (1 + g * r1) / two_s * exp(r2 * t);
    }
    return g - g * damped_c(t) + (1 - xi * g) * damped_s(t);
  }
  Real du(const Real& t) const {
    using std::exp;
    if (by_roots()) {
      const Real r1 = slow_root(), r2 = fast_root(), two_s = 2 * root_lambda;
      return (g + r1) / two_s * exp(r1 * t) - (g + r2) / two_s * exp(r2 * t);
    }
    return damped_c(t) + (g - xi) * damped_s(t);
  }
  // int_0^T u'^2 dt for lambda > 0: with omega = sqrt(lambda), K = (g - xi)/omega,
  // u'^2 = e^{-2 xi t} [(1+K^2)/2 + (1-K^2)/2 cos(2 omega t) + K sin(2 omega t)].
  Real dissipation_integral(const Real& T) const {
    using std::cos;
    using std::exp;
    using std::sin;
    using std::expm1;
    const Real omega = root_lambda, K = (g - xi) / omega;
    const Real plain = -expm1(Real(-2 * xi * T)) / (2 * xi);  // int e^{-2 xi t}
    // int e^{(a + i b) t} = (e^{(a+ib)T} - 1)/(a + ib), a = -2 xi, b = 2 omega
    const Real a = -2 * xi, b = 2 * omega, decay = exp(a * T);
    const Real re_num = decay * cos(b * T) - 1, im_num = decay * sin(b * T);
    const Real denom = a * a + b * b;
    const Real cos_part = (re_num * a + im_num * b) / denom;
    const Real sin_part = (im_num * a - re_num * b) / denom;
    return (1 + K * K) / 2 * plain + (1 - K * K) / 2 * cos_part + K * sin_part;
  }
};
}  // namespace detail

namespace detail {
// The closed form evaluated in Real's own arithmetic (exact_linear below makes it
// right to Real's precision).
template <class Real>
exact_result<Real> linear_closed_form(const Real& gamma, const Real& g) {
  using std::atan2;
  using std::atanh;
  using std::exp;
  using std::expm1;
  const Real pi = boost::math::constants::pi<Real>();
  const Real inf = std::numeric_limits<Real>::infinity();
  const detail::linear_oscillator<Real> osc(gamma, g);
  auto du = [&](const Real& t) { return osc.du(t); };
  auto u = [&](const Real& t) { return osc.u(t); };

  exact_result<Real> r;
  r.formula = "linear spring-dashpot closed form (App. D, eqs. 109-116)";

  // Maximal compression: first zero of u' = e^{-xi t}(C + (g - xi) S).
  Real t0;
  if (osc.underdamped()) {
    t0 = atan2(osc.root_lambda, osc.xi - g) / osc.root_lambda;
  } else if (osc.xi - g > osc.root_lambda) {
    t0 = osc.lambda == 0 ? Real(1 / (osc.xi - g)) : Real(atanh(osc.root_lambda / (osc.xi - g)) / osc.root_lambda);
  } else {
    // Overdamped with g >= xi - s > 0: u creeps up to g and never turns back.
    r.outcome = impact_outcome::stick;
    r.e = 0, r.one_minus_e = 1;
    r.time_of_max_compression = inf, r.max_compression = g, r.contact_time = inf;
    return r;
  }
  r.time_of_max_compression = t0;
  r.max_compression = u(t0);

  // End of the restitution phase: the next zero of u' (or never).
  Real t1 = inf;
  if (osc.underdamped()) t1 = t0 + pi / osc.root_lambda;
  const bool returns_to_zero = osc.underdamped() ? u(t1) < 0 : g < 0;
  if (!returns_to_zero) {
    r.outcome = impact_outcome::stick;
    r.e = 0, r.one_minus_e = 1, r.contact_time = t1;
    return r;
  }

  Real tf;
  if (g == 0 && osc.underdamped()) {
    tf = pi / osc.root_lambda;  // u(t) = e^{-xi t} sin(omega t)/omega: exact half period
  } else {
    if (t1 == inf) {  // overdamped with g < 0: u -> g < 0, bracket by doubling
      t1 = t0 + 1;
      for (int i = 0; u(t1) >= 0; ++i, t1 = t0 + 2 * (t1 - t0))
        if (i > 4 * binary_digits<Real>()) throw convergence_error("exact_linear: no bracket for the return to u = 0");
    }
    tf = detail::monotone_root(u, du, t0, t1, "exact_linear: return to u = 0");
  }
  r.contact_time = tf;
  r.outcome = impact_outcome::rebound;
  r.e = -du(tf);
  if (gamma == 0) {
    r.e = 1, r.one_minus_e = 0;  // energy is conserved exactly
  } else if (g == 0 && osc.underdamped()) {
    r.e = exp(-osc.xi * tf);
    r.one_minus_e = -expm1(Real(-osc.xi * tf));
  } else if (osc.underdamped()) {
    // NOTE: u'(T_f) carries the cancellation of terms of size g (and T_f an error
    // ~ eps g / e), so for large g it loses log10(g) digits. The dissipated
    // energy D = 1 - e^2 is insensitive to T_f (dD/dT_f = 2 gamma e^2); while
    // D <= 1/2, sqrt(1 - D) gives e to full precision.
    using std::sqrt;
    const Real dissipated = 2 * gamma * osc.dissipation_integral(tf);
    if (dissipated <= Real(1) / 2) r.e = sqrt(1 - dissipated);
    r.one_minus_e = dissipated / (1 + r.e);
  } else {
    r.one_minus_e = 1 - r.e;  // gamma >= 2: e is far from 1, no cancellation
  }
  return r;
}

#if VISCOR_HAS_MPFR
// Whether two evaluations of the closed form share `digits` significant digits in
// every quantity (and the outcome).
inline bool closed_forms_agree(const exact_result<mpfr_real>& a, const exact_result<mpfr_real>& b, int digits) {
  if (a.outcome != b.outcome) return false;
  auto same = [&](const mpfr_real& x, const mpfr_real& y) { return agreement_digits(x, y, y, digits) >= digits; };
  auto same_optional = [&](const std::optional<mpfr_real>& x, const std::optional<mpfr_real>& y) {
    return x.has_value() == y.has_value() && (!x || same(*x, *y));
  };
  return same(a.e, b.e) && same(a.one_minus_e, b.one_minus_e) && same_optional(a.contact_time, b.contact_time) &&
         same_optional(a.max_compression, b.max_compression) &&
         same_optional(a.time_of_max_compression, b.time_of_max_compression);
}

template <class Real>
std::optional<Real> narrow_optional(const std::optional<mpfr_real>& x, int digits) {
  if (!x) return std::nullopt;
  return narrow<Real>(*x, static_cast<unsigned>(digits));
}
#endif
}  // namespace detail

/// Exact impact of the linear spring-dashpot (alpha = beta = 1) for any gamma >= 0
/// and g, every quantity right to Real's precision. NOTE: the closed form cancels:
/// u_max, T_f and u'(T_f) are differences of terms of size |g| and gamma (measured in
/// double: up to 12 digits lost at g = -1e6, 30 at g = -1e12, 11 near critical
/// damping), and at working precision its root finder may not even bracket T_f. So
/// it is evaluated in mpfr_real with guard digits, checked by a second evaluation 20
/// digits wider, and the guard doubled until the two agree to Real's digits + 2.
template <class Real>
exact_result<Real> exact_linear(const Real& gamma, const Real& g) {
  require_non_negative(gamma, "gamma");
  require_finite(g, "g");
#if VISCOR_HAS_MPFR
  using std::abs;
  using std::log10;
  const int digits = decimal_digits<Real>();
  const auto order = [](const Real& x) {  // decimal order of magnitude of max(1, |x|)
    return abs(x) > 1 ? static_cast<int>(static_cast<double>(Real(log10(abs(x))))) + 1 : 0;
  };
  constexpr int most_digits = 5000;
  for (int guard = 10 + 3 * order(g) + order(gamma); digits + guard <= most_digits; guard *= 2) {
    std::optional<exact_result<mpfr_real>> low, high;
    try {
      for (auto [result, precision] : {std::pair{&low, digits + guard}, std::pair{&high, digits + guard + 20}}) {
        scoped_precision scope(precision);
        *result = detail::linear_closed_form(detail::widen<mpfr_real>(gamma), detail::widen<mpfr_real>(g));
      }
    } catch (const convergence_error&) {
      continue;  // the guard was too small to bracket the end of contact
    }
    scoped_precision scope(digits + guard + 20);
    if (!detail::closed_forms_agree(*low, *high, digits + 2)) continue;
    exact_result<Real> r;
    r.e = detail::narrow<Real>(high->e, digits), r.one_minus_e = detail::narrow<Real>(high->one_minus_e, digits);
    r.outcome = high->outcome;
    r.contact_time = detail::narrow_optional<Real>(high->contact_time, digits);
    r.max_compression = detail::narrow_optional<Real>(high->max_compression, digits);
    r.time_of_max_compression = detail::narrow_optional<Real>(high->time_of_max_compression, digits);
    r.formula = high->formula;
    return r;
  }
  throw convergence_error("exact_linear: the closed form did not settle below " + std::to_string(most_digits) +
                          " digits (gamma, g too extreme)");
#else
  return detail::linear_closed_form(gamma, g);
#endif
}

}  // namespace viscor
