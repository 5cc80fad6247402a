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
// Evaluation: a grid lookup of the patch (the k-d tree's walk where the grid cell
// is split further), one 2-D Clenshaw sum on coefficients stored by columns (vector
// fused multiply-adds on x86 with AVX2 + FMA, chosen at run time, bit-identical to
// the portable path); no allocation, no multiprecision. docs/performance.md
// ("Surrogates") has the cost and the profile behind this layout. The coefficients
// are data (reference_data/surrogates/<law>.surrogate), read at run time by
// read_cor_surrogate.
#pragma once

#include <viscor/core/checksums.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/surrogate/chebyshev.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <istream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace viscor::surrogate {

/// Chebyshev patches on an adaptive k-d tree over the box [x0, x1] x [y0, y1].
/// Every split halves its cell, so the tree is all a lookup needs; build_index adds a
/// grid that finds most patches without walking the tree.
struct patch_tree {
  /// A node of the tree: an inner split or a leaf naming its patch.
  struct node {
    double split = 0;     ///< the coordinate value at which an inner node splits
    std::int32_t dim = 2;  ///< 0: splits x, 1: splits y, 2: leaf
    std::int32_t child = 0;  ///< inner: index of the lower child (upper = child + 1); leaf: patch index
  };
  /// A leaf's affine map from its cell onto [-1, 1]^2.
  struct patch {
    double cx = 0, sx = 1, cy = 0, sy = 1;  ///< u = (x - cx) * sx, v = (y - cy) * sy in [-1, 1]
  };
  /// The points the tree sends to one patch: x_lo <= x < x_hi and y_lo <= y < y_hi
  /// (its ancestors' splits; infinite on the sides where it has none).
  struct region {
    double x_lo = -HUGE_VAL, x_hi = HUGE_VAL, y_lo = -HUGE_VAL, y_hi = HUGE_VAL;
    /// Whether (x, y) is one of them (false for NaN).
    bool holds(double x, double y) const noexcept { return x >= x_lo && x < x_hi && y >= y_lo && y < y_hi; }
  };
  /// A uniform grid over the box: each cell holds the patch that covers it (-1 - p), or
  /// else the deepest node that does (>= 0), from which the walk goes on. Derived from
  /// the tree by build_index; empty until then (locate walks the whole tree).
  struct lookup_grid {
    int nx = 0, ny = 0;          ///< cells per direction (powers of 2)
    double sx = 0, sy = 0;       ///< cells per unit of x and of y
    std::vector<std::int32_t> cells;  ///< cell (kx, ky) at ky * nx + kx
    std::vector<region> regions;      ///< per patch, to confirm a patch found through the grid
  };

  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int order = 12;  ///< points per direction; coefficients per patch: order^2
  std::vector<node> nodes{node{}};
  std::vector<patch> patches;
  /// Patch p: [p n^2, (p + 1) n^2), n = order, stored by columns: the coefficient of
  /// T_i(x) T_j(y) at p n^2 + j n + i (clenshaw_2d_by_columns). The fit and the file
  /// hold them by rows (i n + j); add_patch and read_cor_surrogate transpose.
  std::vector<double> coefficients;
  lookup_grid index;  ///< see lookup_grid; rebuild with build_index after changing nodes

  /// Appends patch q with its coefficients by rows (c[i n + j], as
  /// chebyshev_coefficients_2d gives them); returns its index.
  std::int32_t add_patch(const patch& q, const double* by_rows) {
    const std::size_t n = static_cast<std::size_t>(order);
    patches.push_back(q);
    const std::size_t first = coefficients.size();
    coefficients.resize(first + n * n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) coefficients[first + j * n + i] = by_rows[i * n + j];
    return static_cast<std::int32_t>(patches.size() - 1);
  }

