// The report's Tables 2-5 (maximum absolute errors of Prop. 2's O(gamma^2)
// approximation (36) with exact, numeric and Chebyshev-Beta coefficients, plus
// Schwager-Poschel for Kuwabara-Kono, per gamma range) and Figs. 8-11 (relative
// error of g_c of eq. (24) against certified thresholds), computed in double from
// the committed tables (tables/approximation_errors.hpp), as `viscor report`
// prints them; and the regression baseline of every approximation's errors
// (`viscor report baseline`, which approximation_regression_test compares against).
#pragma once

#include <viscor/jobs/json_fields.hpp>

#include <viscor/config.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/tables/approximation_errors.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::jobs {

/// Where the certified tables are and how the report is written.
struct report_request {
  std::string data;     ///< the directory of the certified tables (cor_*.csv, sticking_hertz.csv)
  std::string output;   ///< the file the text goes to ("" for none): CSV when it ends in .csv
  std::string values;   ///< "" or a CSV of every row's reference and approximations is wanted
  bool csv = false;     ///< CSV instead of Markdown
  bool compare = false; ///< the report's printed values next to ours
};

/// The report's text, and the per-row values CSV when asked for.
struct report_output {
  std::string text;
  std::string values_csv;
};

/// The tables to read and the baseline file's name (recorded in its header).
struct baseline_request {
  std::string data, output;
};

/// The baseline CSV, its number of groups, and one warning per group with non-finite values.
struct baseline_output {
  std::string text;
  std::size_t groups = 0;
  std::vector<std::string> warnings;
};

namespace detail {

namespace fs = std::filesystem;

/// The committed CoR tables of a directory (cor_*.csv), sorted by name.
inline std::vector<std::string> cor_tables(const std::string& dir) {
  std::vector<std::string> out;
  if (!fs::is_directory(dir)) throw invalid_parameter(VISCOR_FIELD("data") ": '" + dir + "' is not a directory");
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("cor_", 0) == 0 && entry.path().extension() == ".csv") out.push_back(entry.path().string());
  }
  if (out.empty())
    throw invalid_parameter(VISCOR_FIELD("data")
                            ": '" + dir + "' holds no certified CoR tables (cor_*.csv); nothing to report");
  std::sort(out.begin(), out.end());
  return out;
}

inline std::string sci(double x, int digits = 3) {
  if (x == 0) return "0";
  std::ostringstream s;
  s << std::scientific << std::setprecision(digits - 1) << x;
  return s.str();
}

// ---- the report's printed values (Tables 2-5, text of the PDF) ----
// key: law|g|range|source; ranges small/rest (g < 10), small/medium/large (g = 10).
// Where the PDF's text lost an entry (Table 5b, Num., small gamma) there is none.
inline const std::map<std::string, double>& printed_values() {
  static const std::map<std::string, double> v = [] {
    std::map<std::string, double> m;
    auto a = [&](const std::string& law, const std::string& g, double ns, double nr, double as, double ar) {
      if (g == "0") m[law + "|0|small|exact_at_zero"] = ns, m[law + "|0|rest|exact_at_zero"] = nr;
      m[law + "|" + g + "|small|numeric"] = ns, m[law + "|" + g + "|rest|numeric"] = nr;
      m[law + "|" + g + "|small|chebyshev_beta"] = as, m[law + "|" + g + "|rest|chebyshev_beta"] = ar;
    };
    auto b = [&](const std::string& law, const std::string& source, double s, double me, double l) {
      if (s > 0) m[law + "|10|small|" + source] = s;
      m[law + "|10|medium|" + source] = me, m[law + "|10|large|" + source] = l;
    };
    a("hertz_linear_damping", "0", 5.39e-6, 6.57e-4, 5.39e-6, 6.57e-4);
    a("hertz_linear_damping", "0.05", 5.63e-6, 6.89e-4, 1.32e-5, 7.26e-4);
    a("hertz_linear_damping", "1", 6.82e-5, 1.77e-2, 1.32e-4, 1.85e-2);
    b("hertz_linear_damping", "numeric", 4.39e-7, 4.25e-3, 5.63e-13);
    b("hertz_linear_damping", "chebyshev_beta", 8.03e-5, 1.33e-2, 5.63e-13);
    a("tsuji", "0", 9.17e-6, 1.11e-3, 9.17e-6, 1.11e-3);
    a("tsuji", "0.05", 9.88e-6, 1.12e-3, 1.77e-5, 1.12e-3);
    a("tsuji", "1", 1.65e-4, 1.10e-1, 2.40e-4, 1.11e-1);
    b("tsuji", "numeric", 5.56e-8, 3.32e-4, 2.84e-13);
    b("tsuji", "chebyshev_beta", 8.07e-5, 1.76e-2, 2.84e-13);
    a("kuwabara_kono", "0", 1.37e-5, 1.60e-3, 1.37e-5, 1.60e-3);
    a("kuwabara_kono", "0.05", 1.52e-5, 1.78e-3, 2.33e-5, 1.82e-3);
    a("kuwabara_kono", "1", 3.67e-4, 2.08e-1, 4.58e-4, 2.09e-1);
    b("kuwabara_kono", "numeric", 1.06e-7, 2.38e-4, 2.84e-13);
    b("kuwabara_kono", "chebyshev_beta", 8.11e-5, 2.11e-2, 2.84e-13);
    a("hunt_crossley", "0", 3.87e-5, 4.26e-3, 3.87e-5, 4.26e-3);
    a("hunt_crossley", "0.05", 4.94e-5, 5.39e-3, 5.84e-5, 5.43e-3);
    a("hunt_crossley", "1", 2.06e-3, 3.11e-1, 2.20e-3, 3.11e-1);
    b("hunt_crossley", "numeric", 0, 9.67e-4, 2.84e-13);
    b("hunt_crossley", "chebyshev_beta", 8.57e-5, 2.50e-1, 2.84e-13);
    return m;
  }();
  return v;
}

