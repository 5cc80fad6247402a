// Lobatto IIIC (Chipman 1971; Hairer and Wanner, "Solving ODEs II", sec. IV.5): the
// GBS solver's stiff integrator, for the creep of strongly damped impacts. Written apart
// from the Taylor solver's Radau IIA (radau_integrator.hpp) on purpose: the two solvers
// share no integrator code (only the dense LU of the Newton matrix, detail/dense_lu.hpp,
// which sets how fast Newton converges but not what to).
// s stages, order 2s - 2, L-stable and stiffly accurate.
//
// Tableau, computed in Real: nodes c_1 = 0, c_s = 1 and the zeros of P'_{s-1}(2c - 1);
// weights b_j = 1/(s (s-1) P_{s-1}(2 c_j - 1)^2) (Lobatto quadrature on [0, 1]);
// a_i1 = b_1 and, for j >= 2, a_ij = int_0^{c_i} L_j - b_1 L_j(0), L_j the Lagrange
// basis on c_2..c_s (so that row i integrates polynomials of degree s - 2 exactly from
// 0 to c_i); the integrals by (s-1)-point Gauss-Legendre quadrature, exact for them.
//
// Operations, named as in radau_integrator.hpp: try_step (one step of h against two of
// h/2; the halves are kept), fixed_step (one step, no error control), solve_stages (the
// stage values Y_i = y0 + h sum_j a_ij f(Y_j) by Newton's method with the Jacobian at
// the step's start, a fresh LU each step), predict, newton, factor/substitute (LU in
// Real) and factor_low/substitute_low (LU in double). Deliberate differences from Radau
// IIA: the unknowns are the stage values Y_i themselves; the error of a step goes like
// h^s at worst (stage order), so the step factor is (tol/err)^(1/s) (safety 7/8, growth
// at most 3); up to three matrix refreshes per solve; Newton's convergence test counts
// the rounding floor of the terms summed into G (see newton).
//
// Speed, without changing the stage values that are solved for:
// - For a work type wider than long double the Newton matrix is factored in double
//   (G is evaluated in W, only the update comes from the double solve: iterative
//   refinement to the same Y), in the variables scaled by |y0|. The update is
//   trusted while Newton's change shrinks; when it does not, or the matrix is out of
//   double's range, the same stage solve is repeated with the LU in W.
// - On that double path, when Newton's change shrinks by less than 1e6 per iteration
//   (the Jacobian varies over the step), the matrix is made again from the Jacobians
//   at the stage values (the true Newton matrix), at most three times per solve; the
//   first update through a rebuilt matrix is not held against the one before it.
// - Newton for the two half steps starts from the whole step's stages, interpolated
//   (the polynomial of degree s - 1 through (c_j, Y_j)) at the halves' nodes, instead
//   of from y0.
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

/// Legendre values P_0..P_n at x (n >= 0) into p (size n + 1).
template <class Real>
void legendre_table(int n, const Real& x, std::vector<Real>& p) {
  p.resize(static_cast<std::size_t>(n) + 1);
  p[0] = 1;
  if (n >= 1) p[1] = x;
  for (int k = 1; k < n; ++k) p[k + 1] = ((2 * k + 1) * x * p[k] - k * p[k - 1]) / (k + 1);
}

/// Simple zeros of q inside (-1, 1), ascending: bracketed by sign changes of q on
/// 32 n equal steps of the angle theta, x = -cos(theta), then halved to a width of eps.
template <class Real, class Q>
std::vector<Real> bracketed_zeros(int n, Q q) {
  using std::cos;
  const Real pi = boost::math::constants::pi<Real>();
  const int steps = 32 * (n + 1);
  std::vector<Real> out;
  Real a = -cos(pi / steps), qa = q(a);
  for (int k = 2; k < steps; ++k) {
    const Real b = -cos(pi * Real(k) / steps), qb = q(b);
    if (qa == 0) {
      out.push_back(a);
    } else if ((qa < 0) != (qb < 0) && qb != 0) {
      Real lo = a, hi = b;
      const bool lo_negative = qa < 0;
      for (;;) {
        if (!(hi - lo > epsilon<Real>())) break;  // absolute: a zero at x = 0 would never end
        const Real m = (lo + hi) / 2;
        const Real qm = q(m);
        if (qm == 0) {
          lo = hi = m;
          break;
        }
        ((qm < 0) == lo_negative ? lo : hi) = m;
      }
      out.push_back(lo);
    }
    a = b, qa = qb;
  }
  return out;
}

