// Fuzz target: certified table CSVs (reference_data/*.csv, `viscor table`
// outputs, --resume's .partial files, `table merge` inputs): tables/reference_table.hpp.
// Read both ways (a truncated tail refused, and allowed as --resume allows it).
// Checks beyond "no crash": the canonical text of the rows (table_text, what merge
// writes) reads back to the same rows; every row's fields are its line's text
// between commas; numeric fields read as double are finite and e lies in [0, 1].
#include "fuzz_support.hpp"

#include <viscor/tables/reference_table.hpp>

#include <cmath>

namespace {

using viscor::fuzz::fuzz_require;

void check(const viscor::csv_table& t) {
  for (const auto& row : t.rows) {
    std::string joined;
    for (std::size_t k = 0; k < row.fields.size(); ++k) joined += (k ? "," : "") + row.fields[k];
    fuzz_require(joined == row.text, "fields do not join back to the row: '" + row.text + "'");
    if (t.kind == viscor::table_kind::cor) {
      for (const char* column : {"gamma", "g", "e", "one_minus_e"}) {
        try {
          const double x = viscor::field_value<double>(t, row, column);
          fuzz_require(std::isfinite(x), std::string("a non-finite ") + column + ": '" + row.text + "'");
          if (std::string(column) == "e" || std::string(column) == "one_minus_e")
            fuzz_require(x >= 0 && x <= 1, std::string(column) + " outside [0, 1]: '" + row.text + "'");
        } catch (const viscor::invalid_parameter&) {
          // over- or underflows double: the table keeps the exact text
        }
      }
    }
  }
  try {
    const std::string canonical = viscor::table_text(t.kind, t.rows, "t.csv");
    const viscor::csv_table again = viscor::parse_table(canonical, "canonical.csv");
    fuzz_require(again.rows.size() == t.rows.size() && again.kind == t.kind, "canonical text has other rows");
    fuzz_require(viscor::table_text(again.kind, again.rows, "canonical.csv") == canonical,
                 "canonical text changes when read back");
  } catch (const viscor::parse_error& e) {
    fuzz_require(std::string(e.what()).find("appears twice") != std::string::npos,
                 std::string("the canonical text of an accepted table is refused: ") + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  viscor::fuzz::refusal_or_result([&] { check(viscor::parse_table(text, "t.csv")); });
  viscor::fuzz::refusal_or_result([&] {
    const viscor::csv_table t = viscor::parse_table(text, "t.csv", true);
    fuzz_require(t.truncated_tail == (!text.empty() && text.back() != '\n'), "truncated_tail is wrong");
    check(t);
  });
  return 0;
}
