// Chebyshev interpolation on [-1, 1] (first-kind points) and Clenshaw
// evaluation in 1-D and 2-D: the building block of the CoR surrogates.
// Evaluation is double only and allocation-free; the coefficients are computed
// once, in long double, when a surrogate is built.
#pragma once

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

// Hardware fused multiply-add for the evaluation. Every Clenshaw step is one
// std::fma (one rounding per step: the arithmetic the surrogates were verified
// with). Compiled for the x86-64 baseline (no -mfma, the default), std::fma is a
// call into libm, and those calls were 70% of an evaluation (perf, docs/
// performance.md "Surrogates"). On x86 with GCC or Clang the evaluation paths are
// therefore also compiled for AVX2 + FMA (VISCOR_SURROGATE_FAST_PATH) and chosen
// at run time when the CPU has them (cpu_has_fma); fma is exactly rounded either
// way, so both give bit-identical results. Elsewhere, or when the build already
// targets FMA (__FMA__), there is one path.
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__)) && !defined(__FMA__)
#define VISCOR_SURROGATE_FMA_DISPATCH 1
/// Marks a function compiled with the FMA instruction (called only where cpu_has_fma()).
#define VISCOR_SURROGATE_FMA_TARGET [[gnu::target("avx2,fma")]]
/// Marks a helper of the evaluation: inlined, so it is compiled for its caller's target.
#define VISCOR_SURROGATE_INLINE [[gnu::always_inline]] inline
#include <immintrin.h>
#else
#define VISCOR_SURROGATE_FMA_DISPATCH 0
#define VISCOR_SURROGATE_FMA_TARGET
#define VISCOR_SURROGATE_INLINE inline
#endif

namespace viscor::surrogate {

/// Whether the evaluation may take its FMA-compiled path (see VISCOR_SURROGATE_FMA_DISPATCH).
inline bool cpu_has_fma() noexcept {
#if VISCOR_SURROGATE_FMA_DISPATCH
  static const bool has = [] {
    __builtin_cpu_init();  // may run before the CPU model is initialised (a static initialiser)
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return has;
#else
  return false;
#endif
}

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
VISCOR_SURROGATE_INLINE double clenshaw(const double* c, int n, double x) noexcept {
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

/// The same sum with the coefficients stored by columns, t[j * N + i] = c[i * N + j],
/// and the same operations as clenshaw_2d<N> for every row i, so the same result to
/// the last bit. By columns, one step of the N Clenshaw sums in y reads N adjacent
/// coefficients: a few vector loads and fused multiply-adds, where by rows the
/// compiler gathers N scattered numbers per step.
template <int N>
VISCOR_SURROGATE_INLINE double clenshaw_2d_by_columns(const double* t, double x, double y) noexcept {
  double a[N];
  const double two_y = 2 * y;
  double b1[N] = {}, b2[N] = {};
  for (int j = N - 1; j >= 1; --j)
    for (int i = 0; i < N; ++i) {
      const double b0 = std::fma(two_y, b1[i], t[j * N + i] - b2[i]);
      b2[i] = b1[i];
      b1[i] = b0;
    }
  for (int i = 0; i < N; ++i) a[i] = std::fma(y, b1[i], t[i] - b2[i]);
  return clenshaw(a, N, x);
}

#if VISCOR_SURROGATE_FMA_DISPATCH
/// clenshaw_2d_by_columns<N> in AVX2 vectors of 4 rows, for N a multiple of 4: the
/// same operations per row (a vector fma is 4 exactly rounded fmas), so the same
/// result to the last bit. Written with intrinsics because the compiler vectorizes
/// the plain loop only where it is not inlined into a loop (inlined, it ran at 75 ns
/// instead of 16). Call it only from code compiled for FMA (cpu_has_fma()).
// NOTE: not always_inline: the helpers that call it are compiled for the baseline
// too (where it would not inline); inside evaluate_with_fma the compiler inlines it.
template <int N>
VISCOR_SURROGATE_FMA_TARGET inline double clenshaw_2d_by_columns_avx2(const double* t, double x, double y) noexcept {
  static_assert(N % 4 == 0);
  constexpr int V = N / 4;
  const __m256d two_y = _mm256_set1_pd(2 * y);
  __m256d b1[V], b2[V];
  for (int v = 0; v < V; ++v) b1[v] = b2[v] = _mm256_setzero_pd();
  for (int j = N - 1; j >= 1; --j)
    for (int v = 0; v < V; ++v) {
      const __m256d c = _mm256_loadu_pd(t + j * N + 4 * v);
      const __m256d b0 = _mm256_fmadd_pd(two_y, b1[v], _mm256_sub_pd(c, b2[v]));
      b2[v] = b1[v];
      b1[v] = b0;
    }
  alignas(32) double a[N];
  const __m256d yv = _mm256_set1_pd(y);
  for (int v = 0; v < V; ++v)
    _mm256_store_pd(a + 4 * v, _mm256_fmadd_pd(yv, b1[v], _mm256_sub_pd(_mm256_loadu_pd(t + 4 * v), b2[v])));
  return clenshaw(a, N, x);
}
#endif

/// Run-time order, coefficients by columns: dispatches to the compiled orders, else a
/// generic loop. WithFma: the AVX2 kernels, for code compiled for FMA only.
template <bool WithFma = false>
VISCOR_SURROGATE_INLINE double clenshaw_2d_by_columns(const double* t, int n, double x, double y) noexcept {
#if VISCOR_SURROGATE_FMA_DISPATCH
  if constexpr (WithFma) {
    switch (n) {
      case 8: return clenshaw_2d_by_columns_avx2<8>(t, x, y);
      case 12: return clenshaw_2d_by_columns_avx2<12>(t, x, y);
      case 16: return clenshaw_2d_by_columns_avx2<16>(t, x, y);
      default: break;
    }
  }
#endif
  switch (n) {
    case 8: return clenshaw_2d_by_columns<8>(t, x, y);
    case 10: return clenshaw_2d_by_columns<10>(t, x, y);
    case 12: return clenshaw_2d_by_columns<12>(t, x, y);
    case 14: return clenshaw_2d_by_columns<14>(t, x, y);
    case 16: return clenshaw_2d_by_columns<16>(t, x, y);
    default: break;
  }
  double a[64];
  const double two_y = 2 * y;
  for (int i = 0; i < n && i < 64; ++i) {  // row i: Clenshaw in y, as clenshaw() does
    double b1 = 0, b2 = 0;
    for (int j = n - 1; j >= 1; --j) {
      const double b0 = std::fma(two_y, b1, t[static_cast<std::ptrdiff_t>(j) * n + i] - b2);
      b2 = b1;
      b1 = b0;
    }
    a[i] = std::fma(y, b1, t[i] - b2);
  }
  return clenshaw(a, n, x);
}

}  // namespace viscor::surrogate
