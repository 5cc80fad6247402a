// Approximated coefficients of section 4.4 and Appendix C: I and Q through the
// map theta(g) and the Chebyshev-Beta approximation of M_{alpha,beta}(theta).
//
//   theta(g): u_M^(alpha+1)/(alpha+1) = 1/(2 theta), i.e. eq. (43)
//             g(theta) = ((alpha+1)/(2 theta))^(-1/(alpha+1)) (1/(2 theta) - 1/2),
//             theta = 1 at g = 0, theta -> 0 as g -> infinity (44);
//   I(g(theta)) = K(theta) J_{alpha,beta}(theta),  K = (2/sqrt(theta)) ((alpha+1)/(2 theta))^(beta/(alpha+1))   (45)
//   Q(g(theta)) = L(theta) M_{alpha,beta}(theta),  L = sqrt(theta) ((alpha+1)/(2 theta))^(beta/(alpha+1))       (46)
//   J_{alpha,beta} = (alpha+1)/(2 beta) M_{alpha,alpha+beta+1} + (theta-1)/(2 beta) M_{alpha,beta+1}             (48)
//   M_{alpha,beta}(theta) ~ sum_{j even < n} c_j a_{j,0}                                                        (49)
//   c_0 = 2/(n+1) sum_{k=(n+1)/2}^{n} h(x_k),  c_j = 4/(n+1) sum h(x_k) cos(j pi (2k+1)/(2n+2))  (j even)     (50)
//   h(x) = ((x^(1-theta) - x^(alpha+1)) / (theta + (1-theta) x - x^(alpha+1)))^(1/2)                           (51)
//   x_k = cos(pi (2k+1)/(2n+2)) + 1                                                                             (52)
//   a_{0,k} = B((beta + k - 1/2 + theta/2)/(alpha+theta), 1/2)/(alpha+theta),  a_{1,k} = a_{0,k+1} - a_{0,k},
//   a_{j+2,k} = 2 a_{j+1,k+1} - 2 a_{j+1,k} - a_{j,k}   (53) as corrected in docs/report-notes.md (the report prints "- a_k").
// At theta = 0 and theta = 1, h = 1 and M reduces to the Beta closed forms (96).
//
// NOTE on the order n (default 21, the report's choice), measured by
// tools/chebyshev_order.cpp (docs/chebyshev_order.md): maximal relative error of M
// (and J) for alpha = 3/2 over theta = 0, 0.01, ..., 1 and beta = 1, 1.25, ..., 4,
// against the quadrature of integrals.hpp, with the scheme evaluated in
//
//     n  |  M double  |  M mpfr 50 |  J double  |  J mpfr 50
//   -----+------------+------------+------------+-----------
//     5  |  3.1e-2    |  3.1e-2    |  2.2e-2    |  2.2e-2
//    11  |  1.3e-2    |  1.3e-2    |  3.4e-3    |  3.4e-3
//    21  |  3.4e-3    |  3.4e-3    |  8.2e-4    |  8.2e-4
//    25  |  2.4e-3    |  2.4e-3    |  6.0e-4    |  5.9e-4
//    29  |  2.0e-3    |  1.8e-3    |  3.3e-3    |  4.6e-4
//    31  |  1.1e-2    |  1.6e-3    |  3.2e-2    |  2.5e-4
//    35  |  1.4e+0    |  1.3e-3    |  3.4e+0    |  2.3e-4
//    41  |  2.1e+3    |  8.8e-4    |  6.8e+3    |  2.5e-4
//    81  |  1.3e+25   |  2.3e-4    |  2.6e+25   |  8.5e-5
//
// In exact arithmetic the error falls steadily (about n^-2: the interpolated h has
// a kink at x = 1 and an x^((1-theta)/2) end point). What limits n is rounding:
// the recurrence (53) turns Beta (monomial) moments into Chebyshev moments and
// amplifies rounding by |T_n(-2)| ~ 3.7^n. In double the best n is 27-29, with
// a cliff right after; n = 21 is within a factor 1.7 of the best and far from the
// cliff, hence the default. Wider types may use larger n.

#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/root_finding.hpp>
#include <viscor/approx/integrals.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/approx/u_max.hpp>

