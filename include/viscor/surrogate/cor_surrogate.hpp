// A fast double-precision surrogate of the CoR e(gamma, g) of one contact law:
// piecewise Chebyshev patches in coordinates in which the CoR is smooth
// (docs/surrogate.md explains the coordinates and why the fit converges).
//
//   low loads  g_min <= g <= g_split:  x = gamma, y = g;  G = (1 - e^2) / gamma
//   high loads g_split < g <= g_max:   x = ln g,  y = sqrt(1 - r), r = gamma / gamma_c(g);
//                                      G = (1 - e^2) / r, and the bead sticks for r >= 1
//
// where gamma_c(g) is the certified-by-verification damping above which the bead
// sticks, itself a 1-D Chebyshev fit of ln gamma_c in ln g. g_split = g_c(gamma_ext)
// with gamma_ext > gamma_max, so the low-load region stays away from the threshold.
// Then e^2 = 1 - w G (w = gamma or r) and 1 - e = w G / (1 + e) keep the relative
// digits of 1 - e as gamma -> 0.
//
// Evaluation: a walk down a k-d tree of patches and one 2-D Clenshaw sum; no
// allocation, no multiprecision. The coefficients are data (reference_data/
// surrogates/<law>.surrogate), read at run time by read_cor_surrogate.
#pragma once

#include <viscor/core/outcome.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/surrogate/chebyshev.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::surrogate {

/// Chebyshev patches on an adaptive k-d tree over the box [x0, x1] x [y0, y1].
/// Every split halves its cell, so the tree is all a lookup needs.
struct patch_tree {
  struct node {
    double split = 0;     ///< the coordinate value at which an inner node splits
    std::int32_t dim = 2;  ///< 0: splits x, 1: splits y, 2: leaf
    std::int32_t child = 0;  ///< inner: index of the lower child (upper = child + 1); leaf: patch index
  };
  struct patch {
    double cx = 0, sx = 1, cy = 0, sy = 1;  ///< u = (x - cx) * sx, v = (y - cy) * sy in [-1, 1]
  };
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int order = 12;  ///< points per direction; coefficients per patch: order^2
  std::vector<node> nodes{node{}};
  std::vector<patch> patches;
  std::vector<double> coefficients;  ///< patch p: [p * order^2, (p + 1) * order^2)

  double operator()(double x, double y) const noexcept {
    std::int32_t i = 0;
    while (nodes[static_cast<std::size_t>(i)].dim != 2) {
      const node& n = nodes[static_cast<std::size_t>(i)];
      const double v = n.dim == 0 ? x : y;
      i = n.child + (v >= n.split ? 1 : 0);
    }
    const std::int32_t p = nodes[static_cast<std::size_t>(i)].child;
    const patch& q = patches[static_cast<std::size_t>(p)];
    const double* c = coefficients.data() + static_cast<std::size_t>(p) * static_cast<std::size_t>(order * order);
    return clenshaw_2d(c, order, (x - q.cx) * q.sx, (y - q.cy) * q.sy);
  }
};

/// Chebyshev patches on consecutive intervals [breaks[k], breaks[k + 1]].
struct patch_line {
  int order = 16;
  std::vector<double> breaks{0, 1};
  std::vector<double> coefficients;  ///< interval k: [k * order, (k + 1) * order)

  double operator()(double x) const noexcept {
    std::size_t lo = 0, hi = breaks.size() - 2;  // find the interval: few, so bisect
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (x >= breaks[mid]) lo = mid; else hi = mid - 1;
    }
    const double a = breaks[lo], b = breaks[lo + 1];
    return clenshaw(coefficients.data() + lo * static_cast<std::size_t>(order), order, (2 * x - a - b) / (b - a));
  }
};

