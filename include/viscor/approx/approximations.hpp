// The approximate CoR formulas of the report, each as a function of
// (contact law, gamma, g), with the typos of docs/report-notes.md corrected:
//   small g, O(gamma)       e = 1 - gamma C0 - gamma g C1                          eq. (22)
//   large g, O(gamma)       e = sqrt(max(1 - 2 gamma C g^p, 0))                    eq. (23)
//   Schwager-Poschel        e = 1 - gamma C0 - gamma g C1 - gamma^2 C2_SP          eqs. (25), (30); Kuwabara-Kono only
//   Proposition 2, O(gamma^2), with I = I(g), Q = Q(g):
//     (89)  e_+ = sqrt(max(e^2, 0)),  e^2 = 1 - 2 beta I gamma + 2 beta^2 I Q gamma^2      (= 37)
//     (90)  e_s = max(1 - beta I gamma + beta^2 I (Q - I/2) gamma^2, 0)                   (= 38)
//     (36)  e   = min(e_+, e_s)
// Prop. 2's I and Q come from one of three sources (coefficient_source):
//   exact_at_zero   the Beta closed forms (39), (40); only at g = 0
//   numeric         tanh-sinh quadrature of (41), (42) at the working precision (integrals.hpp)
//   chebyshev_beta  I = K J, Q = L M with the Chebyshev-Beta M of order n (chebyshev_beta.hpp)
// The linear forms (22) and (25) are returned as they are, possibly negative:
// they cannot represent sticking (the report's remark after Fig. 7).
//
// NOTE: every per-law constant (the Beta functions of C0, C1, C, C2, I(0), Q(0)
// and the Chebyshev nodes) is computed once by cor_approximations; the free
// functions build one per call, which is convenient but slow. Build the object
// at the precision it will be used with (mpfr_real reads its precision then).
#pragma once

#include <viscor/approx/chebyshev_beta.hpp>
#include <viscor/approx/closed_form.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/approx/integrals.hpp>
#include <viscor/core/parameters.hpp>

#include <array>
#include <cmath>
#include <string>
#include <string_view>

namespace viscor {

/// Where Prop. 2's I(g) and Q(g) come from.
enum class coefficient_source {
  exact_at_zero,   ///< Beta closed forms (39), (40): g = 0 only
  numeric,         ///< tanh-sinh quadrature of (41), (42)
  chebyshev_beta,  ///< K J and L M with the Chebyshev-Beta scheme (48)-(53)
};

inline constexpr std::array<coefficient_source, 3> coefficient_sources{
    coefficient_source::exact_at_zero, coefficient_source::numeric, coefficient_source::chebyshev_beta};

inline std::string_view to_string(coefficient_source s) {
  switch (s) {
    case coefficient_source::exact_at_zero: return "exact_at_zero";
    case coefficient_source::numeric: return "numeric";
    case coefficient_source::chebyshev_beta: return "chebyshev_beta";
  }
  return "unknown";
}

/// Parses "exact_at_zero", "numeric" or "chebyshev_beta".
inline coefficient_source parse_coefficient_source(std::string_view name) {
  for (auto s : coefficient_sources)
    if (to_string(s) == name) return s;
  throw invalid_parameter("unknown coefficient source '" + std::string(name) +
                          "' (known: exact_at_zero, numeric, chebyshev_beta)");
}

/// Prop. 2 at one (gamma, g): its coefficients and both branches.
template <class Real>
struct prop2_result {
  Real I, Q;            ///< coefficients used
  Real e_squared;       ///< e^2 of (37)/(89), may be negative
  Real e_plus;          ///< (89): sqrt(max(e^2, 0))
  Real e_linearized;    ///< (90) = (38): e_s
  Real e;               ///< (36): min(e_+, e_s)
  coefficient_source source;
};

namespace detail {
template <class Real>
void require_approximation_input(const Real& gamma, const Real& g) {
  require_non_negative(gamma, "gamma");
  require_finite(g, "g");
}
}  // namespace detail

/// All approximations of one contact law, with its constants computed once.
template <class Real>
class cor_approximations {
 public:
  /// alpha, beta >= 1; chebyshev_order odd and positive (the report uses 21).
  cor_approximations(const Real& alpha, const Real& beta, int chebyshev_order = 21)
      : m_closed(alpha, beta), m_scheme(chebyshev_order) {
    m_kuwabara_kono = alpha == Real(3) / 2 && beta == Real(3) / 2;
    if (m_kuwabara_kono) m_c2_sp = schwager_poschel_C2<Real>();
  }
  explicit cor_approximations(const contact_law& law, int chebyshev_order = 21)
      : cor_approximations((law.validate(), law.alpha.value<Real>()), law.beta.value<Real>(), chebyshev_order) {
    m_law_name = law.describe();
  }

  const closed_form_coefficients<Real>& closed_forms() const noexcept { return m_closed; }
  const chebyshev_beta<Real>& scheme() const noexcept { return m_scheme; }
  bool is_kuwabara_kono() const noexcept { return m_kuwabara_kono; }

