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

// Sets the units of a number_array; none for a quantity without CF units (N/m^alpha).
void with_units(dataset_array& a, const std::string& units) {
  if (units.empty()) a.attributes.pop_back();
  else a.attributes.back().second = units;
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

namespace {

// A dimension of the dataset: the columns whose fields name a position on it, the
// positions in the order rows first give them, and a row at each position.
struct dimension {
  std::string name;
  std::vector<std::size_t> columns;
  axis positions;
  std::vector<const csv_record*> first_rows;
};

// The row of each cell of the grid the dimensions span (outermost first), in cell
// order; refuses a table that is not a complete grid, or that fills a cell twice.
std::vector<std::size_t> place_rows(const csv_table& table, std::vector<dimension>& dims,
                                    const std::string& table_name) {
  std::vector<std::vector<std::size_t>> at(table.rows.size());
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    for (dimension& d : dims) {
      std::string key;
      for (std::size_t c : d.columns) key += table.rows[r].fields[c] + ",";
      const std::size_t p = d.positions.add(key);
      if (p == d.first_rows.size()) d.first_rows.push_back(&table.rows[r]);
      at[r].push_back(p);
    }
  std::size_t cells_total = 1;
  std::string shape;
  for (const dimension& d : dims) {
    cells_total *= d.positions.values.size();
    shape += (shape.empty() ? "" : " x ") + std::to_string(d.positions.values.size()) + " " + d.name;
  }
  if (table.rows.empty() || table.rows.size() != cells_total)
    throw parse_error(table_name + ": " + std::to_string(table.rows.size()) + " rows over " + shape +
                      ": not a complete grid (a shard, or a table of points)");
  std::vector<std::size_t> row_of(cells_total, table.rows.size());
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    std::size_t cell = 0;
    for (std::size_t k = 0; k < dims.size(); ++k) cell = cell * dims[k].positions.values.size() + at[r][k];
    if (row_of[cell] != table.rows.size())
      throw parse_error(table_name + ":" + std::to_string(table.rows[r].line) + ": a second row for one grid point");
    row_of[cell] = r;
  }
  return row_of;
}

// The columns of a table in SI after the CoR ones (table_format.hpp, physical_columns).
constexpr std::size_t si = 13;  // the first physical column
enum si_column : std::size_t {
  bead_col = si, m_col, k_col, youngs_modulus_col, poisson_ratio_col, radius_col, density_col, contact_col, wall_col,
  wall_youngs_modulus_col, wall_poisson_ratio_col, other_youngs_modulus_col, other_poisson_ratio_col,
  other_radius_col, other_density_col, v0_col, gamma0_col, target_e_col, gravity_col, force_col,
  contact_time_s_col, max_compression_m_col
};

// An SI number of the rows or of an axis: its column, name, meaning and CF units.
struct si_number {
  std::size_t column;
  const char* name;
  const char* long_name;
  const char* units;
};

}  // namespace

