// Closed-form coefficients of the report, all through Euler's Beta function by
// the report's Definition 1:
//   int_0^{rho^(-1/lambda)} t^x (1 - rho t^lambda)^y dt = B((x+1)/lambda, y+1) / (lambda rho^((x+1)/lambda)).
//
// Conventions (as in Prop. 2, with the typos of docs/report-notes.md corrected):
//   I(g) = 2 int_0^{u_M} F^(1/2) u^(beta-1) du,  Q(g) = int_0^{u_M} F^(-1/2) u^(beta-1) du,
//   F(u) = 1 + 2 (g u - u^(alpha+1)/(alpha+1)),  u_M(0) = ((alpha+1)/2)^(1/(alpha+1))  (eq. 20).
// I carries the factor 2 of Prop. 2, so eq. (22) reads e = 1 - gamma beta I(0) - gamma g beta I'(0):
//   C0 = beta I(0),  C1 = beta dI/dg(0),  dI/dg(g) = 2 int_0^{u_M} F^(-1/2) u^beta du  (eq. 19, times 2).
// At g = 0, Prop. 2's linearised form (38) gives e = 1 - C0 gamma - C2 gamma^2 with
//   C2 = -beta^2 I(0) (Q(0) - I(0)/2)
//      = -beta^3 (alpha+1)^(2z-1) / (2^(2z-2) (alpha+2beta+1)^2) B(z, 1/2)^2,  z = beta/(alpha+1)
// (the formula after eq. 40); for Kuwabara-Kono it equals Schwager-Poschel's (30).
// Large g, eq. (23): e^2 = 1 - 2 gamma C g^p with p = beta/alpha + 1/(2 alpha) + 1/2 and
//   C = 2 sqrt(2) (beta/alpha) (alpha+1)^(beta/alpha + 1/(2 alpha)) B((beta + 1/2)/alpha, 3/2);
// e = 0 from g_c = (2 gamma C)^(-1/p) on (eq. 24), or for gamma >= gamma_c(g) = 1/(2 C g^p).
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/approx/u_max.hpp>

#include <boost/math/constants/constants.hpp>
#include <viscor/approx/detail/beta_function.hpp>

#include <cmath>
#include <string>

