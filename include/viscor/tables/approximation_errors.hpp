// Errors of the report's approximate CoR formulas (approximations.hpp) against a
// committed reference table (reference_table.hpp): every formula x coefficient
// source that applies is evaluated on every row, and the maximum absolute error
// |e_approx - e_ref| is kept per group (table, law, g, gamma range).
//
// Groups, by table (the file name decides, see grouping_of):
//   cor_report_*   the report's ranges (docs/report-notes.md): gamma_max = min(0.1, 1.1 gamma_c(g)),
//                  gamma_c of eq. (24) (infinite at g = 0); small gamma < 0.2 gamma_max,
//                  medium 0.2 gamma_max <= gamma <= 0.92 gamma_max, large 0.92 gamma_max
//                  < gamma <= gamma_max, and "beyond" for the rows past gamma_max.
//   *g_sweep*      one group per (law, gamma): range "gamma=<value>", g = "sweep".
//   otherwise      one group per (law, g): range "all".
// Formulas (formula, source): small_g (22), large_g (23) (g >= 0), schwager_poschel
// (25)+(30) (Kuwabara-Kono), and Prop. 2's prop2 (36), prop2_squared (89) e_+,
// prop2_linearized (90) e_s, each with coefficients exact_at_zero (g = 0 only),
// numeric and chebyshev_beta (g >= 0). A formula that throws or returns NaN/inf
// on a row makes its group non-finite (an error for the regression test).
// NOTE: used in double by the regression test and `viscor report`; I(g), Q(g)
// are computed once per (law, g, source), so the quadrature costs little.
#pragma once

#include <viscor/core/checksums.hpp>
#include <viscor/core/field_names.hpp>
#include <viscor/approx/approximations.hpp>
#include <viscor/approx/closed_form.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/tables/reference_table.hpp>

#include <boost/math/special_functions/fpclassify.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace viscor {

/// How the rows of a table are grouped (see the header comment).
enum class table_grouping { report_ranges, per_gamma, per_g };

/// The grouping of a table, from its file name.
inline table_grouping grouping_of(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.rfind("cor_report_", 0) == 0) return table_grouping::report_ranges;
  if (name.find("g_sweep") != std::string::npos) return table_grouping::per_gamma;
  return table_grouping::per_g;
}

/// One approximation: a formula and where its coefficients come from.
struct approximation_id {
  std::string formula;  ///< small_g, large_g, schwager_poschel, prop2, prop2_squared, prop2_linearized
  std::string source;   ///< closed_form, or a coefficient_source name
  /// The (formula, source) pair, for ordering.
  auto key() const { return std::tie(formula, source); }
};

/// The maximum error of one approximation over one group of rows.
template <class Real>
struct error_group {
  std::string table;  ///< file name (no directory)
  std::string law, g, range;
  std::string formula, source;
  std::int64_t rows = 0;
  std::string gamma_from, gamma_to;  ///< smallest and largest gamma of the group (table text)
  Real gamma_lo = 0, gamma_hi = 0;  ///< the same as numbers
  Real max_error = 0;
  std::string at_gamma, at_g;  ///< where max_error occurs (first occurrence)
  Real e_ref_at = 0, e_approx_at = 0;
  std::int64_t non_finite = 0;  ///< rows where the formula threw or gave NaN/inf
  std::string first_failure;    ///< the first of them, for messages

  /// A unique text key of the group.
  std::string key() const { return table + "|" + law + "|" + g + "|" + range + "|" + formula + "|" + source; }
};

namespace detail {

/// The report's gamma_max = min(0.1, 1.1 gamma_c(g)) (docs/report-notes.md).
template <class Real>
Real report_gamma_max(const contact_law& law, const Real& g) {
  const Real cap = parse_real<Real>("0.1", "gamma_max");
  if (!(g > 0)) return cap;
  const Real gc = critical_gamma(law, g);
  const Real m = Real(11) / 10 * gc;
  return m < cap ? m : cap;
}

/// small / medium / large / beyond for gamma in the report's ranges.
template <class Real>
std::string report_range(const Real& gamma, const Real& gamma_max, bool capped) {
  // At the cap 0.1 the bounds are the exact decimals 0.02 and 0.092, parsed like the table's gamma.
  const Real lo = capped ? parse_real<Real>("0.02", "lo") : Real(gamma_max / 5);
  const Real hi = capped ? parse_real<Real>("0.092", "hi") : Real(gamma_max * 23 / 25);
  if (gamma < lo) return "small";
  if (gamma <= hi) return "medium";
  if (gamma <= gamma_max) return "large";
  return "beyond";
}

/// Per-law approximations with I, Q cached per (g text, source).
template <class Real>
class approximation_cache {
 public:
  const cor_approximations<Real>& of(const contact_law& law) {
    const std::string key = law.alpha.to_string() + "/" + law.beta.to_string();
    auto it = m_laws.find(key);
    if (it == m_laws.end()) it = m_laws.emplace(key, std::make_unique<cor_approximations<Real>>(law)).first;
    return *it->second;
  }
  std::array<Real, 2> coefficients(const contact_law& law, const std::string& g_text, const Real& g,
                                   coefficient_source s) {
    const std::string key = law.alpha.to_string() + "/" + law.beta.to_string() + "|" + g_text + "|" +
                            std::string(to_string(s));
    auto it = m_iq.find(key);
    if (it == m_iq.end()) it = m_iq.emplace(key, of(law).coefficients(g, s)).first;
    return it->second;
  }

