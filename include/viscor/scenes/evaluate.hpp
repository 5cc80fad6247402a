// Accuracy-driven evaluation: e at (law, gamma, g) with an empirical
// error bound <= a requested tolerance, by the cheapest method whose bound meets it.
//
// The bound is EMPIRICAL, not a proof: each method's bound is a measured or
// estimated error times a safety factor, and the factors were chosen from (and are
// checked by) comparisons with independent references (tests/evaluate_test.cpp on
// a sample in the default suite, tests/evaluate_slow_test.cpp on 500 points).
// Methods, tried in order of cost; the first whose bound meets the tolerance wins:
//   0. a surrogate (evaluate_options::surrogate, a fast_cor: core/fast_cor.hpp;
//      docs/surrogate.md), only inside its domain. Bound: its stated bound (measured
//      maximum over >= 20,000 certified points it was not fitted to x a safety
//      factor): |de| where e >= 1e-2, else |de^2| / e_s; for a stick 0 (outside the
//      band below, a rebound would break the |de^2| bound), else sqrt(|de^2|);
//      relative on 1 - e its own relative bound where gamma <= 1e-2. Never within
//      |e_s^2| < 1e-8 of the threshold, where its outcome is not verified.
//   1. a double-precision approximation (eqs. 22, 23, 25, then Prop. 2 with
//      Chebyshev-Beta, then quadrature coefficients) -- only inside a cell of an
//      error map (error_map.hpp) for this law. Bound: the cell's, 4 x the largest
//      error seen over the certified table rows in the cell (+ 1e-14), i.e. a
//      sampled maximum, not a maximum over the cell.
//   2. an exact closed form (closed_form_for decides which), evaluated at two
//      precisions d and d + 10. Bound: 4 x their difference + 8 epsilon: the formula
//      is exact, so the difference measures the rounding of the first.
//   3. the Taylor solve (solve_impact) at d digits, d = max(digits of Real,
//      -log10(tolerance) + 3), in the cheapest type that carries them (double
//      first). Bound: 10 x its error estimate (detail/estimate_safety.hpp), the
//      estimate being a heuristic (steps x tolerance x energy scale + the energy
//      residual); a stick verdict gets 10 sqrt(2 x energy uncertainty): a bead that
//      wrongly seems to stick can have rebounded only with that little energy.
//   4. below 1e-15, certify (certification.hpp) at d digits instead of 3. Bound:
//      10^(1 - certified digits), relative and absolute; certified digits are an
//      agreement of independent methods, not an enclosure.
// The first Taylor solve steps at tolerance/1000 (cheaper); if its bound misses,
// the same digits at full step accuracy; then d grows by the shortfall plus 4
// digits and 3 or 4 is repeated (5 solves in all); then certification_error.
//
// The bound is absolute on e, |e - e_true| <= bound, or with relative = true
// relative on 1 - e, |one_minus_e - (1 - e_true)| <= bound (1 - e_true), which
// stays meaningful as gamma -> 0 (one_minus_e is computed without cancellation).
// For an approximation or an estimate with absolute bound B at value e, the
// relative bound is B / (1 - e - B).
// Compatibility: evaluation::bound was called error_bound, then empirical_bound (the
// result vocabulary, core/field_names.hpp: `bound` is a stated bound, its kind said by
// the result); the scene outputs keep the column empirical_bound
// (empirical_bound_relative), formerly error_bound (error_bound_relative); the values
// are unchanged.
//
// Inputs are used exactly: solves run in a type at least as wide as Real.
// Results are rounded to Real (the bound includes that rounding), so Real must
// carry the tolerance: tolerance >= 10 epsilon<Real>(). For 1e-30 use mpfr_real
// at 40 digits or so (with_working_precision).
#pragma once

#include <viscor/certify/certification.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/scenes/detail/estimate_safety.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/fast_cor.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/widen.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

