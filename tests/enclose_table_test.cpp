// viscor table with "method": "proven" (include/viscor/jobs/table_format.hpp,
// proven_rows.hpp; docs/tables.md): every row certified as method "certify" does,
// plus the bounds, proven digits and proven outcome of viscor::enclose. Checked:
// the linear law's enclosures contain its closed form (exact/exact_linear.hpp in
// MPFR at 80 digits, not the code under test), proven digits >= certified digits - 2
// and every certified e and 1 - e within a unit of its last digit of the enclosure
// (linear law and Kuwabara-Kono at 30 digits), the run stops when a certified e is
// moved outside (test seam), and every table property holds for the new columns:
// resume, shards and merge (byte-identical), no mixing with a certified run, bad
// input exit 2 naming the value with nothing written.
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/exact/exact_linear.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace {

namespace fs = std::filesystem;
using namespace viscor;
using viscor::test::run_cli;

const std::string header =
    "index,law,alpha,beta,gamma,g,outcome,e,one_minus_e,contact_time,max_compression,digits,method,"
    "e_lower,e_upper,one_minus_e_lower,one_minus_e_upper,proven_digits,outcome_proven";

// Linear law only (cheap proofs): 2 gamma x 2 g, all rebounds; for the table properties.
const std::string linear_spec = R"({
  "laws": ["linear"], "gamma": [0.05, 0.3], "g": [0, 0.2], "digits": 30, "method": "proven"
})";

// The closed form's law at a rebound and a stick, and Kuwabara-Kono (the general prover).
const std::string mixed_spec = R"({
  "laws": ["linear", "kuwabara_kono"], "gamma": [0.05, 0.5], "g": 1, "digits": 30, "method": "proven"
})";

class ProvenTable : public viscor::test::scratch_dir_test {
 protected:
  ProvenTable() : scratch_dir_test("viscor_proven_table_") {}
};

/// The rows of a CSV text as column -> field.
std::vector<std::map<std::string, std::string>> rows_of(const std::string& csv) {
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  auto split = [](const std::string& s) {
    std::vector<std::string> f;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = s.find(',', start);
      f.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) return f;
      start = comma + 1;
    }
  };
  const std::vector<std::string> names = split(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(lines, line)) {
    const std::vector<std::string> fields = split(line);
    EXPECT_EQ(fields.size(), names.size()) << line;
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < names.size() && k < fields.size(); ++k) row[names[k]] = fields[k];
    rows.push_back(row);
  }
  return rows;
}

/// Whether the certified decimal `value` (to `digits` digits) is within one unit of its
/// last digit of [lower, upper] (a certified value is off by less than half a unit).
bool within_last_digit(const std::string& value, int digits, const std::string& lower, const std::string& upper) {
  const mpfr_real x(value), lo(lower), hi(upper);
  const mpfr_real unit = x == 0 ? mpfr_real(0) : mpfr_real(pow(mpfr_real(10), floor(log10(abs(x))) - digits + 1));
  return lo - unit <= x && x <= hi + unit;
}

