// The public entry point of the proofs: viscor::enclose(law, gamma, g, digits)
// proves one impact (proven_linear.hpp for the linear law, proven_impact.hpp
// for every other law with rational exponents) and returns each quantity as exact
// decimal bounds, lower <= exact value <= upper, with its proven correctly rounded
// digits (docs/proofs.md).
//
// Bounds: the ball's lower (upper) end rounded down (up) to a decimal, so each
// printed bound is itself a rigorous bound. Proven digits: the largest d for which
// both ends, rounded to nearest at d significant digits, give the same decimal;
// rounding to nearest is monotone, so that decimal is the exact value correctly
// rounded to d digits.
//
// The machinery is in namespace viscor::proofs (headers in include/viscor/enclose/,
// CMake target viscor::enclose); only this function is in viscor itself.
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/enclose/proven_bounds.hpp>
#include <viscor/enclose/proven_impact.hpp>
#include <viscor/enclose/proven_linear.hpp>

#include <mpfr.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace viscor::proofs {

/// What enclose() proved about one impact: the decimals and the Arb balls they come from.
struct cor_enclosure : proven_decimals {
  proven_impact balls;  ///< the underlying enclosures, as Arb balls
};

namespace detail {

/// One end of x (lower: upper = false) as an exact MPFR number (init'ed here; the caller clears).
inline void ball_end(mpfr_t out, const ball& x, bool upper) {
  arf_t end;
  arf_init(end);
  if (upper)
    arb_get_ubound_arf(end, x.get(), ARF_PREC_EXACT);
  else
    arb_get_lbound_arf(end, x.get(), ARF_PREC_EXACT);
  mpfr_init2(out, std::max<mpfr_prec_t>(2, static_cast<mpfr_prec_t>(arf_bits(end))));
  arf_get_mpfr(out, end, MPFR_RNDN);  // exact: the precision holds every bit
  arf_clear(end);
}

/// x as a decimal of `digits` significant digits, rounded in mode `rnd`: "d.ddde<exp>".
inline std::string decimal(const mpfr_t x, int digits, mpfr_rnd_t rnd) {
  if (mpfr_zero_p(x)) return "0";
  mpfr_exp_t exponent = 0;
  char* raw = mpfr_get_str(nullptr, &exponent, 10, static_cast<std::size_t>(digits), x, rnd);
  std::string s(raw);
  mpfr_free_str(raw);
  const bool negative = s.front() == '-';
  if (negative) s.erase(0, 1);
  while (s.size() > 1 && s.back() == '0') s.pop_back();  // trailing zeros say nothing
  // raw means 0.s x 10^exponent; print plainly near 1, else d.ddd e(exponent - 1).
  std::string out;
  if (exponent > 0 && exponent <= 6) {
    const auto point = static_cast<std::size_t>(exponent);
    out = s.size() <= point ? s + std::string(point - s.size(), '0') : s.substr(0, point) + "." + s.substr(point);
  } else if (exponent <= 0 && exponent > -5) {
    out = "0." + std::string(static_cast<std::size_t>(-exponent), '0') + s;
  } else {
    out = s.substr(0, 1) + (s.size() > 1 ? "." + s.substr(1) : "") + "e" + std::to_string(exponent - 1);
  }
  return negative ? "-" + out : out;
}

/// The bounds of x with `shown` significant digits, and its proven correctly rounded
/// digits (searched down from a little above the relative width; at most `cap`).
inline proven_bounds bounds_of(const ball& x, int cap) {
  proven_bounds b;
  if (!x.finite()) return {"-inf", "inf", 0, ""};
  mpfr_t lo, hi;
  ball_end(lo, x, false);
  ball_end(hi, x, true);
  const int relative = x.rad_double() == 0 ? cap : std::min(cap, proven_impact::relative_digits(x));
  const bool one_sign = x.positive() || x.negative() || x.rad_double() == 0;
  for (int d = std::min(cap, relative + 3); one_sign && d >= 1 && b.proven_digits == 0; --d) {
    mpfr_exp_t e_lo = 0, e_hi = 0;
    char* s_lo = mpfr_get_str(nullptr, &e_lo, 10, static_cast<std::size_t>(d), lo, MPFR_RNDN);
    char* s_hi = mpfr_get_str(nullptr, &e_hi, 10, static_cast<std::size_t>(d), hi, MPFR_RNDN);
    if (e_lo == e_hi && std::string(s_lo) == s_hi) b.proven_digits = d;
    mpfr_free_str(s_lo);
    mpfr_free_str(s_hi);
  }
  if (b.proven_digits > 0) b.rounded = decimal(lo, b.proven_digits, MPFR_RNDN);
  // Enough digits that the two bounds differ where the ball does (and at least 10).
  const int shown = std::max(10, std::min(cap, relative) + 5);
  b.lower = decimal(lo, shown, MPFR_RNDD);
  b.upper = decimal(hi, shown, MPFR_RNDU);
  mpfr_clear(lo);
  mpfr_clear(hi);
  return b;
}

}  // namespace detail

}  // namespace viscor::proofs

namespace viscor {

/// Proves the impact of `law` at (gamma, g), given as exact decimals, working with
/// balls of working_bits(digits) bits, and returns lower and upper bounds of e,
/// 1 - e, T_f and u_max with their proven correctly rounded digits (at most
/// `digits`; an exact value, such as e = 0 of a stick, counts `digits`). Throws
/// invalid_parameter for a law whose exponents are not rational ("not provable",
/// naming the law), gamma < 0, digits outside [5, 100000], or a text that is not a
/// finite decimal.
inline proofs::cor_enclosure enclose(const contact_law& law, std::string_view gamma, std::string_view g, int digits,
                                     const proofs::proof_options& options = {}) {
  using namespace proofs;
  law.validate();
  const bool linear = law.alpha.is_rational() && law.beta.is_rational() && law.alpha.numerator() == 1 &&
                      law.alpha.denominator() == 1 && law.beta.numerator() == 1 && law.beta.denominator() == 1;
  cor_enclosure r;
  r.balls = linear ? prove_linear_impact(gamma, g, digits, options) : prove_impact(law, gamma, g, digits, options);
  r.outcome = r.balls.outcome;
  r.how = r.balls.how;
  scoped_ball_bits bits(working_bits(digits));
  if (r.outcome == impact_outcome::undecided) return r;
  r.e = proofs::detail::bounds_of(r.balls.e, digits);
  r.one_minus_e = proofs::detail::bounds_of(r.balls.one_minus_e, digits);
  if (r.outcome == impact_outcome::rebound) r.contact_time = proofs::detail::bounds_of(r.balls.contact_time, digits);
  if (r.balls.max_compression) r.max_compression = proofs::detail::bounds_of(*r.balls.max_compression, digits);
  return r;
}

}  // namespace viscor
