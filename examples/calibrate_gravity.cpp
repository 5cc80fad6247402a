// The damping of a real bead from a measured CoR, with and without the load:
// the report's 8 mm steel bead (Kuwabara-Kono), e = 0.893 measured at 0.01 m/s.
#include <viscor/viscor.hpp>

#include <iostream>

int main() {
  const viscor::contact_law law = viscor::law_by_name("kuwabara_kono");
  const double m = 2.05e-3, k = 6.9716e9, v0 = 0.01, force = 0, e = 0.893;  // SI units
  const auto with_gravity = viscor::calibrate_gamma0<double>(law, m, k, v0, 9.8, force, e);
  const auto without = viscor::calibrate_gamma0<double>(law, m, k, v0, 0.0, force, e);
  std::cout << "gamma0 = " << with_gravity.gamma0 << " under gravity, " << without.gamma0
            << " without: ignoring the load moves it by " << 100 * (without.gamma0 / with_gravity.gamma0 - 1)
            << " %\n";
  return with_gravity.gamma0 < without.gamma0 ? 0 : 1;
}
