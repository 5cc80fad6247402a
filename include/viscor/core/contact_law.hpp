// The contact law F = k (u^alpha + gamma0 d/dt u^beta): its two exponents, kept
// as exact rationals p/q whenever they are given so (the integrators need the
// denominators to regularise u^(p/q) at u = 0), and the named presets.
#pragma once

#include <viscor/core/checked_arithmetic.hpp>
#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_io.hpp>

#include <array>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace viscor {

/// A contact-law exponent: an exact rational p/q (q <= max_denominator), or any
/// other real number held as its exact decimal text.
class exponent {
 public:
  static constexpr std::int64_t max_denominator = 1'000'000'000;

  /// p/q, reduced. Throws invalid_parameter for q <= 0.
  static exponent rational(std::int64_t p, std::int64_t q) {
    if (q <= 0) throw invalid_parameter("exponent denominator must be positive, got " + std::to_string(q));
    const std::int64_t d = std::gcd(p, q);
    exponent e;
    e.m_num = p / d;
    e.m_den = q / d;
    return e;
  }

  /// Parses "3/2", "1.5", "1.25e0" or a long decimal. A decimal whose exact value
  /// is p/q with q <= max_denominator becomes that rational; any other decimal
  /// stays an exact decimal (a "real" exponent). `name` is used in errors.
  static exponent parse(const std::string& text, const std::string& name) {
    const auto slash = text.find('/');
    if (slash != std::string::npos) {
      const std::string p = text.substr(0, slash), q = text.substr(slash + 1);
      auto is_int = [](const std::string& s) {
        std::size_t i = (!s.empty() && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
        if (i == s.size() || s.size() - i > 18) return false;
        for (; i < s.size(); ++i)
          if (s[i] < '0' || s[i] > '9') return false;
        return true;
      };
      if (!is_int(p) || !is_int(q) || std::stoll(q) <= 0)
        throw invalid_parameter("parameter " + name + " must be a fraction p/q of integers with q > 0, got '" +
                                text + "'");
      return rational(std::stoll(p), std::stoll(q));
    }
    if (!detail::looks_like_decimal(text))
      throw invalid_parameter("parameter " + name + " must be a number or a fraction p/q, got '" + text + "'");
    if (auto r = decimal_as_rational(text)) return *r;
    exponent e;
    e.m_decimal = text;
    return e;
  }

  /// A real exponent known only as a value of some type (say sqrt(2) at 100 digits).
  template <class Real>
  static exponent from_real(const Real& x) {
    exponent e;
    const std::string text = to_decimal_string(x);
    if (auto r = decimal_as_rational(text)) return *r;
    e.m_decimal = text;
    return e;
  }

  /// Whether the exponent is an exact rational p/q (else a decimal that is not one).
  bool is_rational() const noexcept { return !m_decimal.has_value(); }
  std::int64_t numerator() const noexcept { return m_num; }      ///< valid when is_rational()
  std::int64_t denominator() const noexcept { return m_den; }    ///< valid when is_rational()

  /// The exponent correctly rounded to Real.
  template <class Real>
  Real value() const {
    if (m_decimal) return parse_real<Real>(*m_decimal, "exponent");
    return Real(m_num) / Real(m_den);
  }

  /// "3/2", "1", or the exact decimal text.
  std::string to_string() const {
    if (m_decimal) return *m_decimal;
    return m_den == 1 ? std::to_string(m_num) : std::to_string(m_num) + "/" + std::to_string(m_den);
  }

  /// The exponent in long double, for display and rough comparisons only: never
  /// for validation (0.99999999999999999999999 rounds to 1 there); use at_least_one.
  long double approximate() const {
    return m_decimal ? std::strtold(m_decimal->c_str(), nullptr)
                     : static_cast<long double>(m_num) / static_cast<long double>(m_den);
  }

  /// Exactly whether the exponent is >= 1, as the rational or decimal it was read as.
  bool at_least_one() const {
    if (!m_decimal) return m_num >= m_den;  // m_den > 0
    return detail::exact_decimal::parse(*m_decimal, "exponent") >= detail::exact_decimal(1, 0);
  }

  friend bool operator==(const exponent& a, const exponent& b) {
    return a.m_num == b.m_num && a.m_den == b.m_den && a.m_decimal == b.m_decimal;
  }

 private:
  // Exact value of a short decimal as p/q, or nothing if it does not fit.
  static std::optional<exponent> decimal_as_rational(const std::string& s) {
    std::size_t i = 0;
    bool negative = false;
    if (s[i] == '+' || s[i] == '-') negative = s[i++] == '-';
    __int128 num = 0;
    int scale = 0, exp10 = 0;
    bool after_point = false;
    for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
      if (s[i] == '.') { after_point = true; continue; }
      num = num * 10 + (s[i] - '0');
      if (after_point) ++scale;
      if (num > (__int128(1) << 100)) return std::nullopt;
    }
    if (i < s.size()) {
      const std::string e = s.substr(i + 1);
      if (e.size() > 4) return std::nullopt;
      exp10 = std::stoi(e);
    }
    scale -= exp10;
    __int128 den = 1;
    for (; scale > 0; --scale) {
      den *= 10;
      if (den > (__int128(1) << 100)) return std::nullopt;
    }
    for (; scale < 0; ++scale) {
      num *= 10;
      if (num > (__int128(1) << 100)) return std::nullopt;
    }
    __int128 a = num, b = den;
    while (b != 0) { const __int128 t = a % b; a = b; b = t; }
    if (a != 0) num /= a, den /= a;
    if (den > max_denominator || num > std::numeric_limits<std::int64_t>::max()) return std::nullopt;
    return rational(static_cast<std::int64_t>(negative ? -num : num), static_cast<std::int64_t>(den));
  }

