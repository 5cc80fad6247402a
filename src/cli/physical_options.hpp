// The physical inputs of every subcommand as command-line options (the inputs
// and their checks are the library's: jobs/physical_inputs.hpp).
#pragma once

#include "cli_common.hpp"

#include <viscor/jobs/physical_inputs.hpp>

namespace viscor::cli {

/// --strict: inputs outside their plausible range are errors, not warnings.
inline void add_strict_flag(CLI::App& app, bool& strict) {
  app.add_flag("--strict", strict,
               "refuse physical inputs far outside their plausible range (a unit mistake, most likely) instead of "
               "warning about them");
}

/// --m --k --v0 --gamma0 --gravity --force (and --youngs-modulus --poisson-ratio --radius --density).
struct physical_options : jobs::physical_inputs {
  /// Adds the options; `with_gamma0` false for commands that compute gamma0 (calibrate).
  void add_to(CLI::App& app, bool with_gamma0 = true, bool with_materials = true) {
    app.add_option("--m", m, "bead mass, kg");
    app.add_option("--k", k, "contact stiffness, N/m^alpha");
    app.add_option("--v0", v0, "impact speed, m/s (> 0)");
    if (with_gamma0) app.add_option("--gamma0", gamma0, "damping coefficient, SI (N s^beta / m^beta... per the law), >= 0");
    app.add_option("--gravity", gravity,
                   "gravitational acceleration towards the wall, m/s^2 (required in physical mode; 0 for none)");
    app.add_option("--force", force, "constant external force, N (> 0 presses on the wall; default 0)");
    app.add_option("--F", deprecated_force, "deprecated spelling of --force")->group("");
    if (with_materials) {
      app.add_option("--youngs-modulus", youngs_modulus, "bead Young's modulus, Pa (instead of --k; alpha = 3/2)");
      app.add_option("--poisson-ratio", poisson_ratio, "bead Poisson ratio, in (-1, 1/2] (with --youngs-modulus)");
      app.add_option("--radius", radius, "bead radius, m (with --youngs-modulus)");
      app.add_option("--density", density, "bead density, kg/m^3 (instead of --m, with --radius)");
      app.add_option("--contact", contact,
                     "wall (the default: a bead on a wall) or pair (two beads; gravity drops out, --force presses them "
                     "together); with the bead as a material");
      app.add_option("--wall-youngs-modulus", wall_youngs_modulus, "a wall of its own material: its Young's modulus, Pa "
                                                                   "(neither wall option: a rigid wall)");
      app.add_option("--wall-poisson-ratio", wall_poisson_ratio, "a wall of its own material: its Poisson ratio");
      app.add_option("--other-youngs-modulus", other_youngs_modulus,
                     "--contact pair: the other bead's Young's modulus, Pa (no --other-* option: a bead like the first)");
      app.add_option("--other-poisson-ratio", other_poisson_ratio, "--contact pair: the other bead's Poisson ratio");
      app.add_option("--other-radius", other_radius, "--contact pair: the other bead's radius, m");
      app.add_option("--other-density", other_density, "--contact pair: the other bead's density, kg/m^3");
    }
    add_strict_flag(app, strict);
  }
};

}  // namespace viscor::cli
