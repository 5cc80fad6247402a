// A CoR table as a gridded dataset (include/viscor/jobs/table_dataset.hpp).
#include <viscor/jobs/table_dataset.hpp>

#include <viscor/core/checksums.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/sha256.hpp>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cfenv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <string>

namespace viscor::jobs {

namespace {


// The columns of a CoR table (tables/reference_table.hpp, jobs/table_format.hpp).
enum cor_column : std::size_t {
  law_col = 1, alpha_col, beta_col, gamma_col, g_col, outcome_col, e_col, one_minus_e_col, contact_time_col,
  max_compression_col, certified_digits_col, method_col,
  e_lower_col, e_upper_col, one_minus_e_lower_col, one_minus_e_upper_col, proven_digits_col, outcome_proven_col
};

// The values of one axis in the order rows first give them, each once.
struct axis {
  std::vector<std::string> values;
  std::map<std::string, std::size_t> position;
  std::size_t add(const std::string& v) {
    const auto [it, added] = position.emplace(v, values.size());
    if (added) values.push_back(v);
    return it->second;
  }
};

struct number_column {
  cor_column column;
  const char* name;
  const char* long_name;
  rounding direction;
};

// Every number of a CoR row, with what it means; the scaled model has no units.
constexpr number_column cor_numbers[] = {
    {e_col, "e", "coefficient of restitution", rounding::nearest},
    {one_minus_e_col, "one_minus_e", "1 - e, computed without cancellation", rounding::nearest},
    {contact_time_col, "contact_time", "contact time T_f (scaled; for a stick, the time the bead stops separating)",
     rounding::nearest},
    {max_compression_col, "max_compression", "maximal compression u_max (scaled)", rounding::nearest},
};
constexpr number_column proven_numbers[] = {
    {e_lower_col, "e_lower", "proven lower bound of e", rounding::down},
    {e_upper_col, "e_upper", "proven upper bound of e", rounding::up},
    {one_minus_e_lower_col, "one_minus_e_lower", "proven lower bound of 1 - e", rounding::down},
    {one_minus_e_upper_col, "one_minus_e_upper", "proven upper bound of 1 - e", rounding::up},
};

const char* rounding_note(rounding r) {
  switch (r) {
    case rounding::nearest: return "the exact decimal (variable NAME_exact) rounded to the nearest double";
    case rounding::down: return "the exact decimal bound (variable NAME_exact) rounded down: still a bound";
    case rounding::up: return "the exact decimal bound (variable NAME_exact) rounded up: still a bound";
  }
  return "";
}

std::string with_name(std::string note, const std::string& name) {
  note.replace(note.find("NAME"), 4, name);
  return note;
}

dataset_array text_array(std::string name, std::vector<std::string> dims, std::string long_name) {
  dataset_array a;
  a.name = std::move(name);
  a.dims = std::move(dims);
  a.kind = dataset_array::type::text;
  a.attributes = {{"long_name", std::move(long_name)}};
  return a;
}

dataset_array number_array(std::string name, std::vector<std::string> dims, std::string long_name) {
  dataset_array a = text_array(std::move(name), std::move(dims), std::move(long_name));
  a.kind = dataset_array::type::float64;
  a.attributes.emplace_back("units", "1");
  return a;
}

std::string text_of(const json& j) { return j.is_string() ? j.get<std::string>() : j.dump(); }

// The sidecar's provenance as attributes: what made the table, and checksums of both files.
std::vector<std::pair<std::string, dataset_attribute>> provenance(const json& sidecar, const std::string& table_text,
                                                                  const std::string& sidecar_text,
                                                                  const std::string& table_name) {
  std::vector<std::pair<std::string, dataset_attribute>> a;
  a.emplace_back("title", "viscor CoR table " + std::filesystem::path(table_name).filename().string());
  a.emplace_back("Conventions", "CF-1.8");
  a.emplace_back("source", "viscor " + text_of(sidecar.value("viscor_version", json("unknown"))));
  for (const char* key : {"viscor_version", "git_commit", "date", "command_line"})
    if (sidecar.contains(key)) a.emplace_back(key, text_of(sidecar[key]));
  if (sidecar.contains("method") && sidecar["method"].contains("requested"))
    a.emplace_back("method", text_of(sidecar["method"]["requested"]));
  if (sidecar.contains("scalar")) {
    const json& s = sidecar["scalar"];
    if (s.contains("type")) a.emplace_back("scalar_type", text_of(s["type"]));
    if (s.contains("decimal_digits") && s["decimal_digits"].is_number_integer())
      a.emplace_back("working_digits", s["decimal_digits"].get<std::int64_t>());
  }
  if (sidecar.contains("method") && sidecar["method"].contains("certified_digits") &&
      sidecar["method"]["certified_digits"].contains("goal"))
    a.emplace_back("certified_digits_goal", sidecar["method"]["certified_digits"]["goal"].get<std::int64_t>());
  a.emplace_back("spec", sidecar.contains("spec") ? sidecar["spec"].dump() : std::string("{}"));
  a.emplace_back("rows", sidecar.value("rows", std::int64_t{0}));
  a.emplace_back("table_sha256", sha256_hex(table_text));
  a.emplace_back("sidecar_sha256", sha256_hex(sidecar_text));
  a.emplace_back("sidecar", sidecar_text);
  return a;
}

}  // namespace

double decimal_to_double(const std::string& text, rounding direction) {
  if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
  // glibc's strtod rounds correctly in the current rounding mode.
  const int saved = std::fegetround();
  std::fesetround(direction == rounding::down ? FE_DOWNWARD : direction == rounding::up ? FE_UPWARD : FE_TONEAREST);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  std::fesetround(saved);
  if (end != text.c_str() + text.size()) throw parse_error("not a decimal number: '" + text + "'");
  return value;
}

table_dataset table_dataset_of(const std::string& table_text, const std::string& sidecar_text,
                               const std::string& table_name) {
  const table_format format = table_format::of_text(table_text);
  if (format.kind != table_kind::cor)
    throw parse_error(table_name + ": a sticking-threshold table has no (law, g, gamma) grid of e; the dataset form "
                      "is for CoR tables");
  if (format.physical)
    throw parse_error(table_name + ": a table from a spec in SI has no (law, g, gamma) grid; its dataset form is "
                      "not written yet (read its columns with Table.column)");
  const csv_table table = format.parse(table_text, table_name);
  json sidecar;
  try {
    sidecar = json::parse(sidecar_text);
  } catch (const json::exception& e) {
    throw parse_error(table_name + ".json: not a viscor sidecar: " + e.what());
  }
  if (!sidecar.is_object()) throw parse_error(table_name + ".json: not a viscor sidecar (not a JSON object)");
  if (sidecar.contains("shard") && !sidecar["shard"].is_null())
    throw parse_error(table_name + ": a shard (" + sidecar["shard"].dump() +
                      ") is not the whole grid: merge the shards first (viscor table merge)");

  axis laws, gs, gammas;  // a law is its name and exponents (a law of the spec's own has no name)
  struct placed {
    std::size_t law, g, gamma;
  };
  std::vector<placed> cells;
  std::vector<const csv_record*> law_rows;  // a row of each law
  for (const csv_record& row : table.rows) {
    const std::size_t law = laws.add(row.fields[law_col] + "," + row.fields[alpha_col] + "," + row.fields[beta_col]);
    if (law == law_rows.size()) law_rows.push_back(&row);
    cells.push_back({law, gs.add(row.fields[g_col]), gammas.add(row.fields[gamma_col])});
  }
  const std::size_t n_law = laws.values.size(), n_g = gs.values.size(), n_gamma = gammas.values.size();
  const std::size_t cells_total = n_law * n_g * n_gamma;
  if (table.rows.empty() || table.rows.size() != cells_total)
    throw parse_error(table_name + ": " + std::to_string(table.rows.size()) + " rows over " + std::to_string(n_law) +
                      " laws x " + std::to_string(n_g) + " g x " + std::to_string(n_gamma) +
                      " gamma: not a complete grid (a shard, or a table of points)");
  std::vector<std::size_t> row_of(cells_total, table.rows.size());
  for (std::size_t r = 0; r < cells.size(); ++r) {
    const std::size_t cell = (cells[r].law * n_g + cells[r].g) * n_gamma + cells[r].gamma;
    if (row_of[cell] != table.rows.size())
      throw parse_error(table_name + ":" + std::to_string(table.rows[r].line) + ": a second row for one grid point");
    row_of[cell] = r;
  }

  table_dataset d;
  d.dimensions = {{"law", n_law}, {"g", n_g}, {"gamma", n_gamma}};
  dataset_array law = text_array("law", {"law"}, "contact law (a law without a name: alpha=A beta=B)");
  dataset_array alpha = text_array("alpha", {"law"}, "elastic exponent alpha (exact)");
  dataset_array beta = text_array("beta", {"law"}, "dissipative exponent beta (exact)");
  for (const csv_record* row : law_rows) {
    const std::string& name = row->fields[law_col];
    law.texts.push_back(!name.empty() ? name : "alpha=" + row->fields[alpha_col] + " beta=" + row->fields[beta_col]);
    alpha.texts.push_back(row->fields[alpha_col]);
    beta.texts.push_back(row->fields[beta_col]);
  }
  d.coordinates = {law, alpha, beta};
  const auto add_axis = [&](const axis& values, const std::string& name, const std::string& long_name) {
    dataset_array numbers = number_array(name, {name}, long_name);
    numbers.attributes.emplace_back("comment", with_name(rounding_note(rounding::nearest), name));
    dataset_array exact = text_array(name + "_exact", {name}, long_name + " (the exact decimal input)");
    for (const std::string& v : values.values) {
      numbers.numbers.push_back(decimal_to_double(v, rounding::nearest));
      exact.texts.push_back(v);
    }
    d.coordinates.push_back(std::move(numbers));
    d.coordinates.push_back(std::move(exact));
  };
  add_axis(gs, "g", "scaled load g");
  add_axis(gammas, "gamma", "scaled damping gamma");

  const std::vector<std::string> grid{"law", "g", "gamma"};
  const auto add_numbers = [&](const number_column& c) {
    dataset_array numbers = number_array(c.name, grid, c.long_name);
    numbers.attributes.emplace_back("comment", with_name(rounding_note(c.direction), c.name));
    dataset_array exact = text_array(std::string(c.name) + "_exact", grid, std::string(c.long_name) +
                                                                               " (the table's exact decimal; empty: "
                                                                               "not available)");
    for (std::size_t r : row_of) {
      const std::string& v = table.rows[r].fields[c.column];
      numbers.numbers.push_back(decimal_to_double(v, c.direction));
      exact.texts.push_back(v);
    }
    d.variables.push_back(std::move(numbers));
    d.variables.push_back(std::move(exact));
  };
  const auto add_texts = [&](cor_column column, const char* name, const char* long_name) {
    dataset_array a = text_array(name, grid, long_name);
    for (std::size_t r : row_of) a.texts.push_back(table.rows[r].fields[column]);
    d.variables.push_back(std::move(a));
  };
  const auto add_digits = [&](cor_column column, const char* name, const char* long_name) {
    dataset_array a = text_array(name, grid, long_name);
    a.kind = dataset_array::type::int32;
    a.attributes.emplace_back("comment", "-1: not available");
    for (std::size_t r : row_of) {
      const std::string& v = table.rows[r].fields[column];
      a.integers.push_back(v.empty() ? -1 : static_cast<std::int32_t>(std::stol(v)));
    }
    d.variables.push_back(std::move(a));
  };
  for (const number_column& c : cor_numbers) add_numbers(c);
  add_texts(outcome_col, "outcome", "rebound or stick");
  add_digits(certified_digits_col, "certified_digits", "certified significant digits of the row's values");
  add_texts(method_col, "method", "exact (closed form) or certified");
  if (format.proven) {
    for (const number_column& c : proven_numbers) add_numbers(c);
    add_digits(proven_digits_col, "proven_digits", "correctly rounded significant digits of e both bounds prove");
    add_texts(outcome_proven_col, "outcome_proven", "rebound, stick or undecided, as the proof decides");
  }
  d.attributes = provenance(sidecar, table_text, sidecar_text, table_name);
  return d;
}

table_dataset read_table_dataset(const std::string& table_path) {
  const std::string table_text = read_checked_file<parse_error>(table_path, "table");
  const std::string sidecar_text = read_checked_file<parse_error>(table_path + ".json", "table sidecar");
  return table_dataset_of(table_text, sidecar_text, table_path);
}

}  // namespace viscor::jobs