/// The accuracy a surrogate claims: measured maxima over its verification set
/// times `safety_factor` (0: never verified, nothing is claimed).
struct surrogate_bound {
  double abs_e = 0;            ///< |e_s - e| where e >= 1e-2
  double abs_e_squared = 0;    ///< |e_s^2 - e^2| everywhere
  double rel_one_minus_e = 0;  ///< |(1 - e)_s / (1 - e) - 1| for gamma <= 1e-2
  double safety_factor = 0;
  bool verified() const noexcept { return safety_factor > 0; }
};

/// The accuracy targets of issue 14.
struct surrogate_targets {
  double abs_e = 1e-12;            ///< where e >= 1e-2
  double abs_e_squared = 1e-13;    ///< everywhere
  double rel_one_minus_e = 1e-10;  ///< for gamma <= small_gamma (and e >= 1e-2)
  double small_gamma = 1e-2;
};

/// One surrogate evaluation.
struct surrogate_value {
  bool in_domain = false;  ///< false: outside the fitted domain, nothing else is set
  impact_outcome outcome = impact_outcome::rebound;
  double e = 0, one_minus_e = 1;
  double e_squared = 0;  ///< 1 - w G before the square root (negative past the threshold)
};

/// The surrogate of one law.
struct cor_surrogate {
  std::string law_name, alpha, beta;  ///< the law, exponents as exact texts ("3/2")
  double gamma_max = 1, g_min = -0.5, g_max = 1e4;  ///< the domain
  double gamma_ext = 1.5;  ///< the low-load region ends where g_c(gamma_ext) is
  double g_split = 0;
  patch_line log_gamma_c;  ///< ln gamma_c as a function of ln g on [ln g_split, ln g_max]
  patch_tree low_load, high_load;
  surrogate_bound bound;

  bool in_domain(double gamma, double g) const noexcept {
    return gamma >= 0 && gamma <= gamma_max && g >= g_min && g <= g_max;
  }

  /// gamma_c(g) for g_split <= g <= g_max: the bead sticks for gamma >= gamma_c.
  double critical_gamma(double g) const noexcept { return std::exp(log_gamma_c(std::log(g))); }

  surrogate_value operator()(double gamma, double g) const noexcept {
    surrogate_value v;
    if (!in_domain(gamma, g)) return v;  // also rejects NaN
    v.in_domain = true;
    double w = gamma, G = 0;
    if (g <= g_split) {
      G = low_load(gamma, g);
    } else {
      const double x = std::log(g);
      const double r = gamma / std::exp(log_gamma_c(x));
      if (r >= 1) return stick(v, 1 - r);
      w = r;
      G = high_load(x, std::sqrt(1 - r));
    }
    const double dissipated = w * G;  // 1 - e^2
    v.e_squared = 1 - dissipated;
    if (!(v.e_squared > 0)) return stick(v, v.e_squared);
    v.e = std::sqrt(v.e_squared);
    v.one_minus_e = dissipated / (1 + v.e);
    return v;
  }