 private:
  std::map<std::string, std::unique_ptr<cor_approximations<Real>>> m_laws;
  std::map<std::string, std::array<Real, 2>> m_iq;
};

}  // namespace detail

/// The approximations that apply at (law, g), in a fixed order.
inline std::vector<approximation_id> applicable_approximations(bool kuwabara_kono, bool g_is_zero,
                                                               bool g_non_negative) {
  std::vector<approximation_id> ids{{"small_g", "closed_form"}};
  if (g_non_negative) ids.push_back({"large_g", "closed_form"});
  if (kuwabara_kono) ids.push_back({"schwager_poschel", "closed_form"});
  for (const coefficient_source s : coefficient_sources) {
    if (s == coefficient_source::exact_at_zero && !g_is_zero) continue;
    if (s == coefficient_source::chebyshev_beta && !g_non_negative) continue;
    for (const char* f : {"prop2", "prop2_squared", "prop2_linearized"}) ids.push_back({f, std::string(to_string(s))});
  }
  return ids;
}

/// One evaluated row: the reference and every applicable approximation
/// (NaN where a formula threw).
template <class Real>
struct evaluated_row {
  contact_law law;
  std::string gamma_text, g_text;
  Real gamma, g, e_ref;
  std::vector<approximation_id> ids;
  std::vector<Real> values;
  std::vector<std::string> failures;  ///< per id: empty, or the exception message
};

/// Evaluates every applicable approximation on every row of a CoR table.
template <class Real>
std::vector<evaluated_row<Real>> evaluate_approximations(const csv_table& table, detail::approximation_cache<Real>& cache) {
  if (table.kind != table_kind::cor) throw invalid_parameter("approximation errors need a CoR table");
  std::vector<evaluated_row<Real>> out;
  out.reserve(table.rows.size());
  for (const csv_record& rec : table.rows) {
    evaluated_row<Real> r;
    const auto& f = rec.fields;
    r.law = f[1].empty() ? make_law(exponent::parse(f[2], "alpha"), exponent::parse(f[3], "beta")) : law_by_name(f[1]);
    r.gamma_text = f[4], r.g_text = f[5];
    r.gamma = parse_real<Real>(f[4], "gamma");
    r.g = parse_real<Real>(f[5], "g");
    r.e_ref = parse_real<Real>(f[7], field::e);
    const cor_approximations<Real>& a = cache.of(r.law);
    r.ids = applicable_approximations(a.is_kuwabara_kono(), r.g == 0, r.g >= 0);
    for (const approximation_id& id : r.ids) {
      Real v = std::numeric_limits<Real>::quiet_NaN();
      std::string failure;
      try {
        if (id.formula == "small_g") {
          v = a.small_g(r.gamma, r.g);
        } else if (id.formula == "large_g") {
          v = a.large_g(r.gamma, r.g);
        } else if (id.formula == "schwager_poschel") {
          v = a.schwager_poschel(r.gamma, r.g);
        } else {
          const coefficient_source s = parse_coefficient_source(id.source);
          const auto iq = cache.coefficients(r.law, r.g_text, r.g, s);
          const prop2_result<Real> p = a.prop2_from(r.gamma, iq[0], iq[1], s);
          v = id.formula == "prop2" ? p.e : id.formula == "prop2_squared" ? p.e_plus : p.e_linearized;
        }
      } catch (const std::exception& e) {
        failure = e.what();
      }
      r.values.push_back(v);
      r.failures.push_back(failure);
    }
    out.push_back(std::move(r));
  }
  return out;
}

