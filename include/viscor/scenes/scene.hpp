// Scenes: a bead, a wall, a contact law, a damping, a load and a list of impact
// speeds, evaluated impact by impact to a stated tolerance (evaluate.hpp).
//
// The bead is given either by its mass m and contact stiffness k directly, or by
// density rho, radius R, Young's modulus E1 and Poisson ratio nu1 against a wall
// (E2, nu2, or rigid) or, with contact "pair", a second bead (like the first, or
// of its own material and size). Then (Hertz, core/elastic_contact.hpp)
//     F = k delta^(3/2),  k = (4/3) E* sqrt(R*),  1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,
// with the wall's term dropped for a rigid wall, R* = R and m = rho (4/3) pi R^3 on a
// wall, and the reduced R* and m* of the two beads in a pair, where a uniform gravity
// drops out of the relative motion. This stiffness exists only for alpha = 3/2. Damping is gamma0 directly, or calibrated (calibration.hpp) from a
// CoR measured at a stated impact speed, gravity and force.
//
// Every impact is converted to (gamma, g) by eq. (2) at the working precision and
// evaluated with error bound <= tolerance; the contact time is T_f times the time
// scale T of eq. (2). The bound covers e (or 1 - e) at the scaled parameters as
// computed, not the uncertainty of the inputs themselves.
//
// Inputs are decimal text (scene_description), so that one description serves
// every precision; resolve_scene parses it at the working precision of Real.
#pragma once

#include <viscor/scenes/calibration.hpp>
#include <viscor/core/contact_law.hpp>
#include <viscor/core/elastic_contact.hpp>
#include <viscor/scenes/evaluate.hpp>
#include <viscor/scenes/spaced_range.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/parameters.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace viscor {

/// The most impacts one scene evaluates (a range's count): each impact is a row held in
/// memory, so a count of 10^9 would ask for gigabytes before the first solve.
inline constexpr std::size_t max_scene_impacts = 10'000'000;

/// A scene as decimal text, as read from a file (field names are those of the
/// JSON format, docs/scenes.md). Exactly one of (mass, stiffness) and
/// (density, radius, youngs_modulus, poisson_ratio) describes the bead; exactly one
/// of gamma0 and measured_e the damping.
struct scene_description {
  contact_law law;
  std::optional<std::string> mass, stiffness;
  std::optional<std::string> density, radius, youngs_modulus, poisson_ratio;
  std::optional<std::string> wall_youngs_modulus, wall_poisson_ratio;  ///< neither: a rigid wall
  bool pair = false;  ///< contact "pair": the bead meets a second bead, not a wall
  /// The pair's other bead ("other" in the file); none: a bead like the first.
  std::optional<std::string> other_density, other_radius, other_youngs_modulus, other_poisson_ratio;
  std::optional<std::string> gamma0;
  std::optional<std::string> measured_e, measured_speed, measured_gravity, measured_force;
  std::string gravity = "0", force = "0";
  std::vector<std::string> velocities;  ///< explicit impact speeds, m/s
  /// Or a range: count speeds from..to, linear or logarithmic spacing.
  std::optional<std::string> velocity_from, velocity_to;
  std::size_t velocity_count = 0;
  bool velocity_log = false;
  std::string tolerance;
  bool relative = false;      ///< bound relative on 1 - e
  bool contact_time = false;  ///< only methods that compute the contact time
};

/// Decimal digits a scene at `tolerance` works with: the tolerance's digits plus
/// 3 (evaluate's own first choice), at least double's; plus `extra`.
inline int scene_digits(const std::string& tolerance, int extra = 3) {
  if (!detail::looks_like_decimal(tolerance))
    throw invalid_parameter("parameter tolerance must be a decimal number, got '" + tolerance + "'");
  const long double t = std::strtold(tolerance.c_str(), nullptr);
  if (!(t > 0)) throw invalid_parameter("parameter tolerance must be > 0, got " + tolerance);
  const int needed = static_cast<int>(std::ceil(-std::log10(t) - 1e-9L)) + extra;  // 1e-12 -> 12, not 13
  return needed > 15 ? needed : 15;
}

/// How gamma0 was calibrated (decimal text at the calibration's precision).
struct scene_calibration {
  std::string gamma0, gamma, g, target_bound;
  int working_digits = 0;  ///< the calibration's working precision (written as precision.digits)
};

/// A scene parsed and resolved at the working precision of Real.
template <class Real>
struct resolved_scene {
  contact_law law;
  Real mass = 0, stiffness = 0, gamma0 = 0, gravity = 0, force = 0, tolerance = 0;
  bool relative = false, contact_time = false;
  std::vector<Real> velocities;
  bool stiffness_from_material = false;
  std::optional<scene_calibration> calibration;  ///< when gamma0 was calibrated
};

namespace detail {
template <class Real>
Real scene_number(const std::optional<std::string>& text, const std::string& field) {
  if (!text) throw invalid_parameter("scene: missing field " + field);
  return parse_real<Real>(*text, field);
}
}  // namespace detail

