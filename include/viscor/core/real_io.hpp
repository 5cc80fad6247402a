// Decimal I/O of Real at full precision: parsing user input exactly (correctly
// rounded in Real, never through double) and printing round-trip strings.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <ios>
#include <sstream>
#include <string>
#include <type_traits>

namespace viscor {

/// Significant decimal digits that make a Real round-trip through text
/// (std::numeric_limits<T>::max_digits10 = ceil(binary log10 2) + 1).
template <class Real>
int roundtrip_digits() {
  return static_cast<int>(static_cast<long long>(binary_digits<Real>()) * 30103 / 100000) + 2;
}

/// x in scientific notation with `digits` significant digits (default: round-trip).
template <class Real>
std::string to_decimal_string(const Real& x, int digits = 0) {
  using boost::math::isfinite;
  using boost::math::isnan;
  if (!isfinite(x)) return isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf");
  if (digits <= 0) digits = roundtrip_digits<Real>();
  std::ostringstream out;
  out << std::scientific << std::setprecision(digits - 1) << x;
  return out.str();
}

namespace detail {
inline bool looks_like_decimal(const std::string& s) {
  // [+-]digits[.digits][(e|E)[+-]digits]: what strtod, mpfr and float128 all accept alike.
  std::size_t i = 0, n = s.size();
  if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa_digits = 0;
  while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++mantissa_digits;
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++mantissa_digits;
  }
  if (mantissa_digits == 0) return false;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == n;
}

/// Whether a decimal accepted by looks_like_decimal has a nonzero digit before its exponent.
inline bool has_nonzero_digit(const std::string& s) {
  for (const char c : s) {
    if (c == 'e' || c == 'E') return false;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

/// Whether x, parsed from a nonzero decimal, lost it to underflow: rounded to zero,
/// or (in double and long double) to a subnormal number, which keeps fewer digits
/// than the working precision promises.
template <class Real>
bool underflowed(const Real& x) {
  if (x == 0) return true;
  if constexpr (std::is_floating_point_v<Real>) return std::fpclassify(x) == FP_SUBNORMAL;
  return false;
}
}  // namespace detail

/// Parses a finite decimal number, correctly rounded to Real. `name` is the
/// parameter named in the error message ("gamma", "g", ...).
template <class Real>
Real parse_real(const std::string& text, const std::string& name) {
  if (!detail::looks_like_decimal(text))
    throw invalid_parameter("parameter " + name + " must be a finite decimal number, but got '" + text + "'");
  Real x;
  if constexpr (std::is_same_v<Real, double>) {
    x = std::strtod(text.c_str(), nullptr);
  } else if constexpr (std::is_same_v<Real, long double>) {
    x = std::strtold(text.c_str(), nullptr);
  } else {
    x = Real(text);  // Boost.Multiprecision parses at the type's own precision
  }
  using boost::math::isfinite;
  if (!isfinite(x))
    throw invalid_parameter("parameter " + name + " = " + text + " overflows the working precision");
  if (detail::has_nonzero_digit(text) && detail::underflowed(x))
    throw invalid_parameter("parameter " + name + " = " + text +
                            " underflows the working precision (nonzero, but below its smallest normal number; "
                            "give 0 or ask for more digits)");
  return x;
}

/// Sets this thread's default precision of run-time mpfr_float for a scope; a no-op for
/// every fixed-precision type.
class scoped_precision {
 public:
  /// Sets the precision to `decimal_digits_wanted` digits until the end of the scope.
  explicit scoped_precision(int decimal_digits_wanted) {
#if VISCOR_HAS_MPFR
    m_saved = mpfr_real::thread_default_precision();
    mpfr_real::thread_default_precision(static_cast<unsigned>(decimal_digits_wanted));
#else
    (void)decimal_digits_wanted;
#endif
  }
  ~scoped_precision() {
#if VISCOR_HAS_MPFR
    mpfr_real::thread_default_precision(m_saved);
#endif
  }
  scoped_precision(const scoped_precision&) = delete;
  scoped_precision& operator=(const scoped_precision&) = delete;

 private:
  unsigned m_saved = 0;
};

}  // namespace viscor
