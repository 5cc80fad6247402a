// The impact ODE  u' = v,  v' = g - u^alpha - gamma beta u^(beta-1) v  (u > 0),
// with the dissipated energy D' = 2 gamma beta u^(beta-1) v^2 (eq. 6) carried
// along, as two Taylor systems for taylor_integrator:
//
// time_system: independent variable tau, states (u, v, D). Needs u > 0: the
//   power recurrences for u^alpha, u^beta divide by u(tau0).
//
// endpoint_system: independent variable sigma with u = phi(sigma) monotone, for
//   the first and last part of the contact where u -> 0. States (v, tau, D):
//     dtau/dsigma = J / v,
//     dv/dsigma   = (g J - u^alpha J) / v - gamma beta u^(beta-1) J,
//     dD/dsigma   = 2 gamma beta u^(beta-1) J v,          J = du/dsigma.
//   Two choices of phi make every known series analytic at u = 0:
//   * rational exponents, Q = lcm of the denominators: u = s^Q. Then
//     J = Q s^(Q-1), u^alpha J = Q s^(Q(alpha+1)-1), u^(beta-1) J = Q s^(Q beta-1)
//     are polynomials, and s = 0 is a regular point of the system while v != 0:
//     the impact starts and ends exactly there.
//   * any real exponents: u = exp(sigma). The known series exp(lambda sigma) are
//     entire; u = 0 moves to sigma = -infinity and the last gap [0, u_eps] is
//     closed by the leading terms of the generalized (Puiseux) series of the
//     solution (see taylor_impact.hpp).
//
// spiral_system (g = 0 and alpha + 1 = 2 beta: linear, Tsuji): the equation is
//   invariant under u -> lambda u, tau -> lambda^(-(alpha-1)/2) tau, so with
//   sigma = ln u, the scale-free speed r = v / u^c, c = beta = (alpha+1)/2, and
//   the scale-free time theta = tau u^(c-1),
//     dr/dsigma     = -(1 + gamma beta r + c r^2) / r,
//     dtheta/dsigma = (c - 1) theta + 1/r,
//     dD/dsigma     = 2 gamma beta r exp(2 beta sigma).
//   NOTE: tau itself grows like exp(-(c-1) sigma) (Tsuji: c - 1 = 1/4), an entire
//   series whose Jorba-Zou step stays ~ 4p/e^3 in sigma however slowly r moves;
//   theta relaxes to the slowly varying -1/((c-1) r) instead.
//   Near critical damping (gamma beta)^2 -> 4c the bead creeps back along a slow
//   spiral, ln u falling by ~ pi/omega, omega^2 = 1/c - (gamma beta/(2c))^2,
//   before it leaves (e = exp(-pi/omega)-small: 1e-13644 at gamma = 2 - 1e-8 for
//   the linear law); in tau that is ~ pi/omega time units of steps, in sigma a
//   handful, as r(sigma) varies on the scale 1/omega.
#pragma once

#include <viscor/detail/taylor_series.hpp>
#include <viscor/taylor_integrator.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace viscor::detail {

/// Constants of one impact, converted once to Real.
template <class Real>
struct impact_constants {
  Real alpha, beta, gamma, g;
  Real alpha_plus_one, beta_plus_one;
  Real gamma_beta, two_gamma, two_gamma_beta;
  bool alpha_equals_beta = false;
  bool alpha_is_one = false;
  bool beta_is_one = false;
  // u = s^Q variable (rational exponents): integer exponents of the monomials.
  bool use_root_variable = false;
  long Q = 1, Q_alpha = 1, Q_beta = 1;
};

template <class Real>
class time_system {
 public:
  enum : std::size_t { u = 0, v = 1, D = 2 };

  time_system(const impact_constants<Real>& c, std::size_t order)
      : m_c(c), m_A(order + 2), m_P(order + 2), m_dP(order + 2), m_ju(order + 2),
        m_inv(integer_reciprocals<Real>(order + 1)) {}