struct entry {
  std::string table, law, g, range, formula, source;
  double ours = -1;  // < 0: no rows
  std::string where;
};

inline const std::vector<std::string> hertz_laws{"hertz_linear_damping", "tsuji", "kuwabara_kono", "hunt_crossley"};
inline const std::map<std::string, std::string> table_number{
    {"hertz_linear_damping", "2"}, {"tsuji", "3"}, {"kuwabara_kono", "4"}, {"hunt_crossley", "5"}};

/// Table entries from the groups of one table: prop2 per source and schwager_poschel, "rest" = medium + large.
inline void collect(const std::vector<error_group<double>>& groups, std::map<std::string, entry>& out) {
  for (const auto& grp : groups) {
    const bool wanted = grp.formula == "prop2" || grp.formula == "schwager_poschel";
    if (!wanted || grp.range == "beyond" || grp.range == "all") continue;
    const std::string source = grp.formula == "schwager_poschel" ? "schwager_poschel" : grp.source;
    std::vector<std::string> ranges{grp.range};
    if (grp.g != "10" && grp.range != "small") ranges = {"rest"};
    for (const auto& r : ranges) {
      const std::string key = grp.law + "|" + grp.g + "|" + r + "|" + source;
      entry& e = out[key];
      e.table = grp.table, e.law = grp.law, e.g = grp.g, e.range = r, e.formula = grp.formula, e.source = source;
      const double err = grp.non_finite > 0 ? std::numeric_limits<double>::quiet_NaN() : grp.max_error;
      if (e.ours < 0 || err > e.ours || err != err) {
        e.ours = err;
        e.where = "gamma = " + grp.at_gamma;
      }
    }
  }
}

inline std::string range_label(const std::string& range, const std::string& law, const std::string& g,
                        const std::map<std::string, double>& gmax) {
  const auto it = gmax.find(law + "|" + g);
  const double gm = it == gmax.end() ? 0.1 : it->second;
  if (range == "small") return "γ < " + sci(0.2 * gm);
  if (range == "rest") return "γ ≥ " + sci(0.2 * gm);
  if (range == "medium") return sci(0.2 * gm) + " ≤ γ ≤ " + sci(0.92 * gm);
  return sci(0.92 * gm) + " < γ ≤ " + sci(gm);
}

inline std::string cell(const std::map<std::string, entry>& entries, const std::string& key, bool compare) {
  const auto it = entries.find(key);
  std::string ours = it == entries.end() || it->second.ours < 0 ? "—" : sci(it->second.ours);
  if (!compare) return ours;
  const auto p = printed_values().find(key);
  const std::string printed = p == printed_values().end() ? "—" : sci(p->second);
  std::string flag;
  if (p != printed_values().end() && it != entries.end() && it->second.ours > 0) {
    const double ratio = it->second.ours / p->second;
    if (ratio > 2 || ratio < 0.5) flag = " ⚑";
  }
  return ours + " / " + printed + flag;
}

}  // namespace detail

