// The closed-form CoR where one exists (gamma = 0; the linear law; beta = alpha + 1
// at g = 0; Tsuji at g = 0), as `viscor exact` and viscor.exact report it.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/command_output.hpp>
#include <viscor/jobs/json_fields.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/exact/exact_solutions.hpp>

#include <chrono>
#include <optional>
#include <sstream>
#include <string>

namespace viscor::jobs {

/// One closed-form evaluation: the law, scaled gamma and g as exact decimal text.
struct exact_request {
  contact_law law;
  std::string gamma = "0", g = "0";
  int digits = 15;  ///< working precision in decimal digits
};

/// The closed form at (gamma, g), or `"exists": false` when none is known.
inline command_output run_exact(const exact_request& q) {
  command_output out;
  with_working_precision(q.digits, [&]<class Real>() {
    const Real gamma_value = parse_real<Real>(q.gamma, "gamma");
    const Real g_value = parse_real<Real>(q.g, "g");
    const auto start = std::chrono::steady_clock::now();
    const std::optional<exact_result<Real>> r = exact_cor(q.law, gamma_value, g_value);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    json& j = out.object;
    j["command"] = "exact";
    j["law"] = law_json(q.law);
    j["gamma"] = number(gamma_value), j["g"] = number(g_value);
    j["precision"] = scalar_json<Real>(q.digits);
    j["exists"] = r.has_value();
    std::ostringstream text;
    text << "law      " << q.law.describe() << "\ngamma    " << q.gamma << "\ng        " << q.g << "\n";
    if (!r) {
      text << "no exact solution is known for these parameters (exact: gamma = 0; alpha = beta = 1;\n"
              "beta = alpha + 1 with g = 0; alpha = 3/2, beta = 5/4 with g = 0). Use 'viscor cor'.\n";
      out.text = text.str();
      return;
    }
    j["formula"] = r->formula;
    j[field::e] = number(r->e);
    j[field::one_minus_e] = number(r->one_minus_e);
    j[field::outcome] = std::string(to_string(r->outcome));
    if (r->contact_time) j[field::contact_time] = number(*r->contact_time);
    if (r->max_compression) j[field::max_compression] = number(*r->max_compression);
    if (r->time_of_max_compression) j[field::time_of_max_compression] = number(*r->time_of_max_compression);
    j[field::seconds] = seconds;
    text << "formula  " << r->formula << "\n"
         << "outcome  " << to_string(r->outcome) << " (contact ends at zero overlap u = 0)\n"
         << "e        " << number(r->e) << "\n"
         << "1 - e    " << number(r->one_minus_e) << "\n";
    if (r->contact_time) text << "T_f      " << number(*r->contact_time) << "\n";
    if (r->max_compression) text << "u_max    " << number(*r->max_compression) << "\n";
    text << "digits   " << decimal_digits<Real>() << " (working precision)\n"
         << "seconds  " << seconds << " s\n";
    out.text = text.str();
  });
  return out;
}

}  // namespace viscor::jobs