  std::size_t size() const { return 3; }
  // Step-control scales, set by jet(): D relative to itself (for the linear law
  // u, v are entire and only the truncation of v^2 limits the step); u and v
  // at least 1 (absolute error) for an O(1) motion, and relative to the size
  // of a small one (S < 1/4), S^2 = v^2 + 2 u^(alpha+1)/(alpha+1) (speed) and
  // S^(2/(alpha+1)) (overlap), so that a bead creeping towards rest keeps its
  // relative digits.
  const Real& step_scale(std::size_t i, const Real& /*x0*/) const { return m_scale[i]; }
  /// omega^2 = alpha u^(alpha-1) at the expansion point, set by jet(): the
  /// square of the fastest local frequency of the motion.
  const Real& stiffness() const { return m_omega2; }

  void jet(const Real& /*tau0*/, taylor_jet<Real>& x) {
    using std::pow;
    const std::size_t p = x.order();
    Real* U = x[u];
    Real* V = x[v];
    Real* E = x[D];
    Real* A = m_A.data();
    Real* P = m_P.data();
    Real* dP = m_dP.data();
    Real* ju = m_ju.data();
    ju[0] = 0;
    m_inv_u0 = 1;
    m_inv_u0 /= U[0];
    P[0] = m_c.beta_is_one ? U[0] : Real(pow(U[0], m_c.beta));
    if (m_c.alpha_equals_beta) {
      A = P;
    } else {
      A[0] = pow(U[0], m_c.alpha);
    }
    for (std::size_t k = 0; k < p; ++k) {
      if (k > 0 && !m_c.alpha_equals_beta)
        real_power(A[k], m_scratch, m_c.alpha_plus_one, U, ju, A, k, m_inv_u0, m_inv);
      U[k + 1] = V[k];
      divide_by(U[k + 1], k + 1, m_inv);
      ju[k + 1] = V[k];
      if (m_c.beta_is_one) {
        P[k + 1] = U[k + 1];
      } else {
        real_power(P[k + 1], m_scratch, m_c.beta_plus_one, U, ju, P, k + 1, m_inv_u0, m_inv);
      }
      dP[k] = P[k + 1];
      dP[k] *= static_cast<long>(k + 1);
      // v' = g - u^alpha - gamma (u^beta)'
      m_t = dP[k];
      m_t *= m_c.gamma;
      V[k + 1] = A[k];
      V[k + 1] += m_t;
      V[k + 1] = -V[k + 1];
      if (k == 0) V[k + 1] += m_c.g;
      divide_by(V[k + 1], k + 1, m_inv);
      // D' = 2 gamma v (u^beta)'
      product(E[k + 1], V, dP, k);
      E[k + 1] *= m_c.two_gamma;
      divide_by(E[k + 1], k + 1, m_inv);
    }
    set_scales(U[0], V[0], A[0], E[0]);
    if (m_c.alpha_is_one) {
      m_omega2 = 1;
    } else {
      m_omega2 = A[0];
      m_omega2 *= m_c.alpha;
      m_omega2 /= U[0];
    }
  }

 private:
  void set_scales(const Real& u0, const Real& v0, const Real& u_alpha, const Real& D0) {
    using std::abs;
    using std::pow;
    using std::sqrt;
    // m_t = S^2
    m_t = u0 * u_alpha;
    m_t *= 2;
    m_t /= m_c.alpha_plus_one;
    m_t += v0 * v0;
    m_scale[u] = abs(u0);
    m_scale[v] = abs(v0);
    // NOTE: only for a small motion (S < 1/4): the scale enters the step as
    // scale^(1/p), so near S ~ 1 this would change nothing but cost a pow.
    if (m_t < Real(1) / 16) {
      m_scratch = m_c.alpha_is_one ? Real(sqrt(m_t)) : Real(pow(m_t, 1 / m_c.alpha_plus_one));
      if (m_scale[u] < m_scratch) m_scale[u] = m_scratch;
      m_scratch = sqrt(m_t);
      if (m_scale[v] < m_scratch) m_scale[v] = m_scratch;
    } else {
      if (m_scale[u] < 1) m_scale[u] = 1;
      if (m_scale[v] < 1) m_scale[v] = 1;
    }
    m_scale[D] = abs(D0);
  }

