// The YADE sweep (label slow): both materials of dem_drop_utils.hpp, v0 in {0.01, 1}
// m/s, gravity 0 and 9.81 m/s^2, dt = T/200, T/400, T/800, with the deck of
// `viscor dem yade --damping mindlin`; and YADE's own `en` conversion (Thornton's
// fit) against the builtin_e viscor predicts for it. One yade run for all drops.
// And the visco-elastic law for head-on pairs (the deck's 2 kn, 2 cn per material).
#include "yade_drop_utils.hpp"

#include <cmath>

namespace {

using namespace viscor::test;
using namespace viscor::test::yade_drop;

TEST(YadeDropSweep, MindlinReproducesTarget) {
  const auto yade = find_yade();
  if (!yade) VISCOR_SKIP_OR_FAIL_MISSING("yade is not installed (tools/install-deps.sh installs it)");
  std::vector<drop_case> cases;
  for (const auto& m : dem_drop::drop_materials())
    for (double v0 : {0.01, 1.0})
      for (double gravity : {0.0, 9.81})
        for (int per_T : {200, 400, 800}) cases.push_back(deck_drop(m, v0, gravity, per_T));
  std::string message;
  ASSERT_TRUE(run_drops(*yade, cases, message)) << message;
  for (std::size_t i = 0; i < cases.size(); i += 3) {  // T/200, T/400, T/800
    check_halving(cases[i + 1], cases[i + 2], yade_tolerance_at_T_over_400, halving::shrinks);
    SCOPED_TRACE(cases[i].name);
    ASSERT_TRUE(cases[i].ok);
    EXPECT_LT(std::abs(cases[i + 1].e - cases[i + 1].expected_e), std::abs(cases[i].e - cases[i].expected_e));
  }
}

// Two identical beads head-on (E* = E/(2(1 - nu^2)), R* = R/2, m* = m/2), free and
// pressed together by 1e-4 N each (setPermF), at dt = T/400 and T/800.
TEST(YadeDropSweep, PairReproducesTarget) {
  const auto yade = find_yade();
  if (!yade) VISCOR_SKIP_OR_FAIL_MISSING("yade is not installed (tools/install-deps.sh installs it)");
  std::vector<drop_case> cases;
  for (const auto& m : dem_drop::drop_materials())
    for (double force : {0.0, 1e-4})
      for (int per_T : {400, 800}) cases.push_back(deck_drop(m, 0.01, 0.0, per_T, contact_kind::pair, force));
  std::string message;
  ASSERT_TRUE(run_drops(*yade, cases, message)) << message;
  for (std::size_t i = 0; i < cases.size(); i += 2)
    check_halving(cases[i], cases[i + 1], yade_tolerance_at_T_over_400, halving::shrinks);
}

// Writing the measured e as `en` (YADE's own conversion): YADE gives viscor's builtin_e.
TEST(YadeDropSweep, BuiltinConversion) {
  const auto yade = find_yade();
  if (!yade) VISCOR_SKIP_OR_FAIL_MISSING("yade is not installed (tools/install-deps.sh installs it)");
  const dem_model& model = find_dem_model("yade", "mindlin");
  std::vector<drop_case> cases;
  for (const auto& m : dem_drop::drop_materials())
    for (double v0 : {0.01, 1.0}) {
      drop_case c = deck_drop(m, v0, 9.81, 800);
      dem_impact<double> impact;
      impact.bead = m.bead, impact.v0 = v0, impact.gravity = 9.81;
      c.en = dem_drop::format_double(m.target_e);
      c.expected_e = *dem_deck_for(model, impact, m.target_e).builtin_e;
      cases.push_back(c);
    }
  std::string message;
  ASSERT_TRUE(run_drops(*yade, cases, message)) << message;
  for (const drop_case& c : cases) {
    SCOPED_TRACE(c.name);
    ASSERT_TRUE(c.ok);
    EXPECT_NEAR(c.e, c.expected_e, yade_tolerance_at_T_over_400 / 2);
    std::printf("[yade] en: %s: e = %.6f, builtin_e = %.6f\n", c.name.c_str(), c.e, c.expected_e);
  }
}

// YADE visco-elastic, two beads head-on (contact kn, cn = half the material's), free and
// pressed together by 1e-4 N each, at dt = T/400 and T/800: first-order misses as on the wall.
TEST(YadeDropSweep, ViscoelasticPairReproducesTarget) {
  const auto yade = find_yade();
  if (!yade) VISCOR_SKIP_OR_FAIL_MISSING("yade is not installed (tools/install-deps.sh installs it)");
  std::vector<drop_case> cases;
  for (const auto& m : viscel_materials())
    for (double force : {0.0, 1e-4})
      for (int per_T : {400, 800}) cases.push_back(viscel_drop(m, 0.01, 0.0, per_T, contact_kind::pair, force));
  std::string message;
  ASSERT_TRUE(run_drops(*yade, cases, message)) << message;
  for (std::size_t i = 0; i < cases.size(); i += 2)
    check_halving(cases[i], cases[i + 1], yade_viscel_tolerance_at_T_over_400, halving::first_order);
}

}  // namespace
