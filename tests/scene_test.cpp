// Scenes (scene.hpp): Hertz stiffness and mass from materials, resolution of a
// description (errors naming the field), the calibrate-then-evaluate round trip,
// and rows in physical units.
#include "scaling_reference.hpp"
#include "test_utils.hpp"

#include <viscor/exact/exact_solutions.hpp>
#include <viscor/certify/extern_templates.hpp>
#include <viscor/dem/hertz_contact.hpp>
#include <viscor/jobs/physical_inputs.hpp>
#include <viscor/scenes/scene.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace viscor {
namespace {

using test::relative_close;

scene_description steel_bead() {
  scene_description d;
  d.law = law_by_name("kuwabara_kono");
  d.density = "7850", d.radius = "4e-3", d.youngs_modulus = "2.0e11", d.poisson_ratio = "0.3";
  d.gamma0 = "8.5e-7";
  d.gravity = "9.8";
  d.velocities = {"0.1", "0.246", "1"};
  d.tolerance = "1e-6";
  return d;
}

TEST(scene, hertz_stiffness_and_mass_from_materials) {
  // Expected values computed independently (Python, double): k = (4/3) E* sqrt(R).
  scene_description d = steel_bead();
  resolved_scene<double> rigid = resolve_scene<double>(d);
  EXPECT_TRUE(rigid.stiffness_from_material);
  EXPECT_PRED_FORMAT3(relative_close<double>, rigid.stiffness, 18533495444.210281, 1e-14);
  EXPECT_PRED_FORMAT3(relative_close<double>, rigid.mass, 0.0021044481988846827, 1e-14);
  d.wall_youngs_modulus = "2.0e11", d.wall_poisson_ratio = "0.3";
  EXPECT_PRED_FORMAT3(relative_close<double>, resolve_scene<double>(d).stiffness, 9266747722.1051407, 1e-14);
  d.wall_youngs_modulus = "7.0e10", d.wall_poisson_ratio = "0.22";
  EXPECT_PRED_FORMAT3(relative_close<double>, resolve_scene<double>(d).stiffness, 4647601211.7006321, 1e-14);
#if VISCOR_HAS_MPFR
  // The same at 50 digits: the closed form in mpfr, against the same formula in mpfr (no double inside).
  const resolved_scene<mpfr_50> r50 = resolve_scene<mpfr_50>(d);
  const mpfr_50 e_star = 1 / ((1 - mpfr_50("0.09")) / mpfr_50("2.0e11") + (1 - mpfr_50("0.0484")) / mpfr_50("7.0e10"));
  EXPECT_PRED_FORMAT3(relative_close<mpfr_50>, r50.stiffness, mpfr_50(4 * e_star * sqrt(mpfr_50("4e-3")) / 3),
                      mpfr_50(1e-48));
#endif
}

// One contact from materials in every command: a scene, `viscor cor`/`calibrate`
// (jobs/physical_inputs.hpp bead_of_material) and the DEM decks (make_hertz_contact)
// give the same m* and k to the last bit (they once took three orders of operations).
TEST(scene, every_command_takes_the_same_contact_from_materials) {
  std::mt19937_64 rng(54);
  auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  auto log_uniform = [&](double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); };
  auto text = [](double x) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return std::string(b);
  };
  auto bits_equal = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  const contact_law law = law_by_name("tsuji");
  int compared = 0, differences = 0;
  for (int n = 0; n < 4000; ++n) {
    const dem::bead_material<double> bead{log_uniform(1e6, 3e11), uniform(-0.5, 0.5), log_uniform(1e-5, 1e-1),
                                          uniform(500, 20000)};
    const dem::bead_material<double> other{log_uniform(1e6, 3e11), uniform(-0.5, 0.5), log_uniform(1e-5, 1e-1),
                                           uniform(500, 20000)};
    const elastic_material<double> wall{log_uniform(1e6, 3e11), uniform(-0.5, 0.5)};
    const dem::contact_kind kind = n % 4 < 2 ? dem::contact_kind::wall : dem::contact_kind::pair;
    dem::contact_partner<double> partner;
    if (n % 4 == 1) partner.wall = wall;
    if (n % 4 == 3) partner.other = other;
    const dem::hertz_contact<double> deck = dem::make_hertz_contact(bead, kind, partner);
    const auto [m, k] = jobs::bead_of_material<double>(law, bead.youngs_modulus, bead.poisson_ratio, bead.radius,
                                                       std::nullopt, bead.density, kind, partner);
    scene_description d;
    d.law = law;
    d.density = text(bead.density), d.radius = text(bead.radius);
    d.youngs_modulus = text(bead.youngs_modulus), d.poisson_ratio = text(bead.poisson_ratio);
    if (partner.wall) d.wall_youngs_modulus = text(wall.youngs_modulus), d.wall_poisson_ratio = text(wall.poisson_ratio);
    d.pair = kind == dem::contact_kind::pair;
    if (partner.other) {
      d.other_density = text(other.density), d.other_radius = text(other.radius);
      d.other_youngs_modulus = text(other.youngs_modulus), d.other_poisson_ratio = text(other.poisson_ratio);
    }
    d.gamma0 = "0";
    d.velocities = {"1"};
    d.tolerance = "1e-6";
    const resolved_scene<double> scene = resolve_scene<double>(d);
    ++compared;
    if (!bits_equal(m, deck.effective_mass) || !bits_equal(k, deck.stiffness) || !bits_equal(scene.mass, deck.effective_mass) ||
        !bits_equal(scene.stiffness, deck.stiffness)) {
      if (++differences <= 5)
        ADD_FAILURE() << "case " << n << " (kind " << n % 4 << "): deck m* " << deck.effective_mass << " k "
                      << deck.stiffness << ", cor " << m << " " << k << ", scene " << scene.mass << " " << scene.stiffness;
    }
  }
  EXPECT_EQ(compared, 4000);
  EXPECT_EQ(differences, 0);
}