  /// The inverse for calibration: the gamma in [0, gamma_max] at which e(gamma, g) =
  /// e_target, for 0.01 <= e_target < 1; NaN if e_target or g is outside that range or
  /// no gamma in the domain reaches e_target. Solves w G(w) = 1 - e_target^2 (w = gamma
  /// or r, increasing) by the Illinois variant of regula falsi on the surrogate itself,
  /// so the result is as accurate as the surrogate (about 10 evaluations).
  double gamma_for(double e_target, double g) const noexcept {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!(e_target >= 0.01 && e_target < 1) || !(g >= g_min && g <= g_max)) return nan;
    const double dissipated = (1 - e_target) * (1 + e_target);
    if (g <= g_split)
      return solve_increasing([&](double gamma) { return gamma * low_load(gamma, g) - dissipated; }, gamma_max);
    const double x = std::log(g), gc = std::exp(log_gamma_c(x));
    const double r = solve_increasing([&](double r) { return r * high_load(x, std::sqrt(1 - r)) - dissipated; },
                                      std::min(1.0, gamma_max / gc));
    return r * gc;
  }

 private:
  // The root of an increasing f on [0, b] with f(0) < 0; NaN if f(b) < 0.
  template <class F>
  static double solve_increasing(F f, double b) noexcept {
    double a = 0, fa = f(a), fb = f(b);
    if (fb < 0) return std::numeric_limits<double>::quiet_NaN();
    if (fb == 0) return b;
    int side = 0;
    for (int i = 0; i < 100; ++i) {
      const double c = (a * fb - b * fa) / (fb - fa);
      if (!(c > a && c < b)) return c == a || c == b ? c : (a + b) / 2;
      const double fc = f(c);
      // |f| is the error in 1 - e^2: 4 eps of it is below what the fit carries.
      if (std::abs(fc) <= 4 * std::numeric_limits<double>::epsilon()) return c;
      if (fc < 0) {
        a = c, fa = fc;
        if (side == -1) fb /= 2;  // Illinois: the same end twice, halve the other's weight
        side = -1;
      } else {
        b = c, fb = fc;
        if (side == 1) fa /= 2;
        side = 1;
      }
      if (b - a <= 4 * std::numeric_limits<double>::epsilon() * b) break;
    }
    return (a * fb - b * fa) / (fb - fa);
  }

  static surrogate_value stick(surrogate_value v, double e_squared) noexcept {
    v.outcome = impact_outcome::stick;
    v.e = 0, v.one_minus_e = 1, v.e_squared = e_squared;
    return v;
  }
};

// ---- the coefficient file: a small text format, every double with 17 digits ----

namespace detail {

inline void write_doubles(std::ostream& out, const std::vector<double>& v, std::size_t per_line) {
  for (std::size_t i = 0; i < v.size(); ++i) out << v[i] << ((i + 1) % per_line == 0 || i + 1 == v.size() ? '\n' : ' ');
}

inline void write_tree(std::ostream& out, const std::string& name, const patch_tree& t) {
  out << name << ' ' << t.x0 << ' ' << t.x1 << ' ' << t.y0 << ' ' << t.y1 << ' ' << t.order << ' ' << t.nodes.size()
      << ' ' << t.patches.size() << '\n';
  for (const auto& n : t.nodes) out << n.dim << ' ' << n.child << ' ' << n.split << '\n';
  for (const auto& p : t.patches) out << p.cx << ' ' << p.sx << ' ' << p.cy << ' ' << p.sy << '\n';
  write_doubles(out, t.coefficients, static_cast<std::size_t>(t.order));
}

struct reader {
  std::istream& in;
  std::string file;
  template <class T>
  T next(const char* what) {
    T x;
    if (!(in >> x)) throw parse_error(file + ": surrogate file: cannot read " + std::string(what));
    return x;
  }
  void expect(const std::string& word) {
    const auto w = next<std::string>(word.c_str());
    if (w != word) throw parse_error(file + ": surrogate file: expected '" + word + "', got '" + w + "'");
  }
};

inline patch_tree read_tree(reader& r, const std::string& name) {
  r.expect(name);
  patch_tree t;
  t.x0 = r.next<double>("x0"), t.x1 = r.next<double>("x1"), t.y0 = r.next<double>("y0"), t.y1 = r.next<double>("y1");
  t.order = r.next<int>("order");
  const auto nodes = r.next<std::size_t>("node count"), patches = r.next<std::size_t>("patch count");
  if (t.order < 2 || t.order > 64 || nodes < 1 || nodes > 100'000'000 || patches > nodes)
    throw parse_error(r.file + ": surrogate file: bad sizes in " + name);
  t.nodes.resize(nodes);
  for (auto& n : t.nodes) {
    n.dim = r.next<std::int32_t>("node"), n.child = r.next<std::int32_t>("node"), n.split = r.next<double>("node");
    const bool ok = n.dim == 2 ? (n.child >= 0 && static_cast<std::size_t>(n.child) < patches)
                               : (n.dim >= 0 && n.dim < 2 && n.child > 0 && static_cast<std::size_t>(n.child) + 1 < nodes);
    if (!ok) throw parse_error(r.file + ": surrogate file: bad node in " + name);
  }
  t.patches.resize(patches);
  for (auto& p : t.patches)
    p.cx = r.next<double>("patch"), p.sx = r.next<double>("patch"), p.cy = r.next<double>("patch"),
    p.sy = r.next<double>("patch");
  t.coefficients.resize(patches * static_cast<std::size_t>(t.order * t.order));
  for (auto& c : t.coefficients) c = r.next<double>("coefficient");
  return t;
}

}  // namespace detail

