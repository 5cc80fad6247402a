// viscor dem CODE: damping entries for a DEM deck that reproduce a measured e, and
// the reverse (the dem job, jobs/dem_job.hpp).
#include "cli_common.hpp"
#include "command_registry.hpp"
#include "physical_options.hpp"

#include <viscor/jobs/dem_job.hpp>
#include <viscor/jobs/dem_render.hpp>

namespace viscor::cli::cmd_dem {  // named: the subcommands share translation units (unity build)
namespace {

struct dem_command {
  output_options output;
  dem_request request;

  void run() const {
    const dem_result r = run_dem(request);
    output.emit(render::dem_text(r), render::dem_json(r));
  }
};

void setup(CLI::App& app) {
  auto cmd = std::make_shared<dem_command>();
  cmd->output.add_to(app);
  dem_request& q = cmd->request;
  app.add_option("code", q.code, "DEM code: lammps (29 Sep 2021), liggghts (3.8.0) or yade (2023.02a)");
  app.add_option("--damping", q.damping,
                 "damping model: lammps velocity|mass_velocity|viscoelastic|tsuji, liggghts hertz, yade "
                 "mindlin|viscoelastic");
  app.add_option("--contact", q.contact,
                 "wall (bead on a wall: rigid, or of --wall-youngs-modulus and --wall-poisson-ratio) or pair (two "
                 "beads: alike, or the other of --other-youngs-modulus, --other-poisson-ratio, --other-radius, "
                 "--other-density)")
      ->capture_default_str();
  app.add_option("--wall-youngs-modulus", q.wall_youngs_modulus, "a wall of its own material: its Young's modulus, Pa");
  app.add_option("--wall-poisson-ratio", q.wall_poisson_ratio, "a wall of its own material: its Poisson ratio");
  app.add_option("--other-youngs-modulus", q.other_youngs_modulus, "--contact pair: the other bead's Young's modulus, Pa");
  app.add_option("--other-poisson-ratio", q.other_poisson_ratio, "--contact pair: the other bead's Poisson ratio");
  app.add_option("--other-radius", q.other_radius, "--contact pair: the other bead's radius, m");
  app.add_option("--other-density", q.other_density, "--contact pair: the other bead's density, kg/m^3");
  app.add_option("--youngs-modulus", q.youngs_modulus, "Young's modulus E of the bead, Pa");
  app.add_option("--poisson-ratio", q.poisson_ratio, "Poisson ratio of the bead");
  app.add_option("--k", q.stiffness,
                 "yade viscoelastic: the contact's normal stiffness kn of its linear spring, N/m (no Hertz material)");
  app.add_option("--radius", q.radius, "bead radius, m");
  app.add_option("--density", q.density, "bead density, kg/m^3");
  app.add_option("--target-e", q.target_e, "measured coefficient of restitution to reproduce, 0 < e < 1");
  app.add_option("--deck-damping", q.deck_damping, "reverse: the deck's damping entry; prints the e it gives");
  app.add_option("--deck-en", q.deck_en,
                 "reverse, yade mindlin: YADE's own input en (turned into betan by Thornton's fit); prints the e it gives");
  app.add_option("--v0", q.v0, "impact (approach) speed, m/s");
  app.add_option("--gravity", q.gravity, "gravitational acceleration towards the wall, m/s^2 (required; 0 for none)");
  app.add_option("--force", q.force, "constant force pressing the bead on the wall (or the pair together), N")
      ->capture_default_str();
  app.add_option("--speeds", q.speeds, "reverse: comma-separated impact speeds, m/s")->capture_default_str();
  app.add_option("--drop-deck", q.drop_deck_path,
                 "also write a complete single-bead drop on a wall for the code (LAMMPS/LIGGGHTS input, YADE script) "
                 "that prints the rebound e; never replaces a file viscor did not write");
  app.add_option("--variables", q.variables_path,
                 "lammps, liggghts: also write the entries, the impact and the time step as a `variable` block "
                 "(variable viscor_NAME string VALUE) for a deck's `include`; never replaces a file viscor did not write");
  app.add_option("--digits", q.digits, "working precision in decimal digits")->capture_default_str();
  app.add_option("--timestep", q.timestep,
                 "calibrate for the e the code's own update gives at this time step: seconds, T/N (T the impact's "
                 "time scale) or contact/N (docs/dem.md)");
  app.add_option("--method", q.method,
                 "solve (the calibration by the Taylor solve) or surrogate (the committed surrogate's inverse in "
                 "double: the C export's entries, docs/dem.md)")
      ->capture_default_str();
  add_strict_flag(app, q.strict);
  app.callback([cmd] { cmd->run(); });
}

const registration reg{"dem", "damping entries for LAMMPS / LIGGGHTS / YADE inputs that reproduce a measured e", setup};

}  // namespace
}  // namespace viscor::cli::cmd_dem
