// A double-double scalar: QD's dd_real (Hida, Li and Bailey, "Algorithms for
// quad-double precision floating point arithmetic", ARITH 15, 2001; the Debian package
// libqd-dev) wrapped so that it meets what viscor asks of a Real (docs/precision.md):
// a value is an unevaluated sum hi + lo of two doubles with |lo| <= ulp(hi)/2.
//
// Error rules relied on (u = 2^-53; the bounds are those proved by Joldes, Muller and
// Popescu, "Tight and rigorous error bounds for basic building blocks of double-word
// arithmetic", ACM TOMS 44(2), 2017, for the algorithms QD implements; none is
// correctly rounded):
//   a + b, a - b   Briggs-Kahan addition (QD's ieee_add; QD's default "sloppy" add has
//                  no relative bound under cancellation and is never used by these
//                  operators): relative error <= 3u^2 / (1 - 4u)
//   a * b          QD's product (exact partial product by Dekker's split, or by FMA
//                  where the compiler targets it): <= 7u^2
//   a / b          QD's division: <= 15u^2 + 56u^3
//   with a double  operand: within the same bounds
// (+ - * / are QD's algorithms written out in detail::dd_kernels, so that they inline),
// so every + - * / is within 16u^2 = 2^-102 = 2 epsilon relative (epsilon = 2^-103,
// digits = 104 as QD's own numeric_limits says): 31 decimal digits
// (decimal_digits_of_binary(104)). QD's own functions (sqrt, exp, log, sin, npwr, compiled
// into libqd) use its sloppy add inside and come with no stated bound: for them nothing
// is proved. tests/double_double_test.cpp measures them against MPFR at chosen points
// (sqrt within 2, exp and log within 4 epsilon) and they are trusted no further. pow(x, y)
// is computed here as 2^j exp(f ln 2 + y ln m), so that its error does not grow with
// |ln x|; it still grows with |y| (exp's relative error is about its argument's absolute
// error): measured within 8 epsilon for the solvers' exponents (|y| <= 7/2), no bound for
// large |y|. log1p and expm1 are computed here from series (QD's log near 1 keeps only
// its absolute accuracy): measured within 2 epsilon, down to arguments of 1e-30.
// Certification's agreement rule catches what these rules miss.
//
// Limits: the exponent range is double's, and the lo part is an ordinary double, so a
// value keeps its 104 bits only for |x| >= 2^-969 (about 2.0e-292,
// std::numeric_limits<double_double>::min()); below it the lo part is subnormal and the
// value carries fewer digits. parse_real refuses such inputs, to_decimal_string prints
// only the digits such a value carries, carries_full_precision tells a caller whether a
// value is in the range where the rules above hold, and solve_impact<double_double>
// refuses a result with a value below 2^-939 (double_double_smallest_reported).
//
// Available where CMake found QD (config.hpp's VISCOR_HAS_QD; the library then links
// libqd); with_working_precision picks it for 19 to 31 digits (core/precision.hpp).
#pragma once

#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>

#if VISCOR_HAS_QD

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <qd/dd_real.h>

#include <cmath>
#include <compare>
#include <concepts>
#include <cstdlib>
#include <iomanip>
#include <ios>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>

