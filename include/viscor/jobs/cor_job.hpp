// One impact as a job: run_cor is the whole of `viscor cor` for one point (scaled
// or physical inputs, optionally certified and proven) and returns a cor_result,
// numbers in the working type; solve_cor is its scaled core, also used by
// `viscor cor --points` and Python. Front ends render the result
// (jobs/cor_render.hpp), so the CLI, its JSON and Python cannot drift apart.
#pragma once

#include <viscor/jobs/cor_result.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#if defined(VISCOR_WITH_ENCLOSE)
#include <viscor/enclose/enclose.hpp>
#endif

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/impact/solve_impact.hpp>

#include <viscor/core/scaling.hpp>

#include <chrono>
#include <optional>
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
inline integration_method parse_integration_method(const std::string& text, const std::string& option = VISCOR_FIELD("method")) {
  if (text == "taylor") return integration_method::taylor;
  if (text == "adaptive") return integration_method::adaptive;
  throw invalid_parameter(option + " must be 'taylor' or 'adaptive', got '" + text + "'");
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
  bool certify = false;                 ///< add the certified digits (viscor::certify)
  bool prove = false;                   ///< add proven enclosures (needs viscor::enclose and scaled exact inputs)
};

namespace detail {

// --prove needs exact decimal inputs and rational exponents: checked before any work.
inline void check_provable(const contact_law& law, bool is_physical) {
  if (is_physical)
    throw invalid_parameter(VISCOR_FIELD("prove") " needs the scaled " VISCOR_FIELD("gamma") " and "
                            VISCOR_FIELD("g") " (exact decimals), not physical inputs");
  if (const std::string why = law.why_not_provable(); !why.empty()) throw invalid_parameter(why);
#if !defined(VISCOR_WITH_ENCLOSE)
  throw invalid_parameter(VISCOR_FIELD("prove")
                          ": this viscor was built without Arb (apt-get install libflint-arb-dev)");
#endif
}

}  // namespace detail

/// Solves one impact at scaled (gamma, g) in the working type Real, and with
/// `certify` certifies it (viscor::certify). `requested_digits`, when given, are the
/// digits asked for, so the result says when the arithmetic left their type.
template <class Real>
cor_result solve_cor(const contact_law& law, const Real& gamma, const Real& g, const solve_options<Real>& options,
                     bool certify = false, std::optional<int> requested_digits = std::nullopt) {
  const auto start = std::chrono::steady_clock::now();
  const impact_result<Real> r = solve_impact(law, gamma, g, options);
  cor_result out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  static_cast<impact_result<working_number>&>(out) = detail::erased(r);
  out.law = law;
  out.gamma = working_number::of(gamma), out.g = working_number::of(g);
  out.precision = precision_used::of<Real>(requested_digits);
  if (certify) out.certified = detail::erased(viscor::certify<Real>(law, gamma, g));
  return out;
}

/// The whole `viscor cor` job for one point: inputs checked, solved at the working
/// precision, optionally certified and proven.
inline cor_result run_cor(cor_request q) {
  const bool is_physical = q.physical.given();
  if (is_physical && (q.gamma || q.g))
    throw invalid_parameter("give either the physical inputs (" + q.physical.given_names() +
                            ") or the scaled " VISCOR_FIELD("gamma") "/" VISCOR_FIELD("g") ", not both");
  if (!is_physical && !q.gamma)
    throw invalid_parameter("cor needs " VISCOR_FIELD("gamma") " (and optionally " VISCOR_FIELD("g")
                            "), or the physical inputs " VISCOR_FIELD("m") " " VISCOR_FIELD("k") " "
                            VISCOR_FIELD("gamma0") " " VISCOR_FIELD("v0") " "
                            VISCOR_FIELD("gravity") " [" VISCOR_FIELD("force") "], or " VISCOR_FIELD("points") " FILE");
  if (is_physical) {
    q.physical.check("cor");
    q.physical.require_gamma0("cor");
  }
  if (q.prove) detail::check_provable(q.law, is_physical);
  cor_result out = with_working_precision(q.digits, [&]<class Real>() {
    Real gamma_value, g_value;
    std::optional<scaled_parameters<Real>> scales;
    std::optional<physical_parameters<Real>> bead;
    if (is_physical) {
      bead = q.physical.parameters<Real>(q.law);
      scales = to_scaled(q.law, *bead);
      gamma_value = scales->gamma, g_value = scales->g;
    } else {
      gamma_value = parse_real<Real>(*q.gamma, "gamma");
      g_value = q.g ? parse_real<Real>(*q.g, "g") : Real(0);
    }
    solve_options<Real> options;
    options.method = q.method;
    options.tolerance = parse_real<Real>(q.tolerance, "tolerance");
    options.max_steps = q.max_steps;
    cor_result r = solve_cor(q.law, gamma_value, g_value, options, q.certify, q.digits);
    if (scales) {
      physical_side side;
      side.inputs = q.physical;
      side.m = working_number::of(bead->m), side.k = working_number::of(bead->k);
      side.time_scale = working_number::of(scales->time_scale);
      side.length_scale = working_number::of(scales->length_scale);
      if (r.contact_time) side.contact_time_s = working_number::of(Real(*r.contact_time->as<Real>() * scales->time_scale));
      side.max_compression_m = working_number::of(Real(*r.max_compression.as<Real>() * scales->length_scale));
      r.physical = std::move(side);
    }
    return r;
  });
#if defined(VISCOR_WITH_ENCLOSE)
  if (q.prove) out.proof = viscor::enclose(q.law, *q.gamma, q.g ? *q.g : std::string("0"), q.digits);
#endif
  return out;
}

}  // namespace viscor::jobs
