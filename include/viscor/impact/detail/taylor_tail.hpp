// The high orders of a Taylor jet in double ("the tail"), for the impact systems.
//
// A coefficient of order k enters the step polynomial as |x[k] h^k| ~ e^(-2k) of the
// state at the Jorba-Zou step (taylor_integrator.hpp), so past an order k_t of about
// (digits of Real - 16) ln(10)/2 its relative accuracy need not exceed double's. For
// float128 that is the top 13 of 40 orders, about half of the products of a jet, done
// in hardware instead of in software (libgcc's soft-float). taylor_integrator caps the
// step so that the orders computed in double contribute less than the tolerance
// (log_bound; tested against 50-digit jets in taylor_tail_test). MPFR types keep their
// own arithmetic: double would take a smaller share of their orders (a third at 50
// digits), and their exponent range and run-time precision want more care.
//
// The tail runs in the independent variable h' = h / H, H = 2^m near the radius of
// convergence: coefficient k times H^k is then of order 1, inside double's exponent
// range whatever Real's, and the system's right-hand sides are multiplied by H.
//
// The tail declines (the jet is finished in Real) whenever double's relative error
// model could fail or the step cap could not see its error: a constant (gamma, g,
// ...) or an input coefficient that is nonzero in Real but not a normal double
// (gamma = 1e-320 is subnormal there, 1e-400 zero); a non-finite or subnormal
// output; or nonzero tail orders in a state that is 0 at the expansion point (tau
// and D at the start of contact), whose step scale is 0, so that the cap
// (taylor_integrator::limit_tail) skips it.
#pragma once

#include <viscor/core/detail/log_abs.hpp>
#include <viscor/core/real_types.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <type_traits>

namespace viscor::detail {

/// The arithmetic of the tail for Real (void: none).
template <class Real>
struct taylor_tail {
  using type = void;
};
#if VISCOR_HAS_FLOAT128
template <>
struct taylor_tail<quad> {
  using type = double;
};
#endif

template <class Real>
inline constexpr bool has_taylor_tail = !std::is_void_v<typename taylor_tail<Real>::type>;

/// Where a system's tail starts and what bounds it, and the conversions to and from it.
template <class Real>
class tail_plan {
 public:
  using arithmetic = std::conditional_t<has_taylor_tail<Real>, typename taylor_tail<Real>::type, double>;

  // A coefficient computed in the tail is off by ~ 4 p eps_d of itself (k-term sums,
  // one rounding each, inputs rounded to double); over the ~p/2 tail orders that stays
  // below tol/4 if |x[k] h^k| <= B s, B = tol / (8 p^2 eps_d): at the Jorba-Zou step
  // from order -ln(B)/2 on.
  tail_plan(std::size_t order, const Real& tolerance) : m_split(order) {
    if constexpr (has_taylor_tail<Real>) {
      const double p = static_cast<double>(order);
      const double eps = std::numeric_limits<arithmetic>::epsilon();
      m_log_bound = log_abs(tolerance) - std::log(8 * p * p * eps);
      const double start = std::ceil(-m_log_bound / 2) + 1;
      if (start >= 2 && start + 2 <= p) m_split = static_cast<std::size_t>(start);
    }
  }

  /// Orders 0..split() in Real, split() + 1.. in the tail (split() == order: no tail).
  std::size_t split() const { return m_split; }
  /// ln B: the tail orders must satisfy |x_i[k] h^k| <= B s_i at the step taken.
  double log_bound() const { return m_log_bound; }

  /// Computes orders 1..p of a jet: orders(from, to) in Real up to split(), then
  /// tail(split()) beyond, or orders(split(), p) again when the tail declines (false).
  /// Returns the first order the tail computed (p + 1: none). NOTE: tail must be a
  /// generic lambda, so that types without a tail never instantiate its body.
  template <class Orders, class Tail>
  std::size_t run(std::size_t p, Orders&& orders, Tail&& tail) const {
    const std::size_t split = std::min(m_split, p);
    orders(std::size_t(0), split);
    if constexpr (has_taylor_tail<Real>) {
      if (split < p) {
        if (tail(split)) return split + 1;
        orders(split, p);
      }
    }
    return p + 1;
  }

  /// m with H = 2^m near the radius of convergence seen by orders split - 1 and split
  /// of the given series (relative to max(1, |x[0]|)).
  int scale_exponent(std::initializer_list<const Real*> series) const {
    double l = -std::numeric_limits<double>::infinity();
    for (const Real* c : series) {
      const double log_scale = std::max(0.0, log_abs(c[0]));
      for (std::size_t k = m_split - 1; k <= m_split; ++k)
        if (c[k] != 0) l = std::max(l, (log_abs(c[k]) - log_scale) / static_cast<double>(k));
    }
    return std::isfinite(l) ? static_cast<int>(std::lround(-l / std::log(2.0))) : 0;
  }

  /// to[k] = from[k] 2^(k m + shift), k = 0..last; false if one leaves double's
  /// normal range (overflow, or a nonzero value that becomes subnormal or 0).
  static bool down(const Real* from, arithmetic* to, std::size_t last, int m, int shift = 0) {
    using std::ldexp;
    for (std::size_t k = 0; k <= last; ++k) {
      to[k] = static_cast<arithmetic>(ldexp(from[k], static_cast<int>(k) * m + shift));
      if (to[k] == 0 ? from[k] != 0 : !std::isnormal(to[k])) return false;
    }
    return true;
  }

  /// c in the tail arithmetic; `ok` becomes false unless c is 0 or a normal double
  /// (a constant outside double's normal range switches the tail off).
  static arithmetic constant(const Real& c, bool& ok) {
    const arithmetic x = static_cast<arithmetic>(c);
    if (x == 0 ? c != 0 : !std::isnormal(x)) ok = false;
    return x;
  }

  /// True if t[first..last] are all 0 or normal doubles (no overflow, NaN or underflow).
  static bool outputs_in_range(const arithmetic* t, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k <= last; ++k)
      if (t[k] != 0 && !std::isnormal(t[k])) return false;
    return true;
  }

  /// True if t[first..last] are all 0: what the tail may add to a state that is 0
  /// at the expansion point (the step cap measures states relative to their value).
  static bool all_zero(const arithmetic* t, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k <= last; ++k)
      if (t[k] != 0) return false;
    return true;
  }

  /// to[k] = from[k] 2^(-k m), k = first..last.
  static void up(const arithmetic* from, Real* to, std::size_t first, std::size_t last, int m) {
    using std::ldexp;
    for (std::size_t k = first; k <= last; ++k) to[k] = ldexp(Real(from[k]), -static_cast<int>(k) * m);
  }

 private:
  std::size_t m_split;
  double m_log_bound = 0;
};

}  // namespace viscor::detail

#if defined(VISCOR_HAS_QD) && VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>

namespace viscor::detail {
/// double_double: the same tail in double (in hardware, as its working arithmetic): at
/// 31 digits the top 13 of 37 orders, more than half of the products of a jet.
template <>
struct taylor_tail<double_double> {
  using type = double;
};
}  // namespace viscor::detail
#endif
