// Radau IIA collocation (Hairer and Wanner, "Solving ODEs II", sec. IV.5 and IV.8):
// viscor's stiff integrator, for the creeping phase of strongly damped impacts
// (issue 18 item 8), where explicit steps are bounded by the fast damping time while
// the motion itself is slow. s stages, order 2s - 1, stiffly accurate and L-stable:
// the fast mode is damped however long the step, so the step follows the slow motion.
//
// The tableau is computed in Real when the integrator is built, so the order can
// follow the working precision: the nodes c_i are the zeros of P_s(2c-1) - P_{s-1}(2c-1)
// (c_s = 1), a_ij = int_0^{c_i} l_j (l_j the Lagrange basis on the nodes) by s-point
// Gauss-Legendre quadrature, which is exact for it. Zeros are bracketed on a grid in
// theta = arccos x and refined by bisection to a width of eps.
// A step solves the collocation equations Z_i = h sum_j a_ij f(y0 + Z_j) by simplified
// Newton (one LU of I - h A (x) J per step, J the Jacobian at the step's start). The
// error is estimated by step doubling: the step is taken as one step of h and as two of
// h/2, the two must agree to the tolerance, and the two half steps are kept.
#pragma once

#include <viscor/core/real_types.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace viscor {

namespace detail {

/// P_n(x) and P_{n-1}(x) (n >= 1) by the three-term recurrence.
template <class Real>
void legendre_pair(int n, const Real& x, Real& pn, Real& pn_minus_1) {
  Real p0 = 1, p1 = x;
  for (int k = 1; k < n; ++k) {
    Real p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
    p0 = p1;
    p1 = p2;
  }
  pn = p1;
  pn_minus_1 = p0;
}

/// The zeros in (-1, 1) of q, a polynomial of degree <= n whose zeros there are
/// simple, in increasing order: sign changes on a grid of 16 n + 1 points in theta,
/// then bisection in x to an absolute width of eps.
template <class Real, class Q>
std::vector<Real> zeros_in_open_interval(int n, Q q) {
  using std::cos;
  const Real pi = boost::math::constants::pi<Real>();
  const int grid = 16 * n;
  std::vector<Real> zeros;
  Real x_prev = cos(pi * Real(grid - 1) / grid), q_prev = q(x_prev);  // near -1
  for (int k = grid - 2; k >= 1; --k) {
    const Real x = cos(pi * Real(k) / grid), qx = q(x);
    if ((q_prev < 0) != (qx < 0) || qx == 0) {
      Real lo = x_prev, hi = x, q_lo = q_prev;
      for (;;) {
        // NOTE: to an absolute width of eps (the zeros lie in (-1, 1)): a relative
        // test would halve on towards a zero at x = 0 through the whole exponent range.
        if (!(hi - lo > epsilon<Real>())) break;
        const Real mid = (lo + hi) / 2;
        const Real q_mid = q(mid);
        if ((q_mid < 0) == (q_lo < 0) && q_mid != 0) {
          lo = mid, q_lo = q_mid;
        } else {
          hi = mid;
        }
      }
      zeros.push_back(qx == 0 ? x : hi);
    }
    x_prev = x, q_prev = qx;
  }
  return zeros;
}

/// The Radau IIA tableau with s stages: nodes c (c_s = 1) and matrix a (row-major).
template <class Real>
struct radau_tableau {
  int s;
  std::vector<Real> c, a;

