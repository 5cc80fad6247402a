// Dense LU with partial pivoting for the Newton matrices of the implicit integrators
// (radau_integrator.hpp, lobatto_integrator.hpp), one code for the working type and
// for the double rounding of the matrix. The only integrator code the Taylor and GBS
// solvers share (docs/architecture.md): it decides how fast their simplified Newton
// iterations converge, not what to, since each computes its own residual and its own
// convergence test (a wrong factor costs iterations or a shorter step, not digits).
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace viscor::detail {

/// LU with partial pivoting of the n x n row-major matrix a, in place; the row
/// interchanges in pivot (row k was swapped with row pivot[k]). False if a pivot is 0
/// or not finite.
template <class T>
bool lu_factor(std::vector<T>& a, std::vector<std::size_t>& pivot, std::size_t n) {
  using std::abs;
  pivot.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (abs(a[i * n + k]) > abs(a[p * n + k])) p = i;
    pivot[k] = p;
    if (!(a[p * n + k] != 0) || !boost::math::isfinite(a[p * n + k])) return false;
    if (p != k)
      for (std::size_t j = 0; j < n; ++j) std::swap(a[k * n + j], a[p * n + j]);
    for (std::size_t i = k + 1; i < n; ++i) {
      a[i * n + k] /= a[k * n + k];
      const T& l = a[i * n + k];
      if (l == 0) continue;
      for (std::size_t j = k + 1; j < n; ++j) a[i * n + j] -= l * a[k * n + j];
    }
  }
  return true;
}

/// r := M^{-1} r with the factors of lu_factor. NOTE: lu_factor swaps whole rows (the
/// multipliers too), so all the interchanges come first, then the unit lower
/// triangle (as LAPACK's getrs).
template <class T>
void lu_solve(const std::vector<T>& a, const std::vector<std::size_t>& pivot, std::vector<T>& r, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k)
    if (pivot[k] != k) std::swap(r[k], r[pivot[k]]);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = k + 1; i < n; ++i) r[i] -= a[i * n + k] * r[k];
  for (std::size_t k = n; k-- > 0;) {
    for (std::size_t j = k + 1; j < n; ++j) r[k] -= a[k * n + j] * r[j];
    r[k] /= a[k * n + k];
  }
}

}  // namespace viscor::detail
