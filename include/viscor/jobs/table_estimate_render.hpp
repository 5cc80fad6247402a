// A table estimate (jobs/table_estimate.hpp) as readable text and as JSON: `viscor
// table SPEC --estimate` prints the text, Python's viscor.table(..., estimate=True)
// returns the JSON as a Result.
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/table_estimate.hpp>

#include <cstdio>
#include <sstream>
#include <string>

namespace viscor::render {

/// Seconds as "0.42 s", "12 min 5 s" or "3 h 20 min".
inline std::string duration_words(double seconds) {
  char text[64];
  if (seconds < 60) std::snprintf(text, sizeof text, "%.2g s", seconds);
  else if (seconds < 3600) std::snprintf(text, sizeof text, "%d min %d s", int(seconds / 60), int(seconds) % 60);
  else std::snprintf(text, sizeof text, "%d h %d min", int(seconds / 3600), int(seconds / 60) % 60);
  return text;
}

/// Where the estimate's costs come from, for both forms.
inline constexpr const char* estimate_model =
    "CPU time per row measured by law, working digits and table method on a 2-core x86-64 machine "
    "(tools/cost_data/row_cost_by_digits.csv, docs/performance.md \"Cost before work\"); scale by your machine's speed";

/// The JSON object of an estimate.
inline jobs::json table_estimate_json(const jobs::table_estimate& e) {
  jobs::json j;
  j["command"] = "table";
  j["estimate"] = true;
  j["rows"] = e.rows;
  j["rows_total"] = e.rows_total;
  j["shard"] = e.part.whole() ? jobs::json(nullptr) : jobs::json{{"index", e.part.index}, {"count", e.part.count}};
  j["working_digits"] = e.working_digits;
  j["method"] = e.method;
  j["cpu_time_s"] = e.cpu_time_s;
  j["threads"] = e.threads;
  j["wall_time_s"] = e.wall_time_s;
  jobs::json laws = jobs::json::array();
  for (const jobs::law_estimate& l : e.laws)
    laws.push_back({{"law", jobs::law_json(l.law)},
                    {"rows", l.rows},
                    {"cpu_time_per_row_s", l.cpu_time_per_row_s},
                    {"cpu_time_s", l.cpu_time_s}});
  j["laws"] = laws;
  j["model"] = estimate_model;
  return j;
}

/// The readable estimate.
inline std::string table_estimate_text(const jobs::table_estimate& e) {
  std::ostringstream text;
  text << "rows       " << e.rows;
  if (!e.part.whole()) text << " of " << e.rows_total << " (shard " << e.part.to_string() << ")";
  text << "\n"
       << "digits     " << e.working_digits << " working, method " << e.method << "\n";
  for (const jobs::law_estimate& l : e.laws)
    text << "  " << l.law.describe() << ": " << l.rows << " rows x " << duration_words(l.cpu_time_per_row_s) << "\n";
  text << "CPU time   " << duration_words(e.cpu_time_s) << " (expected)\n"
       << "wall time  " << duration_words(e.wall_time_s) << " at " << e.threads << " thread" << (e.threads == 1 ? "" : "s")
       << "\n";
  if (!e.part.whole())
    text << "           every shard of " << e.part.count << " at once, on its own machine: about "
         << duration_words(e.wall_time_s) << " each\n";
  text << "model      " << estimate_model << "\n";
  return text.str();
}

}  // namespace viscor::render
