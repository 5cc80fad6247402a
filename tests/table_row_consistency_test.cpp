// A table row must agree with itself, wherever it is read (a merge, a resume, a
// reader of committed data): a certified e outside its own proven enclosure, more
// proven digits than the enclosure's width allows, more certified digits than e is
// written with, and a resumed row that is not the grid point of its index are each
// refused naming the file, line and field. The rows are committed ones
// (reference_data/proven/cor_g_sweep.csv) with one field changed.
#include "test_utils.hpp"

#include <viscor/jobs/table_format.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using viscor::test::run_cli;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream s(line);
  for (std::string x; std::getline(s, x, ',');) f.push_back(x);
  return f;
}

std::string join(const std::vector<std::string>& f) {
  std::string s;
  for (const auto& x : f) s += (s.empty() ? "" : ",") + x;
  return s;
}

/// The header and first row of a committed proven table, with field `column` of the row replaced.
std::string proven_table_with(std::size_t column, const std::string& value) {
  std::ifstream in(std::string(VISCOR_SOURCE_DIR) + "/reference_data/proven/cor_g_sweep.csv");
  std::string header, row;
  std::getline(in, header), std::getline(in, row);
  std::vector<std::string> f = split(row);
  if (column < f.size()) f[column] = value;
  return header + "\n" + join(f) + "\n";
}

std::string refusal(const std::string& text) {
  try {
    viscor::jobs::table_format{viscor::table_kind::cor, true}.parse(text, "t.csv");
  } catch (const viscor::parse_error& e) {
    return e.what();
  }
  return "";
}

TEST(TableRowConsistency, CommittedRowPasses) { EXPECT_EQ(refusal(proven_table_with(99, "")), ""); }

TEST(TableRowConsistency, CertifiedEOutsideItsEnclosure) {
  // 9.98e-01 written where the row's enclosure holds 0.99843...: wrong in the fourth digit
  const std::string why = refusal(proven_table_with(7, "9.9800000000000000000000000000000000000e-01"));
  EXPECT_NE(why.find("t.csv:2: field e"), std::string::npos) << why;
  EXPECT_NE(why.find("outside its own proven enclosure"), std::string::npos) << why;
  const std::string why2 = refusal(proven_table_with(8, "1.6000000000000000000000000000000000000e-03"));
  EXPECT_NE(why2.find("field one_minus_e"), std::string::npos) << why2;
}

TEST(TableRowConsistency, MoreProvenDigitsThanTheEnclosureHolds) {
  const std::string why = refusal(proven_table_with(17, "999"));
  EXPECT_NE(why.find("field proven_digits"), std::string::npos) << why;
  EXPECT_NE(why.find("claims 999 proven digits"), std::string::npos) << why;
}

TEST(TableRowConsistency, MoreCertifiedDigitsThanWritten) {
  const std::string why = refusal(proven_table_with(11, "99"));
  EXPECT_NE(why.find("field digits"), std::string::npos) << why;
  EXPECT_NE(why.find("claims 99 certified digits"), std::string::npos) << why;
}

// --resume keeps only rows that are the grid points of their index.
TEST(TableRowConsistency, ResumedRowOffTheGridIsRefused) {
  std::string dir = ::testing::TempDir() + "viscor_row_consistencyXXXXXX";
  ASSERT_NE(::mkdtemp(dir.data()), nullptr);
  const std::string spec = dir + "/spec.json", out = dir + "/t.csv";
  std::ofstream(spec) << R"({"laws": ["linear"], "gamma": [0.05, 0.1, 0.5], "g": 1, "digits": 20})";
  setenv("VISCOR_TABLE_STOP_AFTER", "1", 1);
  const auto stopped = run_cli("table " + spec + " -o " + out + " --threads 1 --quiet", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  ASSERT_NE(stopped.status, 0);
  std::ifstream in(out + ".partial");
  std::string header, row;
  std::getline(in, header), std::getline(in, row);
  in.close();
  std::vector<std::string> f = split(row);
  ASSERT_GE(f.size(), 6u);
  f[4] = f[4] == "0.05" ? "0.07" : "0.05";  // a gamma of another row, or off the grid
  std::ofstream(out + ".partial") << header << "\n" << join(f) << "\n";
  const auto resumed = run_cli("table " + spec + " -o " + out + " --resume --quiet");
  EXPECT_NE(resumed.status, 0);
  EXPECT_NE(resumed.err.find("not the grid point"), std::string::npos) << resumed.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
