// Unit mistakes caught before any work: a physical input far outside the plausible
// range of its quantity (core/plausible_units.hpp) is warned about (core/warnings.hpp),
// or refused when strict. Used by the command-line options and scene files.
#pragma once

#include <viscor/core/exceptions.hpp>
#include <viscor/core/plausible_units.hpp>
#include <viscor/core/warnings.hpp>
#include <viscor/scenes/scene.hpp>

#include <cstdlib>
#include <optional>
#include <string>

namespace viscor::jobs {

/// Warns on stderr when the physical input `text` of `option` lies far outside the
/// plausible range of its quantity (a unit mistake, most likely); with `strict`, refuses it.
inline void check_plausible_unit(physical_quantity q, const std::optional<std::string>& text, const std::string& option,
                                 bool strict) {
  if (!text) return;
  const double value = std::strtod(text->c_str(), nullptr);  // a coarse check; the exact parse comes later
  const std::optional<std::string> message = implausible_unit(q, value, option, *text);
  if (!message) return;
  if (strict) throw invalid_parameter(*message + " (refused under " VISCOR_FIELD("strict") ")");
  warn(*message + " (" VISCOR_FIELD("strict") " makes this an error)");
}

/// The same checks for a scene file's bead, wall and load; `where` names the field's line.
template <class Locate>
void check_plausible_scene_units(const scene_description& d, bool strict, const Locate& where) {
  const auto check = [&](physical_quantity q, const std::optional<std::string>& v, const std::string& field) {
    check_plausible_unit(q, v, where(field) + field, strict);
  };
  if (std::strtod(d.gravity.c_str(), nullptr) < 0) throw invalid_parameter(where("gravity") + negative_gravity_message(d.gravity));
  check(physical_quantity::youngs_modulus, d.youngs_modulus, "bead.youngs_modulus");
  check(physical_quantity::youngs_modulus, d.wall_youngs_modulus, "wall.youngs_modulus");
  check(physical_quantity::youngs_modulus, d.other_youngs_modulus, "other.youngs_modulus");
  check(physical_quantity::density, d.other_density, "other.density");
  check(physical_quantity::radius, d.other_radius, "other.radius");
  check(physical_quantity::density, d.density, "bead.density");
  check(physical_quantity::radius, d.radius, "bead.radius");
  check(physical_quantity::gravity, d.gravity, "gravity");
  for (const std::string& v : d.velocities) check(physical_quantity::speed, v, "velocities");
  check(physical_quantity::speed, d.velocity_to, "velocities.to");
}

}  // namespace viscor::jobs
