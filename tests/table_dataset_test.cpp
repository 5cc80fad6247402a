// A table as a gridded dataset (jobs/table_dataset.hpp) and its NetCDF form
// (jobs/netcdf_file.hpp): decimals to doubles rounded as asked (checked against MPFR
// at 1000 bits), every row at its grid point, and what is not a whole CoR grid
// refused. The round trip through xarray is tests/python/test_xarray.py.
#include <viscor/jobs/netcdf_file.hpp>
#include <viscor/jobs/table_dataset.hpp>
#include <viscor/jobs/table_jobs.hpp>

#include "certified_claims.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <cfenv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace {

using namespace viscor;

// Where a decimal lies against a double, decided by MPFR at 1000 bits (exact for
// the decimals drawn here): -1, 0 or 1 as decimal <, =, > value.
int compare_decimal(const std::string& decimal, double value) {
  mpfr_t x;
  mpfr_init2(x, 1000);
  mpfr_set_str(x, decimal.c_str(), 10, MPFR_RNDN);
  const int c = mpfr_cmp_d(x, value);
  mpfr_clear(x);
  return c > 0 ? 1 : c < 0 ? -1 : 0;
}

TEST(TableDataset, DecimalsBecomeDoublesRoundedAsAsked) {
  std::mt19937_64 random(20261207);
  std::uniform_int_distribution<int> digit(0, 9), exponent(-30, 30), length(1, 40);
  int judged = 0, inexact = 0;
  for (int k = 0; k < 2000; ++k) {
    std::string text = std::to_string(1 + digit(random) % 9) + ".";
    for (int n = length(random); n > 0; --n) text += static_cast<char>('0' + digit(random));
    text += "e" + std::to_string(exponent(random));
    const double down = jobs::decimal_to_double(text, jobs::rounding::down);
    const double up = jobs::decimal_to_double(text, jobs::rounding::up);
    const double nearest = jobs::decimal_to_double(text, jobs::rounding::nearest);
    ASSERT_LE(compare_decimal(text, up), 0) << text;  // bounds stay bounds
    ASSERT_GE(compare_decimal(text, down), 0) << text;
    ASSERT_GT(compare_decimal(text, std::nextafter(up, -INFINITY)), 0) << text;  // and are the tightest
    ASSERT_LT(compare_decimal(text, std::nextafter(down, INFINITY)), 0) << text;
    ASSERT_TRUE(nearest == down || nearest == up) << text;
    inexact += down != up;
    ++judged;
  }
  EXPECT_EQ(judged, 2000);
  EXPECT_GT(inexact, 1500);  // most draws are not doubles: the directions were tested
  EXPECT_EQ(jobs::decimal_to_double("0.5", jobs::rounding::down), 0.5);
  EXPECT_TRUE(std::isinf(jobs::decimal_to_double("inf", jobs::rounding::nearest)));
  EXPECT_TRUE(std::isnan(jobs::decimal_to_double("", jobs::rounding::up)));
  EXPECT_THROW(jobs::decimal_to_double("0.5x", jobs::rounding::nearest), parse_error);
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);  // the caller's rounding mode is back
}

std::string text_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct made_table {
  std::string table, sidecar;
};

made_table make(const std::filesystem::path& dir, const std::string& name, const shard& part = {}) {
  jobs::table_run_options run;
  run.output = (dir / name).string();
  run.threads = 2;
  run.quiet = true;
  run.part = part;
  jobs::make_cor_table(jobs::parse_spec_json(R"({"laws": ["linear", {"alpha": "3/2", "beta": "13/10"}], "gamma": [0.1, 0.2, 0.3],
                                                 "g": [0, 1], "digits": 20})",
                                             "spec.json"),
                       run);
  return {text_of(run.output), text_of(run.output + ".json")};
}

