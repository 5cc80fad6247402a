// From a measured e to the deck, and from a deck to the e it produces.
//
// Forward (dem_deck_for): the physical bead (make_hertz_contact) at impact speed
// v0 under gravity and a force F is calibrated exactly (calibrate_gamma0, the
// Taylor solve): gamma0 gives e = target. Then D = gamma0 / damping_scale and the
// deck entry is D itself or the e the code's own conversion turns into D.
// For models whose deck entry is an e, builtin_e is the e the code produces when
// the measured e is written there directly (the code's own conversion).
//
// Loads: for a wall the bead feels gravity + F/m towards the wall. For a pair,
// v0 is the approach speed, a uniform gravity moves both beads alike and drops
// out, and F presses the two together, so the relative motion feels F/m*.
#pragma once

#include <viscor/core/scaling.hpp>
#include <viscor/dem/deck_convention.hpp>
#include <viscor/impact/clamped_impact.hpp>
#include <viscor/impact/solve_impact.hpp>
#include <viscor/scenes/calibration.hpp>

#include <boost/math/tools/toms748_solve.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace viscor::dem {

/// One impact as a DEM code sees it: the bead's material, its speed, the load and the contact.
template <class Real>
struct dem_impact {
  bead_material<Real> bead;
  contact_kind kind = contact_kind::wall;
  contact_partner<Real> partner;  ///< the wall's material or the other bead (none: rigid wall, like bead)
  Real v0 = 0;       ///< impact (approach) speed, m/s
  Real gravity = 0;  ///< m/s^2 towards the wall (drops out for a pair)
  Real force = 0;    ///< N pressing the bead on the wall (or the pair together)
  Real stiffness = 0;  ///< the contact's linear stiffness kn, N/m (only models that take it: takes_linear_stiffness)
};

/// The contact the code should simulate: Hertz from the bead's material, or for a
/// linear-spring model the user's stiffness with the bead's mass (E and nu unused).
template <class Real>
hertz_contact<Real> model_contact(const dem_model& model, const dem_impact<Real>& impact) {
  if (!takes_linear_stiffness(model)) return make_hertz_contact(impact.bead, impact.kind, impact.partner);
  if (impact.partner.wall || impact.partner.other)
    throw invalid_parameter(std::string(model.code_name) + " " + std::string(model.damping_name) + " is a linear "
                            "spring of the contact's stiffness " VISCOR_FIELD("k")
                            ": a wall material or another bead does not enter it "
                            "(give the contact's kn as " VISCOR_FIELD("k") ")");
  require_positive(impact.stiffness, "k");
  require_positive(impact.bead.radius, "radius");
  require_positive(impact.bead.density, "density");
  hertz_contact<Real> c;
  const bool wall = impact.kind == contact_kind::wall;
  c.kind = impact.kind;
  c.bead_mass = impact.bead.mass();
  c.effective_radius = wall ? impact.bead.radius : Real(impact.bead.radius / 2);
  c.effective_mass = wall ? c.bead_mass : Real(c.bead_mass / 2);
  c.stiffness = impact.stiffness;  // F = k delta + damping; effective_modulus stays 0 (no Hertz modulus)
  const std::string from =
      "radius = " + to_decimal_string(impact.bead.radius) + ", density = " + to_decimal_string(impact.bead.density);
  require_representable_positive(c.effective_mass, "the bead's mass", from);
  require_representable_positive(c.effective_radius, "the effective radius", from);
  return c;
}

/// viscor's physical parameters for the impact (m = m*, see the header comment).
template <class Real>
physical_parameters<Real> physical_impact(const hertz_contact<Real>& c, const dem_impact<Real>& impact,
                                          const Real& gamma0) {
  physical_parameters<Real> p;
  p.m = c.effective_mass, p.k = c.stiffness, p.gamma0 = gamma0, p.v0 = impact.v0;
  p.gravity = impact.kind == contact_kind::wall ? impact.gravity : Real(0);
  p.force = impact.force;
  return p;
}

/// The e the code produces for a deck damping entry at this impact (exact solve).
template <class Real>
impact_result<Real> e_for_deck(const dem_model& model, const dem_impact<Real>& impact, const Real& deck_damping,
                               const solve_options<Real>& options = {}) {
  validate_deck_damping(model, deck_damping);
  const hertz_contact<Real> c = model_contact(model, impact);
  const Real gamma0 = damping_number(model, deck_damping) * damping_scale(model, c);
  const contact_law law = law_of(model);
  const scaled_parameters<Real> s = to_scaled(law, physical_impact(c, impact, gamma0));
  if (!model.clamped) return solve_impact(law, s.gamma, s.g, options);
  const clamped_impact_result<Real> clamped = solve_clamped_impact(law, s.gamma, s.g);
  impact_result<Real> r;
  r.e = clamped.e, r.one_minus_e = 1 - clamped.e, r.outcome = clamped.outcome;
  r.contact_time = clamped.contact_time, r.steps = clamped.steps;
  return r;
}

