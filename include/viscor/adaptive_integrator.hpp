// Gragg-Bulirsch-Stoer extrapolation with adaptive order and step: viscor's
// second integrator, independent of the Taylor-series one in algorithm and code.
//
// Method (Hairer, Norsett, Wanner, "Solving ODEs I", sec. II.9, code ODEX;
// Deuflhard 1983): over a step H the modified midpoint rule (Gragg 1965) with
// n_j = 2(j+1) sub-steps gives T_{j,0}, whose error has an expansion in even
// powers of H/n_j; Aitken-Neville extrapolation to zero step
//     T_{j,k} = T_{j,k-1} + (T_{j,k-1} - T_{j-1,k-1}) / ((n_j/n_{j-k})^2 - 1)
// makes T_{j,j} of order 2j+2, and |T_{j,j} - T_{j,j-1}| estimates the error.
// Column count (order) and step are chosen together to minimise the work per
// unit step A_j/H_j, A_j = 1 + n_0 + ... + n_j right-hand-side evaluations.
//
// NOTE: why this reaches 50 and 100 digits in reasonable time. The order is not
// capped at a small constant (Boost.Odeint's bulirsch_stoer stops at m_k_max = 8,
// i.e. order 16, which at tolerance 1e-100 forces steps ~1e-6 of the solution's
// scale). Here the column count grows with the requested digits (measured on the
// impact problem: 16-21 columns, order 34-44, at 50 digits; about 29, order 60, at
// 100 digits; 49 at 200), so a step stays a sizeable fraction of the radius of
// convergence and an impact takes 40-90 steps. The work per step grows only like
// j^2 (harmonic sequence), i.e. quadratically in the digits, as for a Taylor method:
// 15-20 ms per impact at 50 digits, 80-100 ms at 100 (about 2-3x the Taylor solve).
//
// NOTE: rounding. The harmonic sequence's extrapolation amplifies the rounding
// errors of the T_{j,0} by its Lebesgue constant, about 10^(0.36 j) (measured:
// 16 columns lose 4.6 of 50 digits). gbs_work<Real> therefore names a wider type
// to integrate in (guard digits), and gbs_max_columns caps j to what those guard
// digits absorb; callers that integrate in Real itself lose ~0.36 j digits.
#pragma once

#include <viscor/real_io.hpp>
#include <viscor/real_types.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
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
template <>
struct gbs_work<double> {
  using type = long double;
  static int guard_digits() { return 3; }
};
#if VISCOR_HAS_FLOAT128
template <>
struct gbs_work<long double> {
  using type = quad;
  static int guard_digits() { return 15; }
};
#endif
#if VISCOR_HAS_MPFR
template <class Real>
int mpfr_guard_digits() {
  return 10 + decimal_digits<Real>() / 8;
}
#if VISCOR_HAS_FLOAT128
template <>
struct gbs_work<quad> {
  using type = mpfr_real;
  static int guard_digits() { return mpfr_guard_digits<quad>(); }
};
#endif
/// Fixed-precision mpfr types integrate in a wider fixed type with limbs on the
/// stack: no allocation and no thread-default-precision look-up per operation.
template <unsigned D, boost::multiprecision::mpfr_allocation_type A, boost::multiprecision::expression_template_option ET>
struct gbs_work<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<D, A>, ET>> {
  static constexpr unsigned guard = 10 + D / 8;
  using type = boost::multiprecision::number<
      boost::multiprecision::mpfr_float_backend<D + guard, boost::multiprecision::allocate_stack>>;
  static int guard_digits() { return static_cast<int>(guard); }
};
template <boost::multiprecision::mpfr_allocation_type A, boost::multiprecision::expression_template_option ET>
struct gbs_work<boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0, A>, ET>> {
  using type = mpfr_real;
  static int guard_digits() { return mpfr_guard_digits<mpfr_real>(); }
};
#endif

/// Largest column index worth computing in type Work when `guard` decimal digits
/// absorb the extrapolation's rounding amplification (about 0.36 digits per column).
inline int gbs_max_columns(int work_decimal_digits, int guard) {
  const int by_guard = guard > 0 ? static_cast<int>((guard - 1) / 0.36) : 6;
  const int by_need = work_decimal_digits / 3 + 6;  // no use going beyond order ~ digits
  return std::clamp(std::min(by_guard, by_need), 3, 64);
}
}  // namespace detail

/// Outcome of one attempted GBS step.
enum class gbs_status {
  accepted,      ///< t, y advanced; h holds the proposed next step
  rejected,      ///< error too large; h holds a smaller step to retry with
  domain_error,  ///< the right-hand side refused a stage (left its domain); h halved
};

/// A GBS extrapolation stepper for y' = f(t, y), y in Real^N, any precision.
/// The right-hand side is `bool f(const Real& t, const std::array<Real, N>& y,
/// std::array<Real, N>& dydt)`, returning false when y is outside its domain.
/// Error control per component: |err_i| <= atol_i + rtol * max(|y_i|, |y_new_i|).
template <class Real, std::size_t N>
class gbs_integrator {
 public:
  using state = std::array<Real, N>;

  gbs_integrator(const Real& rtol, const state& atol, int max_columns)
      : m_rtol(rtol), m_atol(atol), m_max_columns(std::max(max_columns, 2)) {
    // Start near the order the tolerance needs: about digits/4 + 4 columns.
    using std::frexp;
    int binary_exponent = 0;
    frexp(rtol, &binary_exponent);
    m_columns = std::clamp(static_cast<int>(-binary_exponent * 0.30103 / 4) + 4, 2, m_max_columns);
    // NOTE: coefficients 1/((n_j/n_{j-k})^2 - 1) from integers, in Real.
    m_coef.resize(m_max_columns + 2);
    for (int j = 0; j < m_max_columns + 2; ++j) {
      m_coef[j].resize(j + 1);
      for (int k = 1; k <= j; ++k) {
        const long long a = (j + 1) * (j + 1), b = (j - k + 1) * (j - k + 1);
        m_coef[j][k] = Real(b) / Real(a - b);
      }
    }
    m_table.assign(m_max_columns + 2, std::vector<state>(m_max_columns + 2));
    m_errors.assign(m_max_columns + 2, Real(0));
  }

