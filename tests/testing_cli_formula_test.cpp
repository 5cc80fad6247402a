// viscor formula points|check (src/cli/cmd_formula.cpp): the points, a values file
// of the report's Prop. 2 computed here, the verdict and its exit codes, and bad
// input. The statistics are the library's (testing_cor_formula_test.cpp checks
// them against the committed error map); here the front end must give the same.
#include <viscor/testing/cor_formula.hpp>

#include <viscor/approx/approximations.hpp>

#include "test_utils.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

double prop2_numeric(double gamma, double g) {
  static const viscor::cor_approximations<double> approx(viscor::law_by_name("kuwabara_kono"));
  return approx.prop2(gamma, g, viscor::coefficient_source::numeric).e;
}

// Writes gamma,g,e of `formula` at the points `viscor formula points` lists.
std::string values_file(const std::string& name, double (*formula)(double, double)) {
  const auto points = run_cli("formula points --model kuwabara_kono");
  EXPECT_EQ(points.status, 0) << points.err;
  std::istringstream in(points.out);
  const std::string path = ::testing::TempDir() + name;
  std::ofstream out(path);
  out << "gamma,g,e\n";
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line == "gamma,g") continue;
    const auto comma = line.find(',');
    const double gamma = std::stod(line.substr(0, comma)), g = std::stod(line.substr(comma + 1));
    out << line << ',' << viscor::to_decimal_string(formula(gamma, g), 17) << '\n';
    ++n;
  }
  EXPECT_GT(n, 1000u);
  return path;
}

// Writes `text` to the file `name` in the test's temporary directory; returns its path.
std::string write_values(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

double wrong_in_one_cell(double gamma, double g) {
  return prop2_numeric(gamma, g) + (1e-4 <= gamma && gamma <= 2e-4 && 0.01 <= g && g <= 0.1 ? 1e-3 : 0);
}

TEST(CliFormula, CheckGivesTheLibrarysStatisticsAndExitCodes) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string good = values_file("prop2_numeric.csv", prop2_numeric);
  const auto r = run_cli("formula check --model kuwabara_kono --values " + good + " --tolerance 1e-5 --gamma-max 1e-3 --json");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["pass"], true);
  const viscor::formula_comparison lib =
      viscor::testing::check_cor_formula(prop2_numeric, "kuwabara_kono", 1e-5, viscor::formula_region{0, 1e-3});
  ASSERT_EQ(j["cells"].size(), lib.cells.size());
  for (std::size_t k = 0; k < lib.cells.size(); ++k)  // the file holds 17 digits: the errors agree to rounding
    EXPECT_NEAR(std::stod(j["cells"][k]["max_abs_e"].get<std::string>()), lib.cells[k].max_abs_e, 1e-16);

  const std::string bad = values_file("wrong.csv", wrong_in_one_cell);
  const auto f = run_cli("formula check --model kuwabara_kono --values " + bad + " --tolerance 1e-5 --gamma-max 1e-3");
  EXPECT_EQ(f.status, 1) << f.err;
  EXPECT_NE(f.out.find("verdict    FAIL"), std::string::npos) << f.out;
  EXPECT_NE(f.out.find("fails      gamma 1e-4..2e-4, g 0.01..0.1"), std::string::npos) << f.out;
}

TEST(CliFormula, BadValuesFilesAreRefusedNamingTheProblem) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto unknown = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " +
                               write_values("unknown.csv", "gamma,g,e\n0.123456,0.5,0.9\n"));
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("gamma = 0.123456"), std::string::npos) << unknown.err;
  const auto no_value = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " +
                                write_values("no_value.csv", "gamma,g\n0.1,0.5\n"));
  EXPECT_EQ(no_value.status, 2);
  EXPECT_NE(no_value.err.find("e (or one_minus_e)"), std::string::npos) << no_value.err;
  const auto twice = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " +
                             write_values("twice.csv", "gamma,g,e,e\n0.1,0.5,0.9,0.9\n"));
  EXPECT_EQ(twice.status, 2);
  EXPECT_NE(twice.err.find("given twice"), std::string::npos) << twice.err;
  const auto text = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " +
                            write_values("text.csv", "gamma,g,e\n0.1,0.5,abc\n"));
  EXPECT_EQ(text.status, 2);
  EXPECT_NE(text.err.find("abc"), std::string::npos) << text.err;
  const auto linear_law = run_cli("formula points --alpha 1 --beta 1");
  EXPECT_EQ(linear_law.status, 2);
  const auto not_utf8 = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " +
                                write_values("latin1.csv", "gamma,g,e\n0.1,0.5,0.9\n# caf\xe9\n"));
  EXPECT_EQ(not_utf8.status, 2);
  EXPECT_NE(not_utf8.err.find("latin1.csv:3: not UTF-8"), std::string::npos) << not_utf8.err;
  const std::string long_field(5000, '7');
  const auto huge = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " +
                            write_values("huge.csv", "gamma,g,e\n0.1,0.5," + long_field + "x\n"));
  EXPECT_EQ(huge.status, 2);
  EXPECT_LT(huge.err.size(), 400u) << "the message quotes the start of the field only";
}

