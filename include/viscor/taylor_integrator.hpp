// Adaptive-order Taylor integrator for a small autonomous-or-not system whose
// Taylor coefficients a `System` computes by automatic differentiation
// (detail/taylor_series.hpp). Order and step follow Jorba and Zou (2005), as in
// heyoka (Biscani and Izzo 2021):
//   order  p = max(2, ceil(-ln(tol)/2 + 1)),
//   step   h = rho exp(-0.7/(p-1)) / e^2,
//   rho    = min_i min_{k = p-3..p} (s_i/|x_i[k]|)^(1/k)
// (Jorba-Zou use k = p-1, p; the wider window also sees sparse series), with
// the scale s_i chosen by the system: max(1, |x_i[0]|) for dynamic states
// (absolute error when small, relative when large), |x_i[0]| for quadratures
// that must keep relative precision, 0 to leave a component out. The order is
// fixed per integrator, so the series buffers are allocated once. Dense output and event location use the step
// polynomial itself: an event is the root of a component of it, found by TOMS
// 748 at working precision (detail/root_finding.hpp).
//
// A System provides
//   std::size_t size() const;                   number of components
//   Real step_scale(std::size_t i, const Real& x0) const;   s_i (0: not used)
//   void jet(const Real& t0, taylor_jet<Real>& x); fills x[i][1..order] from x[i][0]
#pragma once

#include <viscor/detail/root_finding.hpp>
#include <viscor/detail/taylor_series.hpp>
#include <viscor/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace viscor {

/// Taylor coefficients 0..order (+1 spare) of `size` series, stored contiguously.
template <class Real>
class taylor_jet {
 public:
  taylor_jet(std::size_t size, std::size_t order)
      : m_size(size), m_order(order), m_stride(order + 2), m_data(size * (order + 2), Real(0)) {}
  Real* operator[](std::size_t i) { return m_data.data() + i * m_stride; }
  const Real* operator[](std::size_t i) const { return m_data.data() + i * m_stride; }
  std::size_t size() const noexcept { return m_size; }
  std::size_t order() const noexcept { return m_order; }

 private:
  std::size_t m_size, m_order, m_stride;
  std::vector<Real> m_data;
};

/// The Taylor order for a tolerance (Jorba-Zou): max(2, ceil(-ln(tol)/2 + 1)).
template <class Real>
std::size_t taylor_order(const Real& tolerance) {
  using std::ceil;
  using std::log;
  const Real p = ceil(-log(tolerance) / 2 + 1);
  return p < 2 ? std::size_t(2) : static_cast<std::size_t>(p.template convert_to<long long>());
}
template <>
inline std::size_t taylor_order<double>(const double& tolerance) {
  const double p = std::ceil(-std::log(tolerance) / 2 + 1);
  return p < 2 ? 2 : static_cast<std::size_t>(p);
}
template <>
inline std::size_t taylor_order<long double>(const long double& tolerance) {
  const long double p = std::ceil(-std::log(tolerance) / 2 + 1);
  return p < 2 ? 2 : static_cast<std::size_t>(p);
}

template <class Real, class System>
class taylor_integrator {
 public:
  taylor_integrator(System& system, const Real& tolerance)
      : m_system(system),
        m_tolerance(tolerance),
        m_order(taylor_order(tolerance)),
        m_jet(system.size(), m_order),
        m_window(m_order < 4 ? m_order : 4) {
    using std::exp;
    m_safety = exp(Real(-0.7) / Real(static_cast<long>(m_order - 1)) - 2);
  }

  std::size_t order() const noexcept { return m_order; }
  const System& system() const noexcept { return m_system; }
  const Real& tolerance() const noexcept { return m_tolerance; }
  taylor_jet<Real>& jet() noexcept { return m_jet; }
  const taylor_jet<Real>& jet() const noexcept { return m_jet; }

  /// Loads the state x at t0, computes its Taylor expansion and returns the
  /// Jorba-Zou step, capped at |h_max| and signed like h_max (h_max != 0).
  Real expand(const Real& t0, const std::vector<Real>& x, const Real& h_max) {
    for (std::size_t i = 0; i < m_jet.size(); ++i) m_jet[i][0] = x[i];
    m_system.jet(t0, m_jet);
    return step_size(h_max);
  }