  /// The coefficient of T_i(x) T_j(y) in patch p.
  double coefficient(std::size_t p, int i, int j) const noexcept {
    const std::size_t n = static_cast<std::size_t>(order);
    return coefficients[p * n * n + static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i)];
  }

  /// Builds `index` from the nodes (read_cor_surrogate and the fit call it).
  void build_index() {
    index = lookup_grid{};
    if (patches.empty() || !(x1 > x0) || !(y1 > y0)) return;  // nothing to index: locate walks
    // Depth of the tree in x and in y, and each patch's region.
    std::vector<region> regions(patches.size());
    int depth_x = 0, depth_y = 0;
    struct visit { std::int32_t node; region r; int dx, dy; };
    std::vector<visit> todo{{0, region{}, 0, 0}};
    while (!todo.empty()) {
      const visit v = todo.back();
      todo.pop_back();
      const node& n = nodes[static_cast<std::size_t>(v.node)];
      if (n.dim == 2) {
        regions[static_cast<std::size_t>(n.child)] = v.r;
        depth_x = std::max(depth_x, v.dx), depth_y = std::max(depth_y, v.dy);
        continue;
      }
      visit lower = v, upper = v;
      lower.node = n.child, upper.node = n.child + 1;
      if (n.dim == 0) lower.r.x_hi = upper.r.x_lo = n.split, ++lower.dx, ++upper.dx;
      else lower.r.y_hi = upper.r.y_lo = n.split, ++lower.dy, ++upper.dy;
      todo.push_back(lower);
      todo.push_back(upper);
    }
    // At most 2^10 cells per direction and 2^16 in all: deeper cells go on walking.
    depth_x = std::min(depth_x, 10), depth_y = std::min(depth_y, 10);
    while (depth_x + depth_y > 16) (depth_x > depth_y ? depth_x : depth_y) -= 1;
    lookup_grid g;
    g.nx = 1 << depth_x, g.ny = 1 << depth_y;
    g.sx = g.nx / (x1 - x0), g.sy = g.ny / (y1 - y0);
    g.cells.resize(static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny));
    const double wx = (x1 - x0) / g.nx, wy = (y1 - y0) / g.ny;
    for (int ky = 0; ky < g.ny; ++ky)
      for (int kx = 0; kx < g.nx; ++kx) {
        // The deepest node whose cell holds this one (shrunk by 1e-9 of its width, so
        // that a split computed with other roundings than the grid's still decides).
        const double a = x0 + kx * wx + 1e-9 * wx, b = x0 + (kx + 1) * wx - 1e-9 * wx;
        const double c = y0 + ky * wy + 1e-9 * wy, d = y0 + (ky + 1) * wy - 1e-9 * wy;
        std::int32_t i = 0;
        for (;;) {
          const node& n = nodes[static_cast<std::size_t>(i)];
          if (n.dim == 2) break;
          const double lo = n.dim == 0 ? a : c, hi = n.dim == 0 ? b : d;
          if (lo >= n.split) i = n.child + 1;
          else if (hi < n.split) i = n.child;
          else break;
        }
        const node& n = nodes[static_cast<std::size_t>(i)];
        g.cells[static_cast<std::size_t>(ky) * static_cast<std::size_t>(g.nx) + static_cast<std::size_t>(kx)] =
            n.dim == 2 ? -1 - n.child : i;
      }
    g.regions = std::move(regions);
    index = std::move(g);
  }

  /// The index of the patch that holds (x, y): the walk down the tree from the root.
  VISCOR_SURROGATE_INLINE std::int32_t walk(double x, double y, std::int32_t i = 0) const noexcept {
    while (nodes[static_cast<std::size_t>(i)].dim != 2) {
      const node& n = nodes[static_cast<std::size_t>(i)];
      const double v = n.dim == 0 ? x : y;
      i = n.child + (v >= n.split ? 1 : 0);
    }
    return nodes[static_cast<std::size_t>(i)].child;
  }

  /// The index of the patch that holds (x, y), the same as walk(x, y): through the
  /// grid where it is built, confirmed by the patch's region (a point on a split, or
  /// a cell index rounded the other way, takes the walk from the root).
  VISCOR_SURROGATE_INLINE std::int32_t locate(double x, double y) const noexcept {
    if (index.cells.empty()) return walk(x, y);
    const double fx = (x - x0) * index.sx, fy = (y - y0) * index.sy;
    // NOTE: compared as doubles before the conversion (out of range or NaN: no int).
    const int kx = fx >= 0 ? (fx < index.nx ? static_cast<int>(fx) : index.nx - 1) : 0;
    const int ky = fy >= 0 ? (fy < index.ny ? static_cast<int>(fy) : index.ny - 1) : 0;
    const std::int32_t cell = index.cells[static_cast<std::size_t>(ky) * static_cast<std::size_t>(index.nx) + static_cast<std::size_t>(kx)];
    const std::int32_t p = cell < 0 ? -1 - cell : walk(x, y, cell);
    return index.regions[static_cast<std::size_t>(p)].holds(x, y) ? p : walk(x, y);
  }

  /// The interpolant at (x, y), which must lie in the box. WithFma: by the AVX2
  /// kernels (clenshaw_2d_by_columns), for code compiled for FMA only.
  template <bool WithFma = false>
  VISCOR_SURROGATE_INLINE double value(double x, double y) const noexcept {
    const std::int32_t p = locate(x, y);
    const patch& q = patches[static_cast<std::size_t>(p)];
    const double* c = coefficients.data() + static_cast<std::size_t>(p) * static_cast<std::size_t>(order * order);
    return clenshaw_2d_by_columns<WithFma>(c, order, (x - q.cx) * q.sx, (y - q.cy) * q.sy);
  }
  /// The interpolant at (x, y), which must lie in the box.
  double operator()(double x, double y) const noexcept { return value(x, y); }
};