  explicit radau_tableau(int stages) : s(stages), c(static_cast<std::size_t>(stages)), a(c.size() * c.size()) {
    // Nodes on [-1, 1]: the zeros of P_s - P_{s-1} (all in (-1, 1), and x = 1).
    auto radau = [&](const Real& x) -> Real {
      Real pn, pn1;
      legendre_pair(s, x, pn, pn1);
      return pn - pn1;
    };
    std::vector<Real> x = zeros_in_open_interval<Real>(s, radau);
    x.push_back(Real(1));
    if (static_cast<int>(x.size()) != s) throw std::logic_error("radau_tableau: wrong number of Radau nodes");
    for (int i = 0; i < s; ++i) c[i] = (x[i] + 1) / 2;
    // Gauss-Legendre with s points on [-1, 1]: w = 2 (1 - x^2)/(s P_{s-1}(x))^2.
    auto legendre = [&](const Real& y) -> Real {
      Real pn, pn1;
      legendre_pair(s, y, pn, pn1);
      return pn;
    };
    const std::vector<Real> gx = zeros_in_open_interval<Real>(s, legendre);
    if (static_cast<int>(gx.size()) != s) throw std::logic_error("radau_tableau: wrong number of Gauss nodes");
    std::vector<Real> gw(gx.size());
    for (std::size_t k = 0; k < gx.size(); ++k) {
      Real pn, pn1;
      legendre_pair(s, gx[k], pn, pn1);
      const Real d = s * pn1;
      gw[k] = 2 * (1 - gx[k] * gx[k]) / (d * d);
    }
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        Real sum = 0;
        for (std::size_t k = 0; k < gx.size(); ++k) {
          const Real t = c[i] * (1 + gx[k]) / 2;
          Real l = 1;
          for (int m = 0; m < s; ++m)
            if (m != j) l *= (t - c[m]) / (c[j] - c[m]);
          sum += gw[k] * l;
        }
        a[static_cast<std::size_t>(i * s + j)] = c[i] / 2 * sum;
      }
  }
};

}  // namespace detail

/// Radau IIA with adaptive step (step doubling) for an autonomous system of N
/// components: f(y, dy) returns false outside its domain; jacobian(y, J) fills the
/// N x N Jacobian J[i][j] = d f_i / d y_j.
template <class Real, std::size_t N>
class radau_integrator {
 public:
  using state = std::array<Real, N>;
  using matrix = std::array<std::array<Real, N>, N>;

  /// s stages (order 2s - 1); tolerance: the scaled error allowed per step.
  radau_integrator(int stages, const Real& tolerance) : m_tab(stages), m_tol(tolerance) {}

  /// The number of stages s (order 2s - 1).
  int stages() const { return m_tab.s; }
  /// The scaled error estimate of the last step tried.
  const Real& last_error() const { return m_error; }

  /// One step from y over h (> 0 or < 0), scales[i] > 0 the size of component i that
  /// the tolerance is relative to. Accepted: y holds the new state, `taken` the step,
  /// h the next trial step; returns true. Rejected: y unchanged, h shortened, false.
  template <class F, class Jac>
  bool try_step(F& f, Jac& jacobian, state& y, Real& h, const state& scales, Real& taken) {
    using std::abs;
    using std::pow;
    state full, half, two_halves;
    const Real h2 = h / 2;
    bool ok = collocate(f, jacobian, y, h, full) && collocate(f, jacobian, y, h2, half) &&
              collocate(f, jacobian, half, h2, two_halves);
    if (!ok) {
      m_error = 1 / epsilon<Real>();
      h /= 4;
      return false;
    }
    m_error = 0;
    for (std::size_t i = 0; i < N; ++i) {
      const Real d = abs(full[i] - two_halves[i]) / scales[i];
      if (!(d <= m_error)) m_error = d;  // NaN-safe: a NaN difference is the error
    }
    const Real exponent = Real(1) / (m_tab.s + 1);
    if (!(m_error <= m_tol)) {
      Real factor = boost::math::isfinite(m_error) ? Real(pow(m_tol / m_error, exponent) * 4 / 5) : Real(1) / 8;
      if (factor < Real(1) / 8) factor = Real(1) / 8;
      if (factor > Real(1) / 2) factor = Real(1) / 2;
      h *= factor;
      return false;
    }
    y = two_halves;
    taken = h;
    Real factor = m_error == 0 ? Real(4) : Real(pow(m_tol / m_error, exponent) * 4 / 5);
    if (factor > 4) factor = 4;
    if (factor < 1) factor = 1;
    h *= factor;
    return true;
  }

