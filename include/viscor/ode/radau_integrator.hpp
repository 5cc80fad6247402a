// Radau IIA collocation (Hairer and Wanner, "Solving ODEs II", sec. IV.5 and IV.8):
// the Taylor solver's stiff integrator, for the creep of strongly damped impacts, where
// explicit steps are bounded by the fast damping time while the motion itself is slow.
// s stages, order 2s - 1, stiffly accurate and L-stable: the fast mode is damped however
// long the step, so the step follows the slow motion.
//
// The tableau is computed in Real when the integrator is built, so the order can
// follow the working precision: the nodes c_i are the zeros of P_s(2c-1) - P_{s-1}(2c-1)
// (c_s = 1), a_ij = int_0^{c_i} l_j (l_j the Lagrange basis on the nodes) by s-point
// Gauss-Legendre quadrature, which is exact for it. Zeros are bracketed on a grid in
// theta = arccos x and refined by bisection to a width of eps.
//
// Operations, named as in lobatto_integrator.hpp (the GBS solver's, written apart):
// try_step (step doubling: one step of h and two of h/2 must agree to the tolerance;
// the two halves are kept), fixed_step (one step, no error control), solve_stages
// (the stage equations Z_i = h sum_j a_ij f(y0 + Z_j) by simplified Newton, one LU of
// I - h A (x) J per solve, J the Jacobian at the step's start), predict (first guesses
// for the halves' stages), newton, factor/substitute (LU in Real) and
// factor_low/substitute_low (LU in double). Deliberate differences from Lobatto IIIC:
// the unknowns are the increments Z_i = Y_i - y0, not the stage values; order 2s - 1,
// so the step factor is (tol/err)^(1/(s+1)) (safety 4/5, growth at most 4); up to four
// matrix refreshes per solve.
//
// Most of a creep's time is in the Real LU and its substitutions (docs/performance.md).
// Three things make it cheap without changing what is computed:
// - Where Real is wider than long double, the iteration matrix is factored in double
//   (in the unknowns scaled by |y0|; double, not x87 long double, which is several
//   times slower): the residual is still evaluated in Real, and the double solve only
//   gives the correction (iterative refinement), so Newton converges to the same
//   collocation solution, at a rate ~ cond(M) eps_double per iteration on top of
//   the simplified Newton's own. If it does not contract (or the matrix does not fit
//   double's range), the stages are solved again with the LU in Real.
// - In that double path, where simplified Newton contracts slowly (a correction
//   shrinking by less than 1e-6: J changes over a long step), the matrix is rebuilt
//   from the Jacobians at the current stages (Newton's own matrix, quadratic).
// - The two half steps start Newton from the full step's collocation polynomial
//   (interpolated at their nodes: degree s through 0 and the stages), not from the
//   explicit first-order guess, which saves most of their iterations.
#pragma once

#include <viscor/core/real_types.hpp>
#include <viscor/ode/detail/dense_lu.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>

