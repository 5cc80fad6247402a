// Fitting a CoR surrogate (cor_surrogate.hpp) for any law (alpha, beta):
//   1. g_split = g_c(gamma_ext) and gamma_c(g) on [g_split, g_max] by bisection on
//      the outcome of long double Taylor solves, fitted as ln gamma_c(ln g) on
//      adaptively halved intervals;
//   2. G = (1 - e^2) / w on the two regions (see cor_surrogate.hpp) by Chebyshev
//      interpolation on adaptively halved patches: a patch is kept when the
//      interpolant matches the solver at the (order - 1)^2 points halfway (in
//      angle) between its interpolation points to `fit_fraction` of the issue's
//      targets there; otherwise it is halved along the direction whose Chebyshev
//      coefficients decay slower.
// The solver is solve_impact in the `truth` type (long double by default: 1e-18,
// far below the targets). The fit never sees the verification points
// (surrogate_verify.hpp), which are drawn afterwards and certified independently.
#pragma once

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/impact_result.hpp>
#include <viscor/config.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/surrogate/chebyshev.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace viscor::surrogate {

/// What to fit.
struct fit_settings {
  contact_law law;
  double gamma_max = 1, g_min = -0.5, g_max = 1e4;
  double gamma_ext = 1.5;     ///< low loads end at g_c(gamma_ext); must exceed gamma_max
  int order = 12;             ///< Chebyshev points per direction per patch (8, 10, 12, 14 or 16)
  int threshold_order = 16;   ///< points per interval of ln gamma_c(ln g)
  double fit_fraction = 0.1;  ///< a patch must meet this fraction of the targets at its check points
  int max_depth = 40;         ///< halvings of one patch, at most
  std::size_t max_patches = 20000;  ///< per region; more means the fit does not converge: an error
  bool long_double_truth = true;  ///< solve in long double (else double)
  /// p in gamma_c(g) = g^-p exp(h(ln g)): the threshold is fitted as h = ln gamma_c + p ln g
  /// (cor_surrogate::threshold_power). 0 fits ln gamma_c itself; the large-g power law of
  /// gamma_c (2 for the linear law) keeps h and its rounding small.
  double threshold_power = 0;
};

/// Counters of a fit, for the sidecar.
struct fit_report {
  std::size_t solves = 0, threshold_solves = 0;
  std::size_t patches_low = 0, patches_high = 0, threshold_intervals = 0;
  std::size_t unconverged_patches = 0;  ///< patches left at max_depth above tolerance
  double worst_check_ratio = 0;  ///< max over kept patches of |fit - solver| / allowed at the check points
  double seconds = 0;
};

