// What a careful or hostile user can feed the CLI: integers that would overflow
// (exponents times their common denominator, counts, digits, grid sizes), output
// targets that are not regular files, a full standard output, numbers that
// underflow, empty list entries, bytes that are not UTF-8, repeated columns,
// deeply nested JSON, and an impact whose double result contradicts the energy
// identity. Each is refused with exit 2 and a message naming the option and value
// (or, for the impact, reported undecided). Skipped when the CLI is not built.
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

/// Runs the CLI with `args`; expects exit 2 and every one of `named` in the message.
void expect_refused(const std::string& args, const std::vector<std::string>& named) {
  SCOPED_TRACE(args);
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 2) << r.err << r.out;
  for (const auto& word : named) EXPECT_NE(r.err.find(word), std::string::npos) << "'" << word << "' not in: " << r.err;
}

class CliInputChecks : public viscor::test::scratch_dir_test {
 protected:
  CliInputChecks() : scratch_dir_test("cli_input_checks_") {}
  void SetUp() override {
    if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
    scratch_dir_test::SetUp();
  }
};

// ---- checked integer arithmetic: every integer-producing option at its overflow value

TEST_F(CliInputChecks, ExponentTimesCommonDenominatorOverflowIsRefused) {
  // Q = 4, Q alpha = 4 x 4611686018427387905 wraps around 64 bits (to alpha = 1).
  expect_refused("cor --alpha 4611686018427387905 --beta 5/4 --gamma 0.05 --g 0", {"alpha", "4611686018427387905"});
  // Q = 22, Q alpha = 11 x 922337203685477581 overflows.
  expect_refused("cor --alpha 922337203685477581/2 --beta 12/11 --gamma 0.05", {"alpha", "922337203685477581/2"});
  // Q itself: the lcm of two large coprime denominators.
  expect_refused("cor --alpha 999999999999999999/999999999999999998 --beta 999999999999999998/999999999999999997 "
                 "--gamma 0.05 --g 0",
                 {"common denominator", "999999999999999998/999999999999999997"});
  // The same law in a --points file and in a table spec.
  const std::string points = write("points.csv", "alpha,beta,gamma\n4611686018427387905,5/4,0.05\n");
  const auto r = run_cli("cor --points " + points);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("4611686018427387905"), std::string::npos) << r.err;
  const std::string spec = write("spec.json", R"({"laws": [{"alpha": "4611686018427387905", "beta": "5/4"}],
    "gamma": [0.1], "g": [0], "digits": 15})");
  expect_refused("table " + spec + " -o " + path("t.csv"), {"4611686018427387905"});
  EXPECT_FALSE(std::filesystem::exists(path("t.csv")));
}

TEST_F(CliInputChecks, CountsAndDigitsBeyondTheirTypesAreRefused) {
  const std::string points = write("points.csv", "law,gamma\nlinear,0.1\n");
  expect_refused("cor --model linear --gamma 0.1 --digits 99999999999", {"--digits", "99999999999"});
  expect_refused("cor --model linear --gamma 0.1 --digits 100001", {"digits", "100001"});
  expect_refused("cor --model linear --gamma 0.1 --max-steps 99999999999999999999999", {"--max-steps", "99999999999999999999999"});
  expect_refused("cor --points " + points + " --threads 99999999999", {"--threads", "99999999999"});
  expect_refused("cor --points " + points + " --threads 5000", {"--threads", "5000"});
  expect_refused("approx --model tsuji --gamma 0.1 --order 99999999999", {"--order", "99999999999"});
  const std::string spec = write("spec.json", R"({"laws": ["linear"], "gamma": [0.1], "g": [0], "digits": 15})");
  expect_refused("table " + spec + " -o " + path("t.csv") + " --threads 99999999999", {"--threads", "99999999999"});
  expect_refused("table " + spec + " -o " + path("t.csv") + " --shard 1/99999999999", {"--shard", "1/99999999999"});
  const std::string huge_count = write("count.json", R"({"laws": ["linear"], "gamma": [{"from": 0, "to": 1,
    "count": 99999999999999999999}], "g": [0], "digits": 15})");
  expect_refused("table " + huge_count + " -o " + path("t.csv"), {"count", "99999999999999999999"});
  const std::string digits = write("digits.json", R"({"laws": ["linear"], "gamma": [0.1], "g": [0],
    "digits": 99999999999})");
  expect_refused("table " + digits + " -o " + path("t.csv"), {"digits", "99999999999"});
  // Too many rows: each axis within its limit, their product not.
  const std::string rows = write("rows.json", R"({"laws": ["linear", "tsuji", "kuwabara_kono", "hunt_crossley",
    "hertz_linear_damping"], "gamma": [{"from": 0, "to": 4999, "count": 5000}], "g": [{"from": 0, "to": 4999,
    "count": 5000}], "digits": 15})");
  expect_refused("table " + rows + " -o " + path("t.csv"), {"rows", "125000000"});
  EXPECT_FALSE(std::filesystem::exists(path("t.csv"))) << "no output file left behind";
}

