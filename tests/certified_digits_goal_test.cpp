// Certified digits asked for (certify/certified_digits_goal.hpp, `viscor cor
// --certified-digits N`): the precision loop's rules on runs whose results the test
// dictates, then the whole job on held-out points of the report grid whose e and
// 1 - e are proven to 50 digits by Arb (reference_data/proven/digits50/, not used to
// choose the loop's first precision): at least N certified digits, each of them right
// against the enclosure; and the CLI's spelling, refusals and point batches.
#include <viscor/certify/certified_digits_goal.hpp>
#include <viscor/jobs/cor_job.hpp>
#include <viscor/jobs/cor_render.hpp>

#include "certified_claims.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace viscor;
using viscor::test::check_claim;
using viscor::test::claim;

// ---- the loop, with runs that certify what the test says ----

TEST(CertifiedDigitsGoal, FirstPrecisionIsTheGoalPlusTheMarginAndOneMoreInMpfr) {
  EXPECT_EQ(first_working_digits(10, 2), 12);  // double
  EXPECT_EQ(first_working_digits(13, 2), 15);
  EXPECT_EQ(first_working_digits(29, 2), 31);
  EXPECT_EQ(first_working_digits(40, 2), 43);  // mpfr
  EXPECT_EQ(first_working_digits(100, 2), 103);
}

TEST(CertifiedDigitsGoal, AShortRunIsRepeatedHigherByItsShortfall) {
  certified_digits_goal goal;
  std::vector<int> asked;
  const int got = certify_to_goal(
      40, 2,
      [&](int digits) {
        asked.push_back(digits);
        return digits >= 50 ? digits - 2 : digits - 6;  // loses 6 digits below 50
      },
      [&](int certified) { return precision_run{asked.back(), certified}; }, goal);
  EXPECT_GE(got, 40);
  ASSERT_EQ(asked.size(), 2u);
  EXPECT_EQ(asked[0], 43);
  EXPECT_EQ(asked[1], 43 + (40 - 37) + 1);  // 47: still short
  ASSERT_EQ(goal.runs.size(), 2u);
  EXPECT_EQ(goal.certified_digits, 40);
}

// Raised by the whole goal and one more (30 -> 32, 63, 94, 125), at most doubled.
TEST(CertifiedDigitsGoal, ARunThatCertifiesNothingIsRaisedByTheWholeGoalAtMostDoubled) {
  certified_digits_goal goal;
  std::vector<int> asked;
  EXPECT_THROW(certify_to_goal(
                   30, 2,
                   [&](int digits) {
                     asked.push_back(digits);
                     return 0;  // the outcome never certified
                   },
                   [&](int certified) { return precision_run{asked.back(), certified}; }, goal),
               certified_digits_unreached);
  ASSERT_EQ(asked.size(), static_cast<std::size_t>(max_precision_runs));
  EXPECT_EQ(asked, (std::vector<int>{32, 63, 94, 125}));
  EXPECT_EQ(next_working_digits(200, precision_run{100, 0}), 200);  // doubled, not 301
}