namespace viscor {

namespace detail::dd_kernels {
// QD's algorithms for + - * / (include/qd/inline.h, dd_inline.h: Dekker, Knuth, Briggs
// and Kahan), written out here with always_inline: in a solver's large translation units
// GCC stops inlining QD's own copies, and a call per operation costs a third of a solve.
// The same operations in the same order, so the same results and error bounds; with FMA
// available at compile time the exact product uses it (also exact).
#define VISCOR_DD_INLINE [[gnu::always_inline]] inline

/// s + e = a + b exactly (Knuth).
VISCOR_DD_INLINE double two_sum(double a, double b, double& e) {
  const double s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
  return s;
}
/// s + e = a + b exactly for |a| >= |b| (Dekker).
VISCOR_DD_INLINE double quick_two_sum(double a, double b, double& e) {
  const double s = a + b;
  e = b - (s - a);
  return s;
}
/// p + e = a b exactly (Dekker's split; QD's scaling for |a| > 2^996).
VISCOR_DD_INLINE double two_prod(double a, double b, double& e) {
  const double p = a * b;
#if defined(__FMA__)
  e = __builtin_fma(a, b, -p);
#else
  constexpr double splitter = 134217729.0;  // 2^27 + 1
  constexpr double thresh = 6.69692879491417e+299;  // 2^996
  auto split = [](double x, double& hi, double& lo) {
    if (x > thresh || x < -thresh) {
      x *= 3.7252902984619140625e-09;  // 2^-28
      const double t = splitter * x;
      hi = t - (t - x);
      lo = x - hi;
      hi *= 268435456.0;  // 2^28
      lo *= 268435456.0;
    } else {
      const double t = splitter * x;
      hi = t - (t - x);
      lo = x - hi;
    }
  };
  double a_hi, a_lo, b_hi, b_lo;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  e = ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
#endif
  return p;
}
/// QD's ieee_add (Briggs-Kahan).
VISCOR_DD_INLINE dd_real add(const dd_real& a, const dd_real& b) {
  double s2, t2;
  double s1 = two_sum(a.x[0], b.x[0], s2);
  const double t1 = two_sum(a.x[1], b.x[1], t2);
  s2 += t1;
  s1 = quick_two_sum(s1, s2, s2);
  s2 += t2;
  s1 = quick_two_sum(s1, s2, s2);
  return dd_real(s1, s2);
}
/// QD's double-double + double.
VISCOR_DD_INLINE dd_real add(const dd_real& a, double b) {
  double s2;
  double s1 = two_sum(a.x[0], b, s2);
  s2 += a.x[1];
  s1 = quick_two_sum(s1, s2, s2);
  return dd_real(s1, s2);
}
/// QD's double-double product.
VISCOR_DD_INLINE dd_real mul(const dd_real& a, const dd_real& b) {
  double p2;
  double p1 = two_prod(a.x[0], b.x[0], p2);
  p2 += (a.x[0] * b.x[1] + a.x[1] * b.x[0]);
  p1 = quick_two_sum(p1, p2, p2);
  return dd_real(p1, p2);
}
/// QD's double-double * double.
VISCOR_DD_INLINE dd_real mul(const dd_real& a, double b) {
  double p2;
  double p1 = two_prod(a.x[0], b, p2);
  p2 += (a.x[1] * b);
  p1 = quick_two_sum(p1, p2, p2);
  return dd_real(p1, p2);
}
/// QD's (sloppy) double-double division.
VISCOR_DD_INLINE dd_real div(const dd_real& a, const dd_real& b) {
  const double q1 = a.x[0] / b.x[0];
  const dd_real r = mul(b, q1);
  double s2;
  const double s1 = two_sum(a.x[0], -r.x[0], s2);  // QD's two_diff
  s2 -= r.x[1];
  s2 += a.x[1];
  const double q2 = (s1 + s2) / b.x[0];
  double lo;
  const double hi = quick_two_sum(q1, q2, lo);
  return dd_real(hi, lo);
}
/// QD's double-double / double.
VISCOR_DD_INLINE dd_real div(const dd_real& a, double b) {
  const double q1 = a.x[0] / b;
  double p2, e;
  const double p1 = two_prod(q1, b, p2);
  const double s = two_sum(a.x[0], -p1, e);  // QD's two_diff
  e += a.x[1];
  e -= p2;
  const double q2 = (s + e) / b;
  double lo;
  const double hi = quick_two_sum(q1, q2, lo);
  return dd_real(hi, lo);
}
#undef VISCOR_DD_INLINE
}  // namespace detail::dd_kernels

/// The double-double type and the functions found for it by argument-dependent lookup,
/// apart so that unqualified calls elsewhere in viscor never see them.
namespace double_double_math {

/// Double-double real number (QD's dd_real with the error rules of this header's
/// comment): 104 significant bits, 31 decimal digits, double's exponent range.
class double_double {
 public:
  /// Zero.
  double_double() = default;
  /// The double x, exactly.
  double_double(double x) : m_v(x) {}  // NOLINT: implicit like every built-in promotion
  /// The long double x, exactly (an x87 long double has 64 bits).
  double_double(long double x) {
    const double hi = static_cast<double>(x);
    m_v = std::isfinite(hi) ? dd_real::add(hi, static_cast<double>(x - static_cast<long double>(hi))) : dd_real(hi);
  }
#if VISCOR_HAS_FLOAT128
  /// The binary128 x rounded to double-double (Boost's quadrature tables are binary128
  /// literals): hi the nearest double, lo the remainder's nearest double.
  double_double(__float128 x) {  // NOLINT: implicit, as the tables' initialiser lists need
    const double hi = static_cast<double>(x);
    m_v = std::isfinite(hi) && hi != 0 ? dd_real::add(hi, static_cast<double>(x - static_cast<__float128>(hi))) : dd_real(hi);
  }
#endif
  /// The integer n, exactly (64-bit integers split into two doubles).
  template <std::integral I>
  double_double(I n) {  // NOLINT: implicit like every built-in promotion
    if constexpr (sizeof(I) <= 4) {
      m_v = dd_real(static_cast<double>(n));
    } else {
      using U = std::make_unsigned_t<I>;
      const U bits = static_cast<U>(n);
      const U low_mask = static_cast<U>(0xffffffffu);
      // n = high + low with low in [0, 2^32) and high a multiple of 2^32: both exact doubles.
      const double low = static_cast<double>(bits & low_mask);
      const double high = std::is_signed_v<I> ? static_cast<double>(static_cast<I>(n - static_cast<I>(bits & low_mask)))
                                              : static_cast<double>(bits & ~low_mask);
      m_v = dd_real::add(high, low);
    }
  }
  /// QD's value v as it is.
  explicit double_double(const dd_real& v) : m_v(v) {}
  /// The decimal number `text` within 2^-105 relative (see parse_double_double).
  explicit double_double(const char* text);
  /// The decimal number `text` within 2^-105 relative (see parse_double_double).
  explicit double_double(const std::string& text) : double_double(text.c_str()) {}

