// Lobatto IIIC (Chipman 1971; Hairer and Wanner, "Solving ODEs II", sec. IV.5): the
// GBS solver's stiff integrator, for the creeping phase of strongly damped impacts
// (issue 18 item 8). Written apart from the Taylor solver's Radau IIA
// (radau_integrator.hpp) on purpose: the two solvers share no integrator code.
// s stages, order 2s - 2, L-stable and stiffly accurate.
//
// Tableau, computed in Real: nodes c_1 = 0, c_s = 1 and the zeros of P'_{s-1}(2c - 1);
// weights b_j = 1/(s (s-1) P_{s-1}(2 c_j - 1)^2) (Lobatto quadrature on [0, 1]);
// a_i1 = b_1 and, for j >= 2, a_ij = int_0^{c_i} L_j - b_1 L_j(0), L_j the Lagrange
// basis on c_2..c_s (so that row i integrates polynomials of degree s - 2 exactly from
// 0 to c_i); the integrals by (s-1)-point Gauss-Legendre quadrature, exact for them.
// A step: the stage values Y_i = y0 + h sum_j a_ij f(Y_j) by Newton's method with the
// Jacobian at the step's start, a fresh LU each step; the error is estimated by
// comparing one step of h with two of h/2 (the halves are kept).
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
  }
};

}  // namespace detail

/// Lobatto IIIC steps with error control for an autonomous system of N components;
/// f(y, dy) is false outside its domain, jacobian(y, J) gives J[i][j] = d f_i/d y_j.
template <class Real, std::size_t N>
class lobatto_integrator {
 public:
  using state = std::array<Real, N>;
  using matrix = std::array<std::array<Real, N>, N>;

  /// s stages (order 2s - 2); tolerance on the scaled error per step.
  lobatto_integrator(int stages, const Real& tolerance) : m_tab(stages), m_tol(tolerance) {}

  /// A step of h from y, error relative to `scales`. True: y advanced by `taken` = h
  /// and h is the next trial step. False: rejected, y unchanged, h reduced.
  template <class F, class Jac>
  bool step(F& f, Jac& jacobian, state& y, Real& h, const state& scales, Real& taken) {
    using std::abs;
    using std::pow;
    state whole, mid, end;
    const Real half = h / 2;
    if (!stage_solve(f, jacobian, y, h, whole) || !stage_solve(f, jacobian, y, half, mid) ||
        !stage_solve(f, jacobian, mid, half, end)) {
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

 private:
  // Y_i = y0 + h sum_j a_ij f(Y_j); y1 = Y_s (stiffly accurate). False: Newton did not
  // converge, or a stage left the domain.
  template <class F, class Jac>
  bool stage_solve(F& f, Jac& jacobian, const state& y0, const Real& h, state& y1) {
    using std::abs;
    const std::size_t s = m_tab.c.size(), n = s * N;
    matrix J;
    jacobian(y0, J);
    // Newton matrix for the stage values: I - h (A x J)
    m_m.assign(n * n, Real(0));
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t p = 0; p < N; ++p) {
        m_m[(i * N + p) * n + (i * N + p)] = 1;
        for (std::size_t j = 0; j < s; ++j)
          for (std::size_t q = 0; q < N; ++q) m_m[(i * N + p) * n + (j * N + q)] -= h * m_tab.a[i * s + j] * J[p][q];
      }
    if (!decompose(n)) return false;
    std::vector<state> Y(s, y0), slopes(s);
    const int limit = 20 + binary_digits<Real>() / 6;
    Real last = -1;
    for (int it = 0; it < limit; ++it) {
      for (std::size_t j = 0; j < s; ++j)
        if (!f(Y[j], slopes[j])) return false;
      // G_i = Y_i - y0 - h sum_j a_ij F_j; Newton: M dY = -G
      m_b.resize(n);
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          Real g = Y[i][p] - y0[p];
          for (std::size_t j = 0; j < s; ++j) g -= h * m_tab.a[i * s + j] * slopes[j][p];
          m_b[i * N + p] = -g;
        }
      back_solve(n);
      Real change = 0;
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t p = 0; p < N; ++p) {
          Y[i][p] += m_b[i * N + p];
          const Real d = abs(m_b[i * N + p]) / (abs(Y[i][p]) + abs(y0[p]) + epsilon<Real>());
          if (!(d <= change)) change = d;
        }
      if (!boost::math::isfinite(change)) return false;
      if (change <= m_tol / 32 || (it >= 2 && change >= last / 2 && change <= 64 * epsilon<Real>())) {
        y1 = Y[s - 1];
        return true;
      }
      if (it >= 2 && change > last) return false;
      last = change;
    }
    return false;
  }

  // In-place LU of m_m with row pivoting (m_rows: the row order).
  bool decompose(std::size_t n) {
    using std::abs;
    m_rows.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_rows[i] = i;
    for (std::size_t k = 0; k < n; ++k) {
      std::size_t best = k;
      for (std::size_t i = k + 1; i < n; ++i)
        if (abs(m_m[m_rows[i] * n + k]) > abs(m_m[m_rows[best] * n + k])) best = i;
      std::swap(m_rows[k], m_rows[best]);
      const Real pivot = m_m[m_rows[k] * n + k];
      if (pivot == 0) return false;
      for (std::size_t i = k + 1; i < n; ++i) {
        Real& l = m_m[m_rows[i] * n + k];
        l /= pivot;
        if (l == 0) continue;
        for (std::size_t j = k + 1; j < n; ++j) m_m[m_rows[i] * n + j] -= l * m_m[m_rows[k] * n + j];
      }
    }
    return true;
  }

  // m_b := M^{-1} m_b (rows addressed through m_rows: no rows are moved).
  void back_solve(std::size_t n) {
    m_x.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Real sum = m_b[m_rows[i]];
      for (std::size_t j = 0; j < i; ++j) sum -= m_m[m_rows[i] * n + j] * m_x[j];
      m_x[i] = sum;
    }
    for (std::size_t i = n; i-- > 0;) {
      Real sum = m_x[i];
      for (std::size_t j = i + 1; j < n; ++j) sum -= m_m[m_rows[i] * n + j] * m_x[j];
      m_x[i] = sum / m_m[m_rows[i] * n + i];
    }
    m_b = m_x;
  }

  detail::lobatto_iiic_tableau<Real> m_tab;
  Real m_tol;
  std::vector<Real> m_m, m_b, m_x;
  std::vector<std::size_t> m_rows;
};

}  // namespace viscor
