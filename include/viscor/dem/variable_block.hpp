// A calibrated deck as LAMMPS/LIGGGHTS `variable NAME string VALUE` lines, for `include FILE`
// in a deck of the user's own (`viscor dem --variables FILE`).
#pragma once

#include <viscor/dem/deck_snippet.hpp>
#include <viscor/dem/dem_model.hpp>
#include <viscor/dem/drop_deck.hpp>

#include <string>

namespace viscor::dem {

/// The first line of every variable block viscor writes (viscor dem replaces only such a file).
inline constexpr const char* variables_marker = "# viscor dem variables";

/// The deck entries, the impact they are calibrated for and the time step as LAMMPS/LIGGGHTS
/// `variable NAME string VALUE` lines (exact decimal text, substituted verbatim by ${NAME}).
inline std::string variable_block(const dem_model& model, contact_kind kind, const deck_strings& s,
                                  const drop_deck_inputs& in, const std::string& contact_time) {
  std::string b = std::string(variables_marker) + ": " + std::string(model.version) + ", " +
                  std::string(model.code_name) + " damping " + std::string(model.damping_name) + " on a " +
                  std::string(to_string(kind)) + " (viscor law " + std::string(model.law_name) + ")\n";
  b += "# use: `include FILE` in a deck with `units si`, then ${viscor_NAME} where the values go\n";
  const auto line = [&b](const std::string& name, const std::string& value) {
    b += "variable viscor_" + name + " string " + value + "\n";
  };
  b += "# the impact the entries are calibrated for (SI units, as given to viscor dem)\n";
  line("radius", in.radius), line("diameter", in.diameter), line("density", in.density);
  line("v0", in.v0), line("gravity", in.gravity), line("force", in.force), line("target_e", in.target_e);
  b += model.code == dem_code::liggghts
           ? "# model hertz: youngsModulus and poissonsRatio of the bead type; damping = the bead-wall\n"
             "# coefficientRestitution; wall_youngs_modulus = the wall type's youngsModulus (1e30: rigid)\n"
           : "# hertz/material E damp nu damping " + std::string(model.damping_name) +
                 ": youngs_modulus = E, damping = damp, poisson_ratio = nu\n";
  line("youngs_modulus", s.youngs_modulus), line("poisson_ratio", s.poisson_ratio), line("damping", s.damping);
  if (s.wall_youngs_modulus) line("wall_youngs_modulus", *s.wall_youngs_modulus);
  if (s.wall_poisson_ratio) line("wall_poisson_ratio", *s.wall_poisson_ratio);
  if (s.other_youngs_modulus) {
    b += "# the other bead (type 2) and, for LAMMPS, the explicit cross entry pair_coeff 1 2\n";
    line("other_youngs_modulus", *s.other_youngs_modulus), line("other_poisson_ratio", *s.other_poisson_ratio);
    if (s.cross_youngs_modulus) line("cross_youngs_modulus", *s.cross_youngs_modulus);
    if (s.other_other_damping) line("other_other_damping", *s.other_other_damping);
  }
  if (s.bead_bead_damping) {
    b += "# bead-bead entries: two beads at the same e and approach speed, without load\n";
    line("bead_bead_youngs_modulus", s.bead_bead_youngs_modulus.value_or(s.youngs_modulus));
    line("bead_bead_damping", *s.bead_bead_damping);
  }
  b += "# the recommended time step, T/" + in.steps_per_time_scale + " (halve it for a smaller error), and how "
       "long the contact lasts, s\n";
  line("time_step", in.time_step), line("contact_time", contact_time);
  return b;
}

}  // namespace viscor::dem
