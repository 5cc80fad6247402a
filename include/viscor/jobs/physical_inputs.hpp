// The physical inputs of an impact, one vocabulary for every job and front end:
//   m (kg), k (N/m^alpha), v0 (m/s), gamma0 (SI), gravity (m/s^2), force (N),
// or the bead as a material (Hertz, alpha = 3/2):
//   youngs_modulus (Pa), poisson_ratio, radius (m), density (kg/m^3),
// hitting a wall (rigid, or of wall_youngs_modulus and wall_poisson_ratio) or, with
// contact "pair", a second bead (like the first, or of other_youngs_modulus,
// other_poisson_ratio, other_radius, other_density): then m and k are the reduced
// mass and the stiffness of the relative motion, a uniform gravity drops out of it
// (both beads fall alike) and force presses the two together.
// Values are kept as the user wrote them (exact decimal text) and parsed at the
// working precision. Gravity never defaults: a physical computation without it is
// an error naming it (0 is a value the user types), because the load changes the
// result. Messages name the command-line options (--m, ...), which the Python
// keywords mirror (m=, ...).
#pragma once

#include <viscor/jobs/json_fields.hpp>
#include <viscor/jobs/unit_checks.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/core/plausible_units.hpp>
#include <viscor/core/real_io.hpp>
#include <viscor/core/scaling.hpp>
#include <viscor/dem/hertz_contact.hpp>
#include <viscor/scenes/scene.hpp>

#include <cstdlib>
#include <initializer_list>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace viscor::jobs {

/// Refuses a negative --gravity with the sign convention, quoting the value as typed.
inline void require_gravity_towards_wall(const std::optional<std::string>& text) {
  if (text && std::strtod(text->c_str(), nullptr) < 0) throw invalid_parameter("--" + negative_gravity_message(*text));
}

/// The bead (m, k) of a Hertz sphere of a material against a wall or a second bead
/// (dem::contact_partner: none is a rigid wall, or a bead like the first): the
/// reduced mass m* and k = (4/3) E* sqrt(R*) (core/elastic_contact.hpp); the mass
/// given, or from the density. Holds only for alpha = 3/2 (refused otherwise, naming the law).
template <class Real>
std::pair<Real, Real> bead_of_material(const contact_law& law, const Real& youngs_modulus, const Real& poisson_ratio,
                                       const Real& radius, const std::optional<Real>& mass,
                                       const std::optional<Real>& density,
                                       dem::contact_kind kind = dem::contact_kind::wall,
                                       const dem::contact_partner<Real>& partner = {}) {
  if (!(law.alpha == exponent::rational(3, 2)))
    throw invalid_parameter(VISCOR_FIELD("youngs_modulus")
                            " gives a Hertz stiffness, which holds only for alpha = 3/2; the law has "
                            "alpha = " + law.alpha.to_string() + ": give " VISCOR_FIELD("k") " instead");
  require_positive(radius, "radius");
  elastic_material<Real> material{youngs_modulus, poisson_ratio};
  material.validate("bead");
  partner.validate(kind);
  Real m;
  if (mass) {
    m = *mass;
  } else {
    require_positive(*density, "density");
    m = sphere_mass(*density, radius);
  }
  const elastic_sphere<Real> sphere{material, radius, m};
  std::optional<elastic_sphere<Real>> other;
  if (partner.other) other = partner.other->sphere();
  const hertz_effective<Real> h =
      kind == dem::contact_kind::wall ? hertz_with_wall(sphere, partner.wall) : hertz_with_sphere(sphere, other);
  return {h.mass, h.stiffness};
}