/// Chebyshev patches on consecutive intervals [breaks[k], breaks[k + 1]].
struct patch_line {
  int order = 16;
  std::vector<double> breaks{0, 1};
  std::vector<double> coefficients;  ///< interval k: [k * order, (k + 1) * order)

  /// The index k of the interval that holds x: the number of inner breaks <= x
  /// (NaN: 0). Few breaks are counted without a branch to mispredict; many, bisected.
  VISCOR_SURROGATE_INLINE std::size_t interval(double x) const noexcept {
    const std::size_t inner = breaks.size() - 2;
    if (inner <= 32) {
      std::size_t k = 0;
      for (std::size_t m = 1; m <= inner; ++m) k += x >= breaks[m] ? 1 : 0;
      return k;
    }
    std::size_t lo = 0, hi = inner;
    while (lo < hi) {
      const std::size_t mid = (lo + hi + 1) / 2;
      if (x >= breaks[mid]) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  /// The interpolant at x, which must lie in [breaks.front(), breaks.back()].
  VISCOR_SURROGATE_INLINE double operator()(double x) const noexcept {
    const std::size_t k = interval(x);
    const double a = breaks[k], b = breaks[k + 1];
    return clenshaw(coefficients.data() + k * static_cast<std::size_t>(order), order, (2 * x - a - b) / (b - a));
  }
};

/// The accuracy a surrogate claims: measured maxima over its verification set
/// times `safety_factor` (0: never verified, nothing is claimed).
struct surrogate_bound {
  double abs_e = 0;            ///< |e_s - e| where e >= 1e-2
  double abs_e_squared = 0;    ///< |e_s^2 - e^2| everywhere
  double rel_one_minus_e = 0;  ///< |(1 - e)_s / (1 - e) - 1| for gamma <= 1e-2
  double safety_factor = 0;
  /// Whether the bound comes from a verification (a safety factor was applied).
  bool verified() const noexcept { return safety_factor > 0; }
};

/// The accuracy targets a surrogate is built and verified against (docs/surrogate.md).
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
  /// ln gamma_c(g) = log_gamma_c(ln g) - threshold_power ln g on [ln g_split, ln g_max]: the
  /// fitted line holds ln(g^p gamma_c), which stays O(1) where gamma_c follows a power law.
  /// NOTE: ln gamma_c itself reaches -20 at large g (linear law: gamma_c ~ 1/(2 pi g^2)),
  /// and a double near 20 is only good to 3.6e-15: gamma_c = exp(ln gamma_c) in double
  /// would jitter by ~1e-14 from one g to the next, and G with it near the threshold.
  /// With g^-p taken out, gamma_c = exp(h) pow(g, -p) is good to a few 1e-16.
  patch_line log_gamma_c;
  double threshold_power = 0;
  patch_tree low_load, high_load;
  surrogate_bound bound;

  /// Whether (gamma, g) lies in the fitted domain (false for NaN).
  bool in_domain(double gamma, double g) const noexcept {
    return gamma >= 0 && gamma <= gamma_max && g >= g_min && g <= g_max;
  }

  /// gamma_c(g) for g_split <= g <= g_max: the bead sticks for gamma >= gamma_c.
  double critical_gamma(double g) const noexcept { return critical_gamma_at(g, std::log(g)); }
  /// The same, given x = ln g.
  VISCOR_SURROGATE_INLINE double critical_gamma_at(double g, double x) const noexcept {
    const double h = std::exp(log_gamma_c(x));
    return threshold_power == 0 ? h : h * std::pow(g, -threshold_power);
  }

  /// e, 1 - e and the outcome at (gamma, g); in_domain false (and nothing else set) outside the domain.
  surrogate_value operator()(double gamma, double g) const noexcept {
#if VISCOR_SURROGATE_FMA_DISPATCH
    if (cpu_has_fma()) return evaluate_with_fma(gamma, g);
#endif
    return evaluate(gamma, g);
  }

  /// The inverse for calibration: the gamma in [0, gamma_max] at which e(gamma, g) =
  /// e_target, for 0.01 <= e_target < 1; NaN if e_target or g is outside that range or
  /// no gamma in the domain reaches e_target. Solves w G(w) = D = 1 - e_target^2 (w =
  /// gamma or r, w G increasing in w) on the surrogate itself, so the result is as
  /// accurate as the surrogate, by Newton's method started from w G(0) = D, inside a
  /// bracket that every step narrows (bisection when a step leaves it). G and dG/dw
  /// come from the patch restricted to the line of fixed g: one 1-D Chebyshev series
  /// per patch visited, so a Newton step costs a short Clenshaw sum, not a 2-D one.
  double gamma_for(double e_target, double g) const noexcept {
#if VISCOR_SURROGATE_FMA_DISPATCH
    if (cpu_has_fma()) return inverse_with_fma(e_target, g);
#endif
    return inverse(e_target, g);
  }

  /// operator() on the portable path (std::fma as compiled for the build's target,
  /// a libm call on the x86-64 baseline); operator() must give bit-identical results.
  surrogate_value evaluate_portable(double gamma, double g) const noexcept { return evaluate(gamma, g); }
  /// gamma_for on the portable path, bit-identical to gamma_for.
  double gamma_for_portable(double e_target, double g) const noexcept { return inverse(e_target, g); }

 private:
#if VISCOR_SURROGATE_FMA_DISPATCH
  VISCOR_SURROGATE_FMA_TARGET surrogate_value evaluate_with_fma(double gamma, double g) const noexcept {
    return evaluate<true>(gamma, g);
  }
  VISCOR_SURROGATE_FMA_TARGET double inverse_with_fma(double e_target, double g) const noexcept {
    return inverse(e_target, g);
  }
#endif

  // WithFma: the 2-D sums by the AVX2 kernels (only in evaluate_with_fma).
  template <bool WithFma = false>
  VISCOR_SURROGATE_INLINE surrogate_value evaluate(double gamma, double g) const noexcept {
    surrogate_value v;
    if (!in_domain(gamma, g)) return v;  // also rejects NaN
    v.in_domain = true;
    double w = gamma, G = 0;
    if (g <= g_split) {
      G = low_load.value<WithFma>(gamma, g);
    } else {
      const double x = std::log(g);
      const double r = gamma / critical_gamma_at(g, x);
      if (r >= 1) return stick(v, 1 - r);
      w = r;
      G = high_load.value<WithFma>(x, std::sqrt(1 - r));
    }
    const double dissipated = w * G;  // 1 - e^2
    v.e_squared = 1 - dissipated;
    if (!(v.e_squared > 0)) return stick(v, v.e_squared);
    v.e = std::sqrt(v.e_squared);
    v.one_minus_e = dissipated / (1 + v.e);
    return v;
  }

  VISCOR_SURROGATE_INLINE double inverse(double e_target, double g) const noexcept {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!(e_target >= 0.01 && e_target < 1) || !(g >= g_min && g <= g_max)) return nan;
    const double dissipated = (1 - e_target) * (1 + e_target);
    if (!(dissipated > 0)) return 0;
    if (g <= g_split) return solve_dissipation(low_load, /*x_free=*/true, g, dissipated, gamma_max);
    const double x = std::log(g), gc = critical_gamma_at(g, x);
    return solve_dissipation(high_load, /*x_free=*/false, x, dissipated, std::min(1.0, gamma_max / gc)) * gc;
  }

