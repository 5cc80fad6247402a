// One impact as every front end reports it: the fields of `viscor cor --json`, of
// each line of `viscor cor --points` and of the Python module's viscor.cor come from
// here, so they cannot drift apart. run_cor is the whole job of `viscor cor` for
// one point: scaled or physical inputs, optionally certified and proven.
#pragma once

#include <viscor/core/field_names.hpp>
#include <viscor/jobs/certify_report.hpp>
#include <viscor/jobs/command_output.hpp>
#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#if defined(VISCOR_WITH_ENCLOSE)
#include <viscor/jobs/proof_report.hpp>
#endif

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <viscor/core/scaling.hpp>

#include <chrono>
#include <optional>
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
  j[field::method] = std::string(to_string(r.method));
  j[field::e] = number(r.e);
  j[field::one_minus_e] = number(r.one_minus_e);
  j[field::outcome] = std::string(to_string(r.outcome));
  j[field::contact_time] = number(r.contact_time);
  j[field::max_compression] = number(r.max_compression);
  if (r.outcome == impact_outcome::stick) j[field::stop_overlap] = number(r.stop_overlap);
  j[field::time_of_max_compression] = number(r.time_of_max_compression);
  j[field::energy_residual] = number(r.energy_residual);
  j[field::error_estimate] = number(r.error_estimate);
  j[field::steps] = r.steps;
  j[field::seconds] = seconds;
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

/// One impact: scaled gamma and g, or the physical inputs (with gamma0), as exact decimal text.
struct cor_request {
  contact_law law;
  std::optional<std::string> gamma, g;  ///< scaled inputs (g defaults to 0)
  physical_inputs physical;             ///< or these, converted by the report's scaling
  integration_method method = integration_method::taylor;
  std::string tolerance = "0";          ///< relative tolerance per step (0: the working precision)
  std::size_t max_steps = solve_options<double>{}.max_steps;
  int digits = 15;                      ///< working precision in decimal digits
  bool certify = false;                 ///< add the certified digits (certify_report.hpp)
  bool prove = false;                   ///< add proven enclosures (needs viscor::enclose and scaled exact inputs)
};

namespace detail {

// --prove needs exact decimal inputs and rational exponents: checked before any work.
inline void check_provable(const contact_law& law, bool is_physical) {
  if (is_physical)
    throw invalid_parameter("--prove needs the scaled --gamma and --g (exact decimals), not physical inputs");
  if (const std::string why = law.why_not_provable(); !why.empty()) throw invalid_parameter(why);
#if !defined(VISCOR_WITH_ENCLOSE)
  throw invalid_parameter("--prove: this viscor was built without Arb (apt-get install libflint-arb-dev)");
#endif
}

// A scaled contact time in seconds (time_scale T); unknown stays unknown.
template <class Real>
std::optional<Real> in_seconds(const std::optional<Real>& contact_time, const Real& time_scale) {
  if (!contact_time) return std::nullopt;
  return Real(*contact_time * time_scale);
}

// The readable summary of one solved impact (after the law and the physical inputs).
template <class Real>
void describe_impact(std::ostringstream& text, const impact_result<Real>& r, const Real& gamma, const Real& g,
                     const std::optional<scaled_parameters<Real>>& scales, double seconds) {
  text << "gamma      " << number(gamma) << "\n"
       << "g          " << number(g) << "\n"
       << "outcome    " << to_string(r.outcome)
       << (r.outcome == impact_outcome::undecided
               ? " (rebound or stick cannot be decided at this precision: e = 0 to within the error below)\n"
               : " (contact ends at zero overlap u = 0)\n")
       << "e          " << number(r.e) << "\n"
       << "1 - e      " << number(r.one_minus_e) << "\n"
       << (r.outcome == impact_outcome::rebound ? "T_f        " : "T_stop     ")
       << (r.outcome == impact_outcome::undecided ? std::string("unknown") : number(r.contact_time)) << " (scaled)\n";
  if (scales && r.outcome != impact_outcome::undecided)
    text << "time       " << number(in_seconds(r.contact_time, scales->time_scale)) << " s (contact)\n";
  text << "u_max      " << number(r.max_compression) << " at tau = " << number(r.time_of_max_compression) << "\n"
       << (r.outcome == impact_outcome::stick
               ? "u_stop     " + number(r.stop_overlap) + " (where u' returns to 0, or the rest position)\n"
               : std::string())
       << "error      " << to_decimal_string(r.error_estimate, 3) << " (estimated, absolute, on e)\n"
       << "energy     " << to_decimal_string(r.energy_residual, 3) << " (residual of identity (6))\n"
       << "steps      " << r.steps << " (" << to_string(r.method) << ")\n"
       << "seconds    " << seconds << " s\n"
       << "digits     " << decimal_digits<Real>() << " (working precision)\n";
}

}  // namespace detail

