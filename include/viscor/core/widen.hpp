// Conversions between viscor's scalar types, one rule each: exact widening into a
// type that holds every value (the solvers' work types, evaluate's wider types, the
// tests' reference types) and rounding back to the caller's precision.
#pragma once

#include <viscor/core/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <limits>
#include <type_traits>

namespace viscor::detail {

/// Whether every value of Real converts exactly into W (at run time the working
/// precision is never below Real's, so run-time mpfr on either side qualifies).
template <class W, class Real>
constexpr bool can_widen() {
  if constexpr (std::is_same_v<W, Real>) return true;
#if VISCOR_HAS_MPFR
  else if constexpr (std::is_same_v<W, mpfr_real> || std::is_same_v<Real, mpfr_real>) return true;
#endif
  else return std::numeric_limits<W>::digits >= std::numeric_limits<Real>::digits;
}

/// x exactly in W (can_widen<W, Real>()); a run-time mpfr_real result carries at
/// least the thread's working precision, so that it computes at that precision.
template <class W, class Real>
W widen(const Real& x) {
  static_assert(can_widen<W, Real>(), "widen: W does not hold every value of Real");
#if VISCOR_HAS_MPFR
  if constexpr (std::is_same_v<W, mpfr_real>) {
    W y(x);  // exact: at least the source's precision
    const unsigned wanted = W::thread_default_precision();
    if (y.precision() < wanted) y.precision(wanted);  // exact widening
    return y;
  } else
#endif
    return static_cast<W>(x);
}

/// x rounded to Real; a run-time mpfr_real result to `real_digits10` decimal digits
/// (the caller's precision, read before a solve raised the working precision).
template <class Real, class W>
Real narrow(const W& x, [[maybe_unused]] unsigned real_digits10) {
  using boost::math::isinf;
  if (isinf(x)) return x > 0 ? std::numeric_limits<Real>::infinity() : -std::numeric_limits<Real>::infinity();
#if VISCOR_HAS_MPFR
  if constexpr (std::is_same_v<Real, mpfr_real>) {
    Real y = x;
    y.precision(real_digits10);  // round to the caller's precision
    return y;
  } else
#endif
    return static_cast<Real>(x);
}

}  // namespace viscor::detail