/// The physical inputs as text, with their completeness and unit checks.
struct physical_inputs {
  std::optional<std::string> m, k, v0, gamma0, gravity, force;
  std::optional<std::string> youngs_modulus, poisson_ratio, radius, density;
  std::optional<std::string> contact;  ///< "wall" (the default) or "pair"
  std::optional<std::string> wall_youngs_modulus, wall_poisson_ratio;  ///< a wall of its own material; none: rigid
  /// The pair's other bead; none: a bead like the first.
  std::optional<std::string> other_youngs_modulus, other_poisson_ratio, other_radius, other_density;
  std::optional<std::string> deprecated_force;  ///< --F, the spelling before 0.2.0
  bool strict = false;  ///< refuse, not only warn about, inputs outside their plausible range

  /// Whether the bead is given as a material (youngs_modulus, poisson_ratio, radius, density).
  bool has_material() const { return youngs_modulus || poisson_ratio || radius || density; }
  /// Whether a wall material or the other bead is given.
  bool has_partner() const {
    return wall_youngs_modulus || wall_poisson_ratio || other_youngs_modulus || other_poisson_ratio || other_radius ||
           other_density;
  }
  /// Whether the bead meets a second bead (contact "pair").
  bool is_pair() const { return contact && *contact == "pair"; }
  /// Whether any physical input was given (the command is then in physical mode).
  bool given() const {
    return m || k || v0 || gamma0 || gravity || force || deprecated_force || has_material() || contact || has_partner();
  }

  /// The names of the physical options given, "--m, --k", for messages.
  std::string given_names() const {
    std::string s;
    auto add = [&](const auto& o, const char* name) {
      if (o) s += std::string(s.empty() ? "" : ", ") + name;
    };
    add(m, VISCOR_FIELD("m")), add(k, VISCOR_FIELD("k")), add(v0, VISCOR_FIELD("v0")), add(gamma0, VISCOR_FIELD("gamma0")), add(gravity, VISCOR_FIELD("gravity"));
    add(force, VISCOR_FIELD("force")), add(youngs_modulus, VISCOR_FIELD("youngs_modulus")), add(poisson_ratio, VISCOR_FIELD("poisson_ratio"));
    add(radius, VISCOR_FIELD("radius")), add(density, VISCOR_FIELD("density")), add(contact, VISCOR_FIELD("contact"));
    add(wall_youngs_modulus, VISCOR_FIELD("wall_youngs_modulus")), add(wall_poisson_ratio, VISCOR_FIELD("wall_poisson_ratio"));
    add(other_youngs_modulus, VISCOR_FIELD("other_youngs_modulus")), add(other_poisson_ratio, VISCOR_FIELD("other_poisson_ratio"));
    add(other_radius, VISCOR_FIELD("other_radius")), add(other_density, VISCOR_FIELD("other_density"));
    return s;
  }

  /// Folds the deprecated spelling in (with a warning), checks completeness
  /// (check_complete) and the values: gravity towards the wall, every input within
  /// double's range, and plausible units (a warning, or refused when strict).
  void check(const std::string& command) {
    if (deprecated_force) {
      if (force) throw invalid_parameter("give " VISCOR_FIELD("force") ", not both " VISCOR_FIELD("force") " and "
                                         VISCOR_FIELD("F") " (" VISCOR_FIELD("F") " is its deprecated spelling)");
      deprecation_warning(VISCOR_FIELD("F"), VISCOR_FIELD("force"));
      force = deprecated_force;
      deprecated_force.reset();
    }
    check_complete(command);
    require_gravity_towards_wall(gravity);
    require_double_range();
    check_plausible_units();
  }

