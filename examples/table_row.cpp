// One row of a certified reference table (what `viscor table` writes per grid
// point): Tsuji at gamma = 0.01, g = 0.05, 40 working digits.
#include <viscor/viscor.hpp>

#include <iostream>

int main() {
  viscor::scoped_precision precision(40);
  viscor::table_settings settings;
  settings.digits = 40;
  using Real = viscor::mpfr_real;
  const auto r = viscor::evaluate_point<Real>(viscor::law_by_name("tsuji"), Real("0.01"), Real("0.05"), settings);
  const int d = r.certified_digits;
  std::cout << "tsuji,0.01,0.05," << to_string(r.outcome) << "," << viscor::rounded_decimal(r.e, d) << ","
            << viscor::rounded_decimal(r.one_minus_e, d) << "," << d << "\n";
  return r.certified_digits >= 30 ? 0 : 1;
}
