// Chebyshev interpolation on [-1, 1] (first-kind points) and Clenshaw
// evaluation in 1-D and 2-D: the building block of the CoR surrogates.
// Evaluation is double only and allocation-free; the coefficients are computed
// once, in long double, when a surrogate is built.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace viscor::surrogate {

/// The n Chebyshev points of the first kind, x_k = cos(pi (k + 1/2) / n), k = 0..n-1
/// (they never include the end points, so a fit never evaluates its function there).
inline std::vector<long double> chebyshev_points(int n) {
  std::vector<long double> x(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) x[static_cast<std::size_t>(k)] = std::cos(std::numbers::pi_v<long double> * (k + 0.5L) / n);
  return x;
}

/// cos(pi j (k + 1/2) / n): T_j at the k-th first-kind point.
inline long double chebyshev_t_at_point(int j, int k, int n) {
  return std::cos(std::numbers::pi_v<long double> * j * (k + 0.5L) / n);
}

/// Coefficients c_j (j < n) of the degree n-1 interpolant sum_j c_j T_j through
/// values f_k at the first-kind points (discrete cosine transform).
inline std::vector<double> chebyshev_coefficients_1d(const std::vector<long double>& f) {
  const int n = static_cast<int>(f.size());
  std::vector<double> c(f.size());
  for (int j = 0; j < n; ++j) {
    long double s = 0;
    for (int k = 0; k < n; ++k) s += f[static_cast<std::size_t>(k)] * chebyshev_t_at_point(j, k, n);
    c[static_cast<std::size_t>(j)] = static_cast<double>(s * (j == 0 ? 1.0L : 2.0L) / n);
  }
  return c;
}

/// 2-D version: f[k * n + l] = f(x_k, y_l); returns c[i * n + j], the coefficient of T_i(x) T_j(y).
inline std::vector<double> chebyshev_coefficients_2d(const std::vector<long double>& f, int n) {
  const std::size_t N = static_cast<std::size_t>(n);
  std::vector<long double> t(N * N);  // t[j * n + k] = T_j(x_k)
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) t[static_cast<std::size_t>(j) * N + static_cast<std::size_t>(k)] = chebyshev_t_at_point(j, k, n);
  // Transform along y, then along x.
  std::vector<long double> half(N * N);  // half[k * n + j] = sum_l f[k][l] T_j(y_l)
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t j = 0; j < N; ++j) {
      long double s = 0;
      for (std::size_t l = 0; l < N; ++l) s += f[k * N + l] * t[j * N + l];
      half[k * N + j] = s * (j == 0 ? 1.0L : 2.0L) / n;
    }
  std::vector<double> c(N * N);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      long double s = 0;
      for (std::size_t k = 0; k < N; ++k) s += half[k * N + j] * t[i * N + k];
      c[i * N + j] = static_cast<double>(s * (i == 0 ? 1.0L : 2.0L) / n);
    }
  return c;
}

/// sum_{j < n} c[j] T_j(x) by Clenshaw's recurrence.
inline double clenshaw(const double* c, int n, double x) noexcept {
  const double two_x = 2 * x;
  double b1 = 0, b2 = 0;
  for (int j = n - 1; j >= 1; --j) {
    const double b0 = std::fma(two_x, b1, c[j] - b2);
    b2 = b1;
    b1 = b0;
  }
  return std::fma(x, b1, c[0] - b2);
}

/// sum_{i, j < n} c[i * n + j] T_i(x) T_j(y): n Clenshaw sums in y (independent,
/// so they pipeline), then one in x.
template <int N>
inline double clenshaw_2d(const double* c, double x, double y) noexcept {
  double a[N];
  const double two_y = 2 * y;
  double b1[N] = {}, b2[N] = {};
  for (int j = N - 1; j >= 1; --j)
    for (int i = 0; i < N; ++i) {
      const double b0 = std::fma(two_y, b1[i], c[i * N + j] - b2[i]);
      b2[i] = b1[i];
      b1[i] = b0;
    }
  for (int i = 0; i < N; ++i) a[i] = std::fma(y, b1[i], c[i * N] - b2[i]);
  return clenshaw(a, N, x);
}

/// Run-time order: dispatches to the compiled orders, else a generic loop.
inline double clenshaw_2d(const double* c, int n, double x, double y) noexcept {
  switch (n) {
    case 8: return clenshaw_2d<8>(c, x, y);
    case 10: return clenshaw_2d<10>(c, x, y);
    case 12: return clenshaw_2d<12>(c, x, y);
    case 14: return clenshaw_2d<14>(c, x, y);
    case 16: return clenshaw_2d<16>(c, x, y);
    default: break;
  }
  double a[64];
  for (int i = 0; i < n && i < 64; ++i) a[i] = clenshaw(c + static_cast<std::ptrdiff_t>(i) * n, n, y);
  return clenshaw(a, n, x);
}

}  // namespace viscor::surrogate
