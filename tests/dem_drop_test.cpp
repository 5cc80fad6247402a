// The real DEM programs reproduce the target e with the deck entries of
// viscor dem (default-suite subset: per supported model, the polymer bead at
// v0 = 0.01 m/s under gravity, where the load matters most, and the steel bead
// at v0 = 1 m/s without; 4 program runs per model; plus two polymer beads pressed
// together in a head-on collision; about 20 s quiet, 65 s at load average 16). The full sweep
// is dem_drop_slow_test.cpp. Programs come from tools/install-deps.sh (Debian 12
// lammps, liggghts); a missing one is skipped with a message.
#include "dem_drop_utils.hpp"

namespace {

using namespace viscor::test::dem_drop;

void run_subset(viscor::dem::dem_code code) {
  const auto program = find_program(program_name(code));
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name(code) << " is not installed (tools/install-deps.sh installs it)");
  for (const auto& model : viscor::dem::dem_models) {
    if (model.code != code) continue;
    expect_drop_reproduces_target(*program, model, drop_materials()[1], 0.01, 9.81);
    expect_drop_reproduces_target(*program, model, drop_materials()[0], 1.0, 0.0);
  }
  // two polymer beads pressed together by 1e-4 N each (the load of a pair), tsuji damping
  const auto& tsuji = code == viscor::dem::dem_code::lammps ? viscor::dem::find_dem_model("lammps", "tsuji")
                                                            : viscor::dem::find_dem_model("liggghts", "hertz");
  expect_drop_reproduces_target(*program, tsuji, drop_materials()[1], 0.01, 0.0, viscor::dem::contact_kind::pair, 1e-4);
}

TEST(DemDrop, LammpsWallReproducesTarget) { run_subset(viscor::dem::dem_code::lammps); }
TEST(DemDrop, LiggghtsWallReproducesTarget) { run_subset(viscor::dem::dem_code::liggghts); }

}  // namespace
