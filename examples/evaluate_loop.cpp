// e to 1e-6 for 1,000 impacts of one law, as a DEM code would ask for it: the
// evaluator builds the per-law constants once; every result carries its bound.
#include <viscor/viscor.hpp>

#include <algorithm>
#include <iostream>

int main() {
  const viscor::evaluator<double> evaluate(viscor::law_by_name("hertz_linear_damping"));
  double worst = 0;
  for (int i = 0; i < 1000; ++i) {
    const double gamma = 1e-3 + 1e-4 * i, g = 0.1;
    const viscor::evaluation<double> r = evaluate(gamma, g, 1e-6);
    worst = std::max(worst, r.bound);
  }
  std::cout << "1000 impacts, largest empirical error bound " << worst << "\n";
  return worst <= 1e-6 ? 0 : 1;
}
