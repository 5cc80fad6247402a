// Exact decimal numbers m * 10^k (m an arbitrary-precision integer) for the
// inputs of reference tables: grid values are generated and printed without any
// binary rounding, so the gamma and g written in a table are exactly the decimal
// numbers the row was computed for (each is then correctly rounded once into the
// working precision by parse_real).
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_io.hpp>

#include <boost/multiprecision/cpp_int.hpp>

#include <compare>
#include <optional>
#include <string>

namespace viscor::detail {

class exact_decimal {
 public:
  using integer = boost::multiprecision::cpp_int;

  /// Largest |decimal exponent| and number of mantissa digits accepted: far
  /// beyond any table, small enough that arithmetic stays instantaneous.
  static constexpr int max_exponent = 100000;
  static constexpr std::size_t max_mantissa_digits = 10000;

  exact_decimal() = default;
  exact_decimal(integer mantissa, int exponent10) : m_mantissa(std::move(mantissa)), m_exponent(exponent10) {
    normalise();
  }

  /// Parses [+-]digits[.digits][e[+-]digits]; throws invalid_parameter naming `name`.
  static exact_decimal parse(const std::string& text, const std::string& name) {
    if (!looks_like_decimal(text))
      throw invalid_parameter("parameter " + name + " must be a finite decimal number, but got '" + text + "'");
    std::size_t i = 0;
    bool negative = false;
    if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
    std::string digits;
    long long exponent10 = 0;
    bool after_point = false;
    for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
      if (text[i] == '.') {
        after_point = true;
        continue;
      }
      digits += text[i];
      if (after_point) --exponent10;
    }
    if (i < text.size()) {
      const std::string e = text.substr(i + 1);
      const std::size_t first = e.find_first_not_of("+-0");
      if (first != std::string::npos && e.size() - first > 7)
        throw invalid_parameter("parameter " + name + " = " + text + " has an out-of-range exponent");
      exponent10 += std::stoll(e);
    }
    const std::size_t first_nonzero = digits.find_first_not_of('0');
    digits = first_nonzero == std::string::npos ? "0" : digits.substr(first_nonzero);
    // Trailing zeros go into the exponent here, not one division at a time in normalise.
    const std::size_t last_nonzero = digits.find_last_not_of('0');
    if (last_nonzero != std::string::npos) {
      exponent10 += static_cast<long long>(digits.size() - 1 - last_nonzero);
      digits.resize(last_nonzero + 1);
    }
    if (digits.size() > max_mantissa_digits)
      throw invalid_parameter("parameter " + name + " = " + text + " has too many digits");
    if (exponent10 > max_exponent || exponent10 < -max_exponent)
      throw invalid_parameter("parameter " + name + " = " + text + " has an out-of-range exponent");
    integer m(digits);
    return exact_decimal(negative ? integer(-m) : m, static_cast<int>(exponent10));
  }

  /// Canonical text: positional for 1e-4 <= |x| < 1e16 ("0.05", "1000000"),
  /// else scientific with a two-digit exponent ("1e-08", "1.58489e-08").
  std::string to_string() const {
    if (m_mantissa == 0) return "0";
    const bool negative = m_mantissa < 0;
    const std::string digits = (negative ? integer(-m_mantissa) : m_mantissa).str();
    const long long n = static_cast<long long>(digits.size());
    const long long adjusted = m_exponent + n - 1;  // exponent of the leading digit
    std::string s = negative ? "-" : "";
    if (adjusted < -4 || adjusted >= 16) {
      s += digits.substr(0, 1);
      if (n > 1) s += "." + digits.substr(1);
      std::string e = std::to_string(adjusted < 0 ? -adjusted : adjusted);
      if (e.size() < 2) e = "0" + e;
      return s + "e" + (adjusted < 0 ? "-" : "+") + e;
    }
    if (m_exponent >= 0) return s + digits + std::string(static_cast<std::size_t>(m_exponent), '0');
    const long long point = n + m_exponent;  // digits before the decimal point
    if (point > 0) return s + digits.substr(0, point) + "." + digits.substr(point);
    return s + "0." + std::string(static_cast<std::size_t>(-point), '0') + digits;
  }

