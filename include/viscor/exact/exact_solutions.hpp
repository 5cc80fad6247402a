// Which exact solution applies to (law, gamma, g), if any.
#pragma once

#include <viscor/exact/exact_hunt_crossley.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_tsuji.hpp>
#include <viscor/core/parameters.hpp>

#include <optional>

namespace viscor {

namespace detail {
inline bool is_rational(const exponent& x, std::int64_t p, std::int64_t q) {
  return x.is_rational() && x.numerator() == p && x.denominator() == q;
}
inline bool is_alpha_plus_one(const contact_law& law) {
  // beta = alpha + 1 exactly: compare p2/q2 with (p1 + q1)/q1 in integers.
  const auto& a = law.alpha;
  const auto& b = law.beta;
  return a.is_rational() && b.is_rational() && b.denominator() == a.denominator() &&
         b.numerator() == a.numerator() + a.denominator();
}
}  // namespace detail

/// The exact CoR where a closed form exists, else std::nullopt:
/// gamma = 0 (e = 1); alpha = beta = 1 (any g); beta = alpha + 1 with g = 0;
/// alpha = 3/2, beta = 5/4 with g = 0.
template <class Real>
std::optional<exact_result<Real>> exact_cor(const contact_law& law, const Real& gamma, const Real& g) {
  impact_parameters<Real>{law, gamma, g}.validate();
  if (detail::is_rational(law.alpha, 1, 1) && detail::is_rational(law.beta, 1, 1)) return exact_linear(gamma, g);
  if (gamma == 0) {
    exact_result<Real> r;
    r.e = 1, r.one_minus_e = 0;
    r.formula = "gamma = 0: energy is conserved, e = 1";
    return r;
  }
  if (g == 0 && detail::is_alpha_plus_one(law)) return exact_hunt_crossley(law.alpha.value<Real>(), gamma);
  if (g == 0 && detail::is_rational(law.alpha, 3, 2) && detail::is_rational(law.beta, 5, 4)) return exact_tsuji(gamma);
  return std::nullopt;
}

}  // namespace viscor
