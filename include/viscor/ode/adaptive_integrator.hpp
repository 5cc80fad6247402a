// Gragg-Bulirsch-Stoer extrapolation with adaptive order and step: viscor's
// second integrator, independent of the Taylor-series one in algorithm and code.
//
// Method (Hairer, Norsett, Wanner, "Solving ODEs I", sec. II.9, code ODEX;
// Deuflhard 1983): over a step H the modified midpoint rule (Gragg 1965) with
// n_j = 2(j+1) sub-steps gives T_{j,0}, whose error has an expansion in even
// powers of H/n_j; polynomial extrapolation to zero step (the Aitken-Neville
// tableau's T_{j,k}, here evaluated directly from precomputed Lagrange weights, see
// weighted_sum) makes T_{j,j} of order 2j+2, and |T_{j,j} - T_{j,j-1}| estimates the error.
// Column count (order) and step are chosen together to minimise the work per
// unit step A_j/H_j, A_j = 1 + n_0 + ... + n_j right-hand-side evaluations.
//
// NOTE: why this reaches 50 and 100 digits in reasonable time: the order is not
// capped at a small constant (Boost.Odeint's bulirsch_stoer stops at order 16); the
// column count grows with the requested digits, so a step stays a sizeable fraction
// of the radius of convergence, and the work per step grows only like j^2
// (harmonic sequence), i.e. quadratically in the digits, as for a Taylor method.
//
// NOTE: rounding. The harmonic sequence's extrapolation amplifies the rounding
// errors of the T_{j,0} by its Lebesgue constant, about 10^(0.33 j). The midpoint
// columns therefore run on increments d = z - y from the step's start, so that their
// rounding is relative to the increment (a tenth of the state or less) rather than
// to the state. gbs_work<Real> names a wider type to integrate in (guard digits),
// and gbs_max_columns caps j to what those guard digits absorb; callers that
// integrate in Real itself lose ~0.3 j - 1 digits.
//
// Measurements behind these and the choices below: docs/performance.md,
// "ode/adaptive_integrator.hpp".
#pragma once

#include <viscor/core/detail/log_abs.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace viscor {

