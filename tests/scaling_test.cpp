// Scaling of eq. (2): against values computed outside the library, round trips,
// and the report's worked numbers.
#include "scaling_reference.hpp"
#include "test_utils.hpp"

#include <viscor/core/scaling.hpp>

namespace viscor::test {
namespace {

template <class Real>
class Scaling : public ::testing::Test {};
TYPED_TEST_SUITE(Scaling, all_real_types);

// tests/data/scaling_reference.csv (tools/scaling_reference.py, derived from the
// physical equation of motion, not from the exponents of scaling.hpp).
TYPED_TEST(Scaling, MatchesIndependentReference) {
  using Real = TypeParam;
  using std::abs;
  // a few roundings of the decimal inputs through pow
  const Real tol = 256 * epsilon<Real>();
  int checked = 0;
  for (const auto& r : scaling_reference_rows()) {
    SCOPED_TRACE(r.case_name + " " + r.law);
    physical_parameters<Real> p;
    p.m = parse_real<Real>(r.m, "m"), p.k = parse_real<Real>(r.k, "k"), p.gamma0 = parse_real<Real>(r.gamma0, "gamma0");
    p.v0 = parse_real<Real>(r.v0, "v0"), p.gravity = parse_real<Real>(r.gravity, "gravity");
    p.force = parse_real<Real>(r.force, "F");
    const contact_law law = law_by_name(r.law);
    const scaled_parameters<Real> s = to_scaled(law, p);
    EXPECT_PRED_FORMAT3(relative_close<Real>, s.gamma, parse_real<Real>(r.gamma, "gamma"), tol);
    EXPECT_PRED_FORMAT3(relative_close<Real>, s.g, parse_real<Real>(r.g, "g"), tol);
    EXPECT_PRED_FORMAT3(relative_close<Real>, s.time_scale, parse_real<Real>(r.time_scale, "T"), tol);
    // and back: the reference's gamma and g give the reference's gamma0 and F
    const physical_parameters<Real> q = to_physical(law, parse_real<Real>(r.gamma, "gamma"),
                                                    parse_real<Real>(r.g, "g"), p.m, p.k, p.v0, p.gravity);
    EXPECT_PRED_FORMAT3(relative_close<Real>, q.gamma0, p.gamma0, tol);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, q.force, p.force, Real(1e3 * tol * (abs(p.force) + p.m * abs(p.gravity))));
    ++checked;
  }
  EXPECT_GE(checked, 26);  // 3 cases x 5 laws, unit damping x 5 laws, the scene x 3 speeds, the DEM bead x 3 laws
}

TYPED_TEST(Scaling, PhysicalScaledPhysicalRoundTrip) {
  using Real = TypeParam;
  const Real tol = 64 * epsilon<Real>();
  for (const auto& n : named_laws) {
    SCOPED_TRACE(n.name);
    physical_parameters<Real> p;
    p.m = parse_real<Real>("2.05e-3", "m");
    p.k = parse_real<Real>("9.858e9", "k");
    p.gamma0 = parse_real<Real>("1.5237e-6", "gamma0");
    p.v0 = parse_real<Real>("0.731", "v0");
    p.gravity = parse_real<Real>("9.80665", "gravity");
    p.force = parse_real<Real>("0.0375", "F");
    const contact_law law = law_by_name(n.name);
    const scaled_parameters<Real> s = to_scaled(law, p);
    const physical_parameters<Real> q = to_physical(law, s.gamma, s.g, p.m, p.k, p.v0, p.gravity);
    EXPECT_PRED_FORMAT3(relative_close<Real>, q.gamma0, p.gamma0, tol);
    EXPECT_PRED_FORMAT3(relative_close<Real>, q.force, p.force, Real(1e3 * tol));  // F = m a - m gravity cancels
    // the time scale is what it says: delta = v0 T, and g = load T^2/delta
    EXPECT_PRED_FORMAT3(relative_close<Real>, s.length_scale, Real(p.v0 * s.time_scale), tol);
    EXPECT_PRED_FORMAT3(relative_close<Real>, s.g,
                        Real((p.gravity + p.force / p.m) * s.time_scale * s.time_scale / s.length_scale), tol);
  }
}

TYPED_TEST(Scaling, ReportFigure2bLoadVanishesAtMinusMg) {
  // Fig. 2(b): m = 0.154 kg, k = 3.6138e10, alpha = beta = 3/2, gravity 9.8:
  // g = 0 at F = -1.5092 N (= -m * 9.8) for every impact speed.
  using Real = TypeParam;
  using std::abs;
  for (const char* v0 : {"0.01", "0.246", "1", "10"}) {
    physical_parameters<Real> p;
    p.m = parse_real<Real>("0.154", "m");
    p.k = parse_real<Real>("3.6138e10", "k");
    p.v0 = parse_real<Real>(v0, "v0");
    p.gravity = parse_real<Real>("9.8", "gravity");
    p.force = parse_real<Real>("-1.5092", "F");
    const scaled_parameters<Real> s = to_scaled(law_by_name("kuwabara_kono"), p);
    p.force = 0;
    const Real g_without_force = to_scaled(law_by_name("kuwabara_kono"), p).g;
    // rounding of the decimal inputs leaves a few ulps of the unbalanced load
    EXPECT_LE(abs(s.g), 16 * epsilon<Real>() * g_without_force) << "v0 = " << v0;
  }
}

TYPED_TEST(Scaling, ReportSteelBeadLoads) {
  // Sec. 4.1 and docs/report-notes.md: m = 2.05e-3 kg, alpha = 3/2, gravity 9.8, F = 0.
  using Real = TypeParam;
  struct row {
    const char *k, *v0, *g_printed;
  };
  for (const row& r : {row{"9.858e9", "1", "8.2873e-5"}, row{"6.9716e9", "0.246", "5.1224e-4"},
                       row{"9.858e9", "0.246", "4.4595e-4"}}) {
    physical_parameters<Real> p;
    p.m = parse_real<Real>("2.05e-3", "m");
    p.k = parse_real<Real>(r.k, "k");
    p.v0 = parse_real<Real>(r.v0, "v0");
    p.gravity = parse_real<Real>("9.8", "gravity");
    const Real g = to_scaled(law_by_name("kuwabara_kono"), p).g;
    // printed to 5 significant digits: half a unit in the last place
    EXPECT_PRED_FORMAT3(relative_close<Real>, g, parse_real<Real>(r.g_printed, "g"), Real(6e-5)) << r.k << " " << r.v0;
  }
}

}  // namespace
}  // namespace viscor::test
