// `viscor prove` and `viscor cor --prove` (src/cli/cmd_prove.cpp, cmd_cor.cpp,
// jobs/cor_render.hpp): their enclosures contain the closed forms (Tsuji at
// g = 0, the linear law under load; exact/ in MPFR at 60 digits, not the proof),
// both use the same JSON names (docs/json-schema.md) with the same values, and bad
// input (a non-rational exponent: "not provable") exits 2 with a message naming the
// value and no output file.
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_tsuji.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "test_utils.hpp"

namespace {

using namespace viscor;
using nlohmann::json;

/// "[mid +/- rad]" -> whether |x - mid| <= rad.
bool encloses(const std::string& text, const mpfr_real& x) {
  const auto plus = text.find("+/-");
  if (text.front() != '[' || plus == std::string::npos) return false;
  const mpfr_real mid(text.substr(1, plus - 2)), rad(text.substr(plus + 4, text.size() - plus - 5));
  return abs(x - mid) <= rad;
}

json prove(const std::string& args) {
  const auto r = viscor::test::run_cli("prove " + args + " --json");
  EXPECT_EQ(r.status, 0) << args << ": " << r.err;
  return r.status == 0 ? json::parse(r.out) : json::object();
}

// Hertz with linear damping at g = 0 has no closed form: its proven outcome (a stick
// by the trap of proven_impact.hpp where it creeps into u = 0) must be the GBS
// solver's, a method the proof shares nothing with.
TEST(ProveCli, ZeroLoadOutcomesAgreeWithTheGbsSolver) {
  for (const std::string gamma : {"0.5", "2", "5", "100"}) {
    const std::string point = "--model hertz_linear_damping --gamma " + gamma + " --g 0";
    const auto gbs = viscor::test::run_cli("cor " + point + " --method adaptive --json");
    ASSERT_EQ(gbs.status, 0) << gbs.err;
    const std::string gbs_outcome = json::parse(gbs.out)["outcome"];
    ASSERT_NE(gbs_outcome, "undecided") << point;
    const json proof = prove(point + " --digits 30");
    EXPECT_EQ(proof["outcome_proven"], gbs_outcome) << point << "\n" << proof.dump(2);
  }
}

TEST(ProveCli, EnclosesTheClosedForms) {
  scoped_precision precision(60);
  const json tsuji = prove("--model tsuji --gamma 0.3 --g 0 --digits 30");
  ASSERT_EQ(tsuji["outcome"], "rebound") << tsuji.dump(2);
  const auto tsuji_exact = exact_tsuji(mpfr_real("0.3"));  // no contact time: mapped in the phase plane
  EXPECT_TRUE(encloses(tsuji["enclosure"]["e"], tsuji_exact.e)) << tsuji.dump(2);
  EXPECT_TRUE(encloses(tsuji["enclosure"]["one_minus_e"], tsuji_exact.one_minus_e)) << tsuji.dump(2);
  EXPECT_GE(tsuji["proven_digits"].get<int>(), 27);

  const json linear = prove("--model linear --gamma 0.3 --g 0.2 --digits 30");
  ASSERT_EQ(linear["outcome"], "rebound") << linear.dump(2);
  const auto linear_exact = exact_linear(mpfr_real("0.3"), mpfr_real("0.2"));
  EXPECT_TRUE(encloses(linear["enclosure"]["e"], linear_exact.e)) << linear.dump(2);
  EXPECT_TRUE(encloses(linear["enclosure"]["one_minus_e"], linear_exact.one_minus_e)) << linear.dump(2);
  ASSERT_TRUE(linear_exact.contact_time.has_value());
  EXPECT_TRUE(encloses(linear["enclosure"]["contact_time"], *linear_exact.contact_time)) << linear.dump(2);

  // Every field name is in the schema.
  std::ifstream schema(std::string(VISCOR_SOURCE_DIR) + "/docs/json-schema.md");
  std::stringstream text;
  text << schema.rdbuf();
  for (const json* object : {&linear, &linear["enclosure"], &linear["precision"]})
    for (const auto& [key, value] : object->items())
      EXPECT_NE(text.str().find("| `" + key + "` |"), std::string::npos) << key << " is not in docs/json-schema.md";
}

/// Whether lower <= x <= upper for the decimal strings j[name_lower], j[name_upper].
bool between(const json& j, const std::string& name, const mpfr_real& x) {
  if (!j.contains(name + "_lower") || !j.contains(name + "_upper")) return false;
  return mpfr_real(j[name + "_lower"].get<std::string>()) <= x && x <= mpfr_real(j[name + "_upper"].get<std::string>());
}

TEST(CorProve, BoundsContainTheClosedFormsWithTheNamesOfProve) {
  scoped_precision precision(80);
  const auto r = viscor::test::run_cli("cor --model linear --gamma 0.3 --g 0.2 --digits 30 --prove --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json cor = json::parse(r.out);
  const auto exact = exact_linear(mpfr_real("0.3"), mpfr_real("0.2"));
  EXPECT_EQ(cor["outcome_proven"], "rebound") << cor.dump(2);
  EXPECT_TRUE(between(cor, "e", exact.e)) << cor.dump(2);
  EXPECT_TRUE(between(cor, "one_minus_e", exact.one_minus_e)) << cor.dump(2);
  EXPECT_TRUE(between(cor, "contact_time", *exact.contact_time)) << cor.dump(2);
  EXPECT_TRUE(between(cor, "max_compression", *exact.max_compression)) << cor.dump(2);
  EXPECT_GE(cor["proven_digits"].get<int>(), 27);
  EXPECT_GE(cor["proven_digits_max_compression"].get<int>(), 27);

  // prove --json: the same names, the same values (the same proof).
  const json proved = prove("--model linear --gamma 0.3 --g 0.2 --digits 30");
  for (const std::string name : {"e_lower", "e_upper", "one_minus_e_lower", "one_minus_e_upper", "proven_digits",
                                 "outcome_proven", "max_compression_lower", "max_compression_upper"})
    EXPECT_EQ(cor[name], proved[name]) << name;

  // Tsuji at g = 0 through cor --prove (the general prover).
  const auto t = viscor::test::run_cli("cor --model tsuji --gamma 0.3 --g 0 --digits 40 --prove --json");
  ASSERT_EQ(t.status, 0) << t.err;
  const json tsuji = json::parse(t.out);
  const auto tsuji_exact = exact_tsuji(mpfr_real("0.3"));
  EXPECT_TRUE(between(tsuji, "e", tsuji_exact.e)) << tsuji.dump(2);
  EXPECT_TRUE(between(tsuji, "one_minus_e", tsuji_exact.one_minus_e)) << tsuji.dump(2);
  EXPECT_GE(tsuji["proven_digits"].get<int>(), 37);

  std::ifstream schema(std::string(VISCOR_SOURCE_DIR) + "/docs/json-schema.md");
  std::stringstream text;
  text << schema.rdbuf();
  for (const json* object : {&cor, &proved})
    for (const auto& [key, value] : object->items())
      EXPECT_NE(text.str().find("| `" + key + "` |"), std::string::npos) << key << " is not in docs/json-schema.md";
}

TEST(CorProve, TextShowsTheBoundsAndTheRoundedDigits) {
  const auto r = viscor::test::run_cli("cor --model kuwabara_kono --gamma 0.05 --g 1 --digits 30 --prove");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("proven     rebound"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("e in       ["), std::string::npos) << r.out;
  // reference_data/cor_report_grid.csv row 11511 (certified to 33 digits,
  // 5.92146160261239281669938431034917e-01) rounded to 30 digits:
  EXPECT_NE(r.out.find("30 proven correctly rounded digits: 0.592146160261239281669938431035"), std::string::npos)
      << r.out;
}

TEST(CorProve, NotProvableOrPhysicalExits2WithoutOutput) {
  const std::string out = ::testing::TempDir() + "cor_prove_bad.json";
  for (const auto& [args, says] : std::vector<std::pair<std::string, std::string>>{
           {"--alpha 1.4142135623730950488016887242097 --beta 1 --gamma 0.1 --g 0", "1.4142135623730950488016887242097"},
           {"--alpha 1 --beta 1.7320508075688772935274463415058 --gamma 0.1", "1.7320508075688772935274463415058"},
           {"--model linear --m 1 --k 1 --gamma0 0.1 --v0 1 --gravity 9.81", "--prove needs the scaled"}}) {
    std::remove(out.c_str());
    const auto r = viscor::test::run_cli("cor " + args + " --prove -o " + out);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::ifstream(out).good()) << args << ": an output file was written";
  }
  const auto r = viscor::test::run_cli("cor --alpha 1.4142135623730950488016887242097 --beta 1 --gamma 0.1 --prove");
  EXPECT_NE(r.err.find("not provable"), std::string::npos) << r.err;
}

// Exponents whose u = s^Q would need huge series (Q, Q alpha or Q beta past the caps
// the solver has too) are refused before any allocation, naming the exponents.
TEST(ProveCli, ExponentsPastTheRootVariableCapsAreRefused) {
  for (const auto& [law, says] : std::vector<std::pair<std::string, std::string>>{
           {"--alpha 4611686018427387905 --beta 1", "Q alpha = 4611686018427387905"},
           {"--alpha 1000000001/1000000000 --beta 1", "Q = 1000000000"},
           {"--alpha 3/2 --beta 1001/1000", "Q = 1000, Q alpha = 1500, Q beta = 1001"}}) {
    for (const std::string command : {"prove " + law + " --gamma 0.1 --g 0 --digits 20",
                                      "cor " + law + " --gamma 0.1 --g 0 --digits 20 --prove"}) {
      const auto r = viscor::test::run_cli(command);
      EXPECT_EQ(r.status, 2) << command << ": " << r.err;
      EXPECT_NE(r.err.find("not provable"), std::string::npos) << command << ": " << r.err;
      EXPECT_NE(r.err.find(says), std::string::npos) << command << ": " << r.err;
    }
  }
}

TEST(ProveCli, ProvesAStick) {
  const auto r = viscor::test::run_cli("prove --model kuwabara_kono --gamma 0.5 --g 3 --digits 20 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["outcome"], "stick") << r.out;
  EXPECT_EQ(json::parse(r.out)["e_upper"], "0") << r.out;
  const auto text = viscor::test::run_cli("prove --model kuwabara_kono --gamma 0.5 --g 3 --digits 20");
  EXPECT_NE(text.out.find("e in       0 (exact)"), std::string::npos) << text.out;
}

TEST(ProveCli, BadInputExits2WithoutOutput) {
  const std::string out = ::testing::TempDir() + "prove_bad.json";
  for (const std::string args : {"--model tsuji --gamma -1 --g 0", "--model tsuji --gamma 0.1 --g x",
                                 "--alpha 1.4142135623730950488016887242097 --beta 1 --gamma 0.1 --g 0",
                                 "--model tsuji --g 0", "--model tsuji --gamma 0.1 --g 0 --digits 1"}) {
    std::remove(out.c_str());
    const auto r = viscor::test::run_cli("prove " + args + " -o " + out);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(std::ifstream(out).good()) << args << ": an output file was written";
  }
}

// Q alpha = 4 x 4611686018427387905 wraps around 64 bits into alpha = 1: the proof
// would have integrated another equation. Refused, naming the exponent.
TEST(ProveCli, ExponentOverflowIsRefusedNamingTheExponent) {
  const auto r = viscor::test::run_cli("prove --alpha 4611686018427387905 --beta 5/4 --gamma 0.05 --g 0 --digits 20");
  EXPECT_EQ(r.status, 2) << r.err << r.out;
  EXPECT_NE(r.err.find("alpha"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("4611686018427387905"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// prove reads numbers as cor does: what cor refuses, prove refuses; a ball is not
// an exact decimal.
TEST(ProveCli, NumbersAreReadAsEveryOtherSubcommandReadsThem) {
  for (const std::string g : {"--g=--1", "--g=+-1", "--g=-+1", "--g=' 0.5'", "--g='0.5 '", "--g=inf", "--g=0x10"}) {
    const auto prove = viscor::test::run_cli("prove --model tsuji --gamma 0.1 " + g);
    EXPECT_EQ(prove.status, 2) << g << ": " << prove.err << prove.out;
    EXPECT_NE(prove.err.find("parameter g"), std::string::npos) << g << ": " << prove.err;
    const auto cor = viscor::test::run_cli("cor --model tsuji --gamma 0.1 " + g);
    EXPECT_EQ(cor.status, 2) << g << ": " << cor.err;
  }
  const auto ball = viscor::test::run_cli("prove --model tsuji --gamma '[0.05 +/- 1e-25]' --g 0");
  EXPECT_EQ(ball.status, 2) << ball.err << ball.out;
  EXPECT_NE(ball.err.find("exact decimal"), std::string::npos) << ball.err;
  EXPECT_NE(ball.err.find("[0.05 +/- 1e-25]"), std::string::npos) << ball.err;
}

// The fields that read as values hold proven digits only: e is the exact value
// correctly rounded to its proven digits; the ball's midpoint is e_midpoint.
TEST(ProveCli, JsonValuesHoldOnlyProvenDigits) {
  const json j = prove("--model tsuji --gamma 0.3 --g 0 --digits 30");
  ASSERT_EQ(j.value("outcome", ""), "rebound") << j.dump(2);
  for (const std::string name : {"e", "one_minus_e", "contact_time"}) {
    const std::string value = j[name], digits_field = name == "e" ? "proven_digits" : "proven_digits_" + name;
    const int proven = j[digits_field];
    const std::string mantissa = value.substr(0, value.find_first_of("eE"));
    const auto significant = mantissa.find_first_not_of("0.") == std::string::npos
                                 ? 0
                                 : std::count_if(mantissa.begin() + static_cast<long>(mantissa.find_first_not_of("0.")),
                                                 mantissa.end(), [](char c) { return c >= '0' && c <= '9'; });
    EXPECT_LE(significant, proven) << name << " = " << value << ", proven digits " << proven;
    EXPECT_GE(proven, 20) << j.dump(2);
    EXPECT_TRUE(j.contains(name + "_midpoint")) << j.dump(2);
    scoped_precision precision(60);
    const mpfr_real x(value), lower(j[name + "_lower"].get<std::string>()), upper(j[name + "_upper"].get<std::string>());
    const mpfr_real unit = pow(mpfr_real(10), -(proven - 1)) * abs(x);
    EXPECT_TRUE(lower - unit <= x && x <= upper + unit) << name << ": " << value;
  }
}

}  // namespace