namespace detail {
/// The type GBS integrates in when the caller wants results good to Real's
/// precision, and the decimal guard digits it adds (mpfr types: run-time
/// mpfr_real at decimal_digits<Real>() + guard, set with scoped_precision).
template <class Real>
struct gbs_work {
  using type = Real;
  static int guard_digits() { return 0; }
};
#if VISCOR_HAS_MPFR
// NOTE: MPFR's cost goes by 64-bit limbs, not by bits, so the work precision is
// rounded up to whole limbs: those guard digits are free. (mpfr_50's 57 digits
// forgo MPFR's faster products below 188 bits: 55 digits are too few guard digits.)
// Decimal digits of the widest Boost mpfr precision in as many limbs as `digits10`.
constexpr unsigned mpfr_limb_filled_digits(unsigned digits10) {
  using boost::multiprecision::detail::digits10_2_2;
  const unsigned long limb = GMP_NUMB_BITS;
  const unsigned long bits = (digits10_2_2(digits10) + limb - 1) / limb * limb;
  unsigned d = digits10;
  while (digits10_2_2(d + 1) <= bits) ++d;
  return d;
}
// Least guard digits for a target of D digits: the tolerance 10^-(D+2) starts GBS at
// about D/4 + 4 columns, whose rounding growth (about 0.3 digits per column on the
// increments, see the header comment) is then D/12 + 1 digits; 2 more for safety.
constexpr unsigned mpfr_min_guard_digits(unsigned digits10) { return 3 + digits10 / 12; }
template <class Real>
int mpfr_guard_digits() {
  const auto d = static_cast<unsigned>(decimal_digits<Real>());
  return static_cast<int>(mpfr_limb_filled_digits(d + mpfr_min_guard_digits(d)) - d);
}
#endif

/// The GBS work type of a built-in type Real, chosen by width (never by name): the
/// first of long double, float128 that carries at least MinGuard decimal digits
/// more than Real, else mpfr_real at decimal_digits<Real>() + MinGuard + d/8 digits
/// filled to the limb. So where long double is double (MSVC) or binary128 (aarch64
/// Linux), the work type is still wider than Real by the intended margin.
template <class Real, int MinGuard>
struct gbs_work_by_width {
  static constexpr int working = fixed_decimal_digits<Real>();
  static constexpr bool long_double_wide = fixed_decimal_digits<long double>() >= working + MinGuard;
#if VISCOR_HAS_FLOAT128
  static constexpr bool quad_wide = fixed_decimal_digits<quad>() >= working + MinGuard;
  using quad_or_void = quad;
#else
  static constexpr bool quad_wide = false;
  using quad_or_void = void;
#endif
#if VISCOR_HAS_MPFR
  using mpfr_or_void = mpfr_real;
#else
  using mpfr_or_void = void;
#endif
  using type = std::conditional_t<long_double_wide, long double, std::conditional_t<quad_wide, quad_or_void, mpfr_or_void>>;
  static_assert(!std::is_void_v<type>, "no scalar type wider than Real by MinGuard digits for GBS (build with MPFR)");
  static int guard_digits() {
#if VISCOR_HAS_MPFR
    if constexpr (std::is_same_v<type, mpfr_real>) {
      const auto d = static_cast<unsigned>(working);
      return static_cast<int>(mpfr_limb_filled_digits(d + MinGuard + d / 8) - d);
    } else
#endif
    {
      static_assert(fixed_decimal_digits<type>() - working >= MinGuard);
      return fixed_decimal_digits<type>() - working;
    }
  }
};
/// double: 3 guard digits (x87 long double: 18 - 15).
template <>
struct gbs_work<double> : gbs_work_by_width<double, 3> {};
/// long double: 10 or more (float128 over x87: 33 - 18 = 15).
template <>
struct gbs_work<long double> : gbs_work_by_width<long double, 10> {};
#if VISCOR_HAS_FLOAT128
/// float128: mpfr_real at 33 + 10 + 33/8 digits filled to the limb (57).
template <>
struct gbs_work<quad> : gbs_work_by_width<quad, 10> {};
#endif
#if VISCOR_HAS_MPFR
/// Fixed-precision mpfr types integrate in a wider fixed type with limbs on the
/// stack: no allocation and no thread-default-precision look-up per operation.
/// mpfr_50: 57 digits (3 limbs, guard 7); mpfr_100: 115 digits (6 limbs, guard 15).
template <unsigned D, boost::multiprecision::mpfr_allocation_type A, boost::multiprecision::expression_template_option ET>
struct gbs_work<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D, A>, ET>> {
  static constexpr unsigned digits = mpfr_limb_filled_digits(D + mpfr_min_guard_digits(D));
  using type = boost::multiprecision::number<
      boost::multiprecision::mpfr_float_backend<digits, boost::multiprecision::allocate_stack>>;
  static int guard_digits() { return static_cast<int>(digits - D); }
  static_assert(digits >= D + mpfr_min_guard_digits(D), "the GBS work type must be wider than mpfr at D digits");
  // NOTE: a wider type (the former 10 + D/8 guard digits, filled: mpfr_50 76 digits,
  // mpfr_100 134) for when the tolerance asks for more digits than `type` can
  // resolve: under a large load g it shrinks by 1 + |g| (solve_impact_adaptive).
  static constexpr bool has_wide = true;
  static constexpr unsigned wide_digits = mpfr_limb_filled_digits(D + 10 + D / 8);
  using wide_type = boost::multiprecision::number<
      boost::multiprecision::mpfr_float_backend<wide_digits, boost::multiprecision::allocate_stack>>;
  static int wide_guard_digits() { return static_cast<int>(wide_digits - D); }
};
template <boost::multiprecision::mpfr_allocation_type A, boost::multiprecision::expression_template_option ET>
struct gbs_work<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0, A>, ET>> {
  using type = mpfr_real;
  static int guard_digits() { return mpfr_guard_digits<mpfr_real>(); }
};
#endif

/// Largest column index worth computing in type Work when `guard` decimal digits
/// absorb the extrapolation's rounding growth: about 0.3 digits per column on the
/// increments, which are typically a tenth of the state or less (1 digit back).
inline int gbs_max_columns(int work_decimal_digits, int guard) {
  const int by_guard = guard > 0 ? (guard + 1) * 10 / 3 : 6;
  const int by_need = work_decimal_digits / 3 + 6;  // no use going beyond order ~ digits
  return std::clamp(std::min(by_guard, by_need), 3, 64);
}

/// Rounding floor for the local tolerance in type Work: the noise of the error
/// estimate at the column count the tolerance itself calls for (digits/4 + 4).
template <class Work>
Work gbs_rounding_floor(const Work& rtol) {
  using std::log10;
  using std::pow;
  const double digits = -static_cast<double>(log10(rtol));
  const double columns = digits / 4 + 4;
  return epsilon<Work>() * pow(Work(10), Work(static_cast<int>(3 * columns) - 10) / 10);
}
}  // namespace detail