  /// Eq. (22): 1 - gamma C0 - gamma g C1 (any finite g; linear, may be negative).
  Real small_g(const Real& gamma, const Real& g) const {
    detail::require_approximation_input(gamma, g);
    return 1 - gamma * (m_closed.C0 + g * m_closed.C1);
  }

  /// Eq. (23): sqrt(max(1 - 2 gamma C g^p, 0)); g >= 0.
  Real large_g(const Real& gamma, const Real& g) const {
    detail::require_approximation_input(gamma, g);
    require_non_negative(g, "g");
    using std::pow;
    using std::sqrt;
    const Real e2 = 1 - 2 * gamma * m_closed.C * pow(g, m_closed.p);
    return e2 > 0 ? Real(sqrt(e2)) : Real(0);
  }

  /// Eqs. (25), (30): 1 - gamma C0 - gamma g C1 - gamma^2 C2_SP, Kuwabara-Kono only.
  Real schwager_poschel(const Real& gamma, const Real& g) const {
    detail::require_approximation_input(gamma, g);
    if (!m_kuwabara_kono)
      throw invalid_parameter("the Schwager-Poschel coefficient (30) exists only for Kuwabara-Kono "
                              "(alpha = beta = 3/2), got " + law_text());
    return 1 - gamma * (m_closed.C0 + g * m_closed.C1) - gamma * gamma * m_c2_sp;
  }

  /// Prop. 2's I(g) and Q(g) from `source`; for chebyshev_beta also theta(g).
  std::array<Real, 2> coefficients(const Real& g, coefficient_source source) const {
    require_finite(g, "g");
    switch (source) {
      case coefficient_source::exact_at_zero:
        if (g != 0)
          throw invalid_parameter("coefficient source exact_at_zero is the closed form (39), (40) at g = 0, "
                                  "got g = " + to_decimal_string(g));
        return {m_closed.I0, m_closed.Q0};
      case coefficient_source::numeric: {
        const auto v = integrals_IQ(m_closed.alpha, m_closed.beta, g);
        return {v.I, v.Q};
      }
      case coefficient_source::chebyshev_beta: {
        require_non_negative(g, "g");
        const auto v = chebyshev_beta_integrals(m_scheme, m_closed.alpha, m_closed.beta, g);
        return {v.I, v.Q};
      }
    }
    throw invalid_parameter("unknown coefficient source");
  }

  /// Proposition 2, eqs. (36)-(38) = (89), (90), with coefficients from `source`.
  prop2_result<Real> prop2(const Real& gamma, const Real& g, coefficient_source source) const {
    detail::require_approximation_input(gamma, g);
    const auto iq = coefficients(g, source);
    return prop2_from(gamma, iq[0], iq[1], source);
  }

  /// Prop. 2 from given I and Q (for callers that tabulate them).
  prop2_result<Real> prop2_from(const Real& gamma, const Real& I, const Real& Q,
                                coefficient_source source = coefficient_source::numeric) const {
    using std::sqrt;
    const Real& beta = m_closed.beta;
    prop2_result<Real> r;
    r.I = I, r.Q = Q, r.source = source;
    const Real bi = beta * I * gamma;  // beta I gamma
    r.e_squared = 1 - 2 * bi + 2 * beta * Q * bi * gamma;
    r.e_plus = r.e_squared > 0 ? Real(sqrt(r.e_squared)) : Real(0);
    const Real es = 1 - bi + beta * (Q - I / 2) * bi * gamma;
    r.e_linearized = es > 0 ? es : Real(0);
    r.e = r.e_plus < r.e_linearized ? r.e_plus : r.e_linearized;
    return r;
  }

 private:
  std::string law_text() const {
    return m_law_name.empty()
               ? "alpha = " + to_decimal_string(m_closed.alpha) + ", beta = " + to_decimal_string(m_closed.beta)
               : m_law_name;
  }

  closed_form_coefficients<Real> m_closed;
  chebyshev_beta<Real> m_scheme;
  bool m_kuwabara_kono = false;
  Real m_c2_sp = 0;
  std::string m_law_name;
};

/// Eq. (22) for one law (builds the constants each call; use cor_approximations in loops).
template <class Real>
Real cor_small_g(const contact_law& law, const Real& gamma, const Real& g) {
  return cor_approximations<Real>(law).small_g(gamma, g);
}

/// Eq. (23).
template <class Real>
Real cor_large_g(const contact_law& law, const Real& gamma, const Real& g) {
  return cor_approximations<Real>(law).large_g(gamma, g);
}

/// Eqs. (25), (30): Kuwabara-Kono only.
template <class Real>
Real cor_schwager_poschel(const contact_law& law, const Real& gamma, const Real& g) {
  return cor_approximations<Real>(law).schwager_poschel(gamma, g);
}

/// Proposition 2 (36)-(38), (89), (90).
template <class Real>
prop2_result<Real> cor_prop2(const contact_law& law, const Real& gamma, const Real& g,
                             coefficient_source source = coefficient_source::numeric, int chebyshev_order = 21) {
  return cor_approximations<Real>(law, chebyshev_order).prop2(gamma, g, source);
}

}  // namespace viscor
