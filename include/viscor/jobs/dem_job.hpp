// The damping to write into a DEM code's contact model so the code reproduces a
// measured e at an impact speed under a load (the exact calibration of viscor's
// force law, mapped through the code's own conventions, include/viscor/dem/), and
// the reverse: the e a deck damping entry produces. As `viscor dem` and viscor.dem
// report it; the forward job can also write a complete single-bead drop deck.
// Rendered by jobs/dem_render.hpp.
#pragma once

#include <viscor/core/working_number.hpp>
#include <viscor/jobs/precision_used.hpp>

#include <viscor/core/outcome.hpp>
#include <viscor/dem/deck_snippet.hpp>
#include <viscor/dem/dem_model.hpp>
#include <viscor/dem/hertz_contact.hpp>
#include <viscor/surrogate/cor_surrogate.hpp>

#include <optional>
#include <string>
#include <vector>

namespace viscor::jobs {

/// The code and its damping model, the bead, the load, and either a target e
/// (forward: the deck entries) or a deck entry (reverse: the e it gives). Values
/// are exact decimal text; "" is an input not given.
struct dem_request {
  std::string code;              ///< lammps, liggghts or yade
  std::string damping;           ///< the code's damping model (dem/dem_models.hpp)
  std::string contact = "wall";  ///< wall or pair
  std::string youngs_modulus, poisson_ratio, radius, density;
  std::string wall_youngs_modulus, wall_poisson_ratio;  ///< a wall of its own material ("": rigid)
  /// A pair of two materials: the other bead ("": a bead like the first).
  std::string other_youngs_modulus, other_poisson_ratio, other_radius, other_density;
  std::string stiffness;         ///< yade viscoelastic: the linear spring's kn, N/m
  std::string target_e;          ///< forward: the measured e
  std::string deck_damping;      ///< reverse: the deck's damping entry
  std::string deck_en;           ///< reverse, yade mindlin: YADE's own en input
  std::string v0, gravity, force = "0";
  std::string speeds = "0.001,0.01,0.1,1,10";  ///< reverse: impact speeds, comma-separated
  std::string drop_deck_path;    ///< forward: also write a complete single-bead drop deck here
  std::string variables_path;    ///< forward, LAMMPS/LIGGGHTS: also write the entries as a `variable` block here
  int digits = 15;               ///< working precision in decimal digits
  /// Forward: solve (the calibration by the Taylor solve, at `digits`) or surrogate (the committed
  /// surrogate's inverse in double, as the C export computes each code's entries: docs/dem.md).
  std::string method = "solve";
  /// Forward: calibrate for the e the code's own update gives at this time step (dem/stepped_drop.hpp):
  /// seconds, "T/N" (T the impact's time scale) or "contact/N"; "": the continuous impact.
  std::string timestep;
  bool strict = false;           ///< refuse, not only warn about, implausible inputs

  /// The wall's and the other bead's inputs, under their field names.
  std::vector<std::pair<std::string, const std::string*>> partner_inputs() const {
    return {{"wall_youngs_modulus", &wall_youngs_modulus}, {"wall_poisson_ratio", &wall_poisson_ratio},
            {"other_youngs_modulus", &other_youngs_modulus}, {"other_poisson_ratio", &other_poisson_ratio},
            {"other_radius", &other_radius}, {"other_density", &other_density}};
  }
};

/// The contact the code integrates, from the bead and its partner.
struct dem_contact_values {
  std::optional<working_number> effective_modulus;  ///< E*, Pa (Hertz contacts; not a linear spring)
  working_number effective_radius, effective_mass;  ///< R* (m), m* (kg)
  working_number stiffness;                         ///< k: N/m^1.5 (Hertz) or N/m (linear spring)
};

/// What the code's own e-to-damping conversion would give for the target.
struct dem_builtin {
  working_number e;              ///< the e the code's conversion gives
  working_number error;          ///< e - target
  working_number error_percent;  ///< of 1 - target
  std::optional<working_number> tc;  ///< YADE visco-elastic: the tc that gives its kn = k, s
  std::string conversion;        ///< what the code is given instead ("" for LAMMPS and LIGGGHTS)
};

/// Forward: the deck entries for a target e, the calibration behind them and the time step.
struct dem_forward {
  std::string target_e;    ///< as given
  dem::deck_strings deck;  ///< the entries as written into the input (shortest doubles)
  working_number damping_number, gamma0, gamma, g, e, target_bound, time_scale;
  /// Method surrogate: the surrogate's stated bound (target_bound is then |e - target| + its bound on e).
  std::optional<surrogate::surrogate_bound> surrogate_bound;
  std::optional<dem_builtin> builtin;
  std::string snippet;  ///< the input lines, ready to paste
  working_number contact_time, time_step;  ///< s: how long the contact lasts, the recommended step
  working_number timing_time_scale;        ///< s: the drop's time scale T (time_step = T / steps_per_time_scale)
  /// With a time step: the step, and what the entries calibrated for the continuous impact give at it.
  struct at_time_step {
    working_number time_step;   ///< s, as asked for
    working_number e;           ///< the stepped drop's e with these entries
    std::string continuous_damping;  ///< the continuous calibration's damping entry
    working_number continuous_e;     ///< the stepped drop's e with it (its drift from the target)
  };
  std::optional<at_time_step> stepped;
  long steps_per_time_scale = 0, steps_per_contact = 0;
  std::string drop_deck_path, variables_path;  ///< the files written ("" when not asked for)
};

/// Reverse: the e a deck entry gives, per impact speed and load.
struct dem_reverse_row {
  std::string v0, gravity, force;  ///< as given
  working_number e;
  impact_outcome outcome = impact_outcome::rebound;
};
/// Reverse: the deck entry and the e it gives at each speed and load.
struct dem_reverse {
  std::string deck_en;       ///< YADE's en, when given instead of the damping
  std::string deck_damping;  ///< the deck's damping entry (converted from en when en was given)
  working_number damping_number;
  std::vector<dem_reverse_row> rows;
};

/// What `viscor dem` found: the code's model, the contact it integrates, and the
/// forward deck or the reverse table.
struct dem_result {
  dem::dem_model model;
  dem::contact_kind kind = dem::contact_kind::wall;
  dem_request inputs;  ///< as given (echoed by the front ends)
  dem_contact_values contact;
  std::optional<dem_forward> forward;
  std::optional<dem_reverse> reverse;
  precision_used precision;
  double seconds = 0;
};

/// The deck entries for a target e, or the e of a deck entry at the listed speeds.
dem_result run_dem(const dem_request& q);

}  // namespace viscor::jobs