/// Outcome of one attempted GBS step.
enum class gbs_status {
  accepted,      ///< t, y advanced; h holds the proposed next step
  rejected,      ///< error too large; h holds a smaller step to retry with
  domain_error,  ///< the right-hand side refused a stage (left its domain); h halved
  non_finite,    ///< y or f(t, y) at the step's start is not finite: no step size helps; t, y, h unchanged
};

/// A GBS extrapolation stepper for y' = f(t, y), y in Real^N, any precision.
/// The right-hand side is `bool f(const Real& t, const std::array<Real, N>& y,
/// std::array<Real, N>& dydt)`, returning false when y is outside its domain.
/// Error control per component: |err_i| <= atol_i + rtol * max(|y_i|, |y_new_i|).
template <class Real, std::size_t N>
class gbs_integrator {
 public:
  using state = std::array<Real, N>;

  /// An integrator for relative tolerance rtol, absolute tolerances atol, at most max_columns extrapolation columns (>= 2).
  gbs_integrator(const Real& rtol, const state& atol, int max_columns)
      : m_rtol(rtol), m_atol(atol), m_max_columns(std::max(max_columns, 2)) {
    // Start near the order the tolerance needs: about digits/4 + 4 columns.
    using std::frexp;
    int binary_exponent = 0;
    frexp(rtol, &binary_exponent);
    m_columns = std::clamp(static_cast<int>(-binary_exponent * 0.30103 / 4) + 4, 2, m_max_columns);
    // NOTE: extrapolation by precomputed Lagrange weights at h = 0 rather than the
    // Aitken-Neville tableau. Only T_{j,j} and T_{j,j} - T_{j,j-1} at the 3-4
    // columns around the target order are ever read; the tableau computes all
    // j(j+1)/2 entries per step, the weights 2(j+1) per needed column. The
    // polynomial in h^2 through (1/n_i^2, T_{i,0}), i = lo..j, at 0 has weights
    //     w_i = prod_{k != i} n_i^2 / (n_i^2 - n_k^2) = prod_{k != i} (i+1)^2 / ((i+1)^2 - (k+1)^2),
    // products of exact integer ratios, rounded once per factor in Real. The sums
    // amplify rounding by sum |w_i|, the same Lebesgue constant as the tableau.
    const int size = m_max_columns + 2;
    m_columns_values.assign(size, state{});
    m_errors.assign(size, Real(0));
  }

  /// Whether try_step records the nodes of the accepted column (event detection).
  void set_keep_nodes(bool keep) { m_keep_nodes = keep; }
  /// Whether f ignores t (then the stage times are not computed: f gets the step's start).
  void set_autonomous(bool autonomous) { m_autonomous = autonomous; }
  /// f reads only the first k components of y (quadratures riding along): the others
  /// of the stage states are not formed (they hold stale values when f sees them).
  void set_read_components(std::size_t k) { m_read = std::min(k, N); }

  /// Current target column index (order 2 * columns + 2).
  int columns() const { return m_columns; }
  /// Sets the target column index, clamped to [2, max_columns()].
  void set_columns(int k) { m_columns = std::clamp(k, 2, m_max_columns); }
  /// The largest column index allowed.
  int max_columns() const { return m_max_columns; }
  /// Column index and scaled error estimate (<= 1) of the last accepted step.
  int last_columns() const { return m_last_columns; }
  /// The scaled error estimate (<= 1) of the last accepted step.
  const Real& last_error() const { return m_last_error; }
  /// Absolute error estimate per component of the last accepted step.
  const state& last_error_vector() const { return m_last_error_vector; }
  /// Right-hand-side evaluations so far.
  std::size_t evaluations() const { return m_evaluations; }
  /// States at the nodes t + m H/n (m = 0..n) of the finest midpoint column of
  /// the last accepted step (O(h^2)-accurate: for event detection, not output).
  const std::vector<state>& nodes() const { return m_nodes; }
  /// The times of nodes().
  const std::vector<Real>& node_times() const { return m_node_times; }

