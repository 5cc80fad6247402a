// Where viscor finds the committed surrogates: $VISCOR_SURROGATE_DIR, else
// <data directory>/surrogates (data_directory.hpp: installed share/viscor or the
// source tree's reference_data), and the JSON of a surrogate evaluation (docs/surrogate.md).
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/files.hpp>
#include <viscor/jobs/data_directory.hpp>

#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_verify.hpp>
#include <viscor/tables/reference_table.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace viscor::jobs {

/// The certified rows of a surrogate's verification table (FILE.verification.csv,
/// a CoR table, read from `path`) in the surrogate's types: the truth its bounds are
/// measured against.
inline std::vector<surrogate::reference_value> verification_rows(const csv_table& table, const std::string& path) {
  if (table.kind != table_kind::cor) throw parse_error(path + ":1: a verification table is a CoR table");
  std::vector<surrogate::reference_value> refs;
  for (const auto& r : table.rows) {
    const auto& f = r.fields;
    if (f.size() < 12) throw parse_error(path + ": a verification row needs 12 fields");
    surrogate::reference_value v;
    v.gamma = std::strtod(f[4].c_str(), nullptr), v.g = std::strtod(f[5].c_str(), nullptr);
    v.outcome = f[6] == "stick" ? impact_outcome::stick : impact_outcome::rebound;
    v.e = std::strtold(f[7].c_str(), nullptr), v.one_minus_e = std::strtold(f[8].c_str(), nullptr);
    v.certified_digits = std::atoi(f[11].c_str());
    refs.push_back(v);
  }
  return refs;
}

/// verification_rows of the table file `path`, read through the checking reader.
inline std::vector<surrogate::reference_value> read_verification_rows(const std::string& path) {
  return verification_rows(read_table(path), path);
}

/// The directory of the committed surrogates: $VISCOR_SURROGATE_DIR, else
/// <data directory>/surrogates.
inline std::string surrogate_directory() {
  if (const char* dir = std::getenv("VISCOR_SURROGATE_DIR"); dir && *dir) return dir;
  return data_directory() + "/surrogates";
}

/// The committed surrogate of a named law, or nullptr (custom law, or no file).
/// Read once per law and kept; safe to call from several threads.
inline const surrogate::cor_surrogate* find_surrogate(const contact_law& law) {
  static std::map<std::string, std::unique_ptr<surrogate::cor_surrogate>> cache;
  static std::mutex mutex;
  if (law.name.empty()) return nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(law.name);
  if (it == cache.end()) {
    const std::string path = surrogate_directory() + "/" + law.name + ".surrogate";
    std::unique_ptr<surrogate::cor_surrogate> s;
    if (std::filesystem::exists(path)) s = std::make_unique<surrogate::cor_surrogate>(surrogate::read_cor_surrogate(path));
    it = cache.emplace(law.name, std::move(s)).first;
  }
  return it->second.get();
}

/// error_bound of a surrogate value: what is claimed and what the claim is.
inline json surrogate_bound_json(const surrogate::surrogate_bound& b) {
  if (!b.verified()) return {{"kind", "none: this surrogate file was never verified (no bound is claimed)"}};
  return {{"kind", "measured maximum over the certified verification points x safety factor"},
          {"safety_factor", b.safety_factor},
          {"abs_e", b.abs_e},
          {"abs_e_applies", "where e >= 1e-2"},
          {"abs_e_squared", b.abs_e_squared},
          {"rel_one_minus_e", b.rel_one_minus_e},
          {"rel_one_minus_e_applies", "where gamma <= 1e-2 and e >= 1e-2"},
          {"outcome", "correct except within relative 1e-10 in g of the sticking threshold"}};
}
/// error_bound of a surrogate: the bound it states (surrogate_bound_json of its bound).
inline json surrogate_bound_json(const surrogate::cor_surrogate& s) { return surrogate_bound_json(s.bound); }

}  // namespace viscor::jobs
