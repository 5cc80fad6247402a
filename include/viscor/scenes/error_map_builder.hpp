// Building error maps (error_map.hpp) from reference values of e.
//
// Input: reference points (gamma, g, e, outcome) of one contact law -- rows of
// the certified tables of reference_data/, or values computed here by
// solve_impact at high precision -- and a tensor grid of cell edges in gamma and
// g. Each cell [gamma_i, gamma_i+1] x [g_j, g_j+1] is mapped only if
//   * all four corners are reference points and it holds >= min_samples of them;
//   * for each approximation, every sample gives a finite value;
// and then gets bound = safety_factor x max |approximation - e| + floor.
//
// NOTE on the safety factor (default 4) and the floor (default 1e-14): the
// bound must hold between the samples too. Away from the sticking threshold the
// approximation errors are smooth in (gamma, g) and grow like a power of gamma,
// so the worst sample is close to the worst point. Measured (3000 random points
// per law in the mapped cells of gamma in [1e-5, 0.3] x g in [0, 10], half-decade
// cells in gamma, 3 x 3 samples per cell, references by solve_impact at 34
// digits): worst error / worst sample <= 0.99 for Kuwabara-Kono and Hunt-Crossley,
// 1.11 for Prop. 2 (quadrature) on the linear law; with the corners alone
// (2 x 2 samples) still <= 0.99 for Kuwabara-Kono. A factor 4 leaves a 3.6x
// margin over the worst case seen. The floor covers rounding of the double
// formulas and of the inputs (tens of ulps of e).
// Cells the threshold crosses (mixed outcomes) get no bounds: there
// e ~ sqrt(distance to the threshold) and no sampling bounds the error.
// Monotonicity of e in gamma and g (checked in the calibration tests) makes the
// corners decide the outcome of the whole cell.
#pragma once

#include <viscor/approx/approximations.hpp>
#include <viscor/scenes/error_map.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/scenes/spaced_range.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace viscor {

/// One reference value; gamma, g, e and 1 - e as exact decimal text.
struct reference_point {
  std::string gamma, g, e;
  impact_outcome outcome = impact_outcome::rebound;
  std::string one_minus_e;  ///< "" where the source gives only e
};

/// A reference value in double, with its place in the list it came from.
struct reference_sample {
  double gamma = 0, g = 0, e = 0;
  impact_outcome outcome = impact_outcome::rebound;
  std::size_t index = 0;  ///< into the reference points
};

/// A cell of the grid with the reference samples that map it.
struct mappable_cell {
  std::size_t i = 0, j = 0;                    ///< the cell [gamma_i, gamma_i+1] x [g_j, g_j+1]
  std::vector<const reference_sample*> samples; ///< the reference points inside it, edges included
  cell_outcome outcome = cell_outcome::rebound; ///< mixed when the samples disagree (or one is undecided)
};

/// What build_error_map needs: the cell edges, the safety factor, floor and fewest samples per cell, and provenance.
struct error_map_spec {
  std::vector<std::string> gamma_edges, g_edges;  ///< increasing exact decimals
  double safety_factor = 4;
  double floor = 1e-14;
  int min_samples = 4;
  std::vector<std::pair<std::string, std::string>> metadata;  ///< provenance written into the map
};

namespace detail {
inline std::vector<double> parse_edges(const std::vector<std::string>& edges, const std::string& name) {
  if (edges.size() < 2) throw invalid_parameter("error map: " + name + " needs at least 2 edges");
  std::vector<double> v;
  for (const auto& e : edges) {
    v.push_back(parse_real<double>(e, name + " edge"));
    if (v.size() > 1 && !(v[v.size() - 2] < v.back()))
      throw invalid_parameter("error map: " + name + " must increase, got " + edges[v.size() - 2] + " then " + e);
  }
  return v;
}
}  // namespace detail

/// The reference points in double (their text checked: numbers only).
inline std::vector<reference_sample> reference_samples(const std::vector<reference_point>& points) {
  std::vector<reference_sample> s;
  s.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const reference_point& p = points[k];
    for (const auto* t : {&p.gamma, &p.g, &p.e})
      if (!detail::looks_like_decimal(*t)) throw invalid_parameter("error map: reference value '" + *t + "' is not a number");
    s.push_back({std::strtod(p.gamma.c_str(), nullptr), std::strtod(p.g.c_str(), nullptr),
                 std::strtod(p.e.c_str(), nullptr), p.outcome, k});
  }
  return s;
}

