// The committed reference values of eq. (2) (tests/data/scaling_reference.csv),
// computed outside the library by tools/scaling_reference.py: the scaling tests
// compare with these rather than with the library's own inverse.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace viscor::test {

/// One row, as the decimal strings the script wrote (parse them in the type under test).
struct scaling_reference_row {
  std::string case_name, law, m, k, gamma0, v0, gravity, force, gamma, g, time_scale;
};

inline std::vector<scaling_reference_row> scaling_reference_rows() {
  const std::string path = std::string(VISCOR_SOURCE_DIR) + "/tests/data/scaling_reference.csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("missing committed data file " + path);
  std::vector<scaling_reference_row> rows;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::stringstream fields(line);
    scaling_reference_row r;
    for (std::string* f : {&r.case_name, &r.law, &r.m, &r.k, &r.gamma0, &r.v0, &r.gravity, &r.force, &r.gamma, &r.g,
                           &r.time_scale})
      std::getline(fields, *f, ',');
    rows.push_back(r);
  }
  if (rows.empty()) throw std::runtime_error("no rows in " + path);
  return rows;
}

/// The row of one case and law; throws when the data file lacks it.
inline scaling_reference_row scaling_reference(const std::string& case_name, const std::string& law) {
  for (const auto& r : scaling_reference_rows())
    if (r.case_name == case_name && r.law == law) return r;
  throw std::runtime_error("tests/data/scaling_reference.csv has no row " + case_name + "," + law);
}

}  // namespace viscor::test