 private:
  // The collocation solution y1 after one step h from y0; false if Newton fails or a
  // stage leaves the domain of f.
  template <class F, class Jac>
  bool collocate(F& f, Jac& jacobian, const state& y0, const Real& h, state& y1) {
    using std::abs;
    const std::size_t s = static_cast<std::size_t>(m_tab.s), n = s * N;
    matrix J;
    jacobian(y0, J);
    state f0;
    if (!f(y0, f0)) return false;
    // M = I - h (A x J), row (i, p), column (j, q): delta - h a_ij J_pq.
    m_lu.assign(n * n, Real(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const Real ha = h * m_tab.a[i * s + j];
        for (std::size_t p = 0; p < N; ++p)
          for (std::size_t q = 0; q < N; ++q) {
            Real& m = m_lu[(i * N + p) * n + (j * N + q)];
            m = -ha * J[p][q];
            if (i == j && p == q) m += 1;
          }
      }
    if (!factor(n)) return false;
    m_Z.assign(n, Real(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t p = 0; p < N; ++p) m_Z[i * N + p] = m_tab.c[i] * h * f0[p];
    std::vector<state> slopes(s);
    state y;
    Real previous = -1;
    const int max_iterations = 16 + binary_digits<Real>() / 8;
    for (int it = 0; it < max_iterations; ++it) {
      for (std::size_t j = 0; j < s; ++j) {
        for (std::size_t p = 0; p < N; ++p) y[p] = y0[p] + m_Z[j * N + p];
        if (!f(y, slopes[j])) return false;
      }
      // residual r = -Z + h A F
      m_r.assign(n, Real(0));
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          Real sum = 0;
          for (std::size_t j = 0; j < s; ++j) sum += m_tab.a[i * s + j] * slopes[j][p];
          m_r[i * N + p] = h * sum - m_Z[i * N + p];
        }
      substitute(n);
      Real size = 0;
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          m_Z[i * N + p] += m_r[i * N + p];
          const Real d = abs(m_r[i * N + p]) / (abs(y0[p]) + abs(m_Z[i * N + p]) + epsilon<Real>());
          if (!(d <= size)) size = d;
        }
      if (!boost::math::isfinite(size)) return false;
      // Converged: corrections below the tolerance, or stalled at the rounding level.
      if (size <= m_tol / 16 || (it >= 2 && size >= previous / 2 && size <= 64 * epsilon<Real>())) {
        for (std::size_t p = 0; p < N; ++p) y1[p] = y0[p] + m_Z[(s - 1) * N + p];  // stiffly accurate: c_s = 1
        return true;
      }
      if (it >= 2 && size > previous) return false;  // diverging: a shorter step
      previous = size;
    }
    return false;
  }

  // LU with partial pivoting of m_lu (n x n) in place, the row permutation in m_pivot.
  bool factor(std::size_t n) {
    using std::abs;
    m_pivot.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t p = k;
      for (std::size_t i = k + 1; i < n; ++i)
        if (abs(m_lu[i * n + k]) > abs(m_lu[p * n + k])) p = i;
      m_pivot[k] = p;
      if (m_lu[p * n + k] == 0) return false;
      if (p != k)
        for (std::size_t j = 0; j < n; ++j) std::swap(m_lu[k * n + j], m_lu[p * n + j]);
      for (std::size_t i = k + 1; i < n; ++i) {
        m_lu[i * n + k] /= m_lu[k * n + k];
        const Real& factor = m_lu[i * n + k];
        if (factor == 0) continue;
        for (std::size_t j = k + 1; j < n; ++j) m_lu[i * n + j] -= factor * m_lu[k * n + j];
      }
    }
    return true;
  }

  // m_r := M^{-1} m_r with the factors of factor().
  void substitute(std::size_t n) {
    // NOTE: factor() swaps whole rows (the multipliers too), so all the row
    // interchanges come first, then the unit lower triangle (as LAPACK's getrs).
    for (std::size_t k = 0; k < n; ++k)
      if (m_pivot[k] != k) std::swap(m_r[k], m_r[m_pivot[k]]);
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t i = k + 1; i < n; ++i) m_r[i] -= m_lu[i * n + k] * m_r[k];
    for (std::size_t k = n; k-- > 0;) {
      for (std::size_t j = k + 1; j < n; ++j) m_r[k] -= m_lu[k * n + j] * m_r[j];
      m_r[k] /= m_lu[k * n + k];
    }
  }

  detail::radau_tableau<Real> m_tab;
  Real m_tol;
  Real m_error = 0;
  std::vector<Real> m_lu, m_Z, m_r;
  std::vector<std::size_t> m_pivot;
};

}  // namespace viscor
