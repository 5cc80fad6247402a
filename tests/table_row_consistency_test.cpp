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
#include <functional>
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

/// A table run of `spec_text` stopped after its first row, that row of its .partial
/// passed through `change`, then resumed (`partial` names the .partial in messages).
struct resume_attempt {
  viscor::test::cli_run resumed;
  bool output_written = false;
  std::string partial;
};

resume_attempt resume_with_changed_row(const std::string& spec_text,
                                       const std::function<void(std::vector<std::string>&)>& change) {
  const scratch_dir scratch{"viscor_row_consistency"};
  EXPECT_FALSE(scratch.path.empty());
  const std::string dir = scratch.path.string(), spec = dir + "/spec.json", out = dir + "/t.csv";
  std::ofstream(spec) << spec_text;
  setenv("VISCOR_TABLE_STOP_AFTER", "1", 1);
  const auto stopped = run_cli("table " + spec + " -o " + out + " --threads 1 --quiet", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  EXPECT_NE(stopped.status, 0);
  std::ifstream in(out + ".partial");
  std::string header, row;
  std::getline(in, header), std::getline(in, row);
  in.close();
  std::vector<std::string> f = split(row);
  EXPECT_GE(f.size(), 13u);
  if (f.size() >= 13) change(f);
  std::ofstream(out + ".partial") << header << "\n" << join(f) << "\n";
  resume_attempt a;
  a.resumed = run_cli("table " + spec + " -o " + out + " --resume --quiet");
  a.output_written = fs::exists(out);
  a.partial = out + ".partial";
  return a;
}

// --resume keeps only rows that are the grid points of their index.
TEST(TableRowConsistency, ResumedRowOffTheGridIsRefused) {
  const resume_attempt a =
      resume_with_changed_row(R"({"laws": ["linear"], "gamma": [0.05, 0.1, 0.5], "g": 1, "digits": 20})",
                              [](std::vector<std::string>& f) {
                                f[4] = f[4] == "0.05" ? "0.07" : "0.05";  // a gamma of another row, or off the grid
                              });
  EXPECT_NE(a.resumed.status, 0);
  EXPECT_NE(a.resumed.err.find("not the grid point"), std::string::npos) << a.resumed.err;
  EXPECT_FALSE(a.output_written);
}

/// Makes the two shards of a small table from `spec_text` in a fresh folder (`command`:
/// "table" or "table sticking"), changes field `column` of shard 1's first row to
/// `value` (to another row's value when `value` is that row's own) and merges them.
struct merge_attempt {
  viscor::test::cli_run merged;
  bool output_written = false;
};

merge_attempt merge_with_changed_field(const std::string& command, const std::string& spec_text, std::size_t column,
                                       const std::function<std::string(const std::string&)>& change) {
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
    if (f.size() > column) f[column] = change(f[column]);
    std::ofstream(dir + "/s1.csv") << header << "\n" << join(f) << "\n" << rest;
  }
  merge_attempt a;
  a.merged = run_cli("table merge " + dir + "/s0.csv " + dir + "/s1.csv -o " + dir + "/all.csv");
  a.output_written = fs::exists(dir + "/all.csv");
  return a;
}

merge_attempt merge_with_changed_row(const std::string& command, const std::string& spec_text, std::size_t column,
                                     const std::string& value, const std::string& other_value) {
  return merge_with_changed_field(command, spec_text, column,
                                  [&](const std::string& was) { return was == value ? other_value : value; });
}

// The decimal `text` with its fourth digit changed: every field stays well-formed and
// as long as before, but the value is another one.
std::string fourth_digit_changed(std::string text) {
  int seen = 0;
  for (char& c : text)
    if (c >= '0' && c <= '9' && ++seen == 4) {
      c = c == '9' ? '8' : static_cast<char>(c + 1);
      break;
    }
  return text;
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

// e and 1 - e are written apart, each to the row's certified digits: a row whose e was
// changed in one digit no longer adds up to 1, and is refused wherever it is read (a
// committed table, a resumed run, a merged shard), naming the file, line and field.
TEST(TableRowConsistency, ChangedEThatNoLongerAddsUpIsRefused) {
  std::ifstream in(std::string(VISCOR_SOURCE_DIR) + "/reference_data/cor_report_grid.csv");
  std::string header, row;
  std::getline(in, header), std::getline(in, row), std::getline(in, row);  // index 1: a rebound at gamma > 0
  std::vector<std::string> f = split(row);
  ASSERT_EQ(f.at(6), "rebound");
  const auto read = [&](const std::string& text) {
    try {
      viscor::jobs::table_format{viscor::table_kind::cor, false}.parse(text, "t.csv");
    } catch (const viscor::parse_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(read(header + "\n" + row + "\n"), "");  // as committed: it adds up
  f[7] = fourth_digit_changed(f[7]);
  const std::string why = read(header + "\n" + join(f) + "\n");
  EXPECT_NE(why.find("t.csv:2: field one_minus_e: e + one_minus_e must be 1 within the row's"), std::string::npos) << why;
}

TEST(TableRowConsistency, ResumedRowWithAChangedEIsRefused) {
  const resume_attempt a =
      resume_with_changed_row(R"({"laws": ["tsuji"], "gamma": [0.05, 0.1, 0.5], "g": 1, "digits": 20})",
                              [](std::vector<std::string>& f) {
                                EXPECT_EQ(f[6], "rebound");
                                f[7] = fourth_digit_changed(f[7]);
                              });
  EXPECT_EQ(a.resumed.status, 2) << a.resumed.err;
  EXPECT_NE(a.resumed.err.find(a.partial + ":2: field one_minus_e: e + one_minus_e must be 1"), std::string::npos)
      << a.resumed.err;
  EXPECT_FALSE(a.output_written);
}

TEST(TableRowConsistency, MergedRowWithAChangedEIsRefused) {
  const merge_attempt a = merge_with_changed_field("table", cor_spec, 7, fourth_digit_changed);
  EXPECT_EQ(a.merged.status, 2) << a.merged.err;
  EXPECT_NE(a.merged.err.find("s1.csv:2: field one_minus_e: e + one_minus_e must be 1"), std::string::npos)
      << a.merged.err;
  EXPECT_FALSE(a.output_written);
}

}  // namespace