/// The calibration of a clamping model (impact/clamped_impact.hpp): the scaled gamma
/// whose clamped e is target_e at the scaled load g, by TOMS 748 on gamma (e falls
/// as gamma grows); unreachable_target when even gamma_max leaves e above the target.
template <class Real>
calibration_result<Real> calibrate_clamped_gamma(const contact_law& law, const Real& g, const Real& target_e,
                                                 const calibration_options<Real>& options) {
  calibration_result<Real> r;
  r.g = g;
  auto miss = [&](const Real& gamma) {
    ++r.solves;
    return Real(solve_clamped_impact(law, gamma, g).e - target_e);
  };
  Real hi = Real(1) / 4;
  while (miss(hi) > 0) {
    if (hi > options.gamma_max)
      throw unreachable_target("target_e = " + to_decimal_string(target_e) + " needs a scaled damping above " +
                               to_decimal_string(options.gamma_max) + " with the clamped force");
    hi *= 2;
  }
  // NOTE: gamma to 44 bits: e is a smooth function of gamma, so that is ~1e-13 in e,
  // and tighter brackets would only chase the solver's last-digit noise.
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(miss, Real(0), hi, Real(1 - target_e), miss(hi),
                                                         boost::math::tools::eps_tolerance<Real>(44), iterations);
  r.gamma_lo = bracket.first, r.gamma_hi = bracket.second;
  r.gamma = (bracket.first + bracket.second) / 2;
  r.e = solve_clamped_impact(law, r.gamma, g).e;
  if (!(r.e > 0))
    throw unreachable_target("target_e = " + to_decimal_string(target_e) +
                             " is unreachable with the clamped force at this load: the bead sticks first");
  using std::abs;
  r.target_bound = abs(r.e - target_e);
  return r;
}

/// The values to write into a DEM code's contact-model input, and what they reproduce.
template <class Real>
struct dem_deck {
  Real youngs_modulus = 0;  ///< deck E (or Y) of the bead
  std::optional<Real> wall_youngs_modulus;  ///< LIGGGHTS wall type's Y, YADE wall material's young (1e30: rigid)
  std::optional<Real> wall_poisson_ratio;   ///< the wall's nu, when it has a material
  std::optional<Real> other_youngs_modulus, other_poisson_ratio;  ///< the pair's other bead (type 2, second material)
  std::optional<Real> cross_youngs_modulus;  ///< LAMMPS, two bead types: the explicit pair_coeff 1 2 modulus
  Real poisson_ratio = 0;   ///< deck nu
  Real damping = 0;         ///< deck damping entry (a coefficient, or an e for restitution models)
  Real damping_number = 0;  ///< D, what the code multiplies the damping force by
  Real gamma0 = 0;          ///< viscor's physical damping (units that make k gamma0 d/dt(delta^beta) a force)
  hertz_contact<Real> contact;
  physical_calibration<Real> calibration;
  std::optional<Real> builtin_e;  ///< restitution models (and YADE's `en`): e when the target is written into the deck
  std::optional<Real> stiffness;  ///< YADE visco-elastic: the bead material's kn, N/m (the wall's: 1e30)
  std::optional<Real> builtin_tc;  ///< YADE visco-elastic: the tc that, with en = target, gives YADE's kn = k, s
};

/// Refuses a target or load no deck can be calibrated for, before any work.
template <class Real>
void check_deck_request(const dem_impact<Real>& impact, const Real& target_e) {
  require_finite(target_e, "target_e");
  if (!(target_e > 0 && target_e < 1))
    throw invalid_parameter("parameter target_e must be in (0, 1), got " + to_decimal_string(target_e));
  require_positive(impact.v0, "v0");
  require_gravity_towards_wall(impact.gravity);
  require_finite(impact.force, "force");
}