table_dataset table_dataset_of(const std::string& table_text, const std::string& sidecar_text,
                               const std::string& table_name) {
  const table_format format = table_format::of_text(table_text);
  if (format.kind != table_kind::cor)
    throw parse_error(table_name + ": a sticking-threshold table has no grid of e; the dataset form is for CoR "
                      "tables");
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

  // The grid: (law, g, gamma), or for a table in SI its axes, v0 innermost.
  const bool calibrated = format.physical && !table.rows.empty() && !table.rows.front().fields[target_e_col].empty();
  for (const csv_record& row : table.rows)
    if (format.physical && row.fields[target_e_col].empty() == calibrated)
      throw parse_error(table_name + ":" + std::to_string(row.line) + ": field target_e: given in some rows only");
  std::vector<dimension> dims{{"law", {law_col, alpha_col, beta_col}, {}, {}}};
  if (!format.physical) {
    dims.push_back({"g", {g_col}, {}, {}});
    dims.push_back({"gamma", {gamma_col}, {}, {}});
  } else {
    dims.push_back({"bead", {bead_col, m_col, k_col, youngs_modulus_col, poisson_ratio_col, radius_col, density_col}, {}, {}});
    dims.push_back({"wall", {wall_col, wall_youngs_modulus_col, wall_poisson_ratio_col, other_youngs_modulus_col,
                             other_poisson_ratio_col, other_radius_col, other_density_col}, {}, {}});
    dims.push_back({"gravity", {gravity_col}, {}, {}});
    dims.push_back({"force", {force_col}, {}, {}});
    dims.push_back(calibrated ? dimension{"target_e", {target_e_col}, {}, {}} : dimension{"gamma0", {gamma0_col}, {}, {}});
    dims.push_back({"v0", {v0_col}, {}, {}});
  }
  const std::vector<std::size_t> row_of = place_rows(table, dims, table_name);

  table_dataset d;
  std::vector<std::string> grid;
  for (const dimension& dim : dims) {
    d.dimensions.emplace_back(dim.name, dim.positions.values.size());
    grid.push_back(dim.name);
  }
  dataset_array law = text_array("law", {"law"}, "contact law (a law without a name: alpha=A beta=B)");
  dataset_array alpha = text_array("alpha", {"law"}, "elastic exponent alpha (exact)");
  dataset_array beta = text_array("beta", {"law"}, "dissipative exponent beta (exact)");
  for (const csv_record* row : dims[0].first_rows) {
    const std::string& name = row->fields[law_col];
    law.texts.push_back(!name.empty() ? name : "alpha=" + row->fields[alpha_col] + " beta=" + row->fields[beta_col]);
    alpha.texts.push_back(row->fields[alpha_col]);
    beta.texts.push_back(row->fields[beta_col]);
  }
  d.coordinates = {law, alpha, beta};
  // A number along one dimension, from the column of a row at each position: float64
  // and, beside it, the exact decimal.
  const auto add_coordinate = [&](const dimension& dim, std::size_t column, const std::string& name,
                                  const std::string& long_name, const std::string& units) {
    dataset_array numbers = number_array(name, {dim.name}, long_name);
    with_units(numbers, units);
    numbers.attributes.emplace_back("comment", with_name(rounding_note(rounding::nearest), name));
    dataset_array exact = text_array(name + "_exact", {dim.name}, long_name + " (the exact decimal input; empty: "
                                                                               "not given)");
    for (const csv_record* row : dim.first_rows) {
      numbers.numbers.push_back(decimal_to_double(row->fields[column], rounding::nearest));
      exact.texts.push_back(row->fields[column]);
    }
    d.coordinates.push_back(std::move(numbers));
    d.coordinates.push_back(std::move(exact));
  };
  const auto add_names = [&](const dimension& dim, std::size_t column, const std::string& long_name) {
    dataset_array names = text_array(dim.name, {dim.name}, long_name);
    for (const csv_record* row : dim.first_rows) names.texts.push_back(row->fields[column]);
    d.coordinates.push_back(std::move(names));
  };

  // A number of every row, over the whole grid (float64, and the exact decimal beside it).
  const auto add_variable = [&](std::size_t column, const std::string& name, const std::string& long_name,
                                rounding direction, const std::string& units) {
    dataset_array numbers = number_array(name, grid, long_name);
    with_units(numbers, units);
    numbers.attributes.emplace_back("comment", with_name(rounding_note(direction), name));
    dataset_array exact = text_array(name + "_exact", grid, long_name + " (the table's exact decimal; empty: not "
                                                                        "available)");
    for (std::size_t r : row_of) {
      const std::string& v = table.rows[r].fields[column];
      numbers.numbers.push_back(decimal_to_double(v, direction));
      exact.texts.push_back(v);
    }
    d.variables.push_back(std::move(numbers));
    d.variables.push_back(std::move(exact));
  };
  const auto add_numbers = [&](const number_column& c) { add_variable(c.column, c.name, c.long_name, c.direction, "1"); };
  const auto add_texts = [&](std::size_t column, const char* name, const char* long_name) {
    dataset_array a = text_array(name, grid, long_name);
    for (std::size_t r : row_of) a.texts.push_back(table.rows[r].fields[column]);
    d.variables.push_back(std::move(a));
  };
  const auto add_digits = [&](std::size_t column, const char* name, const char* long_name) {
    dataset_array a = text_array(name, grid, long_name);
    a.kind = dataset_array::type::int32;
    a.attributes.emplace_back("comment", "-1: not available");
    for (std::size_t r : row_of) {
      const std::string& v = table.rows[r].fields[column];
      a.integers.push_back(v.empty() ? -1 : static_cast<std::int32_t>(std::stol(v)));
    }
    d.variables.push_back(std::move(a));
  };

  if (!format.physical) {
    add_coordinate(dims[1], g_col, "g", "scaled load g", "1");
    add_coordinate(dims[2], gamma_col, "gamma", "scaled damping gamma", "1");
  } else {
    add_names(dims[1], bead_col, "bead, as the spec names it");
    for (const si_number& c : {si_number{m_col, "m", "bead mass (given)", "kg"},
                               si_number{k_col, "k", "contact stiffness (given), N/m^alpha", ""},
                               si_number{youngs_modulus_col, "youngs_modulus", "bead's Young's modulus", "Pa"},
                               si_number{poisson_ratio_col, "poisson_ratio", "bead's Poisson ratio", "1"},
                               si_number{radius_col, "radius", "bead radius", "m"},
                               si_number{density_col, "density", "bead density", "kg m-3"}})
      add_coordinate(dims[1], c.column, c.name, c.long_name, c.units);
    add_names(dims[2], wall_col, "wall, as the spec names it (rigid; none: the second bead of a pair)");
    for (const si_number& c :
         {si_number{wall_youngs_modulus_col, "wall_youngs_modulus", "wall's Young's modulus", "Pa"},
          si_number{wall_poisson_ratio_col, "wall_poisson_ratio", "wall's Poisson ratio", "1"},
          si_number{other_youngs_modulus_col, "other_youngs_modulus", "second bead's Young's modulus (a pair)", "Pa"},
          si_number{other_poisson_ratio_col, "other_poisson_ratio", "second bead's Poisson ratio (a pair)", "1"},
          si_number{other_radius_col, "other_radius", "second bead's radius (a pair)", "m"},
          si_number{other_density_col, "other_density", "second bead's density (a pair)", "kg m-3"}})
      add_coordinate(dims[2], c.column, c.name, c.long_name, c.units);
    add_coordinate(dims[3], gravity_col, "gravity", "gravity towards the wall", "m s-2");
    add_coordinate(dims[4], force_col, "force", "force pressing the bead onto the wall (or the beads together)", "N");
    if (calibrated) add_coordinate(dims[5], target_e_col, "target_e", "the CoR the damping is calibrated to", "1");
    else add_coordinate(dims[5], gamma0_col, "gamma0", "damping coefficient (SI, as viscor cor takes it)", "");
    add_coordinate(dims[6], v0_col, "v0", "impact speed", "m s-1");
    add_variable(gamma_col, "gamma", "scaled damping gamma the inputs map to", rounding::nearest, "1");
    add_variable(g_col, "g", "scaled load g the inputs map to", rounding::nearest, "1");
    if (calibrated)
      add_variable(gamma0_col, "gamma0", "damping coefficient (SI) calibrated to target_e", rounding::nearest, "");
  }
  for (const number_column& c : cor_numbers) add_numbers(c);
  add_texts(outcome_col, "outcome", "rebound or stick");
  add_digits(certified_digits_col, "certified_digits", "certified significant digits of the row's values");
  add_texts(method_col, "method", "exact (closed form) or certified");
  if (format.proven) {
    for (const number_column& c : proven_numbers) add_numbers(c);
    add_digits(proven_digits_col, "proven_digits", "correctly rounded significant digits of e both bounds prove");
    add_texts(outcome_proven_col, "outcome_proven", "rebound, stick or undecided, as the proof decides");
  }
  if (format.physical) {
    add_variable(contact_time_s_col, "contact_time_s", "contact time in seconds (certified digits)", rounding::nearest,
                 "s");
    add_variable(max_compression_m_col, "max_compression_m", "maximal compression in metres (certified digits)",
                 rounding::nearest, "m");
  }
  d.attributes = provenance(sidecar, table_text, sidecar_text, table_name);
  if (format.physical) d.attributes.emplace_back("contact", table.rows.front().fields[contact_col]);
  return d;
}

table_dataset read_table_dataset(const std::string& table_path) {
  const std::string table_text = read_checked_file<parse_error>(table_path, "table");
  const std::string sidecar_text = read_checked_file<parse_error>(table_path + ".json", "table sidecar");
  return table_dataset_of(table_text, sidecar_text, table_path);
}

}  // namespace viscor::jobs
