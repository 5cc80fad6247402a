// viscor table through the command line: small linear-law tables (closed-form
// rows), determinism, interrupt-and-resume, shard-and-merge (byte-identical to a
// single run), sticking thresholds, and malformed specs and tables (clear
// errors naming file, line and field; nothing written).
#include "test_utils.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using viscor::test::run_cli;

class TableCli : public viscor::test::scratch_dir_test {
 protected:
  TableCli() : scratch_dir_test("viscor_table_") {}
};

// Linear law (closed form at every g): 6 gamma (one overdamped) x 5 g (one
// pulling the bead off) = 30 exact rows.
const std::string linear_spec = R"({
  "description": "linear law, closed-form rows",
  "laws": ["linear"],
  "gamma": [0, {"from": "0.05", "to": "0.5", "count": 4}, 2.5],
  "g": [-0.5, 0, 0.05, 1, 10],
  "digits": 40,
  "method": "exact"
})";

const std::string linear_only_spec = R"({
  "laws": "linear",
  "gamma": {"from": 0, "to": 0.1, "count": 11},
  "g": [0, 1],
  "digits": 20,
  "method": "exact"
})";

TEST_F(TableCli, SmallLinearTable) {
  const std::string spec = write("spec.json", linear_only_spec);
  const auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = read(path("out.csv"));
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "index,law,alpha,beta,gamma,g,outcome,e,one_minus_e,contact_time,max_compression,digits,method");
  int rows = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(line.substr(0, line.find(',')), std::to_string(rows)) << "rows in grid order";
    ++rows;
  }
  EXPECT_EQ(rows, 22);
  // Row 3: gamma = 0.03, g = 0: e = exp(-xi pi/omega), xi = 0.015, to 18 digits (20 - 2).
  EXPECT_NE(csv.find("\n3,linear,1,1,0.03,0,rebound,"), std::string::npos);
  const std::size_t e_start = csv.find("\n3,linear,1,1,0.03,0,rebound,") + 29;
  const std::string e_text = csv.substr(e_start, csv.find(',', e_start) - e_start);
#if VISCOR_HAS_MPFR
  using viscor::mpfr_50;
  const mpfr_50 xi = mpfr_50(3) / 200, pi = boost::math::constants::pi<mpfr_50>();
  const mpfr_50 expected = exp(-xi * pi / sqrt(1 - xi * xi));
  const mpfr_50 e = viscor::parse_real<mpfr_50>(e_text, "e");
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, e, expected, mpfr_50("1e-17")) << e_text;
#endif
  const std::string sidecar = read(path("out.csv.json"));
  for (const char* field : {"\"viscor_version\"", "\"git_commit\"", "\"scalar\"", "\"wall_time_seconds\"",
                            "\"host\"", "\"date\"", "\"command_line\"", "\"spec\"", "exact closed form"})
    EXPECT_NE(sidecar.find(field), std::string::npos) << field;
  EXPECT_EQ(files(), (std::vector<std::string>{"out.csv", "out.csv.json", "spec.json"}));  // no partial left
}

TEST_F(TableCli, DeterministicWhateverTheThreads) {
  const std::string spec = write("spec.json", linear_spec);
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("a.csv") + " --threads 1 --quiet").status, 0);
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("b.csv") + " --threads 3 --quiet").status, 0);
  const std::string a = read(path("a.csv"));
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 31);  // header + 6 gamma x 5 g
  EXPECT_EQ(a, read(path("b.csv")));
  // Reformatting the spec does not change the table.
  const std::string spec2 = write("spec2.json", R"({"method":"exact","digits":40,"g":["10","1","0.05","0.0",-5e-1],
    "gamma":[2.50,{"to":0.5,"from":0.05,"count":4},0.0],"laws":"linear"})");
  ASSERT_EQ(run_cli("table " + spec2 + " -o " + path("c.csv") + " --quiet").status, 0);
  EXPECT_EQ(a, read(path("c.csv")));
}

TEST_F(TableCli, InterruptAndResumeGiveTheSameBytes) {
  const std::string spec = write("spec.json", linear_spec);
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("full.csv") + " --quiet").status, 0);

  // The test hook raises SIGINT after 7 rows: the run stops non-zero and keeps them.
  setenv("VISCOR_TABLE_STOP_AFTER", "7", 1);
  auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.csv")));
  const std::string partial = read(path("out.csv.partial"));
  EXPECT_EQ(std::count(partial.begin(), partial.end(), '\n'), 8);  // header + 7 rows

  // Without --resume the partial run is not overwritten.
  r = run_cli("table " + spec + " -o " + path("out.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--resume"), std::string::npos) << r.err;

  // A second interruption, then a row cut short by a kill inside write().
  setenv("VISCOR_TABLE_STOP_AFTER", "5", 1);
  r = run_cli("table " + spec + " -o " + path("out.csv") + " --resume --threads 2", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  EXPECT_NE(r.status, 0);
  std::ofstream(path("out.csv.partial"), std::ios::app) << "29,linear,1,1,2.5,10,reb";

  r = run_cli("table " + spec + " -o " + path("out.csv") + " --resume --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("dropped one row cut short"), std::string::npos) << r.err;
  EXPECT_EQ(read(path("out.csv")), read(path("full.csv")));
  EXPECT_FALSE(fs::exists(path("out.csv.partial")));
  EXPECT_FALSE(fs::exists(path("out.csv.partial.json")));
  EXPECT_NE(read(path("out.csv.json")).find("\"sessions\": 3"), std::string::npos);

  // --resume of a finished table (a resubmitted batch job) leaves it alone.
  const auto before = fs::last_write_time(path("out.csv"));
  r = run_cli("table " + spec + " -o " + path("out.csv") + " --resume");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("already complete"), std::string::npos) << r.err;
  EXPECT_EQ(fs::last_write_time(path("out.csv")), before);
}

