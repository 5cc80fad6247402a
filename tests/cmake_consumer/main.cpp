// Uses the installed viscor: the exact linear CoR at g = 0 is exp(-xi pi/omega).
#include <viscor/viscor.hpp>

#include <cmath>
#include <iostream>

int main() {
  const double gamma = 0.2, xi = gamma / 2, expected = std::exp(-xi * M_PI / std::sqrt(1 - xi * xi));
  const auto r = viscor::exact_cor(viscor::law_by_name("linear"), gamma, 0.0);
  std::cout << "consumer: e = " << r->e << " (viscor " << VISCOR_VERSION << ")\n";
  return r && std::abs(r->e - expected) < 1e-14 ? 0 : 1;
}