/// The exact calibration of the deck's contact: gamma0 whose e is target_e, by the
/// Taylor solve (or the clamped force's solve for models that clamp).
template <class Real>
physical_calibration<Real> calibrate_deck(const dem_model& model, const dem_impact<Real>& impact,
                                          const hertz_contact<Real>& contact, const Real& target_e,
                                          const calibration_options<Real>& options) {
  const contact_law law = law_of(model);
  const physical_parameters<Real> p = physical_impact(contact, impact, Real(0));
  if (!model.clamped) return calibrate_gamma0(law, p.m, p.k, p.v0, p.gravity, p.force, target_e, options);
  physical_parameters<Real> unit = p;
  unit.gamma0 = 1;  // scaled gamma is proportional to gamma0; g does not depend on it
  const scaled_parameters<Real> s = to_scaled(law, unit);
  physical_calibration<Real> c;
  c.scaled = calibrate_clamped_gamma(law, s.g, target_e, options);
  c.gamma0 = c.scaled.gamma / s.gamma;
  c.time_scale = s.time_scale;
  return c;
}

/// Everything of the deck after its calibration (d.contact and d.calibration set): the
/// damping number, the deck's damping entry, the moduli, and the e the code's own
/// conversion gives, by e_of_entry(deck damping entry) (the exact solve or a surrogate).
template <class Real, class EOfEntry>
void complete_deck(const dem_model& model, const dem_impact<Real>& impact, const Real& target_e, dem_deck<Real>& d,
                   EOfEntry e_of_entry) {
  d.gamma0 = d.calibration.gamma0;
  d.damping_number = d.gamma0 / damping_scale(model, d.contact);
  try {
    d.damping = deck_damping_for(model, d.damping_number);
  } catch (const unreachable_target& e) {
    throw unreachable_target("target_e = " + to_decimal_string(target_e) + " is unreachable with " +
                             std::string(model.code_name) + " " + std::string(model.damping_name) +
                             " at this impact: " + e.what());
  }
  if (takes_linear_stiffness(model)) {
    d.stiffness = yade_viscel_deck_stiffness(d.contact);
    // YADE's own conversion: ViscElMat(tc, en = target) with the tc that makes its kn = k;
    // its cn then comes from the reduced mass m/2 (also on a wall, where the bead's m moves).
    const Real reduced_mass = d.contact.bead_mass / 2;
    d.builtin_tc = yade_viscel_tc_for_stiffness(d.contact.stiffness, target_e, reduced_mass);
    const Real contact_cn = yade_viscel_from_tc_en(*d.builtin_tc, target_e, reduced_mass).cn;
    const Real deck_cn = impact.kind == contact_kind::wall ? contact_cn : Real(2 * contact_cn);
    d.builtin_e = e_of_entry(deck_cn);
    return;
  }
  d.youngs_modulus = deck_youngs_modulus(model, impact.bead, d.contact, impact.partner);
  d.poisson_ratio = impact.bead.poisson_ratio;
  if (model.code != dem_code::lammps && impact.kind == contact_kind::wall) {
    d.wall_youngs_modulus = wall_deck_modulus(model, impact.partner);
    if (impact.partner.wall) d.wall_poisson_ratio = impact.partner.wall->poisson_ratio;
  }
  if (impact.partner.other) {  // every code reads the other bead's own material; LAMMPS also a cross entry
    d.other_youngs_modulus = impact.partner.other->youngs_modulus;
    d.other_poisson_ratio = impact.partner.other->poisson_ratio;
    if (model.code == dem_code::lammps) d.cross_youngs_modulus = lammps_cross_modulus(d.contact, d.poisson_ratio);
  }
  if (model.deck_kind == deck_damping_kind::coefficient_of_restitution) d.builtin_e = e_of_entry(target_e);
  if (model.damping == damping_model::mindlin)  // the deck's `en` instead of betan: Thornton's fit
    d.builtin_e = e_of_entry(yade_thornton_betan(target_e));
}

/// The deck that reproduces target_e at this impact; unreachable_target when no
/// deck entry of the model can (the message says why).
template <class Real>
dem_deck<Real> dem_deck_for(const dem_model& model, const dem_impact<Real>& impact, const Real& target_e,
                            const calibration_options<Real>& options = {}) {
  check_deck_request(impact, target_e);
  dem_deck<Real> d;
  d.contact = model_contact(model, impact);
  d.calibration = calibrate_deck(model, impact, d.contact, target_e, options);
  complete_deck(model, impact, target_e, d,
                [&](const Real& entry) { return e_for_deck(model, impact, entry, options.solve).e; });
  return d;
}

/// The built-in conversion's miss in % of (1 - target_e): 100 (e - target)/(1 - target).
template <class Real>
Real percent_of_one_minus_e(const Real& e, const Real& target_e) {
  return Real(100 * (e - target_e) / (1 - target_e));
}

}  // namespace viscor::dem
