// Regression of the report's approximations against the committed reference
// tables (reference_data/cor_*.csv): every approximation is re-evaluated in
// double on every row, and each group's maximum absolute error must stay within
// 1% of reference_data/approximation_error_baseline.csv (written by
// `viscor report baseline`). Plus reproducibility: a few committed rows are
// recomputed with table_row.hpp at their spec's working digits and must match
// the committed text character by character.
#include "test_utils.hpp"

#include <viscor/tables/approximation_errors.hpp>
#include <viscor/tables/table_row.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace {

namespace fs = std::filesystem;
using namespace viscor;

const std::string data_dir = std::string(VISCOR_SOURCE_DIR) + "/reference_data";
const std::string baseline_path = data_dir + "/approximation_error_baseline.csv";

// Relative growth allowed over the baseline, and an absolute floor for groups
// whose baseline error is 0 or rounding-level (a few ulps of e <= 1).
constexpr double allowed_growth = 0.01;
constexpr double absolute_floor = 1e-15;

struct comparison {
  std::vector<std::string> failures;
  std::vector<std::string> changes;  // every group whose error moved at all
};

/// Compares computed groups with the baseline entries; every group must have an
/// entry and every entry a group.
comparison compare_to_baseline(const std::vector<error_group<double>>& groups,
                               const std::vector<baseline_entry>& baseline) {
  comparison c;
  std::map<std::string, const baseline_entry*> expected;
  for (const auto& b : baseline) expected[b.key] = &b;
  std::set<std::string> seen;
  for (const auto& g : groups) {
    seen.insert(g.key());
    if (g.non_finite > 0) {
      c.failures.push_back(g.key() + ": " + std::to_string(g.non_finite) + " NaN/inf/throwing evaluations, first " +
                           g.first_failure);
      continue;
    }
    const auto it = expected.find(g.key());
    if (it == expected.end()) {
      c.failures.push_back(g.key() + ": not in the baseline (new table or group: regenerate the baseline)");
      continue;
    }
    const double base = std::stod(it->second->max_abs_error);
    const double now = g.max_error;
    std::ostringstream line;
    line << std::left << std::setw(90) << g.key() << std::right << std::setw(14) << std::setprecision(6)
         << std::scientific << base << std::setw(14) << now << std::setw(11) << std::fixed << std::setprecision(4)
         << (base > 0 ? now / base : 0.0);
    if (now > base * (1 + allowed_growth) + absolute_floor) {
      c.failures.push_back(line.str() + "  GREW");
      c.changes.push_back(line.str() + "  GREW");
    } else if (std::abs(now - base) > 1e-7 * base) {
      c.changes.push_back(line.str());
    }
    if (g.rows != it->second->rows)
      c.failures.push_back(g.key() + ": " + std::to_string(g.rows) + " rows, the baseline has " +
                           std::to_string(it->second->rows));
  }
  for (const auto& b : baseline)
    if (!seen.count(b.key)) c.failures.push_back(b.key + ": in the baseline but no rows evaluated it");
  return c;
}