/// Tables 2-5 and Figs. 8-11 from the certified tables of q.data (Markdown, or CSV
/// with q.csv or an output name ending in .csv), and with q.values the per-row CSV.
inline report_output make_report(const report_request& o) {
  using namespace detail;
  std::map<std::string, entry> entries;
  std::map<std::string, double> gmax;  // law|g -> gamma_max
  viscor::detail::approximation_cache<double> cache;
  std::ostringstream values;
  if (!o.values.empty())
    values << "table,law,g,gamma,e_ref,small_g,large_g,schwager_poschel,prop2_exact_at_zero,prop2_numeric,"
              "prop2_chebyshev_beta\n";
  for (const auto& path : cor_tables(o.data)) {
    const std::string name = fs::path(path).filename().string();
    const csv_table table = read_table(path);
    if (grouping_of(path) == table_grouping::report_ranges) {
      collect(approximation_errors(table, path, cache), entries);
      for (const auto& rec : table.rows) {
        const contact_law law = law_by_name(rec.fields[1]);
        const std::string k = rec.fields[1] + "|" + rec.fields[5];
        if (!gmax.count(k)) gmax[k] = viscor::detail::report_gamma_max(law, parse_real<double>(rec.fields[5], "g"));
      }
    }
    if (!o.values.empty() && grouping_of(path) != table_grouping::per_gamma) {
      for (const auto& r : evaluate_approximations(table, cache)) {
        std::map<std::string, double> v;
        for (std::size_t i = 0; i < r.ids.size(); ++i)
          if (r.ids[i].formula == "prop2" || r.ids[i].source == "closed_form")
            v[r.ids[i].formula == "prop2" ? "prop2_" + r.ids[i].source : r.ids[i].formula] = r.values[i];
        auto f = [&](const char* k) {
          const auto it = v.find(k);
          return it == v.end() ? std::string() : to_decimal_string(it->second, 17);
        };
        values << name << ',' << r.law.name << ',' << r.g_text << ',' << r.gamma_text << ','
               << to_decimal_string(r.e_ref, 17) << ',' << f("small_g") << ',' << f("large_g") << ','
               << f("schwager_poschel") << ',' << f("prop2_exact_at_zero") << ',' << f("prop2_numeric") << ','
               << f("prop2_chebyshev_beta") << '\n';
      }
    }
  }
  // Figs. 8-11: g_c of eq. (24) against the certified thresholds.
  struct gc_row {
    std::string law, gamma, g_ref;
    double approx, rel;
  };
  std::vector<gc_row> gc;
  const std::string sticking = (fs::path(o.data) / "sticking_hertz.csv").string();
  if (fs::exists(sticking)) {
    const csv_table t = read_table(sticking);
    for (const auto& rec : t.rows) {
      if (rec.fields[4] != "g") continue;
      const contact_law law = law_by_name(rec.fields[1]);
      const double gamma = parse_real<double>(rec.fields[5], "gamma"), ref = parse_real<double>(rec.fields[6], "g");
      const double approx = critical_g(law, gamma);
      gc.push_back({rec.fields[1], rec.fields[5], rec.fields[6], approx, std::abs(approx - ref) / ref});
    }
  }

  const bool as_csv = o.csv || (o.output.size() > 4 && o.output.substr(o.output.size() - 4) == ".csv");
  std::ostringstream out;
  if (as_csv) {
    out << "kind,law,g,range,approximation,max_abs_error,at,report_value\n";
    for (const auto& [key, e] : entries) {
      const auto p = printed_values().find(key);
      out << "table" << table_number.at(e.law) << ',' << e.law << ',' << e.g << ',' << e.range << ',' << e.source
          << ',' << (e.ours < 0 ? "" : to_decimal_string(e.ours, 6)) << ',' << e.where << ','
          << (p == printed_values().end() ? "" : sci(p->second)) << '\n';
    }
    for (const auto& r : gc)
      out << "fig_gc," << r.law << ',' << r.g_ref << ",gamma=" << r.gamma << ",eq24_relative_error,"
          << to_decimal_string(r.rel, 6) << ",g_c(eq24)=" << to_decimal_string(r.approx, 17) << ",\n";
  } else {
    out << "# Maximum absolute errors of the report's approximations against the certified tables\n\n"
        << "Computed by `viscor report" << (o.compare ? " --compare" : "") << "` (viscor " << VISCOR_VERSION
        << ", commit " << git_commit() << ") from the tables in `" << o.data << "`, in double precision.\n"
        << "Prop. 2's O(γ²) approximation (36) = min(e₊, eₛ) with I, Q from the closed forms (39), (40) (Exact, g = 0), "
           "tanh-sinh quadrature of (41), (42) (Num.) or the Chebyshev-Beta scheme (48), (49), n = 21 (Approx.).\n"
        << "Ranges as in the report: γ_max = min(0.1, 1.1 γ_c(g)), small γ < 0.2 γ_max, medium up to 0.92 γ_max, "
           "large above.\n";
    if (o.compare) out << "Each cell: ours / the report's printed value; ⚑ marks a ratio outside [1/2, 2].\n";
    for (const auto& law : hertz_laws) {
      const bool kk = law == "kuwabara_kono";
      out << "\n## Table " << table_number.at(law) << ": " << law << " (" << law_by_name(law).describe() << ")\n\n";
      out << "(a) g = 0, 0.05, 1\n\n| g | Exact γ<0.02 | Exact γ≥0.02 | Num. γ<0.02 | Num. γ≥0.02 | Approx. γ<0.02 | "
             "Approx. γ≥0.02 |"
          << (kk ? " S-P γ<0.02 | S-P γ≥0.02 |" : "") << "\n|---|---|---|---|---|---|---|" << (kk ? "---|---|" : "")
          << "\n";
      for (const std::string g : {"0", "0.05", "1"}) {
        out << "| " << g;
        std::vector<std::string> sources{"exact_at_zero", "numeric", "chebyshev_beta"};
        if (kk) sources.push_back("schwager_poschel");
        for (const auto& s : sources)
          for (const std::string r : {"small", "rest"}) out << " | " << cell(entries, law + "|" + g + "|" + r + "|" + s, o.compare);
        out << " |\n";
      }
      if (gmax.count(law + "|1") && gmax.at(law + "|1") < 0.1)
        out << "\nAt g = 1, γ_max = " << sci(gmax.at(law + "|1"), 6) << " (1.1 γ_c): the ranges are γ < "
            << sci(0.2 * gmax.at(law + "|1")) << " and above.\n";
      out << "\n(b) g = 10, γ_max = "
          << (gmax.count(law + "|10") ? sci(gmax.at(law + "|10"), 6) : std::string("(table missing)")) << "\n\n"
          << "| I & Q | " << range_label("small", law, "10", gmax) << " | " << range_label("medium", law, "10", gmax)
          << " | " << range_label("large", law, "10", gmax) << " |\n|---|---|---|---|\n";
      std::vector<std::pair<std::string, std::string>> rows{{"Num.", "numeric"}, {"Approx.", "chebyshev_beta"}};
      if (kk) rows.push_back({"S-P", "schwager_poschel"});
      for (const auto& [label, s] : rows) {
        out << "| " << label;
        for (const std::string r : {"small", "medium", "large"})
          out << " | " << cell(entries, law + "|10|" + r + "|" + s, o.compare);
        out << " |\n";
      }
    }
    out << "\n## Figs. 8-11: relative error of g_c(γ) of eq. (24)\n\n"
        << "Against the certified thresholds of `sticking_hertz.csv` (e = 0 exactly for g ≥ g_c).\n\n";
    if (gc.empty()) {
      out << "(sticking_hertz.csv not found)\n";
    } else {
      out << "| γ |";
      for (const auto& law : hertz_laws) out << ' ' << law << " g_c | eq. (24) rel. err. |";
      out << "\n|---|";
      for (std::size_t i = 0; i < hertz_laws.size(); ++i) out << "---|---|";
      out << "\n";
      std::vector<std::string> gammas;
      for (const auto& r : gc)
        if (std::find(gammas.begin(), gammas.end(), r.gamma) == gammas.end()) gammas.push_back(r.gamma);
      for (const auto& gamma : gammas) {
        out << "| " << gamma << " |";
        for (const auto& law : hertz_laws) {
          const auto it = std::find_if(gc.begin(), gc.end(), [&](const gc_row& r) { return r.law == law && r.gamma == gamma; });
          if (it == gc.end())
            out << " — | — |";
          else
            out << ' ' << to_decimal_string(parse_real<double>(it->g_ref, "g"), 6) << " | " << sci(it->rel) << " |";
        }
        out << "\n";
      }
    }
  }
  return {out.str(), values.str()};
}