  int sign() const { return m_mantissa == 0 ? 0 : (m_mantissa < 0 ? -1 : 1); }
  /// Exponent of the leading decimal digit (x = d.ddd * 10^leading_exponent); x != 0.
  long long leading_exponent() const {
    const std::string digits = (m_mantissa < 0 ? integer(-m_mantissa) : m_mantissa).str();
    return m_exponent + static_cast<long long>(digits.size()) - 1;
  }
  bool is_zero() const { return m_mantissa == 0; }

  friend exact_decimal operator+(const exact_decimal& a, const exact_decimal& b) {
    const int k = a.m_exponent < b.m_exponent ? a.m_exponent : b.m_exponent;
    return exact_decimal(a.scaled_to(k) + b.scaled_to(k), k);
  }
  friend exact_decimal operator-(const exact_decimal& a, const exact_decimal& b) {
    return a + exact_decimal(integer(-b.m_mantissa), b.m_exponent);
  }
  exact_decimal times(long long k) const { return exact_decimal(m_mantissa * k, m_exponent); }

  /// this / n if that is a terminating decimal with at most max_mantissa_digits digits.
  std::optional<exact_decimal> divided_exactly(long long n) const {
    if (n == 0) return std::nullopt;
    integer m = m_mantissa;
    int e = m_exponent;
    // NOTE: x/n terminates iff n / gcd(m, n) has no prime factor other than 2 and 5;
    // each factor 10 taken into m removes one of them, so 4 log2(n) + 1 rounds suffice.
    for (int round = 0; round < 260; ++round, m *= 10, --e)
      if (m % n == 0) return exact_decimal(integer(m / n), e);
    return std::nullopt;
  }

  friend bool operator==(const exact_decimal& a, const exact_decimal& b) {
    return a.m_mantissa == b.m_mantissa && a.m_exponent == b.m_exponent;  // both normalised
  }
  friend std::strong_ordering operator<=>(const exact_decimal& a, const exact_decimal& b) {
    // By sign, then by the exponent of the leading digit: numbers far apart are
    // compared without aligning their exponents (1e99999 against 1 would otherwise
    // multiply by 10 a hundred thousand times).
    if (a.sign() != b.sign()) return a.sign() <=> b.sign();
    if (a.sign() == 0) return std::strong_ordering::equal;
    if (a.m_exponent == b.m_exponent)
      return a.m_mantissa == b.m_mantissa ? std::strong_ordering::equal
                                          : (a.m_mantissa < b.m_mantissa ? std::strong_ordering::less
                                                                         : std::strong_ordering::greater);
    const int gap = a.m_exponent > b.m_exponent ? a.m_exponent - b.m_exponent : b.m_exponent - a.m_exponent;
    if (gap > 64) {  // rare: the leading digits decide unless they are at the same place
      const long long la = a.leading_exponent(), lb = b.leading_exponent();
      if (la != lb) return a.sign() > 0 ? la <=> lb : lb <=> la;
    }
    const integer d = (a - b).m_mantissa;
    return d == 0 ? std::strong_ordering::equal : (d < 0 ? std::strong_ordering::less : std::strong_ordering::greater);
  }

 private:
  // Mantissa for exponent k <= m_exponent (one multiplication by a power of 10).
  integer scaled_to(int k) const {
    if (k >= m_exponent) return m_mantissa;
    return m_mantissa * boost::multiprecision::pow(integer(10), static_cast<unsigned>(m_exponent - k));
  }
  // Strips trailing zeros so that equal numbers have equal representations.
  void normalise() {
    if (m_mantissa == 0) {
      m_exponent = 0;
      return;
    }
    while (m_mantissa % 10 == 0) m_mantissa /= 10, ++m_exponent;
  }

  integer m_mantissa = 0;
  int m_exponent = 0;
};

}  // namespace viscor::detail
