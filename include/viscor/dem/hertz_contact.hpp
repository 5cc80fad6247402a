// The physical contact a DEM code should simulate: a sphere of Young's modulus E,
// Poisson ratio nu, radius R and density rho hitting a rigid flat wall, or an
// identical sphere. Hertz theory gives the elastic force k delta^(3/2) with
//   k = (4/3) E* sqrt(R*),
//   wall: E* = E / (1 - nu^2),        R* = R,     m* = m
//   pair: E* = E / (2 (1 - nu^2)),    R* = R / 2, m* = m / 2
// (m = (4/3) pi R^3 rho). For a pair, delta is the overlap of the two spheres and
// the motion is that of the relative coordinate with the reduced mass m*.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>

#include <boost/math/constants/constants.hpp>

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
  throw invalid_parameter("unknown contact '" + text + "': expected wall (sphere on a rigid wall) or pair (two identical spheres)");
}

/// The bead's material and size in SI units.
template <class Real>
struct bead_material {
  Real youngs_modulus = 0;  ///< E, Pa
  Real poisson_ratio = 0;   ///< nu, in (-1, 1/2]
  Real radius = 0;          ///< R, m
  Real density = 0;         ///< rho, kg/m^3

  /// Throws invalid_parameter naming the first invalid field.
  void validate() const {
    require_positive(youngs_modulus, "youngs_modulus");
    require_finite(poisson_ratio, "poisson_ratio");
    if (!(poisson_ratio > -1 && poisson_ratio <= Real(1) / 2))
      throw invalid_parameter("parameter poisson_ratio must be in (-1, 0.5], got " + to_decimal_string(poisson_ratio));
    require_positive(radius, "radius");
    require_positive(density, "density");
  }

  /// The bead's mass 4/3 pi R^3 rho, kg.
  Real mass() const {
    return 4 * boost::math::constants::pi<Real>() * radius * radius * radius * density / 3;
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

/// The Hertz contact of a bead (validated) with a rigid wall or an identical bead: E*, R*, m* and k.
template <class Real>
hertz_contact<Real> make_hertz_contact(const bead_material<Real>& bead, contact_kind kind) {
  using std::sqrt;
  bead.validate();
  hertz_contact<Real> c;
  c.kind = kind;
  c.bead_mass = bead.mass();
  const Real plane_strain_modulus = bead.youngs_modulus / (1 - bead.poisson_ratio * bead.poisson_ratio);
  const bool wall = kind == contact_kind::wall;
  c.effective_modulus = wall ? plane_strain_modulus : Real(plane_strain_modulus / 2);
  c.effective_radius = wall ? bead.radius : Real(bead.radius / 2);
  c.effective_mass = wall ? c.bead_mass : Real(c.bead_mass / 2);
  c.stiffness = 4 * c.effective_modulus * sqrt(c.effective_radius) / 3;
  const std::string from = "radius = " + to_decimal_string(bead.radius) + ", density = " +
                           to_decimal_string(bead.density) + ", youngs_modulus = " +
                           to_decimal_string(bead.youngs_modulus);
  require_representable_positive(c.effective_mass, "the bead's mass", from);
  require_representable_positive(c.effective_radius, "the effective radius", from);
  require_representable_positive(c.stiffness, "the Hertz stiffness k", from);
  return c;
}

}  // namespace viscor::dem