/// The whole `viscor cor` job for one point: inputs checked, solved at the working
/// precision, optionally certified and proven.
inline command_output run_cor(cor_request q) {
  const bool is_physical = q.physical.given();
  if (is_physical && (q.gamma || q.g))
    throw invalid_parameter("give either the physical inputs (" + q.physical.given_names() +
                            ") or the scaled --gamma/--g, not both");
  if (!is_physical && !q.gamma)
    throw invalid_parameter("cor needs --gamma (and optionally --g), or the physical inputs --m --k --gamma0 --v0 "
                            "--gravity [--force], or --points FILE");
  if (is_physical) {
    q.physical.check("cor");
    if (!q.physical.gamma0) throw invalid_parameter("cor: physical mode needs --gamma0 (the damping coefficient, SI)");
  }
  if (q.prove) detail::check_provable(q.law, is_physical);
  command_output out;
  with_working_precision(q.digits, [&]<class Real>() {
    json& j = out.object;
    j["command"] = "cor";
    j["law"] = law_json(q.law);
    std::ostringstream text;
    text << "law        " << q.law.describe() << "\n";
    Real gamma_value, g_value;
    std::optional<scaled_parameters<Real>> scales;
    if (is_physical) {
      const physical_parameters<Real> p = q.physical.parameters<Real>(q.law);
      scales = to_scaled(q.law, p);
      gamma_value = scales->gamma, g_value = scales->g;
      j["physical"] = q.physical.echo();
      j["time_scale_s"] = number(scales->time_scale);
      j["length_scale_m"] = number(scales->length_scale);
      text << "physical   " << q.physical.echo_text() << "\n";
      if (q.physical.has_material())  // the bead's mass and stiffness are computed, not typed
        text << (q.physical.is_pair() ? "pair       m* = " : "bead       m = ") << to_decimal_string(p.m, 10)
             << " kg, k = " << to_decimal_string(p.k, 10)
             << (q.physical.is_pair() ? " N/m^(3/2) (the relative motion's reduced mass and stiffness, from the "
                                        "materials)\n"
                                      : " N/m^(3/2) (from the material)\n");
    } else {
      gamma_value = parse_real<Real>(*q.gamma, "gamma");
      g_value = q.g ? parse_real<Real>(*q.g, "g") : Real(0);
    }
    solve_options<Real> options;
    options.method = q.method;
    options.tolerance = parse_real<Real>(q.tolerance, "tolerance");
    options.max_steps = q.max_steps;

    const auto start = std::chrono::steady_clock::now();
    const impact_result<Real> r = solve_impact(q.law, gamma_value, g_value, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    j["gamma"] = number(gamma_value);
    j["g"] = number(g_value);
    j["precision"] = scalar_json<Real>(q.digits);
    add_result_json(j, r, seconds);
    if (scales) {
      j[field::contact_time_s] = number(detail::in_seconds(r.contact_time, scales->time_scale));
      j[field::max_compression_m] = number(Real(r.max_compression * scales->length_scale));
    }
    detail::describe_impact(text, r, gamma_value, g_value, scales, seconds);
    if (q.certify) certify_and_report<Real>(q.law, gamma_value, g_value, text, j);
#if defined(VISCOR_WITH_ENCLOSE)
    if (q.prove) add_proof(q.law, *q.gamma, q.g ? *q.g : std::string("0"), q.digits, text, j);
#endif
    out.text = text.str();
  });
  return out;
}

}  // namespace viscor::jobs