namespace viscor {

enum class evaluation_method {
  small_g,           ///< eq. (22), via an error map
  large_g,           ///< eq. (23), via an error map
  schwager_poschel,  ///< eq. (25), via an error map
  prop2_chebyshev_beta,   ///< Prop. 2 with Chebyshev-Beta coefficients, via an error map
  prop2_numeric,     ///< Prop. 2 with quadrature coefficients, via an error map
  exact,             ///< a closed form (exact_cor)
  taylor,            ///< solve_impact at `digits`
  certified,         ///< certify at `digits`
  surrogate,         ///< a surrogate (evaluate_options::surrogate), double
};

/// The method's name as printed in JSON and scene files.
inline std::string to_string(evaluation_method m) {
  switch (m) {
    case evaluation_method::small_g: return "small_g";
    case evaluation_method::large_g: return "large_g";
    case evaluation_method::schwager_poschel: return "schwager_poschel";
    case evaluation_method::prop2_chebyshev_beta: return "prop2_chebyshev_beta";
    case evaluation_method::prop2_numeric: return "prop2_numeric";
    case evaluation_method::exact: return "exact";
    case evaluation_method::taylor: return "taylor";
    case evaluation_method::certified: return "certified";
    case evaluation_method::surrogate: return "surrogate";
  }
  return "?";
}

/// How evaluate may meet a tolerance: bound kind, error map, which methods are allowed.
struct evaluate_options {
  bool relative = false;            ///< bound relative on 1 - e instead of absolute on e
  const error_map* map = nullptr;   ///< approximations are used only inside its cells
  const fast_cor* surrogate = nullptr;  ///< tried first, inside its domain (must outlive the evaluator)
  bool need_contact_time = false;   ///< only methods that compute T_f (not the approximations)
  bool allow_certify = true;        ///< certify below 1e-15
  int max_attempts = 5;             ///< solves (methods 3-4) before giving up
  bool loose_first_attempt = true;  ///< first Taylor solve at step tolerance tolerance/1000
};

/// What evaluate returns: e, 1 - e, the outcome, the method chosen and its bound.
template <class Real>
struct evaluation {
  Real e = 1, one_minus_e = 0;
  impact_outcome outcome = impact_outcome::rebound;
  /// Empirical bound on the error (see the header comment for how each method
  /// obtains it): absolute on e, or relative on 1 - e when `relative`; empirical, that
  /// is measured, not proven (docs/scenes.md). Formerly error_bound, then empirical_bound;
  /// written as empirical_bound (empirical_bound_relative) in JSON and CSV.
  Real bound = 0;
  bool relative = false;
  evaluation_method method = evaluation_method::taylor;
  int working_digits = 0;  ///< working decimal digits of the method (15 for the double approximations)
  /// Scaled T_f (rebound) or stop time (stick, +inf for a creep), where the method
  /// computes it (not the approximations; exact forms only for the linear law).
  std::optional<Real> contact_time;
  int attempts = 0;     ///< precisions tried by methods 3-4
  double seconds = 0;   ///< wall time of the call
};

namespace detail {

// A result at some working precision, as decimal text (so that it can leave the
// precision scope of with_working_precision and be rounded into Real).
struct evaluation_text {
  bool ok = false;
  std::string e, one_minus_e, bound, contact_time;  // bound: rounded up
  impact_outcome outcome = impact_outcome::rebound;
  evaluation_method method = evaluation_method::taylor;
  int working_digits = 0;
};

// x rounded up to 3 significant digits (bounds must not shrink in print).
template <class W>
std::string bound_text(const W& x) {
  using boost::math::isfinite;
  if (!isfinite(x)) return "inf";
  return to_decimal_string(W(x * (1 + W(1) / 64)), 3);
}

template <class Real>
double to_double(const Real& x) {
  if constexpr (std::is_same_v<Real, double>) return x;
  else return std::strtod(to_decimal_string(x, 17).c_str(), nullptr);
}

// Absolute bound `abs_bound` at value e as the requested kind of bound.
template <class W>
W as_requested(const W& abs_bound, const W& one_minus_e, bool relative) {
  if (!relative) return abs_bound;
  const W room = one_minus_e - abs_bound;
  if (!(room > 0)) return std::numeric_limits<W>::infinity();
  return abs_bound / room;
}

// Decimal digits for the first attempt at tolerance tol, never fewer than Real's.
template <class Real>
int first_digits(const Real& tol, int extra) {
  using std::ceil;
  using std::log10;
  const int needed = static_cast<int>(Real(ceil(-log10(tol) - Real(1) / 1000000))) + extra;  // 1e-12 -> 12
  return needed > decimal_digits<Real>() ? needed : decimal_digits<Real>();
}

// Method 2 at `digits` (and digits + 10 for the check).
template <class W, class Real>
evaluation_text exact_in(const contact_law& law, const Real& gamma, const Real& g, const std::string& tol_text,
                         bool relative, int digits) {
  evaluation_text out;
  const W wg = widen<W>(gamma), wgg = widen<W>(g);
  const std::optional<exact_result<W>> a = exact_cor(law, wg, wgg);
  if (!a) return out;
  // The check at digits + 10 (a type at least that wide).
  const std::string check = with_working_precision(digits + 10, [&]<class V>() {
    if constexpr (!can_widen<V, Real>()) {
      return std::string();  // unreachable: digits + 10 exceeds the digits of Real
    } else {
      const std::optional<exact_result<V>> b = exact_cor(law, widen<V>(gamma), widen<V>(g));
      if (!b || b->outcome != a->outcome) return std::string();
      return to_decimal_string(relative ? b->one_minus_e : b->e, roundtrip_digits<W>() + 4);
    }
  });
  if (check.empty()) return out;
  using std::abs;
  const W checked = parse_real<W>(check, "e");
  W bound;
  if (relative) {  // on 1 - e, which the closed forms give without cancellation
    const W abs_bound = abs(a->one_minus_e - checked) * 4 + 8 * epsilon<W>() * a->one_minus_e;
    bound = as_requested(abs_bound, a->one_minus_e, true);
  } else {
    bound = abs(a->e - checked) * 4 + 8 * epsilon<W>();
  }
  if (!(bound <= parse_real<W>(tol_text, "tolerance"))) return out;
  out.ok = true;
  out.method = evaluation_method::exact;
  out.outcome = a->outcome;
  out.e = to_decimal_string(a->e), out.one_minus_e = to_decimal_string(a->one_minus_e);
  out.bound = bound_text(bound);
  if (a->contact_time) out.contact_time = to_decimal_string(*a->contact_time);
  out.working_digits = decimal_digits<W>();
  return out;
}

// Method 3 at the working precision of W: the solve and its bound (returned even
// when it misses). step_tolerance is the solver's tolerance per step (0: epsilon).
template <class W>
struct taylor_evaluation {
  impact_result<W> solve;
  W bound;  // as requested (absolute on e or relative on 1 - e)
};

template <class W, class Real>
taylor_evaluation<W> taylor_raw(const contact_law& law, const Real& gamma, const Real& g, bool relative,
                                const W& step_tolerance) {
  using std::abs;
  using std::sqrt;
  const W wg = widen<W>(g);
  solve_options<W> options;
  options.tolerance = step_tolerance;
  taylor_evaluation<W> out{{}, W(0)};
  try {
    out.solve = solve_impact(law, widen<W>(gamma), wg, options);
  } catch (const certification_error&) {
    // NOTE: the solve refused its own result at this precision (the energy identity
    // fails where the bead stops: Hunt-Crossley a hair below gamma_c(50) in double):
    // no claim, so the caller escalates the precision.
    out.solve.outcome = impact_outcome::undecided;
    out.bound = std::numeric_limits<W>::infinity();
    return out;
  }
  const impact_result<W>& r = out.solve;
  const W step_tol = step_tolerance > epsilon<W>() ? step_tolerance : epsilon<W>();
  W abs_bound;
  if (r.outcome == impact_outcome::undecided) {
    abs_bound = std::numeric_limits<W>::infinity();  // no claim to bound: escalate
  } else if (r.outcome == impact_outcome::stick) {
    // Energy uncertainty: the identity's residual plus steps x tolerance on the energy
    // scale (kinetic 1/2, load g u_max); a wrong stick verdict hides e <= sqrt(2 dE).
    const W scale = 1 + abs(wg) * r.max_compression;
    const W dE = abs(r.energy_residual) + W(int(r.steps) + 1) * 100 * step_tol * scale;
    abs_bound = taylor_estimate_safety * sqrt(2 * dE);
  } else {
    abs_bound = taylor_estimate_safety * r.error_estimate;
  }
  out.bound = as_requested(abs_bound, r.one_minus_e, relative);
  return out;
}

template <class W, class Real>
evaluation_text taylor_in(const contact_law& law, const Real& gamma, const Real& g, bool relative,
                          const std::string& step_tolerance) {
  const taylor_evaluation<W> t = taylor_raw<W>(law, gamma, g, relative, parse_real<W>(step_tolerance, "step tolerance"));
  evaluation_text out;
  out.ok = true;
  out.method = evaluation_method::taylor;
  out.outcome = t.solve.outcome;
  out.e = to_decimal_string(t.solve.e), out.one_minus_e = to_decimal_string(t.solve.one_minus_e);
  out.bound = bound_text(t.bound);
  if (t.solve.contact_time) out.contact_time = to_decimal_string(*t.solve.contact_time);
  out.working_digits = decimal_digits<W>();
  return out;
}

// Method 4 at the working precision of W.
template <class W, class Real>
evaluation_text certified_in(const contact_law& law, const Real& gamma, const Real& g, bool relative) {
  using std::abs;
  using std::pow;
  const certified_result<W> c = certify(law, widen<W>(gamma), widen<W>(g));
  evaluation_text out;
  out.ok = true;
  out.method = evaluation_method::certified;
  out.outcome = c.outcome;
  out.working_digits = decimal_digits<W>();
  out.e = to_decimal_string(c.e), out.one_minus_e = to_decimal_string(c.one_minus_e);
  if (c.contact_time) out.contact_time = to_decimal_string(*c.contact_time);
  W bound;
  if (!c.outcome_certified) {
    bound = std::numeric_limits<W>::infinity();
  } else if (c.outcome == impact_outcome::stick) {
    bound = 0;  // e = 0 exactly once the outcome is certified
  } else {
    // `certified_digits` significant digits: relative error < 10^(1 - digits), with a digit to spare.
    const W rel = c.certified_digits > 0 ? W(pow(W(10), 1 - c.certified_digits))
                                         : W(std::numeric_limits<W>::infinity());
    const W abs_e = c.certified_absolute_digits_e > 0 ? W(pow(W(10), 1 - c.certified_absolute_digits_e))
                                                      : W(std::numeric_limits<W>::infinity());
    if (relative) {
      bound = rel;  // digits covers 1 - e as well
      const W via_abs = as_requested(abs_e, c.one_minus_e, true);
      if (via_abs < bound) bound = via_abs;
    } else {
      bound = rel * abs(c.e);
      if (abs_e < bound) bound = abs_e;
    }
  }
  out.bound = bound_text(bound);
  return out;
}

}  // namespace detail

/// Evaluates e for one contact law with an error bound; see the header comment.
template <class Real>
class evaluator {
 public:
  /// An evaluator for `law`; throws invalid_parameter for an invalid law, a map of another law or max_attempts < 1.
  explicit evaluator(contact_law law, evaluate_options options = {}) : m_law(std::move(law)), m_options(options) {
    m_law.validate();
    if (m_options.map) {
      if (!(m_options.map->law.alpha == m_law.alpha) || !(m_options.map->law.beta == m_law.beta))
        throw invalid_parameter("the error map is for " + m_options.map->law.describe() + ", not for " +
                                m_law.describe());
      m_approx.emplace(m_law);
    }
    if (m_options.surrogate && (m_options.surrogate->alpha() != m_law.alpha.to_string() ||
                                m_options.surrogate->beta() != m_law.beta.to_string()))
      throw invalid_parameter("the surrogate is for alpha = " + m_options.surrogate->alpha() + ", beta = " +
                              m_options.surrogate->beta() + ", not for " + m_law.describe());
    if (m_options.max_attempts < 1) throw invalid_parameter("parameter max_attempts must be >= 1");
  }