// ---- output files: only regular files, every write checked

TEST_F(CliInputChecks, OutputOntoAFifoASymlinkOrADirectoryIsRefusedAndLeftAlone) {
  const std::string fifo = path("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string target = write("target.txt", "keep me\n");
  const std::string link = path("link.txt");
  std::filesystem::create_symlink(target, link);
  const std::string dir = path("dir");
  std::filesystem::create_directory(dir);
  for (const std::string& command : {std::string("exact --model linear --gamma 0.1 --g 1"),
                                     std::string("cor --model linear --gamma 0.1 --g 1")}) {
    expect_refused(command + " -o " + fifo, {fifo, "FIFO"});
    expect_refused(command + " -o " + link, {link, "symbolic link"});
    expect_refused(command + " -o " + dir, {dir, "directory"});
  }
  const std::string spec = write("spec.json", R"({"laws": ["linear"], "gamma": [0.1], "g": [0], "digits": 15})");
  expect_refused("table " + spec + " -o " + fifo, {fifo, "FIFO"});
  expect_refused("report -o " + fifo, {fifo, "FIFO"});
  expect_refused("errormap --model linear --reference-digits 30 --gamma-edges 0,1 --g-edges 0,1 -o " + fifo, {fifo, "FIFO"});
  // Checked when the options are read, before any work: the target is named, not the bad gamma.
  expect_refused("cor --model linear --gamma -1 -o " + fifo, {fifo, "FIFO"});
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
  ASSERT_EQ(::lstat(link.c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode)) << "the symbolic link was replaced";
  EXPECT_EQ(read(target), "keep me\n");
  // A regular file is replaced as before, and no temporary is left.
  const auto r = run_cli("exact --model linear --gamma 0.1 --g 1 -o " + target);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read(target).find("e"), std::string::npos);
  EXPECT_EQ(files(), (std::vector<std::string>{"dir", "fifo", "link.txt", "spec.json", "target.txt"}));
}

TEST_F(CliInputChecks, AFailedWriteToStandardOutputExitsNonZero) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  for (const std::string& args : {std::string("cor --model linear --gamma 0.1 --g 1 --json"),
                                  std::string("exact --model linear --gamma 0.1 --g 1")}) {
    const std::string command = std::string(VISCOR_CLI_PATH) + " " + args + " > /dev/full 2> " + path("err.txt");
    const int raw = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << args;
    EXPECT_EQ(WEXITSTATUS(raw), 2) << args;
    EXPECT_NE(read(path("err.txt")).find("standard output"), std::string::npos) << read(path("err.txt"));
  }
}

// ---- a double result that the energy identity rules out is undecided, not a rebound

