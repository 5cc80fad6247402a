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
// 748 at working precision (detail/root_finding.hpp). What a System must provide
// is the concept taylor_system below.
#pragma once

#include <viscor/core/detail/root_finding.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/ode/detail/taylor_series.hpp>
#include <viscor/core/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cfenv>
#include <limits>
#include <string>
#include <vector>

namespace viscor {

/// Taylor coefficients 0..order (+1 spare) of `size` series, stored contiguously.
template <class Real>
class taylor_jet {
 public:
  /// Zeroed coefficients of `size` series up to `order`.
  taylor_jet(std::size_t size, std::size_t order)
      : m_size(size), m_order(order), m_stride(order + 2), m_data(size * (order + 2), Real(0)) {}
  /// The coefficients of series i (order() + 2 of them).
  Real* operator[](std::size_t i) { return m_data.data() + i * m_stride; }
  /// The coefficients of series i (order() + 2 of them).
  const Real* operator[](std::size_t i) const { return m_data.data() + i * m_stride; }
  /// The number of series.
  std::size_t size() const noexcept { return m_size; }
  /// The highest order stored (one spare above it).
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
/// taylor_order for double, without multiprecision conversions.
template <>
inline std::size_t taylor_order<double>(const double& tolerance) {
  const double p = std::ceil(-std::log(tolerance) / 2 + 1);
  return p < 2 ? 2 : static_cast<std::size_t>(p);
}
/// taylor_order for long double.
template <>
inline std::size_t taylor_order<long double>(const long double& tolerance) {
  const long double p = std::ceil(-std::log(tolerance) / 2 + 1);
  return p < 2 ? 2 : static_cast<std::size_t>(p);
}

/// What taylor_integrator needs of a System of ODEs in Real:
/// size() components; step_scale(i, x0) = s_i, the scale of component i at the
/// expansion point x0 for the step estimate (0: left out); jet(t0, x) fills the
/// Taylor coefficients x[i][1..order] at t0 from x[i][0].
template <class System, class Real>
concept taylor_system = requires(System& system, const System& csystem, std::size_t i, const Real& t0,
                                 const Real& x0, taylor_jet<Real>& x) {
  { csystem.size() } -> std::convertible_to<std::size_t>;
  { csystem.step_scale(i, x0) } -> std::convertible_to<Real>;
  system.jet(t0, x);
};

/// A taylor_system whose last jet computed the orders from tail_start() on in a
/// lower precision, bounded by |x_i[k] h^k| <= exp(tail_log_bound()) s_i
/// (the integrator caps its step to keep that bound: limit_tail).
template <class System>
concept taylor_system_with_tail = requires(const System& system) {
  { system.tail_start() } -> std::convertible_to<std::size_t>;
  { system.tail_log_bound() } -> std::convertible_to<double>;
};

/// Fixed-order Taylor steps of a taylor_system with the Jorba-Zou order and step rules.
template <class Real, taylor_system<Real> System>
class taylor_integrator {
 public:
  /// An integrator of `system` (kept by reference) at relative tolerance `tolerance` per step.
  taylor_integrator(System& system, const Real& tolerance)
      : m_system(system),
        m_tolerance(tolerance),
        m_order(taylor_order(tolerance)),
        m_jet(system.size(), m_order),
        m_window(m_order < 4 ? m_order : 4) {
    m_log_safety = -0.7 / static_cast<double>(m_order - 1) - 2;
  }

  /// The Taylor order, taylor_order(tolerance()).
  std::size_t order() const noexcept { return m_order; }
  /// The system integrated.
  const System& system() const noexcept { return m_system; }
  /// The relative tolerance per step.
  const Real& tolerance() const noexcept { return m_tolerance; }
  /// The Taylor coefficients of the last step's expansion point.
  taylor_jet<Real>& jet() noexcept { return m_jet; }
  /// The Taylor coefficients of the last step's expansion point.
  const taylor_jet<Real>& jet() const noexcept { return m_jet; }

  /// Loads the state x at t0, computes its Taylor expansion and returns the
  /// Jorba-Zou step, capped at |h_max| and signed like h_max (h_max != 0).
  Real expand(const Real& t0, const std::vector<Real>& x, const Real& h_max) {
    for (std::size_t i = 0; i < m_jet.size(); ++i) m_jet[i][0] = x[i];
    const bool underflowed = compute_jet(t0);
    require_representable_jet();
    const Real h = step_size(h_max);
    if (underflowed) require_precise_jet(h);
    return h;
  }

  /// Computes the jet at t0 (the state in its order-0 coefficients); true when one of
  /// its operations underflowed, in a type with double's exponent range (double,
  /// double-double): only then can a coefficient be subnormal (the inputs are normal).
  /// NOTE: read from the floating-point environment's sticky flag, the caller's flag given
  /// back as it was: scanning every coefficient for a subnormal one at every step cost 6.6%
  /// of the instructions of 45 double solves of the five laws (callgrind), the flag 0.9%.
  bool compute_jet(const Real& t0) {
    if constexpr (std::numeric_limits<Real>::max_exponent <= std::numeric_limits<double>::max_exponent) {
      std::fexcept_t caller;
      std::fegetexceptflag(&caller, FE_UNDERFLOW);
      std::feclearexcept(FE_UNDERFLOW);
      m_system.jet(t0, m_jet);
      const bool underflowed = std::fetestexcept(FE_UNDERFLOW) != 0;
      if (!underflowed) std::fesetexceptflag(&caller, FE_UNDERFLOW);
      return underflowed;
    } else {
      m_system.jet(t0, m_jet);
      return false;
    }
  }