// A verdict over nothing judged is no verdict: exit 2 naming why, and no output file;
// region bounds and tolerances go through the one number parser.
TEST(CliFormula, ACheckThatJudgesNothingIsRefused) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string out = ::testing::TempDir() + "nothing_judged.json";
  std::remove(out.c_str());
  const auto header_only = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 -o " + out + " --values " +
                                   write_values("header_only.csv", "gamma,g,e\n"));
  EXPECT_EQ(header_only.status, 2);
  EXPECT_NE(header_only.err.find("judged no cell"), std::string::npos) << header_only.err;
  EXPECT_NE(header_only.err.find("0 of 108 cells in the region judged"), std::string::npos) << header_only.err;
  EXPECT_FALSE(std::ifstream(out).good()) << "no output for a check that judged nothing";
  // Four certified points, each right, no two cells' corners among them: nothing judged.
  // (Four that are the corners of one cell judge that cell: "1 of 108 cells".)
  const std::string four = write_values("four.csv", "gamma,g,e\n" + [] {
    std::string rows;
    for (const char* point : {"1e-6,0", "2e-6,1e-4", "5e-6,0", "1e-5,1e-4"}) {
      const auto comma = std::string(point).find(',');
      rows += std::string(point) + "," +
              viscor::to_decimal_string(prop2_numeric(std::stod(std::string(point).substr(0, comma)),
                                                      std::stod(std::string(point).substr(comma + 1))), 17) + "\n";
    }
    return rows;
  }());
  const auto four_rows = run_cli("formula check --model kuwabara_kono --tolerance 1e-3 --values " + four);
  EXPECT_EQ(four_rows.status, 2) << four_rows.out;
  EXPECT_NE(four_rows.err.find("0 of 108 cells in the region judged; 5 points in no judged cell"), std::string::npos) << four_rows.err;

  const std::string good = values_file("prop2_for_regions.csv", prop2_numeric);
  const std::string check = "formula check --model kuwabara_kono --tolerance 1e-5 --values " + good;
  const auto no_cell = run_cli(check + " --gamma-min 0.3 --gamma-max 0.4");  // between the edges 0.2 and 0.5
  EXPECT_EQ(no_cell.status, 2);
  EXPECT_NE(no_cell.err.find("the region holds no cell of the map"), std::string::npos) << no_cell.err;
  const auto inverted = run_cli(check + " --gamma-min 0.01 --gamma-max 0.001");
  EXPECT_EQ(inverted.status, 2);
  EXPECT_NE(inverted.err.find("gamma_min = 0.01 is not below gamma_max = 0.001"), std::string::npos) << inverted.err;
  for (const char* bound : {"nan", "inf", "0x10", "1e-400"}) {
    const auto r = run_cli(check + " --gamma-max " + bound);
    EXPECT_EQ(r.status, 2) << bound << ": " << r.out;
    EXPECT_NE(r.err.find("gamma_max"), std::string::npos) << r.err;
  }
  for (const char* tolerance : {"1", "-1e-3", "nan", "2"}) {
    const auto r = run_cli("formula check --model kuwabara_kono --values " + good + " --tolerance " + tolerance);
    EXPECT_EQ(r.status, 2) << tolerance << ": " << r.out;
    EXPECT_NE(r.err.find("tolerance"), std::string::npos) << r.err;
  }
  // The values from standard input, and the coverage line of a check that judged.
  const auto from_stdin =
      run_cli("formula check --model kuwabara_kono --tolerance 1e-5 --gamma-max 1e-3 --values - < " + good);
  EXPECT_EQ(from_stdin.status, 0) << from_stdin.err;
  EXPECT_NE(from_stdin.out.find("coverage   "), std::string::npos) << from_stdin.out;
  EXPECT_NE(from_stdin.out.find(" cells in the region judged; "), std::string::npos) << from_stdin.out;
}

}  // namespace
