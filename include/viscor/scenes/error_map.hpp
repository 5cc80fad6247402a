// Error maps: per contact law, the worst absolute error of each double-precision
// approximation of e (approximations.hpp) over cells of (gamma, g) space, times a
// safety factor. evaluate.hpp trusts an approximation at a point only through a
// cell of such a map that contains the point; error_map_builder.hpp makes maps.
//
// File format (reference_data/error_maps/<law>.csv, format 1): '#' lines first,
// "# key=value" for the metadata (law, alpha, beta, safety_factor, floor, and
// free-text provenance: reference, command); then a CSV header and one row per cell:
//   gamma_lo,gamma_hi,g_lo,g_hi,samples,outcome,small_g,large_g,schwager_poschel,prop2_chebyshev_beta,prop2_numeric
// A cell is the closed rectangle [gamma_lo, gamma_hi] x [g_lo, g_hi]. Each
// method column holds its bound, safety_factor x (worst |approximation - e| over
// the cell's reference samples) + floor, or is empty where the formula does not
// apply (large_g for g < 0, Schwager-Poschel off Kuwabara-Kono) or gave a
// non-finite value. outcome is rebound or stick (every sample agrees) or mixed:
// the sticking threshold crosses the cell, where e ~ sqrt(distance) varies too
// fast for samples to bound it, so a mixed cell carries no bounds.
// Approximations are clamped to [0, 1] (the linear forms (22), (25) go negative
// past the threshold) both when maps are built and when they are used.
//
// NOTE: maps are about double-precision formulas, so this header works in double
// on purpose; cell edges are the exact decimals of the reference grid, rounded
// to double identically on both sides.
#pragma once

#include <viscor/approx/approximations.hpp>
#include <viscor/core/checksums.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/outcome.hpp>
#include <viscor/core/text_fields.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace viscor {

/// The double-precision approximations an error map can vouch for, in order of
/// cost (measured: eqs. 22, 23, 25 about 20 ns; Prop. 2 with Chebyshev-Beta
/// coefficients 3.4 us; with quadrature 47 us, as much as an exact solve).
enum class approximation { small_g, large_g, schwager_poschel, prop2_chebyshev_beta, prop2_numeric };

inline constexpr std::array<approximation, 5> all_approximations{
    approximation::small_g, approximation::large_g, approximation::schwager_poschel, approximation::prop2_chebyshev_beta,
    approximation::prop2_numeric};

/// The approximation's name, as in the map's column header and evaluate's method.
inline std::string to_string(approximation a) {
  switch (a) {
    case approximation::small_g: return "small_g";
    case approximation::large_g: return "large_g";
    case approximation::schwager_poschel: return "schwager_poschel";
    case approximation::prop2_chebyshev_beta: return "prop2_chebyshev_beta";
    case approximation::prop2_numeric: return "prop2_numeric";
  }
  return "?";
}

/// The approximation's value at (gamma, g), clamped to [0, 1]; nullopt where the
/// formula does not apply or is not finite.
inline std::optional<double> approximate_e(const cor_approximations<double>& a, approximation which, double gamma,
                                           double g) {
  double e = 0;
  switch (which) {
    case approximation::small_g: e = a.small_g(gamma, g); break;
    case approximation::large_g:
      if (g < 0) return std::nullopt;
      e = a.large_g(gamma, g);
      break;
    case approximation::schwager_poschel:
      if (!a.is_kuwabara_kono()) return std::nullopt;
      e = a.schwager_poschel(gamma, g);
      break;
    case approximation::prop2_chebyshev_beta:
      if (g < 0) return std::nullopt;
      e = a.prop2(gamma, g, coefficient_source::chebyshev_beta).e;
      break;
    case approximation::prop2_numeric: e = a.prop2(gamma, g, coefficient_source::numeric).e; break;
  }
  if (!std::isfinite(e)) return std::nullopt;
  return std::clamp(e, 0.0, 1.0);
}

/// Whether all reference samples of a cell rebound, all stick, or both occur.
enum class cell_outcome { rebound, stick, mixed };

/// "rebound", "stick" or "mixed".
inline std::string to_string(cell_outcome o) {
  return o == cell_outcome::rebound ? "rebound" : o == cell_outcome::stick ? "stick" : "mixed";
}

