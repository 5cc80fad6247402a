// The report's approximate CoR formulas (approx/approximations.hpp) at one (law,
// gamma, g), as `viscor approx` and viscor.approx report them: small g (22), large
// g (23), Schwager-Poschel (25)+(30), and Proposition 2 (36) with its branches
// (89), (90), each with its coefficients I(g), Q(g) from the closed forms at g = 0,
// tanh-sinh quadrature, or the Chebyshev-Beta approximation; or the committed
// surrogate in double (never silently outside its domain or for a law without one).
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/command_output.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/surrogate_files.hpp>

#include <viscor/approx/approximations.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/precision.hpp>
#include <viscor/core/real_io.hpp>

#include <array>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace viscor::jobs {

/// One (law, gamma, g) and the formulas to evaluate.
struct approx_request {
  contact_law law;
  std::string gamma;            ///< scaled damping, exact decimal text (required)
  std::string g = "0";          ///< scaled load
  std::string formula = "all";  ///< all, small_g, large_g, schwager_poschel, prop2, prop2_squared, prop2_linearized, surrogate
  std::string source = "all";   ///< Prop. 2 coefficients: all, exact_at_zero, numeric, chebyshev_beta
  int digits = 15;              ///< working precision in decimal digits
  int order = 21;               ///< odd order of the Chebyshev-Beta approximation, 1 to 999
};

namespace detail {

constexpr std::array<const char*, 8> formula_names{"all",   "small_g",       "large_g",         "schwager_poschel",
                                                   "prop2", "prop2_squared", "prop2_linearized", "surrogate"};

struct approx_job : approx_request {
  bool wants(const char* name) const { return formula == "all" || formula == name; }

  // --formula surrogate: the committed surrogate in double (docs/surrogate.md); never silently
  // outside its domain or for a law without one.
  command_output run_surrogate(const contact_law& model) const {
    const surrogate::cor_surrogate* s = find_surrogate(model);
    if (!s)
      throw invalid_parameter("no surrogate for " + model.describe() + " (looked in '" + surrogate_directory() +
                              "'; build one with 'viscor surrogate build', docs/surrogate.md)");
    const double gamma_value = parse_real<double>(gamma, "gamma"), g_value = parse_real<double>(g, "g");
    const surrogate::surrogate_value v = (*s)(gamma_value, g_value);
    if (!v.in_domain) {
      std::ostringstream domain;
      domain << "0 <= gamma <= " << s->gamma_max << ", " << s->g_min << " <= g <= " << s->g_max;
      throw invalid_parameter("gamma = " + gamma + ", g = " + g + " is outside the domain of the " + model.name +
                              " surrogate (" + domain.str() + ")");
    }
    json j;
    j["command"] = "approx";
    j["formula"] = "surrogate";
    j["law"] = law_json(model);
    j["gamma"] = gamma, j["g"] = g;
    j[field::e] = number(v.e);
    j[field::one_minus_e] = number(v.one_minus_e);
    j[field::outcome] = std::string(to_string(v.outcome));
    j["error_bound"] = surrogate_bound_json(*s);
    std::ostringstream text;
    text << "law          " << model.describe() << "\n"
         << "surrogate    e = " << number(v.e) << ", 1 - e = " << number(v.one_minus_e) << " (" << to_string(v.outcome)
         << ")\n"
         << (s->bound.verified() ? "" : "error bound  none: this surrogate file was never verified\n");
    if (s->bound.verified())
      text << "error bound  |de| <= " << s->bound.abs_e << " (e >= 1e-2), |de^2| <= " << s->bound.abs_e_squared
         << ", relative d(1 - e) <= " << s->bound.rel_one_minus_e << " (gamma <= 1e-2)\n"
         << "             (measured maximum over the certified verification points x " << s->bound.safety_factor << ")\n";
    return {text.str(), j};
  }