  /// The two parts: value = hi() + lo(), |lo()| <= ulp(hi())/2.
  double hi() const { return m_v.x[0]; }
  /// The low part (see hi()).
  double lo() const { return m_v.x[1]; }
  /// QD's value.
  const dd_real& qd() const { return m_v; }

  /// Rounded to a built-in floating type (hi + lo in that type), or truncated toward
  /// zero to an integer type.
  template <class T>
    requires std::is_arithmetic_v<T>
  explicit operator T() const {
    if constexpr (std::is_floating_point_v<T>) {
      return static_cast<T>(m_v.x[0]) + static_cast<T>(m_v.x[1]);
    } else {
      const dd_real t = aint(m_v);  // both parts integers
      return static_cast<T>(static_cast<long long>(t.x[0]) + static_cast<long long>(t.x[1]));
    }
  }

  /// hi + lo in a Boost.Multiprecision floating type (a reference type wider than this
  /// one): exact where N's precision spans the bits from hi's leading one to lo's last,
  /// else one rounding in N.
  template <class B, boost::multiprecision::expression_template_option ET>
  explicit operator boost::multiprecision::number<B, ET>() const {
    boost::multiprecision::number<B, ET> x(m_v.x[0]);
    x += m_v.x[1];
    return x;
  }
  /// A Boost.Multiprecision number rounded to double-double: hi the nearest double, lo
  /// the remainder's nearest double (within 2^-106 relative from 2^-969 up).
  template <class B, boost::multiprecision::expression_template_option ET>
  explicit double_double(const boost::multiprecision::number<B, ET>& x) {
    const double hi = x.template convert_to<double>();
    if (!std::isfinite(hi) || hi == 0) {
      m_v = dd_real(hi);
    } else {
      const boost::multiprecision::number<B, ET> rest = x - hi;  // exact: x and hi share their leading bits
      m_v = dd_real::add(hi, rest.template convert_to<double>());
    }
  }

  /// static_cast<T>(*this), as Boost.Multiprecision numbers spell it.
  template <class T>
    requires std::is_arithmetic_v<T>
  T convert_to() const {
    return static_cast<T>(*this);
  }

  /// -x.
  double_double operator-() const { return double_double(-m_v); }
  /// x.
  double_double operator+() const { return *this; }