  /// The Jorba-Zou step of the current jet (see the file comment), capped at |h_max|.
  Real step_size(const Real& h_max) const {
    using std::abs;
    using std::exp;
    using std::log;
    using boost::math::isfinite;
    const std::size_t p = m_order;
    // max over states and orders of log(|x_i[k]| / s_i) / k = -log(rho)
    Real log_inv_rho = -std::numeric_limits<Real>::infinity();
    bool any = false;
    for (std::size_t i = 0; i < m_jet.size(); ++i) {
      const Real* c = m_jet[i];
      const Real scale = m_system.step_scale(i, c[0]);
      if (!(scale > 0)) continue;
      // NOTE: Jorba-Zou use orders p-1 and p. Series of the endpoint systems can
      // be sparse (only every Q(alpha+1)-th term at s = 0), so we take the
      // smallest radius over the last m_window orders: never larger, and never
      // blind to a series whose last two terms happen to vanish.
      for (std::size_t k = p + 1 - m_window; k <= p; ++k) {
        if (c[k] == 0) continue;
        const Real l = log(Real(abs(c[k]) / scale)) / Real(static_cast<long>(k));
        if (!any || l > log_inv_rho) log_inv_rho = l;
        any = true;
      }
    }
    const Real rho = any ? Real(exp(-log_inv_rho)) : Real(std::numeric_limits<Real>::infinity());
    Real h = rho * m_safety;
    if (!isfinite(h) || h > abs(h_max)) h = abs(h_max);
    if (h_max < 0) h = -h;
    limit_cancellation(h);
    return h;
  }

  /// Shrinks h until no component's step polynomial cancels by more than a
  /// factor m_cancellation: sum_k |x_i[k] h^k| <= K max(s_i, |x_i(t0 + h)|).
  /// NOTE: the Horner sum's rounding error is ~eps sum |x_i[k] h^k|. For entire
  /// solutions (fast decaying modes, e^(-lambda t)) the Jorba-Zou radius grows
  /// like p/e with the order, and the sum with it like e^(lambda h): at 300
  /// digits (p = 346) 7 digits were lost per step without this cap.
  void limit_cancellation(Real& h) const {
    using std::abs;
    // NOTE: the worst case, an entire series (x^k/k! at the Jorba-Zou step,
    // x = p/e^3), sums to e^(p/e^3): below the factor K = 8 up to p = 41
    // (double, long double, float128), so there the check is skipped.
    if (m_order <= 41) return;
    for (int tries = 0; tries < 64; ++tries) {
      bool ok = true;
      for (std::size_t i = 0; i < m_jet.size() && ok; ++i) {
        const Real* c = m_jet[i];
        const Real scale = m_system.step_scale(i, c[0]);
        if (!(scale > 0)) continue;
        // m_sum = sum |c_k| |h|^k, m_value = sum c_k h^k (Horner both)
        m_sum = abs(c[m_order]);
        m_value = c[m_order];
        m_abs_h = abs(h);
        for (std::size_t k = m_order; k-- > 0;) {
          m_sum *= m_abs_h;
          m_sum += abs(c[k]);
          m_value *= h;
          m_value += c[k];
        }
        m_value = abs(m_value);
        if (m_value < scale) m_value = scale;
        ok = m_sum <= m_cancellation * m_value;
      }
      if (ok) return;
      h *= Real(3) / 4;
    }
  }

  /// Component i of the step polynomial at t0 + h (dense output).
  Real value(std::size_t i, const Real& h) const {
    Real out;
    detail::horner(out, m_jet[i], m_order, h);
    return out;
  }
  /// d/dt of component i at t0 + h.
  Real derivative(std::size_t i, const Real& h) const {
    Real out;
    detail::horner_derivative(out, m_jet[i], m_order, h);
    return out;
  }
  /// All components at t0 + h.
  void values(std::vector<Real>& x, const Real& h) const {
    for (std::size_t i = 0; i < m_jet.size(); ++i) detail::horner(x[i], m_jet[i], m_order, h);
  }

  /// The root in [0, h] (or [h, 0]) of component i minus `level`, given that it
  /// changes sign over the step; TOMS 748 on the step polynomial, then one Newton step.
  Real locate(std::size_t i, const Real& level, const Real& h, const std::string& what) const {
    auto f = [&](const Real& t) { return Real(value(i, t) - level); };
    auto df = [&](const Real& t) { return derivative(i, t); };
    if (h > 0) return detail::monotone_root(f, df, Real(0), h, what);
    return detail::monotone_root(f, df, h, Real(0), what);
  }

 private:
  System& m_system;
  Real m_tolerance;
  std::size_t m_order;
  taylor_jet<Real> m_jet;
  std::size_t m_window;  // orders p - window + 1 .. p enter the radius estimate
  Real m_safety;         // exp(-0.7/(p-1)) / e^2
  Real m_cancellation = 8;  // at most one digit lost to cancellation per step
  mutable Real m_sum, m_value, m_abs_h;
};

}  // namespace viscor