  /// Which inputs are given, not their values: the bead as (m, k) or as a material
  /// (youngs_modulus, poisson_ratio, radius, and m or density), a wall material or a
  /// second bead only with a material bead and the fitting contact, v0, and gravity,
  /// which never defaults. `command` begins each message. (Python's evaluate checks
  /// its arrays' names here too.)
  void check_complete(const std::string& command) const {
    if (has_material()) {
      if (k) throw invalid_parameter(command + ": give the stiffness either as " VISCOR_FIELD("k") " or as "
                                               VISCOR_FIELD("youngs_modulus") ", "
                                               VISCOR_FIELD("poisson_ratio") " and " VISCOR_FIELD("radius")
                                               ", not both");
      if (!youngs_modulus || !poisson_ratio || !radius)
        throw invalid_parameter(command + ": a bead given as a material needs " VISCOR_FIELD("youngs_modulus") ", "
                                          VISCOR_FIELD("poisson_ratio") " and "
                                          VISCOR_FIELD("radius") " (missing " + missing_material() + ")");
      if (m && density) throw invalid_parameter(command + ": give the mass either as " VISCOR_FIELD("m") " or as "
                                                          VISCOR_FIELD("density") ", not both");
      if (!m && !density) throw invalid_parameter(command + ": the bead needs " VISCOR_FIELD("m") " (kg) or "
                                                            VISCOR_FIELD("density") " (kg/m^3)");
    } else {
      if (!m) throw invalid_parameter(command + ": physical mode needs " VISCOR_FIELD("m") " (bead mass, kg)");
      if (!k) throw invalid_parameter(command + ": physical mode needs " VISCOR_FIELD("k")
                                                " (contact stiffness, N/m^alpha)");
    }
    check_partner(command);
    if (!v0) throw invalid_parameter(command + ": physical mode needs " VISCOR_FIELD("v0") " (impact speed, m/s)");
    if (!gravity)
      throw invalid_parameter(command + ": physical mode needs " VISCOR_FIELD("gravity")
                                        " (m/s^2 towards the wall; 0 for none): "
                                        "the load changes the result, so it never defaults");
  }

  /// Solving an impact from physical inputs (cor, evaluate) needs the damping gamma0.
  void require_gamma0(const std::string& command) const {
    if (!gamma0) throw invalid_parameter(command + ": physical mode needs " VISCOR_FIELD("gamma0")
                                                   " (the damping coefficient, SI)");
  }

  /// Every physical input is an SI value within double's normal range (about 2.2e-308 to
  /// 1.8e308), whatever the working precision: an input such as v0 = 1e-400 is refused
  /// naming it at 20 digits as it is at 15, instead of giving an answer that depends on
  /// the digits asked for.
  void require_double_range() const {
    for (const auto& [value, name] : std::initializer_list<std::pair<const std::optional<std::string>*, const char*>>{
             {&m, "m"}, {&k, "k"}, {&v0, "v0"}, {&gamma0, "gamma0"}, {&gravity, "gravity"}, {&force, "force"},
             {&youngs_modulus, "youngs_modulus"}, {&poisson_ratio, "poisson_ratio"}, {&radius, "radius"},
             {&density, "density"}, {&wall_youngs_modulus, "wall_youngs_modulus"},
             {&wall_poisson_ratio, "wall_poisson_ratio"}, {&other_youngs_modulus, "other_youngs_modulus"},
             {&other_poisson_ratio, "other_poisson_ratio"}, {&other_radius, "other_radius"},
             {&other_density, "other_density"}})
      if (*value) (void)parse_real<double>(**value, name);
  }

  /// Warns (refuses under --strict) about inputs far outside their quantity's range.
  void check_plausible_units() const {
    check_plausible_unit(physical_quantity::youngs_modulus, youngs_modulus, VISCOR_FIELD("youngs_modulus"), strict);
    check_plausible_unit(physical_quantity::density, density, VISCOR_FIELD("density"), strict);
    check_plausible_unit(physical_quantity::radius, radius, VISCOR_FIELD("radius"), strict);
    check_plausible_unit(physical_quantity::speed, v0, VISCOR_FIELD("v0"), strict);
    check_plausible_unit(physical_quantity::gravity, gravity, VISCOR_FIELD("gravity"), strict);
    check_plausible_unit(physical_quantity::youngs_modulus, wall_youngs_modulus, VISCOR_FIELD("wall_youngs_modulus"), strict);
    check_plausible_unit(physical_quantity::youngs_modulus, other_youngs_modulus, VISCOR_FIELD("other_youngs_modulus"), strict);
    check_plausible_unit(physical_quantity::density, other_density, VISCOR_FIELD("other_density"), strict);
    check_plausible_unit(physical_quantity::radius, other_radius, VISCOR_FIELD("other_radius"), strict);
  }