  /// a + b (Briggs-Kahan: relative error <= 3u^2).
  friend double_double operator+(const double_double& a, const double_double& b) {
    return double_double(detail::dd_kernels::add(a.m_v, b.m_v));
  }
  /// a - b (Briggs-Kahan: relative error <= 3u^2).
  friend double_double operator-(const double_double& a, const double_double& b) {
    return double_double(detail::dd_kernels::add(a.m_v, -b.m_v));
  }
  /// a * b (relative error <= 7u^2).
  friend double_double operator*(const double_double& a, const double_double& b) {
    return double_double(detail::dd_kernels::mul(a.m_v, b.m_v));
  }
  /// a / b (relative error <= 15u^2 + 56u^3).
  friend double_double operator/(const double_double& a, const double_double& b) {
    return double_double(detail::dd_kernels::div(a.m_v, b.m_v));
  }
  /// a + b with a double.
  friend double_double operator+(const double_double& a, double b) { return double_double(detail::dd_kernels::add(a.m_v, b)); }
  /// a + b with a double.
  friend double_double operator+(double a, const double_double& b) { return double_double(detail::dd_kernels::add(b.m_v, a)); }
  /// a - b with a double.
  friend double_double operator-(const double_double& a, double b) { return double_double(detail::dd_kernels::add(a.m_v, -b)); }
  /// a - b with a double.
  friend double_double operator-(double a, const double_double& b) { return double_double(detail::dd_kernels::add(-b.m_v, a)); }
  /// a * b with a double.
  friend double_double operator*(const double_double& a, double b) { return double_double(detail::dd_kernels::mul(a.m_v, b)); }
  /// a * b with a double.
  friend double_double operator*(double a, const double_double& b) { return double_double(detail::dd_kernels::mul(b.m_v, a)); }
  /// a / b with a double.
  friend double_double operator/(const double_double& a, double b) { return double_double(detail::dd_kernels::div(a.m_v, b)); }
  /// a / b with a double.
  friend double_double operator/(double a, const double_double& b) { return double_double(a) / b; }
  /// a + n, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator+(const double_double& a, I n) {
    return fits_double(n) ? a + static_cast<double>(n) : a + double_double(n);
  }
  /// n + a, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator+(I n, const double_double& a) { return a + n; }
  /// a - n, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator-(const double_double& a, I n) {
    return fits_double(n) ? a - static_cast<double>(n) : a - double_double(n);
  }
  /// n - a, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator-(I n, const double_double& a) { return double_double(n) - a; }
  /// a * n, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator*(const double_double& a, I n) {
    return fits_double(n) ? a * static_cast<double>(n) : a * double_double(n);
  }
  /// n * a, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator*(I n, const double_double& a) { return a * n; }
  /// a / n, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator/(const double_double& a, I n) {
    return fits_double(n) ? a / static_cast<double>(n) : a / double_double(n);
  }
  /// n / a, n an integer converted exactly.
  template <std::integral I>
  friend double_double operator/(I n, const double_double& a) { return double_double(n) / a; }

  /// *this = *this + b.
  template <class T>
  double_double& operator+=(const T& b) { return *this = *this + b; }
  /// *this = *this - b.
  template <class T>
  double_double& operator-=(const T& b) { return *this = *this - b; }
  /// *this = *this * b.
  template <class T>
  double_double& operator*=(const T& b) { return *this = *this * b; }
  /// *this = *this / b.
  template <class T>
  double_double& operator/=(const T& b) { return *this = *this / b; }

  /// Equality of values (NaN unequal to everything).
  friend bool operator==(const double_double& a, const double_double& b) { return a.m_v == b.m_v; }
  /// Order of values; unordered with a NaN.
  friend std::partial_ordering operator<=>(const double_double& a, const double_double& b) {
    if (a.m_v < b.m_v) return std::partial_ordering::less;
    if (a.m_v > b.m_v) return std::partial_ordering::greater;
    if (a.m_v == b.m_v) return std::partial_ordering::equivalent;
    return std::partial_ordering::unordered;
  }

 private:
  // Whether the integer n is a double exactly (|n| <= 2^53).
  template <std::integral I>
  static bool fits_double(I n) {
    constexpr long long limit = 1LL << 53;
    if constexpr (std::is_signed_v<I>) {
      return n >= -limit && n <= limit;
    } else {
      return n <= static_cast<unsigned long long>(limit);
    }
  }

  dd_real m_v;
};

}  // namespace double_double_math

using double_double_math::double_double;

