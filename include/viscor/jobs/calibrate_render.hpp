// The calibrate job's result (jobs/calibrate_job.hpp) as readable text and as JSON,
// for `viscor calibrate` and Python's viscor.calibrate.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/calibrate_job.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/surrogate_files.hpp>

#include <sstream>
#include <string>

namespace viscor::render {

/// The object of `viscor calibrate --json`.
inline jobs::json calibrate_json(const jobs::calibrate_result& r) {
  using jobs::number;
  jobs::json j;
  j["command"] = "calibrate";
  if (r.by_surrogate) j[field::method] = "surrogate";
  j["law"] = jobs::law_json(r.law);
  j[field::target_e] = r.target_e;
  if (r.physical) j["physical"] = r.physical->echo();
  if (r.physical && !r.by_surrogate) {
    j["gamma0"] = number(*r.gamma0);
    j["time_scale_s"] = number(*r.time_scale);
  }
  j["gamma"] = number(r.gamma);
  j["g"] = number(r.g);
  j[field::e] = number(r.e);
  if (r.by_surrogate) {
    j["error_bound"] = jobs::surrogate_bound_json(r.bound);
  } else {
    j[field::target_bound] = number(r.target_bound);
    j[field::gamma_lo] = number(r.gamma_lo);
    j[field::gamma_hi] = number(r.gamma_hi);
    j[field::solves] = r.solves;
  }
  j["precision"] = jobs::precision_json(r.precision);
  j[field::seconds] = r.seconds;
  if (r.physical && r.by_surrogate) {
    j["gamma0"] = number(*r.gamma0);
    j["time_scale_s"] = number(*r.time_scale);
  }
  return j;
}

/// The readable summary of `viscor calibrate`.
inline std::string calibrate_text(const jobs::calibrate_result& r) {
  using jobs::number;
  std::ostringstream text;
  text << "law        " << r.law.describe() << "\n"
       << "target e   " << r.target_e << "\n";
  if (r.by_surrogate) {
    if (r.physical) text << "gamma0     " << number(*r.gamma0) << "\n";
    text << "gamma      " << number(r.gamma) << " (scaled; the surrogate's inverse)\n"
         << "g          " << number(r.g) << " (scaled load)\n"
         << "e          " << number(r.e) << " at gamma (surrogate)\n"
         << "bound      |de| <= " << number(r.bound.abs_e) << " where e >= 1e-2 (measured maximum x "
         << number(r.bound.safety_factor) << ", docs/surrogate.md)\n"
         << "seconds    " << r.seconds << " s\n";
    return text.str();
  }
  if (r.physical)
    text << "bead       m = " << number(r.m) << " kg, k = " << number(r.k) << ", v0 = " << number(r.v0)
         << " m/s, gravity = " << number(r.gravity) << " m/s^2, force = " << number(r.force) << " N\n"
         << "gamma0     " << number(*r.gamma0) << "\n";
  text << "gamma      " << number(r.gamma) << " (scaled)\n"
       << "g          " << number(r.g) << " (scaled load)\n"
       << "e          " << number(r.e) << " at gamma (solve_impact)\n"
       << "|e - tgt|  <= " << r.target_bound.decimal(3) << " (miss plus 10 x the solver's estimate)\n"
       << "solves     " << r.solves << "\n"
       << "seconds    " << r.seconds << " s\n"
       << "digits     " << r.precision.digits << " (working precision)\n";
  return text.str();
}

}  // namespace viscor::render