  command_output run() const {
    const contact_law& model = law;
    if (gamma.empty()) throw invalid_parameter("approx needs --gamma");
    if (formula == "surrogate") return run_surrogate(model);
    bool known = false;
    for (const char* f : formula_names) known = known || formula == f;
    if (!known)
      throw invalid_parameter("parameter formula must be one of all, small_g, large_g, schwager_poschel, prop2, "
                              "prop2_squared, prop2_linearized, surrogate; got '" + formula + "'");
    std::vector<coefficient_source> sources;
    if (source == "all") {
      sources.assign(coefficient_sources.begin(), coefficient_sources.end());
    } else {
      sources.push_back(parse_coefficient_source(source));
    }
    command_output out;
    with_working_precision(digits, [&]<class Real>() {
      const Real gamma_value = parse_real<Real>(gamma, "gamma");
      const Real g_value = parse_real<Real>(g, "g");
      const cor_approximations<Real> approx(model, order);
      const auto& c = approx.closed_forms();

      json j;
      j["command"] = "approx";
      j["law"] = law_json(model);
      j["gamma"] = number(gamma_value);
      j["g"] = number(g_value);
      j["precision"] = scalar_json<Real>(digits);
      j["chebyshev_order"] = order;
      json closed;
      closed["I0"] = number(c.I0), closed["Q0"] = number(c.Q0), closed["dI_dg0"] = number(c.dI_dg0);
      closed["C0"] = number(c.C0), closed["C1"] = number(c.C1), closed["C"] = number(c.C);
      closed["p"] = number(c.p), closed["C2"] = number(c.C2);
      if (gamma_value > 0) closed["critical_g"] = number(critical_g(c.alpha, c.beta, gamma_value));
      if (g_value > 0) closed["critical_gamma"] = number(critical_gamma(c.alpha, c.beta, g_value));
      j["closed_forms"] = closed;

      std::ostringstream text;
      text << "law        " << model.describe() << "\n"
           << "gamma      " << number(gamma_value) << "\n"
           << "g          " << number(g_value) << "\n"
           << "C0 = " << to_decimal_string(c.C0, 10) << ", C1 = " << to_decimal_string(c.C1, 10)
           << ", C = " << to_decimal_string(c.C, 10) << ", C2(g=0) = " << to_decimal_string(c.C2, 10) << "\n";
      if (gamma_value > 0)
        text << "g_c(gamma) = " << to_decimal_string(critical_g(c.alpha, c.beta, gamma_value), 10) << " (eq. 24)\n";
      text << "\n" << std::left << std::setw(34) << "formula" << std::setw(16) << "coefficients" << "e\n";
      auto row = [&](const std::string& name, const std::string& from, const std::string& value) {
        text << std::left << std::setw(34) << name << std::setw(16) << from << value << "\n";
      };
      std::vector<std::string> skipped;
      const bool all = formula == "all";

      if (wants("small_g")) {
        const Real e = approx.small_g(gamma_value, g_value);
        j["small_g"] = number(e);
        row("small_g (22)", "closed form", number(e));
      }
      if (wants("large_g")) {
        if (all && g_value < 0) {
          skipped.push_back("large_g (23) needs g >= 0");
        } else {
          const Real e = approx.large_g(gamma_value, g_value);
          j["large_g"] = number(e);
          row("large_g (23)", "closed form", number(e));
        }
      }
      if (wants("schwager_poschel")) {
        if (all && !approx.is_kuwabara_kono()) {
          skipped.push_back("schwager_poschel (25)+(30) exists for Kuwabara-Kono only");
        } else {
          const Real e = approx.schwager_poschel(gamma_value, g_value);
          j["schwager_poschel"] = number(e);
          row("schwager_poschel (25)+(30)", "closed form", number(e));
        }
      }
      const bool any_prop2 = wants("prop2") || wants("prop2_squared") || wants("prop2_linearized");
      if (any_prop2) {
        json prop2;
        for (const coefficient_source s : sources) {
          const std::string from(to_string(s));
          if (source == "all" && s == coefficient_source::exact_at_zero && g_value != 0) {
            skipped.push_back("prop2 with exact_at_zero coefficients needs g = 0");
            continue;
          }
          if (source == "all" && s == coefficient_source::chebyshev_beta && g_value < 0) {
            skipped.push_back("prop2 with chebyshev_beta coefficients needs g >= 0");
            continue;
          }
          const prop2_result<Real> r = approx.prop2(gamma_value, g_value, s);
          json one;
          one["I"] = number(r.I), one["Q"] = number(r.Q);
          if (s == coefficient_source::chebyshev_beta) one["theta"] = number(theta_of_g(c.alpha, g_value));
          one["e_squared"] = number(r.e_squared);
          if (wants("prop2")) {
            one[field::e] = number(r.e);
            row("prop2 (36) min(e_+, e_s)", from, number(r.e));
          }
          if (wants("prop2_squared")) {
            one["e_plus"] = number(r.e_plus);
            row("prop2_squared (89) e_+", from, number(r.e_plus));
          }
          if (wants("prop2_linearized")) {
            one["e_linearized"] = number(r.e_linearized);
            row("prop2_linearized (90) e_s", from, number(r.e_linearized));
          }
          prop2[from] = one;
        }
        j["prop2"] = prop2;
      }
      if (!skipped.empty()) {
        json s = json::array();
        text << "\nnot applicable:\n";
        for (const auto& why : skipped) s.push_back(why), text << "  " << why << "\n";
        j["not_applicable"] = s;
      }
      text << "\nApproximations of the CoR at zero overlap (u = 0); compare with 'viscor cor'.\n"
           << "digits   " << decimal_digits<Real>() << " (working precision; the formulas' own error is far larger)\n";
      out = {text.str(), j};
    });
    return out;
  }
};

}  // namespace detail

/// The requested formulas at (gamma, g).
inline command_output run_approx(const approx_request& q) {
  if (q.order < 1 || q.order > 999) throw invalid_parameter("order must be from 1 to 999, got " + std::to_string(q.order));
  return detail::approx_job{q}.run();
}

}  // namespace viscor::jobs