/// The regression baseline of the approximations' errors: every group of every
/// cor_*.csv table of o.data; groups with non-finite values are listed in `warnings`.
inline baseline_output make_baseline(const baseline_request& o) {
  using namespace detail;
  if (o.output.empty()) throw invalid_parameter("report baseline needs -o FILE");
  viscor::detail::approximation_cache<double> cache;
  std::ostringstream out;
  out << "# generated by: viscor report baseline --data " << o.data << " -o " << o.output << "  (viscor "
      << VISCOR_VERSION << ", commit " << git_commit() << ")\n"
      << "# max |e_approx - e_ref| in double per (table, law, g, gamma range) of every approximation; "
         "ranges: include/viscor/tables/approximation_errors.hpp\n"
      << error_baseline_header() << "\n";
  baseline_output result;
  for (const auto& path : cor_tables(o.data)) {
    for (const auto& grp : approximation_errors(read_table(path), path, cache)) {
      out << error_baseline_line(grp) << "\n";
      ++result.groups;
      if (grp.non_finite > 0)
        result.warnings.push_back(grp.key() + ": " + std::to_string(grp.non_finite) + " non-finite values, first at " +
                                  grp.first_failure);
    }
  }
  result.text = out.str();
  return result;
}

}  // namespace viscor::jobs