/// One cell of an error map: its rectangle, how many reference samples it saw, their outcome and the bound of each approximation.
struct error_map_cell {
  std::string gamma_lo, gamma_hi, g_lo, g_hi;  ///< exact decimal edges, as written
  double gamma_lo_v = 0, gamma_hi_v = 0, g_lo_v = 0, g_hi_v = 0;
  int samples = 0;
  cell_outcome outcome = cell_outcome::mixed;
  std::array<std::optional<double>, all_approximations.size()> bound{};  ///< per approximation, in enum order
};

/// What a map says at one point: the smallest bound of each approximation over
/// the cells that contain the point (nullopt: no trusted bound).
struct map_bounds {
  std::array<std::optional<double>, all_approximations.size()> bound{};
  cell_outcome outcome = cell_outcome::mixed;
};

/// Per-cell bounds on the error of each double-precision approximation of one law, read from a map file.
class error_map {
 public:
  contact_law law;
  double safety_factor = 0;
  double floor = 0;
  /// Provenance "# key=value" lines other than law, alpha, beta, safety_factor, floor.
  std::vector<std::pair<std::string, std::string>> metadata;

  /// The cells, in the order added.
  const std::vector<error_map_cell>& cells() const noexcept { return m_cells; }

  /// Adds a cell; throws invalid_parameter for an empty or inverted rectangle.
  void add(error_map_cell c) {
    if (!(c.gamma_lo_v < c.gamma_hi_v) || !(c.g_lo_v < c.g_hi_v))
      throw invalid_parameter("error map cell [" + c.gamma_lo + ", " + c.gamma_hi + "] x [" + c.g_lo + ", " + c.g_hi +
                              "] must have gamma_lo < gamma_hi and g_lo < g_hi");
    m_cells.push_back(std::move(c));
    m_index.clear();
  }

  /// The bounds at (gamma, g): min over the containing cells (1 to 4 of them on
  /// shared edges) that are not mixed. nullopt outside the mapped region, or when
  /// a containing cell is crossed by the sticking threshold and none is clean.
  std::optional<map_bounds> at(double gamma, double g) const {
    if (m_index.empty()) build_index();
    std::optional<map_bounds> out;
    const auto gi = candidates(m_gamma_edges, gamma);
    const auto gj = candidates(m_g_edges, g);
    for (std::size_t i : gi) {
      for (std::size_t j : gj) {
        const auto it = m_index.find({i, j});
        if (it == m_index.end()) continue;
        const error_map_cell& c = m_cells[it->second];
        if (!(c.gamma_lo_v <= gamma && gamma <= c.gamma_hi_v && c.g_lo_v <= g && g <= c.g_hi_v)) continue;
        if (c.outcome == cell_outcome::mixed) continue;
        if (!out) {
          out.emplace();
          out->outcome = c.outcome;
        } else if (out->outcome != c.outcome) {
          out->outcome = cell_outcome::mixed;  // a point on the threshold itself
        }
        for (std::size_t k = 0; k < c.bound.size(); ++k)
          if (c.bound[k] && (!out->bound[k] || *c.bound[k] < *out->bound[k])) out->bound[k] = c.bound[k];
      }
    }
    if (out && out->outcome == cell_outcome::mixed) return std::nullopt;
    return out;
  }

