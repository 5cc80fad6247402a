// Fuzz target: law and exponent options (--model/--law NAME, --alpha, --beta, a
// table spec's or a point's law): core/contact_law.hpp. The input's first line is
// a law name, the next two alpha and beta. Checks beyond "no crash": a law that
// validates has exponents >= 1, and for rational exponents Q is a common multiple
// of both denominators with Q alpha and Q beta exactly Q times the exponents (the
// integers the solvers and proofs use; 64-bit overflow there once proved another law).
#include "fuzz_support.hpp"

#include <viscor/core/contact_law.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::fuzz::fuzz_require;
  if (size > 4096) return 0;
  const auto lines = viscor::fuzz::lines_of(viscor::fuzz::text_of(data, size));

  viscor::fuzz::refusal_or_result([&] {
    const viscor::contact_law law = viscor::law_by_name(lines[0]);
    fuzz_require(law.name == lines[0], "law_by_name('" + lines[0] + "') returned " + law.name);
    law.validate();
  });
  if (lines.size() < 3) return 0;

  viscor::fuzz::refusal_or_result([&] {
    const viscor::contact_law law =
        viscor::make_law(viscor::exponent::parse(lines[1], "alpha"), viscor::exponent::parse(lines[2], "beta"));
    fuzz_require(law.alpha.at_least_one() && law.beta.at_least_one(), "a validated law has an exponent < 1");
    fuzz_require(law.alpha.value<long double>() >= 1 && law.beta.value<long double>() >= 1,
                 "a validated law's exponent rounds below 1: " + law.describe());
    if (!law.alpha.is_rational() || !law.beta.is_rational()) return;
    const viscor::exponent_multiples m = law.multiples();
    const __int128 Q = m.Q;
    fuzz_require(Q > 0 && Q % law.alpha.denominator() == 0 && Q % law.beta.denominator() == 0,
                 "Q is not a common multiple of the denominators: " + law.describe());
    fuzz_require(__int128(m.Q_alpha) * law.alpha.denominator() == __int128(law.alpha.numerator()) * Q,
                 "Q alpha != Q * alpha: " + law.describe());
    fuzz_require(__int128(m.Q_beta) * law.beta.denominator() == __int128(law.beta.numerator()) * Q,
                 "Q beta != Q * beta: " + law.describe());
  });
  return 0;
}
