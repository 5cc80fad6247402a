// The physical axes of a table spec (docs/tables.md, "Physical specs"): beads as
// materials or (m, k), a rigid wall, walls of a material or a second bead, impact
// speeds v0, gravities, forces, and dampings gamma0 or target CoRs target_e (the
// damping is then calibrated per row), all in SI, expanded into one
// jobs::physical_inputs per row. Each row is then solved as `viscor cor` solves the
// same inputs (physical_table.cpp), so the scaling is the library's one scaling.
// Values are exact decimal text, as everywhere in a spec.
#pragma once

#include <viscor/jobs/physical_inputs.hpp>

#include <viscor/core/contact_law.hpp>
#include <viscor/core/exceptions.hpp>
#include <viscor/tables/grid_spec.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace viscor::jobs {

/// A bead of a physical spec: (m, k), or a material (youngs_modulus, poisson_ratio,
/// radius, and m or density). Also the second bead of a pair.
struct physical_bead {
  std::string name;  ///< as the rows name it
  std::optional<std::string> m, k, youngs_modulus, poisson_ratio, radius, density;
  std::string where;  ///< "spec.json:7", for messages
};

/// A wall of a physical spec: rigid (no material), or of youngs_modulus and poisson_ratio.
struct physical_wall {
  std::string name = "rigid";
  std::optional<std::string> youngs_modulus, poisson_ratio;
  std::string where;
};

/// The physical axes of a spec: its rows are laws x beads x walls x gravity x force x
/// (gamma0 or target_e) x v0, in that order (v0 innermost: each e(v0) curve is one
/// block of rows).
struct physical_axes {
  std::vector<physical_bead> beads;
  std::string contact = "wall";           ///< "wall" or "pair"
  std::vector<physical_wall> walls;       ///< contact wall: rigid unless given
  std::optional<physical_bead> other;     ///< contact pair: the second bead (none: like the first)
  grid_axis v0, gravity, force;           ///< force: 0 unless given
  grid_axis gamma0, target_e;             ///< the damping, or the CoR it is calibrated to (one of them)
};

/// The expanded values of the physical axes (sorted exact decimals).
struct expanded_physical_axes {
  std::vector<std::string> v0, gravity, force;
  std::vector<std::string> damping;  ///< gamma0 values, or target_e values
};

/// One row of a physical table.
struct physical_point {
  std::int64_t index = 0;
  contact_law law;
  std::size_t bead = 0, wall = 0;  ///< positions in physical_axes::beads and walls
  physical_inputs inputs;          ///< what `viscor cor` would be given (gamma0 unset for a target)
  std::optional<std::string> target_e;  ///< the CoR gamma0 is calibrated to (viscor calibrate)
};

/// The axes expanded into sorted exact decimals (force: 0 when not given).
inline expanded_physical_axes expand(const physical_axes& axes) {
  expanded_physical_axes out;
  out.v0 = expand_axis(axes.v0, "v0");
  out.gravity = expand_axis(axes.gravity, "gravity");
  out.force = axes.force.empty() ? std::vector<std::string>{"0"} : expand_axis(axes.force, "force");
  out.damping = axes.target_e.empty() ? expand_axis(axes.gamma0, "gamma0") : expand_axis(axes.target_e, "target_e");
  return out;
}

/// Rows per law: beads x walls x gravity x force x (gamma0 or target_e) x v0.
inline std::int64_t physical_rows_per_law(const physical_axes& axes, const expanded_physical_axes& values) {
  return static_cast<std::int64_t>(axes.beads.size() * axes.walls.size() * values.gravity.size() *
                                   values.force.size() * values.damping.size() * values.v0.size());
}

/// The inputs of one row, as `viscor cor` takes them (gamma0 unset: calibrated to a target).
inline physical_inputs inputs_of(const physical_axes& axes, const physical_bead& bead, const physical_wall& wall,
                                 const std::string& gravity, const std::string& force,
                                 const std::optional<std::string>& gamma0, const std::string& v0) {
  physical_inputs in;
  in.m = bead.m, in.k = bead.k;
  in.youngs_modulus = bead.youngs_modulus, in.poisson_ratio = bead.poisson_ratio;
  in.radius = bead.radius, in.density = bead.density;
  in.contact = axes.contact;
  in.wall_youngs_modulus = wall.youngs_modulus, in.wall_poisson_ratio = wall.poisson_ratio;
  if (axes.other) {
    in.other_youngs_modulus = axes.other->youngs_modulus, in.other_poisson_ratio = axes.other->poisson_ratio;
    in.other_radius = axes.other->radius, in.other_density = axes.other->density;
  }
  in.gravity = gravity, in.force = force, in.gamma0 = gamma0, in.v0 = v0;
  return in;
}

/// The rows of the table in table order, only those of `part`.
inline std::vector<physical_point> physical_points(const std::vector<contact_law>& laws, const physical_axes& axes,
                                                   const expanded_physical_axes& values, shard part = {}) {
  std::vector<physical_point> points;
  std::int64_t index = 0;
  for (const auto& law : laws)
    for (std::size_t b = 0; b < axes.beads.size(); ++b)
      for (std::size_t w = 0; w < axes.walls.size(); ++w)
        for (const auto& gravity : values.gravity)
          for (const auto& force : values.force)
            for (const auto& damping : values.damping)
              for (const auto& v0 : values.v0) {
                if (part.contains(index)) {
                  const bool target = !axes.target_e.empty();
                  points.push_back(
                      {index, law, b, w,
                       inputs_of(axes, axes.beads[b], axes.walls[w], gravity, force,
                                 target ? std::nullopt : std::optional<std::string>(damping), v0),
                       target ? std::optional<std::string>(damping) : std::nullopt});
                }
                ++index;
              }
  return points;
}

/// Warns (refuses under `strict`) about spec values far outside their quantity's
/// range, once per value; `source` begins each field name.
inline void check_plausible_physical_units(const physical_axes& axes, const expanded_physical_axes& values,
                                           const std::string& source, bool strict = false) {
  const auto check = [&](physical_quantity q, const std::optional<std::string>& v, const std::string& field) {
    check_plausible_unit(q, v, source + ": field " + field, strict);
  };
  const auto check_bead = [&](const physical_bead& b, const std::string& field) {
    check(physical_quantity::youngs_modulus, b.youngs_modulus, field + ".youngs_modulus");
    check(physical_quantity::density, b.density, field + ".density");
    check(physical_quantity::radius, b.radius, field + ".radius");
  };
  for (std::size_t i = 0; i < axes.beads.size(); ++i) check_bead(axes.beads[i], "beads[" + std::to_string(i) + "]");
  if (axes.other) check_bead(*axes.other, "other");
  for (std::size_t i = 0; i < axes.walls.size(); ++i)
    check(physical_quantity::youngs_modulus, axes.walls[i].youngs_modulus,
          "walls[" + std::to_string(i) + "].youngs_modulus");
  for (const auto& v : values.v0) check(physical_quantity::speed, v, "v0");
  for (const auto& g : values.gravity) check(physical_quantity::gravity, g, "gravity");
}

}  // namespace viscor::jobs