TEST_F(ProvenTable, BoundsHoldTheClosedFormAndTheCertifiedValues) {
  scoped_precision precision(80);
  const std::string spec = write("spec.json", mixed_spec);
  const auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 2 --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = read(path("out.csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n')), header);
  const auto rows = rows_of(csv);
  ASSERT_EQ(rows.size(), 4u);
  int closed_form_rows = 0, kuwabara_kono_rebounds = 0;
  for (const auto& row : rows) {
    const std::string what = row.at("law") + " gamma " + row.at("gamma") + " g " + row.at("g");
    EXPECT_EQ(row.at("method"), "certified") << what;
    if (row.at("outcome_proven") == "undecided") {
      ADD_FAILURE() << what << ": undecided (none expected at these points)";
      continue;
    }
    EXPECT_EQ(row.at("outcome_proven"), row.at("outcome")) << what;
    const int certified = std::stoi(row.at("digits")), proven = std::stoi(row.at("proven_digits"));
    EXPECT_GE(proven, certified - 2) << what;
    EXPECT_GE(certified, 25) << what;
    for (const std::string q : {"e", "one_minus_e"}) {
      EXPECT_LE(mpfr_real(row.at(q + "_lower")), mpfr_real(row.at(q + "_upper"))) << what << " " << q;
      EXPECT_TRUE(within_last_digit(row.at(q), certified, row.at(q + "_lower"), row.at(q + "_upper")))
          << what << ": certified " << q << " = " << row.at(q) << " vs [" << row.at(q + "_lower") << ", "
          << row.at(q + "_upper") << "]";
    }
    if (row.at("law") == "kuwabara_kono" && row.at("outcome") == "rebound") ++kuwabara_kono_rebounds;
    if (row.at("law") != "linear") continue;
    // The truth, from the closed form (allowance 1e-70 for its own rounding at 80 digits).
    const auto exact = exact_linear(mpfr_real(row.at("gamma")), mpfr_real(row.at("g")));
    EXPECT_EQ(to_string(exact.outcome), row.at("outcome_proven")) << what;
    const mpfr_real slack("1e-70");
    EXPECT_LE(mpfr_real(row.at("e_lower")) - slack, exact.e) << what;
    EXPECT_GE(mpfr_real(row.at("e_upper")) + slack, exact.e) << what;
    EXPECT_LE(mpfr_real(row.at("one_minus_e_lower")) - slack, exact.one_minus_e) << what;
    EXPECT_GE(mpfr_real(row.at("one_minus_e_upper")) + slack, exact.one_minus_e) << what;
    ++closed_form_rows;
  }
  EXPECT_EQ(closed_form_rows, 2);
  EXPECT_EQ(kuwabara_kono_rebounds, 1);  // gamma 0.05: the general prover, not just the linear one
  EXPECT_EQ(rows[1].at("outcome"), "stick");  // linear, gamma 0.5, g 1 (docs/tables.md)
  EXPECT_EQ(rows[1].at("e_lower"), "0");
  EXPECT_EQ(rows[1].at("e_upper"), "0");

  const auto sidecar = nlohmann::json::parse(read(path("out.csv.json")));
  EXPECT_EQ(sidecar["method"]["requested"], "proven");
  EXPECT_EQ(sidecar["spec"]["method"], "proven");
  EXPECT_TRUE(sidecar["method"].contains("proof"));
  EXPECT_EQ(sidecar["proofs"]["rows_by_outcome_proven"]["undecided"], 0);
  EXPECT_EQ(sidecar["rows_by_method"]["certified"], 4);
  EXPECT_EQ(files(), (std::vector<std::string>{"out.csv", "out.csv.json", "spec.json"}));
}

TEST_F(ProvenTable, ACertifiedValueOutsideTheProofStopsTheRun) {
  // The test seam moves every certified e by 1e-20 (far more than its 27+ digits
  // allow) before the check against the enclosure: the run must stop, write nothing
  // but the partial file, and say which row and why.
  const std::string spec = write("spec.json", linear_spec);
  setenv("VISCOR_TABLE_SHIFT_CERTIFIED_E", "1e-20", 1);
  auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1 --quiet", VISCOR_CLI_TEST_HOOKS_PATH);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("is outside the proven enclosure"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.csv")));
  // A shift inside the last certified digit's allowance passes.
  fs::remove(path("out.csv.partial"));
  fs::remove(path("out.csv.partial.json"));
  setenv("VISCOR_TABLE_SHIFT_CERTIFIED_E", "1e-40", 1);
  r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1 --quiet", VISCOR_CLI_TEST_HOOKS_PATH);
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(ProvenTable, ResumeShardsAndMergeKeepTheProofColumns) {
  const std::string spec = write("spec.json", linear_spec);
  ASSERT_EQ(run_cli("table " + spec + " -o " + path("full.csv") + " --quiet").status, 0);
  const std::string full = read(path("full.csv"));
  EXPECT_EQ(rows_of(full).size(), 4u);

  // Interrupted after 2 rows, resumed: the same bytes.
  setenv("VISCOR_TABLE_STOP_AFTER", "2", 1);
  auto r = run_cli("table " + spec + " -o " + path("out.csv") + " --threads 1 --quiet", VISCOR_CLI_TEST_HOOKS_PATH);
  unsetenv("VISCOR_TABLE_STOP_AFTER");
  EXPECT_NE(r.status, 0);
  const std::string partial = read(path("out.csv.partial"));
  EXPECT_EQ(partial.substr(0, partial.find('\n')), header);
  // A certified spec cannot continue the proven partial run.
  std::string certified_text = linear_spec;
  certified_text.replace(certified_text.find("\"proven\""), 8, "\"certify\"");
  const std::string certified = write("certified.json", certified_text);
  r = run_cli("table " + certified + " -o " + path("out.csv") + " --resume --quiet");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("different spec"), std::string::npos) << r.err;
  r = run_cli("table " + spec + " -o " + path("out.csv") + " --resume --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("out.csv")), full);

  // Two shards merged: the same bytes; a certified shard does not merge with a proven one.
  for (int i = 0; i < 2; ++i)
    ASSERT_EQ(run_cli("table " + spec + " -o " + path("part" + std::to_string(i) + ".csv") + " --shard " +
                      std::to_string(i) + "/2 --quiet")
                  .status,
              0);
  r = run_cli("table merge " + path("part1.csv") + " " + path("part0.csv") + " -o " + path("merged.csv") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("merged.csv")), full);
  EXPECT_TRUE(nlohmann::json::parse(read(path("merged.csv.json"))).contains("proofs"));
  ASSERT_EQ(run_cli("table " + certified + " -o " + path("c1.csv") + " --shard 1/2 --quiet").status, 0);
  r = run_cli("table merge " + path("part0.csv") + " " + path("c1.csv") + " -o " + path("bad.csv"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("must be of one kind"), std::string::npos) << r.err;

  // A corrupted proof field: the error names file, line and field.
  std::string text = read(path("part0.csv"));
  text.replace(text.rfind(",rebound\n"), 9, ",rebounds\n");
  write("part0.csv", text);
  r = run_cli("table merge " + path("part0.csv") + " " + path("part1.csv") + " -o " + path("bad.csv"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("part0.csv:3: field outcome_proven: must be one of rebound, stick, undecided"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(path("bad.csv")));
}

TEST_F(ProvenTable, BadInputExits2AndWritesNothing) {
  struct bad {
    std::string spec, expected;
  };
  const std::vector<bad> cases = {
      {R"({"laws": [{"alpha": "1.5000000001", "beta": 1}], "gamma": 0.1, "g": 0, "method": "proven"})",
       "not provable: exponent alpha = 1.5000000001 is not rational"},
      {R"({"laws": ["linear"], "gamma": 0.1, "g": 0, "digits": 4, "method": "proven"})",
       "field digits: method \"proven\" needs at least 5 digits, got 4"},
      {R"({"laws": ["linear"], "gamma": 0.1, "g": 0, "method": "proved"})",
       "field method: must be \"auto\", \"exact\", \"certify\" or \"proven\", got \"proved\""},
  };
  for (const auto& c : cases) {
    const std::string spec = write("spec.json", c.spec);
    const auto r = run_cli("table " + spec + " -o " + path("out.csv"));
    EXPECT_EQ(r.status, 2) << c.spec;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.spec << "\n" << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{"spec.json"}) << c.spec;
  }
  const std::string sticking = write("spec.json", R"({"laws": "linear", "gamma": 0.5, "solve_for": "g",
    "threshold_digits": 10, "digits": 20,
    "method": "proven"})");
  const auto r = run_cli("table sticking " + sticking + " -o " + path("out.csv"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("spec.json:3: field method: \"proven\" is a method of CoR tables"), std::string::npos) << r.err;
  EXPECT_EQ(files(), std::vector<std::string>{"spec.json"});
}

}  // namespace