 private:
  // Cell (i, j) spans gamma_edges[i..i+1] x g_edges[j..j+1] when cells tile a tensor grid;
  // cells that do not are indexed by every grid interval they cover.
  void build_index() const {
    m_gamma_edges.clear(), m_g_edges.clear();
    for (const auto& c : m_cells) {
      m_gamma_edges.push_back(c.gamma_lo_v), m_gamma_edges.push_back(c.gamma_hi_v);
      m_g_edges.push_back(c.g_lo_v), m_g_edges.push_back(c.g_hi_v);
    }
    for (auto* v : {&m_gamma_edges, &m_g_edges}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    auto span = [](const std::vector<double>& edges, double lo, double hi) {
      const auto a = std::lower_bound(edges.begin(), edges.end(), lo) - edges.begin();
      const auto b = std::lower_bound(edges.begin(), edges.end(), hi) - edges.begin();
      return std::pair<std::size_t, std::size_t>(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
    };
    for (std::size_t n = 0; n < m_cells.size(); ++n) {
      const auto [i0, i1] = span(m_gamma_edges, m_cells[n].gamma_lo_v, m_cells[n].gamma_hi_v);
      const auto [j0, j1] = span(m_g_edges, m_cells[n].g_lo_v, m_cells[n].g_hi_v);
      for (std::size_t i = i0; i < i1; ++i)
        for (std::size_t j = j0; j < j1; ++j) m_index.emplace(std::pair<std::size_t, std::size_t>{i, j}, n);
    }
  }

  // Grid intervals that may contain x: the one it lies in, and the one before
  // when x sits on an edge.
  static std::vector<std::size_t> candidates(const std::vector<double>& edges, double x) {
    std::vector<std::size_t> out;
    if (edges.size() < 2 || !(x >= edges.front()) || !(x <= edges.back())) return out;
    auto it = std::upper_bound(edges.begin(), edges.end(), x);
    std::size_t k = static_cast<std::size_t>(it - edges.begin());  // edges[k-1] <= x < edges[k]
    if (k == edges.size()) k = edges.size() - 1;                    // x == last edge
    out.push_back(k - 1);
    if (edges[k - 1] == x && k >= 2) out.push_back(k - 2);
    return out;
  }

  std::vector<error_map_cell> m_cells;
  mutable std::vector<double> m_gamma_edges, m_g_edges;
  mutable std::map<std::pair<std::size_t, std::size_t>, std::size_t> m_index;
};

namespace detail {

inline double parse_map_number(const std::string& text, const std::string& where) {
  if (!looks_like_decimal(text)) throw parse_error(where + ": expected a decimal number, got '" + text + "'");
  const double x = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(x)) throw parse_error(where + ": number '" + text + "' is not finite in double");
  return x;
}

// Shortest decimal that reads back as x.
inline std::string shortest(double x) {
  char buffer[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    if (std::strtod(buffer, nullptr) == x) break;
  }
  return buffer;
}

inline std::string map_header() {
  std::string h = "gamma_lo,gamma_hi,g_lo,g_hi,samples,outcome";
  for (auto a : all_approximations) h.append(",").append(to_string(a));
  return h;
}

}  // namespace detail

/// Parses an error map; `file` names it in errors (parse_error names file, line and field).
inline error_map parse_error_map(const std::string& text, const std::string& file) {
  error_map map;
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  bool have_header = false;
  std::string law_name, alpha, beta;
  std::optional<double> safety, floor;
  const std::vector<std::string> columns = split_fields(detail::map_header());
  while (std::getline(in, line)) {
    ++number;
    const std::string at = file + ":" + std::to_string(number);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (have_header) throw parse_error(at + ": comment after the column header");
      std::string body = line.substr(1);
      while (!body.empty() && body[0] == ' ') body.erase(0, 1);
      const auto eq = body.find('=');
      if (eq == std::string::npos || body.find(' ') < eq) continue;  // free text
      const std::string key = body.substr(0, eq), value = body.substr(eq + 1);
      if (key == "law") law_name = value;
      else if (key == "alpha") alpha = value;
      else if (key == "beta") beta = value;
      else if (key == "safety_factor") safety = detail::parse_map_number(value, at + ", field safety_factor");
      else if (key == "floor") floor = detail::parse_map_number(value, at + ", field floor");
      else map.metadata.emplace_back(key, value);
      continue;
    }
    const std::vector<std::string> f = split_fields(line);
    if (!have_header) {
      if (f != columns) throw parse_error(at + ": expected the column header '" + detail::map_header() + "'");
      have_header = true;
      continue;
    }
    if (f.size() != columns.size())
      throw parse_error(at + ": expected " + std::to_string(columns.size()) + " fields, got " +
                        std::to_string(f.size()));
    error_map_cell c;
    c.gamma_lo = f[0], c.gamma_hi = f[1], c.g_lo = f[2], c.g_hi = f[3];
    c.gamma_lo_v = detail::parse_map_number(f[0], at + ", field gamma_lo");
    c.gamma_hi_v = detail::parse_map_number(f[1], at + ", field gamma_hi");
    c.g_lo_v = detail::parse_map_number(f[2], at + ", field g_lo");
    c.g_hi_v = detail::parse_map_number(f[3], at + ", field g_hi");
    if (c.gamma_lo_v < 0) throw parse_error(at + ", field gamma_lo: must be >= 0, got " + f[0]);
    const double samples = detail::parse_map_number(f[4], at + ", field samples");
    if (samples < 0 || samples != std::floor(samples)) throw parse_error(at + ", field samples: expected a count");
    c.samples = static_cast<int>(samples);
    if (f[5] == "rebound") c.outcome = cell_outcome::rebound;
    else if (f[5] == "stick") c.outcome = cell_outcome::stick;
    else if (f[5] == "mixed") c.outcome = cell_outcome::mixed;
    else throw parse_error(at + ", field outcome: expected rebound, stick or mixed, got '" + f[5] + "'");
    for (std::size_t k = 0; k < all_approximations.size(); ++k) {
      const std::string& v = f[6 + k];
      if (v.empty()) continue;
      const double b = detail::parse_map_number(v, at + ", field " + columns[6 + k]);
      if (!(b >= 0)) throw parse_error(at + ", field " + columns[6 + k] + ": a bound must be >= 0, got " + v);
      if (c.outcome == cell_outcome::mixed)
        throw parse_error(at + ", field " + columns[6 + k] + ": a mixed cell carries no bounds");
      c.bound[k] = b;
    }
    try {
      map.add(std::move(c));
    } catch (const invalid_parameter& e) {
      throw parse_error(at + ": " + e.what());
    }
  }
  if (!have_header) throw parse_error(file + ": no column header (empty or truncated error map)");
  if (!safety) throw parse_error(file + ": missing '# safety_factor=...'");
  if (!floor) throw parse_error(file + ": missing '# floor=...'");
  if (!(*safety >= 1)) throw parse_error(file + ", field safety_factor: must be >= 1");
  map.safety_factor = *safety, map.floor = *floor;
  try {
    if (!law_name.empty()) {
      map.law = law_by_name(law_name);
      if ((!alpha.empty() && alpha != map.law.alpha.to_string()) || (!beta.empty() && beta != map.law.beta.to_string()))
        throw parse_error(file + ": law " + law_name + " does not have alpha=" + alpha + ", beta=" + beta);
    } else {
      if (alpha.empty() || beta.empty()) throw parse_error(file + ": missing '# law=...' or '# alpha=...'/'# beta=...'");
      map.law = make_law(exponent::parse(alpha, "alpha"), exponent::parse(beta, "beta"));
    }
  } catch (const parse_error&) {
    throw;
  } catch (const invalid_parameter& e) {
    throw parse_error(file + ": " + e.what());
  }
  return map;
}