namespace detail {

/// 2^-969: the smallest magnitude at which a double_double's lo part is still a normal
/// double, i.e. the value carries its 104 bits.
inline double double_double_min_full() { return std::ldexp(1.0, -969); }

/// Significant bits a double_double of this magnitude carries (104 from 2^-969 up,
/// fewer below, where its lo part is subnormal); 0 for zero.
inline int double_double_bits(const double_double& x) {
  if (x.hi() == 0) return 0;
  const int bits = std::ilogb(x.hi()) + 1075;
  return bits < 104 ? (bits < 1 ? 1 : bits) : 104;
}

/// Binary floating type wide enough to hold hi + lo of every double_double exactly
/// (2^1024 down to 2^-1074), for exact decimal output.
using double_double_exact =
    boost::multiprecision::number<boost::multiprecision::cpp_bin_float<2112, boost::multiprecision::digit_base_2>,
                                  boost::multiprecision::et_off>;

/// Binary floating type for decimal input: 240 bits, the decimal correctly rounded.
using double_double_parse =
    boost::multiprecision::number<boost::multiprecision::cpp_bin_float<240, boost::multiprecision::digit_base_2>,
                                  boost::multiprecision::et_off>;

}  // namespace detail

/// The decimal number `text` ([+-]digits[.digits][e[+-]digits]) as a double_double:
/// hi = the double nearest to it (strtod), lo = the remainder rounded to a double, so the
/// error is at most 2^-105 relative (plus 2^-240 for the 240-bit intermediate) for
/// |x| >= 2^-969. Not a syntax check: parse_real checks the text first.
inline double_double parse_double_double(const char* text) {
  const double hi = std::strtod(text, nullptr);
  if (!std::isfinite(hi) || hi == 0) return double_double(hi);
  const detail::double_double_parse x(text);
  const detail::double_double_parse remainder = x - detail::double_double_parse(hi);  // exact
  const double lo = remainder.convert_to<double>();
  return double_double(dd_real::add(hi, lo));
}

/// True where x keeps its 104 bits (zero, or |x| >= 2^-969): the range in which the
/// error rules of this header hold; below it a result has lost digits to underflow.
inline bool carries_full_precision(const double_double& x) {
  return x.hi() == 0 || !std::isfinite(x.hi()) || std::fabs(x.hi()) >= detail::double_double_min_full();
}

