// Damping entries for a LAMMPS deck from a measured coefficient of restitution, as
// `viscor dem lammps --damping tsuji ...` computes them: 2 mm glass beads on a
// rigid wall, e = 0.8 measured at 0.5 m/s under gravity. The calibration solves
// the impact with the law LAMMPS integrates (Hertz with Tsuji's damping), so the
// deck reproduces e = 0.8 where LAMMPS's own e-to-damping conversion misses.
// Then the same through the dem job (jobs/dem_job.hpp), which also writes a
// complete single-bead drop deck that LAMMPS runs as it is (`lmp -in drop.lmp`).
#include <viscor/viscor.hpp>

#include <cmath>
#include <iostream>

int main() {
  using Real = double;
  namespace dem = viscor::dem;
  const dem::dem_model& model = dem::find_dem_model("lammps", "tsuji");
  dem::dem_impact<Real> impact;
  impact.bead.youngs_modulus = 70e9;  // Pa
  impact.bead.poisson_ratio = 0.22;
  impact.bead.radius = 1e-3;     // m
  impact.bead.density = 2500;    // kg/m^3
  impact.bead.validate();
  impact.kind = dem::contact_kind::wall;
  impact.v0 = 0.5;        // m/s
  impact.gravity = 9.81;  // m/s^2, towards the wall
  const Real target_e = 0.8;

  const dem::dem_deck<Real> deck = dem::dem_deck_for(model, impact, target_e);
  dem::deck_strings entries;
  entries.youngs_modulus = dem::deck_number(deck.youngs_modulus);  // the shortest decimal of the double
  entries.poisson_ratio = dem::deck_number(deck.poisson_ratio);
  entries.damping = dem::deck_number(deck.damping);
  const dem::drop_timing<Real> timing = dem::drop_timing_for(model, impact, deck);
  std::cout << dem::deck_snippet(model, impact.kind, entries)
            << "# contact time " << timing.contact_time << " s; time step T/" << timing.steps_per_time_scale << " = "
            << timing.time_step << " s\n";
  if (deck.builtin_e)
    std::cout << "# writing e = 0.8 into LAMMPS's own conversion would give e = " << *deck.builtin_e << "\n";

  // The job: inputs as exact decimal text, a typed result back (jobs/dem_job.hpp);
  // dem_render.hpp makes the CLI's text of it.
  viscor::jobs::dem_request q;
  q.code = "lammps", q.damping = "tsuji";
  q.youngs_modulus = "70e9", q.poisson_ratio = "0.22", q.radius = "1e-3", q.density = "2500";
  q.target_e = "0.8", q.v0 = "0.5", q.gravity = "9.81";
  q.drop_deck_path = "drop.lmp";
  const viscor::jobs::dem_result job = viscor::jobs::run_dem(q);
  std::cout << viscor::render::dem_text(job);
  const viscor::jobs::dem_forward& forward = *job.forward;
  const bool same = forward.deck.damping == entries.damping;  // one calibration, two ways to call it
  if (!same) std::cerr << "the job's damping " << forward.deck.damping << " differs from " << entries.damping << "\n";
  const bool calibrated = std::abs(forward.e - target_e) <= forward.target_bound;  // e at the deck, as a number
  return same && calibrated && deck.damping > 0 && timing.time_step > 0 ? 0 : 1;
}