/// Reads an error map file (see parse_error_map).
/// A map listed in a checksum manifest beside it is checked first (core/checksums.hpp).
inline error_map read_error_map(const std::string& path) {
  return parse_error_map(read_checked_file<parse_error>(path, "error map"), path);
}

/// The text of a map file. Bounds are written with 3 significant digits, rounded up.
inline std::string error_map_text(const error_map& map) {
  std::ostringstream out;
  out << "# viscor error map, format 1: per cell of (gamma, g), safety_factor x the worst absolute\n"
         "# error of each double-precision approximation of e over the cell's reference samples, + floor.\n";
  if (!map.law.name.empty()) out << "# law=" << map.law.name << "\n";
  out << "# alpha=" << map.law.alpha.to_string() << "\n# beta=" << map.law.beta.to_string() << "\n";
  out << "# safety_factor=" << detail::shortest(map.safety_factor) << "\n# floor=" << detail::shortest(map.floor)
      << "\n";
  for (const auto& [key, value] : map.metadata) out << "# " << key << "=" << value << "\n";
  out << detail::map_header() << "\n";
  for (const auto& c : map.cells()) {
    out << c.gamma_lo << "," << c.gamma_hi << "," << c.g_lo << "," << c.g_hi << "," << c.samples << ","
        << to_string(c.outcome);
    for (const auto& b : c.bound) {
      out << ",";
      if (!b) continue;
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.2e", *b);
      double written = std::strtod(buffer, nullptr);
      if (written < *b) {  // round up: a bound must not shrink in print
        std::snprintf(buffer, sizeof buffer, "%.2e", std::nextafter(*b * (1 + 1e-2), 1e308));
      }
      out << buffer;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace viscor
