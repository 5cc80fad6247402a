// viscor bench --surrogate (src/cli/cmd_bench.cpp): the JSON carries a row per law
// and stream with the per-evaluation times and the Taylor ratio, the rebound stream
// holds only rebounds, a law without a surrogate file is skipped and named, and
// bad counts exit with 2. Timings are not judged here (docs/performance.md has them);
// only that they are measured (positive, ordered as median <= p99, and the slowest
// point at least the median). Skipped when the CLI is not built.
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

TEST(CliBenchSurrogate, JsonHasBothStreamsWithTimesAndTheTaylorRatio) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("bench --surrogate --laws kuwabara_kono --points 400 --passes 2 --taylor-points 3 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "surrogate");
  ASSERT_EQ(j["rows"].size(), 2u) << r.out;  // kuwabara_kono mixed and rebound
  EXPECT_EQ(j["rows"][0]["stream"], "mixed");
  EXPECT_EQ(j["rows"][0]["points"], 400);
  EXPECT_EQ(j["rows"][1]["stream"], "rebound");
  EXPECT_GT(j["rows"][1]["points"], 0);
  EXPECT_LT(j["rows"][1]["points"], 400);  // most random points stick
  for (const auto& row : j["rows"]) {
    EXPECT_EQ(row["law"], "kuwabara_kono");
    EXPECT_GT(row["median_ns"].get<double>(), 0);
    // Order statistics of the same timings (surrogate_timing.hpp): median <= p99 <= the
    // largest single timing, and the slowest point's least timing is at most that.
    EXPECT_LE(row["median_ns"].get<double>(), row["p99_ns"].get<double>());
    EXPECT_LE(row["p99_ns"].get<double>(), row["raw_max_ns"].get<double>());
    EXPECT_LE(row["max_ns"].get<double>(), row["raw_max_ns"].get<double>());
    EXPECT_GT(row["stream_mean_ns"].get<double>(), 0);
    EXPECT_GT(row["taylor_double_mean_ns"].get<double>(), 0);
    EXPECT_EQ(row["taylor_points"], 3);
    // The ratio is what it says (no claim on the timings themselves: they depend on the machine).
    EXPECT_DOUBLE_EQ(row["taylor_over_surrogate"].get<double>(),
                     row["taylor_double_mean_ns"].get<double>() / row["stream_mean_ns"].get<double>());
  }
  EXPECT_TRUE(j["skipped_without_surrogate"].empty());
}

TEST(CliBenchSurrogate, ALawWithoutASurrogateIsNamed) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string empty = ::testing::TempDir() + "no_surrogates_" + std::to_string(::getpid());
  std::filesystem::create_directories(empty);
  ::setenv("VISCOR_SURROGATE_DIR", empty.c_str(), 1);
  const auto r = run_cli("bench --surrogate --laws tsuji --points 10 --passes 1 --taylor-points 1 --json");
  ::unsetenv("VISCOR_SURROGATE_DIR");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["rows"].empty());
  ASSERT_EQ(j["skipped_without_surrogate"].size(), 1u);
  EXPECT_EQ(j["skipped_without_surrogate"][0], "tsuji");
}

TEST(CliBenchSurrogate, BadCountsExitWithTwo) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  for (const char* bad : {"--points 0", "--passes 0", "--taylor-points 0"}) {
    const auto r = run_cli(std::string("bench --surrogate --laws linear ") + bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(">= 1"), std::string::npos) << r.err;
  }
}

}  // namespace
