// Hertz contact of two elastic bodies: a sphere on a flat wall, or two spheres.
// For spheres of radii R1, R2 pressed together by delta (Johnson, Contact Mechanics,
// section 4.2; a flat is a sphere of infinite radius and infinite mass):
//     F = k delta^(3/2),  k = (4/3) E* sqrt(R*),
//     1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2   (a rigid body adds nothing),
//     1/R* = 1/R1 + 1/R2,   1/m* = 1/m1 + 1/m2  (a wall: R* = R1, m* = m1).
// The relative coordinate of the two centres then moves like one bead of mass m*
// on a rigid wall of stiffness k, which is what viscor solves.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace viscor {

/// Elastic constants of a body: Young's modulus E > 0 (Pa), Poisson ratio -1 < nu <= 1/2.
template <class Real>
struct elastic_material {
  Real youngs_modulus = 0;
  Real poisson_ratio = 0;

  /// Throws invalid_parameter naming `where` and the invalid field.
  void validate(const std::string& where) const {
    require_positive(youngs_modulus, where + ".youngs_modulus");
    require_finite(poisson_ratio, where + ".poisson_ratio");
    if (!(poisson_ratio > -1 && poisson_ratio <= Real(1) / 2))
      throw invalid_parameter("parameter " + where + ".poisson_ratio must be in (-1, 0.5], got " +
                              to_decimal_string(poisson_ratio));
  }

  /// (1 - nu^2) / E, the body's share of 1/E*.
  Real compliance() const { return (1 - poisson_ratio * poisson_ratio) / youngs_modulus; }
  /// E / (1 - nu^2): E* against a rigid body (one rounding fewer than 1 / compliance()).
  Real plane_strain_modulus() const { return youngs_modulus / (1 - poisson_ratio * poisson_ratio); }
};

/// E* of two bodies; a rigid partner (nullopt) contributes nothing.
template <class Real>
Real effective_modulus(const elastic_material<Real>& bead, const std::optional<elastic_material<Real>>& partner) {
  Real compliance = bead.compliance();
  if (partner) compliance += partner->compliance();
  return 1 / compliance;
}

/// R* of a sphere of radius `radius` on a flat (nullopt) or on a sphere of radius `partner`.
template <class Real>
Real effective_radius(const Real& radius, const std::optional<Real>& partner) {
  return partner ? Real(radius * *partner / (radius + *partner)) : radius;
}

/// m* of a bead of mass `mass` on a wall (nullopt, which does not move) or on a bead of mass `partner`.
template <class Real>
Real reduced_mass(const Real& mass, const std::optional<Real>& partner) {
  return partner ? Real(mass * *partner / (mass + *partner)) : mass;
}

/// Hertz stiffness k = (4/3) E* sqrt(R*), N/m^(3/2).
template <class Real>
Real hertz_stiffness(const Real& effective_modulus_, const Real& effective_radius_) {
  using std::sqrt;
  return 4 * effective_modulus_ * sqrt(effective_radius_) / 3;
}

/// Mass of a sphere: rho (4/3) pi R^3.
template <class Real>
Real sphere_mass(const Real& density, const Real& radius) {  // NOTE: this order is the DEM decks' since their first release
  return 4 * boost::math::constants::pi<Real>() * radius * radius * radius * density / 3;
}

/// A sphere in a Hertz contact: its elastic constants, radius (m) and mass (kg).
template <class Real>
struct elastic_sphere {
  elastic_material<Real> material;
  Real radius = 0;
  Real mass = 0;
};

/// The effective quantities of a Hertz contact: E* (Pa), R* (m), m* (kg) and k (N/m^(3/2)).
template <class Real>
struct hertz_effective {
  Real modulus = 0;
  Real radius = 0;
  Real mass = 0;
  Real stiffness = 0;
};

/// The contact of `sphere` with a flat wall of material `wall` (nullopt: rigid). Every
/// command computes a material's contact here, so the same materials give the same bits.
template <class Real>
hertz_effective<Real> hertz_with_wall(const elastic_sphere<Real>& sphere, const std::optional<elastic_material<Real>>& wall) {
  hertz_effective<Real> h;
  h.modulus = wall ? effective_modulus(sphere.material, wall) : sphere.material.plane_strain_modulus();
  h.radius = sphere.radius;
  h.mass = sphere.mass;
  h.stiffness = hertz_stiffness(h.modulus, h.radius);
  return h;
}

/// The contact of `sphere` with a second sphere (nullopt: one like it): the relative motion.
template <class Real>
hertz_effective<Real> hertz_with_sphere(const elastic_sphere<Real>& sphere, const std::optional<elastic_sphere<Real>>& other) {
  hertz_effective<Real> h;
  if (other) {
    h.modulus = effective_modulus(sphere.material, std::optional<elastic_material<Real>>(other->material));
    h.radius = effective_radius(sphere.radius, std::optional<Real>(other->radius));
    h.mass = reduced_mass(sphere.mass, std::optional<Real>(other->mass));
  } else {  // the same values as with a copy of the sphere, with fewer roundings
    h.modulus = sphere.material.plane_strain_modulus() / 2;
    h.radius = sphere.radius / 2;
    h.mass = sphere.mass / 2;
  }
  h.stiffness = hertz_stiffness(h.modulus, h.radius);
  return h;
}

}  // namespace viscor