std::vector<std::string> committed_cor_tables() {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(data_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("cor_", 0) == 0 && entry.path().extension() == ".csv") out.push_back(entry.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ApproximationRegression, ErrorsStayWithinBaseline) {
  ASSERT_TRUE(fs::exists(baseline_path)) << baseline_path << " is missing: run viscor report baseline";
  const auto start = std::chrono::steady_clock::now();
  const std::vector<baseline_entry> baseline = read_error_baseline(baseline_path);
  std::vector<error_group<double>> groups;
  detail::approximation_cache<double> cache;
  std::size_t rows = 0;
  const auto tables = committed_cor_tables();
  ASSERT_FALSE(tables.empty());
  for (const auto& path : tables) {
    const csv_table t = read_table(path);
    rows += t.rows.size();
    const auto g = approximation_errors(t, path, cache);
    groups.insert(groups.end(), g.begin(), g.end());
  }
  const comparison c = compare_to_baseline(groups, baseline);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << tables.size() << " tables, " << rows << " rows, " << groups.size() << " groups in " << seconds
            << " s\n";
  if (!c.changes.empty()) {
    std::cout << std::left << std::setw(90) << "group (table|law|g|range|formula|source)" << std::right
              << std::setw(14) << "baseline" << std::setw(14) << "now" << std::setw(11) << "ratio" << "\n";
    for (const auto& line : c.changes) std::cout << line << "\n";
  }
  for (const auto& f : c.failures) ADD_FAILURE() << f;
}

// The comparison itself must catch growth, NaN, and missing or extra groups.
TEST(ApproximationRegression, ComparisonDetectsRegressions) {
  error_group<double> g;
  g.table = "t.csv", g.law = "tsuji", g.g = "0", g.range = "small", g.formula = "prop2", g.source = "numeric";
  g.rows = 10, g.max_error = 1.0e-5, g.at_gamma = "0.01";
  baseline_entry b;
  b.key = g.key(), b.max_abs_error = "1e-05", b.rows = 10;
  EXPECT_TRUE(compare_to_baseline({g}, {b}).failures.empty());
  g.max_error = 1.009e-5;  // within 1%
  EXPECT_TRUE(compare_to_baseline({g}, {b}).failures.empty());
  EXPECT_EQ(compare_to_baseline({g}, {b}).changes.size(), 1u);
  g.max_error = 1.02e-5;  // 2% growth
  EXPECT_EQ(compare_to_baseline({g}, {b}).failures.size(), 1u);
  g.max_error = 1e-5, g.non_finite = 1, g.first_failure = "gamma = 0.01: non-finite value nan";
  EXPECT_EQ(compare_to_baseline({g}, {b}).failures.size(), 1u);
  g.non_finite = 0;
  EXPECT_EQ(compare_to_baseline({}, {b}).failures.size(), 1u);  // baseline group without rows
  EXPECT_EQ(compare_to_baseline({g}, {}).failures.size(), 1u);   // group without baseline
}

// A corrupted reference value (e off by 0.01, the formulas agree with it to ~1e-6) must show up as a grown error (end to end through the table parser).
TEST(ApproximationRegression, CorruptedReferenceIsDetected) {
  const std::string header = table_header(table_kind::cor) + "\n";
  const std::string good = header + "0,tsuji,3/2,5/4,0.01,0,rebound,9.8259e-01,1.741e-02,,,5,certified\n";
  const std::string bad = header + "0,tsuji,3/2,5/4,0.01,0,rebound,9.7259e-01,2.741e-02,,,5,certified\n";
  detail::approximation_cache<double> cache;
  const auto base_groups = approximation_errors(parse_table(good, "cor_x.csv"), "cor_x.csv", cache);
  std::vector<baseline_entry> baseline;
  for (const auto& g : base_groups) {
    baseline_entry b;
    b.key = g.key(), b.max_abs_error = to_decimal_string(g.max_error, 8), b.rows = g.rows;
    baseline.push_back(b);
  }
  EXPECT_TRUE(compare_to_baseline(base_groups, baseline).failures.empty());
  const auto now = approximation_errors(parse_table(bad, "cor_x.csv"), "cor_x.csv", cache);
  EXPECT_FALSE(compare_to_baseline(now, baseline).failures.empty());
}

// The report's ranges: gamma_max = min(0.1, 1.1 gamma_c(g)); docs/report-notes.md lists the g = 10 values.
TEST(ApproximationRegression, ReportGammaMaxMatchesTablesMd) {
  const std::vector<std::pair<std::string, double>> expected{{"hertz_linear_damping", 0.00553427},
                                                             {"tsuji", 0.00315879},
                                                             {"kuwabara_kono", 0.00183309},
                                                             {"hunt_crossley", 0.000221371}};
  for (const auto& [law, gm] : expected)
    EXPECT_NEAR(detail::report_gamma_max(law_by_name(law), 10.0), gm, 1e-8) << law;
  EXPECT_NEAR(detail::report_gamma_max(law_by_name("hunt_crossley"), 1.0), 0.0700036, 1e-7);
  EXPECT_EQ(detail::report_gamma_max(law_by_name("tsuji"), 0.0), 0.1);
  EXPECT_EQ(detail::report_range(0.0199, 0.1, true), "small");
  EXPECT_EQ(detail::report_range(parse_real<double>("0.02", "g"), 0.1, true), "medium");
  EXPECT_EQ(detail::report_range(parse_real<double>("0.092", "g"), 0.1, true), "medium");
  EXPECT_EQ(detail::report_range(0.0921, 0.1, true), "large");
}

// ---- reproducibility: committed rows recomputed digit by digit ----

/// The working digits of a table's spec (reference_data/<stem>.json, "digits": N).
int spec_digits(const std::string& table) {
  const fs::path spec = fs::path(table).replace_extension(".json");
  std::ifstream in(spec);
  std::stringstream s;
  s << in.rdbuf();
  std::smatch m;
  const std::string text = s.str();
  if (!std::regex_search(text, m, std::regex("\"digits\"\\s*:\\s*([0-9]+)"))) return 0;
  return std::stoi(m[1]);
}

TEST(TableReproducibility, CommittedRowsRegenerateDigitByDigit) {
  // (table, law, gamma, g): spread over laws, g and methods (exact and certified rows).
  const std::vector<std::array<std::string, 4>> picks{
      {"cor_report_grid.csv", "linear", "0.05", "1"},
      {"cor_report_grid.csv", "tsuji", "0.0123", "0.05"},
      {"cor_report_grid.csv", "kuwabara_kono", "0.03", "0"},
      {"cor_report_grid.csv", "hunt_crossley", "0.0007", "1"},
      {"cor_report_g10_hertz_linear_damping.csv", "hertz_linear_damping", "0.001", "10"},
      {"cor_gamma_sweep.csv", "hertz_linear_damping", "0.001", "0.05"},
  };
  int checked = 0;
  for (const auto& [file, law, gamma, g] : picks) {
    const std::string path = data_dir + "/" + file;
    if (!fs::exists(path)) {
      std::cout << "not committed yet: " << file << "\n";
      continue;
    }
    const int digits = spec_digits(path);
    ASSERT_GT(digits, 0) << "no \"digits\" in the spec of " << path;
    const csv_table t = read_table(path);
    const csv_record* rec = nullptr;
    for (const auto& r : t.rows)
      if (r.fields[1] == law && r.fields[4] == gamma && r.fields[5] == g) rec = &r;
    if (rec == nullptr) {
      ADD_FAILURE() << file << " has no row " << law << ", gamma = " << gamma << ", g = " << g;
      continue;
    }
    grid_point p;
    p.index = rec->index, p.law = law_by_name(law), p.gamma = gamma, p.g = g;
    table_settings settings;
    settings.digits = digits;
    const auto start = std::chrono::steady_clock::now();
    const std::string line = csv_line(compute_row(p, settings));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (line != rec->text) {
      // Not byte-identical: the certified digit count may move by one between
      // versions of the certifier (it sits on a margin); the values must still
      // agree digit by digit on the digits both certify.
      std::size_t diff = 0;
      while (diff < line.size() && diff < rec->text.size() && line[diff] == rec->text[diff]) ++diff;
      std::cout << file << ":" << rec->line << ": not byte-identical (first difference at character " << diff
                << ")\n  now:       " << line << "\n  committed: " << rec->text << "\n";
      const auto now = split_fields(line);
      const int d_now = std::stoi(now[11]), d_old = std::stoi(rec->fields[11]);
      EXPECT_LE(std::abs(d_now - d_old), 1) << "certified digits moved from " << d_old << " to " << d_now;
      const int d = std::min(d_now, d_old);
      for (std::size_t c = 0; c < now.size(); ++c) {
        if (c == 11) continue;
        if (c < 7 || c == 12 || now[c].empty() || rec->fields[c].empty() || now[c] == "0" || now[c] == "1" || now[c] == "inf") {
          EXPECT_EQ(now[c], rec->fields[c]) << file << ":" << rec->line << ": column " << c;
          continue;
        }
        const std::string a = to_decimal_string(parse_real<mpfr_100>(now[c], "now"), d);
        const std::string b = to_decimal_string(parse_real<mpfr_100>(rec->fields[c], "committed"), d);
        EXPECT_EQ(a, b) << file << ":" << rec->line << ": column " << c << " differs within its " << d
                        << " certified digits";
      }
    }
    std::cout << file << ":" << rec->line << " (" << law << ", gamma = " << gamma << ", g = " << g
              << ") reproduced in " << seconds << " s\n";
    ++checked;
  }
  EXPECT_GE(checked, 3) << "fewer than 3 committed rows could be checked";
}

}  // namespace
