// One impact as a job: run_cor is the whole of `viscor cor` for one point (scaled
// or physical inputs, optionally certified and proven) and returns a cor_result,
// numbers in the working type; solve_cor is its scaled core, also used by
// `viscor cor --points` and Python. Front ends render the result
// (jobs/cor_render.hpp), so the CLI, its JSON and Python cannot drift apart.
#pragma once

#include <viscor/jobs/cor_result.hpp>
#include <viscor/jobs/physical_inputs.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/impact/solve_impact.hpp>
#if VISCOR_HAS_QD
#include <viscor/core/double_double.hpp>
#endif

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
  /// At least this many certified digits of e, 1 - e, T_f and u_max: the working
  /// precision is chosen (certify/certified_digits_goal.hpp) and `digits` is not read.
  std::optional<int> certified_digits;
  bool certify = false;                 ///< add the certified digits (viscor::certify)
  bool prove = false;                   ///< add proven enclosures (needs viscor::enclose and scaled exact inputs)
};

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

/// Calls solve(working_digits), a certified cor_result, at rising precision until it
/// certifies `wanted` digits (certify/certified_digits_goal.hpp); the result carries the
/// runs in `goal`. Throws certified_digits_unreached when they fall short.
template <class Solve>
cor_result certify_cor_to_goal(int wanted, Solve&& solve) {
  certified_digits_goal goal;
  cor_result r = certify_to_goal(
      wanted, certify_options{}.safety_margin, solve,
      [](const cor_result& c) { return precision_run{c.certified->working_digits, c.certified->certified_digits}; },
      goal);
  r.goal = std::move(goal);
  return r;
}

/// The whole `viscor cor` job for one point: inputs checked, solved at the working
/// precision, optionally certified and proven; with certified_digits, solved and
/// certified at rising precision until the goal is met (result.goal says how), or
/// certified_digits_unreached.
cor_result run_cor(cor_request q);

// solve_cor for the types with_working_precision picks is compiled once (src/jobs/cor_job.cpp).
#define VISCOR_SOLVE_COR_TEMPLATE(EXTERN, Real)                                                  \
  EXTERN template cor_result solve_cor<Real>(const contact_law&, const Real&, const Real&,        \
                                             const solve_options<Real>&, bool, std::optional<int>);
#define VISCOR_SOLVE_COR_RUNTIME_TEMPLATES(EXTERN)                                               \
  VISCOR_SOLVE_COR_TEMPLATE(EXTERN, double)                                                      \
  VISCOR_SOLVE_COR_TEMPLATE(EXTERN, long double)                                                 \
  VISCOR_SOLVE_COR_DOUBLE_DOUBLE(EXTERN)                                                         \
  VISCOR_SOLVE_COR_QUAD(EXTERN)                                                                  \
  VISCOR_SOLVE_COR_MPFR(EXTERN)
#if VISCOR_HAS_QD
#define VISCOR_SOLVE_COR_DOUBLE_DOUBLE(EXTERN) VISCOR_SOLVE_COR_TEMPLATE(EXTERN, ::viscor::double_double)
#else
#define VISCOR_SOLVE_COR_DOUBLE_DOUBLE(EXTERN)
#endif
#if VISCOR_HAS_FLOAT128
#define VISCOR_SOLVE_COR_QUAD(EXTERN) VISCOR_SOLVE_COR_TEMPLATE(EXTERN, ::viscor::quad)
#else
#define VISCOR_SOLVE_COR_QUAD(EXTERN)
#endif
#if VISCOR_HAS_MPFR
#define VISCOR_SOLVE_COR_MPFR(EXTERN) VISCOR_SOLVE_COR_TEMPLATE(EXTERN, ::viscor::mpfr_real)
#else
#define VISCOR_SOLVE_COR_MPFR(EXTERN)
#endif
#ifndef VISCOR_COMPILING_INSTANTIATIONS
VISCOR_SOLVE_COR_RUNTIME_TEMPLATES(extern)
#endif

}  // namespace viscor::jobs
