// A certified decimal against a proven enclosure of the same quantity: the claim of a
// certified digit checked by a method that shares nothing with certification (Arb's
// validated integration, reference_data/proven/). Used by proven_tables_test and
// certified_digits_goal_test.
#pragma once

#include <viscor/core/real_io.hpp>
#include <viscor/core/real_types.hpp>
#include <viscor/core/text_fields.hpp>

#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace viscor::test {

using claim_number = mpfr_100;  // the tables carry at most 50 digits; bounds compared exactly enough

/// A CSV file as rows of named fields (the proven columns are not the library's format).
inline std::vector<std::map<std::string, std::string>> read_named_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::map<std::string, std::string>> rows;
  if (!in) return rows;
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> names = split_fields(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split_fields(line);
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < names.size() && i < fields.size(); ++i) row[names[i]] = fields[i];
    rows.push_back(std::move(row));
  }
  return rows;
}

/// One unit of the last printed digit of a decimal in scientific notation
/// ("9.9984e-01" -> 1e-4); 0 for an exact value printed without an exponent ("1", "0").
inline claim_number last_digit_unit(const std::string& text) {
  const auto e = text.find('e');
  if (e == std::string::npos) return 0;
  const std::string mantissa = text.substr(0, e);
  const int printed = static_cast<int>(mantissa.size()) - (mantissa.find('.') == std::string::npos ? 0 : 1) -
                      (mantissa[0] == '-' ? 1 : 0);
  return pow(claim_number(10), std::stoi(text.substr(e + 1)) - (printed - 1));
}

/// Where a certified value sits against its enclosure [lower, upper].
enum class claim { exact_inside, correctly_rounded, within_a_unit, wrong };

inline claim check_claim(const std::string& certified, const std::string& lower, const std::string& upper) {
  const claim_number x = parse_real<claim_number>(certified, "certified"), unit = last_digit_unit(certified);
  const claim_number lo = parse_real<claim_number>(lower, "lower"), hi = parse_real<claim_number>(upper, "upper");
  if (unit == 0) return lo <= x && x <= hi ? claim::exact_inside : claim::wrong;  // e = 1 at gamma = 0, e = 0 of a stick
  if (lo >= x - unit / 2 && hi <= x + unit / 2) return claim::correctly_rounded;
  if (lo >= x - unit && hi <= x + unit) return claim::within_a_unit;
  return claim::wrong;
}

}  // namespace viscor::test