namespace viscor {

/// I(0), eq. (39): ((alpha+1)/2)^(beta/(alpha+1) - 1) (alpha+1)/(alpha+1+2 beta) B(1/2, beta/(alpha+1)).
template <class Real>
Real integral_I_at_zero(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real a1 = alpha + 1, z = beta / a1;
  return pow(a1 / 2, z - 1) * a1 / (a1 + 2 * beta) * detail::beta_function<Real>(Real(1) / 2, z);
}

/// Q(0), eq. (40): ((alpha+1)/2)^(beta/(alpha+1) - 1) B(beta/(alpha+1), 1/2) / 2.
template <class Real>
Real integral_Q_at_zero(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real a1 = alpha + 1, z = beta / a1;
  return pow(a1 / 2, z - 1) * detail::beta_function<Real>(z, Real(1) / 2) / 2;
}

/// dI/dg at g = 0, eq. (19) with I's factor 2: ((alpha+1)/2)^((beta+1)/(alpha+1) - 1) B((beta+1)/(alpha+1), 1/2).
template <class Real>
Real integral_dI_dg_at_zero(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real a1 = alpha + 1, z = (beta + 1) / a1;
  return pow(a1 / 2, z - 1) * detail::beta_function<Real>(z, Real(1) / 2);
}

/// C0 of eq. (22): beta ((alpha+1)/2)^((beta-alpha-1)/(alpha+1)) B(beta/(alpha+1), 3/2) = beta I(0).
template <class Real>
Real coefficient_C0(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real a1 = alpha + 1;
  return beta * pow(a1 / 2, (beta - a1) / a1) * detail::beta_function<Real>(beta / a1, Real(3) / 2);
}

/// C1 of eq. (22): beta ((alpha+1)/2)^((beta-alpha)/(alpha+1)) B((beta+1)/(alpha+1), 1/2) = beta dI/dg(0).
template <class Real>
Real coefficient_C1(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real a1 = alpha + 1;
  return beta * pow(a1 / 2, (beta - alpha) / a1) * detail::beta_function<Real>((beta + 1) / a1, Real(1) / 2);
}

/// Exponent p = beta/alpha + 1/(2 alpha) + 1/2 of g in eqs. (23), (24).
template <class Real>
Real large_g_exponent(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  return (2 * beta + 1 + alpha) / (2 * alpha);
}

/// C of eq. (23): 2 sqrt(2) (beta/alpha) (alpha+1)^(beta/alpha + 1/(2 alpha)) B((beta + 1/2)/alpha, 3/2).
template <class Real>
Real coefficient_C(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  using std::sqrt;
  const Real half = Real(1) / 2;
  return 2 * sqrt(Real(2)) * beta / alpha * pow(alpha + 1, (2 * beta + 1) / (2 * alpha)) *
         detail::beta_function<Real>((beta + half) / alpha, Real(3) / 2);
}

/// C2 at g = 0 (formula after eq. 40): -beta^2 I(0) (Q(0) - I(0)/2), written with one Beta function.
template <class Real>
Real coefficient_C2_at_zero(const Real& alpha, const Real& beta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  using std::pow;
  const Real a1 = alpha + 1, z = beta / a1, b = detail::beta_function<Real>(z, Real(1) / 2), d = a1 + 2 * beta;
  return -beta * beta * beta * pow(a1, 2 * z - 1) / (pow(Real(2), 2 * z - 2) * d * d) * b * b;
}

/// Schwager-Poschel's first coefficient for Kuwabara-Kono at g = 0: c1 = -C0(3/2, 3/2)/(3/2)
/// (the report prints -1.15448854 with two digits swapped; docs/report-notes.md).
template <class Real>
Real schwager_poschel_c1() {
  const Real three_halves = Real(3) / 2;
  return -coefficient_C0(three_halves, three_halves) / three_halves;
}

/// Schwager-Poschel's second coefficient c2 = (3/5) c1^2 (the report prints 0.7982665553; docs/report-notes.md).
template <class Real>
Real schwager_poschel_c2() {
  const Real c1 = schwager_poschel_c1<Real>();
  return Real(3) / 5 * c1 * c1;
}

/// C2 = -(9/4) c2, eq. (30): Kuwabara-Kono only.
template <class Real>
Real schwager_poschel_C2() {
  return -Real(9) / 4 * schwager_poschel_c2<Real>();
}

/// g_c(gamma) of eq. (24): g_c^p = 1/(2 gamma C), i.e. g_c = (2 gamma C)^(-1/p); gamma > 0.
template <class Real>
Real critical_g(const Real& alpha, const Real& beta, const Real& gamma) {
  require_positive(gamma, "gamma");
  using std::pow;
  return pow(2 * gamma * coefficient_C(alpha, beta), -1 / large_g_exponent(alpha, beta));
}

/// gamma_c(g), the inverse of eq. (24): gamma_c = 1/(2 C g^p); g > 0.
template <class Real>
Real critical_gamma(const Real& alpha, const Real& beta, const Real& g) {
  require_positive(g, "g");
  using std::pow;
  return 1 / (2 * coefficient_C(alpha, beta) * pow(g, large_g_exponent(alpha, beta)));
}

/// Every closed form of one law, computed once (they cost a Beta function each).
template <class Real>
struct closed_form_coefficients {
  Real alpha, beta;
  Real I0;      ///< I(0), eq. (39)
  Real Q0;      ///< Q(0), eq. (40)
  Real dI_dg0;  ///< dI/dg(0), eq. (19)
  Real C0, C1;  ///< eq. (22)
  Real C;       ///< eq. (23)
  Real p;       ///< exponent of g in eq. (23)
  Real C2;      ///< C2 at g = 0, after eq. (40)

  closed_form_coefficients(const Real& alpha_, const Real& beta_)
      : alpha(alpha_),
        beta(beta_),
        I0(integral_I_at_zero(alpha_, beta_)),
        Q0(integral_Q_at_zero(alpha_, beta_)),
        dI_dg0(integral_dI_dg_at_zero(alpha_, beta_)),
        C0(coefficient_C0(alpha_, beta_)),
        C1(coefficient_C1(alpha_, beta_)),
        C(coefficient_C(alpha_, beta_)),
        p(large_g_exponent(alpha_, beta_)),
        C2(coefficient_C2_at_zero(alpha_, beta_)) {}

  explicit closed_form_coefficients(const contact_law& law)
      : closed_form_coefficients((law.validate(), law.alpha.value<Real>()), law.beta.value<Real>()) {}
};

// Contact-law overloads.
template <class Real>
Real integral_I_at_zero(const contact_law& law) { return closed_form_coefficients<Real>(law).I0; }
template <class Real>
Real integral_Q_at_zero(const contact_law& law) { return closed_form_coefficients<Real>(law).Q0; }
template <class Real>
Real coefficient_C0(const contact_law& law) { return closed_form_coefficients<Real>(law).C0; }
template <class Real>
Real coefficient_C1(const contact_law& law) { return closed_form_coefficients<Real>(law).C1; }
template <class Real>
Real coefficient_C(const contact_law& law) { return closed_form_coefficients<Real>(law).C; }
template <class Real>
Real coefficient_C2_at_zero(const contact_law& law) { return closed_form_coefficients<Real>(law).C2; }
template <class Real>
Real critical_g(const contact_law& law, const Real& gamma) {
  law.validate();
  return critical_g(law.alpha.value<Real>(), law.beta.value<Real>(), gamma);
}
template <class Real>
Real critical_gamma(const contact_law& law, const Real& g) {
  law.validate();
  return critical_gamma(law.alpha.value<Real>(), law.beta.value<Real>(), g);
}

}  // namespace viscor