/// The Lobatto IIIC tableau with s >= 2 stages: nodes c, matrix a (row-major).
template <class Real>
struct lobatto_iiic_tableau {
  int s;
  std::vector<Real> c, a;

  explicit lobatto_iiic_tableau(int stages) : s(stages), a(static_cast<std::size_t>(stages * stages)) {
    if (s < 2) throw std::logic_error("lobatto_iiic_tableau: at least 2 stages");
    using std::abs;
    std::vector<Real> p;
    const int n = s - 1;
    // interior nodes on [-1, 1]: zeros of P'_n, i.e. of P_{n-1}(x) - x P_n(x)
    auto dp = [&](const Real& x) -> Real {
      legendre_table(n, x, p);
      return Real(p[static_cast<std::size_t>(n) - 1] - x * p[static_cast<std::size_t>(n)]);
    };
    std::vector<Real> x{Real(-1)};
    if (n >= 2)
      for (const Real& z : bracketed_zeros<Real>(n, dp)) x.push_back(z);
    x.push_back(Real(1));
    if (static_cast<int>(x.size()) != s) throw std::logic_error("lobatto_iiic_tableau: wrong number of nodes");
    c.resize(x.size());
    std::vector<Real> b(x.size());
    for (std::size_t j = 0; j < x.size(); ++j) {
      c[j] = (x[j] + 1) / 2;
      legendre_table(n, x[j], p);
      b[j] = 1 / (Real(s) * Real(n) * p[static_cast<std::size_t>(n)] * p[static_cast<std::size_t>(n)]);
    }
    // (s-1)-point Gauss-Legendre on [-1, 1]: zeros of P_{s-1}, w = 2 (1 - x^2)/((s-1) P_{s-2}(x))^2.
    auto pn = [&](const Real& y) -> Real {
      legendre_table(n, y, p);
      return p[static_cast<std::size_t>(n)];
    };
    const std::vector<Real> gx = bracketed_zeros<Real>(n, pn);
    if (static_cast<int>(gx.size()) != n) throw std::logic_error("lobatto_iiic_tableau: wrong number of Gauss nodes");
    std::vector<Real> gw(gx.size());
    for (std::size_t k = 0; k < gx.size(); ++k) {
      legendre_table(n, gx[k], p);
      const Real d = Real(n) * p[static_cast<std::size_t>(n) - 1];
      gw[k] = 2 * (1 - gx[k] * gx[k]) / (d * d);
    }
    // L_j on the nodes c_2..c_s (indices 1..s-1)
    auto basis = [&](std::size_t j, const Real& t) -> Real {
      Real l = 1;
      for (std::size_t m = 1; m < c.size(); ++m)
        if (m != j) l *= (t - c[m]) / (c[j] - c[m]);
      return l;
    };
    for (std::size_t i = 0; i < c.size(); ++i) {
      a[i * c.size()] = b[0];
      for (std::size_t j = 1; j < c.size(); ++j) {
        Real integral = 0;
        for (std::size_t k = 0; k < gx.size(); ++k) integral += gw[k] * basis(j, Real(c[i] * (1 + gx[k]) / 2));
        a[i * c.size() + j] = c[i] / 2 * integral - b[0] * basis(j, Real(0));
      }
    }
    for (std::size_t i = 0; i < c.size(); ++i) {
      Real row = 0;
      for (std::size_t j = 0; j < c.size(); ++j) row += abs(a[i * c.size() + j]);
      if (row > widest_row) widest_row = row;
    }
    // Lagrange weights on all nodes c_1..c_s at the stage times of the two half
    // steps, in units of the whole step: at c_i/2 (left) and at (1 + c_i)/2 (right).
    first_half.resize(a.size());
    second_half.resize(a.size());
    for (std::size_t i = 0; i < c.size(); ++i)
      for (std::size_t j = 0; j < c.size(); ++j) {
        Real l_left = 1, l_right = 1;
        const Real t_left = c[i] / 2, t_right = (1 + c[i]) / 2;
        for (std::size_t m = 0; m < c.size(); ++m) {
          if (m == j) continue;
          l_left *= (t_left - c[m]) / (c[j] - c[m]);
          l_right *= (t_right - c[m]) / (c[j] - c[m]);
        }
        first_half[i * c.size() + j] = l_left;
        second_half[i * c.size() + j] = l_right;
      }
  }

