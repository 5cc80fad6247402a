// Issue 18 item 8, the full grid of what is fixed (see overdamped_test.cpp): gamma
// from 2 to 1e10 and g from 1e-3 to 1e12 (where the trapping sector holds from the
// start: gamma beta u^(beta-1) large enough), every named law, double and 50 digits.
// The rest of the box (g <= 0: creeping out or into u = 0) is measured by
// tools/overdamped_sweep.py, not yet asserted.
#include <gtest/gtest.h>

#include "overdamped_test_utils.hpp"

namespace {

using namespace viscor;

TEST(overdamped_slow, creep_up_to_the_equilibrium_full_grid) {
  for (const char* law : viscor::test::overdamped_laws)
    for (const char* gamma : {"1e2", "1e3", "1e4", "1e6", "1e8", "1e10"})
      for (const char* g : {"1e-3", "1", "1e3", "1e6", "1e9", "1e12"}) {
        viscor::test::check_creep_up<double>(law, gamma, g);
        viscor::test::check_creep_up<mpfr_50>(law, gamma, g);
      }
}

TEST(overdamped_slow, creeping_out_full_grid_double) {
  // g < 0 for every law at gamma >= 1e3 (the stiff creep out), and g = 0 for
  // Hunt-Crossley (a creep out at finite speed, the closed form the truth).
  for (const char* law : viscor::test::overdamped_laws)
    for (const char* gamma : {"1e3", "1e4", "1e6", "1e8", "1e10"})
      for (const char* g : {"-1e6", "-1e3", "-1", "-1e-3"}) viscor::test::check_creep_out<double>(law, gamma, g, 1e-9);
  for (const char* gamma : {"1e3", "1e4", "1e6", "1e8", "1e10"})
    viscor::test::check_creep_out<double>("hunt_crossley", gamma, "0", 1e-9);
}

TEST(overdamped_slow, creeping_out_50_digits) {
  // Spot checks: the implicit steps at 50 digits take seconds per solve (docs/performance.md).
  for (const char* law : {"linear", "hunt_crossley"})
    viscor::test::check_creep_out<mpfr_50>(law, "1e10", "-1", mpfr_50("1e-40"));
  viscor::test::check_creep_out<mpfr_50>("hunt_crossley", "1e10", "0", mpfr_50("1e-40"));
}

}  // namespace