/// Validates a description and resolves the bead (m, k) and the damping gamma0
/// (calibrated if a measured CoR is given). Errors name the field.
template <class Real>
resolved_scene<Real> resolve_scene(const scene_description& d) {
  using detail::scene_number;
  resolved_scene<Real> s;
  d.law.validate();
  s.law = d.law;
  s.tolerance = parse_real<Real>(d.tolerance, "tolerance");
  require_positive(s.tolerance, "tolerance");
  s.relative = d.relative, s.contact_time = d.contact_time;

  // Bead.
  const bool direct = d.mass || d.stiffness;
  const bool material = d.density || d.radius || d.youngs_modulus || d.poisson_ratio;
  if (direct == material)
    throw invalid_parameter(direct ? "scene: give the bead either as bead.m and bead.k or as "
                                     "bead.density, radius, youngs_modulus and poisson_ratio, not both"
                                   : "scene: missing field bead (bead.m and bead.k, or bead.density, "
                                     "radius, youngs_modulus and poisson_ratio)");
  const bool wall = d.wall_youngs_modulus || d.wall_poisson_ratio;
  const bool other = d.other_density || d.other_radius || d.other_youngs_modulus || d.other_poisson_ratio;
  if (wall && d.pair) throw invalid_parameter("scene: a wall material belongs to contact \"wall\", not \"pair\"");
  if (other && !d.pair) throw invalid_parameter("scene: field other (the second bead) needs contact \"pair\"");
  if (direct) {
    if (wall) throw invalid_parameter("scene: a wall material needs the bead as a material, not bead.k");
    if (d.pair) throw invalid_parameter("scene: contact \"pair\" needs the beads as materials, not bead.k");
    s.mass = scene_number<Real>(d.mass, "bead.m");
    s.stiffness = scene_number<Real>(d.stiffness, "bead.k");
    require_positive(s.mass, "bead.m");
    require_positive(s.stiffness, "bead.k");
  } else {
    if (!(d.law.alpha == exponent::rational(3, 2)))
      throw invalid_parameter("scene: a Hertz stiffness from bead.youngs_modulus holds only for alpha = 3/2, the law "
                              "has alpha = " + d.law.alpha.to_string() + "; give bead.k instead");
    const Real density = scene_number<Real>(d.density, "bead.density");
    const Real radius = scene_number<Real>(d.radius, "bead.radius");
    require_positive(density, "bead.density");
    require_positive(radius, "bead.radius");
    elastic_material<Real> bead{scene_number<Real>(d.youngs_modulus, "bead.youngs_modulus"),
                                scene_number<Real>(d.poisson_ratio, "bead.poisson_ratio")};
    bead.validate("bead");
    std::optional<elastic_material<Real>> w;
    if (wall) {
      w = elastic_material<Real>{scene_number<Real>(d.wall_youngs_modulus, "wall.youngs_modulus"),
                                 scene_number<Real>(d.wall_poisson_ratio, "wall.poisson_ratio")};
      w->validate("wall");
    }
    const elastic_sphere<Real> sphere{bead, radius, sphere_mass(density, radius)};
    hertz_effective<Real> h;
    if (d.pair) {  // the relative motion of the two beads: E*, R*, m* of the pair
      std::optional<elastic_sphere<Real>> second;
      if (other) {
        elastic_material<Real> material{scene_number<Real>(d.other_youngs_modulus, "other.youngs_modulus"),
                                        scene_number<Real>(d.other_poisson_ratio, "other.poisson_ratio")};
        material.validate("other");
        const Real second_radius = scene_number<Real>(d.other_radius, "other.radius");
        const Real second_density = scene_number<Real>(d.other_density, "other.density");
        require_positive(second_radius, "other.radius");
        require_positive(second_density, "other.density");
        second = elastic_sphere<Real>{material, second_radius, sphere_mass(second_density, second_radius)};
      }
      h = hertz_with_sphere(sphere, second);
    } else {
      h = hertz_with_wall(sphere, w);
    }
    s.mass = h.mass;
    s.stiffness = h.stiffness;
    s.stiffness_from_material = true;
  }

  // Load and speeds.
  s.gravity = parse_real<Real>(d.gravity, "gravity");
  if (d.pair) s.gravity = 0;  // both beads fall alike: it drops out of the relative motion
  s.force = parse_real<Real>(d.force, "force");
  for (std::size_t i = 0; i < d.velocities.size(); ++i) {
    const std::string field = "velocities[" + std::to_string(i) + "]";
    s.velocities.push_back(parse_real<Real>(d.velocities[i], field));
    require_positive(s.velocities.back(), field);
  }
  if (d.velocity_from || d.velocity_to || d.velocity_count) {
    if (!d.velocities.empty())
      throw invalid_parameter("scene: give velocities either as a list or as a range, not both");
    const Real from = scene_number<Real>(d.velocity_from, "velocities.from");
    const Real to = scene_number<Real>(d.velocity_to, "velocities.to");
    require_positive(from, "velocities.from");
    require_positive(to, "velocities.to");
    if (d.velocity_count == 0) throw invalid_parameter("scene: field velocities.count must be >= 1");
    if (d.velocity_count > max_scene_impacts)
      throw invalid_parameter("scene: field velocities.count must be at most " + std::to_string(max_scene_impacts) +
                              ", got " + std::to_string(d.velocity_count));
    s.velocities = spaced_range(from, to, d.velocity_count, d.velocity_log);
  }
  if (s.velocities.empty()) throw invalid_parameter("scene: missing field velocities (no impact speeds)");

  // Damping.
  if (d.gamma0.has_value() == d.measured_e.has_value())
    throw invalid_parameter(d.gamma0 ? "scene: give damping.gamma0 or damping.measured_e, not both"
                                     : "scene: missing field damping (damping.gamma0, or damping.measured_e with "
                                       "damping.v0 and damping.gravity)");
  if (d.gamma0) {
    s.gamma0 = parse_real<Real>(*d.gamma0, "damping.gamma0");
    require_non_negative(s.gamma0, "damping.gamma0");
  } else {
    // NOTE: calibrated to the working precision of a type with 7 more digits than the
    // tolerance (10^5 epsilon <= tolerance / 10, so the calibration error stays small
    // against the bounds), a wider type than the scene's when needed; it costs a few solves.
    const int digits = std::max(decimal_digits<Real>(), scene_digits(d.tolerance, 7));
    const std::string mass = to_decimal_string(s.mass, roundtrip_digits<Real>() + 2);
    const std::string stiffness = to_decimal_string(s.stiffness, roundtrip_digits<Real>() + 2);
    s.calibration = with_working_precision(digits, [&]<class C>() {
      const C e = parse_real<C>(*d.measured_e, "damping.measured_e");
      const C speed = scene_number<C>(d.measured_speed, "damping.v0");
      require_positive(speed, "damping.v0");
      const C grav = d.pair ? C(0) : scene_number<C>(d.measured_gravity, "damping.gravity");
      const C f = d.measured_force ? parse_real<C>(*d.measured_force, "damping.force") : C(0);
      calibration_options<C> options;
      options.tolerance = detail::default_calibration_tolerance<C>();  // <= tolerance / 10 by the choice of C
      try {
        const physical_calibration<C> c = calibrate_gamma0(s.law, parse_real<C>(mass, "bead.m"),
                                                           parse_real<C>(stiffness, "bead.k"), speed, grav, f,
                                                           e, options);
        return scene_calibration{to_decimal_string(c.gamma0), to_decimal_string(c.scaled.gamma),
                                 to_decimal_string(c.scaled.g), to_decimal_string(c.scaled.target_bound, 3),
                                 decimal_digits<C>()};
      } catch (const unreachable_target& error) {
        throw unreachable_target(std::string("scene: damping.measured_e: ") + error.what());
      }
    });
    s.gamma0 = parse_real<Real>(s.calibration->gamma0, "damping.gamma0");
  }
  physical_parameters<Real>{s.mass, s.stiffness, s.gamma0, s.velocities.front(), s.gravity, s.force}.validate();
  return s;
}