  const impact_constants<Real>& m_c;
  std::vector<Real> m_A, m_P, m_dP, m_ju, m_inv;
  Real m_scratch, m_t, m_omega2, m_inv_u0;
  Real m_scale[3];
};

template <class Real>
class endpoint_system {
 public:
  enum : std::size_t { v = 0, tau = 1, D = 2 };

  endpoint_system(const impact_constants<Real>& c, std::size_t order)
      : m_c(c), m_order(order), m_J(order + 2), m_M(order + 2), m_L(order + 2), m_r(order + 2), m_tmp(order + 2),
        m_inv(integer_reciprocals<Real>(order + 1)) {
    if (!c.use_root_variable) {
      m_lambda_alpha = c.alpha_plus_one;
      m_lambda_beta = c.beta;
    }
  }

  std::size_t size() const { return 3; }
  // NOTE: every state relative to itself, v too: the endpoint phases keep |v|
  // away from 0 (v > 4/5 of its peak, or |v| > |v1|/2 on the way out), and e
  // may be tiny (near critical damping) yet wanted to relative precision.
  Real step_scale(std::size_t, const Real& x0) const {
    using std::abs;
    return abs(x0);
  }

  void jet(const Real& sigma0, taylor_jet<Real>& x) {
    const std::size_t p = x.order();
    fill_known_series(sigma0, p);
    Real* V = x[v];
    Real* T = x[tau];
    Real* E = x[D];
    Real* r = m_r.data();
    r[0] = 1;
    r[0] /= V[0];
    for (std::size_t k = 0; k < p; ++k) {
      if (k > 0) reciprocal(r[k], V, r, k);
      const std::size_t lo_J = k > m_deg_J ? k - m_deg_J : 0;
      const std::size_t lo_M = k > m_deg_M ? k - m_deg_M : 0;
      // sum over j of J[k-j] r[j] with k - j <= deg J
      convolution(T[k + 1], r, m_J.data(), k, lo_J, k);
      divide_by(T[k + 1], k + 1, m_inv);
      convolution(V[k + 1], r, m_M.data(), k, lo_M, k);
      if (k <= m_deg_L) {
        m_t = m_L[k];
        m_t *= m_c.gamma_beta;
        V[k + 1] -= m_t;
      }
      divide_by(V[k + 1], k + 1, m_inv);
      const std::size_t lo_L = k > m_deg_L ? k - m_deg_L : 0;
      convolution(E[k + 1], V, m_L.data(), k, lo_L, k);
      E[k + 1] *= m_c.two_gamma_beta;
      divide_by(E[k + 1], k + 1, m_inv);
    }
  }

  /// u at sigma.
  Real u_of(const Real& sigma) const {
    using std::exp;
    using std::pow;
    if (m_c.use_root_variable) return pow(sigma, m_c.Q);
    return exp(sigma);
  }