TEST(TableDataset, EveryRowIsAtItsGridPoint) {
  test::scratch_dir dir("table_dataset");
  const made_table t = make(dir.path, "t.csv");
  const jobs::table_dataset d = jobs::table_dataset_of(t.table, t.sidecar, "t.csv");
  ASSERT_EQ(d.dimensions.size(), 3u);
  EXPECT_EQ(d.dimensions[0], (std::pair<std::string, std::size_t>{"law", 2}));
  EXPECT_EQ(d.dimensions[1], (std::pair<std::string, std::size_t>{"g", 2}));
  EXPECT_EQ(d.dimensions[2], (std::pair<std::string, std::size_t>{"gamma", 3}));
  const auto variable = [&](const std::string& name) -> const jobs::dataset_array& {
    for (const auto& v : d.variables)
      if (v.name == name) return v;
    throw std::runtime_error("no variable " + name);
  };
  // The table's rows are in grid order (laws as listed, g, then gamma ascending,
  // docs/tables.md): row k is cell k.
  const auto rows = test::read_named_rows((dir.path / "t.csv").string());
  ASSERT_EQ(rows.size(), 12u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(variable("e_exact").texts[k], rows[k].at("e"));
    EXPECT_EQ(variable("e").numbers[k], std::stod(rows[k].at("e")));
    EXPECT_EQ(variable("outcome").texts[k], rows[k].at("outcome"));
    EXPECT_EQ(variable("certified_digits").integers[k], std::stoi(rows[k].at("digits")));
  }
  for (const auto& v : d.variables) EXPECT_NE(v.name, "e_lower");  // not a proven table
  ASSERT_EQ(d.coordinates[0].name, "law");
  EXPECT_EQ(d.coordinates[0].texts[0], "linear");
  EXPECT_EQ(d.coordinates[0].texts[1], "alpha=" + rows[6].at("alpha") + " beta=" + rows[6].at("beta"));  // no name
  if (!jobs::netcdf_available()) GTEST_SKIP() << "this build writes no NetCDF";
  const std::string bytes = jobs::netcdf_file_bytes(d);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89HDF\r\n\x1a\n", 8));  // NetCDF-4 is HDF5
}

TEST(TableDataset, WhatIsNotAWholeCorGridIsRefused) {
  test::scratch_dir dir("table_dataset");
  const made_table whole = make(dir.path, "t.csv");
  // A row gone: the grid has a hole.
  std::string holed = whole.table;
  const std::size_t second = holed.find('\n', holed.find('\n') + 1);
  holed.erase(holed.find('\n') + 1, second - holed.find('\n'));
  try {
    jobs::table_dataset_of(holed, whole.sidecar, "t.csv");
    ADD_FAILURE() << "a table with a hole was taken";
  } catch (const parse_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a complete grid"), std::string::npos) << e.what();
  }
  // A shard.
  const made_table part = make(dir.path, "s.csv", shard::parse("0/2"));
  try {
    jobs::table_dataset_of(part.table, part.sidecar, "s.csv");
    ADD_FAILURE() << "a shard was taken";
  } catch (const parse_error& e) {
    EXPECT_NE(std::string(e.what()).find("merge the shards first"), std::string::npos) << e.what();
  }
  // A sidecar that is not one.
  EXPECT_THROW(jobs::table_dataset_of(whole.table, "[1, 2", "t.csv"), parse_error);
  // A run asked for its NetCDF form as a shard stops before writing anything.
  jobs::table_run_options run;
  run.output = (dir.path / "n.csv").string();
  run.part = shard::parse("1/2");
  run.netcdf = true;
  run.quiet = true;
  EXPECT_THROW(jobs::make_cor_table(jobs::parse_spec_json(R"({"laws": ["linear"], "gamma": [0.1], "g": [0],
                                                              "digits": 20})",
                                                          "spec.json"),
                                    run),
               invalid_parameter);
  EXPECT_FALSE(std::filesystem::exists(run.output));
  EXPECT_FALSE(std::filesystem::exists(dir.path / "n.nc"));
}

}  // namespace
