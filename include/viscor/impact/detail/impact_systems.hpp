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

#include <viscor/core/contact_law.hpp>
#include <viscor/impact/detail/taylor_tail.hpp>
#include <viscor/ode/detail/taylor_series.hpp>
#include <viscor/ode/taylor_integrator.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <type_traits>
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

/// The constants of (law, gamma, g) in Real: the one place that builds
/// impact_constants (the Taylor solver and the tests call it). The endpoint
/// variable is u = s^Q for rational exponents, Q = lcm of the denominators,
/// unless Q or Q alpha or Q beta is too large (exponent_multiples::fit_root_variable);
/// else u = exp(sigma).
template <class Real>
impact_constants<Real> make_impact_constants(const contact_law& law, const Real& gamma, const Real& g) {
  impact_constants<Real> c;
  c.alpha = law.alpha.value<Real>();
  c.beta = law.beta.value<Real>();
  c.gamma = gamma;
  c.g = g;
  c.alpha_plus_one = c.alpha + 1;
  c.beta_plus_one = c.beta + 1;
  c.gamma_beta = gamma * c.beta;
  c.two_gamma = 2 * gamma;
  c.two_gamma_beta = 2 * c.gamma_beta;
  c.alpha_equals_beta = law.alpha == law.beta;
  c.beta_is_one = law.beta.is_rational() && law.beta.numerator() == 1 && law.beta.denominator() == 1;
  c.alpha_is_one = law.alpha.is_rational() && law.alpha.numerator() == 1 && law.alpha.denominator() == 1;
  // NOTE: u = s^Q needs polynomials of degree Q(alpha+1) - 1; for huge
  // denominators the exponential variable is cheaper and just as exact.
  if (law.alpha.is_rational() && law.beta.is_rational()) {
    const exponent_multiples m = law.multiples();
    if (m.fit_root_variable()) {
      c.use_root_variable = true;
      c.Q = m.Q, c.Q_alpha = m.Q_alpha, c.Q_beta = m.Q_beta;
    }
  }
  return c;
}

/// Pointers to the series of one time_system jet in arithmetic T, with its scratch.
template <class T>
struct time_series {
  T *U, *V, *E, *A, *P, *dP, *ju;
  const std::vector<T>* inv;
  T inv_u0, scratch, t;
};

/// Orders k_begin + 1 .. k_end of a time_system jet in arithmetic T, from orders
/// 0 .. k_begin. Scaled: the series are in h' = h / H (coefficient k times H^k),
/// i.e. the system's right-hand sides times H (detail/taylor_tail.hpp).
template <class T, bool Scaled>
void time_orders(time_series<T>& s, const impact_constants<T>& c, std::size_t k_begin, std::size_t k_end,
                 const T& H) {
  T *U = s.U, *V = s.V, *E = s.E, *A = s.A, *P = s.P, *dP = s.dP, *ju = s.ju;
  const std::vector<T>& inv = *s.inv;
  for (std::size_t k = k_begin; k < k_end; ++k) {
    if (k > 0 && !c.alpha_equals_beta) real_power(A[k], s.scratch, c.alpha_plus_one, U, ju, A, k, s.inv_u0, inv);
    // u' = v
    ju[k + 1] = V[k];
    if constexpr (Scaled) ju[k + 1] *= H;
    U[k + 1] = ju[k + 1];
    divide_by(U[k + 1], k + 1, inv);
    if (c.beta_is_one) {
      P[k + 1] = U[k + 1];
    } else {
      real_power(P[k + 1], s.scratch, c.beta_plus_one, U, ju, P, k + 1, s.inv_u0, inv);
    }
    dP[k] = P[k + 1];
    dP[k] *= static_cast<long>(k + 1);
    // v' = g - u^alpha - gamma (u^beta)'
    s.t = dP[k];
    s.t *= c.gamma;
    V[k + 1] = A[k];
    if constexpr (Scaled) V[k + 1] *= H;
    V[k + 1] += s.t;
    V[k + 1] = -V[k + 1];
    if (k == 0) {
      if constexpr (Scaled) {
        V[k + 1] += H * c.g;
      } else {
        V[k + 1] += c.g;
      }
    }
    divide_by(V[k + 1], k + 1, inv);
    // D' = 2 gamma v (u^beta)'
    product(E[k + 1], V, dP, k);
    E[k + 1] *= c.two_gamma;
    divide_by(E[k + 1], k + 1, inv);
  }
}

template <class Real>
class time_system {
 public:
  enum : std::size_t { u = 0, v = 1, D = 2 };