#include <boost/math/constants/constants.hpp>
#include <viscor/approx/detail/beta_function.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace viscor {

/// g(theta) of eq. (43), theta in (0, 1].
template <class Real>
Real g_of_theta(const Real& alpha, const Real& theta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_theta(theta);
  if (theta == 0) throw invalid_parameter("g(theta) of eq. (43) is infinite at theta = 0");
  using std::pow;
  const Real a1 = alpha + 1;
  return pow(a1 / (2 * theta), -1 / a1) * (1 - theta) / (2 * theta);
}

/// theta(g): the root of eq. (43) for g >= 0, by a bracketing solver (TOMS 748) to
/// working precision. The bracket comes from that of u_M (u_max.hpp) through
/// theta = (alpha+1)/(2 u_M^(alpha+1)).
template <class Real>
Real theta_of_g(const Real& alpha, const Real& g) {
  detail::require_exponent(alpha, "alpha");
  require_non_negative(g, "g");
  if (g == 0) return Real(1);
  using std::pow;
  const Real a1 = alpha + 1;
  const auto [u_lo, u_hi] = detail::u_max_bracket(alpha, g);
  Real theta_lo = a1 / (2 * pow(u_hi, a1)), theta_hi = a1 / (2 * pow(u_lo, a1));
  if (theta_hi > 1) theta_hi = 1;
  // g - g(theta), increasing in theta; (1 - theta)/(2 theta) keeps its digits as theta -> 1.
  auto f = [&](const Real& theta) -> Real { return g - pow(a1 / (2 * theta), -1 / a1) * (1 - theta) / (2 * theta); };
  detail::widen_bracket(f, theta_lo, theta_hi, "theta(g): root of eq. (43)");
  static const std::string what = "theta(g): root of eq. (43)";
  return detail::bracketed_root(f, theta_lo, theta_hi, what);
}

/// K(theta) of eq. (45): I = K J; theta in (0, 1].
template <class Real>
Real k_factor(const Real& alpha, const Real& beta, const Real& theta) {
  using std::pow;
  using std::sqrt;
  return 2 / sqrt(theta) * pow((alpha + 1) / (2 * theta), beta / (alpha + 1));
}

/// L(theta) of eq. (46): Q = L M; theta in (0, 1].
template <class Real>
Real l_factor(const Real& alpha, const Real& beta, const Real& theta) {
  using std::pow;
  using std::sqrt;
  return sqrt(theta) * pow((alpha + 1) / (2 * theta), beta / (alpha + 1));
}

/// M_{alpha,beta} at theta = 0 and 1 in closed form, eq. (96).
template <class Real>
Real m_closed_form(const Real& alpha, const Real& beta, const Real& theta) {
  detail::require_exponent(alpha, "alpha");
  detail::require_exponent(beta, "beta");
  const Real half = Real(1) / 2;
  if (theta == 0) return detail::beta_half<Real>((beta - half) / alpha) / alpha;
  if (theta == 1) return detail::beta_half<Real>(beta / (alpha + 1)) / (alpha + 1);
  throw invalid_parameter("M_{alpha,beta}(theta) has a closed form (96) only at theta = 0 or 1, got theta = " +
                          to_decimal_string(theta));
}

/// The Chebyshev-Beta scheme (49)-(53) of odd order n: nodes and cosines are
/// computed once here, so build one object per order (and per precision for
/// mpfr_real) and reuse it.
template <class Real>
class chebyshev_beta {
 public:
  explicit chebyshev_beta(int n = 21) : m_n(n) {
    if (n <= 0 || n % 2 == 0)
      throw invalid_parameter("Chebyshev-Beta order n must be a positive odd integer, got n = " + std::to_string(n));
    using std::cos;
    using std::sin;
    const Real pi = boost::math::constants::pi<Real>();
    const int half = (n + 1) / 2;
    m_x.resize(half);
    m_y.resize(half);
    for (int i = 0; i < half; ++i) {
      const int k = half + i;
      const Real phi = pi * (2 * k + 1) / (2 * n + 2);  // in (pi/2, pi)
      const Real c = cos(phi / 2);
      m_x[i] = 2 * c * c;  // x_k = 1 + cos(phi) without cancellation, eq. (52)
      m_y[i] = -cos(phi);  // 1 - x_k
    }
    // cos(j pi (2k+1)/(2n+2)) for even j <= n-1 (row j/2) and the nodes of the lower half.
    m_cos.resize(static_cast<std::size_t>(half) * half);
    for (int jj = 0; jj < half; ++jj)
      for (int i = 0; i < half; ++i) {
        const int k = half + i;
        m_cos[static_cast<std::size_t>(jj) * half + i] = cos(pi * (2 * jj) * (2 * k + 1) / (2 * n + 2));
      }
  }