  /// The contact and its partner: "wall" or "pair", partner inputs complete and fitting the contact.
  void check_partner(const std::string& command) const {
    if (contact && *contact != "wall" && *contact != "pair")
      throw invalid_parameter(VISCOR_FIELD("contact") " must be wall or pair, got '" + *contact + "'");
    if ((is_pair() || has_partner()) && !has_material())
      throw invalid_parameter(command + ": a wall material or a second bead needs the bead as a material "
                                        "(" VISCOR_FIELD("youngs_modulus") ", " VISCOR_FIELD("poisson_ratio") ", "
                                        VISCOR_FIELD("radius") "), not " VISCOR_FIELD("k"));
    const bool wall_given = wall_youngs_modulus || wall_poisson_ratio;
    const bool other_given = other_youngs_modulus || other_poisson_ratio || other_radius || other_density;
    if (wall_given && is_pair())
      throw invalid_parameter(command + ": " VISCOR_FIELD("wall_youngs_modulus") " and "
                                        VISCOR_FIELD("wall_poisson_ratio") " describe a wall, not "
                                        VISCOR_FIELD("contact") " pair");
    if (other_given && !is_pair())
      throw invalid_parameter(command + ": " VISCOR_FIELD("other_youngs_modulus") ", "
                                        VISCOR_FIELD("other_poisson_ratio") ", " VISCOR_FIELD("other_radius") " and "
                                        VISCOR_FIELD("other_density") " describe the second bead of "
                                        VISCOR_FIELD("contact") " pair");
    if (wall_given && (!wall_youngs_modulus || !wall_poisson_ratio))
      throw invalid_parameter(command + ": a wall of its own material needs " VISCOR_FIELD("wall_youngs_modulus")
                                        " and "
                                        VISCOR_FIELD("wall_poisson_ratio") " (neither: a rigid wall)");
    if (other_given && (!other_youngs_modulus || !other_poisson_ratio || !other_radius || !other_density))
      throw invalid_parameter(command + ": the other bead needs " VISCOR_FIELD("other_youngs_modulus") ", "
                                        VISCOR_FIELD("other_poisson_ratio") ", "
                                        VISCOR_FIELD("other_radius") " and " VISCOR_FIELD("other_density")
                                        " (none: a bead like the first)");
  }

  /// The wall's material or the other bead at the working precision (call check() first).
  template <class Real>
  dem::contact_partner<Real> partner() const {
    dem::contact_partner<Real> p;
    if (wall_youngs_modulus)
      p.wall = elastic_material<Real>{parse_real<Real>(*wall_youngs_modulus, "wall_youngs_modulus"),
                                      parse_real<Real>(*wall_poisson_ratio, "wall_poisson_ratio")};
    if (other_youngs_modulus)
      p.other = dem::bead_material<Real>{parse_real<Real>(*other_youngs_modulus, "other_youngs_modulus"),
                                         parse_real<Real>(*other_poisson_ratio, "other_poisson_ratio"),
                                         parse_real<Real>(*other_radius, "other_radius"),
                                         parse_real<Real>(*other_density, "other_density")};
    return p;
  }

  /// The bead (m, k) at the working precision; from the material when given.
  template <class Real>
  std::pair<Real, Real> bead(const contact_law& law) const {
    if (!has_material()) return {parse_real<Real>(*m, "m"), parse_real<Real>(*k, "k")};
    const std::optional<Real> mass = m ? std::optional<Real>(parse_real<Real>(*m, "m")) : std::nullopt;
    const std::optional<Real> rho = density ? std::optional<Real>(parse_real<Real>(*density, "density")) : std::nullopt;
    return bead_of_material<Real>(law, parse_real<Real>(*youngs_modulus, "youngs_modulus"),
                                  parse_real<Real>(*poisson_ratio, "poisson_ratio"), parse_real<Real>(*radius, "radius"),
                                  mass, rho, is_pair() ? dem::contact_kind::pair : dem::contact_kind::wall,
                                  partner<Real>());
  }