  // One patch of a tree restricted to a line of its fixed coordinate: G as a
  // Chebyshev series in t = (z - c) s on [lo, hi] of the free coordinate z.
  // NOTE: products are added by std::fma, never written a * b + c: GCC contracts
  // a * b + c into an fma where the target has one (-ffp-contract=fast, its
  // default), so the FMA path and the portable path would differ in the last bit.
  struct slice {
    std::int32_t patch = -1;
    double c = 0, s = 1, lo = 0, hi = 0;
    int n = 0;
    double a[64] = {};

    VISCOR_SURROGATE_INLINE void build(const patch_tree& tree, bool x_free, double fixed, double z) noexcept {
      patch = x_free ? tree.locate(z, fixed) : tree.locate(fixed, z);
      const auto& q = tree.patches[static_cast<std::size_t>(patch)];
      const std::size_t N = static_cast<std::size_t>(tree.order);
      n = tree.order;
      const double* coef = tree.coefficients.data() + static_cast<std::size_t>(patch) * N * N;
      // T_k at the fixed coordinate's position in the patch
      const double u = x_free ? (fixed - q.cy) * q.sy : (fixed - q.cx) * q.sx;
      double T[64];
      T[0] = 1, T[1] = u;
      for (std::size_t k = 2; k < N; ++k) T[k] = std::fma(2 * u, T[k - 1], -T[k - 2]);
      for (std::size_t i = 0; i < N; ++i) a[i] = 0;
      if (x_free) {  // coefficient (i, j) of T_i(x) T_j(y) at coef[j * N + i]; y fixed
        for (std::size_t i = 0; i < N; ++i)
          for (std::size_t j = 0; j < N; ++j) a[i] = std::fma(coef[j * N + i], T[j], a[i]);
        c = q.cx, s = q.sx;
      } else {
        for (std::size_t i = 0; i < N; ++i)
          for (std::size_t j = 0; j < N; ++j) a[j] = std::fma(coef[j * N + i], T[i], a[j]);
        c = q.cy, s = q.sy;
      }
      lo = c - 1 / s, hi = c + 1 / s;
    }
    bool holds(double z) const noexcept { return patch >= 0 && z >= lo && z < hi; }
    // G and dG/dz at z (Clenshaw with its derivative).
    VISCOR_SURROGATE_INLINE void value(double z, double& G, double& dG) const noexcept {
      const double t = (z - c) * s, two_t = 2 * t;
      double b1 = 0, b2 = 0, d1 = 0, d2 = 0;
      for (int k = n - 1; k >= 1; --k) {
        const double b0 = std::fma(two_t, b1, a[k] - b2);
        const double d0 = std::fma(two_t, d1, 2 * b1 - d2);
        b2 = b1, b1 = b0, d2 = d1, d1 = d0;
      }
      G = std::fma(t, b1, a[0] - b2);
      dG = (std::fma(t, d1, b1) - d2) * s;
    }
  };

