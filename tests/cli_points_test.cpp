// viscor cor --points: many points from one process. Values are checked
// against the closed form of the linear law (exact_solutions.hpp), at double and
// at 50 digits; CSV and JSON lines, standard input, threads, refused lines.
#include <viscor/exact/exact_solutions.hpp>

#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "viscor_points_" + name;
  std::ofstream(path) << text;
  return path;
}

std::vector<nlohmann::json> json_lines(const std::string& out) {
  std::vector<nlohmann::json> v;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) v.push_back(nlohmann::json::parse(line));
  return v;
}

TEST(CliPoints, JsonLinesMatchTheClosedForm) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string file = write_file("linear.jsonl",
                                      "{\"law\": \"linear\", \"gamma\": 0.05, \"g\": 1}\n"
                                      "# a comment\n"
                                      "{\"alpha\": 1, \"beta\": 1, \"gamma\": \"0.3\", \"g\": -0.5, \"digits\": 50}\n"
                                      "\n"
                                      "{\"law\": \"linear\", \"gamma\": 0.1, \"digits\": 50}\n");
  for (const char* threads : {"1", "2"}) {
    SCOPED_TRACE(threads);
    const auto r = run_cli("cor --points " + file + " --threads " + threads);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = json_lines(r.out);
    ASSERT_EQ(lines.size(), 3u) << r.out;
    const std::vector<std::pair<std::string, std::string>> points{{"0.05", "1"}, {"0.3", "-0.5"}, {"0.1", "0"}};
    const std::vector<int> line_numbers{1, 3, 5}, digits{15, 50, 50};
    for (std::size_t i = 0; i < lines.size(); ++i) {
      EXPECT_EQ(lines[i]["line"], line_numbers[i]);
      EXPECT_EQ(lines[i]["outcome"], "rebound");
      EXPECT_GE(lines[i]["precision"]["digits"].get<int>(), digits[i]);
      viscor::scoped_precision p(70);
      const auto exact = viscor::exact_cor<viscor::mpfr_real>(viscor::law_by_name("linear"),
                                                              viscor::mpfr_real(points[i].first),
                                                              viscor::mpfr_real(points[i].second));
      const auto e = viscor::parse_real<viscor::mpfr_real>(lines[i]["e"].get<std::string>(), "e");
      EXPECT_GE(viscor::test::agreeing_digits(e, exact->e), digits[i] - 2.0) << lines[i]["e"];
    }
  }
}

TEST(CliPoints, CsvFromStandardInput) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string file = write_file("points.csv", "law,gamma,g\nlinear,0.05,1\ntsuji,0.1,0.5\n");
  const auto r = run_cli("cor --points - < " + file);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lines = json_lines(r.out);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0]["line"], 2);
  EXPECT_EQ(lines[1]["law"]["name"], "tsuji");
  const auto exact = viscor::exact_cor<double>(viscor::law_by_name("linear"), 0.05, 1.0);
  EXPECT_NEAR(std::stod(lines[0]["e"].get<std::string>()), exact->e, 1e-14);
}

TEST(CliPoints, RefusedPointsAreNamedAndTheRestComputed) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string file = write_file("bad.jsonl",
                                      "{\"law\": \"linear\", \"gamma\": 0.05}\n"
                                      "{\"law\": \"linear\", \"gamma\": -1}\n"
                                      "{\"law\": \"linear\", \"gama\": 0.1}\n"
                                      "{\"law\": \"linear\", \"gamma\": 0.1, \"digits\": \"x\"}\n"
                                      "not json\n"
                                      "{\"law\": \"linear\", \"gamma\": 0.2}\n");
  const auto r = run_cli("cor --points " + file);
  EXPECT_EQ(r.status, 2) << r.err;
  const auto lines = json_lines(r.out);
  ASSERT_EQ(lines.size(), 6u) << r.out;
  EXPECT_FALSE(lines[0].contains("error"));
  for (int i : {1, 2, 3, 4}) EXPECT_TRUE(lines[i].contains("error")) << lines[i];
  EXPECT_NE(lines[1]["error"].get<std::string>().find("gamma"), std::string::npos) << lines[1];
  EXPECT_NE(lines[2]["error"].get<std::string>().find("gama"), std::string::npos) << lines[2];
  EXPECT_NE(lines[3]["error"].get<std::string>().find("digits"), std::string::npos) << lines[3];
  EXPECT_FALSE(lines[5].contains("error"));
  EXPECT_NE(r.err.find("bad.jsonl:2:"), std::string::npos) << r.err;
  // Options that belong to the points are refused with --points.
  EXPECT_EQ(run_cli("cor --points " + file + " --gamma 0.1").status, 2);
  EXPECT_EQ(run_cli("cor --points /no/such/file").status, 2);
  EXPECT_EQ(run_cli("cor --points " + write_file("bad.csv", "law,gamma,speed\n")).status, 2);
}

}  // namespace
