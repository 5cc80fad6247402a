// How each code turns its deck entries into the force on the overlap delta, read
// from the source of the installed version and checked by a one-step force test
// in the real program (tests/dem/static_force_data.hpp):
//
// LAMMPS 29 Sep 2021 (pair granular / fix wall/gran granular, hertz/material E damp nu):
//   F = K sqrt(R* delta) delta + D P delta^(beta-1) d(delta)/dt, K = (4/3) E*_code,
//   pair: E*_code = 1 / ((1-nu^2)/E + (1-nu^2)/E) = E / (2 (1 - nu^2))  (standard);
//   wall: E*_code = E / (2 (1 - nu))  (NOT the documented E / (1 - nu^2): a rigid
//         wall needs deck E = 2 E / (1 + nu));
//   velocity D = damp, P = 1; mass_velocity P = m*; viscoelastic P = m* sqrt(R*);
//   tsuji D = eta'(damp) (builtin_conversions.hpp), P = sqrt(m* k).
// LIGGGHTS 3.8.0 (model hertz, youngsModulus/poissonsRatio per type, coefficientRestitution):
//   F = (4/3) Y* sqrt(R* delta) delta + 2 sqrt(5/6) |b| sqrt(2 Y* sqrt(R* delta) m*) d(delta)/dt,
//   Y* = 1 / ((1-nu_i^2)/Y_i + (1-nu_j^2)/Y_j) also for the wall, whose particle
//   type has its own Y and nu (so a wall type of the bead's material halves E*);
//   a wall type with Y = 1e30 is rigid. The damping is D P delta^(1/4) delta' with
//   D = |b(e)|, P = sqrt(5) sqrt(m* k).
// YADE 2023.02a (Ip2_FrictMat_FrictMat_MindlinPhys(betan), Law2_ScGeom_MindlinPhys_Mindlin):
//   F = max(0, kno delta^(3/2) + 2 betan sqrt(mbar (3/2) kno sqrt(delta)) d(delta)/dt),
//   kno = (4/3) E* sqrt(R*), E* = 1 / ((1-nu_a^2)/E_a + (1-nu_b^2)/E_b), R* = R_a R_b / (R_a + R_b),
//   where a wall (utils.wall, Ig2_Wall_Sphere_ScGeom) counts with the sphere's radius
//   (refR1 = refR2 = R): R* = R/2 on a wall. mbar = the dynamic body's mass when the
//   other is not dynamic, else m1 m2 / (m1 + m2). A wall material with E = 1e30 is
//   rigid, and the deck E = sqrt(2) E makes kno the physical k. D = betan,
//   P = sqrt(6) sqrt(m* k); the clamp at zero is impact/clamped_impact.hpp.
// YADE 2023.02a (ViscElMat(kn, cn, ks, cs), Ip2_ViscElMat_ViscElMat_ViscElPhys,
// Law2_ScGeom_ViscElPhys_Basic): F = max(0, kn delta + cn d(delta)/dt), a linear spring
//   whose contact kn, cn are the harmonic combinations 1/(1/x1 + 1/x2) of the two
//   materials' values: a wall material with kn = cn = 1e30 is rigid (the contact
//   takes the bead's values), two beads of one material take half of each. The
//   stiffness is the user's (--k = the contact's kn); D = the bead material's cn,
//   P = 1 on a wall, 1/2 for a pair; alpha = beta = 1, gamma0 = D P / k.
#pragma once

#include <viscor/dem/builtin_conversions.hpp>
#include <viscor/dem/dem_model.hpp>
#include <viscor/dem/hertz_contact.hpp>