  /// Weights that carry a step's stages to first guesses for its two half steps (row-major s x s).
  std::vector<Real> first_half, second_half;
  /// max_i sum_j |a_ij|.
  Real widest_row = 0;
};

}  // namespace detail

/// Lobatto IIIC steps with error control for an autonomous system of N components;
/// f(y, dy) is false outside its domain, jacobian(y, J) gives J[i][j] = d f_i/d y_j.
template <class Real, std::size_t N>
class lobatto_integrator {
 public:
  using state = std::array<Real, N>;
  using matrix = std::array<std::array<Real, N>, N>;
  /// The type the Newton matrix is factored in first (double, not x87 long double:
  /// vectorised, and far faster at n = 4s = 84).
  using low_real = double;

  /// s stages (order 2s - 2); tolerance on the scaled error per step.
  lobatto_integrator(int stages, const Real& tolerance) : m_tab(stages), m_tol(tolerance) {}

  /// Whether the Newton matrix is factored in double first (default: where Real is
  /// wider than long double). False: always in Real (the reference path).
  void set_low_precision_lu(bool on) { m_low_allowed = on; }
  /// Whether stage solves start with the double LU (set_low_precision_lu and Real's width).
  bool low_precision_lu() const {
    return m_low_allowed && binary_digits<Real>() > std::numeric_limits<long double>::digits;
  }
  /// Stage solves done with the double LU.
  std::size_t low_precision_solves() const { return m_low_solves; }
  /// Stage solves done with the LU in Real (the reference path, or after the double one failed).
  std::size_t real_precision_solves() const { return m_real_solves; }

  /// A step of h from y, error relative to `scales`. True: y advanced by `taken` = h
  /// and h is the next trial step. False: rejected, y unchanged, h reduced.
  template <class F, class Jac>
  bool try_step(F& f, Jac& jacobian, state& y, Real& h, const state& scales, Real& taken) {
    using std::abs;
    using std::pow;
    state whole, mid, end;
    const Real half = h / 2;
    bool solved = solve_stages(f, jacobian, y, h, whole, nullptr);
    if (solved) {
      predict(m_tab.first_half, m_guess_first);
      predict(m_tab.second_half, m_guess_second);
      solved = solve_stages(f, jacobian, y, half, mid, &m_guess_first) &&
               solve_stages(f, jacobian, mid, half, end, &m_guess_second);
    }
    if (!solved) {
      h /= 4;
      return false;
    }
    Real err = 0;
    for (std::size_t i = 0; i < N; ++i) {
      const Real d = abs(whole[i] - end[i]) / scales[i];
      if (!(d <= err)) err = d;
    }
    const Real root = Real(1) / m_tab.s;  // the error of a step goes like h^(s) at worst (stage order)
    if (!(err <= m_tol)) {
      Real shrink = boost::math::isfinite(err) ? Real(pow(m_tol / err, root) * 7 / 8) : Real(1) / 8;
      if (!(shrink >= Real(1) / 8)) shrink = Real(1) / 8;
      if (shrink > Real(1) / 2) shrink = Real(1) / 2;
      h *= shrink;
      return false;
    }
    y = end;
    taken = h;
    Real grow = err > 0 ? Real(pow(m_tol / err, root) * 7 / 8) : Real(3);
    if (grow > 3) grow = 3;
    if (grow < 1) grow = 1;
    h *= grow;
    return true;
  }

  /// The stage equations of one step of h from y0 solved alone (no error control):
  /// y1 = Y_s. For tests of the two LU paths.
  template <class F, class Jac>
  bool fixed_step(F& f, Jac& jacobian, const state& y0, const Real& h, state& y1) {
    return solve_stages(f, jacobian, y0, h, y1, nullptr);
  }

 private:
  enum class newton_end { converged, domain, no_contraction };