  // f(w) = w G(w) - D on the line of fixed coordinate `fixed`, and df = f'(w); the free
  // coordinate is z = w (low loads, x_free) or z = sqrt(1 - w) (high loads). `sl` caches
  // the patch's restriction to the line. (A function, not a lambda: a lambda would not
  // be compiled for the FMA path of its caller.)
  VISCOR_SURROGATE_INLINE static double dissipation_residual(const patch_tree& tree, bool x_free, double fixed, double D,
                                                             slice& sl, double w, double& df) noexcept {
    const double z = x_free ? w : std::sqrt(1 - w);
    const double zc = x_free ? std::min(std::max(z, tree.x0), tree.x1) : std::min(std::max(z, tree.y0), tree.y1);
    if (!sl.holds(zc)) sl.build(tree, x_free, fixed, zc);
    double G, dGdz;
    sl.value(z, G, dGdz);
    const double dGdw = x_free ? dGdz : (z > 0 ? -dGdz / (2 * z) : 0.0);
    df = std::fma(w, dGdw, G);
    return std::fma(w, G, -D);
  }

  // The w in [0, b] with w G(w) = D (dissipation_residual). NaN if b G(b) < D.
  VISCOR_SURROGATE_INLINE static double solve_dissipation(const patch_tree& tree, bool x_free, double fixed, double D, double b) noexcept {
    constexpr double eps = std::numeric_limits<double>::epsilon();
    slice sl;
    double df = 0;
    if (dissipation_residual(tree, x_free, fixed, D, sl, b, df) < 0) return std::numeric_limits<double>::quiet_NaN();
    double neg = 0, pos = b;
    dissipation_residual(tree, x_free, fixed, D, sl, 0, df);  // df = G(0)
    double w = std::min(D / df, b);
    for (int i = 0; i < 40; ++i) {
      const double fw = dissipation_residual(tree, x_free, fixed, D, sl, w, df);
      if (fw == 0) return w;
      (fw < 0 ? neg : pos) = w;
      double next = w - fw / df;
      // NOTE: converged before the safeguard: a step below rounding lands on w, which
      // was just made a bracket end, and the safeguard would bisect the whole bracket
      // (seen once the residual w G - D became one exactly rounded fma).
      if (std::abs(next - w) <= 2 * eps * w) return next;
      if (!(next > neg && next < pos)) next = (neg + pos) / 2;  // safeguard
      if (pos - neg <= 2 * eps * pos) return next;
      w = next;
    }
    return w;
  }

