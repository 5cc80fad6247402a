// Each code's entries as written into its input: the calibrated deck (dem_calibration.hpp)
// as the shortest decimals that read back as the same doubles, with the entries a code
// reads apart from the contact's (LAMMPS's and LIGGGHTS's like-bead pairs (1,1), (2,2))
// and the rigid-wall stand-ins of deck_convention.hpp.
#pragma once

#include <viscor/dem/deck_convention.hpp>
#include <viscor/dem/deck_snippet.hpp>
#include <viscor/dem/dem_calibration.hpp>

#include <optional>
#include <string>

namespace viscor::dem {

/// LAMMPS and LIGGGHTS read the like-bead entries apart from the contact's (pair_coeff, type pairs (1,1), (2,2))
/// on a wall and for two bead types.
template <class Real>
bool reads_like_beads_separately(const dem_model& model, const dem_impact<Real>& impact) {
  return model.code != dem_code::yade && (impact.kind == contact_kind::wall || impact.partner.other);
}

/// The impact of two beads like `bead` at the same approach speed without load (gravity drops out of a pair).
template <class Real>
dem_impact<Real> like_beads_impact(const dem_impact<Real>& impact, const bead_material<Real>& bead) {
  dem_impact<Real> pair = impact;
  pair.bead = bead;
  pair.kind = contact_kind::pair, pair.partner = {}, pair.gravity = 0, pair.force = 0;
  return pair;
}

/// The deck values as written into the input (deck_number), with the like-bead entries where the code
/// reads them apart, calibrated by make_deck(model, impact, target) as the contact's deck was
/// (dem_deck_for, or the surrogate's deck of dem/surrogate_deck.hpp).
template <class Real, class MakeDeck>
deck_strings deck_entries_for(const dem_model& model, const dem_impact<Real>& impact, const dem_deck<Real>& d,
                              const Real& target, MakeDeck make_deck) {
  deck_strings s;
  s.damping = deck_number(d.damping);
  s.wall_material = impact.partner.wall.has_value();
  auto put = [](std::optional<std::string>& to, const std::optional<Real>& value) {
    if (value) to = deck_number(*value);
  };
  if (d.stiffness) {  // YADE visco-elastic: the bead material's kn, cn; a rigid wall material
    s.stiffness = deck_number(*d.stiffness);
    if (impact.kind == contact_kind::wall) s.wall_youngs_modulus = yade_rigid_wall_viscel;
    return s;
  }
  s.youngs_modulus = deck_number(d.youngs_modulus);
  s.poisson_ratio = deck_number(d.poisson_ratio);
  put(s.wall_youngs_modulus, d.wall_youngs_modulus), put(s.wall_poisson_ratio, d.wall_poisson_ratio);
  if (s.wall_youngs_modulus && !d.wall_poisson_ratio) s.wall_youngs_modulus = liggghts_rigid_wall_modulus;
  put(s.other_youngs_modulus, d.other_youngs_modulus), put(s.other_poisson_ratio, d.other_poisson_ratio);
  put(s.cross_youngs_modulus, d.cross_youngs_modulus);
  if (reads_like_beads_separately(model, impact)) {
    const dem_deck<Real> like = make_deck(model, like_beads_impact(impact, impact.bead), target);
    if (impact.kind == contact_kind::wall) s.bead_bead_youngs_modulus = deck_number(like.youngs_modulus);
    s.bead_bead_damping = deck_number(like.damping);
    if (impact.partner.other)
      s.other_other_damping = deck_number(make_deck(model, like_beads_impact(impact, *impact.partner.other), target).damping);
  }
  return s;
}

/// deck_entries_for with the like-bead decks calibrated exactly (dem_deck_for).
template <class Real>
deck_strings deck_entries_for(const dem_model& model, const dem_impact<Real>& impact, const dem_deck<Real>& d,
                              const Real& target) {
  return deck_entries_for(model, impact, d, target, [](const dem_model& m, const dem_impact<Real>& i, const Real& t) {
    return dem_deck_for(m, i, t);
  });
}

}  // namespace viscor::dem