  /// The law evaluated.
  const contact_law& law() const noexcept { return m_law; }
  /// The options it was built with.
  const evaluate_options& options() const noexcept { return m_options; }

  /// e at (gamma, g) with bound <= tolerance (absolute, or relative on 1 - e).
  evaluation<Real> operator()(const Real& gamma, const Real& g, const Real& tolerance) const {
    const auto start = std::chrono::steady_clock::now();
    impact_parameters<Real>{m_law, gamma, g}.validate();
    require_positive(tolerance, "tolerance");
    if (tolerance < 10 * epsilon<Real>())
      throw precision_unavailable("tolerance " + to_decimal_string(tolerance, 3) + " is below what the result type (" +
                                  std::to_string(decimal_digits<Real>()) +
                                  " digits) holds; evaluate in a wider type (mpfr_real at >= " +
                                  std::to_string(detail::first_digits(tolerance, 3)) + " digits)");
    evaluation<Real> r = compute(gamma, g, tolerance);
    r.relative = m_options.relative;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

 private:
  evaluation<Real> compute(const Real& gamma, const Real& g, const Real& tolerance) const {
    if (auto a = by_surrogate(gamma, g, tolerance)) return *a;
    if (auto a = by_approximation(gamma, g, tolerance)) return *a;
    const std::string tol_text = to_decimal_string(tolerance);
    // Closed forms exist only on special lines; closed_form_for says which.
    if (closed_form_exists(m_law, gamma == 0, g == 0)) {
      const int d = detail::first_digits(tolerance, 4);
      const detail::evaluation_text t = with_working_precision(d, [&]<class W>() {
        if constexpr (detail::can_widen<W, Real>()) {
          return detail::exact_in<W>(m_law, gamma, g, tol_text, m_options.relative, d);
        } else {
          return detail::evaluation_text{};  // unreachable: d >= the digits of Real
        }
      });
      if (t.ok && (!m_options.need_contact_time || !t.contact_time.empty())) {
        const evaluation<Real> r = from_text(t, 0);
        if (r.bound <= tolerance) return r;
      }
    }
    return by_solving(gamma, g, tolerance, tol_text);
  }

  // Method 0: the surrogate's value where its stated bound meets the tolerance.
  std::optional<evaluation<Real>> by_surrogate(const Real& gamma, const Real& g, const Real& tolerance) const {
    if (!m_options.surrogate || m_options.need_contact_time) return std::nullopt;
    const fast_cor_bound b = m_options.surrogate->bound();
    if (!b.verified) return std::nullopt;
    const double gd = detail::to_double(gamma), ggd = detail::to_double(g);
    // Only at points that are doubles: the surrogate takes its inputs in double.
    if (!(Real(gd) == gamma && Real(ggd) == g)) return std::nullopt;
    const fast_cor_value v = m_options.surrogate->at(gd, ggd);
    if (!v.in_domain || !(std::abs(v.e_squared) >= b.uncertain_e_squared)) return std::nullopt;
    const bool stick = v.outcome == impact_outcome::stick;
    // NOTE: a stick here has e_s^2 <= -uncertain_e_squared; a true rebound would put
    // |e_s^2 - e^2| above that, beyond the |de^2| bound when the bound is the smaller:
    // then the stated bound itself says e = 0 exactly. Else e <= sqrt(|de^2| bound).
    const double stick_bound = b.abs_e_squared < b.uncertain_e_squared ? 0.0 : std::sqrt(b.abs_e_squared);
    double abs_bound = stick ? stick_bound
                             : v.e >= 1.01e-2 ? b.abs_e : b.abs_e_squared / v.e;  // |de| = |de^2| / (e_s + e)
    Real bound = detail::as_requested(Real(abs_bound), Real(v.one_minus_e), m_options.relative);
    if (m_options.relative && !stick && gd <= b.small_gamma && v.e >= 1.01e-2 && Real(b.rel_one_minus_e) < bound)
      bound = Real(b.rel_one_minus_e);
    if (!(bound <= tolerance)) return std::nullopt;
    evaluation<Real> r;
    r.e = Real(v.e), r.one_minus_e = Real(v.one_minus_e), r.outcome = v.outcome;
    r.bound = bound;
    r.method = evaluation_method::surrogate;
    r.working_digits = decimal_digits<double>();
    return r;
  }

  std::optional<evaluation<Real>> by_approximation(const Real& gamma, const Real& g, const Real& tolerance) const {
    if (!m_approx || m_options.need_contact_time) return std::nullopt;
    const double gd = detail::to_double(gamma), ggd = detail::to_double(g);
    const std::optional<map_bounds> b = m_options.map->at(gd, ggd);
    if (!b) return std::nullopt;
    for (std::size_t k = 0; k < all_approximations.size(); ++k) {
      if (!b->bound[k]) continue;
      // Quick reject before evaluating the formula (the bound is absolute).
      if (!m_options.relative && !(Real(*b->bound[k]) <= tolerance)) continue;
      const std::optional<double> a = approximate_e(*m_approx, all_approximations[k], gd, ggd);
      if (!a) continue;
      const bool stick = b->outcome == cell_outcome::stick;
      const Real e = stick ? Real(0) : Real(*a);
      const Real one_minus_e = 1 - e;
      const Real bound = detail::as_requested(Real(*b->bound[k]), one_minus_e, m_options.relative);
      if (!(bound <= tolerance)) continue;
      evaluation<Real> r;
      r.e = e, r.one_minus_e = one_minus_e;
      r.outcome = stick ? impact_outcome::stick : impact_outcome::rebound;
      r.bound = bound;
      r.method = static_cast<evaluation_method>(k);  // same order as all_approximations
      r.working_digits = decimal_digits<double>();
      return r;
    }
    return std::nullopt;
  }

  evaluation<Real> by_solving(const Real& gamma, const Real& g, const Real& tolerance,
                              const std::string& tol_text) const {
    using std::ceil;
    using std::log10;
    const bool certified = m_options.allow_certify && tolerance < Real(1e-15);
    // NOTE: 10 x the estimate is within 10^3 epsilon (estimates reach 10^2 epsilon),
    // so 3 digits beyond the tolerance suffice for the solve; certify reports
    // agreement minus a 2-digit margin, so 5 for it.
    int d = detail::first_digits(tolerance, certified ? 5 : 3);
    // NOTE: the first Taylor attempt steps at tolerance/1000, which is cheaper (lower
    // order) while 10 x its estimate still meets the tolerance (measured,
    // docs/performance.md, "scenes/evaluate.hpp"). Any later attempt steps at full precision.
    bool loose = !certified && m_options.loose_first_attempt;
    bool beyond_real_range = false;  // Real's exponent range lost digits (taylor_integrator)
    std::string worst_bound;
    for (int attempt = 1; attempt <= m_options.max_attempts; ++attempt) {
      if constexpr (has_fixed_precision<Real>()) {
        if (!certified && d == decimal_digits<Real>() && !beyond_real_range) {
          // In Real itself: no text round trip (it would cost as much as a loose solve in double).
          std::optional<detail::taylor_evaluation<Real>> in_real;
          try {
            in_real = detail::taylor_raw<Real>(m_law, gamma, g, m_options.relative,
                                               loose ? Real(tolerance / 1000) : Real(0));
          } catch (const exponent_range_exceeded&) {
            beyond_real_range = true;  // with_working_precision below widens the type
          }
          if (in_real) {
            const detail::taylor_evaluation<Real>& t = *in_real;
            if (t.bound <= tolerance) {
              evaluation<Real> r;
              r.e = t.solve.e, r.one_minus_e = t.solve.one_minus_e, r.outcome = t.solve.outcome;
              r.bound = t.bound, r.method = evaluation_method::taylor, r.working_digits = decimal_digits<Real>();
              r.contact_time = t.solve.contact_time, r.attempts = attempt;
              return r;
            }
            worst_bound = to_decimal_string(t.bound, 3);
            if (loose) {
              loose = false;
            } else {
              using boost::math::isfinite;
              d += isfinite(t.bound) ? static_cast<int>(Real(ceil(log10(t.bound / tolerance)))) + 4 : d / 2 + 4;
            }
            continue;
          }
        }
      }
      const std::string step_tol = loose ? to_decimal_string(Real(tolerance / 1000), 3) : std::string("0");
      const detail::evaluation_text t = with_working_precision(d, [&]<class W>() {
        if constexpr (detail::can_widen<W, Real>()) {
          if (certified) return detail::certified_in<W>(m_law, gamma, g, m_options.relative);
          return detail::taylor_in<W>(m_law, gamma, g, m_options.relative, step_tol);
        } else {
          return detail::evaluation_text{};  // unreachable: d >= the digits of Real
        }
      });
      worst_bound = t.bound;
      std::optional<evaluation<Real>> r;
      if (t.bound != "inf") {
        r = from_text(t, attempt);
        if (r->bound <= tolerance) return *r;
      }
      if (loose) {
        loose = false;  // the same precision at full step accuracy first
      } else if (r) {
        d += static_cast<int>(Real(ceil(log10(r->bound / tolerance)))) + 4;
      } else {
        d += d / 2 + 4;
      }
    }
    throw certification_error("evaluate: no method reached the tolerance " + tol_text + " at (" + m_law.describe() +
                              ", gamma = " + to_decimal_string(gamma) + ", g = " + to_decimal_string(g) +
                              ") within " + std::to_string(m_options.max_attempts) +
                              " precision escalations; last bound " + worst_bound);
  }

  // Rounds a text result into Real; the rounding (of e, or of 1 - e when the
  // bound is relative) enters the bound.
  evaluation<Real> from_text(const detail::evaluation_text& t, int attempts) const {
    evaluation<Real> r;
    r.e = parse_real<Real>(t.e, "e");
    r.one_minus_e = parse_real<Real>(t.one_minus_e, "one_minus_e");
    r.outcome = t.outcome;
    r.method = t.method;
    r.working_digits = t.working_digits;
    r.attempts = attempts;
    r.bound = parse_real<Real>(t.bound, "bound");
    if (t.working_digits > decimal_digits<Real>()) r.bound += epsilon<Real>();
    if (!t.contact_time.empty()) {
      if (t.contact_time == "inf") r.contact_time = std::numeric_limits<Real>::infinity();
      else r.contact_time = parse_real<Real>(t.contact_time, "contact_time");
    }
    return r;
  }

  contact_law m_law;
  evaluate_options m_options;
  std::optional<cor_approximations<double>> m_approx;
};

/// One evaluation (builds the per-law constants each call; use evaluator in loops).
template <class Real>
evaluation<Real> evaluate(const contact_law& law, const Real& gamma, const Real& g, const Real& tolerance,
                          const evaluate_options& options = {}) {
  return evaluator<Real>(law, options)(gamma, g, tolerance);
}

}  // namespace viscor