  /// Attempts one step of signed length h from (t, y). On success advances t, y
  /// and sets h to the proposed next step (never more than max_growth * |h|).
  template <class F>
  gbs_status try_step(F& f, Real& t, state& y, Real& h) {
    using std::abs;
    using std::pow;
    using boost::math::isfinite;
    if (!f(t, y, m_f0)) {
      h /= 2;
      return gbs_status::domain_error;
    }
    ++m_evaluations;
    for (std::size_t i = 0; i < N; ++i)
      if (!isfinite(y[i]) || !isfinite(m_f0[i])) return gbs_status::non_finite;
    const int kt = m_columns;
    const int last = std::min(kt + 1, m_max_columns);
    Real last_h = h;
    int last_j = kt;
    for (int j = 0; j <= last; ++j) {
      if (!midpoint(f, t, y, h, j, m_columns_values[j], m_keep_nodes && j >= kt - 1)) {
        h /= 2;
        m_rejected = true;
        return gbs_status::domain_error;
      }
      // accept() reads the error of j - 1 >= kt - 2 (order selection).
      if (j == 0 || j < kt - 2) continue;
      const Real err = error_norm(y, j);
      m_errors[j] = err;
      if (!isfinite(err)) {
        h /= 4;
        m_rejected = true;
        return gbs_status::rejected;
      }
      if (j < kt - 1) continue;
      const Real hj = optimal_step(h, err, j);
      last_h = hj, last_j = j;
      if (err <= 1) {
        accept(t, y, h, j, err, hj, Real(Real(work_of(j)) / abs(hj)));
        return gbs_status::accepted;
      }
      // Convergence monitor (ODEX): give up when even one more column cannot
      // bring the error below 1 (each column gains about (n_{j+1}/n_0)^2).
      const Real growth = Real(j + 2) * (j + 2);
      if (j >= kt && err > growth) break;
    }
    // Rejected: retry at the same order with the step its error estimate asks for.
    m_columns = std::clamp(last_j, 2, m_max_columns);
    h = abs(last_h) < abs(h) * Real(9) / 10 ? last_h : Real(h / 2);
    m_rejected = true;
    return gbs_status::rejected;
  }

  /// A step of length h with exactly `columns` columns and no error control
  /// (event location: h below an accepted step is at least as accurate).
  template <class F>
  bool fixed_step(F& f, const Real& t, const state& y, const Real& h, int columns, state& out) {
    if (!f(t, y, m_f0)) return false;
    ++m_evaluations;
    for (int j = 0; j <= columns; ++j)
      if (!midpoint(f, t, y, h, j, m_columns_values[j], false)) return false;
    extrapolated(columns, m_increment);
    for (std::size_t i = 0; i < N; ++i) out[i] = y[i] + m_increment[i];
    return true;
  }

  /// Marks the start of a fresh integration (forget the last rejection).
  void reset_rejection() { m_rejected = false; }

 private:
  static long long work_of(int j) { return 1 + static_cast<long long>(j + 1) * (j + 2); }

  // Gragg's modified midpoint rule with n = 2(j+1) sub-steps; `out` receives the
  // increment z_n - y (see the note on increments in the header comment).
  // NOTE: d_{m-1} and d_m alternate between m_z0 and m_z1 by pointer: swapping
  // stack-allocated mpfr numbers copies their limbs three times.
  template <class F>
  bool midpoint(F& f, const Real& t, const state& y, const Real& H, int j, state& out, bool keep_nodes) {
    using boost::math::isfinite;
    const int n = 2 * (j + 1);
    m_h = H / n;
    m_two_h = 2 * m_h;
    state* previous = &m_z0;  // d_{m-1} = z_{m-1} - y
    state* current = &m_z1;   // d_m
    for (std::size_t i = 0; i < N; ++i) {
      (*previous)[i] = 0;
      (*current)[i] = m_h * m_f0[i];
    }
    if (keep_nodes) {
      m_scratch_nodes.resize(n + 1);
      m_scratch_times.resize(n + 1);
      m_scratch_nodes[0] = y;
      m_scratch_times[0] = t;
    }
    for (int m = 1; m < n; ++m) {
      for (std::size_t i = 0; i < m_read; ++i) m_arg[i] = y[i] + (*current)[i];  // z_m
      if (m_autonomous) {
        if (!f(t, m_arg, m_fz)) return false;
      } else {
        m_tm = m_h;
        m_tm *= m;
        m_tm += t;
        if (!f(m_tm, m_arg, m_fz)) return false;
      }
      ++m_evaluations;
      if (keep_nodes) {
        m_scratch_nodes[m] = m_arg;
        for (std::size_t i = m_read; i < N; ++i) m_scratch_nodes[m][i] = y[i] + (*current)[i];
        m_scratch_times[m] = t + m * m_h;
      }
      for (std::size_t i = 0; i < N; ++i) {  // d_{m+1}
        // NOTE: product then sum, not one fused multiply-add: mpfr_fma costs more
        // than both, and its single rounding buys nothing here.
        m_tmp = m_two_h * m_fz[i];
        (*previous)[i] += m_tmp;
      }
      std::swap(previous, current);
    }
    for (std::size_t i = 0; i < N; ++i)
      if (!isfinite((*current)[i])) return false;
    out = *current;
    if (keep_nodes) {
      for (std::size_t i = 0; i < N; ++i) m_scratch_nodes[n][i] = y[i] + (*current)[i];
      m_scratch_times[n] = t + H;
    }
    return true;
  }