/// The cells of the grid (gx, gy: its edges) that the samples can map: all four
/// corners among the samples, and at least `min_samples` of them inside (edges
/// included). The error map and the check of an outside formula use this one rule,
/// so both judge a cell by the same points.
inline std::vector<mappable_cell> mappable_cells(const std::vector<reference_sample>& s, const std::vector<double>& gx,
                                                 const std::vector<double>& gy, int min_samples) {
  std::vector<mappable_cell> cells;
  for (std::size_t i = 0; i + 1 < gx.size(); ++i) {
    for (std::size_t j = 0; j + 1 < gy.size(); ++j) {
      mappable_cell c{i, j, {}, cell_outcome::rebound};
      std::set<std::pair<double, double>> at;
      for (const auto& p : s)
        if (gx[i] <= p.gamma && p.gamma <= gx[i + 1] && gy[j] <= p.g && p.g <= gy[j + 1]) {
          c.samples.push_back(&p);
          at.emplace(p.gamma, p.g);
        }
      const bool corners = at.count({gx[i], gy[j]}) && at.count({gx[i + 1], gy[j]}) && at.count({gx[i], gy[j + 1]}) &&
                           at.count({gx[i + 1], gy[j + 1]});
      if (!corners || static_cast<int>(c.samples.size()) < min_samples) continue;
      bool rebound = false, stick = false, undecided = false;
      for (const auto* p : c.samples)
        (p->outcome == impact_outcome::stick ? stick : p->outcome == impact_outcome::rebound ? rebound : undecided) = true;
      c.outcome = undecided || (rebound && stick) ? cell_outcome::mixed
                  : stick                         ? cell_outcome::stick
                                                  : cell_outcome::rebound;
      cells.push_back(std::move(c));
    }
  }
  return cells;
}

/// The error map of `law` from `points` on the grid of `spec` (see the header comment).
inline error_map build_error_map(const contact_law& law, const std::vector<reference_point>& points,
                                 const error_map_spec& spec) {
  law.validate();
  if (!(spec.safety_factor >= 1)) throw invalid_parameter("error map: safety_factor must be >= 1");
  if (!(spec.floor >= 0)) throw invalid_parameter("error map: floor must be >= 0");
  const std::vector<double> gx = detail::parse_edges(spec.gamma_edges, "gamma_edges");
  const std::vector<double> gy = detail::parse_edges(spec.g_edges, "g_edges");
  if (gx.front() < 0) throw invalid_parameter("error map: gamma edges must be >= 0");
  const std::vector<reference_sample> s = reference_samples(points);
  const cor_approximations<double> approx(law);

  error_map map;
  map.law = law;
  map.safety_factor = spec.safety_factor;
  map.floor = spec.floor;
  map.metadata = spec.metadata;
  for (const mappable_cell& m : mappable_cells(s, gx, gy, spec.min_samples)) {
    const std::size_t i = m.i, j = m.j;
    error_map_cell c;
    c.gamma_lo = spec.gamma_edges[i], c.gamma_hi = spec.gamma_edges[i + 1];
    c.g_lo = spec.g_edges[j], c.g_hi = spec.g_edges[j + 1];
    c.gamma_lo_v = gx[i], c.gamma_hi_v = gx[i + 1], c.g_lo_v = gy[j], c.g_hi_v = gy[j + 1];
    c.samples = static_cast<int>(m.samples.size());
    c.outcome = m.outcome;
    if (c.outcome != cell_outcome::mixed) {
      for (std::size_t k = 0; k < all_approximations.size(); ++k) {
        double worst = 0;
        bool ok = true;
        for (const auto* p : m.samples) {
          const std::optional<double> a = approximate_e(approx, all_approximations[k], p->gamma, p->g);
          if (!a) {
            ok = false;
            break;
          }
          worst = std::max(worst, std::abs(*a - p->e));
        }
        if (ok) c.bound[k] = spec.safety_factor * worst + spec.floor;
      }
    }
    map.add(std::move(c));
  }
  return map;
}

/// Grid nodes: the edges and `per_interval - 1` points inside each interval
/// (geometric spacing between positive edges, arithmetic otherwise), as the
/// shortest decimals that round-trip through double.
inline std::vector<std::string> grid_nodes(const std::vector<std::string>& edges, int per_interval) {
  const std::vector<double> v = detail::parse_edges(edges, "edges");
  if (per_interval < 1) throw invalid_parameter("grid_nodes: per_interval must be >= 1");
  std::vector<std::string> out;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    out.push_back(edges[i]);
    const std::vector<double> nodes = spaced_range(v[i], v[i + 1], static_cast<std::size_t>(per_interval) + 1, v[i] > 0);
    for (int k = 1; k < per_interval; ++k) out.push_back(detail::shortest(nodes[k]));
  }
  out.push_back(edges.back());
  return out;
}

/// Reference points on the tensor grid gamma_nodes x g_nodes by solve_impact at
/// `digits` decimal digits (honest for maps of double formulas when digits >= 30:
/// the solve's error is then below 1e-25, far under any bound in double).
inline std::vector<reference_point> reference_by_solve(const contact_law& law,
                                                       const std::vector<std::string>& gamma_nodes,
                                                       const std::vector<std::string>& g_nodes, int digits) {
  return with_working_precision(digits, [&]<class Real>() {
    std::vector<reference_point> out;
    for (const auto& gamma : gamma_nodes) {
      const Real gm = parse_real<Real>(gamma, "gamma");
      for (const auto& g : g_nodes) {
        const impact_result<Real> r = solve_impact(law, gm, parse_real<Real>(g, "g"));
        out.push_back({gamma, g, to_decimal_string(r.e), r.outcome, to_decimal_string(r.one_minus_e)});
      }
    }
    return out;
  });
}

}  // namespace viscor
