// The exact job's result (jobs/exact_job.hpp) as readable text and as JSON, for
// `viscor exact` and Python's viscor.exact.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/exact_job.hpp>
#include <viscor/jobs/json_fields.hpp>

#include <sstream>
#include <string>

namespace viscor::render {

/// The object of `viscor exact --json`.
inline jobs::json exact_json(const jobs::exact_job_result& r) {
  using jobs::number;
  jobs::json j;
  j["command"] = "exact";
  j["law"] = jobs::law_json(r.law);
  j["gamma"] = number(r.gamma), j["g"] = number(r.g);
  j["precision"] = jobs::precision_json(r.precision);
  j["exists"] = r.exact.has_value();
  if (!r.exact) return j;
  const exact_result<working_number>& x = *r.exact;
  j["formula"] = x.formula;
  j[field::e] = number(x.e);
  j[field::one_minus_e] = number(x.one_minus_e);
  j[field::outcome] = std::string(to_string(x.outcome));
  if (x.contact_time) j[field::contact_time] = number(*x.contact_time);
  if (x.max_compression) j[field::max_compression] = number(*x.max_compression);
  if (x.time_of_max_compression) j[field::time_of_max_compression] = number(*x.time_of_max_compression);
  j[field::seconds] = r.seconds;
  return j;
}

/// The readable summary of `viscor exact`.
inline std::string exact_text(const jobs::exact_job_result& r) {
  using jobs::number;
  std::ostringstream text;
  text << "law      " << r.law.describe() << "\ngamma    " << r.gamma_text << "\ng        " << r.g_text << "\n";
  if (!r.exact) {
    text << "no exact solution is known for these parameters (exact: gamma = 0; alpha = beta = 1;\n"
            "beta = alpha + 1 with g = 0; alpha = 3/2, beta = 5/4 with g = 0). Use 'viscor cor'.\n";
    return text.str();
  }
  const exact_result<working_number>& x = *r.exact;
  text << "formula  " << x.formula << "\n"
       << "outcome  " << to_string(x.outcome) << " (contact ends at zero overlap u = 0)\n"
       << "e        " << number(x.e) << "\n"
       << "1 - e    " << number(x.one_minus_e) << "\n";
  if (x.contact_time) text << "T_f      " << number(*x.contact_time) << "\n";
  if (x.max_compression) text << "u_max    " << number(*x.max_compression) << "\n";
  text << "digits   " << r.precision.digits << " (working precision)\n"
       << "seconds  " << r.seconds << " s\n";
  return text.str();
}

}  // namespace viscor::render
