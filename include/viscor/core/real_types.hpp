// The scalar types viscor is built and tested for, and precision queries that
// work for each of them, including run-time-precision mpfr_float.
#pragma once

#include <viscor/config.hpp>

#include <boost/math/tools/precision.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#if VISCOR_HAS_FLOAT128
#include <boost/multiprecision/float128.hpp>
#endif
#if VISCOR_HAS_MPFR
#include <boost/multiprecision/mpfr.hpp>
#endif

#include <cmath>
#include <limits>
#include <type_traits>

namespace viscor {

#if VISCOR_HAS_FLOAT128
using quad = boost::multiprecision::float128;  ///< IEEE binary128, 113-bit significand
#endif
#if VISCOR_HAS_MPFR
using mpfr_50 = boost::multiprecision::mpfr_float_50;
using mpfr_100 = boost::multiprecision::mpfr_float_100;
/// Precision chosen at run time (mpfr_float::default_precision or per value).
using mpfr_real = boost::multiprecision::mpfr_float;
#endif

/// Binary digits of Real. NOTE: for run-time mpfr_float this reads the current
/// default precision, so never cache it across precision changes.
template <class Real>
int binary_digits() {
  return boost::math::tools::digits<Real>();
}

/// The one rule for decimal precision (std::numeric_limits<T>::digits10): a type of
/// `binary` significand bits carries floor((binary - 1) log10 2) decimal digits in
/// full, i.e. every decimal number with that many significant digits survives the
/// round trip through it. double 15, x87 long double 18, float128 33; mpfr at D
/// decimal digits (Boost gives it at least D log2(10) + 1 bits) D.
constexpr int decimal_digits_of_binary(long long binary) { return static_cast<int>((binary - 1) * 30103 / 100000); }

/// Decimal digits that Real carries in full (decimal_digits_of_binary).
template <class Real>
int decimal_digits() {
  return decimal_digits_of_binary(binary_digits<Real>());
}

/// decimal_digits for a type of fixed precision, at compile time (for static_assert).
template <class Real>
constexpr int fixed_decimal_digits() {
  static_assert(std::numeric_limits<Real>::is_specialized && std::numeric_limits<Real>::radix == 2,
                "fixed_decimal_digits needs a binary type of fixed precision");
  return decimal_digits_of_binary(std::numeric_limits<Real>::digits);
}

/// Machine epsilon of Real, computed in Real (never through double).
template <class Real>
Real epsilon() {
  using std::ldexp;
  return ldexp(Real(1), 1 - binary_digits<Real>());
}

/// True for types whose precision is fixed at compile time.
template <class Real>
constexpr bool has_fixed_precision() {
#if VISCOR_HAS_MPFR
  return !std::is_same_v<Real, mpfr_real>;
#else
  return true;
#endif
}

namespace detail {
/// True for the MPFR types (fixed or run-time precision).
template <class Real>
struct is_mpfr : std::false_type {};
#if VISCOR_HAS_MPFR
template <unsigned Digits, boost::multiprecision::mpfr_allocation_type Allocation,
          boost::multiprecision::expression_template_option ET>
struct is_mpfr<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<Digits, Allocation>, ET>>
    : std::true_type {};
#endif
}  // namespace detail

}  // namespace viscor

// X-macro over the scalar types compiled into libviscor (src/instantiation.cpp.in).
#if VISCOR_HAS_FLOAT128
#define VISCOR_FOR_EACH_QUAD(X) X(::viscor::quad)
#else
#define VISCOR_FOR_EACH_QUAD(X)
#endif
#if VISCOR_HAS_MPFR
#define VISCOR_FOR_EACH_MPFR(X) X(::viscor::mpfr_50) X(::viscor::mpfr_100) X(::viscor::mpfr_real)
#else
#define VISCOR_FOR_EACH_MPFR(X)
#endif
#define VISCOR_FOR_EACH_REAL(X) X(double) X(long double) VISCOR_FOR_EACH_QUAD(X) VISCOR_FOR_EACH_MPFR(X)

// The same with a leading argument, M(P, Real) per type: each header that defines a
// template compiled into libviscor declares it `extern` for these types at its end
// (e.g. VISCOR_SOLVE_IMPACT_TEMPLATES in impact/solve_impact.hpp), so that a unit
// including only that header instantiates nothing of it. VISCOR_COMPILING_INSTANTIATIONS turns the declarations off (the
// instantiation files, and the fuzzers, which link nothing of libviscor).
#if VISCOR_HAS_FLOAT128
#define VISCOR_FOR_EACH_QUAD_WITH(M, P) M(P, ::viscor::quad)
#else
#define VISCOR_FOR_EACH_QUAD_WITH(M, P)
#endif
#if VISCOR_HAS_MPFR
#define VISCOR_FOR_EACH_MPFR_WITH(M, P) M(P, ::viscor::mpfr_50) M(P, ::viscor::mpfr_100) M(P, ::viscor::mpfr_real)
#else
#define VISCOR_FOR_EACH_MPFR_WITH(M, P)
#endif
#define VISCOR_FOR_EACH_REAL_WITH(M, P) \
  M(P, double) M(P, long double) VISCOR_FOR_EACH_QUAD_WITH(M, P) VISCOR_FOR_EACH_MPFR_WITH(M, P)
// With double-double too, for what its instantiation file compiles (all but the two
// solvers' own entry points: its solve_impact is its own, impact/double_double_impact.hpp).
#if VISCOR_HAS_QD
namespace viscor {
namespace double_double_math {
class double_double;  // core/double_double.hpp
}
using double_double_math::double_double;
}  // namespace viscor
#define VISCOR_FOR_EACH_COMPILED_WITH(M, P) VISCOR_FOR_EACH_REAL_WITH(M, P) M(P, ::viscor::double_double)
#else
#define VISCOR_FOR_EACH_COMPILED_WITH(M, P) VISCOR_FOR_EACH_REAL_WITH(M, P)
#endif