  VISCOR_SURROGATE_INLINE static surrogate_value stick(surrogate_value v, double e_squared) noexcept {
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
  // By rows, a row per line (the file's order; memory holds them by columns).
  const int n = t.order;
  for (std::size_t p = 0; p < t.patches.size(); ++p)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) out << t.coefficient(p, i, j) << (j + 1 == n ? '\n' : ' ');
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

/// The most nodes a patch tree may have: the fit writes about a hundred; ten
/// million is a file of some 300 MB.
inline constexpr std::size_t max_tree_nodes = 10'000'000;

inline patch_tree read_tree(reader& r, const std::string& name) {
  r.expect(name);
  patch_tree t;
  t.x0 = r.next<double>("x0"), t.x1 = r.next<double>("x1"), t.y0 = r.next<double>("y0"), t.y1 = r.next<double>("y1");
  t.order = r.next<int>("order");
  const auto nodes = r.next<std::size_t>("node count"), patches = r.next<std::size_t>("patch count");
  if (t.order < 2 || t.order > 64 || nodes < 1 || nodes > max_tree_nodes || patches > nodes)
    throw parse_error(r.file + ": surrogate file: bad sizes in " + name);
  if (!std::isfinite(t.x0) || !std::isfinite(t.x1) || !std::isfinite(t.y0) || !std::isfinite(t.y1) ||
      !(t.x0 < t.x1) || !(t.y0 < t.y1))
    throw parse_error(r.file + ": surrogate file: bad box in " + name);
  // A tree as the fit writes it: each node's children come after it, every node
  // but the root is the child of exactly one node and every patch belongs to
  // exactly one leaf. Anything else (a cycle, a shared subtree) would make the
  // walk down the tree loop or the index grow without bound. The counts are only
  // claims: storage grows with what is read, so a short file that claims millions
  // of nodes fails at its end, not after allocating them.
  t.nodes.clear();
  t.nodes.reserve(std::min<std::size_t>(nodes, 4096));
  std::vector<char> node_used, patch_used;
  auto mark = [](std::vector<char>& used, std::size_t i) {  // false if i was used before
    if (i >= used.size()) used.resize(i + 1, 0);
    return !used[i]++;
  };
  for (std::size_t k = 0; k < nodes; ++k) {
    auto& n = t.nodes.emplace_back();
    n.dim = r.next<std::int32_t>("node"), n.child = r.next<std::int32_t>("node"), n.split = r.next<double>("node");
    bool ok = n.dim == 2 ? (n.child >= 0 && static_cast<std::size_t>(n.child) < patches)
                         : (n.dim >= 0 && n.dim < 2 && n.child > 0 && static_cast<std::size_t>(n.child) > k &&
                            static_cast<std::size_t>(n.child) + 1 < nodes && std::isfinite(n.split));
    if (ok && n.dim == 2) ok = mark(patch_used, static_cast<std::size_t>(n.child));
    if (ok && n.dim != 2)
      ok = mark(node_used, static_cast<std::size_t>(n.child)) && mark(node_used, static_cast<std::size_t>(n.child) + 1);
    if (!ok) throw parse_error(r.file + ": surrogate file: bad node " + std::to_string(k) + " in " + name);
  }
  node_used.resize(nodes, 0), patch_used.resize(patches, 0);  // every node and patch read by now
  if (std::count(node_used.begin() + 1, node_used.end(), 0) != 0 || std::count(patch_used.begin(), patch_used.end(), 0) != 0)
    throw parse_error(r.file + ": surrogate file: nodes or patches outside the tree in " + name);
  t.patches.resize(patches);
  for (auto& p : t.patches) {
    p.cx = r.next<double>("patch"), p.sx = r.next<double>("patch"), p.cy = r.next<double>("patch"),
    p.sy = r.next<double>("patch");
    if (!std::isfinite(p.cx) || !std::isfinite(p.sx) || !std::isfinite(p.cy) || !std::isfinite(p.sy))
      throw parse_error(r.file + ": surrogate file: bad patch in " + name);
  }
  const std::size_t n = static_cast<std::size_t>(t.order);
  std::vector<double> by_rows(n * n);  // the file's order, one patch at a time
  std::vector<patch_tree::patch> maps;
  maps.swap(t.patches);
  t.patches.reserve(patches);
  t.coefficients.reserve(patches * n * n);
  for (const auto& q : maps) {
    for (auto& c : by_rows) c = r.next<double>("coefficient");
    t.add_patch(q, by_rows.data());
  }
  t.build_index();
  return t;
}

}  // namespace detail

