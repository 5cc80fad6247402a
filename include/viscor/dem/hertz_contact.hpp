// The physical contact a DEM code should simulate: a sphere of Young's modulus E,
// Poisson ratio nu, radius R and density rho hitting a flat wall (rigid, or of a
// material of its own), or a second sphere (of the same material and size, or of
// its own). Hertz theory (core/elastic_contact.hpp) gives the elastic force
// k delta^(3/2) with k = (4/3) E* sqrt(R*):
//   wall:  1/E* = (1 - nu^2)/E + (1 - nu_w^2)/E_w (rigid: no second term), R* = R, m* = m
//   pair:  1/E* = (1 - nu^2)/E + (1 - nu_2^2)/E_2, 1/R* = 1/R + 1/R_2, 1/m* = 1/m + 1/m_2
// (m = (4/3) pi R^3 rho). For a pair, delta is the overlap of the two spheres and
// the motion is that of the relative coordinate with the reduced mass m*.
#pragma once

#include <viscor/core/elastic_contact.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>

#include <boost/math/constants/constants.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace viscor::dem {

/// What the bead hits.
enum class contact_kind { wall, pair };

/// "wall" or "pair", as in --contact.
inline std::string_view to_string(contact_kind kind) { return kind == contact_kind::wall ? "wall" : "pair"; }

/// Parses "wall" or "pair"; throws invalid_parameter naming `text` otherwise.
inline contact_kind parse_contact_kind(const std::string& text) {
  if (text == "wall") return contact_kind::wall;
  if (text == "pair") return contact_kind::pair;
  throw invalid_parameter("unknown contact '" + text + "': expected wall (sphere on a wall) or pair (two spheres)");
}

/// The bead's material and size in SI units.
template <class Real>
struct bead_material {
  Real youngs_modulus = 0;  ///< E, Pa
  Real poisson_ratio = 0;   ///< nu, in (-1, 1/2]
  Real radius = 0;          ///< R, m
  Real density = 0;         ///< rho, kg/m^3

  /// Throws invalid_parameter naming the first invalid field (after `prefix`: "other_" for the pair's other bead).
  void validate(const std::string& prefix = "") const {
    require_positive(youngs_modulus, prefix + "youngs_modulus");
    require_finite(poisson_ratio, prefix + "poisson_ratio");
    if (!(poisson_ratio > -1 && poisson_ratio <= Real(1) / 2))
      throw invalid_parameter("parameter " + prefix + "poisson_ratio must be in (-1, 0.5], got " +
                              to_decimal_string(poisson_ratio));
    require_positive(radius, prefix + "radius");
    require_positive(density, prefix + "density");
  }

  /// The bead's mass 4/3 pi R^3 rho, kg.
  Real mass() const { return sphere_mass(density, radius); }

  /// Its elastic constants.
  elastic_material<Real> elastic() const { return {youngs_modulus, poisson_ratio}; }

  /// It as a sphere of a Hertz contact.
  elastic_sphere<Real> sphere() const { return {elastic(), radius, mass()}; }
};

/// What the bead meets besides itself: the wall's material on a wall (none: rigid),
/// the other bead in a pair (none: a bead like this one).
template <class Real>
struct contact_partner {
  std::optional<elastic_material<Real>> wall;  ///< a wall of this material; nullopt: rigid
  std::optional<bead_material<Real>> other;    ///< the pair's other bead; nullopt: identical to the bead

  /// Throws invalid_parameter when a partner does not fit `kind` (the other bead on a wall, a wall in a pair).
  void validate(contact_kind kind) const {
    if (kind == contact_kind::wall && other)
      throw invalid_parameter("the other bead (" VISCOR_FIELD("other_youngs_modulus") ", ...) belongs to "
                              VISCOR_FIELD("contact") " pair, not to a wall");
    if (kind == contact_kind::pair && wall)
      throw invalid_parameter("a wall material (" VISCOR_FIELD("wall_youngs_modulus") ", ...) belongs to "
                              VISCOR_FIELD("contact") " wall, not to a pair");
    if (wall) wall->validate("wall");
    if (other) other->validate("other_");
  }
};

/// Effective quantities of the Hertz contact and the stiffness k of
/// F = k delta^(3/2) + (damping).
template <class Real>
struct hertz_contact {
  contact_kind kind = contact_kind::wall;
  Real effective_modulus = 0;  ///< E*, Pa
  Real effective_radius = 0;   ///< R*, m
  Real effective_mass = 0;     ///< m*, kg
  Real bead_mass = 0;          ///< m of one bead, kg
  Real stiffness = 0;          ///< k = (4/3) E* sqrt(R*), N/m^(3/2)
};

/// The Hertz contact of a bead (validated) with a wall or a second bead: E*, R*, m* and k.
template <class Real>
hertz_contact<Real> make_hertz_contact(const bead_material<Real>& bead, contact_kind kind,
                                       const contact_partner<Real>& partner = {}) {
  bead.validate();
  partner.validate(kind);
  hertz_contact<Real> c;
  c.kind = kind;
  const elastic_sphere<Real> sphere = bead.sphere();
  c.bead_mass = sphere.mass;
  std::optional<elastic_sphere<Real>> other;
  if (partner.other) other = partner.other->sphere();
  const hertz_effective<Real> h =
      kind == contact_kind::wall ? hertz_with_wall(sphere, partner.wall) : hertz_with_sphere(sphere, other);
  c.effective_modulus = h.modulus;
  c.effective_radius = h.radius;
  c.effective_mass = h.mass;
  c.stiffness = h.stiffness;
  const std::string from = "radius = " + to_decimal_string(bead.radius) + ", density = " +
                           to_decimal_string(bead.density) + ", youngs_modulus = " +
                           to_decimal_string(bead.youngs_modulus);
  require_representable_positive(c.effective_mass, "the bead's mass", from);
  require_representable_positive(c.effective_radius, "the effective radius", from);
  require_representable_positive(c.stiffness, "the Hertz stiffness k", from);
  return c;
}

}  // namespace viscor::dem