TEST(scene, resolution_errors_name_the_field) {
  auto message = [](const scene_description& d) {
    try {
      resolve_scene<double>(d);
    } catch (const invalid_parameter& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  scene_description d = steel_bead();
  d.density = "-7850";
  EXPECT_NE(message(d).find("bead.density must be > 0"), std::string::npos) << message(d);
  d = steel_bead();
  d.poisson_ratio = "0.6";
  EXPECT_NE(message(d).find("bead.poisson_ratio must be in (-1, 0.5]"), std::string::npos) << message(d);
  d = steel_bead();
  d.mass = "1e-3";
  EXPECT_NE(message(d).find("not both"), std::string::npos) << message(d);
  d = steel_bead();
  d.law = law_by_name("linear");
  EXPECT_NE(message(d).find("alpha = 3/2"), std::string::npos) << message(d);
  d = steel_bead();
  d.tolerance = "0";
  EXPECT_NE(message(d).find("tolerance must be > 0"), std::string::npos) << message(d);
  d = steel_bead();
  d.velocities = {"0.1", "-1"};
  EXPECT_NE(message(d).find("velocities[1] must be > 0"), std::string::npos) << message(d);
  d = steel_bead();
  d.gamma0.reset();
  EXPECT_NE(message(d).find("missing field damping"), std::string::npos) << message(d);
  d.measured_e = "1.2", d.measured_speed = "0.2", d.measured_gravity = "9.8";
  EXPECT_NE(message(d).find("damping.measured_e: target_e = 1.2"), std::string::npos) << message(d);
  EXPECT_NE(message(d).find("is unreachable"), std::string::npos) << message(d);
  d = steel_bead();
  d.density.reset(), d.radius.reset(), d.youngs_modulus.reset(), d.poisson_ratio.reset();
  EXPECT_NE(message(d).find("missing field bead"), std::string::npos) << message(d);
  d.mass = "-1", d.stiffness = "1e9";
  EXPECT_NE(message(d).find("bead.m must be > 0"), std::string::npos) << message(d);
}

// The steel bead from its material: each row's gamma and g against eq. (2) evaluated
// outside the library (tests/data/scaling_reference.csv, k and m from the material there too).
TEST(scene, steel_bead_rows_match_independent_scaling) {
  scene_description d = steel_bead();
  d.velocities = {"0.1", "0.246", "1"};
  const resolved_scene<double> s = resolve_scene<double>(d);
  int rows = 0;
  run_scene(s, nullptr, [&](const scene_row<double>& row) {
    const char* v0 = d.velocities[rows++].c_str();
    SCOPED_TRACE(v0);
    const test::scaling_reference_row ref = test::scaling_reference(std::string("scene_steel_v") + v0, "kuwabara_kono");
    EXPECT_PRED_FORMAT3(relative_close<double>, row.gamma, std::stod(ref.gamma), 1e-14);
    EXPECT_PRED_FORMAT3(relative_close<double>, row.g, std::stod(ref.g), 1e-14);
  });
  EXPECT_EQ(rows, 3);
}

// Acceptance: calibrate gamma0 from e, evaluate with that gamma0, get e back.
TEST(scene, calibrate_then_evaluate_round_trip) {
  for (const char* tolerance : {"1e-4", "1e-10"}) {
    scene_description d = steel_bead();
    d.gamma0.reset();
    d.measured_e = "0.893", d.measured_speed = "0.246", d.measured_gravity = "9.8";
    d.tolerance = tolerance;
    d.velocities = {"0.05", "0.246"};
    const resolved_scene<double> s = resolve_scene<double>(d);
    ASSERT_TRUE(s.calibration.has_value());
    std::vector<scene_row<double>> rows;
    run_scene(s, nullptr, [&](const scene_row<double>& r) { rows.push_back(r); });
    ASSERT_EQ(rows.size(), 2u);
    const double tol = std::strtod(tolerance, nullptr);
    EXPECT_LE(std::abs(rows[1].result.e - 0.893), tol) << "tolerance " << tolerance;
    EXPECT_LE(rows[1].result.bound, tol);
    EXPECT_GT(rows[0].result.e, rows[1].result.e);  // slower impacts lose less (KK: gamma grows with v0)
  }
}

TEST(scene, velocity_ranges_end_at_the_given_speeds) {
  // A linear range from 1e25 down to 2 ended at from + (to - from) = 0 in double (a
  // fuzzer's finding: tests/fuzz/findings/scene/linear-range-ends-at-zero); log ranges
  // whose ratio overflows or underflows ended at inf or 0.
  scene_description d = steel_bead();
  d.velocities.clear();
  d.velocity_from = "9999999999999999999999990.5", d.velocity_to = "2", d.velocity_count = 32;
  std::vector<double> v = resolve_scene<double>(d).velocities;
  ASSERT_EQ(v.size(), 32u);
  EXPECT_EQ(v.front(), 9999999999999999999999990.5);
  EXPECT_EQ(v.back(), 2.0);
  for (std::size_t i = 1; i < v.size(); ++i) EXPECT_LT(v[i], v[i - 1]) << i;
  // Logarithmic, 1e-300 to 1e300 and back in 5 speeds: exactly the powers 10^(-300 + 150 i)
  // up to rounding (truth: the decimal exponents, not the code's formula).
  d.velocity_log = true, d.velocity_count = 5;
  for (const bool up : {true, false}) {
    d.velocity_from = up ? "1e-300" : "1e300", d.velocity_to = up ? "1e300" : "1e-300";
    v = resolve_scene<double>(d).velocities;
    ASSERT_EQ(v.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
      const double expected = std::pow(10.0, up ? -300.0 + 150.0 * i : 300.0 - 150.0 * i);
      EXPECT_PRED_FORMAT3(relative_close<double>, v[i], expected, 1e-12) << (up ? "up " : "down ") << i;
    }
  }
  // A linear span that overflows double cannot come from speeds (both > 0), but from an
  // error map's g edges (error_map_test) and any caller of the helper:
  const std::vector<double> wide = spaced_range(-1.5e308, 1.5e308, 3, false);
  ASSERT_EQ(wide.size(), 3u);
  EXPECT_EQ(wide[0], -1.5e308);
  EXPECT_EQ(wide[1], 0.0);
  EXPECT_EQ(wide[2], 1.5e308);
#if VISCOR_HAS_MPFR
  // At 50 digits the interior of a log range is 10^k to 48 digits.
  d.velocity_from = "1e-3", d.velocity_to = "1e3", d.velocity_count = 7, d.velocity_log = true;
  const std::vector<mpfr_50> w = resolve_scene<mpfr_50>(d).velocities;
  ASSERT_EQ(w.size(), 7u);
  for (int i = 0; i < 7; ++i)
    EXPECT_PRED_FORMAT3(relative_close<mpfr_50>, w[i], mpfr_50(pow(mpfr_50(10), i - 3)), mpfr_50(1e-48)) << i;
#endif
}

TEST(scene, rows_in_physical_units_match_eq_2) {
  // The linear law has closed forms: check e and the physical contact time T * T_f.
  scene_description d;
  d.law = law_by_name("linear");
  d.mass = "0.01", d.stiffness = "1e4", d.gamma0 = "1e-3", d.gravity = "9.8", d.force = "0.05";
  d.velocity_from = "0.1", d.velocity_to = "1", d.velocity_count = 4, d.velocity_log = true;
  d.tolerance = "1e-9";
  d.contact_time = true;
  const resolved_scene<double> s = resolve_scene<double>(d);
  ASSERT_EQ(s.velocities.size(), 4u);
  EXPECT_PRED_FORMAT3(relative_close<double>, s.velocities[1], std::pow(10.0, -2.0 / 3), 1e-15);
  run_scene(s, nullptr, [&](const scene_row<double>& row) {
    // eq. (2) for alpha = beta = 1: T = sqrt(m/k), gamma = gamma0 sqrt(k/m), g = (gravity + F/m) T / v0.
    const double T = std::sqrt(0.01 / 1e4);
    EXPECT_PRED_FORMAT3(relative_close<double>, row.gamma, 1e-3 * std::sqrt(1e4 / 0.01), 1e-14);
    EXPECT_PRED_FORMAT3(relative_close<double>, row.g, (9.8 + 0.05 / 0.01) * T / row.v0, 1e-14);
    const auto exact = exact_cor(law_by_name("linear"), row.gamma, row.g);
    EXPECT_LE(std::abs(row.result.e - exact->e), row.result.bound);
    ASSERT_TRUE(row.contact_time.has_value());
    EXPECT_PRED_FORMAT3(relative_close<double>, *row.contact_time, *exact->contact_time * T, 1e-9);
  });
}

}  // namespace
}  // namespace viscor