/// Writes the surrogate as text (exact: 17 significant digits per double).
inline void write_cor_surrogate(std::ostream& out, const cor_surrogate& s) {
  out << std::setprecision(17);
  // Version 2 adds the threshold power; without one the file stays version 1.
  out << "viscor-cor-surrogate " << (s.threshold_power == 0 ? 1 : 2) << '\n';
  out << "law " << (s.law_name.empty() ? "-" : s.law_name) << ' ' << s.alpha << ' ' << s.beta << '\n';
  out << "domain " << s.gamma_max << ' ' << s.g_min << ' ' << s.g_max << '\n';
  out << "split " << s.gamma_ext << ' ' << s.g_split << '\n';
  out << "bound " << s.bound.abs_e << ' ' << s.bound.abs_e_squared << ' ' << s.bound.rel_one_minus_e << ' '
      << s.bound.safety_factor << '\n';
  out << "threshold " << s.log_gamma_c.order << ' ' << s.log_gamma_c.breaks.size();
  if (s.threshold_power != 0) out << ' ' << s.threshold_power;
  out << '\n';
  detail::write_doubles(out, s.log_gamma_c.breaks, s.log_gamma_c.breaks.size());
  detail::write_doubles(out, s.log_gamma_c.coefficients, static_cast<std::size_t>(s.log_gamma_c.order));
  detail::write_tree(out, "low_load", s.low_load);
  detail::write_tree(out, "high_load", s.high_load);
  out << "end\n";
}

