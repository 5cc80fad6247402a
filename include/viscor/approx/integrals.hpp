// The integrals of the O(gamma^2) expansion (Prop. 2), by double-exponential
// quadrature (Takahasi and Mori 1974; Bailey, Jeyabalan and Li 2005; Boost.Math)
// at the working precision of Real:
//   I(g)     = 2 int_0^{u_M} F^(1/2) u^(beta-1) du       eqs. (41)/(68), corrected as in docs/report-notes.md
//   Q(g)     =   int_0^{u_M} F^(-1/2) u^(beta-1) du      eq. (42) corrected
//   dI/dg(g) = 2 int_0^{u_M} F^(-1/2) u^beta du          eq. (19), with I's factor 2
// with F(u) = 1 + 2 (g u - u^(alpha+1)/(alpha+1)) and u_M(g) the root of eq. (13).
//
// Primary method (integrals_IQ, integral_dI_dg). In r = u/u_M, eq. (13) turns F into a
// sum of two non-negative terms (no cancellation even at g = 1e12, where F itself
// would lose 20 digits):
//   F = (1 - r) + P r (1 - r^alpha),   P = 2 u_M^(alpha+1)/(alpha+1) = 1/theta  (eq. 43).
// F has two features that slow tanh-sinh down:
//  * at r = 1, F ~ (1 - r): an inverse-square-root end point (half the digits lost).
//    NOTE: on [1/2, 1] we substitute r = 1 - t^2, which makes the integrand smooth:
//    F = t^2 H, H = 1 + P r (1 - r^alpha)/t^2, and F^(+-1/2) dr = 2 t^(1 +- 1) H^(+-1/2) dt.
//  * at r ~ theta, F goes from 1 to P r: for large g, theta is tiny (1e-20 at g = 1e12)
//    and the integrand has a singularity at r = -theta, a relative distance theta from
//    the end point; tanh-sinh then converges slowly and its error estimate misleads.
//    NOTE: for theta < 1/4 we integrate [0, theta] in r and [theta, 1/2] in v = ln r,
//    where the singularity sits at Im v = pi, far from the real axis for every theta.
//
// Independent method (m_integral, j_integral; with K, L of chebyshev_beta.hpp they give
// I = K J, Q = L M, eqs. 45-47): the integrals of eq. (91) in x = u/u_M,
//   J_{alpha,beta}(theta) = int_0^1 B^(1/2)  x^(beta-1) dx,   M_{alpha,beta}(theta) = int_0^1 B^(-1/2) x^(beta-1) dx,
//   B = theta + (1 - theta) x - x^(alpha+1) = theta F,
// with [1/2, 1] by tanh-sinh with its singular end point kept and handled by Boost's
// two-argument functor (the exact distance 1 - x), and [0, 1/2] by exp-sinh after
// x = exp(-w)/2, or, for 0 < theta < 1/4, [0, theta] by exp-sinh after x = theta exp(-w)
// and [theta, 1/2] by adaptive Gauss-Kronrod in ln x. Different variables, different
// quadrature rules, different treatment of both difficulties: the two methods share
// no code beyond u_M and theta(g), whose own tests check them. It is slower than the
// primary method, and meant for checks and for the Chebyshev-Beta error tables.
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/approx/u_max.hpp>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace viscor {

namespace detail {

/// One quadrature engine per scalar type and precision, built on first use and
/// shared: building one costs far more than an integration (8 ms at 50 digits).
/// NOTE: the abscissas of run-time mpfr_real are computed at the precision in
/// force when they are built, so that type gets one engine per precision.
/// Boost extends an engine's rows under its own lock, so sharing is thread-safe.
/// Returned non-const: Boost 1.81 defines the two-argument finite-interval
/// tanh_sinh::integrate without the const its declaration carries.
template <class Engine, class Real>
Engine& quadrature_engine(std::size_t max_levels) {
  if constexpr (has_fixed_precision<Real>()) {
    static Engine shared(max_levels);
    return shared;
  } else {
    static std::mutex guard;
    static std::map<int, std::unique_ptr<Engine>> engines;
    const std::lock_guard<std::mutex> lock(guard);
    auto& slot = engines[binary_digits<Real>()];
    if (!slot) slot = std::make_unique<Engine>(max_levels);
    return *slot;
  }
}

template <class Real>
boost::math::quadrature::tanh_sinh<Real>& tanh_sinh_engine() {
  return quadrature_engine<boost::math::quadrature::tanh_sinh<Real>, Real>(15);  // Boost's default
}

/// NOTE: 16 levels rather than Boost's 9: for small theta the integrand of the
/// independent method changes over a unit width at w = ln(1/(2 theta)), where
/// exp-sinh's nodes are sparse; rows are built lazily, only when needed.
template <class Real>
boost::math::quadrature::exp_sinh<Real>& exp_sinh_engine() {
  return quadrature_engine<boost::math::quadrature::exp_sinh<Real>, Real>(16);
}

/// Quadrature tolerance. NOTE: the error estimate of a double-exponential rule is
/// the difference of two levels, about the square root of the true error once the
/// rule converges; on the smooth, well-scaled pieces used here eps^(3/4) stops at
/// full precision, where sqrt(eps) was seen to stop a few digits short.
template <class Real>
Real quadrature_tolerance() {
  using std::sqrt;
  const Real eps = epsilon<Real>();
  return sqrt(eps) * sqrt(sqrt(eps));
}

template <class Real>
void check_quadrature(const Real& value, const Real& error, const Real& l1, const char* what) {
  using boost::math::isfinite;
  using std::sqrt;
  // Boost stops at its level limit or when roundoff makes the estimate grow; an
  // estimate far above the tolerance then means the rule never converged.
  if (!isfinite(value) || !(error <= sqrt(quadrature_tolerance<Real>()) * l1))
    throw convergence_error(std::string(what) + ": quadrature did not converge");
}

/// int_a^b f(x, xc) dx by tanh-sinh, xc = x - a on the left half and b - x on the
/// right half, both exact (Boost's two-argument form).
template <class Real, class F>
Real tanh_sinh_integral(F f, const Real& a, const Real& b, const char* what) {
  Real error = 0, l1 = 0;
  const Real value = tanh_sinh_engine<Real>().integrate(
      [&](const Real& x, const Real& xc) -> Real { return xc < 0 ? f(x, Real(-xc)) : f(x, xc); }, a, b,
      quadrature_tolerance<Real>(), &error, &l1);
  check_quadrature(value, error, l1, what);
  return value;
}

/// int_0^infinity f(w) dw by exp-sinh.
template <class Real, class F>
Real exp_sinh_integral(F f, const char* what) {
  Real error = 0, l1 = 0;
  const Real value = exp_sinh_engine<Real>().integrate(f, quadrature_tolerance<Real>(), &error, &l1);
  check_quadrature(value, error, l1, what);
  return value;
}

/// int_0^1 F^(sigma/2) r^m dr for F = (1 - r) + P r (1 - r^alpha), sigma = +1 or -1,
/// by the piecewise scheme of the header comment.
template <class Real>
Real f_power_integral(const Real& alpha, const Real& p, int sigma, const Real& m, const char* what) {
  using std::pow;
  using std::sqrt;
  using std::exp;
  using std::log;
  using std::log1p;
  using std::expm1;
  const Real half = Real(1) / 2;
  // F^(sigma/2) for r <= 1/2, where neither term cancels.
  auto f_pow = [&](const Real& r) -> Real {
    const Real f = (1 - r) + p * r * (1 - pow(r, alpha));
    return sigma > 0 ? Real(sqrt(f)) : Real(1 / sqrt(f));
  };
  // [1/2, 1] in t, r = 1 - t^2: 2 t^(1+sigma) H^(sigma/2) r^m.
  const Real t_max = sqrt(half);
  const Real right = tanh_sinh_integral<Real>(
      [&](const Real& t, const Real&) -> Real {
        const Real s = t * t, r = 1 - s;
        // (1 - r^alpha)/s = -expm1(alpha log1p(-s))/s, by its series when s underflows.
        const Real ratio = s < epsilon<Real>() ? Real(alpha - alpha * (alpha - 1) * s / 2)
                                               : Real(-expm1(alpha * log1p(-s)) / s);
        const Real h = 1 + p * r * ratio;
        const Real weight = 2 * pow(r, m);
        return sigma > 0 ? Real(weight * s * sqrt(h)) : Real(weight / sqrt(h));
      },
      Real(0), t_max, what);
  const Real theta = 1 / p;
  if (!(theta < half / 2)) {
    // F changes slowly on [0, 1/2]: one piece in r.
    const Real left = tanh_sinh_integral<Real>(
        [&](const Real& r, const Real&) -> Real { return f_pow(r) * pow(r, m); }, Real(0), half, what);
    return left + right;
  }
  // [0, theta] in r; [theta, 1/2] in v = ln r (dr = r dv).
  const Real near_zero = tanh_sinh_integral<Real>(
      [&](const Real& r, const Real&) -> Real { return f_pow(r) * pow(r, m); }, Real(0), theta, what);
  const Real middle = tanh_sinh_integral<Real>(
      [&](const Real& v, const Real&) -> Real {
        const Real r = exp(v);
        return f_pow(r) * pow(r, m + 1);
      },
      Real(log(theta)), Real(-log(Real(2))), what);
  return near_zero + middle + right;
}

}  // namespace detail

/// Values shared by the integrals at one g.
template <class Real>
struct integral_values {
  Real u_max;  ///< u_M(g), eq. (13)
  Real I;      ///< I(g), eq. (41) corrected, with the factor 2 of Prop. 2
  Real Q;      ///< Q(g), eq. (42) corrected
};

/// I(g) and Q(g) by the primary (piecewise tanh-sinh) method; any finite g
/// (the report needs g >= 0; g < 0 is a load pulling the bead off).
template <class Real>
integral_values<Real> integrals_IQ(const Real& alpha, const Real& beta, const Real& g) {
  detail::require_exponent(beta, "beta");
  using std::pow;
  integral_values<Real> v;
  v.u_max = u_max(alpha, g);  // validates alpha and g
  const Real p = 2 * pow(v.u_max, alpha + 1) / (alpha + 1);
  const Real scale = pow(v.u_max, beta), bm1 = beta - 1;
  v.Q = scale * detail::f_power_integral(alpha, p, -1, bm1, "Q(g)");
  v.I = 2 * scale * detail::f_power_integral(alpha, p, +1, bm1, "I(g)");
  return v;
}

/// I(g), eq. (41) corrected (factor 2 included).
template <class Real>
Real integral_I(const Real& alpha, const Real& beta, const Real& g) {
  return integrals_IQ(alpha, beta, g).I;
}

/// Q(g), eq. (42) corrected.
template <class Real>
Real integral_Q(const Real& alpha, const Real& beta, const Real& g) {
  return integrals_IQ(alpha, beta, g).Q;
}

/// dI/dg(g) = 2 int_0^{u_M} F^(-1/2) u^beta du, eq. (19) with I's factor 2.
template <class Real>
Real integral_dI_dg(const Real& alpha, const Real& beta, const Real& g) {
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real um = u_max(alpha, g);
  const Real p = 2 * pow(um, alpha + 1) / (alpha + 1);
  return 2 * pow(um, beta + 1) * detail::f_power_integral(alpha, p, -1, beta, "dI/dg(g)");
}

// Contact-law overloads.
template <class Real>
integral_values<Real> integrals_IQ(const contact_law& law, const Real& g) {
  law.validate();
  return integrals_IQ(law.alpha.value<Real>(), law.beta.value<Real>(), g);
}
template <class Real>
Real integral_I(const contact_law& law, const Real& g) { return integrals_IQ(law, g).I; }
template <class Real>
Real integral_Q(const contact_law& law, const Real& g) { return integrals_IQ(law, g).Q; }

namespace detail {

template <class Real>
void require_theta(const Real& theta) {
  require_finite(theta, "theta");
  if (theta < 0 || theta > 1)
    throw invalid_parameter("parameter theta must lie in [0, 1], got theta = " + to_decimal_string(theta));
}

/// B = theta + (1 - theta) x - x^(alpha+1) at x in [1/2, 1), given y = 1 - x exactly:
/// 1 - (1 - theta) y - (1 - y)^(alpha+1), whose two terms differ by (alpha + theta) y.
template <class Real>
Real theta_bracket_near_one(const Real& alpha, const Real& theta, const Real& y) {
  using std::expm1;
  using std::log1p;
  return -(1 - theta) * y - expm1((alpha + 1) * log1p(-y));
}

/// int_0^1 B^(sigma/2) x^(beta-1) dx by the independent method of the header comment.
template <class Real>
Real theta_form_integral(const Real& alpha, const Real& beta, const Real& theta, int sigma, const char* what) {
  using std::pow;
  using std::sqrt;
  using std::exp;
  using std::log;
  const Real half = Real(1) / 2;
  // B^(sigma/2) x^beta for x <= 1/2, where B has no cancellation.
  auto left_integrand = [&](const Real& x) -> Real {
    if (x == 0) return Real(0);
    const Real b = theta + x * ((1 - theta) - pow(x, alpha));
    return (sigma > 0 ? Real(sqrt(b)) : Real(1 / sqrt(b))) * pow(x, beta);
  };
  Real left;
  if (theta == 0 || theta >= half / 2) {
    // x = exp(-w)/2 maps [0, 1/2] onto [0, infinity): dx = -x dw.
    left = exp_sinh_integral<Real>([&](const Real& w) -> Real { return left_integrand(Real(exp(-w) / 2)); }, what);
  } else {
    // B goes from theta to x near x = theta: [0, theta] with x = theta exp(-w) by exp-sinh,
    // [theta, 1/2] in v = ln x by adaptive Gauss-Kronrod.
    const Real near_zero =
        exp_sinh_integral<Real>([&](const Real& w) -> Real { return left_integrand(Real(theta * exp(-w))); }, what);
    Real error = 0, l1 = 0;
    const Real middle = boost::math::quadrature::gauss_kronrod<Real, 31>::integrate(
        [&](const Real& v) -> Real { return left_integrand(Real(exp(v))); }, Real(log(theta)), Real(-log(Real(2))),
        30, quadrature_tolerance<Real>(), &error, &l1);
    check_quadrature(middle, error, l1, what);
    left = near_zero + middle;
  }
  const Real right = tanh_sinh_integral<Real>(
      [&](const Real& x, const Real& xc) -> Real {
        // xc is the exact distance to the nearer end: 1 - x near x = 1.
        const Real y = x > Real(3) / 4 ? xc : Real(1 - x);
        const Real b = theta_bracket_near_one(alpha, theta, y);
        return (sigma > 0 ? Real(sqrt(b)) : Real(1 / sqrt(b))) * pow(x, beta - 1);
      },
      half, Real(1), what);
  return left + right;
}

}  // namespace detail

/// M_{alpha,beta}(theta) of eq. (91) (alpha, beta >= 1, theta in [0, 1]), by the
/// independent quadrature (exp-sinh and two-argument tanh-sinh).
template <class Real>
Real m_integral(const Real& alpha, const Real& beta, const Real& theta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  detail::require_theta(theta);
  return detail::theta_form_integral(alpha, beta, theta, -1, "M_{alpha,beta}(theta)");
}

/// J_{alpha,beta}(theta) of eq. (91), same method.
template <class Real>
Real j_integral(const Real& alpha, const Real& beta, const Real& theta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  detail::require_theta(theta);
  return detail::theta_form_integral(alpha, beta, theta, +1, "J_{alpha,beta}(theta)");
}

}  // namespace viscor
