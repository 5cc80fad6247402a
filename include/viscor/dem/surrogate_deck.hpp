// The deck calibrated by a committed surrogate's inverse instead of the Taylor solve:
// `viscor dem --method surrogate`, in double. The contact and every convention are
// dem_deck_for's (complete_deck); only gamma0 comes from surrogate::cor_surrogate::gamma_for
// at the impact's scaled load, and the built-in conversion's e from the surrogate's e.
// The C export states these steps in C (jobs/dem_export.hpp): the same bits.
#pragma once

#include <viscor/dem/dem_calibration.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <cmath>
#include <string>

namespace viscor::dem {

/// Refuses a model the surrogates do not describe, the clamped force of YADE's laws, for
/// the continuous deck (the step-aware one needs only the unclamped bracket).
inline void require_surrogate_model(const dem_model& model) {
  if (model.clamped)
    throw invalid_parameter(VISCOR_FIELD("method") " surrogate: " + std::string(model.code_name) + " " +
                            std::string(model.damping_name) +
                            " clamps the contact force at zero, which the committed surrogates (of the unclamped "
                            "force) do not describe: use " VISCOR_FIELD("method") " solve, or give "
                            VISCOR_FIELD("timestep") " for the deck at the code's time step");
}

/// The scaled factors of the impact: gamma / gamma0, g and T, as core/scaling.hpp computes them.
inline scaled_parameters<double> surrogate_scaling(const dem_model& model, const hertz_contact<double>& contact,
                                                  const dem_impact<double>& impact) {
  physical_parameters<double> unit = physical_impact(contact, impact, 1.0);  // gamma = gamma0 * factor: factor
  return to_scaled(law_of(model), unit);
}

/// The deck of the model's law with the force unclamped, by the surrogate's inverse, for
/// any model: of a model that clamps (YADE's Hertz-Mindlin) not its deck, only the bracket
/// its stepped calibration starts from (calibrate_at_time_step doubles it until it holds),
/// which the C export can compute too. dem_deck_by_surrogate for the models it describes.
inline dem_deck<double> unclamped_deck_by_surrogate(const dem_model& model, const dem_impact<double>& impact,
                                                    double target_e, const surrogate::cor_surrogate& s) {
  check_deck_request(impact, target_e);
  if (!(target_e >= 0.01))
    throw invalid_parameter(VISCOR_FIELD("method") " surrogate: " VISCOR_FIELD("target_e") " must be in [0.01, 1), got " +
                            to_decimal_string(target_e));
  dem_deck<double> d;
  d.contact = model_contact(model, impact);
  const scaled_parameters<double> scale = surrogate_scaling(model, d.contact, impact);
  const double g = scale.g;
  if (!(g >= s.g_min && g <= s.g_max))
    throw unreachable_target(VISCOR_FIELD("method") " surrogate: the scaled load g = " + to_decimal_string(g) +
                             " of this impact is outside the surrogate's domain [" + to_decimal_string(s.g_min) +
                             ", " + to_decimal_string(s.g_max) + "]: use " VISCOR_FIELD("method") " solve");
  const double gamma = s.gamma_for(target_e, g);
  if (std::isnan(gamma))
    throw unreachable_target("target_e = " + to_decimal_string(target_e) + " is unreachable with " +
                             std::string(model.code_name) + " " + std::string(model.damping_name) +
                             " at this impact: no scaled damping in [0, " + to_decimal_string(s.gamma_max) +
                             "] gives it at g = " + to_decimal_string(g) + " (the surrogate's domain)");
  calibration_result<double> scaled;
  scaled.gamma = scaled.gamma_lo = scaled.gamma_hi = gamma;
  scaled.g = g;
  scaled.e = s(gamma, g).e;
  scaled.target_bound = std::abs(scaled.e - target_e) + s.bound.abs_e;  // the miss, plus the surrogate's own
  d.calibration.scaled = scaled;
  d.calibration.gamma0 = gamma / scale.gamma;
  d.calibration.time_scale = scale.time_scale;
  complete_deck(model, impact, target_e, d, [&](double entry) {
    const double gamma_of_entry = damping_number(model, entry) * damping_scale(model, d.contact) * scale.gamma;
    const surrogate::surrogate_value v = s(gamma_of_entry, g);
    return v.in_domain ? v.e : std::nan("");  // outside the domain: no value, as the C export's NaN
  });
  if (d.builtin_e && std::isnan(*d.builtin_e)) d.builtin_e.reset();
  return d;
}

/// The deck that reproduces target_e (in [0.01, 1)) at this impact by the surrogate's
/// inverse; unreachable_target when no gamma of the surrogate's domain gives it.
inline dem_deck<double> dem_deck_by_surrogate(const dem_model& model, const dem_impact<double>& impact,
                                              double target_e, const surrogate::cor_surrogate& s) {
  require_surrogate_model(model);
  return unclamped_deck_by_surrogate(model, impact, target_e, s);
}

}  // namespace viscor::dem