/// Reads a surrogate written by write_cor_surrogate from `in`; `path` names it in
/// errors. Throws parse_error naming it.
inline cor_surrogate read_cor_surrogate(std::istream& in, const std::string& path) {
  detail::reader r{in, path};
  cor_surrogate s;
  r.expect("viscor-cor-surrogate");
  const int version = r.next<int>("version");
  if (version != 1 && version != 2) throw parse_error(path + ": surrogate file: unknown version");
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
  if (version >= 2) s.threshold_power = r.next<double>("threshold power");
  if (!std::isfinite(s.threshold_power)) throw parse_error(path + ": surrogate file: bad threshold power");
  if (s.log_gamma_c.order < 2 || s.log_gamma_c.order > 64 || breaks < 2 || breaks > 100000)
    throw parse_error(path + ": surrogate file: bad threshold sizes");
  const auto finite = [](std::initializer_list<double> xs) {
    return std::all_of(xs.begin(), xs.end(), [](double x) { return std::isfinite(x); });
  };
  if (!finite({s.gamma_max, s.g_min, s.g_max, s.gamma_ext, s.g_split}) || !(s.gamma_max > 0) || !(s.g_min < s.g_max))
    throw parse_error(path + ": surrogate file: bad domain");
  if (!finite({s.bound.abs_e, s.bound.abs_e_squared, s.bound.rel_one_minus_e, s.bound.safety_factor}) ||
      s.bound.abs_e < 0 || s.bound.abs_e_squared < 0 || s.bound.rel_one_minus_e < 0 || s.bound.safety_factor < 0)
    throw parse_error(path + ": surrogate file: bad bound");
  s.log_gamma_c.breaks.resize(breaks);
  for (auto& b : s.log_gamma_c.breaks) {
    b = r.next<double>("threshold break");
    if (!std::isfinite(b) || (&b != s.log_gamma_c.breaks.data() && !(b > (&b)[-1])))
      throw parse_error(path + ": surrogate file: threshold breaks must be finite and increasing");
  }
  s.log_gamma_c.coefficients.resize((breaks - 1) * static_cast<std::size_t>(s.log_gamma_c.order));
  for (auto& c : s.log_gamma_c.coefficients) c = r.next<double>("threshold coefficient");
  s.low_load = detail::read_tree(r, "low_load");
  s.high_load = detail::read_tree(r, "high_load");
  r.expect("end");
  std::string rest;
  if (in >> rest) throw parse_error(path + ": surrogate file: text after 'end': '" + rest + "'");
  return s;
}

/// Reads a surrogate file written by write_cor_surrogate; throws parse_error naming the
/// file. A file listed in a checksum manifest beside it is checked first (core/checksums.hpp).
inline cor_surrogate read_cor_surrogate(const std::string& path) {
  std::istringstream in(read_checked_file<invalid_parameter>(path, "surrogate file"));
  return read_cor_surrogate(in, path);
}

}  // namespace viscor::surrogate