TEST(CertifiedDigitsGoal, TheRefusalSaysHowManyDigitsCouldBeCertified) {
  certified_digits_goal goal;
  int digits_asked = 0;
  try {
    certify_to_goal(
        60, 2,
        [&](int digits) {
          digits_asked = digits;
          return 45;  // never more
        },
        [&](int certified) { return precision_run{digits_asked, certified}; }, goal);
    FAIL() << "a goal never met must be refused";
  } catch (const certified_digits_unreached& e) {
    EXPECT_EQ(e.best.certified_digits, 45);
    EXPECT_EQ(e.goal.runs.size(), static_cast<std::size_t>(max_precision_runs));
    const std::string what = e.what();
    EXPECT_NE(what.find("certified_digits = 60 not reached"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 45 digits"), std::string::npos) << what;
  }
}

TEST(CertifiedDigitsGoal, AGoalOutOfRangeIsRefusedByName) {
  certified_digits_goal goal;
  for (int wanted : {0, -3, max_working_digits}) {
    try {
      certify_to_goal(
          wanted, 2, [](int) { return 0; }, [](int c) { return precision_run{0, c}; }, goal);
      FAIL() << wanted;
    } catch (const invalid_parameter& e) {
      EXPECT_NE(std::string(e.what()).find("certified_digits must be from 1 to"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(std::to_string(wanted)), std::string::npos) << e.what();
    }
  }
}

// ---- the job, against proofs ----

// Rows of reference_data/proven/digits50/cor_report_grid.csv: every 1501st row from
// 750 (each law at g = 0 and g = 1) and the last rebound and first stick of the two
// laws whose threshold the grid crosses.
std::vector<std::map<std::string, std::string>> held_out_rows() {
  const auto rows = test::read_named_rows(std::string(VISCOR_SOURCE_DIR) +
                                          "/reference_data/proven/digits50/cor_report_grid.csv");
  std::vector<std::map<std::string, std::string>> out;
  if (rows.size() != 15015) return out;
  for (std::size_t i = 750; i < rows.size(); i += 1501) out.push_back(rows[i]);
  for (std::size_t i : {11865, 11866, 14469, 14470}) out.push_back(rows[i]);
  return out;
}

TEST(CertifiedDigitsGoal, ThirtyAndFortyDigitsAreCertifiedAndRightAgainstProofs) {
  const auto rows = held_out_rows();
  ASSERT_EQ(rows.size(), 14u) << "reference_data/proven/digits50/cor_report_grid.csv";
  int sticks = 0;
  for (int wanted : {30, 40}) {
    for (const auto& row : rows) {
      SCOPED_TRACE(row.at("law") + " gamma " + row.at("gamma") + " g " + row.at("g") + ", " + std::to_string(wanted) +
                   " digits");
      jobs::cor_request q;
      q.law = law_by_name(row.at("law"));
      q.gamma = row.at("gamma"), q.g = row.at("g");
      q.certified_digits = wanted;
      const jobs::cor_result r = jobs::run_cor(q);
      ASSERT_TRUE(r.certified && r.goal);
      EXPECT_GE(r.certified->certified_digits, wanted);
      EXPECT_TRUE(r.certified->outcome_certified);
      EXPECT_EQ(std::string(to_string(r.certified->outcome)), row.at("outcome_proven"));
      ASSERT_FALSE(r.goal->runs.empty());
      EXPECT_EQ(r.goal->runs.back().certified_digits, r.certified->certified_digits);
      EXPECT_EQ(r.goal->runs.back().working_digits, r.certified->working_digits);
      sticks += r.outcome == impact_outcome::stick;
      // The certified decimals as printed (rounded to the certified digits), each within
      // one unit of its last digit of the proven enclosure.
      const nlohmann::json c = render::certified_json(*r.certified);
      const std::string e = c["e"], one_minus_e = c["one_minus_e"];
      EXPECT_NE(check_claim(e, row.at("e_lower"), row.at("e_upper")), claim::wrong)
          << e << " not in [" << row.at("e_lower") << ", " << row.at("e_upper") << "]";
      EXPECT_NE(check_claim(one_minus_e, row.at("one_minus_e_lower"), row.at("one_minus_e_upper")), claim::wrong)
          << one_minus_e << " not in [" << row.at("one_minus_e_lower") << ", " << row.at("one_minus_e_upper") << "]";
      if (r.outcome == impact_outcome::rebound) {
        EXPECT_GE(static_cast<int>(e.find('e')) - 1, wanted) << e;  // mantissa digits printed
      }
    }
  }
  EXPECT_EQ(sticks, 4);  // two sticks at two goals: the stick path was judged
}

TEST(CertifiedDigitsGoal, PhysicalInputsReachTheirGoal) {
  jobs::cor_request q;
  q.law = law_by_name("hertz_linear_damping");
  q.physical.m = "2.05e-3", q.physical.k = "6.97e9", q.physical.gamma0 = "2e-9", q.physical.v0 = "0.246";
  q.physical.gravity = "9.81";
  q.certified_digits = 35;
  const jobs::cor_result r = jobs::run_cor(q);
  ASSERT_TRUE(r.certified && r.goal && r.physical);
  EXPECT_EQ(r.outcome, impact_outcome::rebound);  // scaled gamma 0.087, g 5.1e-4
  EXPECT_GE(r.certified->certified_digits, 35);
}

// ---- the command line ----

TEST(CertifiedDigitsGoalCli, TheGoalIsSpelledAsAnOptionAndItsRunsReported) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = test::run_cli("cor --model tsuji --gamma 0.05 --g 1 --certified-digits 32 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["certified_digits_goal"], 32);
  ASSERT_FALSE(j["precision_runs"].empty());
  EXPECT_GE(j["certified"]["certified_digits"].get<int>(), 32);
  EXPECT_EQ(j["precision_runs"].back()["working_digits"], j["precision"]["digits"]);
  const auto text = test::run_cli("cor --model tsuji --gamma 0.05 --g 1 --certified-digits 32");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("goal       32 certified digits: "), std::string::npos) << text.out;
}

TEST(CertifiedDigitsGoalCli, BadGoalsExitWithTwoAndNameTheOption) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto zero = test::run_cli("cor --model tsuji --gamma 0.05 --certified-digits 0");
  EXPECT_EQ(zero.status, 2);
  EXPECT_NE(zero.err.find("--certified-digits must be from 1 to"), std::string::npos) << zero.err;
  EXPECT_NE(zero.err.find("got 0"), std::string::npos) << zero.err;
  const auto both = test::run_cli("cor --model tsuji --gamma 0.05 --certified-digits 20 --digits 30");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("either --digits"), std::string::npos) << both.err;
  EXPECT_TRUE(both.out.empty()) << both.out;
}