  /// Throws exponent_range_exceeded when a Taylor coefficient is not finite in a type
  /// that carries more digits than double within double's exponent range (double-double).
  /// NOTE: at high orders the coefficients near u = 0 under a large load grow like
  /// (|v|/u)^k and overflow 2^1024 (double-double's order 37, not double's 20); the step
  /// then becomes 0 and no halving helps, while float128's range holds them, so
  /// with_working_precision reruns the solve there.
  void require_representable_jet() const {
    using limits = std::numeric_limits<Real>;
    if constexpr (limits::max_exponent <= std::numeric_limits<double>::max_exponent &&
                  limits::digits > std::numeric_limits<double>::digits) {
      using boost::math::isfinite;
      for (std::size_t i = 0; i < m_jet.size(); ++i)
        for (std::size_t k = 0; k <= m_order; ++k)
          if (!isfinite(m_jet[i][k]))
            throw exponent_range_exceeded("the Taylor coefficient of order " + std::to_string(k) + " of component " +
                                          std::to_string(i) + " overflows the exponent range of the working type");
    }
  }

  /// Throws exponent_range_exceeded when a Taylor coefficient that underflowed could
  /// matter at the step h, in a type with double's exponent range (double and
  /// double-double): below numeric_limits<Real>::min() it is subnormal (double-double:
  /// its low part), so the coefficient is known only to about 2^-1060 absolutely
  /// (2^-1074 per operation), an error that h^k carries into the state. It must stay
  /// below the tolerance on the component's scale (or, for a state still 0, on its
  /// first-order change |x_i[1] h|); else with_working_precision reruns the solve in a
  /// type with a wider range. NOTE: found at tiny gamma under a large load, where the
  /// dissipated energy's coefficients fall below 2^-969 while the linear law's entire
  /// series allow long steps (linear law, gamma = 1e-280, g = 1e6: 10 of 1 - e's 31
  /// digits right at 25 digits; gamma = 1e-305 in double: 5 of 17).
  void require_precise_jet(const Real& h) const {
    using limits = std::numeric_limits<Real>;
    if constexpr (limits::max_exponent <= std::numeric_limits<double>::max_exponent) {
      using std::abs;
      const Real smallest = limits::min();
      if (!any_subnormal_coefficient(smallest)) return;  // an underflow left no coefficient subnormal
      const double log_h = detail::log_abs(h), log_tolerance = detail::log_abs(m_tolerance);
      const double log_error = std::log(std::numeric_limits<double>::denorm_min()) + 14 * std::log(2.0);
      for (std::size_t i = 0; i < m_jet.size(); ++i) {
        const Real* c = m_jet[i];
        const Real scale = std::max(abs(m_system.step_scale(i, c[0])), Real(abs(c[1] * h)));
        if (!(scale > 0)) continue;
        const double allowed = log_tolerance + detail::log_abs(scale);
        for (std::size_t k = 1; k <= m_order; ++k)
          if (c[k] != 0 && abs(c[k]) < smallest && log_error + static_cast<double>(k) * log_h > allowed)
            throw exponent_range_exceeded("the Taylor coefficient of order " + std::to_string(k) + " of component " +
                                          std::to_string(i) + " underflows the working type where it matters");
      }
    }
  }

  /// True when some nonzero Taylor coefficient of order >= 1 is below `smallest`.
  bool any_subnormal_coefficient(const Real& smallest) const {
    using std::abs;
    for (std::size_t i = 0; i < m_jet.size(); ++i)
      for (std::size_t k = 1; k <= m_order; ++k)
        if (m_jet[i][k] != 0 && abs(m_jet[i][k]) < smallest) return true;
    return false;
  }

  /// The Jorba-Zou step of the current jet (see the file comment), capped at |h_max|.
  /// NOTE: computed in double (logarithms of the coefficients): a step needs a
  /// few digits, and log/exp at the working precision are costly (docs/performance.md).
  Real step_size(const Real& h_max) const {
    using std::abs;
    using boost::math::isfinite;
    const std::size_t p = m_order;
    // max over states and orders of log(|x_i[k]| / s_i) / k = -log(rho)
    double log_inv_rho = -std::numeric_limits<double>::infinity();
    bool any = false;
    for (std::size_t i = 0; i < m_jet.size(); ++i) {
      const Real* c = m_jet[i];
      const Real scale = m_system.step_scale(i, c[0]);
      if (!(scale > 0)) continue;
      const double log_scale = detail::log_abs(scale);
      // NOTE: Jorba-Zou use orders p-1 and p. Series of the endpoint systems can
      // be sparse (only every Q(alpha+1)-th term at s = 0), so we take the
      // smallest radius over the last m_window orders: never larger, and never
      // blind to a series whose last two terms happen to vanish.
      for (std::size_t k = p + 1 - m_window; k <= p; ++k) {
        if (c[k] == 0) continue;
        const double l = (detail::log_abs(c[k]) - log_scale) / static_cast<double>(k);
        if (!any || l > log_inv_rho || std::isnan(l)) log_inv_rho = l;
        any = true;
      }
    }
    Real h = abs(h_max);
    if (any && !std::isnan(log_inv_rho)) {
      // h = rho exp(-0.7/(p-1)) / e^2 = 2^l2, built from its binary exponent (the
      // range of Real may exceed double's)
      const Real jz = power_of_e(m_log_safety - log_inv_rho);
      if (isfinite(jz) && jz < h) h = jz;
    }
    if constexpr (taylor_system_with_tail<System>) limit_tail(h);
    if (h_max < 0) h = -h;
    limit_cancellation(h);
    return h;
  }

