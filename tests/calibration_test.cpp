// calibrate_gamma / calibrate_gamma0: round trips against exact solutions (Tsuji at
// g = 0 by the Antypov-Elliott relation; the linear law at any g), monotonicity of
// e in gamma (which the bracketing relies on), and the unreachable targets.
#include "scaling_reference.hpp"
#include "test_utils.hpp"

#include <viscor/scenes/calibration.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/certify/extern_templates.hpp>

#include <boost/math/constants/constants.hpp>

#include <string>

namespace viscor {
namespace {

using test::absolute_close;
using test::relative_close;
using test::scaling_reference;
using test::scaling_reference_row;

template <class Real>
class calibration_typed : public ::testing::Test {};

using calibration_types = ::testing::Types<double, long double
#if VISCOR_HAS_FLOAT128
                                           , quad
#endif
#if VISCOR_HAS_MPFR
                                           , mpfr_50
#endif
                                           >;
TYPED_TEST_SUITE(calibration_typed, calibration_types);

// Tsuji at g = 0: e = exp(-xi pi / sqrt(1 - xi^2)), xi = sqrt(5) gamma / 4, so
// gamma = (4 / sqrt 5) (-ln e) / sqrt(pi^2 + ln^2 e) exactly.
template <class Real>
Real tsuji_gamma_for(const Real& e) {
  using std::log;
  using std::sqrt;
  const Real L = log(e), pi = boost::math::constants::pi<Real>();
  return 4 / sqrt(Real(5)) * (-L) / sqrt(pi * pi + L * L);
}

TYPED_TEST(calibration_typed, tsuji_at_zero_load_matches_antypov_elliott) {
  using Real = TypeParam;
  using std::abs;
  using std::pow;
  const contact_law law = law_by_name("tsuji");
  const Real tol = pow(Real(10), 5 - decimal_digits<Real>());
  for (const char* text : {"0.999", "0.893", "0.5", "0.05"}) {
    const Real target = parse_real<Real>(text, "target");
    calibration_options<Real> options;
    options.tolerance = tol;
    const calibration_result<Real> r = calibrate_gamma(law, Real(0), target, options);
    SCOPED_TRACE(std::string("target e = ") + text);
    // The defining property, checked with the closed form: e(gamma) = target to tol.
    const std::optional<exact_result<Real>> exact = exact_cor(law, r.gamma, Real(0));
    ASSERT_TRUE(exact.has_value());
    EXPECT_PRED_FORMAT3(absolute_close<Real>, exact->e, target, tol);
    EXPECT_LE(r.target_bound, tol);
    // And gamma itself: off by at most tol / |de/dgamma| (slope from the closed form).
    const Real gamma_exact = tsuji_gamma_for(target);
    const Real h = gamma_exact * pow(Real(10), -decimal_digits<Real>() / 3);
    const Real slope = (exact_cor(law, Real(gamma_exact + h), Real(0))->e -
                        exact_cor(law, Real(gamma_exact - h), Real(0))->e) / (2 * h);
    EXPECT_PRED_FORMAT3(absolute_close<Real>, r.gamma, gamma_exact, Real(2 * tol / abs(slope)));
    EXPECT_LE(r.gamma_lo, r.gamma_hi);
  }
}

TYPED_TEST(calibration_typed, linear_law_round_trip_at_any_load) {
  using Real = TypeParam;
  using std::pow;
  const contact_law law = law_by_name("linear");
  const Real tol = pow(Real(10), 5 - decimal_digits<Real>());
  for (const char* g_text : {"-0.5", "0", "0.3", "2"}) {
    for (const char* e_text : {"0.95", "0.6", "0.2"}) {
      const Real g = parse_real<Real>(g_text, "g"), target = parse_real<Real>(e_text, "target");
      calibration_options<Real> options;
      options.tolerance = tol;
      const calibration_result<Real> r = calibrate_gamma(law, g, target, options);
      SCOPED_TRACE(std::string("g = ") + g_text + ", target e = " + e_text);
      EXPECT_PRED_FORMAT3(absolute_close<Real>, exact_cor(law, r.gamma, g)->e, target, tol);
      EXPECT_GT(r.solves, 0);
    }
  }
}

TEST(calibration, target_one_is_zero_damping) {
  const calibration_result<double> r = calibrate_gamma(law_by_name("kuwabara_kono"), 0.5, 1.0);
  EXPECT_EQ(r.gamma, 0.0);
  EXPECT_EQ(r.e, 1.0);
  EXPECT_EQ(r.solves, 0);
}

// The bracketing assumes e decreasing in gamma: check it where it is used.
TEST(calibration, e_decreases_with_gamma_for_the_named_laws) {
  for (const auto& named : named_laws) {
    const contact_law law = law_by_name(named.name);
    for (double g : {-0.5, 0.0, 0.05, 1.0, 10.0}) {
      double previous = 1;
      for (double gamma : {1e-6, 1e-4, 1e-3, 1e-2, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0}) {
        const impact_result<double> r = solve_impact(law, gamma, g);
        EXPECT_LE(r.e, previous + 1e-13) << named.name << " g = " << g << " gamma = " << gamma;
        previous = r.e;
      }
    }
  }
}

// Kuwabara-Kono has no closed form under load: compare with a 50-digit solve.
TEST(calibration, kuwabara_kono_under_load_against_50_digits) {
#if VISCOR_HAS_MPFR
  const contact_law law = law_by_name("kuwabara_kono");
  for (double g : {0.0, 0.05, 1.0, 10.0}) {
    for (double target : {0.99, 0.893, 0.3}) {
      calibration_options<double> options;
      options.tolerance = 1e-10;
      const calibration_result<double> r = calibrate_gamma(law, g, target, options);
      const impact_result<mpfr_50> ref = solve_impact(law, mpfr_50(r.gamma), mpfr_50(g));
      EXPECT_PRED_FORMAT3(absolute_close<mpfr_50>, ref.e, mpfr_50(target), mpfr_50(1e-10))
          << "g = " << g << " target " << target;
    }
  }
#else
  GTEST_SKIP() << "needs MPFR";
#endif
}

TEST(calibration, physical_steel_bead_with_and_without_gravity) {
  // The report's 8 mm steel bead (sec. 4.1, docs/report-notes.md), Kuwabara-Kono, e = 0.893.
  const contact_law law = law_by_name("kuwabara_kono");
  const double m = 2.05e-3, k = 6.9716e9, v0 = 0.246, target = 0.893;
  calibration_options<double> options;
  options.tolerance = 1e-12;
  const physical_calibration<double> with = calibrate_gamma0(law, m, k, v0, 9.8, 0.0, target, options);
  const physical_calibration<double> without = calibrate_gamma0(law, m, k, v0, 0.0, 0.0, target, options);
  EXPECT_EQ(without.scaled.g, 0.0);
  EXPECT_PRED_FORMAT3(relative_close<double>, with.scaled.g, 5.1224e-4, 1e-4);  // docs/report-notes.md value
  // gamma0 against eq. (2) evaluated outside the library (tests/data/scaling_reference.csv):
  // gamma = gamma0 * (gamma at gamma0 = 1), and g at this bead.
  const scaling_reference_row unit = scaling_reference("steel_bead_unit_damping", "kuwabara_kono");
  const double damping_factor = std::stod(unit.gamma);
  EXPECT_PRED_FORMAT3(relative_close<double>, with.scaled.g, std::stod(unit.g), 1e-14);
  for (const auto* c : {&with, &without})
    EXPECT_PRED_FORMAT3(relative_close<double>, c->gamma0 * damping_factor, c->scaled.gamma, 1e-14);
  EXPECT_PRED_FORMAT3(relative_close<double>, with.time_scale, std::stod(unit.time_scale), 1e-14);
  // Forward again through eq. (2) and the solver: the target comes back.
  for (const auto* c : {&with, &without}) {
    physical_parameters<double> p;
    p.m = m, p.k = k, p.v0 = v0, p.gravity = c == &with ? 9.8 : 0.0, p.gamma0 = c->gamma0;
    const scaled_parameters<double> s = to_scaled(law, p);
    EXPECT_PRED_FORMAT3(relative_close<double>, s.gamma, c->scaled.gamma, 1e-14);
    EXPECT_PRED_FORMAT3(absolute_close<double>, solve_impact(law, s.gamma, s.g).e, target, 1e-12);
  }
  // A load makes the same e need less damping (e decreases with g).
  EXPECT_LT(with.gamma0, without.gamma0);
}

TEST(calibration, unreachable_and_invalid_targets) {
  const contact_law law = law_by_name("kuwabara_kono");
  auto message = [&](double g, double target) {
    try {
      calibrate_gamma(law, g, target);
    } catch (const unreachable_target& e) {
      return std::string("unreachable: ") + e.what();
    } catch (const invalid_parameter& e) {
      return std::string("invalid: ") + e.what();
    }
    return std::string("no error");
  };
  EXPECT_NE(message(0.0, 1.2).find("unreachable: target_e = 1.2"), std::string::npos) << message(0.0, 1.2);
  EXPECT_NE(message(0.0, 0.0).find("unreachable: target_e = 0 is a threshold"), std::string::npos);
  EXPECT_NE(message(0.0, -0.1).find("invalid: parameter target_e must be in [0, 1]"), std::string::npos);
  // A pulling load: e(gamma = 100) = 0.058 for g = -0.5, so e = 1e-3 is out of reach.
  const std::string pulled = message(-0.5, 1e-3);
  EXPECT_NE(pulled.find("unreachable: target_e = 1.0"), std::string::npos) << pulled;
  EXPECT_NE(pulled.find("gamma_max"), std::string::npos) << pulled;
  EXPECT_THROW(calibrate_gamma(law, std::numeric_limits<double>::infinity(), 0.5), invalid_parameter);
  calibration_options<double> too_tight;
  too_tight.tolerance = 1e-17;
  EXPECT_THROW(calibrate_gamma(law, 0.0, 0.5, too_tight), precision_unavailable);
  EXPECT_THROW(calibrate_gamma0(law, -1.0, 1e9, 1.0, 9.8, 0.0, 0.5), invalid_parameter);
}

}  // namespace
}  // namespace viscor