  time_system(const impact_constants<Real>& c, std::size_t order, const Real& tolerance)
      : m_c(c), m_A(order + 2), m_P(order + 2), m_dP(order + 2), m_ju(order + 2),
        m_inv(integer_reciprocals<Real>(order + 1)), m_plan(order, tolerance) {
    m_series.P = m_P.data(), m_series.dP = m_dP.data(), m_series.ju = m_ju.data(), m_series.inv = &m_inv;
    if (m_plan.split() < order) init_tail(order);
  }

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
  /// First order computed in double by the last jet (order + 1: none), and ln of
  /// the bound on |x_i[k] h^k| / s_i for those orders (taylor_integrator::step_size).
  std::size_t tail_start() const { return m_last_tail_start; }
  double tail_log_bound() const { return m_plan.log_bound(); }

  void jet(const Real& /*tau0*/, taylor_jet<Real>& x) {
    using std::pow;
    const std::size_t p = x.order();
    time_series<Real>& s = m_series;
    s.U = x[u], s.V = x[v], s.E = x[D];
    s.A = m_c.alpha_equals_beta ? s.P : m_A.data();
    Real* U = s.U;
    s.ju[0] = 0;
    s.inv_u0 = 1;
    s.inv_u0 /= U[0];
    s.P[0] = m_c.beta_is_one ? U[0] : Real(pow(U[0], m_c.beta));
    if (!m_c.alpha_equals_beta) s.A[0] = pow(U[0], m_c.alpha);
    m_last_tail_start = m_plan.run(
        p, [&](std::size_t from, std::size_t to) { time_orders<Real, false>(s, m_c, from, to, Real(1)); },
        [&](auto split) { return tail(s, split, p); });
    set_scales(U[0], x[v][0], s.A[0], x[D][0]);
    if (m_c.alpha_is_one) {
      m_omega2 = 1;
    } else {
      m_omega2 = s.A[0];
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

  using plan = tail_plan<Real>;
  using tail_arithmetic = typename plan::arithmetic;

  void init_tail(std::size_t order) {
    for (auto* a : {&m_tU, &m_tV, &m_tE, &m_tA, &m_tP, &m_tdP, &m_tju}) a->assign(order + 2, 0);
    m_tinv = integer_reciprocals<tail_arithmetic>(order + 1);
    auto& t = m_tail_c;
    bool ok = true;
    t.gamma = plan::constant(m_c.gamma, ok);
    t.g = plan::constant(m_c.g, ok);
    t.alpha_plus_one = plan::constant(m_c.alpha_plus_one, ok);
    t.beta_plus_one = plan::constant(m_c.beta_plus_one, ok);
    t.two_gamma = plan::constant(m_c.two_gamma, ok);
    m_tail_usable = ok;  // else every jet is finished in Real
    t.alpha_equals_beta = m_c.alpha_equals_beta;
    t.beta_is_one = m_c.beta_is_one;
  }

  // Orders split + 1 .. p of s in the tail arithmetic; false (nothing changed) when a
  // needed value leaves its range.
  bool tail(time_series<Real>& s, std::size_t split, std::size_t p) {
    if (!m_tail_usable) return false;
    const int m = m_plan.scale_exponent({s.U, s.V});
    // orders 0 .. split (A, dP: 0 .. split - 1); dP[k] is order k of (u^beta)', times H^(k+1)
    const bool in_range = plan::down(s.U, m_tU.data(), split, m) && plan::down(s.V, m_tV.data(), split, m) &&
                          plan::down(s.E, m_tE.data(), split, m) && plan::down(s.P, m_tP.data(), split, m) &&
                          plan::down(s.ju, m_tju.data(), split, m) && plan::down(s.A, m_tA.data(), split - 1, m) &&
                          plan::down(s.dP, m_tdP.data(), split - 1, m, m);
    const tail_arithmetic u0 = m_tU[0];
    if (!in_range || !std::isnormal(u0) || !std::isnormal(m_tP[0]) || !std::isnormal(m_tA[0])) return false;
    time_series<tail_arithmetic> t{m_tU.data(), m_tV.data(), m_tE.data(), m_tA.data(), m_tP.data(), m_tdP.data(),
                                   m_tju.data(), &m_tinv, 1 / u0, 0, 0};
    if (m_c.alpha_equals_beta) t.A = t.P;
    time_orders<tail_arithmetic, true>(t, m_tail_c, split, p, std::ldexp(tail_arithmetic(1), m));
    const std::size_t first = split + 1;
    if (!plan::outputs_in_range(m_tU.data(), first, p) || !plan::outputs_in_range(m_tV.data(), first, p) ||
        !plan::outputs_in_range(m_tE.data(), first, p))
      return false;
    if ((s.V[0] == 0 && !plan::all_zero(m_tV.data(), first, p)) ||
        (s.E[0] == 0 && !plan::all_zero(m_tE.data(), first, p)))
      return false;  // u > 0 always here
    plan::up(m_tU.data(), s.U, split + 1, p, m);
    plan::up(m_tV.data(), s.V, split + 1, p, m);
    plan::up(m_tE.data(), s.E, split + 1, p, m);
    return true;
  }

  const impact_constants<Real>& m_c;
  std::vector<Real> m_A, m_P, m_dP, m_ju, m_inv;
  time_series<Real> m_series{};  // the jet's series; its scratch numbers are kept from jet to jet
  Real m_scratch, m_t, m_omega2;
  Real m_scale[3];
  plan m_plan;
  std::size_t m_last_tail_start = 0;
  std::vector<tail_arithmetic> m_tU, m_tV, m_tE, m_tA, m_tP, m_tdP, m_tju, m_tinv;
  impact_constants<tail_arithmetic> m_tail_c;
  bool m_tail_usable = false;  // every constant of the tail is 0 or a normal double
};

/// Pointers to the series of one endpoint_system jet in arithmetic T: the states,
/// 1/v, the known series J, M, L with their degrees, and scratch.
template <class T>
struct endpoint_series {
  T *V, *Tau, *E, *r;
  const T *J, *M, *L;
  std::size_t deg_J, deg_M, deg_L;
  const std::vector<T>* inv;
  T gamma_beta, two_gamma_beta, t;
};

/// Orders k_begin + 1 .. k_end of an endpoint_system jet in arithmetic T (Scaled: in
/// sigma / H, see time_orders), from orders 0 .. k_begin (r: 0 .. k_begin - 1).
template <class T, bool Scaled>
void endpoint_orders(endpoint_series<T>& s, std::size_t k_begin, std::size_t k_end, const T& H) {
  T *V = s.V, *Tau = s.Tau, *E = s.E, *r = s.r;
  const std::vector<T>& inv = *s.inv;
  for (std::size_t k = k_begin; k < k_end; ++k) {
    if (k > 0) reciprocal(r[k], V, r, k);
    const std::size_t lo_J = k > s.deg_J ? k - s.deg_J : 0;
    const std::size_t lo_M = k > s.deg_M ? k - s.deg_M : 0;
    // sum over j of J[k-j] r[j] with k - j <= deg J
    convolution(Tau[k + 1], r, s.J, k, lo_J, k);
    if constexpr (Scaled) Tau[k + 1] *= H;
    divide_by(Tau[k + 1], k + 1, inv);
    convolution(V[k + 1], r, s.M, k, lo_M, k);
    if (k <= s.deg_L) {
      s.t = s.L[k];
      s.t *= s.gamma_beta;
      V[k + 1] -= s.t;
    }
    if constexpr (Scaled) V[k + 1] *= H;
    divide_by(V[k + 1], k + 1, inv);
    const std::size_t lo_L = k > s.deg_L ? k - s.deg_L : 0;
    convolution(E[k + 1], V, s.L, k, lo_L, k);
    E[k + 1] *= s.two_gamma_beta;
    if constexpr (Scaled) E[k + 1] *= H;
    divide_by(E[k + 1], k + 1, inv);
  }
}

template <class Real>
class endpoint_system {
 public:
  enum : std::size_t { v = 0, tau = 1, D = 2 };

  endpoint_system(const impact_constants<Real>& c, std::size_t order, const Real& tolerance)
      : m_c(c), m_order(order), m_J(order + 2), m_M(order + 2), m_L(order + 2), m_r(order + 2), m_tmp(order + 2),
        m_inv(integer_reciprocals<Real>(order + 1)), m_plan(order, tolerance) {
    if (!c.use_root_variable) {
      m_lambda_alpha = c.alpha_plus_one;
      m_lambda_beta = c.beta;
    }
    auto& s = m_series;
    s.r = m_r.data(), s.J = m_J.data(), s.M = m_M.data(), s.L = m_L.data(), s.inv = &m_inv;
    s.gamma_beta = c.gamma_beta, s.two_gamma_beta = c.two_gamma_beta;
    if (m_plan.split() < order) {
      for (auto* a : {&m_tV, &m_tTau, &m_tE, &m_tr, &m_tJ, &m_tM, &m_tL}) a->assign(order + 2, 0);
      m_tinv = integer_reciprocals<tail_arithmetic>(order + 1);
      bool ok = true;
      m_tail_gamma_beta = plan::constant(c.gamma_beta, ok);
      m_tail_two_gamma_beta = plan::constant(c.two_gamma_beta, ok);
      m_tail_usable = ok;
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

  /// As time_system::tail_start and tail_log_bound.
  std::size_t tail_start() const { return m_last_tail_start; }
  double tail_log_bound() const { return m_plan.log_bound(); }

  void jet(const Real& sigma0, taylor_jet<Real>& x) {
    const std::size_t p = x.order();
    fill_known_series(sigma0, p);
    auto& s = m_series;
    s.V = x[v], s.Tau = x[tau], s.E = x[D];
    s.deg_J = m_deg_J, s.deg_M = m_deg_M, s.deg_L = m_deg_L;
    s.r[0] = 1;
    s.r[0] /= s.V[0];
    m_last_tail_start = m_plan.run(
        p, [&](std::size_t from, std::size_t to) { endpoint_orders<Real, false>(s, from, to, Real(1)); },
        [&](auto split) { return tail(s, split, p); });
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
      // NOTE: only up to the degrees: beyond them the coefficients are 0, and
      // a loop to the order is costly (docs/performance.md).
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

  using plan = tail_plan<Real>;
  using tail_arithmetic = typename plan::arithmetic;

  // As time_system::tail. r is known to order split - 1 only.
  bool tail(endpoint_series<Real>& s, std::size_t split, std::size_t p) {
    if (!m_tail_usable) return false;
    const int m = m_plan.scale_exponent({s.V, s.Tau});
    const bool in_range = plan::down(s.V, m_tV.data(), split, m) && plan::down(s.Tau, m_tTau.data(), split, m) &&
                          plan::down(s.E, m_tE.data(), split, m) && plan::down(s.r, m_tr.data(), split - 1, m) &&
                          plan::down(s.J, m_tJ.data(), std::min(s.deg_J, p), m) &&
                          plan::down(s.M, m_tM.data(), std::min(s.deg_M, p), m) &&
                          plan::down(s.L, m_tL.data(), std::min(s.deg_L, p), m);
    if (!in_range || !std::isnormal(m_tV[0])) return false;
    endpoint_series<tail_arithmetic> t{m_tV.data(), m_tTau.data(), m_tE.data(), m_tr.data(), m_tJ.data(),
                                       m_tM.data(), m_tL.data(), s.deg_J, s.deg_M, s.deg_L, &m_tinv,
                                       m_tail_gamma_beta, m_tail_two_gamma_beta, 0};
    endpoint_orders<tail_arithmetic, true>(t, split, p, std::ldexp(tail_arithmetic(1), m));
    const std::size_t first = split + 1;
    if (!plan::outputs_in_range(m_tV.data(), first, p) || !plan::outputs_in_range(m_tTau.data(), first, p) ||
        !plan::outputs_in_range(m_tE.data(), first, p))
      return false;
    // tau and D are 0 at the start of contact: their step scale |x0| is 0 there.
    if ((s.Tau[0] == 0 && !plan::all_zero(m_tTau.data(), first, p)) ||
        (s.E[0] == 0 && !plan::all_zero(m_tE.data(), first, p)))
      return false;
    plan::up(m_tV.data(), s.V, split + 1, p, m);
    plan::up(m_tTau.data(), s.Tau, split + 1, p, m);
    plan::up(m_tE.data(), s.E, split + 1, p, m);
    return true;
  }

  const impact_constants<Real>& m_c;
  std::size_t m_order;
  std::vector<Real> m_J, m_M, m_L, m_r, m_tmp, m_powers, m_inv;
  std::size_t m_deg_J = 0, m_deg_M = 0, m_deg_L = 0;
  Real m_lambda_alpha, m_lambda_beta, m_t;
  endpoint_series<Real> m_series{};
  plan m_plan;
  std::size_t m_last_tail_start = 0;
  std::vector<tail_arithmetic> m_tV, m_tTau, m_tE, m_tr, m_tJ, m_tM, m_tL, m_tinv;
  tail_arithmetic m_tail_gamma_beta = 0, m_tail_two_gamma_beta = 0;
  bool m_tail_usable = false;  // gamma beta, 2 gamma beta are 0 or normal doubles
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

// The integrator caps its steps by the double tail of these two (taylor_integrator::limit_tail).
static_assert(taylor_system_with_tail<time_system<double>> && taylor_system_with_tail<endpoint_system<double>>);
static_assert(taylor_system<spiral_system<double>, double> && !taylor_system_with_tail<spiral_system<double>>);

}  // namespace viscor::detail
