// The drop as each code steps it (include/viscor/dem/stepped_drop.hpp): as the step
// shrinks, the stepped drop's e converges to the continuous impact's e of the exact
// (Taylor) solve, for both updates (velocity Verlet, leapfrog with the clamp); the
// step-aware deck's stepped e is the target; time steps are read as seconds, T/N or
// contact/N and refused otherwise. The real programs' rebounds at these steps are
// checked in tests/dem_drop_deck_test.cpp (StepAwareDecksHitTheTarget).
#include <viscor/dem/drop_deck.hpp>
#include <viscor/dem/stepped_drop.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

using namespace viscor::dem;

dem_impact<double> glass_drop() {
  dem_impact<double> im;
  im.bead = {7e10, 0.22, 1e-3, 2500};
  im.v0 = 0.5, im.gravity = 9.81;
  return im;
}

TEST(SteppedDrop, ConvergesToTheExactSolveAsTheStepShrinks) {
  for (const auto& [code, damping] : {std::pair{"lammps", "tsuji"}, {"lammps", "velocity"}, {"liggghts", "hertz"},
                                      {"yade", "mindlin"}}) {
    SCOPED_TRACE(std::string(code) + " " + damping);
    const dem_model& model = find_dem_model(code, damping);
    const dem_impact<double> im = glass_drop();
    const dem_deck<double> d = dem_deck_for(model, im, 0.8);
    const double exact = e_for_deck(model, im, d.damping).e;  // the Taylor solve, independent of the stepping
    const drop_timing<double> t = drop_timing_for(model, im, d);
    double previous = 1;
    for (const int n : {100, 400, 1600, 6400}) {
      const double dt = t.time_scale / n;
      const double e = stepped_e_for_deck(model, im, d, d.damping, dt);
      const double miss = std::abs(e - exact);
      EXPECT_LT(miss, previous) << "T/" << n;
      previous = miss;
      std::printf("%s %s T/%d: stepped e - exact e = %+.2e\n", code, damping, n, e - exact);
    }
    EXPECT_LT(previous, 2e-6) << "at T/6400";
  }
}

TEST(SteppedDrop, TheStepAwareDeckGivesTheTargetAtItsStep) {
  const dem_model& model = find_dem_model("lammps", "tsuji");
  const dem_impact<double> im = glass_drop();
  const dem_deck<double> continuous = dem_deck_for(model, im, 0.8);
  const drop_timing<double> t = drop_timing_for(model, im, continuous);
  const double dt = t.time_scale / 20;
  const dem_deck<double> d = dem_deck_at_time_step(model, im, 0.8, dt, continuous);
  EXPECT_NEAR(stepped_e_for_deck(model, im, d, d.damping, dt), 0.8, 1e-12);
  // at T/20 the continuous entry is off by about 1e-3, far more than the root finding's miss
  EXPECT_GT(std::abs(stepped_e_for_deck(model, im, continuous, continuous.damping, dt) - 0.8), 1e-4);
  EXPECT_NE(d.damping, continuous.damping);
}

TEST(SteppedDrop, ReadsTimeStepsAndRefusesBadOnes) {
  EXPECT_DOUBLE_EQ(time_step_of<double>("T/50", 2e-6, 7e-6), 2e-6 / 50);
  EXPECT_DOUBLE_EQ(time_step_of<double>("contact/20", 2e-6, 7e-6), 7e-6 / 20);
  EXPECT_DOUBLE_EQ(time_step_of<double>("1e-8", 2e-6, 7e-6), 1e-8);
  for (const char* bad : {"T/0", "T/-3", "contact/x", "-1e-8", "0", "fast"}) {
    try {
      time_step_of<double>(bad, 2e-6, 7e-6);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const viscor::invalid_parameter& e) {
      EXPECT_NE(std::string(e.what()).find("timestep"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