  int order() const noexcept { return m_n; }

  /// c_j of eq. (50) for even j = 0, 2, ..., n-1 (entry j/2); theta in [0, 1].
  std::vector<Real> coefficients(const Real& alpha, const Real& theta) const {
    detail::require_exponent(alpha, "alpha");
    detail::require_theta(theta);
    const int half = (m_n + 1) / 2;
    std::vector<Real> h(half);
    for (int i = 0; i < half; ++i) h[i] = h_at(alpha, theta, m_x[i], m_y[i]);
    std::vector<Real> c(half);
    for (int jj = 0; jj < half; ++jj) {
      Real sum = 0;
      for (int i = 0; i < half; ++i) sum += h[i] * m_cos[static_cast<std::size_t>(jj) * half + i];
      c[jj] = (jj == 0 ? Real(2) : Real(4)) * sum / (m_n + 1);
    }
    return c;
  }

  /// M_{alpha,beta}(theta) by eq. (49); exact (96) at theta = 0 and 1.
  Real m(const Real& alpha, const Real& beta, const Real& theta) const {
    detail::require_exponent(alpha, "alpha");
    detail::require_exponent(beta, "beta");
    detail::require_theta(theta);
    if (theta == 0 || theta == 1) return m_closed_form(alpha, beta, theta);
    return m_from(coefficients(alpha, theta), beta_moments(alpha, beta, theta, m_n), 0);
  }

  /// J_{alpha,beta}(theta) by relation (48) from two Chebyshev-Beta M's.
  Real j(const Real& alpha, const Real& beta, const Real& theta) const {
    return approximate(alpha, beta, theta).j;
  }

  /// a_{j,0} = int_0^1 T_j(x-1) (1 - x^(alpha+theta))^(-1/2) x^(beta+theta/2-3/2) dx, j = 0..n-1,
  /// by the Beta moments and the recurrence (53); theta in [0, 1].
  std::vector<Real> chebyshev_moments(const Real& alpha, const Real& beta, const Real& theta) const {
    detail::require_exponent(alpha, "alpha");
    detail::require_exponent(beta, "beta");
    detail::require_theta(theta);
    return first_column(beta_moments(alpha, beta, theta, m_n), 0);
  }

  /// M_{alpha,beta} and J_{alpha,beta} at one theta, sharing c_j and the Beta moments.
  struct m_and_j {
    Real m, j;
  };
  m_and_j approximate(const Real& alpha, const Real& beta, const Real& theta) const {
    detail::require_exponent(alpha, "alpha");
    detail::require_exponent(beta, "beta");
    detail::require_theta(theta);
    const Real a1 = alpha + 1;
    if (theta == 0 || theta == 1) {
      const Real m_b1 = m_closed_form(alpha, Real(beta + 1), theta);
      const Real m_ab1 = m_closed_form(alpha, Real(a1 + beta), theta);
      return {m_closed_form(alpha, beta, theta), (a1 * m_ab1 + (theta - 1) * m_b1) / (2 * beta)};
    }
    const std::vector<Real> c = coefficients(alpha, theta);
    // M_{alpha,beta+1} uses the moments of M_{alpha,beta} shifted by one: compute n + 1 of them.
    const std::vector<Real> moments = beta_moments(alpha, beta, theta, m_n + 1);
    const Real m_b = m_from(c, moments, 0);
    const Real m_b1 = m_from(c, moments, 1);
    const Real m_ab1 = m_from(c, beta_moments(alpha, Real(a1 + beta), theta, m_n), 0);
    return {m_b, (a1 * m_ab1 + (theta - 1) * m_b1) / (2 * beta)};
  }