  // sum_i weights[i] T_{i,0} into out, where j = weights.size() - 1 and the weights
  // sum to 1 (with_base: T_{j,j}) or to 0 (the error estimate T_{j,j} - T_{j,j-1}),
  // evaluated as [T_{j,0} +] sum_{i < j} weights[i] (T_{i,0} - T_{j,0}).
  // NOTE: on the differences from the finest column, not on the T_{i,0}: the
  // common part then cancels exactly, and the weights' own rounding (about j ulps)
  // multiplies only the truncation-sized T_{i,0} - T_{j,0}, which is small exactly
  // where the weights are large. Applied to the T_{i,0} themselves it multiplied
  // the whole increment and swamped the error estimate (many rejected steps).
  void weighted_sum(const std::vector<Real>& weights, bool with_base, state& out) {
    const std::size_t j = weights.size() - 1;
    for (std::size_t c = 0; c < N; ++c) {
      if (with_base)
        out[c] = m_columns_values[j][c];
      else
        out[c] = 0;
      for (std::size_t i = 0; i < j; ++i) {
        m_tmp = m_columns_values[i][c] - m_columns_values[j][c];
        m_tmp *= weights[i];
        out[c] += m_tmp;
      }
    }
  }
  // T_{j,j}, the extrapolated increment over the step.
  void extrapolated(int j, state& out) { weighted_sum(weights_of(j), true, out); }

  // w_i for the columns lo..j (zeros below lo) into w.
  static void lagrange_weights(int lo, int j, std::vector<Real>& w) {
    w.assign(j + 1, Real(0));
    for (int i = lo; i <= j; ++i) {
      Real x = 1;
      const long long a = static_cast<long long>(i + 1) * (i + 1);
      for (int k = lo; k <= j; ++k) {
        if (k == i) continue;
        const long long b = static_cast<long long>(k + 1) * (k + 1);
        x *= Real(a) / Real(a - b);
      }
      w[i] = x;
    }
  }
  // The weights of T_{j,j} and of T_{j,j} - T_{j,j-1}, computed when first needed
  // (O(j^2) operations each) and kept per thread and precision: a solve builds two
  // integrators and needs only a handful of j, too few to amortise a fresh computation.
  struct weight_cache {
    int binary_digits = -1;
    std::vector<std::vector<Real>> weights, error_weights;
  };
  // The cache for the current precision (run-time mpfr: the thread's default,
  // which every Real of this integrator has), with room for column j.
  static weight_cache& weights_cache(int j) {
    static thread_local weight_cache cache;
    const int digits = binary_digits<Real>();
    if (cache.binary_digits != digits) cache = weight_cache{digits, {}, {}};
    if (static_cast<int>(cache.weights.size()) <= j) {
      cache.weights.resize(j + 1);
      cache.error_weights.resize(j + 1);
    }
    return cache;
  }
  const std::vector<Real>& weights_of(int j) {
    auto& w = weights_cache(j).weights[j];
    if (w.empty()) lagrange_weights(0, j, w);
    return w;
  }
  const std::vector<Real>& error_weights_of(int j) {
    const std::vector<Real>& full = weights_of(j);
    auto& e = weights_cache(j).error_weights[j];
    if (e.empty()) {
      std::vector<Real> lower;
      lagrange_weights(1, j, lower);  // T_{j,j-1}: columns 1..j
      e = full;
      for (int i = 1; i <= j; ++i) e[i] -= lower[i];
    }
    return e;
  }