namespace double_double_math {

inline double_double::double_double(const char* text) : m_v(parse_double_double(text).qd()) {}

// ---- functions found by argument-dependent lookup (using std::pow; pow(x, y)) ----

/// |x|.
inline double_double abs(const double_double& x) { return x.hi() < 0 ? -x : x; }
/// |x|.
inline double_double fabs(const double_double& x) { return abs(x); }
/// Whether x is finite.
inline bool isfinite(const double_double& x) { return std::isfinite(x.hi()); }
/// Whether x is NaN.
inline bool isnan(const double_double& x) { return std::isnan(x.hi()) || std::isnan(x.lo()); }
/// Whether x is infinite.
inline bool isinf(const double_double& x) { return std::isinf(x.hi()); }
/// Whether x is negative (or -0).
inline bool signbit(const double_double& x) { return std::signbit(x.hi()); }
/// x * 2^e, exact while no part underflows.
inline double_double ldexp(const double_double& x, int e) { return double_double(ldexp(x.qd(), e)); }
/// m * 2^*e = x with 1/2 <= |m| < 1 (m = 0, *e = 0 for x = 0).
inline double_double frexp(const double_double& x, int* e) {
  *e = 0;
  if (x.hi() == 0 || !std::isfinite(x.hi())) return x;
  (void)std::frexp(x.hi(), e);
  double_double m = ldexp(x, -*e);
  if (std::fabs(m.hi()) == 0.5 && m.lo() != 0 && std::signbit(m.lo()) != std::signbit(m.hi())) {
    m = ldexp(m, 1);  // hi = +-1/2 with lo of the other sign: |m| < 1/2
    --*e;
  }
  return m;
}
/// Largest integer <= x.
inline double_double floor(const double_double& x) { return double_double(floor(x.qd())); }
/// Smallest integer >= x.
inline double_double ceil(const double_double& x) { return double_double(ceil(x.qd())); }
/// x rounded toward zero to an integer.
inline double_double trunc(const double_double& x) { return double_double(aint(x.qd())); }
/// x rounded to the nearest integer, halfway cases away from zero.
inline double_double round(const double_double& x) {
  return signbit(x) ? -floor(-x + double_double(0.5)) : floor(x + double_double(0.5));
}
/// Square root (QD: one Newton step from the double square root).
inline double_double sqrt(const double_double& x) { return double_double(sqrt(x.qd())); }
/// e^x (QD).
inline double_double exp(const double_double& x) { return double_double(exp(x.qd())); }
/// Natural logarithm (QD: one Newton step from the double logarithm).
inline double_double log(const double_double& x) { return double_double(log(x.qd())); }
/// Decimal logarithm (QD).
inline double_double log10(const double_double& x) { return double_double(log10(x.qd())); }
namespace detail {
// NOTE: QD's log is one Newton step from the double logarithm, exact to about 2^-104
// absolutely, so near 1 its relative error grows like 2^-104 / |ln w| (16 digits left at
// w = 1 + 1e-16): log1p and expm1 therefore never take the logarithm of a number near
// 1; they sum series in which every term is small against the first.

// 2 atanh(s) = 2 (s + s^3/3 + s^5/5 + ...), |s| <= 1/3: every term adds, none cancels.
inline double_double twice_atanh_series(const double_double& s) {
  const double_double s2 = s * s;
  double_double term = s, sum = s;
  for (int k = 3; k < 200; k += 2) {
    term = term * s2;
    const double_double next = sum + term / double_double(k);
    if (next == sum) break;
    sum = next;
  }
  return 2 * sum;
}

// e^x - 1 = x + x^2/2! + ... for |x| <= 1/16 (each term at most 1/32 of the one before).
inline double_double expm1_series(const double_double& x) {
  double_double term = x, sum = x;
  for (int k = 2; k < 40; ++k) {
    term = term * x / double_double(k);
    const double_double next = sum + term;
    if (next == sum) break;
    sum = next;
  }
  return sum;
}
}  // namespace detail

/// ln(1 + x) with its relative digits for every x > -1: 2 atanh(x / (2 + x)) where
/// that is at most 1/3 (-1/2 <= x <= 1), else ln(1 + x) (|ln(1 + x)| > 0.69, where
/// log's absolute error is relative too).
inline double_double log1p(const double_double& x) {
  if (x == 0 || !isfinite(x)) return x == 0 ? x : log(1 + x);
  if (x.hi() >= -0.5 && x.hi() <= 1) return detail::twice_atanh_series(x / (2 + x));
  return log(1 + x);
}
/// e^x - 1 with its relative digits: for |x| <= 1/2, the series at x / 2^k (|x / 2^k|
/// <= 1/16), then k <= 3 doublings e^2y - 1 = m (m + 2) with m = e^y - 1 (|m| < 1, so
/// m + 2 > 1 cancels nothing); else e^x - 1 (|e^x - 1| > 0.39).
inline double_double expm1(const double_double& x) {
  if (x == 0 || !isfinite(x) || std::fabs(x.hi()) > 0.5) return x == 0 ? x : exp(x) - 1;
  int halvings = 0;
  double_double y = x;
  while (std::fabs(y.hi()) > 0.0625) y = ldexp(y, -1), ++halvings;  // at most 3
  double_double m = detail::expm1_series(y);
  for (int k = 0; k < halvings; ++k) m = m * (m + 2);
  return m;
}
/// Sine (QD).
inline double_double sin(const double_double& x) { return double_double(sin(x.qd())); }
/// Cosine (QD).
inline double_double cos(const double_double& x) { return double_double(cos(x.qd())); }
/// Hyperbolic sine (QD).
inline double_double sinh(const double_double& x) { return double_double(sinh(x.qd())); }
/// Hyperbolic cosine (QD).
inline double_double cosh(const double_double& x) { return double_double(cosh(x.qd())); }
/// Hyperbolic tangent (QD).
inline double_double tanh(const double_double& x) { return double_double(tanh(x.qd())); }
/// Inverse hyperbolic tangent (QD).
inline double_double atanh(const double_double& x) { return double_double(atanh(x.qd())); }
/// Arc tangent of y/x in the quadrant of (x, y) (QD).
inline double_double atan2(const double_double& y, const double_double& x) {
  return double_double(atan2(y.qd(), x.qd()));
}
/// x^n for an integer n (repeated squaring: about 2 log2|n| products).
inline double_double pow(const double_double& x, int n) {
  return n == 0 ? double_double(1.0) : double_double(npwr(x.qd(), n));  // QD's npwr(0, 0) reports an error
}
/// x^n for an integer n of another integer type (|n| < 2^31).
template <std::integral I>
double_double pow(const double_double& x, I n) {
  return pow(x, static_cast<int>(n));
}
/// x^y for x > 0 (and x = 0, y > 0; integer y for x < 0): with x = 2^k m,
/// 1/sqrt 2 <= m < sqrt 2, and y k = j + f split exactly into an integer j and a
/// fraction f, x^y = 2^j exp(f ln 2 + y ln m), whose argument is O(|y|): unlike
/// exp(y ln x), the error does not grow with |ln x|.
inline double_double pow(const double_double& x, const double_double& y) {
  if (y == 0) return double_double(1.0);
  if (isnan(x) || isnan(y)) return double_double(std::numeric_limits<double>::quiet_NaN());
  if (y.hi() == std::nearbyint(y.hi()) && y.lo() == 0 && std::fabs(y.hi()) <= 1024)
    return pow(x, static_cast<int>(y.hi()));
  if (x.hi() <= 0) {
    if (x.hi() == 0) return y > 0 ? double_double(0.0) : double_double(std::numeric_limits<double>::infinity());
    return double_double(std::numeric_limits<double>::quiet_NaN());
  }
  if (!isfinite(x) || !isfinite(y)) return double_double(exp(y.qd() * log(x.qd())));
  int k = 0;
  double_double m = frexp(x, &k);  // x = m 2^k, 1/2 <= m < 1
  if (m.hi() < 0.70710678118654752) m = ldexp(m, 1), --k;
  // y k exactly: two exact products (two_prod), then the integer part taken off the
  // leading one, which is exact while |y k| < 2^52.
  double e1 = 0, e2 = 0;
  const double p1 = qd::two_prod(y.hi(), static_cast<double>(k), e1);
  const double p2 = qd::two_prod(y.lo(), static_cast<double>(k), e2);
  if (!(std::fabs(p1) < 0x1p52)) return double_double(exp(y.qd() * log(x.qd())));  // overflows or underflows
  const double j = std::nearbyint(p1);
  const double_double f = double_double(p1 - j) + double_double(e1) + double_double(p2) + double_double(e2);
  const double_double ln2(dd_real::_log2);
  const double_double r = exp(f * ln2 + y * log(m));
  if (std::fabs(j) > 2000) return ldexp(r, j > 0 ? 2000 : -2000);  // overflow or underflow, as exp would
  return ldexp(r, static_cast<int>(j));
}
/// x^y with a double exponent (exact conversion to double_double).
inline double_double pow(const double_double& x, double y) { return pow(x, double_double(y)); }
/// The larger of a and b.
inline double_double max(const double_double& a, const double_double& b) { return a < b ? b : a; }
/// The smaller of a and b.
inline double_double min(const double_double& a, const double_double& b) { return b < a ? b : a; }

/// x printed as to_decimal_string prints it (the stream's precision, scientific).
inline std::ostream& operator<<(std::ostream& out, const double_double& x);

}  // namespace double_double_math
}  // namespace viscor

