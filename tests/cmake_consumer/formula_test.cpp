// A formula developer's test, outside viscor: Prop. 2 of the report (numeric
// coefficients) holds to 1e-5 where the damping is light, by the installed tables.
#include <viscor/testing/cor_formula.hpp>

#include <viscor/approx/approximations.hpp>

namespace {

double prop2_numeric(double gamma, double g) {
  static const viscor::cor_approximations<double> approx(viscor::law_by_name("kuwabara_kono"));
  return approx.prop2(gamma, g, viscor::coefficient_source::numeric).e;
}

TEST(ConsumerFormula, Prop2HoldsForLightDamping) {
  EXPECT_COR_WITHIN_REGION(prop2_numeric, "kuwabara_kono", (viscor::formula_region{0, 1e-3, 0, 10}), 1e-5);
}

}  // namespace
