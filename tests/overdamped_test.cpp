// The overdamped extremes, default-suite samples: under a load g > 0 with strong
// damping the bead is pushed in at its terminal speed and creeps up to the
// equilibrium u* = g^(1/alpha) without ever turning back. Both methods prove it by the
// trapping sector below u* while still compressing (steps bounded by the fast damping
// scale would exhaust any budget: linear law, gamma = 1e4, g = 1e6 needs over 1e6).
// Where it is not a creep (a real turn back: Hunt-Crossley at gamma = 1e2, g = 1e-3)
// the stick must still be found and agreed on; where it is pressed past u* and
// creeps back down to it, the trapping sector above u* proves the stick. Truth: the linear law's closed form;
// for the other laws the two methods, which make their proofs independently, must agree. No timing is asserted here (speed lives in
// tools/overdamped_sweep.py and docs/performance.md); a step count bounds the work.
// The full grid of gamma in [2, 1e10], g in (0, 1e12] is overdamped_slow_test.cpp.
#include <viscor/exact/exact_linear.hpp>
#include <viscor/impact/adaptive_impact.hpp>
#include <viscor/impact/taylor_impact.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "overdamped_test_utils.hpp"

namespace {

using namespace viscor;

TEST(overdamped, creep_up_to_the_equilibrium_is_a_proven_stick_double) {
  for (const char* law : viscor::test::overdamped_laws)
    for (const char* gamma : {"1e2", "1e6", "1e10"})
      for (const char* g : {"1e-3", "1e3", "1e12"}) viscor::test::check_creep_up<double>(law, gamma, g);
}

TEST(overdamped, creep_up_to_the_equilibrium_is_a_proven_stick_50_digits) {
  for (const char* law : viscor::test::overdamped_laws)
    for (const char* gamma : {"1e4", "1e10"})
      for (const char* g : {"1", "1e9"}) viscor::test::check_creep_up<mpfr_50>(law, gamma, g);
}

TEST(overdamped, pressed_past_the_equilibrium_creeps_back_a_proven_stick) {
  // Maximal compression above u* (the bead arrives faster than it creeps), then a creep
  // back down to u* on the slow manifold, inside the trapping sector from the start.
  // The adaptive method's GBS steps cannot follow that creep, and E > 0 bounds e only by
  // ~1e-2: without the trapping sector after maximal compression it would say
  // `undecided`. The Taylor solver proves the stick on its own.
  using viscor::test::check_overdamped_point;
  for (const char* gamma : {"1e3", "1e4"})
    EXPECT_EQ(check_overdamped_point<double>("hunt_crossley", gamma, "1e-3"), impact_outcome::stick);
  EXPECT_EQ(check_overdamped_point<mpfr_50>("hunt_crossley", "1e4", "1e-3"), impact_outcome::stick);
  EXPECT_EQ(check_overdamped_point<mpfr_50>("tsuji", "1e2", "1e-3"), impact_outcome::stick);
}

TEST(overdamped, creeping_out_is_a_rebound_both_methods_agree_double) {
  // g < 0 for every law, g = 0 for Hunt-Crossley (alpha + 1 < 2 beta: no barrier to a
  // creep into u = 0; the closed form gives e ~ 1/(2.5 gamma)). Against a closed form
  // (linear law; Hunt-Crossley at g = 0) e is held to overdamped_tolerances; between
  // the methods to 1e-9 (measured up to 6.1e-11: Tsuji, gamma = 1e10, g = -1e-3).
  for (const char* law : viscor::test::overdamped_laws)
    for (const char* gamma : {"1e4", "1e10"})
      for (const char* g : {"-1e6", "-1", "-1e-3"}) viscor::test::check_creep_out<double>(law, gamma, g, 1e-9);
  for (const char* gamma : {"1e4", "1e10"}) viscor::test::check_creep_out<double>("hunt_crossley", gamma, "0", 1e-9);
}

TEST(overdamped, creeping_out_at_zero_load_50_digits) {
  // At 50 digits the adaptive method's implicit creep steps in ln u (adaptive_impact.hpp
  // creep_implicitly); truth: Hunt-Crossley's closed form (to overdamped_tolerances),
  // for Kuwabara-Kono the Taylor solver (the two share no integrator code), to 1e-45 of
  // e ~ 7e-51.
  viscor::test::check_creep_out<mpfr_50>("hunt_crossley", "1e10", "0", mpfr_50("1e-45"));
  viscor::test::check_creep_out<mpfr_50>("kuwabara_kono", "1e10", "0", mpfr_50("1e-45"));
}

TEST(overdamped, creeping_out_under_a_pull_50_digits) {
  // g < 0: both methods hand the creep to implicit steps in ln u at 50 digits (Radau in
  // the Taylor solver, Lobatto in the GBS solver). Truth: the linear law's closed form
  // (to overdamped_tolerances; the 1e-45 applies only between the methods); for Tsuji
  // each method is the other's truth (they share no integrator code but the LU), to
  // 1e-43 of e ~ 6.6e-10 (they differ by 2.4e-45 relative).
  viscor::test::check_creep_out<mpfr_50>("linear", "1e10", "-1", mpfr_50("1e-45"));
  viscor::test::check_creep_out<mpfr_50>("tsuji", "1e10", "-1e-3", mpfr_50("1e-43"));
}

}  // namespace
