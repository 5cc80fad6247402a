// The table estimate (jobs/table_estimate.hpp): its costs are the committed
// measurements (tools/cost_data/row_cost_by_digits.csv), its rows those the table
// run computes (counted here from the grid's own points), its sums and divisions
// right; and `viscor table --estimate` computes and writes nothing. How close the
// estimate comes to real runs is measured, not tested (docs/performance.md "Cost
// before work").
#include <viscor/jobs/table_estimate.hpp>
#include <viscor/jobs/table_estimate_render.hpp>

#include "certified_claims.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using namespace viscor;

const std::string cost_file = std::string(VISCOR_SOURCE_DIR) + "/tools/cost_data/row_cost_by_digits.csv";

jobs::table_spec spec_of(const std::string& json) { return jobs::parse_spec_json(json, "spec.json"); }

TEST(TableEstimate, CostsAreTheCommittedMeasurements) {
  const auto rows = test::read_named_rows(cost_file);
  ASSERT_EQ(rows.size(), 5u * 9u * 2u) << cost_file;
  int compared = 0;
  for (const auto& row : rows) {
    const int digits = std::stoi(row.at("digits"));
    const scalar_kind kind = scalar_for_digits(digits);
    // A build without double-double or float128 computes those digits in another type.
    const bool measured_type = kind == scalar_kind::mpfr || (digits == 15 && kind == scalar_kind::double_) ||
                               (digits == 18 && kind == scalar_kind::long_double) ||
                               (digits == 30 && kind == scalar_kind::double_double) ||
                               (digits == 33 && kind == scalar_kind::quad);
    if (!measured_type) continue;
    EXPECT_EQ(jobs::row_cpu_time_s(law_by_name(row.at("law")), digits, row.at("method") == "proven"),
              std::stod(row.at("cpu_seconds_per_row")))
        << row.at("law") << " " << digits << " " << row.at("method");
    ++compared;
  }
  EXPECT_GE(compared, 5 * 5 * 2);  // at least the MPFR rows
}

TEST(TableEstimate, MpfrPrecisionsBetweenMeasurementsAreInterpolatedLogLog) {
  const contact_law law = law_by_name("tsuji");
  for (bool proven : {false, true}) {
    const double c50 = jobs::row_cpu_time_s(law, 50, proven), c70 = jobs::row_cpu_time_s(law, 70, proven);
    const double mid = jobs::row_cpu_time_s(law, 59, proven);  // sqrt(50 * 70) = 59.16
    EXPECT_GT(mid, std::min(c50, c70));
    EXPECT_LT(mid, std::max(c50, c70));
    const double power = std::log(c70 / c50) / std::log(70.0 / 50.0);
    EXPECT_NEAR(mid, c50 * std::pow(59.0 / 50.0, power), 1e-12 * mid);
    // Beyond the last measurement the last segment goes on.
    const double c100 = jobs::row_cpu_time_s(law, 100, proven), c150 = jobs::row_cpu_time_s(law, 150, proven);
    const double p_end = std::log(c150 / c100) / std::log(1.5);
    EXPECT_NEAR(jobs::row_cpu_time_s(law, 300, proven), c150 * std::pow(2.0, p_end), 1e-9 * c150);
  }
}

TEST(TableEstimate, AnUnnamedLawCostsAsTheNearestNamedOne) {
  const contact_law custom = make_law(exponent::parse("3/2", "alpha"), exponent::parse("1.3", "beta"));
  EXPECT_EQ(jobs::row_cpu_time_s(custom, 50, false), jobs::row_cpu_time_s(law_by_name("tsuji"), 50, false));
}

TEST(TableEstimate, RowsAreTheRunsRowsAndTheTimesAddUp) {
  const jobs::table_spec spec = spec_of(R"({"laws": ["linear", "tsuji", {"alpha": 1.5, "beta": 2.5}],
      "gamma": [{"from": 0, "to": 0.4, "count": 5}], "g": [0, 0.5, 1, 2], "digits": 45})");
  const expanded_axes axes = expand(spec.grid);
  for (std::int64_t count : {1, 2, 7, 61}) {
    std::int64_t total = 0;
    for (std::int64_t index = 0; index < count; ++index) {
      const shard part{index, count};
      const jobs::table_estimate e = jobs::estimate_cor_table(spec, part, 3);
      const auto points = grid_points(spec.grid, axes, part);  // what the run computes
      EXPECT_EQ(e.rows, static_cast<std::int64_t>(points.size()));
      EXPECT_EQ(e.rows_total, 60);
      ASSERT_EQ(e.laws.size(), 3u);
      double cpu = 0;
      for (std::size_t l = 0; l < 3; ++l) {
        std::int64_t of_law = 0;
        for (const auto& p : points) of_law += p.law.alpha == e.laws[l].law.alpha && p.law.beta == e.laws[l].law.beta;
        EXPECT_EQ(e.laws[l].rows, of_law) << "law " << l << ", shard " << part.to_string();
        EXPECT_EQ(e.laws[l].cpu_time_per_row_s, jobs::row_cpu_time_s(e.laws[l].law, 45, false));
        cpu += static_cast<double>(e.laws[l].rows) * e.laws[l].cpu_time_per_row_s;
      }
      EXPECT_DOUBLE_EQ(e.cpu_time_s, cpu);
      const double busy = static_cast<double>(std::min<std::int64_t>(3, std::max<std::int64_t>(e.rows, 1)));
      EXPECT_DOUBLE_EQ(e.wall_time_s, cpu / busy);
      total += e.rows;
    }
    EXPECT_EQ(total, 60) << count << " shards";
  }
}