TEST(CertifiedDigitsGoalCli, PointsTakeTheGoalPerPointOrForTheBatch) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  test::scratch_dir dir("certified_digits_points");
  const std::string file = (dir.path / "points.jsonl").string();
  std::ofstream(file) << "{\"law\": \"tsuji\", \"gamma\": 0.05, \"g\": 1, \"certified_digits\": 25}\n"
                      << "{\"law\": \"tsuji\", \"gamma\": 0.05, \"g\": 1}\n"
                      << "{\"law\": \"tsuji\", \"gamma\": 0.05, \"g\": 1, \"digits\": 15}\n"
                      << "{\"law\": \"tsuji\", \"gamma\": 0.05, \"g\": 1, \"digits\": 15, \"certified_digits\": 9}\n";
  const auto r = test::run_cli("cor --points " + file + " --certified-digits 35");
  EXPECT_EQ(r.status, 2) << r.err;  // the fourth point is refused, the others computed
  std::vector<nlohmann::json> lines;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(lines.size(), 4u) << r.out;
  EXPECT_EQ(lines[0]["certified_digits_goal"], 25);
  EXPECT_GE(lines[0]["certified"]["certified_digits"].get<int>(), 25);
  EXPECT_EQ(lines[1]["certified_digits_goal"], 35);
  EXPECT_GE(lines[1]["certified"]["certified_digits"].get<int>(), 35);
  EXPECT_FALSE(lines[2].contains("certified"));  // its own working precision
  EXPECT_EQ(lines[2]["precision"]["digits"], 15);
  EXPECT_NE(lines[3]["error"].get<std::string>().find("either digits or certified_digits"), std::string::npos);
}

TEST(CertifiedDigitsGoalCli, TableRowsHaveTheDigitsOfTheSpecAndAreRightAgainstProofs) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  test::scratch_dir dir("certified_digits_table");
  const std::string spec = (dir.path / "spec.json").string(), out = (dir.path / "t.csv").string();
  std::ofstream(spec) << R"({"laws": ["tsuji", "kuwabara_kono", "hunt_crossley"], "gamma": [0.0247, 0.0855, 0.0245],
                             "g": [1], "certified_digits": 38})";
  const auto r = test::run_cli("table " + spec + " -o " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = test::read_named_rows(out);
  ASSERT_EQ(rows.size(), 9u);
  std::map<std::string, std::map<std::string, std::string>> proven;
  for (const auto& row : test::read_named_rows(std::string(VISCOR_SOURCE_DIR) +
                                               "/reference_data/proven/digits50/cor_report_grid.csv"))
    proven[row.at("law") + " " + row.at("gamma") + " " + row.at("g")] = row;
  int judged = 0;
  for (const auto& row : rows) {
    SCOPED_TRACE(row.at("law") + " gamma " + row.at("gamma"));
    EXPECT_GE(std::stoi(row.at("digits")), 38);
    const auto it = proven.find(row.at("law") + " " + row.at("gamma") + " " + row.at("g"));
    if (it == proven.end()) continue;
    ++judged;
    EXPECT_EQ(row.at("outcome"), it->second.at("outcome_proven"));
    EXPECT_NE(check_claim(row.at("e"), it->second.at("e_lower"), it->second.at("e_upper")), claim::wrong) << row.at("e");
    EXPECT_NE(check_claim(row.at("one_minus_e"), it->second.at("one_minus_e_lower"), it->second.at("one_minus_e_upper")),
              claim::wrong)
        << row.at("one_minus_e");
  }
  EXPECT_EQ(judged, 9);  // every row is a point of the grid (kuwabara_kono and hunt_crossley stick at 0.0855)
  std::ifstream sidecar(out + ".json");
  const auto provenance = nlohmann::json::parse(sidecar);
  EXPECT_EQ(provenance["spec"]["certified_digits"], 38);
  EXPECT_EQ(provenance["method"]["certified_digits"]["requested"], 38);
  EXPECT_EQ(provenance["scalar"]["requested_digits"], 41);  // 38 + 2 + 1 in MPFR
}

TEST(CertifiedDigitsGoalCli, TableSpecsRefuseAGoalBesideDigitsOrAProof) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  test::scratch_dir dir("certified_digits_table_refusals");
  const std::string spec = (dir.path / "spec.json").string(), out = (dir.path / "t.csv").string();
  std::ofstream(spec) << R"({"laws": ["tsuji"], "gamma": [0.1], "g": [1], "digits": 30, "certified_digits": 20})";
  const auto both = test::run_cli("table " + spec + " -o " + out);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("field digits: give either digits"), std::string::npos) << both.err;
  std::ofstream(spec) << R"({"laws": ["tsuji"], "gamma": [0.1], "g": [1], "method": "proven", "certified_digits": 20})";
  const auto proven = test::run_cli("table " + spec + " -o " + out);
  EXPECT_EQ(proven.status, 2);
  EXPECT_NE(proven.err.find("field certified_digits"), std::string::npos) << proven.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
