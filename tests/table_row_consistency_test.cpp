// A table row must agree with itself, wherever it is read (a merge, a resume, a
// reader of committed data): a certified e outside its own proven enclosure, more
// proven digits than the enclosure's width allows, more certified digits than e is
// written with, and a resumed row that is not the grid point of its index are each
// refused naming the file, line and field; so is a merged row that is not the grid
// point of its index in the spec its sidecar records. The rows are committed ones
// (reference_data/proven/cor_g_sweep.csv) with one field changed, or rows of small
// tables made here.
#include "test_utils.hpp"

#include <viscor/jobs/table_format.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

using viscor::test::scratch_dir;

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
  const scratch_dir scratch{"viscor_row_consistency"};
  ASSERT_FALSE(scratch.path.empty());
  const std::string dir = scratch.path.string(), spec = dir + "/spec.json", out = dir + "/t.csv";
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
}

/// Makes the two shards of a small table from `spec_text` in a fresh folder (`command`:
/// "table" or "table sticking"), changes field `column` of shard 1's first row to
/// `value` (to another row's value when `value` is that row's own) and merges them.
struct merge_attempt {
  viscor::test::cli_run merged;
  bool output_written = false;
};

merge_attempt merge_with_changed_row(const std::string& command, const std::string& spec_text, std::size_t column,
                                     const std::string& value, const std::string& other_value) {
  const scratch_dir scratch{"viscor_merge_grid"};
  EXPECT_FALSE(scratch.path.empty());
  const std::string dir = scratch.path.string(), spec = dir + "/spec.json";
  std::ofstream(spec) << spec_text;
  for (const char* part : {"0", "1"}) {
    const auto made = run_cli(command + " " + spec + " -o " + dir + "/s" + part + ".csv --shard " + part + "/2 --quiet");
    EXPECT_EQ(made.status, 0) << made.err;
  }
  if (column > 0) {
    std::ifstream in(dir + "/s1.csv");
    std::string header, row, rest, line;
    std::getline(in, header), std::getline(in, row);
    while (std::getline(in, line)) rest += line + "\n";
    in.close();
    std::vector<std::string> f = split(row);
    EXPECT_GT(f.size(), column);
    if (f.size() > column) f[column] = f[column] == value ? other_value : value;
    std::ofstream(dir + "/s1.csv") << header << "\n" << join(f) << "\n" << rest;
  }
  merge_attempt a;
  a.merged = run_cli("table merge " + dir + "/s0.csv " + dir + "/s1.csv -o " + dir + "/all.csv");
  a.output_written = fs::exists(dir + "/all.csv");
  return a;
}

const char* const cor_spec = R"({"laws": ["linear"], "gamma": [0.05, 0.1, 0.5], "g": [0, 1], "digits": 20})";
const char* const sticking_spec =
    R"({"laws": ["linear"], "gamma": [0.05, 0.1, 0.5], "solve_for": "g", "threshold_digits": 10, "digits": 20})";

TEST(TableRowConsistency, MergeOfUnchangedShardsPasses) {
  const merge_attempt cor = merge_with_changed_row("table", cor_spec, 0, "", "");
  EXPECT_EQ(cor.merged.status, 0) << cor.merged.err;
  EXPECT_TRUE(cor.output_written);
  const merge_attempt sticking = merge_with_changed_row("table sticking", sticking_spec, 0, "", "");
  EXPECT_EQ(sticking.merged.status, 0) << sticking.merged.err;
  EXPECT_TRUE(sticking.output_written);
}

// A merged row must be the grid point of its index: a gamma or g of another row,
// one off the grid, and a g of another row are each refused, and nothing is written.
TEST(TableRowConsistency, MergedRowOffTheGridIsRefused) {
  for (const auto& [column, value, other] : std::vector<std::tuple<std::size_t, std::string, std::string>>{
           {4, "0.5", "0.05"}, {4, "0.07", "0.08"}, {5, "0", "1"}}) {
    const merge_attempt a = merge_with_changed_row("table", cor_spec, column, value, other);
    EXPECT_EQ(a.merged.status, 2) << "column " << column << ": " << a.merged.err;
    EXPECT_NE(a.merged.err.find("not the grid point"), std::string::npos) << a.merged.err;
    EXPECT_NE(a.merged.err.find("s1.csv:2: fields law..g"), std::string::npos) << a.merged.err;
    EXPECT_FALSE(a.output_written);
  }
}

// The same for a sticking-threshold table: its fixed value (gamma here) names the point.
TEST(TableRowConsistency, MergedThresholdRowOffTheGridIsRefused) {
  const merge_attempt a = merge_with_changed_row("table sticking", sticking_spec, 5, "0.07", "0.08");
  EXPECT_EQ(a.merged.status, 2) << a.merged.err;
  EXPECT_NE(a.merged.err.find("not the grid point"), std::string::npos) << a.merged.err;
  EXPECT_FALSE(a.output_written);
}

}  // namespace
