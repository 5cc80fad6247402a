// Contact-law exponents are validated exactly, as the rational or decimal
// they were read as. 0.99999999999999999999999 is below 1 although it rounds to 1 in
// long double (where it used to be compared).
#include "test_utils.hpp"

#include <viscor/core/contact_law.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace viscor {
namespace {

TEST(ExponentValidation, JustBelowOneIsRefusedExactly) {
  for (const char* text : {"0.99999999999999999999999", "0.9999999999999999999999999999999999999999999999999",
                           "99999999999999999999999e-23", "999999999/1000000000"}) {
    SCOPED_TRACE(text);
    const exponent x = exponent::parse(text, "alpha");
    EXPECT_FALSE(x.at_least_one());
    try {
      make_law(x, exponent::rational(1, 1));
      ADD_FAILURE() << "accepted alpha = " << text;
    } catch (const invalid_parameter& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
    EXPECT_THROW(make_law(exponent::rational(3, 2), x), invalid_parameter);
  }
  for (const char* text : {"1", "1.00000000000000000000001", "1e0", "10e-1", "1000000001/1000000000", "3/2"}) {
    SCOPED_TRACE(text);
    EXPECT_TRUE(exponent::parse(text, "alpha").at_least_one());
    EXPECT_NO_THROW(make_law(exponent::parse(text, "alpha"), exponent::parse(text, "beta")));
  }
}

TEST(ExponentValidation, CliRefusesAlphaJustBelowOne) {
  const std::string out = ::testing::TempDir() + "viscor_alpha_below_one.json";
  std::filesystem::remove(out);
  const auto r = test::run_cli("cor --alpha 0.99999999999999999999999 --beta 1 --gamma 0.1 --g 0 -o " + out);
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("0.99999999999999999999999"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace viscor