  // out_i = sum_j w_ij Y_j (Y: the stages of the last solve).
  void predict(const std::vector<Real>& w, std::vector<state>& out) const {
    const std::size_t s = m_tab.c.size();
    out.resize(s);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t p = 0; p < N; ++p) {
        Real sum = 0;
        for (std::size_t j = 0; j < s; ++j) sum += w[i * s + j] * m_Y[j][p];
        out[i][p] = sum;
      }
  }

  // Y_i = y0 + h sum_j a_ij f(Y_j); y1 = Y_s (stiffly accurate). False: Newton did not
  // converge, or a stage left the domain. start: the first Y (nullptr: all y0).
  template <class F, class Jac>
  bool solve_stages(F& f, Jac& jacobian, const state& y0, const Real& h, state& y1, const std::vector<state>* start) {
    const std::size_t s = m_tab.c.size(), n = s * N;
    matrix J;
    jacobian(y0, J);
    m_stage_j.assign(1, J);
    if (low_precision_lu() && factor_low(m_stage_j, h, y0, n)) {
      // A slow contraction (the Jacobian varies over the step): the matrix is made
      // again from the Jacobian at each stage value, the true Newton matrix.
      auto refresh = [&]() -> bool {
        m_stage_j.resize(s);
        for (std::size_t j = 0; j < s; ++j) jacobian(m_Y[j], m_stage_j[j]);
        return factor_low(m_stage_j, h, y0, n);
      };
      const newton_end end = newton(f, y0, h, start, [&] { substitute_low(n); }, refresh, 3);
      if (end == newton_end::converged) {
        ++m_low_solves;
        y1 = m_Y[s - 1];
        return true;
      }
      if (end == newton_end::domain) return false;
      // no contraction with the double LU: redo the stage solve in Real
    }
    // Newton matrix for the stage values: I - h (A x J)
    m_lu.assign(n * n, Real(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t p = 0; p < N; ++p) {
        m_lu[(i * N + p) * n + (i * N + p)] = 1;
        for (std::size_t j = 0; j < s; ++j)
          for (std::size_t q = 0; q < N; ++q) m_lu[(i * N + p) * n + (j * N + q)] -= h * m_tab.a[i * s + j] * J[p][q];
      }
    if (!factor(n)) return false;
    if (newton(f, y0, h, start, [&] { substitute(n); }, [] { return true; }, 0) != newton_end::converged) return false;
    ++m_real_solves;
    y1 = m_Y[s - 1];
    return true;
  }

  // Newton on the stage values in m_Y; solve() turns m_r (= -G) into the update.
  // refresh(): a new matrix at the current stages (false: it failed), at most
  // `refreshes` times, when the change did not shrink by 1e6.
  template <class F, class Solve, class Refresh>
  newton_end newton(F& f, const state& y0, const Real& h, const std::vector<state>* start, Solve solve,
                    Refresh refresh, int refreshes) {
    using std::abs;
    const std::size_t s = m_tab.c.size(), n = s * N;
    if (start)
      m_Y = *start;
    else
      m_Y.assign(s, y0);
    m_F.resize(s);
    const int limit = 20 + binary_digits<Real>() / 6;
    const Real eps = epsilon<Real>();
    Real last = -1;
    bool refreshed = false;  // the matrix was made again after the last update
    for (int it = 0; it < limit; ++it) {
      for (std::size_t j = 0; j < s; ++j)
        if (!f(m_Y[j], m_F[j])) return newton_end::domain;
      // G_i = Y_i - y0 - h sum_j a_ij F_j; Newton: M dY = -G
      m_r.resize(n);
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          Real sum = 0;
          for (std::size_t j = 0; j < s; ++j) sum += m_tab.a[i * s + j] * m_F[j][p];
          m_r[i * N + p] = y0[p] + h * sum - m_Y[i][p];
        }
      // The size of the terms summed into G_p, |h| max_j |F_jp| max_i sum_j |a_ij|:
      // G's rounding floor is eps times that. NOTE: without it a component that moves
      // far from a small start (tau in the creep: 0.06 to 2e4 in one step) keeps a
      // relative change above 64 eps at the first stage (c_1 = 0, whose terms cancel),
      // and Newton is declared failed at its rounding floor.
      for (std::size_t p = 0; p < N; ++p) {
        Real big = 0;
        for (std::size_t j = 0; j < s; ++j)
          if (abs(m_F[j][p]) > big) big = abs(m_F[j][p]);
        m_term[p] = abs(h) * big * m_tab.widest_row;
      }
      solve();
      Real change = 0;
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          m_Y[i][p] += m_r[i * N + p];
          // no absolute floor: components far below eps (see radau_integrator.hpp)
          const Real scale = abs(m_Y[i][p]) + abs(y0[p]) + m_term[p];
          const Real d = scale > 0 ? Real(abs(m_r[i * N + p]) / scale) : Real(abs(m_r[i * N + p]));
          if (!(d <= change)) change = d;
        }
      if (!boost::math::isfinite(change)) return newton_end::no_contraction;
      if (change <= m_tol / 32 || (it >= 2 && change >= last / 2 && change <= 64 * eps)) return newton_end::converged;
      // NOTE: not right after a refresh: the first update through the new matrix is
      // about as large as the last one through the old, which barely contracted, and
      // may exceed it (Tsuji, gamma = 1e10, g = -1e-3, 50 digits: 1.7e-7, 1.74e-7,
      // 1.3e-7, 5e-13, ...). Counting that as divergence failed 71 stage solves that
      // converge a few iterations later, and each failure was repeated with the LU in
      // Real (up to 47 iterations) and then with h/4.
      if (it >= 2 && !refreshed && change > last) return newton_end::no_contraction;
      refreshed = false;
      if (refreshes > 0 && it >= 1 && change * 1000000 > last) {
        --refreshes;
        if (!refresh()) return newton_end::no_contraction;
        refreshed = true;
      }
      last = change;
    }
    return newton_end::no_contraction;
  }

  bool factor(std::size_t n) { return detail::lu_factor(m_lu, m_pivot, n); }
  // m_r := M^{-1} m_r through the factors in Real.
  void substitute(std::size_t n) { detail::lu_solve(m_lu, m_pivot, m_r, n); }

  // The Newton matrix I - h (A x J) in low_real, factored by detail::lu_factor
  // (interchanges in m_low_pivot). False when an entry or pivot is not finite or a pivot is 0.
  // Js[0] for every column block, or Js[j] for block j (then the exact Newton matrix).
  bool factor_low(const std::vector<matrix>& Js, const Real& h, const state& y0, std::size_t n) {
    using std::abs;
    const std::size_t s = m_tab.c.size();
    if (m_low_a.empty())
      for (const Real& x : m_tab.a) m_low_a.push_back(static_cast<low_real>(x));
    const low_real hl = static_cast<low_real>(h);
    // In the variables y_p / size_p (size_p = |y0_p|, or 1 at 0): the components'
    // sizes differ by many orders (tau against v in the creep), and unscaled the
    // rounding of the largest would swamp the update of the smallest.
    for (std::size_t p = 0; p < N; ++p) {
      const low_real size = static_cast<low_real>(abs(y0[p]));
      m_low_w[p] = size > 0 && std::isfinite(size) ? size : low_real(1);
    }
    m_low_j.resize(Js.size() * N * N);
    for (std::size_t k = 0; k < Js.size(); ++k)
      for (std::size_t p = 0; p < N; ++p)
        for (std::size_t q = 0; q < N; ++q)
          m_low_j[(k * N + p) * N + q] = static_cast<low_real>(Js[k][p][q]) * (m_low_w[q] / m_low_w[p]);
    m_low.assign(n * n, low_real(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t p = 0; p < N; ++p) {
        low_real* row = &m_low[(i * N + p) * n];
        row[i * N + p] = 1;
        for (std::size_t j = 0; j < s; ++j)
          for (std::size_t q = 0; q < N; ++q) {
            row[j * N + q] -= hl * m_low_a[i * s + j] * m_low_j[((Js.size() == 1 ? 0 : j) * N + p) * N + q];
            if (!std::isfinite(row[j * N + q])) return false;
          }
      }
    return detail::lu_factor(m_low, m_low_pivot, n);
  }

  // m_r := M^{-1} m_r through the double factors of factor_low(): -G rounded to
  // double, the update carried back to Real.
  void substitute_low(std::size_t n) {
    m_low_r.resize(n);
    for (std::size_t r = 0; r < n; ++r) m_low_r[r] = static_cast<low_real>(m_r[r]) / m_low_w[r % N];
    detail::lu_solve(m_low, m_low_pivot, m_low_r, n);
    for (std::size_t i = 0; i < n; ++i) m_r[i] = Real(m_low_r[i] * m_low_w[i % N]);
  }

  detail::lobatto_iiic_tableau<Real> m_tab;
  Real m_tol;
  std::vector<Real> m_lu, m_r;
  std::vector<std::size_t> m_pivot;
  std::vector<state> m_Y, m_F, m_guess_first, m_guess_second;
  bool m_low_allowed = true;
  std::vector<low_real> m_low, m_low_a, m_low_r, m_low_j;
  std::vector<matrix> m_stage_j;
  std::vector<std::size_t> m_low_pivot;
  std::array<low_real, N> m_low_w{};
  state m_term{};  // per component: the size of the terms summed into G (see newton)
  std::size_t m_low_solves = 0, m_real_solves = 0;
};

}  // namespace viscor
