// Fuzz target: proven table CSVs (reference_data/proven/*.csv, `viscor table` with
// "method": "proven"): include/viscor/jobs/table_format.hpp, on top of the certified rows'
// checks. Checks beyond "no crash": every accepted row keeps its full line, its
// CoR columns are a valid certified row, and the canonical text reads back alike.
#include "fuzz_support.hpp"

#include <viscor/jobs/table_format.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using viscor::fuzz::fuzz_require;
  if (size > 65536) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  for (const bool allow_tail : {false, true}) {
    viscor::fuzz::refusal_or_result([&] {
      const viscor::csv_table t = viscor::jobs::parse_proven_table(text, "p.csv", allow_tail);
      const std::size_t columns = viscor::jobs::proven_table_columns().size();
      for (const auto& row : t.rows) {
        fuzz_require(row.fields.size() == columns, "an accepted proven row has another number of fields");
        std::string joined;
        for (std::size_t k = 0; k < row.fields.size(); ++k) joined += (k ? "," : "") + row.fields[k];
        fuzz_require(joined == row.text, "fields do not join back to the row: '" + row.text + "'");
      }
      try {
        std::string canonical = viscor::jobs::proven_table_header() + "\n";
        std::vector<viscor::csv_record> rows = t.rows;
        std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
        for (const auto& r : rows) canonical += r.text + "\n";
        const viscor::csv_table again = viscor::jobs::parse_proven_table(canonical, "canonical.csv");
        fuzz_require(again.rows.size() == t.rows.size(), "canonical text has other rows");
      } catch (const viscor::parse_error& e) {
        fuzz_require(false, std::string("the canonical text of an accepted proven table is refused: ") + e.what());
      }
    });
  }
  return 0;
}
