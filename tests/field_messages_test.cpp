// Messages name inputs by their field names (core/exceptions.hpp): what() and Python
// show the names, the command-line tool its options (src/cli/option_spelling.hpp);
// warnings go through core/warnings.hpp. The expected texts are written out here.
#include <viscor/core/exceptions.hpp>
#include <viscor/core/warnings.hpp>
#include <viscor/jobs/dem_job.hpp>

#include <gtest/gtest.h>

#include <string>

namespace viscor {
namespace {

std::string as_option(const std::string& field) { return "--" + field; }

TEST(FieldMessages, WhatNamesTheFieldAndAFrontEndSpellsIt) {
  const invalid_parameter e("dem needs " VISCOR_FIELD("youngs_modulus") " (Pa), not " VISCOR_FIELD("k"));
  EXPECT_STREQ(e.what(), "dem needs youngs_modulus (Pa), not k");
  EXPECT_EQ(e.spelled(as_option), "dem needs --youngs_modulus (Pa), not --k");
  const invalid_parameter copy = e;  // a copy keeps the marks
  EXPECT_EQ(copy.spelled(as_option), e.spelled(as_option));
  EXPECT_EQ(error(e.marked() + "; " + field_ref("resume")).spelled(as_option),
            "dem needs --youngs_modulus (Pa), not --k; --resume");
}

TEST(FieldMessages, TextWithoutMarksIsUnchanged) {
  const error plain("gamma = 0.1 {not a field} \x1e unmatched");
  EXPECT_STREQ(plain.what(), "gamma = 0.1 {not a field} \x1e unmatched");
  EXPECT_EQ(plain.spelled(as_option), plain.what());
}

TEST(FieldMessages, TheLibrarysOwnMessagesUseNoOptionSpelling) {
  jobs::dem_request q;
  q.code = "lammps", q.damping = "tsuji", q.poisson_ratio = "0.3", q.radius = "1e-3", q.density = "2500";
  q.gravity = "9.81", q.target_e = "0.8", q.v0 = "0.5";
  try {
    (void)jobs::run_dem(q);
    FAIL() << "dem without youngs_modulus was not refused";
  } catch (const invalid_parameter& e) {
    EXPECT_STREQ(e.what(), "dem needs youngs_modulus (Pa)");
    EXPECT_EQ(e.spelled(as_option), "dem needs --youngs_modulus (Pa)");
  }
}

std::string last_warning;
void keep_warning(const std::string& marked) { last_warning = marked; }

TEST(FieldMessages, WarningsGoThroughTheHandler) {
  const warning_handler before = current_warning_handler();
  current_warning_handler() = keep_warning;
  warn("use " VISCOR_FIELD("force"));
  current_warning_handler() = before;
  EXPECT_EQ(detail::spell_fields(last_warning, as_option), "use --force");
  EXPECT_EQ(detail::plain_fields(last_warning), "use force");
}

}  // namespace
}  // namespace viscor