#include <array>
#include <cmath>
#include <limits>
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
    // The collocation polynomial of a step, Z(t) = sum_j l_j(t) Z_j with l_j the
    // Lagrange basis on the nodes {0, c_1, .., c_s} (Z(0) = 0), at the stages of the
    // two half steps: first_half[i][j] = l_j(c_i/2), second_half[i][j] =
    // l_j((1 + c_i)/2) - l_j(1/2) (the second half starts from Z(1/2)).
    auto basis = [&](int j, const Real& t) -> Real {
      Real l = t / c[j];  // the factor of node 0
      for (int m = 0; m < s; ++m)
        if (m != j) l *= (t - c[m]) / (c[j] - c[m]);
      return l;
    };
    first_half.resize(a.size());
    second_half.resize(a.size());
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        const std::size_t k = static_cast<std::size_t>(i * s + j);
        first_half[k] = basis(j, Real(c[i] / 2));
        second_half[k] = basis(j, Real((1 + c[i]) / 2)) - basis(j, Real(Real(1) / 2));
      }
  }

  /// Interpolation of a step's stages to the stages of its half steps (row-major s x s).
  std::vector<Real> first_half, second_half;
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
  /// The type the iteration matrix is factored in first (see the header comment).
  using low_real = double;

  /// s stages (order 2s - 1); tolerance: the scaled error allowed per step.
  radau_integrator(int stages, const Real& tolerance) : m_tab(stages), m_tol(tolerance) {}

  /// The number of stages s (order 2s - 1).
  int stages() const { return m_tab.s; }
  /// The scaled error estimate of the last step tried.
  const Real& last_error() const { return m_error; }

  /// Whether the iteration matrix is factored in double first (default: where Real
  /// is wider than long double). False: always in Real (the reference path).
  void set_low_precision_lu(bool on) { m_low_allowed = on; }
  /// Whether stage solves start with the double LU (set_low_precision_lu and Real's width).
  bool low_precision_lu() const {
    return m_low_allowed && binary_digits<Real>() > std::numeric_limits<long double>::digits;
  }
  /// Stage solves done with the double LU.
  std::size_t low_precision_solves() const { return m_low_solves; }
  /// Stage solves done with the LU in Real (the reference path, or after the double one failed).
  std::size_t real_precision_solves() const { return m_real_solves; }
  /// Newton iterations over all stage solves.
  std::size_t newton_iterations() const { return m_iterations; }
  /// Matrices rebuilt from the Jacobians at the stages (slow contraction).
  std::size_t matrix_refreshes() const { return m_refreshes; }

  /// One step from y over h (> 0 or < 0), scales[i] > 0 the size of component i that
  /// the tolerance is relative to. Accepted: y holds the new state, `taken` the step,
  /// h the next trial step; returns true. Rejected: y unchanged, h shortened, false.
  template <class F, class Jac>
  bool try_step(F& f, Jac& jacobian, state& y, Real& h, const state& scales, Real& taken) {
    using std::abs;
    using std::pow;
    state full, half, two_halves;
    const Real h2 = h / 2;
    bool ok = solve_stages(f, jacobian, y, h, full, nullptr);
    if (ok) {
      // the half steps start from the full step's collocation polynomial
      predict(m_tab.first_half, m_guess_first);
      predict(m_tab.second_half, m_guess_second);
      ok = solve_stages(f, jacobian, y, h2, half, &m_guess_first) &&
           solve_stages(f, jacobian, half, h2, two_halves, &m_guess_second);
    }
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

  /// One collocation step of h from y0 alone (no error control), into y1; false if
  /// Newton fails or a stage leaves the domain. For tests of the two LU paths.
  template <class F, class Jac>
  bool fixed_step(F& f, Jac& jacobian, const state& y0, const Real& h, state& y1) {
    return solve_stages(f, jacobian, y0, h, y1, nullptr);
  }

 private:
  enum class newton_end { converged, domain, no_contraction };

  // guess := P Z, P an s x s interpolation matrix of the tableau, Z the last stages.
  void predict(const std::vector<Real>& P, std::vector<Real>& guess) const {
    const std::size_t s = static_cast<std::size_t>(m_tab.s);
    guess.assign(s * N, Real(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const Real& w = P[i * s + j];
        for (std::size_t p = 0; p < N; ++p) guess[i * N + p] += w * m_Z[j * N + p];
      }
  }

  // The collocation solution y1 after one step h from y0; false if Newton fails or a
  // stage leaves the domain of f. guess: the starting stages Z (nullptr: c_i h f(y0)).
  template <class F, class Jac>
  bool solve_stages(F& f, Jac& jacobian, const state& y0, const Real& h, state& y1, const std::vector<Real>* guess) {
    const std::size_t s = static_cast<std::size_t>(m_tab.s), n = s * N;
    matrix J;
    jacobian(y0, J);
    state f0;
    if (!f(y0, f0)) return false;
    auto start = [&] {
      if (guess) {
        m_Z = *guess;
      } else {
        m_Z.assign(n, Real(0));
        for (std::size_t i = 0; i < s; ++i)
          for (std::size_t p = 0; p < N; ++p) m_Z[i * N + p] = m_tab.c[i] * h * f0[p];
      }
    };
    m_stage_j.assign(1, J);
    if (low_precision_lu() && factor_low(m_stage_j, h, y0, n)) {
      start();
      // Where simplified Newton contracts slowly (J varies over the step), the matrix
      // is rebuilt from the Jacobians at the current stages (Newton's own matrix).
      auto refresh = [&]() -> bool {
        m_stage_j.resize(s);
        state y;
        for (std::size_t j = 0; j < s; ++j) {
          for (std::size_t p = 0; p < N; ++p) y[p] = y0[p] + m_Z[j * N + p];
          jacobian(y, m_stage_j[j]);
        }
        return factor_low(m_stage_j, h, y0, n);
      };
      const newton_end end = newton(f, y0, h, y1, [&] { substitute_low(n); }, refresh, 4);
      if (end == newton_end::converged) {
        ++m_low_solves;
        return true;
      }
      if (end == newton_end::domain) return false;
      // no contraction with the double LU: redo the collocation in Real
    }
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
    start();
    const newton_end end = newton(f, y0, h, y1, [&] { substitute(n); }, [] { return true; }, 0);
    if (end == newton_end::converged) ++m_real_solves;
    return end == newton_end::converged;
  }

  // Simplified Newton from the stages in m_Z; solve() replaces m_r by M^{-1} m_r.
  // refresh(): rebuild and factor the matrix at the current stages (false: failed);
  // used at most `refreshes` times, when a correction shrank by less than 1e-6.
  template <class F, class Solve, class Refresh>
  newton_end newton(F& f, const state& y0, const Real& h, state& y1, Solve solve, Refresh refresh,
                    int refreshes) {
    using std::abs;
    const std::size_t s = static_cast<std::size_t>(m_tab.s), n = s * N;
    m_slopes.resize(s);
    state y;
    Real previous = -1;
    const int max_iterations = 16 + binary_digits<Real>() / 8;
    const Real eps = epsilon<Real>();
    for (int it = 0; it < max_iterations; ++it) {
      ++m_iterations;
      for (std::size_t j = 0; j < s; ++j) {
        for (std::size_t p = 0; p < N; ++p) y[p] = y0[p] + m_Z[j * N + p];
        if (!f(y, m_slopes[j])) return newton_end::domain;
      }
      // residual r = -Z + h A F
      m_r.resize(n);
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          Real sum = 0;
          for (std::size_t j = 0; j < s; ++j) sum += m_tab.a[i * s + j] * m_slopes[j][p];
          m_r[i * N + p] = h * sum - m_Z[i * N + p];
        }
      solve();
      Real size = 0;
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          m_Z[i * N + p] += m_r[i * N + p];
          // NOTE: relative to the component's own size, with no absolute floor: the
          // creep's u and v fall far below eps (Kuwabara-Kono, gamma = 1e10, g = 0:
          // u ~ 1e-34, v ~ 1e-44), and "+ eps" took unconverged stages for converged
          // (the step-doubling estimate then held the steps at 5e5: 399,547 steps).
          const Real scale = abs(y0[p]) + abs(m_Z[i * N + p]);
          const Real d = scale > 0 ? Real(abs(m_r[i * N + p]) / scale) : Real(abs(m_r[i * N + p]));
          if (!(d <= size)) size = d;
        }
      if (!boost::math::isfinite(size)) return newton_end::no_contraction;
      // Converged: corrections below the tolerance, or at the rounding level and either
      // stalled there or shrinking at least 64-fold (then what is left is about an
      // ulp). NOTE: a laxer early stop (twofold) left noise that the step-doubling
      // estimate at its 16-ulp floor took for error.
      if (size <= m_tol / 16 || (it >= 2 && size >= previous / 2 && size <= 64 * eps) ||
          (it >= 1 && size <= previous / 64 && size <= 64 * eps)) {
        for (std::size_t p = 0; p < N; ++p) y1[p] = y0[p] + m_Z[(s - 1) * N + p];  // stiffly accurate: c_s = 1
        return newton_end::converged;
      }
      if (it >= 2 && size > previous) return newton_end::no_contraction;  // diverging: a shorter step
      if (refreshes > 0 && previous > 0 && size > previous * Real(1e-6)) {
        --refreshes;
        ++m_refreshes;
        if (!refresh()) return newton_end::no_contraction;
      }
      previous = size;
    }
    return newton_end::no_contraction;
  }

  bool factor(std::size_t n) { return detail::lu_factor(m_lu, m_pivot, n); }
  void substitute(std::size_t n) { detail::lu_solve(m_lu, m_pivot, m_r, n); }

  // M = I - h (A x J) rounded to double and factored as factor() does; false if an
  // entry does not fit double's range or a pivot vanishes (then the Real LU).
  // The matrix is that of the scaled unknowns Z_ip / w_p, w_p = |y0_p| (1 where 0):
  // D^-1 M D with D = diag(w), whose rounding in double does not let the large
  // components (u against v in the creep) swamp the small ones.
  // Js: one Jacobian for every stage (size 1), or the Jacobian at each stage (size s:
  // then M is the exact Jacobian of the collocation equations, column block j at
  // stage j).
  bool factor_low(const std::vector<matrix>& Js, const Real& h, const state& y0, std::size_t n) {
    using std::abs;
    const std::size_t s = static_cast<std::size_t>(m_tab.s);
    for (std::size_t p = 0; p < N; ++p) {
      const low_real w = static_cast<low_real>(abs(y0[p]));
      m_low_w[p] = std::isfinite(w) && w > 0 ? w : low_real(1);
    }
    m_low.assign(n * n, low_real(0));
    std::vector<std::array<std::array<low_real, N>, N>>& j_low = m_low_j;
    j_low.resize(Js.size());
    for (std::size_t k = 0; k < Js.size(); ++k)
      for (std::size_t p = 0; p < N; ++p)
        for (std::size_t q = 0; q < N; ++q) {
          j_low[k][p][q] = static_cast<low_real>(Js[k][p][q]) * m_low_w[q] / m_low_w[p];
          if (!std::isfinite(j_low[k][p][q])) return false;
        }
    if (m_low_a.size() != s * s) {
      m_low_a.resize(s * s);
      for (std::size_t k = 0; k < s * s; ++k) m_low_a[k] = static_cast<low_real>(m_tab.a[k]);
    }
    const low_real h_low = static_cast<low_real>(h);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        const low_real ha = h_low * m_low_a[i * s + j];
        const auto& jj = j_low[Js.size() == 1 ? 0 : j];
        for (std::size_t p = 0; p < N; ++p)
          for (std::size_t q = 0; q < N; ++q) {
            low_real& m = m_low[(i * N + p) * n + (j * N + q)];
            m = -ha * jj[p][q];
            if (i == j && p == q) m += 1;
            if (!std::isfinite(m)) return false;
          }
      }
    return detail::lu_factor(m_low, m_low_pivot, n);
  }

  // m_r := M^{-1} m_r with the double factors of factor_low(): the residual is
  // rounded to double, solved, and the correction carried back to Real.
  void substitute_low(std::size_t n) {
    m_low_r.resize(n);
    for (std::size_t k = 0; k < n; ++k) m_low_r[k] = static_cast<low_real>(m_r[k]) / m_low_w[k % N];
    detail::lu_solve(m_low, m_low_pivot, m_low_r, n);
    for (std::size_t k = 0; k < n; ++k) m_r[k] = Real(m_low_r[k] * m_low_w[k % N]);
  }

  detail::radau_tableau<Real> m_tab;
  Real m_tol;
  Real m_error = 0;
  std::vector<Real> m_lu, m_Z, m_r, m_guess_first, m_guess_second;
  std::vector<state> m_slopes;
  std::vector<std::size_t> m_pivot;
  bool m_low_allowed = true;
  std::vector<low_real> m_low, m_low_r, m_low_a;
  std::vector<std::size_t> m_low_pivot;
  std::array<low_real, N> m_low_w{};
  std::vector<std::array<std::array<low_real, N>, N>> m_low_j;
  std::vector<matrix> m_stage_j;
  std::size_t m_low_solves = 0, m_real_solves = 0, m_iterations = 0, m_refreshes = 0;
};

}  // namespace viscor