/// The maximum absolute errors per group (see the header comment) of every
/// applicable approximation over the rows of `table`, read from `path`.
template <class Real>
std::vector<error_group<Real>> approximation_errors(const csv_table& table, const std::string& path,
                                                    detail::approximation_cache<Real>& cache) {
  using boost::math::isfinite;
  using std::abs;
  const std::string name = std::filesystem::path(path).filename().string();
  const table_grouping grouping = grouping_of(path);
  std::map<std::string, std::size_t> index;
  std::vector<error_group<Real>> groups;
  std::map<std::string, std::pair<Real, bool>> gamma_max;  // per law|g
  for (const evaluated_row<Real>& r : evaluate_approximations(table, cache)) {
    std::string g = r.g_text, range = "all";
    if (grouping == table_grouping::per_gamma) {
      g = "sweep", range = "gamma=" + r.gamma_text;
    } else if (grouping == table_grouping::report_ranges) {
      const std::string k = r.law.alpha.to_string() + "/" + r.law.beta.to_string() + "|" + r.g_text;
      auto it = gamma_max.find(k);
      if (it == gamma_max.end()) {
        const Real gm = detail::report_gamma_max(r.law, r.g);
        it = gamma_max.emplace(k, std::make_pair(gm, gm == parse_real<Real>("0.1", "cap"))).first;
      }
      range = detail::report_range(r.gamma, it->second.first, it->second.second);
    }
    for (std::size_t i = 0; i < r.ids.size(); ++i) {
      error_group<Real> probe;
      probe.table = name, probe.law = r.law.name.empty() ? r.law.describe() : r.law.name;
      probe.g = g, probe.range = range, probe.formula = r.ids[i].formula, probe.source = r.ids[i].source;
      auto [it, fresh] = index.emplace(probe.key(), groups.size());
      if (fresh) {
        probe.gamma_from = probe.gamma_to = r.gamma_text;
        probe.gamma_lo = probe.gamma_hi = r.gamma;
        groups.push_back(probe);
      }
      error_group<Real>& grp = groups[it->second];
      ++grp.rows;
      if (grp.gamma_lo > r.gamma) grp.gamma_lo = r.gamma, grp.gamma_from = r.gamma_text;
      if (grp.gamma_hi < r.gamma) grp.gamma_hi = r.gamma, grp.gamma_to = r.gamma_text;
      const Real v = r.values[i];
      if (!r.failures[i].empty() || !isfinite(v)) {
        if (grp.non_finite++ == 0)
          grp.first_failure = "gamma = " + r.gamma_text + ", g = " + r.g_text + ": " +
                              (r.failures[i].empty() ? "non-finite value " + to_decimal_string(v) : r.failures[i]);
        continue;
      }
      const Real err = abs(v - r.e_ref);
      if (err > grp.max_error || grp.at_gamma.empty()) {
        grp.max_error = err;
        grp.at_gamma = r.gamma_text, grp.at_g = r.g_text, grp.e_ref_at = r.e_ref, grp.e_approx_at = v;
      }
    }
  }
  return groups;
}

/// The column names of the baseline file.
inline std::string error_baseline_header() {
  return "table,law,g,range,gamma_from,gamma_to,formula,source,rows,max_abs_error,at_gamma,at_g,non_finite";
}

/// One group as a line of the baseline file (errors to 8 significant digits).
template <class Real>
std::string error_baseline_line(const error_group<Real>& e) {
  std::ostringstream s;
  s << e.table << ',' << e.law << ',' << e.g << ',' << e.range << ',' << e.gamma_from << ',' << e.gamma_to << ','
    << e.formula << ',' << e.source << ',' << e.rows << ','
    << (e.max_error == 0 ? std::string("0") : to_decimal_string(e.max_error, 8)) << ',' << e.at_gamma << ','
    << e.at_g << ',' << e.non_finite;
  return s.str();
}

/// A baseline entry as read back: its key and expected maximum error.
struct baseline_entry {
  std::string key;  ///< error_group::key()
  std::string max_abs_error;
  std::int64_t rows = 0;
  std::string line;
};

/// Reads a baseline file ('#' lines are comments). Throws parse_error naming file and line.
inline std::vector<baseline_entry> read_error_baseline(const std::string& path) {
  std::istringstream in(read_checked_file<error>(path, "baseline"));  // core/checksums.hpp
  std::vector<baseline_entry> out;
  std::string line;
  std::size_t n = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      if (line != error_baseline_header())
        throw parse_error(path + ":" + std::to_string(n) + ": wrong columns: expected '" + error_baseline_header() +
                          "', got '" + line + "'");
      header = true;
      continue;
    }
    const std::vector<std::string> f = split_fields(line);
    if (f.size() != 13)
      throw parse_error(path + ":" + std::to_string(n) + ": expected 13 fields, got " + std::to_string(f.size()));
    baseline_entry b;
    b.key = f[0] + "|" + f[1] + "|" + f[2] + "|" + f[3] + "|" + f[6] + "|" + f[7];
    b.max_abs_error = f[9];
    try {
      b.rows = std::stoll(f[8]);
    } catch (const std::exception&) {
      throw parse_error(path + ":" + std::to_string(n) + ": field rows: must be an integer, got '" + f[8] + "'");
    }
    b.line = line;
    out.push_back(std::move(b));
  }
  if (!header) throw parse_error(path + ": no header line");
  return out;
}

}  // namespace viscor