namespace viscor::dem {

/// A wall type modulus that makes a LIGGGHTS wall rigid to double precision:
/// (1 - nu^2)/1e30 is below 1e-17 of (1 - nu^2)/E for any E < 1e13 Pa.
inline constexpr const char* liggghts_rigid_wall_modulus = "1e30";

/// kn and cn of a YADE ViscElMat wall material that make the wall rigid: the contact's
/// 1/(1/kn + 1e-30) is kn to double precision for any kn < 1e14 N/m (likewise cn).
inline constexpr const char* yade_rigid_wall_viscel = "1e30";

/// The Young's modulus to write in the deck for the bead so that the code's
/// stiffness is the physical k of make_hertz_contact (Poisson ratio unchanged).
/// LAMMPS' wall reads only its own entry (E*_code = E_deck / (2 (1 - nu))), so the
/// wall entry carries the contact's E*: E_deck = 2 (1 - nu) E* (2 E / (1 + nu) on a
/// rigid wall); LIGGGHTS' wall is a particle type of its own (wall_deck_modulus);
/// YADE takes R* = R/2 on a wall, so both of its moduli are scaled by sqrt(2).
template <class Real>
Real deck_youngs_modulus(const dem_model& model, const bead_material<Real>& bead, const hertz_contact<Real>& contact,
                         const contact_partner<Real>& partner = {}) {
  using std::sqrt;
  if (contact.kind == contact_kind::wall && model.code == dem_code::lammps)
    return partner.wall ? Real(2 * (1 - bead.poisson_ratio) * contact.effective_modulus)
                        : Real(2 * bead.youngs_modulus / (1 + bead.poisson_ratio));
  if (contact.kind == contact_kind::wall && model.code == dem_code::yade)  // R* = R/2 on a YADE wall
    return Real(sqrt(Real(2)) * bead.youngs_modulus);
  return bead.youngs_modulus;
}

/// LIGGGHTS' wall type and YADE's wall material: the wall's own modulus (times
/// sqrt(2) in YADE, as the bead's), or a modulus that makes the wall rigid.
template <class Real>
Real wall_deck_modulus(const dem_model& model, const contact_partner<Real>& partner) {
  using std::sqrt;
  if (!partner.wall) return parse_real<Real>(liggghts_rigid_wall_modulus, "wall youngs_modulus");
  return model.code == dem_code::yade ? Real(sqrt(Real(2)) * partner.wall->youngs_modulus)
                                      : partner.wall->youngs_modulus;
}

/// LAMMPS 29 Sep 2021 mixes hertz/material entries of two types wrongly (its
/// mix_stiffnessE reads the Poisson ratio as a shear modulus: measured, a force of
/// 204 N instead of 0.0067 N), so two bead types need an explicit cross entry
/// `pair_coeff 1 2`, which the code combines with itself: E_deck = 2 (1 - nu^2) E*.
template <class Real>
Real lammps_cross_modulus(const hertz_contact<Real>& contact, const Real& nu) {
  return Real(2 * (1 - nu * nu) * contact.effective_modulus);
}

/// The code's own E* for a deck modulus (and, for a LIGGGHTS or YADE wall, the wall
/// type's modulus and Poisson ratio): what the program computes, referred to the
/// physical R* (YADE's wall uses R/2, so its E* is divided by sqrt(2) here).
template <class Real>
Real code_effective_modulus(const dem_model& model, const Real& deck_modulus, const Real& nu, contact_kind kind,
                            const Real& wall_modulus = Real(0), const Real& wall_nu = Real(0)) {
  if (kind == contact_kind::pair) return Real(deck_modulus / (2 * (1 - nu * nu)));
  using std::sqrt;
  if (model.code == dem_code::lammps) return Real(deck_modulus / (2 * (1 - nu)));
  const Real pair_modulus = 1 / ((1 - nu * nu) / deck_modulus + (1 - wall_nu * wall_nu) / wall_modulus);
  if (model.code == dem_code::yade) return Real(pair_modulus / sqrt(Real(2)));
  return pair_modulus;
}

/// gamma0 per unit damping number D: gamma0 = D * damping_scale = D P / (beta k).
template <class Real>
Real damping_scale(const dem_model& model, const hertz_contact<Real>& c) {
  using std::sqrt;
  const Real& k = c.stiffness;
  const Real& m = c.effective_mass;
  switch (model.damping) {
    case damping_model::velocity: return Real(1 / k);
    case damping_model::mass_velocity: return Real(m / k);
    case damping_model::viscoelastic: return Real(2 * m * sqrt(c.effective_radius) / (3 * k));
    case damping_model::tsuji: return Real(4 * sqrt(m * k) / (5 * k));
    case damping_model::hertz_restitution: return Real(4 * sqrt(Real(5)) * sqrt(m * k) / (5 * k));
    case damping_model::mindlin: return Real(4 * sqrt(Real(6)) * sqrt(m * k) / (5 * k));
    case damping_model::yade_viscoelastic:  // two beads of the deck's material: the contact's cn is half of it
      return c.kind == contact_kind::wall ? Real(1 / k) : Real(1 / (2 * k));
  }
  throw invalid_parameter("damping_scale: unknown damping model");
}

/// YADE visco-elastic: the bead material's kn that gives the contact stiffness k
/// (k on a rigid wall; 2 k for two beads of the material).
template <class Real>
Real yade_viscel_deck_stiffness(const hertz_contact<Real>& c) {
  return c.kind == contact_kind::wall ? c.stiffness : Real(2 * c.stiffness);
}

/// YADE visco-elastic: the normal force the code computes at overlap delta > 0 and
/// overlap rate delta_rate (> 0 approaching) for the materials' kn, cn (the wall's on
/// a wall; for a pair both beads carry the bead's): harmonic combinations, clamped at 0.
template <class Real>
Real yade_viscel_normal_force(contact_kind kind, const Real& kn, const Real& cn, const Real& wall_kn,
                              const Real& wall_cn, const Real& delta, const Real& delta_rate) {
  auto combine = [](const Real& a, const Real& b) { return Real(1 / (1 / a + 1 / b)); };
  const bool wall = kind == contact_kind::wall;
  const Real force = combine(kn, wall ? wall_kn : kn) * delta + combine(cn, wall ? wall_cn : cn) * delta_rate;
  return force < 0 ? Real(0) : force;
}

/// The damping number D the code uses for a deck damping entry.
template <class Real>
Real damping_number(const dem_model& model, const Real& deck_damping) {
  switch (model.damping) {
    case damping_model::tsuji: return lammps_tsuji_damping(deck_damping);
    case damping_model::hertz_restitution: return liggghts_damping_ratio(deck_damping);
    default: return deck_damping;
  }
}

/// The deck damping entry that makes the code use damping number D.
template <class Real>
Real deck_damping_for(const dem_model& model, const Real& damping) {
  switch (model.damping) {
    case damping_model::tsuji: return lammps_tsuji_deck_e(damping);
    case damping_model::hertz_restitution: return liggghts_deck_e(damping);
    default: return damping;
  }
}

/// Checks a deck damping entry: a coefficient must be >= 0, an e in (0, 1].
template <class Real>
void validate_deck_damping(const dem_model& model, const Real& value) {
  require_finite(value, "deck damping");
  if (model.deck_kind == deck_damping_kind::coefficient) {
    require_non_negative(value, "deck damping");
    return;
  }
  const bool lammps = model.code == dem_code::lammps;  // tsuji's polynomial is defined at e = 0; LIGGGHTS' ln is not
  if (!((lammps ? value >= 0 : value > 0) && value <= 1))
    throw invalid_parameter("deck damping is a coefficient of restitution for " + std::string(model.code_name) + " " +
                            std::string(model.damping_name) + " and must be in " + (lammps ? "[0, 1]" : "(0, 1]") +
                            ", got " + to_decimal_string(value));
}

/// The normal force the code computes for its deck entries (deck modulus and
/// Poisson ratio, deck damping entry) at overlap delta > 0 and overlap rate
/// delta_rate (> 0 approaching): F = k_code delta^(3/2) + D P delta^(beta-1) delta_rate
/// (clamped at 0 for models that clamp),
/// with P from the code's own k_code. Used to check the conventions against
/// forces printed by the real programs.
template <class Real>
Real code_normal_force(const dem_model& model, const bead_material<Real>& bead, contact_kind kind,
                       const Real& deck_modulus, const Real& deck_damping, const Real& delta, const Real& delta_rate,
                       const Real& wall_modulus = Real(0), const Real& wall_nu = Real(0)) {
  using std::pow;
  using std::sqrt;
  hertz_contact<Real> c = make_hertz_contact(bead, kind);
  c.effective_modulus = code_effective_modulus(model, deck_modulus, bead.poisson_ratio, kind, wall_modulus, wall_nu);
  c.stiffness = 4 * c.effective_modulus * sqrt(c.effective_radius) / 3;
  const contact_law law = law_of(model);
  const Real beta = law.beta.value<Real>();
  const Real gamma0 = damping_number(model, deck_damping) * damping_scale(model, c);
  // viscor's form: k delta^(3/2) + gamma0 k d/dt(delta^beta) = k delta^(3/2) + gamma0 k beta delta^(beta-1) delta'
  const Real force = c.stiffness * delta * sqrt(delta) + gamma0 * c.stiffness * beta * pow(delta, beta - 1) * delta_rate;
  return model.clamped && force < 0 ? Real(0) : force;
}

}  // namespace viscor::dem
