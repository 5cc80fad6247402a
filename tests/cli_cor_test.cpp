// viscor cor (src/cli/cmd_cor.cpp): e as printed against the exact linear
// solution, at double and at 210 digits (where a too long step once said "stick"), and errors
// for bad input. Skipped when the CLI is not built.
#include <viscor/exact/exact_solutions.hpp>

#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace {

using viscor::test::run_cli;
using viscor::mpfr_real;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

/// The value on the readable summary's line "NAME   value".
std::string summary_field(const std::string& out, const std::string& name) {
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(name + " ", 0) == 0) {
      std::istringstream fields(line.substr(name.size()));
      std::string value;
      fields >> value;
      return value;
    }
  ADD_FAILURE() << "no line '" << name << "' in\n" << out;
  return "nan";
}

TEST(CliCor, LinearLawMatchesExactSolution) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  for (const char* g : {"0", "1", "-0.5"}) {
    SCOPED_TRACE(g);
    const auto r = run_cli(std::string("cor --model linear --gamma 0.05 --g ") + g);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("rebound"), std::string::npos) << r.out;
    const double e = viscor::parse_real<double>(summary_field(r.out, "e"), "e");
    const auto exact = viscor::exact_cor<double>(viscor::law_by_name("linear"), 0.05, std::stod(g));
    EXPECT_NEAR(e, exact->e, 1e-14);
  }
}

// The 210-digit linear law (solve_impact_test) through the CLI: 210 digits printed, all but the last few right.
TEST(CliCor, LinearLawAt210Digits) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("cor --model linear --gamma 0.05 --g 1 --digits 210 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "rebound");
  EXPECT_EQ(j["precision"]["digits"], 210);
  viscor::scoped_precision digits(230);
  const mpfr_real e = viscor::parse_real<mpfr_real>(j["e"].get<std::string>(), "e");
  const auto exact = viscor::exact_cor<mpfr_real>(viscor::law_by_name("linear"), mpfr_real("0.05"), mpfr_real(1));
  EXPECT_GE(viscor::test::agreeing_digits(e, exact->e), 205.0) << j["e"];
}

// The JSON names the arithmetic, and says when the solve left the one the digits chose:
// at 25 digits, gamma = 1e-280 under g = 1e6 leaves double-double's range (its 1 - e then
// agrees with the closed form to 31 digits, not 10).
TEST(CliCor, PrecisionNamesTheArithmeticAndItsEscalation) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto plain = run_cli("cor --model linear --gamma 0.05 --g 1 --digits 25 --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out)["precision"];
  if (p["arithmetic"] != "double-double") GTEST_SKIP() << "this build has no double-double (QD)";
  EXPECT_FALSE(p.contains("escalated_from")) << p;
  const auto tiny = run_cli("cor --model linear --gamma 1e-280 --g 1e6 --digits 25 --json");
  ASSERT_EQ(tiny.status, 0) << tiny.err;
  const auto j = nlohmann::json::parse(tiny.out);
  EXPECT_NE(j["precision"]["arithmetic"], "double-double") << j["precision"];
  EXPECT_EQ(j["precision"]["escalated_from"], "double-double") << j["precision"];
  viscor::scoped_precision digits(50);
  const mpfr_real one_minus_e = viscor::parse_real<mpfr_real>(j["one_minus_e"].get<std::string>(), "1 - e");
  const auto exact = viscor::exact_cor<mpfr_real>(viscor::law_by_name("linear"), mpfr_real("1e-280"), mpfr_real("1e6"));
  EXPECT_GE(viscor::test::agreeing_digits(one_minus_e, exact->one_minus_e), 31.0) << j["one_minus_e"];
  EXPECT_EQ(nlohmann::json::parse(run_cli("cor --model linear --gamma 0.05 --g 1 --json").out)["precision"]["arithmetic"],
            "double");
}

// Double has the same exponent range: at 15 digits, gamma = 1e-305 under g = 1e6 leaves
// it (1 - e had 5 right digits of 17), runs in long double and says so.
TEST(CliCor, DoubleEscalatesWhereItsRangeWouldLoseDigits) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("cor --model linear --gamma 1e-305 --g 1e6 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["precision"]["arithmetic"], "long double") << j["precision"];
  EXPECT_EQ(j["precision"]["escalated_from"], "double") << j["precision"];
  viscor::scoped_precision digits(50);
  const mpfr_real one_minus_e = viscor::parse_real<mpfr_real>(j["one_minus_e"].get<std::string>(), "1 - e");
  const auto exact = viscor::exact_cor<mpfr_real>(viscor::law_by_name("linear"), mpfr_real("1e-305"), mpfr_real("1e6"));
  EXPECT_GE(viscor::test::agreeing_digits(one_minus_e, exact->one_minus_e), 15.0) << j["one_minus_e"];
}

TEST(CliCor, BadInputNamesTheValue) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  auto r = run_cli("cor --model linear --gamma -1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("gamma"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("-1"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  r = run_cli("cor --alpha 0.5 --beta 1 --gamma 0.1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("alpha"), std::string::npos) << r.err;
  EXPECT_TRUE(r.err.find("0.5") != std::string::npos || r.err.find("1/2") != std::string::npos) << r.err;
  r = run_cli("cor --model linear --gamma 0.1 --g nonsense");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("nonsense"), std::string::npos) << r.err;
}

// Through the CLI: a stuck bead's stop overlap (overdamped: creeps to u = g).
TEST(CliCor, UndecidedOutcomeIsPrinted) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  // Linear law, g = 0, gamma = 1.9999: e ~ 4e-137, beyond the adaptive method in double.
  const std::string args = "cor --model linear --gamma 1.9999 --g 0 --method adaptive";
  const auto r = run_cli(args + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "undecided");
  EXPECT_EQ(j["contact_time"], "nan");
  const auto text = run_cli(args);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(summary_field(text.out, "outcome"), "undecided");
  EXPECT_EQ(summary_field(text.out, "T_stop"), "unknown");
}

TEST(CliCor, StuckBeadReportsWhereItStops) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("cor --model linear --gamma 3 --g 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "stick");
  EXPECT_EQ(viscor::parse_real<double>(j["stop_overlap"].get<std::string>(), "stop_overlap"), 0.5);
}

}  // namespace
