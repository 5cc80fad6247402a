// Shared by surrogate_test.cpp and surrogate_slow_test.cpp: the committed
// surrogates and their certified verification tables, and the bound check.
#pragma once

#include <viscor/surrogate/cor_surrogate.hpp>
#include <viscor/surrogate/surrogate_verify.hpp>
#include <viscor/tables/reference_table.hpp>

#include "required_dependencies.hpp"

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::test {

inline std::string surrogate_path(const std::string& law) {
  return std::string(VISCOR_SOURCE_DIR) + "/reference_data/surrogates/" + law + ".surrogate";
}

inline std::optional<surrogate::cor_surrogate> load_committed_surrogate(const std::string& law) {
  if (!std::filesystem::exists(surrogate_path(law))) return std::nullopt;
  return surrogate::read_cor_surrogate(surrogate_path(law));
}

/// Every `every`-th row of the committed verification table (certified values).
inline std::vector<surrogate::reference_value> load_verification_table(const std::string& law, std::size_t every) {
  const csv_table table = read_table(surrogate_path(law) + ".verification.csv");
  std::vector<surrogate::reference_value> refs;
  for (std::size_t i = 0; i < table.rows.size(); i += every) {
    const auto& f = table.rows[i].fields;
    surrogate::reference_value v;
    v.gamma = std::strtod(f[4].c_str(), nullptr), v.g = std::strtod(f[5].c_str(), nullptr);
    v.outcome = f[6] == "stick" ? impact_outcome::stick : impact_outcome::rebound;
    v.e = std::strtold(f[7].c_str(), nullptr), v.one_minus_e = std::strtold(f[8].c_str(), nullptr);
    v.certified_digits = std::stoi(f[11]);
    refs.push_back(v);
  }
  return refs;
}

/// Points where the surrogate breaks its stated bound (a description of each). Rows
/// certified to fewer than 25 digits are judged on the checks their absolute digits
/// decide (surrogate::checks_for), as by the builder.
inline std::vector<std::string> bound_violations(const surrogate::cor_surrogate& s,
                                                 const std::vector<surrogate::reference_value>& refs) {
  std::vector<std::string> out;
  const surrogate::surrogate_targets targets;
  for (const auto& r : refs) {
    const auto v = s(r.gamma, r.g);
    std::ostringstream where;
    where.precision(17);
    where << "gamma = " << r.gamma << ", g = " << r.g << ": ";
    if (!v.in_domain) { out.push_back(where.str() + "outside the domain"); continue; }
    if (surrogate::near_threshold_in_g(s, r.gamma, r.g, 1e-10)) continue;
    const auto check = surrogate::checks_for(r, targets, 25);
    const long double e = v.e, d_e = std::abs(e - r.e), d_e2 = std::abs(e * e - r.e * r.e);
    if (v.outcome != r.outcome) out.push_back(where.str() + "wrong outcome");
    if (check.abs_e && d_e > s.bound.abs_e)
      out.push_back(where.str() + "|de| = " + std::to_string(static_cast<double>(d_e)));
    if (check.abs_e_squared && d_e2 > s.bound.abs_e_squared)
      out.push_back(where.str() + "|de^2| = " + std::to_string(static_cast<double>(d_e2)));
    if (check.rel_one_minus_e) {
      const long double rel = std::abs((static_cast<long double>(v.one_minus_e) - r.one_minus_e) / r.one_minus_e);
      if (rel > s.bound.rel_one_minus_e) out.push_back(where.str() + "relative error of 1 - e " + std::to_string(static_cast<double>(rel)));
    }
  }
  return out;
}

}  // namespace viscor::test