namespace std {
/// numeric_limits of double_double: 104 bits (QD's own figure for dd_real, 31 decimal
/// digits), double's exponent range with min() = 2^-969, the smallest magnitude with
/// all 104 bits; epsilon 2^-103 = 2^(1 - digits), as viscor::epsilon computes it.
template <>
class numeric_limits<viscor::double_double> {
 public:
  static constexpr bool is_specialized = true;
  static constexpr int digits = 104;
  static constexpr int digits10 = 31;
  static constexpr int max_digits10 = 33;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = false;
  static constexpr int radix = 2;
  static constexpr int min_exponent = -968;
  static constexpr int min_exponent10 = -291;
  static constexpr int max_exponent = 1024;
  static constexpr int max_exponent10 = 308;
  static constexpr bool has_infinity = true;
  static constexpr bool has_quiet_NaN = true;
  static constexpr bool has_signaling_NaN = true;
  static constexpr std::float_denorm_style has_denorm = std::denorm_absent;
  static constexpr bool has_denorm_loss = false;
  static constexpr bool is_iec559 = false;
  static constexpr bool is_bounded = true;
  static constexpr bool is_modulo = false;
  static constexpr bool traps = false;
  static constexpr bool tinyness_before = false;
  static constexpr std::float_round_style round_style = std::round_indeterminate;
  /// 2^-969.
  static viscor::double_double min() { return viscor::double_double(std::ldexp(1.0, -969)); }
  /// QD's largest finite value.
  static viscor::double_double max() { return viscor::double_double(dd_real::_max); }
  /// -max().
  static viscor::double_double lowest() { return -max(); }
  /// 2^-103.
  static viscor::double_double epsilon() { return viscor::double_double(std::ldexp(1.0, -103)); }
  /// 1 (in ulps).
  static viscor::double_double round_error() { return viscor::double_double(1.0); }
  /// +inf.
  static viscor::double_double infinity() { return viscor::double_double(std::numeric_limits<double>::infinity()); }
  /// A quiet NaN.
  static viscor::double_double quiet_NaN() { return viscor::double_double(std::numeric_limits<double>::quiet_NaN()); }
  /// A signalling NaN.
  static viscor::double_double signaling_NaN() {
    return viscor::double_double(std::numeric_limits<double>::signaling_NaN());
  }
  /// min() (no subnormal numbers of full precision).
  static viscor::double_double denorm_min() { return min(); }
};
}  // namespace std

