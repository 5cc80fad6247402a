// Measures the error of the Chebyshev-Beta approximation (report eqs. 48-53) of
// M_{alpha,beta}(theta), J_{alpha,beta}(theta) against the independent quadrature of
// integrals.hpp, as a function of the order n and of the scalar type the scheme is
// evaluated in. Writes the table of docs/chebyshev_order.md to stdout.
//
// Build and run (from the repository root, after configuring build-dir):
//   g++ -std=gnu++20 -O2 -Iinclude -I<build-dir>/include tools/chebyshev_order.cpp \
//       -o chebyshev_order -lmpfr -lgmp -lquadmath && ./chebyshev_order
#include <viscor/approx/chebyshev_beta.hpp>
#include <viscor/approx/integrals.hpp>

#include <cstdio>
#include <vector>

using namespace viscor;
using reference_real = quad;  // 34 digits: enough to see errors down to 1e-30

struct grid_point {
  reference_real beta, theta, m, j;
};

template <class Real>
std::pair<double, double> max_errors(const std::vector<grid_point>& grid, const Real& alpha, int n) {
  const chebyshev_beta<Real> scheme(n);
  double worst_m = 0, worst_j = 0;
  for (const auto& p : grid) {
    const auto approx = scheme.approximate(alpha, Real(p.beta), Real(p.theta));
    using std::abs;
    const reference_real em = abs(reference_real(approx.m) - p.m) / p.m;
    const reference_real ej = abs(reference_real(approx.j) - p.j) / p.j;
    worst_m = std::max(worst_m, em.convert_to<double>());
    worst_j = std::max(worst_j, ej.convert_to<double>());
  }
  return {worst_m, worst_j};
}

int main() {
  const reference_real alpha = reference_real(3) / 2;
  std::vector<grid_point> grid;
  for (int b = 4; b <= 16; ++b)        // beta = 1, 1.25, ..., 4
    for (int t = 0; t <= 100; ++t) {   // theta = 0, 0.01, ..., 1
      grid_point p;
      p.beta = reference_real(b) / 4;
      p.theta = reference_real(t) / 100;
      p.m = m_integral(alpha, p.beta, p.theta);
      p.j = j_integral(alpha, p.beta, p.theta);
      grid.push_back(p);
    }
  std::printf("| n | M: double | M: long double | M: float128 | M: mpfr 50 | J: double | J: mpfr 50 |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int n : {1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31, 35, 41, 51, 61, 81, 101}) {
    const auto d = max_errors<double>(grid, 1.5, n);
    const auto ld = max_errors<long double>(grid, 1.5L, n);
    const auto q = max_errors<quad>(grid, quad(3) / 2, n);
    const auto m = max_errors<mpfr_50>(grid, mpfr_50(3) / 2, n);
    std::printf("| %d | %.2e | %.2e | %.2e | %.2e | %.2e | %.2e |\n", n, d.first, ld.first, q.first, m.first,
                d.second, m.second);
    std::fflush(stdout);
  }
}
