// Fuzz target: exact decimal and rational parsing (core/detail/exact_decimal.hpp,
// core/real_io.hpp, core/contact_law.hpp's exponent). Every number viscor reads
// from an option or a file goes through these. Checks beyond "no crash":
//   * exact_decimal: parse -> to_string -> parse gives the same number, and the
//     printed text is canonical (printing it again gives the same text); for two
//     numbers (two lines), a <=> b agrees with the sign of a - b;
//   * parse_real in double and long double: the text and the exact decimal's
//     canonical text round to the same value (or are refused alike);
//   * exponent: parse -> to_string -> parse gives the same exponent, and a
//     rational p/q read from a decimal has exactly the decimal's value.
#include "fuzz_support.hpp"

#include <viscor/core/contact_law.hpp>
#include <viscor/core/detail/exact_decimal.hpp>
#include <viscor/core/real_io.hpp>

#include <optional>

namespace {

template <class Real>
std::optional<Real> parsed(const std::string& text) {
  try {
    return viscor::parse_real<Real>(text, "x");
  } catch (const viscor::invalid_parameter&) {
    return std::nullopt;
  }
}

template <class Real>
void same_value(const std::string& text, const std::string& canonical) {
  const auto a = parsed<Real>(text), b = parsed<Real>(canonical);
  viscor::fuzz::fuzz_require(a.has_value() == b.has_value(),
                             "parse_real accepts one of '" + text + "' and its canonical form '" + canonical + "'");
  if (a) viscor::fuzz::fuzz_require(*a == *b, "parse_real('" + text + "') != parse_real('" + canonical + "')");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::detail::exact_decimal;
  using viscor::fuzz::fuzz_require;
  if (size > 4096) return 0;  // longer numbers are refused by length long before: nothing new to learn
  const std::string text = viscor::fuzz::text_of(data, size);

  viscor::fuzz::refusal_or_result([&] {
    const exact_decimal x = exact_decimal::parse(text, "x");
    const std::string canonical = x.to_string();
    const exact_decimal y = exact_decimal::parse(canonical, "x");
    fuzz_require(x == y, "exact_decimal round trip: '" + text + "' -> '" + canonical + "'");
    fuzz_require(y.to_string() == canonical, "exact_decimal text not canonical: '" + canonical + "'");
    fuzz_require((x <=> y) == 0 && !(x < y) && (x - y).is_zero(), "exact_decimal compares unequal to itself");
    if (text.size() <= 400) {  // correctly rounded both ways: the same double
      same_value<double>(text, canonical);
      same_value<long double>(text, canonical);
    }
  });

  // Two numbers (the input's first two lines): the ordering agrees with the sign of the difference.
  const auto lines = viscor::fuzz::lines_of(text);
  auto short_exponent = [](const std::string& t) {
    const std::size_t e = t.find_first_of("eE");
    return e == std::string::npos || t.size() - e <= 5;
  };
  if (lines.size() >= 2 && short_exponent(lines[0]) && short_exponent(lines[1]))
    viscor::fuzz::refusal_or_result([&] {
      const exact_decimal a = exact_decimal::parse(lines[0], "a"), b = exact_decimal::parse(lines[1], "b");
      const int d = (a - b).sign();
      const auto order = a <=> b;
      fuzz_require((d < 0) == (order < 0) && (d == 0) == (order == 0) && (d > 0) == (order > 0),
                   "a <=> b disagrees with the sign of a - b: '" + lines[0] + "', '" + lines[1] + "'");
      fuzz_require(((b <=> a) < 0) == (order > 0), "b <=> a is not the reverse of a <=> b");
    });

  viscor::fuzz::refusal_or_result([&] {
    const viscor::exponent e = viscor::exponent::parse(text, "alpha");
    const std::string printed = e.to_string();
    const viscor::exponent again = viscor::exponent::parse(printed, "alpha");
    fuzz_require(e == again, "exponent round trip: '" + text + "' -> '" + printed + "'");
    if (e.is_rational()) {
      fuzz_require(e.denominator() > 0, "exponent with denominator <= 0 from '" + text + "'");
      if (text.find('/') == std::string::npos) {
        // p/q must be the decimal's exact value: decimal * q == p.
        const exact_decimal x = exact_decimal::parse(text, "alpha");
        fuzz_require(x.times(e.denominator()) == exact_decimal(e.numerator(), 0),
                     "exponent '" + text + "' read as " + printed + ", not its exact value");
      }
    }
    (void)e.at_least_one();
  });
  return 0;
}