  /// Caps h > 0 so that the orders the system computed in lower precision (from
  /// tail_start() on) stay below its bound: |x_i[k]| h^k <= exp(tail_log_bound()) s_i.
  void limit_tail(Real& h) const {
    const std::size_t start = m_system.tail_start();
    if (start > m_order) return;
    const double log_bound = m_system.tail_log_bound();
    double l_max = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m_jet.size(); ++i) {
      const Real* c = m_jet[i];
      const Real scale = m_system.step_scale(i, c[0]);
      if (!(scale > 0)) continue;
      const double log_scale = detail::log_abs(scale) + log_bound;
      for (std::size_t k = start; k <= m_order; ++k)
        if (c[k] != 0) l_max = std::max(l_max, (detail::log_abs(c[k]) - log_scale) / static_cast<double>(k));
    }
    if (!std::isfinite(l_max)) return;
    const Real cap = power_of_e(-l_max);
    if (cap < h) h = cap;
  }

  /// e^l as a Real, built from its binary exponent (Real's range may exceed double's).
  static Real power_of_e(double l) {
    using std::ldexp;
    constexpr double ln2 = 0.693147180559945309417;
    const double l2 = std::clamp(l / ln2, -1e9, 1e9);
    const double n = std::floor(l2);
    return ldexp(Real(std::exp2(l2 - n)), static_cast<int>(n));
  }

  /// Shrinks h until no component's step polynomial cancels by more than a
  /// factor m_cancellation: sum_k |x_i[k] h^k| <= K max(s_i, |x_i(t0 + h)|).
  /// NOTE: the Horner sum's rounding error is ~eps sum |x_i[k] h^k|. For entire
  /// solutions (fast decaying modes, e^(-lambda t)) the Jorba-Zou radius grows
  /// like p/e with the order, and the sum with it like e^(lambda h), so that
  /// digits are lost at high orders (docs/performance.md). The sums are formed
  /// in double from the logarithms of the terms (a factor 8 needs no more).
  void limit_cancellation(Real& h) const {
    // NOTE: the worst case, an entire series (x^k/k! at the Jorba-Zou step,
    // x = p/e^3), sums to e^(p/e^3): below the factor K = 8 up to p = 41
    // (double, long double, float128), so there the check is skipped.
    if (m_order <= 41) return;
    const std::size_t n = m_jet.size(), stride = m_order + 1;
    m_log.resize(n * stride);
    m_negative.resize(n * stride);
    m_log_scale.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Real* c = m_jet[i];
      const Real scale = m_system.step_scale(i, c[0]);
      m_log_scale[i] = scale > 0 ? detail::log_abs(scale) : std::numeric_limits<double>::quiet_NaN();
      for (std::size_t k = 0; k <= m_order; ++k) {
        m_log[i * stride + k] = detail::log_abs(c[k]);
        m_negative[i * stride + k] = c[k] < 0;
      }
    }
    for (int tries = 0; tries < 64; ++tries) {
      const double log_h = detail::log_abs(h);
      const bool h_negative = h < 0;
      bool ok = true;
      for (std::size_t i = 0; i < n && ok; ++i) {
        if (std::isnan(m_log_scale[i])) continue;
        const double* l = &m_log[i * stride];
        double top = -std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k <= m_order; ++k) top = std::max(top, l[k] + static_cast<double>(k) * log_h);
        if (!std::isfinite(top)) continue;
        double sum = 0, value = 0;
        for (std::size_t k = 0; k <= m_order; ++k) {
          const double term = std::exp(l[k] + static_cast<double>(k) * log_h - top);
          sum += term;
          value += (m_negative[i * stride + k] != (h_negative && k % 2 == 1)) ? -term : term;
        }
        const double floor = std::exp(m_log_scale[i] - top);
        ok = sum <= m_cancellation * std::max(std::fabs(value), floor);
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
  double m_log_safety;   // ln(exp(-0.7/(p-1)) / e^2)
  double m_cancellation = 8;  // at most one digit lost to cancellation per step
  mutable std::vector<double> m_log, m_log_scale;  // scratch of limit_cancellation
  mutable std::vector<bool> m_negative;
};

}  // namespace viscor
