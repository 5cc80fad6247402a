// The committed proven tables: reference_data/proven/NAME.csv holds,
// for every row of the committed certified table reference_data/NAME.csv (the report
// grid and the other committed CoR tables), the enclosure of e and of 1 - e proven by
// viscor::enclose (validated Taylor integration in Arb balls) and its proven outcome.
// Checked here, file against file: the two tables have the same rows; every proven
// outcome is the certified one (none is undecided); every certified e and 1 - e lies within one unit of
// its last certified digit of the enclosure (the certified claim, tested by a proof
// that is not a certification: no shared integrator, no agreement rule); and
// proven_digits >= certified digits - 2 (the acceptance). The counts of
// rows whose certified value is the correctly rounded one (within half a unit) are
// printed; docs/proofs.md reports them. reference_data/proven/digits50/ holds the report
// grid proven at 50 digits: the same checks, and the tightness target (below).
#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/tables/reference_table.hpp>

#include "certified_claims.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace viscor;
using viscor::test::check_claim;
using viscor::test::claim;
using viscor::test::read_named_rows;
using number = viscor::test::claim_number;

const std::string data = std::string(VISCOR_SOURCE_DIR) + "/reference_data/";

/// The committed proven tables, by path under reference_data/proven/: NAME.csv (proven at
/// the certified table's digits) and digitsD/NAME.csv (the same rows proven at D digits).
std::vector<std::string> proven_tables() {
  std::vector<std::string> names;
  const std::filesystem::path root = data + "proven";
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
    if (entry.path().extension() == ".csv") names.push_back(entry.path().lexically_relative(root).generic_string());
  std::sort(names.begin(), names.end());
  return names;
}

/// The certified table that a proven table proves: reference_data/NAME.csv.
std::string certified_table(const std::string& proven_path) {
  return data + std::filesystem::path(proven_path).filename().string();
}

TEST(ProvenTablesCommitted, TheReportGridIsAmongThem) {
  const auto names = proven_tables();
  EXPECT_NE(std::find(names.begin(), names.end(), "cor_report_grid.csv"), names.end());
}

// The tightness target: at 50 digits the relative width of e is at most
// 1e-40 on the well-conditioned points of the report grid. Checked on every rebound
// of the committed 50-digit proof of the grid with e >= 1e-10 (smaller e next to the
// sticking threshold: an absolute width of the exit speed of ~1e-52 is a relative
// one of 1e-52 / e; docs/proofs.md counts them).
TEST(ProvenTablesCommitted, TheReportGridAt50DigitsIsTight) {
  const auto rows = read_named_rows(data + "proven/digits50/cor_report_grid.csv");
  ASSERT_EQ(rows.size(), 15015u) << "reference_data/proven/digits50/cor_report_grid.csv";
  const number limit("1e-40"), well_conditioned("1e-10");
  std::map<std::string, int> counts;
  for (const auto& row : rows) {
    if (row.at("outcome_proven") != "rebound") {
      ++counts[row.at("outcome_proven")];
      continue;
    }
    const number lo = parse_real<number>(row.at("e_lower"), "e_lower"), hi = parse_real<number>(row.at("e_upper"), "e_upper");
    const bool tight = (hi - lo) <= limit * lo;
    ++counts[std::string(tight ? "rebound, relative width <= 1e-40" : "rebound, wider")];
    if (lo >= well_conditioned)
      EXPECT_TRUE(tight) << "row " << row.at("index") << " (" << row.at("law") << ", gamma " << row.at("gamma") << ", g "
                         << row.at("g") << "): e in [" << row.at("e_lower") << ", " << row.at("e_upper") << "]";
  }
  for (const auto& [what, n] : counts) std::cout << "  digits50/cor_report_grid.csv: " << what << ": " << n << " rows\n";
}

class ProvenTables : public ::testing::TestWithParam<std::string> {};

TEST_P(ProvenTables, EveryCertifiedRowIsConfirmedByItsProof) {
  const csv_table certified = read_table(certified_table(GetParam()));
  const auto proven = read_named_rows(data + "proven/" + GetParam());
  ASSERT_EQ(proven.size(), certified.rows.size()) << "reference_data/proven/" << GetParam();
  const std::vector<std::string>& columns = table_columns(table_kind::cor);
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < proven.size(); ++i) {
    const csv_record& c = certified.rows[i];
    auto field = [&](const std::string& name) {
      for (std::size_t k = 0; k < columns.size(); ++k)
        if (columns[k] == name) return c.fields[k];
      return std::string();
    };
    const auto& p = proven[i];
    SCOPED_TRACE("row " + field("index") + ": " + field("law") + ", gamma " + field("gamma") + ", g " + field("g"));
    for (const char* key : {"index", "law", "gamma", "g"}) ASSERT_EQ(p.at(key), field(key)) << key;
    ++counts["proven " + p.at("outcome_proven")];
    // Every committed row is decided (the sticks next to the threshold, undecided until
    // the proof's way out went back to tau, included), and as certified.
    EXPECT_EQ(p.at("outcome_proven"), field("outcome"));
    if (p.at("outcome_proven") == "undecided") continue;
    const int digits = std::stoi(field("digits"));
    EXPECT_GE(std::stoi(p.at("proven_digits")), digits - 2);
    for (const auto& [value, lower, upper] :
         {std::tuple<const char*, const char*, const char*>{"e", "e_lower", "e_upper"},
          {"one_minus_e", "one_minus_e_lower", "one_minus_e_upper"}}) {
      const claim k = check_claim(field(value), p.at(lower), p.at(upper));
      EXPECT_NE(k, claim::wrong) << value << " = " << field(value) << " (" << digits << " digits), proven in ["
                                 << p.at(lower) << ", " << p.at(upper) << "]";
      ++counts[std::string(value) + (k == claim::exact_inside        ? " exact, inside the enclosure"
                                     : k == claim::correctly_rounded ? " correctly rounded"
                                                                     : " within a unit")];
    }
  }
  for (const auto& [what, n] : counts) std::cout << "  " << GetParam() << ": " << what << ": " << n << " rows\n";
}

INSTANTIATE_TEST_SUITE_P(Committed, ProvenTables, ::testing::ValuesIn(proven_tables()),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.size() - 4);
                           std::replace(name.begin(), name.end(), '/', '_');
                           return name;
                         });

}  // namespace