TEST_F(CliInputChecks, AnImpossibleReboundInDoubleIsUndecided) {
  const auto r = run_cli("cor --model hunt_crossley --gamma 1e-30 --g 1e12 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["outcome"], "rebound") << r.out;  // the truth is a stick (20 digits and more)
  EXPECT_LE(std::stod(j["e"].get<std::string>()), 1.0) << r.out;
}

// ---- one number parser: what one subcommand refuses, every one refuses

TEST_F(CliInputChecks, UnderflowIsRefusedLikeOverflow) {
  expect_refused("cor --model linear --gamma 1e-400 --g 0", {"gamma", "1e-400", "underflow"});
  expect_refused("cor --model linear --gamma 0.1 --g 1e-310", {"g", "1e-310", "underflow"});  // subnormal in double
  expect_refused("cor --model linear --gamma 1e400 --g 0", {"gamma", "1e400", "overflow"});
  // A zero is zero, in any spelling; at 50 digits 1e-400 is an ordinary number.
  EXPECT_EQ(run_cli("cor --model linear --gamma 0.1 --g 0e-400").status, 0);
  EXPECT_EQ(run_cli("cor --model linear --gamma 0.1 --g 1e-400 --digits 50").status, 0);
}

// Physical inputs are SI values: the same range at every working precision, so that
// v0 = 1e-400 is refused naming v0 at 20 and 50 digits as at 15 (float128 and MPFR
// would hold it, and the answer would depend on the digits asked for).
TEST_F(CliInputChecks, PhysicalInputsHaveTheSameRangeAtEveryPrecision) {
  const std::string bead = "cor --model tsuji --m 1e-3 --k 1e6 --gamma0 1e-5 --gravity 9.81";
  for (const char* digits : {"15", "20", "50"}) {
    expect_refused(bead + " --v0 1e-400 --digits " + digits, {"v0", "1e-400", "underflow"});
    expect_refused(bead + " --v0 1e400 --digits " + digits, {"v0", "1e400", "overflow"});
  }
  expect_refused("cor --model tsuji --m 1e-3 --k 1e-320 --gamma0 1e-5 --v0 1 --gravity 9.81 --digits 30",
                 {"k", "1e-320", "underflow"});
  EXPECT_EQ(run_cli(bead + " --v0 1 --digits 20").status, 0);
}

TEST_F(CliInputChecks, OutOfRangeOptionsAreRefused) {
  expect_refused("cor --model linear --gamma 0.1 --tolerance 2", {"tolerance", "2"});
  expect_refused("cor --model linear --gamma 0.1 --tolerance 1", {"tolerance", "1"});
  const std::string out = path("map.csv");
  expect_refused("errormap --model linear --reference-digits 5 --gamma-edges 0,1 --g-edges 0,1 -o " + out,
                 {"--reference-digits", "5"});
  expect_refused("errormap --model linear --reference-digits 30 --min-samples 0 --gamma-edges 0,1 --g-edges 0,1 -o " + out,
                 {"--min-samples", "0"});
  expect_refused("errormap --model linear --reference-digits 30 --min-samples -1 --gamma-edges 0,1 --g-edges 0,1 -o " + out,
                 {"--min-samples", "-1"});
  expect_refused("bench --error-maps " + path("nonexistent"), {"--error-maps", path("nonexistent")});
  const std::string dem = "dem yade --damping viscoelastic --k 1e5 --radius 0.001 --density 2500 --deck-damping 0.01 "
                          "--gravity 0 --speeds ";
  expect_refused(dem + "0.1,,1", {"--speeds", "0.1,,1"});
  expect_refused(dem + "0.1,1,", {"--speeds", "0.1,1,"});
  EXPECT_EQ(run_cli(dem + "0.1,1").status, 0);
  expect_refused("cor --gamma= --g 0 --model linear", {"--gamma"});
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(CliInputChecks, PointsFilesMustBeUtf8WithDistinctColumns) {
  const std::string latin1 = write("latin1.csv", "law,gamma\nlinear,0.1\xe9\n");
  expect_refused("cor --points " + latin1, {latin1 + ":2", "UTF-8", "0xE9"});
  const std::string twice = write("twice.csv", "law,gamma,gamma\nlinear,0.1,0.2\n");
  expect_refused("cor --points " + twice, {twice + ":1", "gamma", "twice"});
}

TEST_F(CliInputChecks, DeeplyNestedJsonIsRefusedQuickly) {
  const std::string deep = std::string(400000, '[') + std::string(400000, ']');
  const std::string spec = write("deep.json", R"({"laws": ["linear"], "gamma": [0.1], "g": [0], "description": )" +
                                                  deep + "}");
  const auto start = std::chrono::steady_clock::now();
  expect_refused("table " + spec + " -o " + path("t.csv"), {"deep.json", "nested deeper than 64"});
  const std::string points = write("deep.jsonl", "{\"law\": " + deep + "}\n");
  const auto r = run_cli("cor --points " + points);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("nested deeper than 64"), std::string::npos) << r.err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // Long flat files cost time in proportion to their length (the line count is kept).
  std::string flat = R"({"laws": ["linear"], "g": [0], "digits": 15, "description": [)";
  for (int i = 0; i < 200000; ++i) flat += "1,\n";
  flat += "1], \"gamma\": [0.1]}";
  const std::string flat_spec = write("flat.json", flat);
  const auto flat_start = std::chrono::steady_clock::now();
  expect_refused("table " + flat_spec + " -o " + path("t.csv"), {"flat.json:1", "description"});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - flat_start).count(), 5.0);
}

}  // namespace