namespace detail {

inline std::string exact_text_short(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

/// The solver's answer at one point, in the form the fit needs.
struct truth_sample {
  double e = 0;           ///< 0 for a stick
  long double dissipated = 1;  ///< 1 - e^2 at full relative precision; past the threshold, 1 - (signed e^2)
};

class truth {
 public:
  truth(contact_law law, bool long_double) : m_law(std::move(law)), m_long(long_double) {
    m_alpha = m_law.alpha.value<long double>();
  }

  truth_sample operator()(long double gamma, long double g) {
    ++solves;
    try {
      return m_long ? sample<long double>(gamma, g) : sample<double>(gamma, g);
    } catch (const certification_error&) {
      // NOTE: at a hair from the threshold one precision may fail its energy
      // check; the other one decides (both failing is an error).
      return m_long ? sample<double>(gamma, g) : sample<long double>(gamma, g);
    }
  }

  /// The outcome at (gamma, g); empty when the solver cannot decide it (so
  /// close to the threshold that the energy identity fails in long double).
  std::optional<bool> sticks(long double gamma, long double g) {
    ++solves;
    try {
      return solve_impact<long double>(m_law, gamma, g).outcome == impact_outcome::stick;
    } catch (const certification_error&) {
    }
#if VISCOR_HAS_FLOAT128
    // NOTE: long double cannot decide within ~1e-13 of the threshold at large g; float128 can (to ~1e-30).
    try {
      ++solves;
      return solve_impact<quad>(m_law, quad(gamma), quad(g)).outcome == impact_outcome::stick;
    } catch (const certification_error&) {
    }
#endif
    return std::nullopt;
  }

  /// e^2 for a rebound, its continuation 2 (u_s^(alpha+1)/(alpha+1) - g u_s) < 0 past the
  /// threshold (u_s where the bead turns back); long double, float128 where long double
  /// cannot decide the outcome.
  long double signed_e_squared(long double gamma, long double g) {
    ++solves;
    try {
      return signed_e2_of(solve_impact<long double>(m_law, gamma, g), g);
    } catch (const certification_error&) {
    }
#if VISCOR_HAS_FLOAT128
    ++solves;
    return signed_e2_of(solve_impact<quad>(m_law, quad(gamma), quad(g)), g);
#else
    throw convergence_error("surrogate fit: the outcome at gamma = " + std::to_string(static_cast<double>(gamma)) +
                            ", g = " + std::to_string(static_cast<double>(g)) + " cannot be decided in long double");
#endif
  }

#if VISCOR_HAS_FLOAT128
  /// The signed e^2 from a float128 solve, computed in float128; empty if it fails its check.
  std::optional<quad> signed_e_squared_quad(const quad& gamma, const quad& g) {
    ++solves, ++quad_solves;
    try {
      const auto r = solve_impact<quad>(m_law, gamma, g);
      if (r.outcome == impact_outcome::rebound) return r.e * r.e;
      const quad u = r.stop_overlap, a = m_law.alpha.value<quad>();
      return 2 * (pow(u, a + 1) / (a + 1) - g * u);
    } catch (const certification_error&) {
      return std::nullopt;
    }
  }
#endif

  const contact_law& law() const { return m_law; }
  std::size_t solves = 0, quad_solves = 0;

 private:
  template <class Real>
  truth_sample sample(long double gamma, long double g) {
    const auto r = solve_impact<Real>(m_law, Real(gamma), Real(g));
    truth_sample s;
    if (r.outcome == impact_outcome::rebound) {
      s.e = static_cast<double>(r.e);
      s.dissipated = static_cast<long double>(r.one_minus_e * (1 + r.e));
    } else {
      // Past the threshold the bead turns back at u_s > 0 with energy
      // u_s^(alpha+1)/(alpha+1) - g u_s < 0: the continuation of e^2 / 2 through the threshold.
      const long double u = static_cast<long double>(r.stop_overlap);
      const long double signed_e2 = 2 * (std::pow(u, m_alpha + 1) / (m_alpha + 1) - static_cast<long double>(g) * u);
      s.dissipated = 1 - signed_e2;
    }
    return s;
  }

  template <class Real>
  long double signed_e2_of(const impact_result<Real>& r, long double g) const {
    if (r.outcome == impact_outcome::rebound) return static_cast<long double>(r.e * r.e);
    const long double u = static_cast<long double>(r.stop_overlap);
    return 2 * (std::pow(u, m_alpha + 1) / (m_alpha + 1) - g * u);
  }

  contact_law m_law;
  bool m_long = true;
  long double m_alpha = 1.5L;
};

/// The largest |G_fit - G| the targets allow at a point with weight w (gamma or r).
inline double allowed_error(const surrogate_targets& t, double fraction, double e, double w, double gamma, double G) {
  const double e2_target = e >= 1e-2 ? std::min(t.abs_e_squared, 2 * t.abs_e * e) : t.abs_e_squared;
  double allowed = fraction * e2_target / w;
  // relative error of 1 - e = (dG / G) (1 + e) / (2 e)
  if (gamma <= t.small_gamma && e >= 1e-2 && G > 0)
    allowed = std::min(allowed, fraction * t.rel_one_minus_e * G * 2 * e / (1 + e));
  return allowed;
}

/// Bisection for the boundary between rebound (at lo) and stick (at hi) to long double resolution.
/// Stops where the solver can no longer decide the outcome (there the bracket is
/// already far inside the accuracy the fit needs).
template <class Sticks>
long double bisect_threshold(long double lo, long double hi, Sticks sticks) {
  for (int i = 0; i < 200; ++i) {
    const long double mid = (lo + hi) / 2;
    if (!(mid > lo && mid < hi)) break;
    const std::optional<bool> s = sticks(mid);
    if (!s) return mid;
    if (*s) hi = mid; else lo = mid;
  }
  return (lo + hi) / 2;
}

/// The zero of a decreasing f on [lo, hi] (f(lo) > 0 > f(hi)) by the Illinois
/// variant of regula falsi, until the bracket is below `rel` relative to hi.
template <class Real, class F>
Real illinois_zero(F f, Real lo, Real hi, Real f_lo, Real f_hi, Real rel) {
  int side = 0;
  for (int i = 0; i < 100 && hi - lo > rel * hi; ++i) {
    Real c = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(c > lo && c < hi)) c = (lo + hi) / 2;
    const Real fc = f(c);
    if (fc == 0) return c;
    if (fc > 0) {
      lo = c, f_lo = fc;
      if (side == 1) f_hi /= 2;
      side = 1;
    } else {
      hi = c, f_hi = fc;
      if (side == -1) f_lo /= 2;
      side = -1;
    }
  }
  return (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
}

/// gamma_c(g): expands a bracket around `guess`, then finds the zero of the signed e^2
/// (e^2 on the rebound side, its continuation past the threshold on the other, a
/// smooth decreasing function of gamma through the threshold) by the Illinois
/// variant of regula falsi: about 10 solves instead of 60 for bisection.
/// Two phases: long double to relative 1e-12, then float128 from a bracket of
/// relative 1e-11 around that estimate (widened until float128 confirms the signs) to
/// long double resolution. NOTE: long double alone is not enough: within ~1e-13 of
/// the threshold at large g it can return the wrong outcome without failing its
/// energy check, and the continuation past the threshold cancels (u_s^(alpha+1) and
/// g u_s are ~g^(1 + 1/alpha)), so the long double thresholds were noisy at ~2e-13
/// near g = 2000 and the threshold fit could not converge there.
inline long double critical_gamma_at(truth& t, long double g, long double guess) {
  long double lo = guess, hi = guess;
  long double f_lo = t.signed_e_squared(lo, g), f_hi = f_lo;
  while (!(f_lo > 0)) {
    lo /= 2;
    if (lo < 1e-30L) throw convergence_error("surrogate fit: no rebound below gamma = 1e-30 at g = " + std::to_string(static_cast<double>(g)));
    f_lo = t.signed_e_squared(lo, g);
  }
  while (!(f_hi < 0)) {
    hi *= 2;
    if (hi > 1e6L) throw convergence_error("surrogate fit: no sticking below gamma = 1e6 at g = " + std::to_string(static_cast<double>(g)));
    f_hi = t.signed_e_squared(hi, g);
  }
  if (lo == guess && hi == guess) lo = hi / 2, f_lo = t.signed_e_squared(lo, g);
  const long double estimate = illinois_zero<long double>(
      [&](long double c) { return t.signed_e_squared(c, g); }, lo, hi, f_lo, f_hi, 1e-12L);
#if VISCOR_HAS_FLOAT128
  const quad gq(g);
  quad width = quad(1e-11L);
  for (int widen = 0;; ++widen, width *= 10) {
    if (widen > 8) throw convergence_error("surrogate fit: float128 cannot bracket the threshold at g = " + std::to_string(static_cast<double>(g)));
    const quad qlo = quad(estimate) * (1 - width), qhi = quad(estimate) * (1 + width);
    const auto fq_lo = t.signed_e_squared_quad(qlo, gq), fq_hi = t.signed_e_squared_quad(qhi, gq);
    if (!fq_lo || !fq_hi) return estimate;  // float128 cannot decide at 1e-11: keep long double's answer
    if (!(*fq_lo > 0 && *fq_hi < 0)) continue;
    const quad rel = quad(std::numeric_limits<long double>::epsilon()) / 4;
    std::optional<quad> failed;
    const quad c = illinois_zero<quad>(
        [&](const quad& x) -> quad {
          if (failed) return quad(0);
          const auto f = t.signed_e_squared_quad(x, gq);
          if (!f) failed = x;  // float128 cannot decide: so close that x is the answer
          return f ? *f : quad(0);
        },
        qlo, qhi, *fq_lo, *fq_hi, rel);
    return static_cast<long double>(failed ? *failed : c);
  }
#else
  return estimate;
#endif
}

/// ln gamma_c(e^x) + power x on [x0, x1] by adaptively halved Chebyshev intervals.
inline patch_line fit_threshold(truth& t, double x0, double x1, int order, double power, double tolerance, fit_report& report,
                                const std::function<void(const std::string&)>& progress) {
  patch_line line;
  line.order = order;
  line.breaks = {x0};
  const auto points = chebyshev_points(order);
  long double guess = 1;
  struct interval { double a, b; int depth; };
  std::vector<interval> todo{{x0, x1, 0}};  // a stack, upper intervals first
  while (!todo.empty()) {
    const auto [a, b, depth] = todo.back();
    todo.pop_back();
    auto ln_gamma_c = [&](long double x) {
      const long double gc = critical_gamma_at(t, std::exp(x), guess);
      guess = gc;
      return std::log(gc) + static_cast<long double>(power) * x;
    };
    std::vector<long double> f(static_cast<std::size_t>(order));
    for (int k = order - 1; k >= 0; --k)  // points[k] increase as k decreases: walk from a to b
      f[static_cast<std::size_t>(k)] = ln_gamma_c((a + b) / 2.0L + (b - a) / 2.0L * points[static_cast<std::size_t>(k)]);
    const auto c = chebyshev_coefficients_1d(f);
    double worst = 0;
    for (int k = 1; k < order; ++k) {
      const long double u = std::cos(std::numbers::pi_v<long double> * k / order);
      const long double x = (a + b) / 2.0L + (b - a) / 2.0L * u;
      worst = std::max(worst, static_cast<double>(std::abs(clenshaw(c.data(), order, static_cast<double>(u)) - ln_gamma_c(x))));
    }
    if (progress)
      progress("threshold interval [" + std::to_string(a) + ", " + std::to_string(b) + "]: check error " +
               exact_text_short(worst) + " (" + std::to_string(t.solves) + " solves)");
    if (worst <= tolerance || depth >= 8) {
      if (worst > tolerance) ++report.unconverged_patches;
      line.breaks.push_back(b);
      line.coefficients.insert(line.coefficients.end(), c.begin(), c.end());
    } else {
      todo.push_back({(a + b) / 2, b, depth + 1});
      todo.push_back({a, (a + b) / 2, depth + 1});
    }
  }
  report.threshold_intervals = line.breaks.size() - 1;
  return line;
}

/// gamma_c at x = ln g from the fitted threshold, evaluated in long double: the fit
/// samples G at the exact point (x, y) it stands for, free of the ~1e-16 rounding of
/// the double evaluation (which the verification measures instead).
inline long double critical_gamma_long(const cor_surrogate& s, long double x) {
  const auto& line = s.log_gamma_c;
  std::size_t k = 0;
  while (k + 2 < line.breaks.size() && x >= line.breaks[k + 1]) ++k;
  const long double a = line.breaks[k], b = line.breaks[k + 1], u = (2 * x - a - b) / (b - a);
  const double* c = line.coefficients.data() + k * static_cast<std::size_t>(line.order);
  long double b1 = 0, b2 = 0;
  for (int j = line.order - 1; j >= 1; --j) {
    const long double b0 = 2 * u * b1 - b2 + c[j];
    b2 = b1;
    b1 = b0;
  }
  return std::exp(u * b1 - b2 + c[0] - static_cast<long double>(s.threshold_power) * x);
}

/// One sample of the fitted quantity: G and what error the targets allow in it.
struct fit_sample {
  double G = 0, allowed = 0;
};

/// Fits a patch tree over its box; sample(x, y) gives G and its allowed error.
template <class Sample>
void fit_tree(patch_tree& tree, Sample sample, const fit_settings& settings, fit_report& report,
              const std::function<void(const std::string&)>& progress) {
  const int n = tree.order;
  const std::size_t N = static_cast<std::size_t>(n);
  const auto points = chebyshev_points(n);
  std::vector<long double> checks;
  for (int k = 1; k < n; ++k) checks.push_back(std::cos(std::numbers::pi_v<long double> * k / n));
  struct cell {
    double x0, x1, y0, y1;
    std::int32_t node;
    int depth;
  };
  tree.nodes.assign(1, patch_tree::node{});
  tree.patches.clear();
  tree.coefficients.clear();
  tree.index = {};
  std::vector<cell> todo{{tree.x0, tree.x1, tree.y0, tree.y1, 0, 0}};
  auto last = std::chrono::steady_clock::now();
  while (!todo.empty()) {
    const cell c = todo.back();
    todo.pop_back();
    const double cx = (c.x0 + c.x1) / 2, hx = (c.x1 - c.x0) / 2, cy = (c.y0 + c.y1) / 2, hy = (c.y1 - c.y0) / 2;
    std::vector<long double> f(N * N);
    for (std::size_t k = 0; k < N; ++k)
      for (std::size_t l = 0; l < N; ++l)
        f[k * N + l] = sample(static_cast<double>(cx + hx * points[k]), static_cast<double>(cy + hy * points[l])).G;
    const auto coefficients = chebyshev_coefficients_2d(f, n);
    double worst = 0;
    for (const long double u : checks)
      for (const long double v : checks) {
        const fit_sample s = sample(static_cast<double>(cx + hx * u), static_cast<double>(cy + hy * v));
        const double fit = clenshaw_2d(coefficients.data(), n, static_cast<double>(u), static_cast<double>(v));
        worst = std::max(worst, std::abs(fit - s.G) / s.allowed);
      }
    const bool at_limit = c.depth >= settings.max_depth;
    if (tree.patches.size() + todo.size() > settings.max_patches)
      throw convergence_error("surrogate fit: more than " + std::to_string(settings.max_patches) +
                              " patches; the fit does not converge (worst check at " + std::to_string(worst) +
                              " x tolerance near x = " + std::to_string(cx) + ", y = " + std::to_string(cy) + ")");
    if (worst <= 1 || at_limit) {
      if (worst > 1) ++report.unconverged_patches;
      report.worst_check_ratio = std::max(report.worst_check_ratio, worst);
      auto& node = tree.nodes[static_cast<std::size_t>(c.node)];
      node.dim = 2;
      node.child = static_cast<std::int32_t>(tree.patches.size());
      tree.add_patch({cx, 1 / hx, cy, 1 / hy}, coefficients.data());
    } else {
      // Halve along the direction with the larger coefficient tail (the last two degrees).
      double tail_x = 0, tail_y = 0;
      for (std::size_t j = 0; j < N; ++j) {
        tail_x = std::max(tail_x, std::abs(coefficients[(N - 1) * N + j]) + std::abs(coefficients[(N - 2) * N + j]));
        tail_y = std::max(tail_y, std::abs(coefficients[j * N + N - 1]) + std::abs(coefficients[j * N + N - 2]));
      }
      const int dim = tail_x >= tail_y ? 0 : 1;
      const auto child = static_cast<std::int32_t>(tree.nodes.size());
      {
        auto& node = tree.nodes[static_cast<std::size_t>(c.node)];
        node.dim = dim;
        node.child = child;
        node.split = dim == 0 ? cx : cy;
      }
      tree.nodes.push_back({});
      tree.nodes.push_back({});
      if (dim == 0) {
        todo.push_back({cx, c.x1, c.y0, c.y1, child + 1, c.depth + 1});
        todo.push_back({c.x0, cx, c.y0, c.y1, child, c.depth + 1});
      } else {
        todo.push_back({c.x0, c.x1, cy, c.y1, child + 1, c.depth + 1});
        todo.push_back({c.x0, c.x1, c.y0, cy, child, c.depth + 1});
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (progress && now - last > std::chrono::seconds(5)) {
      last = now;
      progress(std::to_string(tree.patches.size()) + " patches kept, " + std::to_string(todo.size()) + " to do");
    }
  }
  tree.build_index();
}

}  // namespace detail

/// Fits the surrogate of settings.law. progress (may be empty) gets a line now and then.
inline cor_surrogate fit_cor_surrogate(const fit_settings& settings, const surrogate_targets& targets,
                                       fit_report& report,
                                       const std::function<void(const std::string&)>& progress = {}) {
  const auto start = std::chrono::steady_clock::now();
  if (!(settings.gamma_max > 0) || !(settings.gamma_ext > settings.gamma_max))
    throw invalid_parameter("surrogate: need 0 < gamma_max < gamma_ext, got gamma_max = " +
                            std::to_string(settings.gamma_max) + ", gamma_ext = " + std::to_string(settings.gamma_ext));
  if (!(settings.g_min < 0) || !(settings.g_max > 1))
    throw invalid_parameter("surrogate: need g_min < 0 and g_max > 1");
  for (int n : {settings.order}) {
    if (n != 8 && n != 10 && n != 12 && n != 14 && n != 16)
      throw invalid_parameter("surrogate: order must be 8, 10, 12, 14 or 16, got " + std::to_string(n));
  }
  detail::truth t(settings.law, settings.long_double_truth);
  cor_surrogate s;
  s.law_name = settings.law.name;
  s.alpha = settings.law.alpha.to_string(), s.beta = settings.law.beta.to_string();
  s.gamma_max = settings.gamma_max, s.g_min = settings.g_min, s.g_max = settings.g_max;
  s.gamma_ext = settings.gamma_ext;

  // 1. where the low-load region ends, and the threshold beyond it.
  if (t.sticks(settings.gamma_ext, 0).value_or(true))
    throw invalid_parameter("surrogate: the bead sticks at g = 0 for gamma_ext = " + std::to_string(settings.gamma_ext) +
                            "; choose a smaller gamma_ext (still > gamma_max)");
  long double hi = 1e-3L;
  while (!t.sticks(settings.gamma_ext, hi).value_or(false)) hi *= 2;
  s.g_split = static_cast<double>(
      detail::bisect_threshold(hi / 2 > 1e-3L ? hi / 2 : 0.0L, hi, [&](long double g) { return t.sticks(settings.gamma_ext, g); }));
  if (progress) progress("g_split = g_c(" + std::to_string(settings.gamma_ext) + ") = " + std::to_string(s.g_split));
  s.threshold_power = settings.threshold_power;
  s.log_gamma_c = detail::fit_threshold(t, std::log(s.g_split), std::log(settings.g_max), settings.threshold_order,
                                        settings.threshold_power, 5e-14, report, progress);
  report.threshold_solves = t.solves;
  if (progress) progress("threshold: " + std::to_string(report.threshold_intervals) + " intervals, " +
                         std::to_string(t.solves) + " solves");

  // 2. the low-load region: x = gamma, y = g.
  s.low_load.x0 = 0, s.low_load.x1 = settings.gamma_max, s.low_load.y0 = settings.g_min, s.low_load.y1 = s.g_split;
  s.low_load.order = settings.order;
  detail::fit_tree(
      s.low_load,
      [&](double gamma, double g) {
        const auto r = t(gamma, g);
        const double G = static_cast<double>(r.dissipated / gamma);
        return detail::fit_sample{G, detail::allowed_error(targets, settings.fit_fraction, r.e, gamma, gamma, G)};
      },
      settings, report, progress);
  report.patches_low = s.low_load.patches.size();
  if (progress) progress("low loads: " + std::to_string(report.patches_low) + " patches");

  // 3. the high-load region: x = ln g, y = sqrt(1 - gamma / gamma_c(g)).
  s.high_load.x0 = std::log(s.g_split), s.high_load.x1 = std::log(settings.g_max);
  s.high_load.y0 = 0, s.high_load.y1 = 1;
  s.high_load.order = settings.order;
  detail::fit_tree(
      s.high_load,
      [&](double x, double y) {
        // NOTE: (gamma, g) in long double at exactly the point (x, y): in double, the
        // rounding of g = e^x and of r gamma_c would add ~1e-16 of noise to G, which the
        // fit's check points (allowed ~3e-15 near y = 0) cannot tell from a misfit.
        const long double g = std::exp(static_cast<long double>(x)), r = 1 - static_cast<long double>(y) * y;
        const long double gamma = r * detail::critical_gamma_long(s, x);
        const auto sample = t(gamma, g);
        const double G = static_cast<double>(sample.dissipated / r);
        return detail::fit_sample{G, detail::allowed_error(targets, settings.fit_fraction, sample.e, static_cast<double>(r),
                                                           static_cast<double>(gamma), G)};
      },
      settings, report, progress);
  report.patches_high = s.high_load.patches.size();
  report.solves = t.solves;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace viscor::surrogate
