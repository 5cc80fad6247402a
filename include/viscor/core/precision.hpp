// Run-time choice of the scalar type from a requested number of decimal digits: the
// cheapest type that carries them, else mpfr_real at that precision. Cheapest as
// measured (docs/performance.md, bench table): double, long double, double-double
// (about 5 times faster than float128 for a CoR), float128 (about 1.3 times faster
// than MPFR at 33 digits on the Hertz-type laws), MPFR.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#if VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>
#endif

#include <string>
#include <type_traits>

namespace viscor {

/// Largest working precision accepted, in decimal digits.
inline constexpr int max_working_digits = 100000;

/// The scalar type used for a request of `digits` decimal digits.
enum class scalar_kind { double_, long_double, double_double, quad, mpfr };

/// The scalar type's name as printed by the CLI.
inline std::string to_string(scalar_kind k) {
  switch (k) {
    case scalar_kind::double_: return "double";
    case scalar_kind::long_double: return "long double";
    case scalar_kind::double_double: return "double-double";
    case scalar_kind::quad: return "float128";
    case scalar_kind::mpfr: return "mpfr";
  }
  return "?";
}

/// The scalar_kind of the type Real.
template <class Real>
constexpr scalar_kind scalar_kind_of() {
  if constexpr (std::is_same_v<Real, double>) return scalar_kind::double_;
  else if constexpr (std::is_same_v<Real, long double>) return scalar_kind::long_double;
#if VISCOR_HAS_QD
  else if constexpr (std::is_same_v<Real, double_double>) return scalar_kind::double_double;
#endif
#if VISCOR_HAS_FLOAT128
  else if constexpr (std::is_same_v<Real, quad>) return scalar_kind::quad;
#endif
  else return scalar_kind::mpfr;
}

/// Throws precision_unavailable unless the build can compute with `digits` digits.
inline scalar_kind scalar_for_digits(int digits) {
  if (digits < 1)
    throw precision_unavailable("requested precision digits = " + std::to_string(digits) + " must be >= 1");
  if (digits > max_working_digits)
    throw precision_unavailable("requested precision digits = " + std::to_string(digits) +
                                " exceeds the maximum of " + std::to_string(max_working_digits));
  if (digits <= decimal_digits<double>()) return scalar_kind::double_;
  if (digits <= decimal_digits<long double>()) return scalar_kind::long_double;
#if VISCOR_HAS_QD
  if (digits <= decimal_digits<double_double>()) return scalar_kind::double_double;
#endif
#if VISCOR_HAS_FLOAT128
  if (digits <= decimal_digits<quad>()) return scalar_kind::quad;
#endif
#if VISCOR_HAS_MPFR
  return scalar_kind::mpfr;
#else
  throw precision_unavailable("requested precision digits = " + std::to_string(digits) +
                              " needs MPFR, which this build of viscor does not have");
#endif
}

/// Calls f.template operator()<Real>() with the scalar type for `digits`; for
/// mpfr_real the thread's default precision is `digits` for the call's duration.
/// Double and double-double keep double's exponent range: when their call throws
/// exponent_range_exceeded (an input, a result or a Taylor coefficient below the
/// normal range where it matters), f is called again in long double (for double) or
/// float128 (or MPFR), whose wider range carries the digits there, so f must be safe
/// to call twice.
/// Usage: with_working_precision(50, [&]<class Real>() { ... });
template <class F>
decltype(auto) with_working_precision(int digits, F&& f) {
  switch (scalar_for_digits(digits)) {
    case scalar_kind::double_:
      try {
        return f.template operator()<double>();
      } catch (const exponent_range_exceeded&) {
        return f.template operator()<long double>();
      }
    case scalar_kind::long_double: return f.template operator()<long double>();
#if VISCOR_HAS_QD
    case scalar_kind::double_double:
      try {
        return f.template operator()<double_double>();
      } catch (const exponent_range_exceeded&) {
#if VISCOR_HAS_FLOAT128
        return f.template operator()<quad>();
#endif
      }
      break;  // to MPFR
#endif
#if VISCOR_HAS_FLOAT128
    case scalar_kind::quad: return f.template operator()<quad>();
#endif
    default: break;
  }
#if VISCOR_HAS_MPFR
  scoped_precision precision(digits);
  return f.template operator()<mpfr_real>();
#else
  throw precision_unavailable("no scalar type for digits = " + std::to_string(digits));
#endif
}

}  // namespace viscor