  std::int64_t m_num = 1, m_den = 1;
  std::optional<std::string> m_decimal;
};

/// For rational exponents alpha = p1/q1, beta = p2/q2: Q = lcm(q1, q2) and the
/// integers Q alpha, Q beta (u = s^Q turns u^alpha, u^beta into powers of s).
struct exponent_multiples {
  std::int64_t Q = 1, Q_alpha = 1, Q_beta = 1;

  /// The largest Q, and the largest Q alpha and Q beta, for which the end points are
  /// solved in u = s^Q: its series hold Q (alpha + 1) terms per power of the step.
  static constexpr std::int64_t max_Q = 64, max_Q_exponent = 512;
  /// Whether Q, Q alpha and Q beta are within those caps.
  bool fit_root_variable() const noexcept { return Q <= max_Q && Q_alpha <= max_Q_exponent && Q_beta <= max_Q_exponent; }
};

/// Exponents (alpha, beta) of the contact law; alpha, beta >= 1 (Assumption 1).
struct contact_law {
  exponent alpha = exponent::rational(3, 2);
  exponent beta = exponent::rational(3, 2);
  std::string name;  ///< preset name, empty for a custom law

 private:
  // The name of an integer derived from the exponents, for an overflow message, built
  // only when one is thrown (validate runs at every evaluation). Defined before its
  // uses: its return type is deduced.
  auto named(const char* what) const {
    return [this, what] {
      return "contact law alpha = " + alpha.to_string() + ", beta = " + beta.to_string() + ": " + what;
    };
  }

 public:
  /// Throws invalid_parameter unless alpha >= 1 and beta >= 1 and, for rational
  /// exponents, Q, Q alpha, Q beta and the sums the solvers form of them
  /// (Q alpha + Q, 2 Q beta, Q alpha - Q beta + Q) fit in 64-bit integers.
  void validate() const {
    if (!alpha.at_least_one())
      throw invalid_parameter("contact law exponent alpha must be >= 1, got alpha = " + alpha.to_string());
    if (!beta.at_least_one())
      throw invalid_parameter("contact law exponent beta must be >= 1, got beta = " + beta.to_string());
    if (alpha.is_rational() && beta.is_rational()) {
      const exponent_multiples m = multiples();
      checked_sum(m.Q_alpha, m.Q, named("Q (alpha + 1)"));
      checked_product(2, m.Q_beta, named("2 Q beta"));
      checked_sum(checked_difference(m.Q_alpha, m.Q_beta, named("Q (alpha - beta)")), m.Q, named("Q (alpha - beta + 1)"));
    }
  }