 private:
  // h_{alpha,theta}(x) of eq. (51) at a node, given y = 1 - x exactly.
  static Real h_at(const Real& alpha, const Real& theta, const Real& x, const Real& y) {
    using std::pow;
    using std::sqrt;
    using std::expm1;
    using std::log;
    // x^(1-theta) - x^(alpha+1) = x^(1-theta) (1 - x^(alpha+theta))
    const Real numerator = -pow(x, 1 - theta) * expm1((alpha + theta) * log(x));
    const Real denominator = x <= Real(1) / 2 ? Real(theta + x * ((1 - theta) - pow(x, alpha)))
                                              : detail::theta_bracket_near_one(alpha, theta, y);
    return sqrt(numerator / denominator);
  }

  // a_{0,k} = B((beta + k - 1/2 + theta/2)/(alpha+theta), 1/2)/(alpha+theta), k = 0..count-1, eq. (53).
  static std::vector<Real> beta_moments(const Real& alpha, const Real& beta, const Real& theta, int count) {
    const Real at = alpha + theta, half = Real(1) / 2;
    const Real base = beta - half + theta / 2;
    std::vector<Real> a0(count);
    for (int k = 0; k < count; ++k) a0[k] = detail::beta_half<Real>((base + k) / at) / at;
    return a0;
  }

  // a_{j,0}, j = 0..n-1, from a_{0,k} = moments[shift + k], by the corrected recurrence (53):
  // rows j of the table a_{j,k} (Table 1), three at a time.
  std::vector<Real> first_column(const std::vector<Real>& moments, int shift) const {
    const int n = m_n;
    std::vector<Real> column(n);
    std::vector<Real> prev(moments.begin() + shift, moments.begin() + shift + n);  // row j, entries k < n - j
    column[0] = prev[0];
    if (n == 1) return column;
    std::vector<Real> cur(n - 1), next(n);
    for (int k = 0; k < n - 1; ++k) cur[k] = prev[k + 1] - prev[k];  // a_{1,k} = a_{0,k+1} - a_{0,k}
    column[1] = cur[0];
    for (int j = 0; j + 2 < n; ++j) {
      const int len = n - (j + 2);
      for (int k = 0; k < len; ++k) next[k] = 2 * cur[k + 1] - 2 * cur[k] - prev[k];
      column[j + 2] = next[0];
      prev.swap(cur);
      cur.swap(next);
    }
    return column;
  }

  // sum over even j < n of c_j a_{j,0}, eq. (49).
  Real m_from(const std::vector<Real>& c, const std::vector<Real>& moments, int shift) const {
    const std::vector<Real> column = first_column(moments, shift);
    Real sum = 0;
    for (int j = 0; j < m_n; j += 2) sum += c[j / 2] * column[j];
    return sum;
  }

  int m_n;
  std::vector<Real> m_x, m_y;  // upper-half nodes x_k in (0, 1) and 1 - x_k
  std::vector<Real> m_cos;     // cos(j pi (2k+1)/(2n+2)), row-major in (j/2, k)
};

/// M_{alpha,beta}(theta) by the Chebyshev-Beta scheme of order n (49).
template <class Real>
Real chebyshev_beta_m(const Real& alpha, const Real& beta, const Real& theta, int n = 21) {
  return chebyshev_beta<Real>(n).m(alpha, beta, theta);
}

/// J_{alpha,beta}(theta) by (48) and the Chebyshev-Beta M of order n.
template <class Real>
Real chebyshev_beta_j(const Real& alpha, const Real& beta, const Real& theta, int n = 21) {
  return chebyshev_beta<Real>(n).j(alpha, beta, theta);
}

/// I(g) ~ K(theta) J(theta) and Q(g) ~ L(theta) M(theta) with theta = theta(g) (45), (46).
template <class Real>
struct approximated_integrals {
  Real theta, I, Q;
};

template <class Real>
approximated_integrals<Real> chebyshev_beta_integrals(const chebyshev_beta<Real>& scheme, const Real& alpha,
                                                      const Real& beta, const Real& g) {
  const Real theta = theta_of_g(alpha, g);  // validates alpha, g >= 0
  const auto mj = scheme.approximate(alpha, beta, theta);
  return {theta, k_factor(alpha, beta, theta) * mj.j, l_factor(alpha, beta, theta) * mj.m};
}

}  // namespace viscor
