// viscor approx (src/cli/cmd_approx.cpp): output forms, values against the library,
// and errors. Skipped when the CLI is not built.
#include <viscor/approx/approximations.hpp>

#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

TEST(CliApprox, JsonCarriesEveryFormulaAtFullPrecision) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("approx --model kuwabara_kono --gamma 0.05 --g 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "approx");
  const viscor::cor_approximations<double> approx(viscor::law_by_name("kuwabara_kono"));
  auto value = [](const nlohmann::json& x) { return viscor::parse_real<double>(x.get<std::string>(), "json"); };
  EXPECT_EQ(value(j["small_g"]), approx.small_g(0.05, 1.0));
  EXPECT_EQ(value(j["large_g"]), approx.large_g(0.05, 1.0));
  EXPECT_EQ(value(j["schwager_poschel"]), approx.schwager_poschel(0.05, 1.0));
  const auto numeric = approx.prop2(0.05, 1.0, viscor::coefficient_source::numeric);
  EXPECT_EQ(value(j["prop2"]["numeric"]["e"]), numeric.e);
  EXPECT_EQ(value(j["prop2"]["numeric"]["e_plus"]), numeric.e_plus);
  EXPECT_EQ(value(j["prop2"]["numeric"]["e_linearized"]), numeric.e_linearized);
  EXPECT_EQ(value(j["prop2"]["chebyshev_beta"]["e"]),
            approx.prop2(0.05, 1.0, viscor::coefficient_source::chebyshev_beta).e);
  EXPECT_FALSE(j["prop2"].contains("exact_at_zero"));  // g != 0
  EXPECT_EQ(value(j["closed_forms"]["C1"]), 3.0);
  EXPECT_EQ(j["not_applicable"].size(), 1u);
}

TEST(CliApprox, HighPrecisionAndOneFormula) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto ok = run_cli("approx --model tsuji --gamma 0.125 --formula prop2 --source exact_at_zero --digits 40 --json");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const auto j = nlohmann::json::parse(ok.out);
  EXPECT_EQ(j["precision"]["digits"], 40);
  EXPECT_FALSE(j.contains("small_g"));
  const std::string e = j["prop2"]["exact_at_zero"]["e"];
  // 1 - C0/8 - C2/64 at 40 digits, with C0, C2 of the library.
  using viscor::mpfr_real;
  viscor::scoped_precision digits(40);
  const viscor::cor_approximations<mpfr_real> approx(viscor::law_by_name("tsuji"));
  const mpfr_real expected = 1 - approx.closed_forms().C0 / 8 - approx.closed_forms().C2 / 64;
  EXPECT_LE(viscor::test::relative_difference(viscor::parse_real<mpfr_real>(e, "e"), expected), mpfr_real(1e-38));
}

TEST(CliApprox, ReadableSummaryNamesEveryFormula) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("approx --model hunt_crossley --gamma 0.01 --g 0");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {"small_g (22)", "large_g (23)", "prop2 (36)", "prop2_squared (89)", "prop2_linearized (90)",
                           "exact_at_zero", "numeric", "chebyshev_beta", "Kuwabara-Kono only"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
}

TEST(CliApprox, ErrorsNameTheProblem) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  auto r = run_cli("approx --model tsuji --gamma 0.05 --formula schwager_poschel");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("Kuwabara-Kono"), std::string::npos) << r.err;
  r = run_cli("approx --model tsuji --gamma 0.05 --formula everything");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("everything"), std::string::npos) << r.err;
  r = run_cli("approx --model tsuji --gamma 0.05 --g 1 --source exact_at_zero");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("g = 1"), std::string::npos) << r.err;
  r = run_cli("approx --model tsuji --gamma 0.05 --order 20");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("n = 20"), std::string::npos) << r.err;
  r = run_cli("approx --model tsuji --gamma -1");
  EXPECT_NE(r.status, 0);
}

}  // namespace