 private:
  // J = du/dsigma, M = g J - u^alpha J, L = u^(beta-1) J about sigma0; deg_* are
  // the polynomial degrees (order p for the exponential variable).
  void fill_known_series(const Real& sigma0, std::size_t p) {
    if (m_c.use_root_variable) {
      const long Q = m_c.Q;
      integer_power_of_linear(m_J, m_powers, sigma0, Q - 1, p);
      integer_power_of_linear(m_tmp, m_powers, sigma0, Q * 1 + m_c.Q_alpha - 1, p);
      integer_power_of_linear(m_L, m_powers, sigma0, m_c.Q_beta - 1, p);
      m_deg_J = static_cast<std::size_t>(Q - 1);
      m_deg_L = static_cast<std::size_t>(m_c.Q_beta - 1);
      m_deg_M = static_cast<std::size_t>(std::max<long>(Q - 1, Q + m_c.Q_alpha - 1));
      // NOTE: only up to the degrees: beyond them the coefficients are 0 (a
      // loop to the order was a fifth of the work of a float128 endpoint jet).
      const std::size_t top = std::min(p, std::max({m_deg_J, m_deg_L, m_deg_M}));
      for (std::size_t j = 0; j <= top; ++j) {
        m_J[j] *= Q;
        m_L[j] *= Q;
        m_M[j] = m_J[j];
        m_M[j] *= m_c.g;
        m_tmp[j] *= Q;
        m_M[j] -= m_tmp[j];
      }
    } else {
      exponential_of_linear(m_J, Real(1), sigma0, p);
      exponential_of_linear(m_tmp, m_lambda_alpha, sigma0, p);
      exponential_of_linear(m_L, m_lambda_beta, sigma0, p);
      for (std::size_t j = 0; j <= p; ++j) {
        m_M[j] = m_J[j];
        m_M[j] *= m_c.g;
        m_M[j] -= m_tmp[j];
      }
      m_deg_J = m_deg_M = m_deg_L = p;
    }
    m_deg_J = std::min(m_deg_J, p);
    m_deg_M = std::min(m_deg_M, p);
    m_deg_L = std::min(m_deg_L, p);
  }

  const impact_constants<Real>& m_c;
  std::size_t m_order;
  std::vector<Real> m_J, m_M, m_L, m_r, m_tmp, m_powers, m_inv;
  std::size_t m_deg_J = 0, m_deg_M = 0, m_deg_L = 0;
  Real m_lambda_alpha, m_lambda_beta, m_t;
};

template <class Real>
class spiral_system {
 public:
  enum : std::size_t { r = 0, theta = 1, D = 2 };

  spiral_system(const impact_constants<Real>& c, std::size_t order)
      : m_c(c), m_R(order + 2), m_Y(order + 2), m_inv(integer_reciprocals<Real>(order + 1)) {
    m_time_rate = m_c.beta - 1;  // c - 1
    m_dissipation_rate = 2 * m_c.beta;
  }

  std::size_t size() const { return 3; }
  // Every state relative to itself: r < 0 is bounded away from 0 and falls
  // monotonically; e = |r| u^c wants relative digits.
  Real step_scale(std::size_t, const Real& x0) const {
    using std::abs;
    return abs(x0);
  }

  void jet(const Real& sigma0, taylor_jet<Real>& x) {
    const std::size_t p = x.order();
    Real* S = x[r];
    Real* T = x[theta];
    Real* E = x[D];
    Real* R = m_R.data();
    exponential_of_linear(m_Y, m_dissipation_rate, sigma0, p);
    R[0] = 1;
    R[0] /= S[0];
    for (std::size_t k = 0; k < p; ++k) {
      if (k > 0) reciprocal(R[k], S, R, k);
      // r' = -1/r - gamma beta - c r
      m_t = S[k];
      m_t *= m_c.beta;
      S[k + 1] = R[k];
      S[k + 1] += m_t;
      if (k == 0) S[k + 1] += m_c.gamma_beta;
      S[k + 1] = -S[k + 1];
      divide_by(S[k + 1], k + 1, m_inv);
      T[k + 1] = R[k];
      if (!m_c.alpha_is_one) {
        m_t = T[k];
        m_t *= m_time_rate;
        T[k + 1] += m_t;
      }
      divide_by(T[k + 1], k + 1, m_inv);
      product(E[k + 1], S, m_Y.data(), k);
      E[k + 1] *= m_c.two_gamma_beta;
      divide_by(E[k + 1], k + 1, m_inv);
    }
  }

 private:
  const impact_constants<Real>& m_c;
  std::vector<Real> m_R, m_Y, m_inv;
  Real m_time_rate, m_dissipation_rate, m_t;
};

}  // namespace viscor::detail