  /// Whether try_step records the nodes of the accepted column (event detection).
  void set_keep_nodes(bool keep) { m_keep_nodes = keep; }

  /// Current target column index (order 2 * columns + 2).
  int columns() const { return m_columns; }
  void set_columns(int k) { m_columns = std::clamp(k, 2, m_max_columns); }
  int max_columns() const { return m_max_columns; }
  /// Column index and scaled error estimate (<= 1) of the last accepted step.
  int last_columns() const { return m_last_columns; }
  const Real& last_error() const { return m_last_error; }
  /// Absolute error estimate per component of the last accepted step.
  const state& last_error_vector() const { return m_last_error_vector; }
  /// Right-hand-side evaluations so far.
  std::size_t evaluations() const { return m_evaluations; }
  /// States at the nodes t + m H/n (m = 0..n) of the finest midpoint column of
  /// the last accepted step (O(h^2)-accurate: for event detection, not output).
  const std::vector<state>& nodes() const { return m_nodes; }
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
    const int kt = m_columns;
    const int last = std::min(kt + 1, m_max_columns);
    Real last_h = h;
    int last_j = kt;
    for (int j = 0; j <= last; ++j) {
      if (!midpoint(f, t, y, h, j, m_table[j][0], m_keep_nodes && j >= kt - 1)) {
        h /= 2;
        m_rejected = true;
        return gbs_status::domain_error;
      }
      extrapolate(j);
      if (j == 0) continue;
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
    for (int j = 0; j <= columns; ++j) {
      if (!midpoint(f, t, y, h, j, m_table[j][0], false)) return false;
      extrapolate(j);
    }
    out = m_table[columns][columns];
    return true;
  }

  /// Marks the start of a fresh integration (forget the last rejection).
  void reset_rejection() { m_rejected = false; }

 private:
  static long long work_of(int j) { return 1 + static_cast<long long>(j + 1) * (j + 2); }

  // Gragg's modified midpoint rule with n = 2(j+1) sub-steps into `out`.
  template <class F>
  bool midpoint(F& f, const Real& t, const state& y, const Real& H, int j, state& out, bool keep_nodes) {
    using boost::math::isfinite;
    using std::swap;
    const int n = 2 * (j + 1);
    const Real h = H / n, two_h = 2 * h;
    m_z0 = y;
    for (std::size_t i = 0; i < N; ++i) m_z1[i] = y[i] + h * m_f0[i];
    if (keep_nodes) {
      m_scratch_nodes.resize(n + 1);
      m_scratch_times.resize(n + 1);
      m_scratch_nodes[0] = y;
      m_scratch_times[0] = t;
      m_scratch_nodes[1] = m_z1;
      m_scratch_times[1] = t + h;
    }
    for (int m = 1; m < n; ++m) {
      m_tm = t + m * h;
      if (!f(m_tm, m_z1, m_fz)) return false;
      ++m_evaluations;
      for (std::size_t i = 0; i < N; ++i) {
        m_z0[i] += two_h * m_fz[i];
        swap(m_z0[i], m_z1[i]);
      }
      if (keep_nodes) {
        m_scratch_nodes[m + 1] = m_z1;
        m_scratch_times[m + 1] = m + 1 == n ? Real(t + H) : Real(t + (m + 1) * h);
      }
    }
    for (std::size_t i = 0; i < N; ++i)
      if (!isfinite(m_z1[i])) return false;
    out = m_z1;
    return true;
  }

  void extrapolate(int j) {
    for (int k = 1; k <= j; ++k)
      for (std::size_t i = 0; i < N; ++i)
        m_table[j][k][i] = m_table[j][k - 1][i] + (m_table[j][k - 1][i] - m_table[j - 1][k - 1][i]) * m_coef[j][k];
  }

  Real error_norm(const state& y, int j) {
    using std::abs;
    using std::max;
    Real worst = 0;
    for (std::size_t i = 0; i < N; ++i) {
      const Real scale = m_atol[i] + m_rtol * max(abs(y[i]), abs(m_table[j][j][i]));
      const Real diff = abs(m_table[j][j][i] - m_table[j][j - 1][i]);
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
  Real optimal_step(const Real& H, const Real& err, int j) const {
    using std::pow;
    const Real lo = Real(1) / 50, hi = 4;
    if (err == 0) return H * hi;
    Real factor = Real(94) / 100 * pow(Real(65) / 100 / err, Real(1) / (2 * j + 1));
    if (factor < lo) factor = lo;
    if (factor > hi) factor = hi;
    return H * factor;
  }

  void accept(Real& t, state& y, Real& h, int j, const Real& err, const Real& hj, const Real& work) {
    using std::abs;
    t += h;
    y = m_table[j][j];
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
  int m_last_columns = 0;
  Real m_last_error = 0;
  std::size_t m_evaluations = 0;
  std::vector<std::vector<Real>> m_coef;
  std::vector<Real> m_errors;
  std::vector<std::vector<state>> m_table;
  state m_f0{}, m_fz{}, m_z0{}, m_z1{}, m_err_vector{}, m_last_error_vector{};
  Real m_tm = 0;
  std::vector<state> m_nodes, m_scratch_nodes;
  std::vector<Real> m_node_times, m_scratch_times;
};

}  // namespace viscor