/// Writes the surrogate as text (exact: 17 significant digits per double).
inline void write_cor_surrogate(std::ostream& out, const cor_surrogate& s) {
  out << std::setprecision(17);
  out << "viscor-cor-surrogate 1\n";
  out << "law " << (s.law_name.empty() ? "-" : s.law_name) << ' ' << s.alpha << ' ' << s.beta << '\n';
  out << "domain " << s.gamma_max << ' ' << s.g_min << ' ' << s.g_max << '\n';
  out << "split " << s.gamma_ext << ' ' << s.g_split << '\n';
  out << "bound " << s.bound.abs_e << ' ' << s.bound.abs_e_squared << ' ' << s.bound.rel_one_minus_e << ' '
      << s.bound.safety_factor << '\n';
  out << "threshold " << s.log_gamma_c.order << ' ' << s.log_gamma_c.breaks.size() << '\n';
  detail::write_doubles(out, s.log_gamma_c.breaks, s.log_gamma_c.breaks.size());
  detail::write_doubles(out, s.log_gamma_c.coefficients, static_cast<std::size_t>(s.log_gamma_c.order));
  detail::write_tree(out, "low_load", s.low_load);
  detail::write_tree(out, "high_load", s.high_load);
  out << "end\n";
}

/// Reads a surrogate written by write_cor_surrogate; throws parse_error naming the file.
inline cor_surrogate read_cor_surrogate(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw invalid_parameter("cannot open surrogate file '" + path + "'");
  detail::reader r{in, path};
  cor_surrogate s;
  r.expect("viscor-cor-surrogate");
  if (r.next<int>("version") != 1) throw parse_error(path + ": surrogate file: unknown version");
  r.expect("law");
  s.law_name = r.next<std::string>("law name");
  if (s.law_name == "-") s.law_name.clear();
  s.alpha = r.next<std::string>("alpha"), s.beta = r.next<std::string>("beta");
  r.expect("domain");
  s.gamma_max = r.next<double>("gamma_max"), s.g_min = r.next<double>("g_min"), s.g_max = r.next<double>("g_max");
  r.expect("split");
  s.gamma_ext = r.next<double>("gamma_ext"), s.g_split = r.next<double>("g_split");
  r.expect("bound");
  s.bound.abs_e = r.next<double>("bound"), s.bound.abs_e_squared = r.next<double>("bound");
  s.bound.rel_one_minus_e = r.next<double>("bound"), s.bound.safety_factor = r.next<double>("bound");
  r.expect("threshold");
  s.log_gamma_c.order = r.next<int>("threshold order");
  const auto breaks = r.next<std::size_t>("threshold breaks");
  if (s.log_gamma_c.order < 2 || s.log_gamma_c.order > 64 || breaks < 2 || breaks > 100000)
    throw parse_error(path + ": surrogate file: bad threshold sizes");
  s.log_gamma_c.breaks.resize(breaks);
  for (auto& b : s.log_gamma_c.breaks) b = r.next<double>("threshold break");
  s.log_gamma_c.coefficients.resize((breaks - 1) * static_cast<std::size_t>(s.log_gamma_c.order));
  for (auto& c : s.log_gamma_c.coefficients) c = r.next<double>("threshold coefficient");
  s.low_load = detail::read_tree(r, "low_load");
  s.high_load = detail::read_tree(r, "high_load");
  r.expect("end");
  return s;
}

}  // namespace viscor::surrogate
