// The approx job's result (jobs/approx_job.hpp) as readable text and as JSON, for
// `viscor approx` and Python's viscor.approx.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/approx_job.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/surrogate_files.hpp>

#include <iomanip>
#include <sstream>
#include <string>

namespace viscor::render {

/// The object of `viscor approx --json`.
inline jobs::json approx_json(const jobs::approx_result& r) {
  using jobs::json;
  using jobs::number;
  json j;
  j["command"] = "approx";
  if (r.by_surrogate) {
    j["formula"] = "surrogate";
    j["law"] = jobs::law_json(r.law);
    j["gamma"] = r.gamma_text, j["g"] = r.g_text;
    j[field::e] = number(r.e);
    j[field::one_minus_e] = number(r.one_minus_e);
    j[field::outcome] = std::string(to_string(r.outcome));
    j["error_bound"] = jobs::surrogate_bound_json(r.bound);
    return j;
  }
  j["law"] = jobs::law_json(r.law);
  j["gamma"] = number(r.gamma);
  j["g"] = number(r.g);
  j["precision"] = jobs::precision_json(r.precision);
  j["chebyshev_order"] = r.chebyshev_order;
  const auto& c = r.closed;
  json closed;
  closed["I0"] = number(c.I0), closed["Q0"] = number(c.Q0), closed["dI_dg0"] = number(c.dI_dg0);
  closed["C0"] = number(c.C0), closed["C1"] = number(c.C1), closed["C"] = number(c.C);
  closed["p"] = number(c.p), closed["C2"] = number(c.C2);
  if (r.critical_g) closed["critical_g"] = number(*r.critical_g);
  if (r.critical_gamma) closed["critical_gamma"] = number(*r.critical_gamma);
  j["closed_forms"] = closed;
  if (r.small_g) j["small_g"] = number(*r.small_g);
  if (r.large_g) j["large_g"] = number(*r.large_g);
  if (r.schwager_poschel) j["schwager_poschel"] = number(*r.schwager_poschel);
  if (r.prop2_asked) {
    json prop2;  // null when every source was left out
    for (const jobs::prop2_value& v : r.prop2) {
      json one;
      one["I"] = number(v.I), one["Q"] = number(v.Q);
      if (v.theta) one["theta"] = number(*v.theta);
      one["e_squared"] = number(v.e_squared);
      if (v.e) one[field::e] = number(*v.e);
      if (v.e_plus) one["e_plus"] = number(*v.e_plus);
      if (v.e_linearized) one["e_linearized"] = number(*v.e_linearized);
      prop2[std::string(to_string(v.source))] = one;
    }
    j["prop2"] = prop2;
  }
  if (!r.not_applicable.empty()) j["not_applicable"] = r.not_applicable;
  return j;
}

/// The readable summary of `viscor approx`: the closed forms, then one row per formula.
inline std::string approx_text(const jobs::approx_result& r) {
  using jobs::number;
  std::ostringstream text;
  if (r.by_surrogate) {
    text << "law          " << r.law.describe() << "\n"
         << "surrogate    e = " << number(r.e) << ", 1 - e = " << number(r.one_minus_e) << " (" << to_string(r.outcome)
         << ")\n"
         << (r.bound.verified() ? "" : "error bound  none: this surrogate file was never verified\n");
    if (r.bound.verified())
      text << "error bound  |de| <= " << r.bound.abs_e << " (e >= 1e-2), |de^2| <= " << r.bound.abs_e_squared
           << ", relative d(1 - e) <= " << r.bound.rel_one_minus_e << " (gamma <= 1e-2)\n"
           << "             (measured maximum over the certified verification points x " << r.bound.safety_factor
           << ")\n";
    return text.str();
  }
  const auto& c = r.closed;
  text << "law        " << r.law.describe() << "\n"
       << "gamma      " << number(r.gamma) << "\n"
       << "g          " << number(r.g) << "\n"
       << "C0 = " << c.C0.decimal(10) << ", C1 = " << c.C1.decimal(10) << ", C = " << c.C.decimal(10)
       << ", C2(g=0) = " << c.C2.decimal(10) << "\n";
  if (r.critical_g) text << "g_c(gamma) = " << r.critical_g->decimal(10) << " (eq. 24)\n";
  text << "\n" << std::left << std::setw(34) << "formula" << std::setw(16) << "coefficients" << "e\n";
  const auto row = [&](const std::string& name, const std::string& from, const working_number& value) {
    text << std::left << std::setw(34) << name << std::setw(16) << from << number(value) << "\n";
  };
  if (r.small_g) row("small_g (22)", "closed form", *r.small_g);
  if (r.large_g) row("large_g (23)", "closed form", *r.large_g);
  if (r.schwager_poschel) row("schwager_poschel (25)+(30)", "closed form", *r.schwager_poschel);
  for (const jobs::prop2_value& v : r.prop2) {
    const std::string from(to_string(v.source));
    if (v.e) row("prop2 (36) min(e_+, e_s)", from, *v.e);
    if (v.e_plus) row("prop2_squared (89) e_+", from, *v.e_plus);
    if (v.e_linearized) row("prop2_linearized (90) e_s", from, *v.e_linearized);
  }
  if (!r.not_applicable.empty()) {
    text << "\nnot applicable:\n";
    for (const auto& why : r.not_applicable) text << "  " << why << "\n";
  }
  text << "\nApproximations of the CoR at zero overlap (u = 0); compare with 'viscor cor'.\n"
       << "digits   " << r.precision.digits << " (working precision; the formulas' own error is far larger)\n";
  return text.str();
}

}  // namespace viscor::render