TEST(TableEstimate, AGoalOfCertifiedDigitsIsEstimatedAtItsFirstPrecision) {
  const auto e = jobs::estimate_cor_table(spec_of(R"({"laws": ["tsuji"], "gamma": [0.1], "g": [1],
      "certified_digits": 40})"), shard{}, 1);
  EXPECT_EQ(e.working_digits, 43);
  EXPECT_EQ(e.cpu_time_s, jobs::row_cpu_time_s(law_by_name("tsuji"), 43, false));
}

TEST(TableEstimate, ProvenRowsCostTheirProof) {
  const auto e = jobs::estimate_cor_table(spec_of(R"({"laws": ["tsuji"], "gamma": [0.1], "g": [1], "digits": 50,
      "method": "proven"})"), shard{}, 1);
  EXPECT_EQ(e.method, "proven");
  EXPECT_EQ(e.cpu_time_s, jobs::row_cpu_time_s(law_by_name("tsuji"), 50, true));
  EXPECT_GT(e.cpu_time_s, jobs::row_cpu_time_s(law_by_name("tsuji"), 50, false));
}

TEST(TableEstimate, StickingSpecsAndBadThreadsAreRefused) {
  EXPECT_THROW(jobs::estimate_cor_table(spec_of(R"({"laws": ["tsuji"], "gamma": [0.1], "digits": 40,
      "threshold_digits": 20})"), shard{}, 1), parse_error);
  EXPECT_THROW(jobs::estimate_cor_table(spec_of(R"({"laws": ["tsuji"], "gamma": [0.1], "g": [1]})"), shard{}, 0),
               invalid_parameter);
}

TEST(TableEstimateCli, PrintsTheEstimateAndWritesNothing) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  test::scratch_dir dir("table_estimate");
  const std::string spec = (dir.path / "spec.json").string();
  std::ofstream(spec) << R"({"laws": ["tsuji", "hunt_crossley"], "gamma": [{"from": 0, "to": 0.3, "count": 4}],
                             "g": [0, 1], "digits": 50})";
  const auto r = test::run_cli("table " + spec + " --estimate --threads 2 -o " + (dir.path / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("rows       16\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at 2 threads"), std::string::npos) << r.out;
  const auto e = jobs::estimate_cor_table(jobs::read_spec_json(spec), shard{}, 2);
  EXPECT_EQ(r.out, render::table_estimate_text(e));  // the library's estimate, as the CLI prints it
  EXPECT_EQ(test::read_named_rows((dir.path / "t.csv").string()).size(), 0u);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path), std::filesystem::directory_iterator{}), 1);
  const auto shard = test::run_cli("table " + spec + " --estimate --shard 1/3 --threads 1");
  ASSERT_EQ(shard.status, 0) << shard.err;
  EXPECT_NE(shard.out.find(" of 16 (shard 1/3)"), std::string::npos) << shard.out;
  const auto resume = test::run_cli("table " + spec + " --estimate --resume");
  EXPECT_EQ(resume.status, 2);
  EXPECT_NE(resume.err.find("--resume"), std::string::npos) << resume.err;
}

}  // namespace

namespace {

// A spec in SI: its rows are the product of its axes, counted here by hand, and a row
// that calibrates its damping to a target e costs more than one at a given gamma0.
TEST(TableEstimate, SpecsInSiCountTheirAxesAndChargeTheCalibration) {
  const std::string axes = R"("beads": [{"name": "a", "m": 1e-3, "k": 1e9}, {"name": "b", "m": 2e-3, "k": 1e9}],
    "walls": "rigid", "v0": [0.1, 0.2, 0.3], "gravity": [0, 9.81], "force": [0, 1, 2], "digits": 40)";
  const auto given = jobs::estimate_cor_table(
      spec_of(R"({"laws": ["tsuji", "hunt_crossley"], "gamma0": [1e-6, 2e-6], )" + axes + "}"), shard{}, 1);
  EXPECT_EQ(given.rows, 2 * 2 * 3 * 2 * 3 * 2);  // laws x beads x v0 x gravity x force x gamma0
  EXPECT_EQ(given.laws[0].rows, 72);
  EXPECT_EQ(given.laws[0].cpu_time_per_row_s, jobs::row_cpu_time_s(law_by_name("tsuji"), 40, false));
  const auto target = jobs::estimate_cor_table(
      spec_of(R"({"laws": ["tsuji", "hunt_crossley"], "target_e": [0.5, 0.8], )" + axes + "}"), shard{}, 1);
  EXPECT_EQ(target.rows, given.rows);
  EXPECT_GT(target.cpu_time_s, 2 * given.cpu_time_s);  // MPFR: the calibration's solves (docs/performance.md)
  EXPECT_EQ(jobs::estimate_cor_table(spec_of(R"({"laws": ["tsuji"], "gamma0": 1e-6, )" + axes + "}"), shard{1, 4}, 1).rows,
            9);  // 36 rows, indices 1, 5, ..., 33
}

}  // namespace