  /// The gravity the relative motion feels: as given on a wall, 0 for a pair (both beads fall alike).
  template <class Real>
  Real acting_gravity() const {
    return is_pair() ? Real(0) : parse_real<Real>(*gravity, "gravity");
  }

  /// Every physical input at the working precision (call check() first); gamma0 0 when absent.
  template <class Real>
  physical_parameters<Real> parameters(const contact_law& law) const {
    physical_parameters<Real> p;
    std::tie(p.m, p.k) = bead<Real>(law);
    p.v0 = parse_real<Real>(*v0, "v0");
    p.gamma0 = gamma0 ? parse_real<Real>(*gamma0, "gamma0") : Real(0);
    p.gravity = acting_gravity<Real>();
    p.force = force ? parse_real<Real>(*force, "force") : Real(0);
    p.validate();
    return p;
  }

  /// The inputs as the user wrote them, for the readable output: "m = 2.05e-3 kg, ...".
  std::string echo_text() const {
    std::string s;
    auto put = [&](const char* name, const std::optional<std::string>& v, const char* unit) {
      if (v) s += std::string(s.empty() ? "" : ", ") + name + " = " + *v + (*unit ? " " : "") + unit;
    };
    put("m", m, "kg"), put("k", k, "N/m^alpha"), put("youngs_modulus", youngs_modulus, "Pa");
    put("poisson_ratio", poisson_ratio, ""), put("radius", radius, "m"), put("density", density, "kg/m^3");
    put("contact", contact, ""), put("wall_youngs_modulus", wall_youngs_modulus, "Pa");
    put("wall_poisson_ratio", wall_poisson_ratio, ""), put("other_youngs_modulus", other_youngs_modulus, "Pa");
    put("other_poisson_ratio", other_poisson_ratio, ""), put("other_radius", other_radius, "m");
    put("other_density", other_density, "kg/m^3");
    put("gamma0", gamma0, ""), put("v0", v0, "m/s"), put("gravity", gravity, "m/s^2");
    put("force", force ? force : std::optional<std::string>("0"), "N");
    if (is_pair()) s += " (gravity drops out of the pair's relative motion)";
    return s;
  }

  /// The inputs as given (decimal text), under the option names.
  json echo() const {
    json j;
    auto put = [&](const char* name, const std::optional<std::string>& v) {
      if (v) j[name] = *v;
    };
    put("m", m), put("k", k), put("v0", v0), put("gamma0", gamma0), put("gravity", gravity);
    j["force"] = force ? *force : std::string("0");
    put("youngs_modulus", youngs_modulus), put("poisson_ratio", poisson_ratio), put("radius", radius);
    put("density", density), put("contact", contact);
    put("wall_youngs_modulus", wall_youngs_modulus), put("wall_poisson_ratio", wall_poisson_ratio);
    put("other_youngs_modulus", other_youngs_modulus), put("other_poisson_ratio", other_poisson_ratio);
    put("other_radius", other_radius), put("other_density", other_density);
    return j;
  }

 private:
  std::string missing_material() const {
    std::vector<std::string> missing;
    if (!youngs_modulus) missing.push_back(VISCOR_FIELD("youngs_modulus"));
    if (!poisson_ratio) missing.push_back(VISCOR_FIELD("poisson_ratio"));
    if (!radius) missing.push_back(VISCOR_FIELD("radius"));
    std::string s;
    for (const auto& x : missing) s += (s.empty() ? "" : ", ") + x;
    return s;
  }
};

}  // namespace viscor::jobs
