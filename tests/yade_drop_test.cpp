// YADE reproduces the target e with the deck of `viscor dem yade --damping mindlin`
// (default-suite subset: the polymer bead at v0 = 0.01 m/s under gravity and the
// steel bead at 1 m/s without, each at dt = T/400 and T/800, in one yade run of a few
// seconds). The sweep is yade_drop_slow_test.cpp. Skipped, with the reason, when
// yade is not installed (tools/install-deps.sh installs it).
#include "yade_drop_utils.hpp"

#include <cmath>

namespace {

using namespace viscor::test;
using namespace viscor::test::yade_drop;

TEST(YadeDrop, MindlinReproducesTarget) {
  const auto yade = find_yade();
  if (!yade) GTEST_SKIP() << "yade is not installed (tools/install-deps.sh installs it)";
  const auto& steel = dem_drop::drop_materials()[0];
  const auto& polymer = dem_drop::drop_materials()[1];
  std::vector<drop_case> cases{deck_drop(polymer, 0.01, 9.81, 400), deck_drop(polymer, 0.01, 9.81, 800),
                               deck_drop(steel, 1.0, 0.0, 400), deck_drop(steel, 1.0, 0.0, 800)};
  std::string message;
  ASSERT_TRUE(run_drops(*yade, cases, message)) << message;
  for (std::size_t i = 0; i < cases.size(); i += 2) {
    const drop_case& coarse = cases[i];
    const drop_case& fine = cases[i + 1];
    SCOPED_TRACE(coarse.name);
    ASSERT_TRUE(coarse.ok && fine.ok);
    EXPECT_TRUE(coarse.force_free && fine.force_free);  // the clamp released the bead before zero overlap
    const double miss = coarse.e - coarse.expected_e, fine_miss = fine.e - fine.expected_e;
    EXPECT_LE(std::abs(miss), yade_tolerance_at_T_over_400) << "e = " << coarse.e;
    EXPECT_LT(std::abs(fine_miss), std::abs(miss)) << "halving dt: e = " << fine.e;
    std::printf("[yade] %s: e = %.10f (miss %.2e), at dt/2 e = %.10f (miss %.2e)\n", coarse.name.c_str(), coarse.e,
                miss, fine.e, fine_miss);
  }
}

}  // namespace
