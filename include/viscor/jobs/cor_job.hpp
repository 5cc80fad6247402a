// One impact as every front end reports it: the fields of `viscor cor --json`, of
// each line of `viscor cor --points` and of the Python module's viscor.cor come from
// here, so they cannot drift apart.
#pragma once

#include <viscor/jobs/certify_report.hpp>
#include <viscor/jobs/json_fields.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <chrono>
#include <sstream>
#include <string>

namespace viscor::jobs {

/// The law from a name, or from alpha and beta (decimal or p/q).
inline contact_law resolve_law(const std::string& name, const std::string& alpha, const std::string& beta) {
  if (!name.empty()) {
    if (!alpha.empty() || !beta.empty())
      throw invalid_parameter("give either the law's name or alpha and beta, not both (got law '" + name + "')");
    return law_by_name(name);
  }
  if (alpha.empty() || beta.empty()) throw invalid_parameter("the contact law needs a name, or both alpha and beta");
  return make_law(exponent::parse(alpha, "alpha"), exponent::parse(beta, "beta"));
}

/// "taylor" or "adaptive"; `option` names the input in the message.
inline integration_method parse_integration_method(const std::string& text, const std::string& option = "--method") {
  if (text == "taylor") return integration_method::taylor;
  if (text == "adaptive") return integration_method::adaptive;
  throw invalid_parameter(option + " must be 'taylor' or 'adaptive', got '" + text + "'");
}

/// The result fields of one impact (after law, gamma, g and precision).
template <class Real>
void add_result_json(json& j, const impact_result<Real>& r, double seconds) {
  j["method"] = std::string(to_string(r.method));
  j["e"] = number(r.e);
  j["one_minus_e"] = number(r.one_minus_e);
  j["outcome"] = std::string(to_string(r.outcome));
  j["contact_time"] = number(r.contact_time);
  j["max_compression"] = number(r.max_compression);
  if (r.outcome == impact_outcome::stick) j["stop_overlap"] = number(r.stop_overlap);
  j["time_of_max_compression"] = number(r.time_of_max_compression);
  j["energy_residual"] = number(r.energy_residual);
  j["error_estimate"] = number(r.error_estimate);
  j["steps"] = r.steps;
  j["seconds"] = seconds;
}

/// Solves one impact at scaled (gamma, g) in the working type Real and adds its
/// fields to `j`: law, gamma, g, precision, the result, and with `certify` the
/// object "certified" (certify_report.hpp). Returns the result.
template <class Real>
impact_result<Real> add_cor_json(json& j, const contact_law& law, const Real& gamma, const Real& g,
                                 const solve_options<Real>& options, bool certify = false) {
  const auto start = std::chrono::steady_clock::now();
  const impact_result<Real> r = solve_impact(law, gamma, g, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  j["law"] = law_json(law);
  j["gamma"] = number(gamma);
  j["g"] = number(g);
  j["precision"] = scalar_json<Real>();
  add_result_json(j, r, seconds);
  if (certify) {
    std::ostringstream report;  // the readable report is the command-line tool's; the fields are in j
    certify_and_report<Real>(law, gamma, g, report, j);
  }
  return r;
}

}  // namespace viscor::jobs