  /// Q, Q alpha and Q beta of rational exponents, checked: an exponent whose
  /// numerator times Q does not fit in 64 bits is refused (invalid_parameter
  /// naming the exponent) rather than wrapped around into another law.
  exponent_multiples multiples() const {
    exponent_multiples m;
    m.Q = checked_lcm(alpha.denominator(), beta.denominator(), named("the common denominator Q"));
    m.Q_alpha = checked_product(m.Q / alpha.denominator(), alpha.numerator(), named("Q alpha"));
    m.Q_beta = checked_product(m.Q / beta.denominator(), beta.numerator(), named("Q beta"));
    return m;
  }

  /// Why the proof (enclose/proven_impact.hpp) cannot take this law, or "" when it can:
  /// it solves the end points in u = s^Q, so it needs rational exponents whose
  /// multiples fit that variable (exponent_multiples::fit_root_variable).
  std::string why_not_provable() const {
    for (const auto& [what, x] : {std::pair<const char*, const exponent*>{"alpha", &alpha}, {"beta", &beta}})
      if (!x->is_rational())
        return "not provable: exponent " + std::string(what) + " = " + x->to_string() +
               " is not rational (the proof needs u = s^Q at the end points)";
    const exponent_multiples m = multiples();
    if (!m.fit_root_variable())
      return "not provable: alpha = " + alpha.to_string() + ", beta = " + beta.to_string() + " need u = s^Q with Q = " +
             std::to_string(m.Q) + ", Q alpha = " + std::to_string(m.Q_alpha) + ", Q beta = " + std::to_string(m.Q_beta) +
             "; the proof takes Q <= " + std::to_string(exponent_multiples::max_Q) + " and Q alpha, Q beta <= " +
             std::to_string(exponent_multiples::max_Q_exponent);
    return "";
  }

  /// "kuwabara_kono (alpha=3/2, beta=3/2)" or "alpha=1.3, beta=17/10".
  std::string describe() const {
    std::string s = "alpha=" + alpha.to_string() + ", beta=" + beta.to_string();
    return name.empty() ? s : name + " (" + s + ")";
  }
};

/// A custom law; validated.
inline contact_law make_law(exponent alpha, exponent beta) {
  contact_law law{std::move(alpha), std::move(beta), {}};
  law.validate();
  return law;
}

/// A named contact law: its CLI name, exponents alpha = alpha_num/alpha_den, beta = beta_num/beta_den, and a short description.
struct named_law {
  std::string_view name;
  std::int64_t alpha_num, alpha_den, beta_num, beta_den;
  std::string_view description;
};

/// The named laws of the report.
inline constexpr std::array<named_law, 5> named_laws{{
    {"linear", 1, 1, 1, 1, "linear spring-dashpot"},
    {"hertz_linear_damping", 3, 2, 1, 1, "Hertz stiffness with linear damping"},
    {"tsuji", 3, 2, 5, 4, "Tsuji-Tanaka-Ishida"},
    {"kuwabara_kono", 3, 2, 3, 2, "Kuwabara-Kono"},
    {"hunt_crossley", 3, 2, 5, 2, "Simon-Hunt-Crossley"},
}};

/// The preset called `name`; throws invalid_parameter listing the valid names.
inline contact_law law_by_name(std::string_view name) {
  std::string valid;
  for (const auto& n : named_laws) {
    if (n.name == name)
      return {exponent::rational(n.alpha_num, n.alpha_den), exponent::rational(n.beta_num, n.beta_den),
              std::string(n.name)};
    valid += (valid.empty() ? "" : ", ") + std::string(n.name);
  }
  throw invalid_parameter("unknown contact law '" + std::string(name) + "' (known: " + valid + ")");
}

}  // namespace viscor