/// One impact of a scene.
template <class Real>
struct scene_row {
  Real v0 = 0;
  Real gamma = 0, g = 0;         ///< scaled parameters (eq. 2)
  evaluation<Real> result;       ///< e, 1 - e, outcome, bound, method, cost
  std::optional<Real> contact_time;  ///< physical contact (or stop) time T * T_f, s, when computed
};

/// Evaluates every impact of a resolved scene, with `map` (may be null) for the
/// approximations and `surrogate` (may be null) tried first. `each` is called with
/// every row in order.
template <class Real, class F>
void run_scene(const resolved_scene<Real>& s, const error_map* map, F&& each, const fast_cor* surrogate = nullptr) {
  evaluate_options options;
  options.relative = s.relative;
  options.map = map;
  options.surrogate = surrogate;
  options.need_contact_time = s.contact_time;
  const evaluator<Real> ev(s.law, options);
  physical_parameters<Real> p;
  p.m = s.mass, p.k = s.stiffness, p.gamma0 = s.gamma0, p.gravity = s.gravity, p.force = s.force;
  for (const Real& v0 : s.velocities) {
    p.v0 = v0;
    const scaled_parameters<Real> scaled = to_scaled(s.law, p);
    scene_row<Real> row;
    row.v0 = v0, row.gamma = scaled.gamma, row.g = scaled.g;
    row.result = ev(scaled.gamma, scaled.g, s.tolerance);
    if (row.result.contact_time) row.contact_time = in_seconds(*row.result.contact_time, scaled.time_scale);
    each(row);
  }
}

}  // namespace viscor
