// Full drop sweep in the real programs: every supported (code, damping model),
// steel and polymer beads, v0 in {0.01, 1} m/s, with and without gravity, each at
// dt = T/400 and T/800 (see dem_drop_utils.hpp); and the built-in conversions
// reproduced: writing the target e itself into the deck gives the builtin_e
// viscor predicts; and head-on pairs, free and pressed together. 7.8 min at
// load average 16 (200 program runs, mostly start-up).
#include "dem_drop_utils.hpp"

namespace {

using namespace viscor::test::dem_drop;

void run_sweep(viscor::dem::dem_code code) {
  const auto program = find_program(program_name(code));
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name(code) << " is not installed (tools/install-deps.sh installs it)");
  for (const auto& model : viscor::dem::dem_models) {
    if (model.code != code) continue;
    for (const auto& m : drop_materials())
      for (double v0 : {0.01, 1.0})
        for (double gravity : {0.0, 9.81}) expect_drop_reproduces_target(*program, model, m, v0, gravity);
  }
}

// Two identical beads head-on (reduced mass m/2, E* = E/(2(1-nu^2)), R* = R/2),
// free and pressed together by 1e-4 N on each.
void run_pair_sweep(viscor::dem::dem_code code) {
  const auto program = find_program(program_name(code));
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name(code) << " is not installed (tools/install-deps.sh installs it)");
  for (const auto& model : viscor::dem::dem_models) {
    if (model.code != code) continue;
    for (const auto& m : drop_materials())
      for (double v0 : {0.01, 1.0})
        for (double force : {0.0, 1e-4})
          expect_drop_reproduces_target(*program, model, m, v0, 0.0, viscor::dem::contact_kind::pair, force);
  }
}

TEST(DemDropSweep, LammpsPair) { run_pair_sweep(viscor::dem::dem_code::lammps); }
TEST(DemDropSweep, LiggghtsPair) { run_pair_sweep(viscor::dem::dem_code::liggghts); }

TEST(DemDropSweep, Lammps) { run_sweep(viscor::dem::dem_code::lammps); }
TEST(DemDropSweep, Liggghts) { run_sweep(viscor::dem::dem_code::liggghts); }

// The codes' own e -> damping conversions, run in the codes: deck damping = target.
void check_builtin(viscor::dem::dem_code code) {
  using namespace viscor::dem;
  const auto program = find_program(program_name(code));
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name(code) << " is not installed (tools/install-deps.sh installs it)");
  for (const auto& model : dem_models) {
    if (model.code != code || model.deck_kind != deck_damping_kind::coefficient_of_restitution) continue;
    for (const auto& m : drop_materials())
      for (double v0 : {0.01, 1.0}) {
        SCOPED_TRACE(std::string(model.damping_name) + " " + m.name + " v0 = " + format_double(v0));
        dem_impact<double> impact;
        impact.bead = m.bead, impact.v0 = v0, impact.gravity = 9.81;
        const dem_deck<double> d = dem_deck_for(model, impact, m.target_e);
        ASSERT_TRUE(d.builtin_e.has_value());
        drop_setup s;
        s.model = &model;
        s.youngs_modulus = viscor::to_decimal_string(d.youngs_modulus);
        s.poisson_ratio = viscor::to_decimal_string(d.poisson_ratio);
        s.damping = format_double(m.target_e);
        s.radius = m.bead.radius, s.density = m.bead.density, s.v0 = v0, s.gravity = 9.81;
        s.dt = d.calibration.time_scale / 800, s.steps = 6 * 800;
        const drop_result r = run_drop(*program, s);
        ASSERT_TRUE(r.ok) << r.message;
        EXPECT_NEAR(r.e, *d.builtin_e, tolerance_at_T_over_400) << "target " << m.target_e;
      }
  }
}

TEST(DemDropSweep, LammpsBuiltinConversion) { check_builtin(viscor::dem::dem_code::lammps); }
TEST(DemDropSweep, LiggghtsBuiltinConversion) { check_builtin(viscor::dem::dem_code::liggghts); }

}  // namespace
