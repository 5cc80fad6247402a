// A certified CoR at 50 digits: Kuwabara-Kono, gamma = 0.05, g = 1.
#include <viscor/viscor.hpp>

#include <iostream>

int main() {
  viscor::scoped_precision precision(50);  // mpfr_real carries 50 decimal digits in this scope
  const viscor::contact_law law = viscor::law_by_name("kuwabara_kono");
  const auto c = viscor::certify<viscor::mpfr_real>(law, viscor::mpfr_real("0.05"), viscor::mpfr_real(1));
  std::cout << "e = " << viscor::to_decimal_string(c.e, c.certified_digits) << " (" << c.certified_digits
            << " certified digits)\n";
  return c.outcome_certified && c.certified_digits >= 40 ? 0 : 1;
}