TEST_F(TableCli, TheReleasedBinaryHasNoInterruptHook) {
  // VISCOR_TABLE_STOP_AFTER is a test seam of viscor_test_hooks only (src/cli/test_hooks.hpp).
  const std::string spec = write("spec.json", linear_spec);
  setenv("VISCOR_TABLE_STOP_AFTER", "3", 1);
  const auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1 --quiet");
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("out.csv")));
  EXPECT_FALSE(fs::exists(path("out.csv.partial")));
}

TEST_F(TableCli, ResumeRefusesAnotherSpec) {
  const std::string spec = write("spec.json", linear_spec);
  setenv("VISCOR_TABLE_STOP_AFTER", "3", 1);
  EXPECT_NE(run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1 --quiet", VISCOR_CLI_TEST_HOOKS_PATH).status, 0);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  const std::string other = write("other.json", linear_only_spec);
  const auto r = run_cli("table " + other + " -o " + path("out.csv") + " --resume");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("different spec"), std::string::npos) << r.err;
}

TEST_F(TableCli, ShardsMergeIntoTheFullTable) {
  const std::string spec = write("spec.json", linear_spec);
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("full.csv") + " --quiet").status, 0);
  for (int i = 0; i < 3; ++i)
    ASSERT_EQ(run_cli("table " + spec + " -o " + path("part" + std::to_string(i) + ".csv") + " --shard " +
                      std::to_string(i) + "/3 --quiet")
                  .status,
              0);
  const std::string part1 = read(path("part1.csv"));
  EXPECT_EQ(std::count(part1.begin(), part1.end(), '\n'), 1 + 10);  // rows 1, 4, ..., 28
  auto r = run_cli("table merge " + path("part2.csv") + " " + path("part0.csv") + " " + path("part1.csv") + " -o " +
                   path("merged.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("merged.csv")), read(path("full.csv")));
  EXPECT_NE(read(path("merged.csv.json")).find("\"merged_from\""), std::string::npos);

  // A missing shard, a shard given twice, and a shard of another spec are errors.
  r = run_cli("table merge " + path("part0.csv") + " " + path("part1.csv") + " -o " + path("bad.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("row 2 is missing"), std::string::npos) << r.err;
  r = run_cli("table merge " + path("part0.csv") + " " + path("part1.csv") + " " + path("part1.csv") + " " +
              path("part2.csv") + " -o " + path("bad.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("part1.csv:2: field index: row 1 is also in"), std::string::npos) << r.err;
  const std::string other = write("other.json", linear_only_spec);
  ASSERT_EQ(run_cli("table " + other + " -o " + path("other.csv") + " --shard 0/3 --quiet").status, 0);
  r = run_cli("table merge " + path("other.csv") + " " + path("part1.csv") + " " + path("part2.csv") + " -o " +
              path("bad.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("different spec"), std::string::npos) << r.err;
  // A corrupted shard: its error names file, line and field.
  std::string text = read(path("part2.csv"));
  text.replace(text.find(",rebound,"), 9, ",rebounds,");
  write("part2.csv", text);
  r = run_cli("table merge " + path("part0.csv") + " " + path("part1.csv") + " " + path("part2.csv") + " -o " +
              path("bad.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("part2.csv:2: field outcome: must be one of rebound, stick"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("bad.csv")));
}

struct bad_spec {
  std::string text, expected;  // expected: a fragment of the error message
};

TEST_F(TableCli, MalformedSpecsAreClearErrorsAndWriteNothing) {
  const std::vector<bad_spec> cases = {
      {"{\"laws\": [\"linear\"],\n \"gamma\": [0.1, 0.2x],\n \"g\": 0, \"method\": \"exact\"}", "invalid JSON at line 2"},
      {"{\"laws\": [\"linear\",\n  \"linaer\"],\n \"gamma\": 0.1, \"g\": 0}", "spec.json:2: field laws[1]: unknown contact law 'linaer'"},
      {"{\"laws\": \"linear\",\n \"gamma\": [0.1,\n   -0.2],\n \"g\": 0}", "spec.json:3: field gamma[1]: gamma must be >= 0, got -0.2"},
      {"{\"laws\": \"linear\",\n \"gamma\": \"0.1.2\",\n \"g\": 0}", "spec.json:2: field gamma: must be a finite decimal number"},
      {"{\"laws\": \"linear\", \"gamma\": 0.1,\n \"g\": {\"from\": 0, \"to\": 1,\n  \"count\": 7}}", "spec.json:3: field g.count: the step"},
      {"{\"laws\": \"linear\", \"gamma\": 0.1, \"g\": 0,\n \"gama\": 1}", "spec.json:2: field gama: unknown field"},
      {"{\"gamma\": 0.1, \"g\": 0}", "field laws: missing"},
      {"{\"laws\": \"linear\", \"gamma\": 0.1, \"g\": 0,\n \"digits\": 0}", "spec.json:2: field digits: must be an integer from 1"},
      {"{\"laws\": [{\"alpha\": \"1/2\", \"beta\": 1}], \"gamma\": 0.1, \"g\": 0}", "field laws[0].alpha: must be >= 1"},
      {"{\"laws\": \"hertz_linear_damping\", \"gamma\": 0.1, \"g\": 0.05, \"method\": \"exact\"}", "no closed form exists"},
      {"{\"laws\": \"linear\", \"gamma\": 0.1, \"g\": 0,\n \"g\": 1}", "spec.json:2: field g: given twice"},
  };
  for (const auto& c : cases) {
    const std::string spec = write("spec.json", c.text);
    const auto r = run_cli("table " + spec + " -o " + path("out.csv"));
    EXPECT_NE(r.status, 0) << c.text;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << "spec:\n" << c.text << "\nerror: " << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{"spec.json"}) << c.text;  // nothing written
  }
  const auto r = run_cli("table " + path("missing.json") + " -o " + path("out.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("cannot read spec file"), std::string::npos) << r.err;
  EXPECT_NE(run_cli("table " + write("spec.json", linear_spec) + " -o " + path("out.csv") + " --shard 3/3").status, 0);
}

#if VISCOR_HAS_MPFR
TEST_F(TableCli, StickingThresholdsOfTheLinearLaw) {
  // g_c(gamma) of the linear law, checked against the closed-form condition
  // g = rho exp(-xi (t0 + pi/omega)) (see reference_table_test.cpp), and gamma_c
  // of Tsuji at g = 0 against 4/sqrt(5) (critical damping, xi = 1).
  const std::string spec = write("sticking.json", R"({
    "laws": "linear", "gamma": [0.5, 1], "solve_for": "g", "threshold_digits": 20, "digits": 30, "method": "exact"
  })");
  auto r = run_cli("table sticking " + spec + " -o " + path("gc.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = read(path("gc.csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "index,law,alpha,beta,solve_for,gamma,g,rebound_at,stick_at,digits,method");
  using viscor::mpfr_50;
  const mpfr_50 xi = mpfr_50(1) / 4, omega = sqrt(1 - xi * xi), pi = boost::math::constants::pi<mpfr_50>();
  auto overlap = [&](const mpfr_50& g) {
    return mpfr_50(g - sqrt(1 - 2 * xi * g + g * g) * exp(-xi * (atan2(omega, xi - g) + pi) / omega));
  };
  boost::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve(overlap, mpfr_50(0), mpfr_50(100),
                                                      boost::math::tools::eps_tolerance<mpfr_50>(), iterations);
  const std::string prefix = "\n0,linear,1,1,g,0.5,";
  ASSERT_NE(csv.find(prefix), std::string::npos) << csv;
  const std::size_t start = csv.find(prefix) + prefix.size();
  const std::string g_c = csv.substr(start, csv.find(',', start) - start);
  EXPECT_PRED_FORMAT3(viscor::test::relative_close<mpfr_50>, viscor::parse_real<mpfr_50>(g_c, "g_c"),
                      mpfr_50(root.first), mpfr_50("6e-20"))
      << g_c;
  EXPECT_NE(csv.find(",20,exact\n"), std::string::npos) << csv;

  const std::string tsuji = write("tsuji.json", R"({
    "laws": "tsuji", "g": 0, "solve_for": "gamma", "threshold_digits": 15, "digits": 25, "method": "exact"
  })");
  r = run_cli("table sticking " + tsuji + " -o " + path("gammac.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  // 4/sqrt(5) = 1.78885438199983175712...: 15 digits.
  EXPECT_NE(read(path("gammac.csv")).find("\n0,tsuji,3/2,5/4,gamma,1.78885438199983e+00,0,"), std::string::npos)
      << read(path("gammac.csv"));

  // A CoR spec is not a sticking spec, and the reverse.
  r = run_cli("table sticking " + write("cor.json", linear_only_spec) + " -o " + path("x.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("field threshold_digits: missing"), std::string::npos) << r.err;
  r = run_cli("table " + spec + " -o " + path("x.csv"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("viscor table sticking"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("x.csv")));
}
#endif

}  // namespace