  Real error_norm(const state& y, int j) {
    using boost::math::isfinite;
    using std::abs;
    using std::max;
    weighted_sum(error_weights_of(j), false, m_difference);  // T_{j,j} - T_{j,j-1}
    Real worst = 0;
    for (std::size_t i = 0; i < N; ++i) {
      // |y| at both ends; the finest midpoint value stands in for T_{j,j} in the
      // scale (they differ by its truncation error, far below |y|).
      m_tmp = y[i] + m_columns_values[j][i];
      const Real scale = m_atol[i] + m_rtol * max(abs(y[i]), abs(m_tmp));
      const Real diff = abs(m_difference[i]);
      // A non-finite difference is an infinite error (the step is retried shorter), never ignored.
      if (!isfinite(diff)) return std::numeric_limits<Real>::infinity();
      m_err_vector[i] = diff;
      if (scale > 0) {
        const Real r = diff / scale;
        if (r > worst) worst = r;
      } else if (diff > 0) {
        return Real(1) / epsilon<Real>();  // nothing to measure against: treat as huge
      }
    }
    return worst;
  }

  // H_j = H * 0.94 (0.65/err)^(1/(2j+1)), the factor clamped to [1/50, 4] (ODEX).
  // NOTE: the factor in double from ln(err) (err may lie outside double's range):
  // a step needs two digits, and pow at the working precision is costly.
  Real optimal_step(const Real& H, const Real& err, int j) const {
    if (err == 0) return H * 4;
    const double log_factor = (std::log(0.65) - detail::log_abs(err)) / (2 * j + 1);
    const double factor = std::clamp(0.94 * std::exp(log_factor), 1.0 / 50, 4.0);
    return H * Real(factor);
  }

  void accept(Real& t, state& y, Real& h, int j, const Real& err, const Real& hj, const Real& work) {
    using std::abs;
    t += h;
    extrapolated(j, m_increment);
    for (std::size_t i = 0; i < N; ++i) y[i] += m_increment[i];
    m_last_columns = j;
    m_last_error = err;
    for (std::size_t i = 0; i < N; ++i) m_last_error_vector[i] = m_err_vector[i];
    m_nodes.swap(m_scratch_nodes);
    m_node_times.swap(m_scratch_times);
    // Next order: the cheapest per unit step among j - 1, j and j + 1, the error of
    // j + 1 predicted from the trend err_j^2 / err_{j-1} (columns converge about
    // geometrically); a change needs a 10% gain.
    int k_new = j;
    Real h_new = hj, best = work;
    if (j - 1 >= 2) {
      const Real h_lower = optimal_step(h, m_errors[j - 1], j - 1);
      const Real work_lower = Real(work_of(j - 1)) / abs(h_lower);
      if (work_lower < Real(9) / 10 * best) k_new = j - 1, h_new = h_lower, best = work_lower;
    }
    if (j + 1 <= m_max_columns && j >= 2 && m_errors[j - 1] > 0 && k_new == j) {
      const Real predicted = err * (err / m_errors[j - 1]);
      const Real h_higher = optimal_step(h, predicted, j + 1);
      const Real work_higher = Real(work_of(j + 1)) / abs(h_higher);
      if (work_higher < Real(9) / 10 * best) k_new = j + 1, h_new = h_higher, best = work_higher;
    }
    if (m_rejected) {  // after a rejection, do not grow (ODEX)
      if (abs(h_new) > abs(h)) h_new = h;
      k_new = std::min(k_new, m_columns);
    }
    m_columns = std::clamp(k_new, 2, m_max_columns);
    m_rejected = false;
    h = h_new;
  }

  Real m_rtol;
  state m_atol;
  int m_max_columns;
  int m_columns = 2;
  bool m_rejected = false;
  bool m_keep_nodes = true;
  bool m_autonomous = false;
  std::size_t m_read = N;
  int m_last_columns = 0;
  Real m_last_error = 0;
  std::size_t m_evaluations = 0;
  std::vector<Real> m_errors;
  std::vector<state> m_columns_values;  // T_{j,0}: increments of the midpoint columns
  state m_f0{}, m_fz{}, m_z0{}, m_z1{}, m_arg{}, m_increment{}, m_difference{}, m_err_vector{}, m_last_error_vector{};
  Real m_tm = 0, m_h = 0, m_two_h = 0, m_tmp = 0;
  std::vector<state> m_nodes, m_scratch_nodes;
  std::vector<Real> m_node_times, m_scratch_times;
};

}  // namespace viscor

#if defined(VISCOR_HAS_QD) && VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>

namespace viscor::detail {
/// double_double: 10 or more guard digits, as for long double and float128 (float128's
/// 33 digits are too few: mpfr_real at 31 + 10 + 31/8 digits filled to the limb, 57).
template <>
struct gbs_work<double_double> : gbs_work_by_width<double_double, 10> {};
}  // namespace viscor::detail
#endif
