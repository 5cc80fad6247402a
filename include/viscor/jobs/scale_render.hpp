// The scale job's result (jobs/scale_job.hpp) as readable text and as JSON, for
// `viscor scale` and Python's viscor.scale.
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/scale_job.hpp>

#include <sstream>
#include <string>

namespace viscor::render {

/// The object of `viscor scale --json`.
inline jobs::json scale_json(const jobs::scale_result& r) {
  using jobs::number;
  jobs::json j;
  j["command"] = "scale";
  j["law"] = jobs::law_json(r.law);
  j["physical"] = r.physical.echo();
  j["precision"] = jobs::precision_json(r.precision);
  if (r.scaled_to_physical) {
    j["physical"].erase("force");  // computed, not given
    j["direction"] = "scaled_to_physical";
    j["gamma"] = number(r.gamma);
    j["g"] = number(r.g);
    j["gamma0"] = number(r.gamma0);
    j["force"] = number(r.force);
  } else {
    j["direction"] = "physical_to_scaled";
    j["gamma"] = number(r.gamma);
    j["g"] = number(r.g);
    j["time_scale_s"] = number(r.time_scale);
    j["length_scale_m"] = number(r.length_scale);
  }
  return j;
}

/// The readable summary of `viscor scale`.
inline std::string scale_text(const jobs::scale_result& r) {
  using jobs::number;
  std::ostringstream text;
  text << "law      " << r.law.describe() << "\n";
  if (r.scaled_to_physical)
    text << "gamma0   " << number(r.gamma0) << "\nforce    " << number(r.force) << " N\n";
  else
    text << "gamma    " << number(r.gamma) << "\ng        " << number(r.g) << "\n"
         << "T        " << number(r.time_scale) << " s (time scale)\n"
         << "delta    " << number(r.length_scale) << " m (overlap scale)\n";
  return text.str();
}

}  // namespace viscor::render