namespace viscor {

namespace detail {
/// True for double_double: the type whose full precision ends at 2^-969, far above the
/// exponent range of its parts.
template <class Real>
struct is_double_double : std::false_type {};
/// double_double itself.
template <>
struct is_double_double<double_double> : std::true_type {};
}  // namespace detail

/// x in scientific notation with `digits` significant digits, never more than x carries:
/// 31 (decimal_digits<double_double>()), fewer below 2^-969; the default is that maximum.
/// The decimal is the exact value hi + lo correctly rounded.
template <>
inline std::string to_decimal_string<double_double>(const double_double& x, int digits) {
  if (!isfinite(x)) return isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
  const int carried = x.hi() == 0 ? decimal_digits<double_double>() : decimal_digits_of_binary(detail::double_double_bits(x));
  const int shown = carried < 1 ? 1 : carried;
  if (digits <= 0 || digits > shown) digits = shown;
  detail::double_double_exact exact(x.hi());
  exact += x.lo();  // exact: 2112 bits hold every hi + lo
  std::ostringstream out;
  out << std::scientific << std::setprecision(digits - 1) << exact;
  return out.str();
}

/// Parses a finite decimal number into a double_double within 2^-105 relative
/// (parse_double_double); refuses, like the other types, text that overflows and nonzero
/// text below 2^-969, where a double_double no longer carries its 31 digits.
template <>
inline double_double parse_real<double_double>(const std::string& text, const std::string& name) {
  if (!detail::looks_like_decimal(text))
    throw invalid_parameter("parameter " + name + " must be a finite decimal number, but got '" + text + "'");
  const double_double x = parse_double_double(text.c_str());
  if (!isfinite(x))
    throw invalid_parameter("parameter " + name + " = " + text + " overflows the working precision");
  if (detail::has_nonzero_digit(text) && (x == 0 || !carries_full_precision(x)))
    throw exponent_range_exceeded("parameter " + name + " = " + text +
                                  " underflows the working precision (nonzero, but below 2^-969 = 2.0e-292, where "
                                  "double-double keeps fewer than 31 digits; give 0 or use MPFR)");
  return x;
}

/// The smallest nonzero magnitude that a double-double solve accepts as an input or
/// reports as a value: 2^-939, i.e. 2^30 above 2^-969, where the lo part becomes
/// subnormal. NOTE: below 2^-969 each operation adds an absolute error of up to 2^-1075
/// (the lo part's rounding) besides its relative error; a value of at least 2^-939,
/// reached in fewer than 2^30 operations, keeps that share below 2^-105 relative.
inline double double_double_smallest_reported() { return std::ldexp(1.0, -939); }

namespace detail {
/// Throws exponent_range_exceeded when x is nonzero, finite and below
/// double_double_smallest_reported() in magnitude; `what` names the value.
inline void require_double_double_range(const double_double& x, const std::string& what) {
  if (x.hi() == 0 || !std::isfinite(x.hi()) || std::fabs(x.hi()) >= double_double_smallest_reported()) return;
  throw exponent_range_exceeded(what + " = " + to_decimal_string(x, 6) +
                              " is below 2^-939 = 2.2e-283, where double-double (double's exponent range) no "
                              "longer carries its 31 digits; solve in MPFR instead");
}
}  // namespace detail

inline std::ostream& double_double_math::operator<<(std::ostream& out, const double_double& x) {
  const std::streamsize p = out.precision();
  return out << to_decimal_string(x, p > 0 ? static_cast<int>(p) + 1 : 0);
}

}  // namespace viscor

#endif  // VISCOR_HAS_QD
