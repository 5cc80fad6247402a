// `viscor prove` (src/cli/cmd_prove.cpp, issue 17): its enclosures contain the
// closed forms (Tsuji at g = 0, the linear law under load; exact/ in MPFR at 60
// digits, not the proof), its JSON uses the names of docs/json-schema.md, and bad input exits 2
// with a message naming the value and no output file.
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/exact/exact_linear.hpp>
#include <viscor/exact/exact_tsuji.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

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

TEST(ProveCli, EnclosesTheClosedForms) {
  scoped_precision precision(60);
  const json tsuji = prove("--model tsuji --gamma 0.3 --g 0 --digits 30");
  ASSERT_EQ(tsuji["outcome"], "rebound") << tsuji.dump(2);
  const auto tsuji_exact = exact_tsuji(mpfr_real("0.3"));  // no contact time: mapped in the phase plane
  EXPECT_TRUE(encloses(tsuji["enclosure"]["e"], tsuji_exact.e)) << tsuji.dump(2);
  EXPECT_TRUE(encloses(tsuji["enclosure"]["one_minus_e"], tsuji_exact.one_minus_e)) << tsuji.dump(2);
  EXPECT_GE(tsuji["proven_digits"]["e"].get<int>(), 30);

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
  for (const json* object : {&linear, &linear["enclosure"], &linear["proven_digits"], &linear["precision"]})
    for (const auto& [key, value] : object->items())
      EXPECT_NE(text.str().find("| `" + key + "` |"), std::string::npos) << key << " is not in docs/json-schema.md";
}

TEST(ProveCli, ProvesAStick) {
  const auto r = viscor::test::run_cli("prove --model kuwabara_kono --gamma 0.5 --g 3 --digits 20 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["outcome"], "stick") << r.out;
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

}  // namespace
