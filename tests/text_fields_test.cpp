// The one reader of separated fields (include/viscor/core/text_fields.hpp): every field,
// empty ones included, so that "a,b," and "a,b" cannot be read alike; and, through the
// readers that use it, a row with a trailing comma is refused, not shortened.
#include <viscor/core/text_fields.hpp>
#include <viscor/jobs/formula_job.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace viscor {
namespace {

using fields = std::vector<std::string>;

TEST(TextFields, EverySeparatorStartsAField) {
  EXPECT_EQ(split_fields("a,b,c"), (fields{"a", "b", "c"}));
  EXPECT_EQ(split_fields("a,,b,"), (fields{"a", "", "b", ""}));
  EXPECT_EQ(split_fields(",a"), (fields{"", "a"}));
  EXPECT_EQ(split_fields(""), (fields{""}));
  EXPECT_EQ(split_fields(" a , b"), (fields{" a ", " b"}));  // nothing trimmed
  EXPECT_EQ(split_fields("x=1;y=2", ';'), (fields{"x=1", "y=2"}));
}

TEST(TextFields, TrimmedFieldsLoseOnlyBlanksAtTheirEnds) {
  EXPECT_EQ(split_trimmed_fields(" a ,\tb c\r, "), (fields{"a", "b c", ""}));
  EXPECT_EQ(split_trimmed_fields("a,"), (fields{"a", ""}));
}

TEST(TextFields, AListRefusesAnEmptyItemNamingItsValue) {
  EXPECT_EQ(split_list("0.1,0.2", "--speeds"), (fields{"0.1", "0.2"}));
  for (const char* bad : {"0.1,,1", ",0.1", "0.1,", ""}) {
    try {
      split_list(bad, "--speeds");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const invalid_parameter& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("--speeds"), std::string::npos) << what;
      EXPECT_NE(what.find(std::string("'") + bad + "'"), std::string::npos) << what;
    }
  }
}

// Before, the values reader split with std::getline, which drops a trailing empty
// field: "0.1,1,0.5," read as the three fields of the header.
TEST(TextFields, AValuesRowWithATrailingCommaIsRefused) {
  EXPECT_NO_THROW(jobs::parse_formula_values("gamma,g,e\n0.1,1,0.5\n", "values.csv"));
  try {
    jobs::parse_formula_values("gamma,g,e\n0.1,1,0.5,\n", "values.csv");
    ADD_FAILURE() << "a row of four fields was read under a header of three";
  } catch (const parse_error& e) {
    EXPECT_NE(std::string(e.what()).find("values.csv:2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace viscor
