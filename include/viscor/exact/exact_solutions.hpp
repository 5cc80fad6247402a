// Which exact solution applies to (law, gamma, g), if any: the one dispatch rule
// that exact_cor, table rows (tables/table_row.hpp) and evaluate
// (scenes/evaluate.hpp) all use; and how many digits an evaluation of it has,
// measured per quantity by a second evaluation at more digits.
#pragma once

#include <viscor/core/real_types.hpp>
#include <viscor/core/detail/agreement_digits.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/exact/exact_hunt_crossley.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_tsuji.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

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
         __int128(b.numerator()) == __int128(a.numerator()) + a.denominator();  // 128 bits: no overflow
}
}  // namespace detail

/// The closed forms viscor knows.
enum class closed_form {
  none,
  linear,            ///< alpha = beta = 1, any gamma and g (exact_linear.hpp)
  energy_conserved,  ///< gamma = 0: e = 1
  hunt_crossley,     ///< beta = alpha + 1, g = 0 (exact_hunt_crossley.hpp)
  tsuji,             ///< alpha = 3/2, beta = 5/4, g = 0 (exact_tsuji.hpp)
};

/// Which closed form applies; only whether gamma and g are zero matters.
inline closed_form closed_form_for(const contact_law& law, bool gamma_is_zero, bool g_is_zero) {
  if (detail::is_rational(law.alpha, 1, 1) && detail::is_rational(law.beta, 1, 1)) return closed_form::linear;
  if (gamma_is_zero) return closed_form::energy_conserved;
  if (g_is_zero && detail::is_alpha_plus_one(law)) return closed_form::hunt_crossley;
  if (g_is_zero && detail::is_rational(law.alpha, 3, 2) && detail::is_rational(law.beta, 5, 4)) return closed_form::tsuji;
  return closed_form::none;
}

/// True if exact_cor has an answer at (law, gamma, g).
inline bool closed_form_exists(const contact_law& law, bool gamma_is_zero, bool g_is_zero) {
  return closed_form_for(law, gamma_is_zero, g_is_zero) != closed_form::none;
}

/// The exact CoR where a closed form exists, else std::nullopt (see closed_form_for).
template <class Real>
std::optional<exact_result<Real>> exact_cor(const contact_law& law, const Real& gamma, const Real& g) {
  impact_parameters<Real>{law, gamma, g}.validate();
  switch (closed_form_for(law, gamma == 0, g == 0)) {
    case closed_form::linear: return exact_linear(gamma, g);
    case closed_form::energy_conserved: {
      exact_result<Real> r;
      r.e = 1, r.one_minus_e = 0;
      r.formula = "gamma = 0: energy is conserved, e = 1";
      return r;
    }
    case closed_form::hunt_crossley: return exact_hunt_crossley(law.alpha.value<Real>(), gamma);
    case closed_form::tsuji: return exact_tsuji(gamma);
    case closed_form::none: break;
  }
  return std::nullopt;
}

/// Significant digits of an exact_cor result, per quantity: its agreement with the
/// same closed form evaluated from the same inputs at more digits (a formula
/// evaluated at working precision can lose digits to its conditioning: the linear
/// law loses about log10(g) in e and T_f at large g).
struct closed_form_digits {
  bool outcome_agrees = false;  ///< false: the check found the other outcome (0 digits)
  int e = 0, one_minus_e = 0, contact_time = 0, max_compression = 0;
  /// The fewest digits over the four quantities (0 when the outcome disagrees).
  int least() const { return outcome_agrees ? std::min({e, one_minus_e, contact_time, max_compression}) : 0; }
};

namespace detail {
// x converted exactly into the check type V (V at least as wide as Real).
template <class V, class Real>
V exactly_as(const Real& x) {
#if VISCOR_HAS_MPFR
  if constexpr (std::is_same_v<V, mpfr_real>) {
    V y(x);
    const unsigned wanted = V::thread_default_precision();
    if (y.precision() < wanted) y.precision(wanted);
    return y;
  } else
#endif
    return static_cast<V>(x);
}

template <class V, class Real>
int optional_agreement(const std::optional<Real>& a, const std::optional<V>& b, int cap) {
  if (!a && !b) return cap;
  if (!a || !b) return 0;
  return agreement_digits(exactly_as<V>(*a), *b, *b, cap);
}
}  // namespace detail

/// Decimal texts of gamma and g, when x was computed from them rounded to Real.
using decimal_inputs = std::optional<std::pair<std::string, std::string>>;

/// The digits of x = exact_cor<Real>(law, gamma, g), capped at `cap`, checked by
/// exact_cor at cap + 10 digits (in mpfr_real, or the cheapest type that carries
/// them) from gamma and g converted exactly, or, given `inputs`, from the decimal
/// numbers they were rounded from: then the rounding of the inputs counts too (near
/// critical damping e = exp(-pi xi/sqrt(1 - xi^2)) is very sensitive to gamma).
template <class Real>
closed_form_digits check_closed_form(const contact_law& law, const Real& gamma, const Real& g,
                                     const exact_result<Real>& x, int cap, const decimal_inputs& inputs = std::nullopt) {
  return with_working_precision(std::max(cap, decimal_digits<Real>()) + 10, [&]<class V>() {
    closed_form_digits d;
    if constexpr (has_fixed_precision<V>() && has_fixed_precision<Real>() &&
                  std::numeric_limits<V>::digits < std::numeric_limits<Real>::digits) {
      return d;  // unreachable: V carries more digits than Real
    } else {
      const V vg = inputs ? parse_real<V>(inputs->first, "gamma") : detail::exactly_as<V>(gamma);
      const V vgg = inputs ? parse_real<V>(inputs->second, "g") : detail::exactly_as<V>(g);
      const std::optional<exact_result<V>> y = exact_cor(law, vg, vgg);
      if (!y || y->outcome != x.outcome) return d;
      d.outcome_agrees = true;
      if (x.outcome == impact_outcome::stick) {
        d.e = d.one_minus_e = cap;  // e = 0 and 1 - e = 1 exactly once the outcome agrees
      } else {
        d.e = detail::agreement_digits(detail::exactly_as<V>(x.e), y->e, y->e, cap);
        d.one_minus_e = detail::agreement_digits(detail::exactly_as<V>(x.one_minus_e), y->one_minus_e, y->one_minus_e, cap);
      }
      d.contact_time = detail::optional_agreement(x.contact_time, y->contact_time, cap);
      d.max_compression = detail::optional_agreement(x.max_compression, y->max_compression, cap);
      return d;
    }
  });
}

}  // namespace viscor

// exact_cor is compiled once per scalar type into libviscor (src/instantiation.cpp.in):
// declared extern here, so that no unit including this header instantiates it again.
#define VISCOR_EXACT_TEMPLATES(PREFIX, Real) \
  PREFIX template std::optional<exact_result<Real>> exact_cor<Real>(const contact_law&, const Real&, const Real&);
#ifndef VISCOR_COMPILING_INSTANTIATIONS
namespace viscor {
VISCOR_FOR_EACH_COMPILED_WITH(VISCOR_EXACT_TEMPLATES, extern)
}
#endif
