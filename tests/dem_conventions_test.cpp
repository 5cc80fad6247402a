// include/viscor/dem: the codes' conventions against forces printed by the real
// programs (dem_static_force_data.hpp), the mapping against viscor's force law,
// the deck round trip e(deck(target)) = target, the built-in conversions, and
// errors naming the bad value.
#include <viscor/dem/dem_calibration.hpp>
#include <viscor/dem/deck_snippet.hpp>
#include <viscor/exact/exact_linear_clamped.hpp>
#include <viscor/exact/exact_tsuji.hpp>

#include "dem_static_force_data.hpp"
#include "scaling_reference.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace viscor;
using namespace viscor::dem;

// The overlaps of the static runs, as the programs compute them from the positions.
constexpr double pair_overlap() { return 2 * 1e-3 - 0.001998; }
constexpr double wall_overlap() { return 1e-3 - 0.000998; }

TEST(DemConventions, ForcesMatchTheRealPrograms) {
  const bead_material<double> bead{1e8, 0.3, 1e-3, 2500};
  for (const auto& c : test::static_forces) {
    SCOPED_TRACE(std::string(c.code) + " " + c.damping + " " + c.contact);
    const dem_model& model = find_dem_model(c.code, c.damping);
    const contact_kind kind = parse_contact_kind(c.contact);
    const bool wall = kind == contact_kind::wall;
    const double f = code_normal_force(model, bead, kind, 1e8, c.deck_damping, wall ? wall_overlap() : pair_overlap(),
                                       wall ? 0.05 : 0.1, c.wall_modulus, 0.3);
    // The programs compute in double with another operation order: a few ulps.
    EXPECT_NEAR(f, c.force, 2e-15 * c.force);
  }
}

// YADE 2023.02a: Hertz-Mindlin through dem_model "yade mindlin" (deck E = 1e8 given
// directly: the code's own E*, here E/(sqrt(2)(1 - nu^2)) on a wall referred to R* = R),
// Thornton's en -> betan, the clamp, and the visco-elastic law F = max(0, kn d + cn d')
// with the pair taking half of the per-material kn and cn.
TEST(DemConventions, ForcesMatchYade) {
  const bead_material<double> bead{1e8, 0.3, 1e-3, 2500};
  const dem_model& model = find_dem_model("yade", "mindlin");
  int clamped = 0;
  for (const auto& c : test::yade_static_forces) {
    SCOPED_TRACE(std::string(c.law) + " " + c.contact + " rate " + std::to_string(c.overlap_rate));
    const contact_kind kind = parse_contact_kind(c.contact);
    const double delta = kind == contact_kind::wall ? wall_overlap() : pair_overlap();
    double f = 0;
    if (std::string(c.law) == "mindlin") {
      const double betan = c.deck_is_en ? yade_thornton_betan(c.deck_damping) : c.deck_damping;
      f = code_normal_force(model, bead, kind, 1e8, betan, delta, c.overlap_rate, 1e30, 0.3);
    } else if (std::string(c.law) == "viscel") {  // a wall of the bead's material: half of each
      f = yade_viscel_normal_force(kind, 1e4, c.deck_damping, 1e4, c.deck_damping, delta, c.overlap_rate);
    } else if (std::string(c.law) == "viscel_rigid") {
      f = yade_viscel_normal_force(kind, 1e4, c.deck_damping, 1e30, 1e30, delta, c.overlap_rate);
    } else {  // tc, en on both bodies: YADE's contact kn, cn with the reduced mass m/2 (also on the wall)
      const auto kc = yade_viscel_from_tc_en(1e-5, c.deck_damping, bead.mass() / 2);
      f = kc.kn * delta + kc.cn * c.overlap_rate;
    }
    clamped += c.force == 0;
    EXPECT_NEAR(f, c.force, 4e-15 * c.force);
  }
  EXPECT_EQ(clamped, 3);  // the clamp is exercised for both laws
  // Thornton's fit as YADE computed it (Ip2_FrictMat_FrictMat_MindlinPhys(en=0.5).betan, printed by yade).
  EXPECT_NEAR(yade_thornton_betan(0.5), 0.2330248576834424, 2e-16);
  EXPECT_NEAR(yade_thornton_betan(0.8), 0.06790289004602458, 2e-16);
}

// The damping must matter in the static cases, or they would not test it.
TEST(DemConventions, StaticCasesExerciseTheDamping) {
  const bead_material<double> bead{1e8, 0.3, 1e-3, 2500};
  for (const auto& c : test::static_forces) {
    SCOPED_TRACE(std::string(c.code) + " " + c.damping + " " + c.contact);
    const dem_model& model = find_dem_model(c.code, c.damping);
    const contact_kind kind = parse_contact_kind(c.contact);
    const bool wall = kind == contact_kind::wall;
    const double elastic = code_normal_force(model, bead, kind, 1e8, c.deck_damping, wall ? wall_overlap() : pair_overlap(),
                                             0.0, c.wall_modulus, 0.3);
    EXPECT_GT(c.force - elastic, 0.2 * elastic);
  }
}

// The deck of dem_deck_for, put through the code's force law, is viscor's force
// F = k delta^(3/2) + gamma0 k d/dt(delta^beta) for the physical material.
TEST(DemConventions, DeckGivesThePhysicalForce) {
  const bead_material<double> bead{7e10, 0.22, 2e-3, 2500};
  for (const auto& model : dem_models)
    for (contact_kind kind : {contact_kind::wall, contact_kind::pair}) {
      SCOPED_TRACE(std::string(model.code_name) + " " + std::string(model.damping_name) + " " +
                   std::string(to_string(kind)));
      dem_impact<double> impact;
      impact.bead = bead, impact.kind = kind, impact.v0 = 0.3, impact.gravity = 9.81;
      impact.stiffness = 1e5;  // N/m, YADE visco-elastic only
      const dem_deck<double> d = dem_deck_for(model, impact, 0.6);
      const double wall_modulus = d.wall_youngs_modulus.value_or(0.0);
      const double alpha = law_of(model).alpha.value<double>(), beta = law_of(model).beta.value<double>();
      for (double delta : {1e-7, 3e-6})
        for (double rate : {-0.2, 0.05}) {
          const double f = takes_linear_stiffness(model)
                               ? yade_viscel_normal_force(kind, *d.stiffness, d.damping, 1e30, 1e30, delta, rate)
                               : code_normal_force(model, bead, kind, d.youngs_modulus, d.damping, delta, rate,
                                                   wall_modulus, bead.poisson_ratio);
          const double k = d.contact.stiffness;
          double physical = k * std::pow(delta, alpha) + d.gamma0 * k * beta * std::pow(delta, beta - 1) * rate;
          if (model.clamped) physical = std::max(physical, 0.0);
          EXPECT_NEAR(f, physical, 1e-12 * std::abs(physical));
        }
    }
}

// The deck's gamma0 and scaled load against eq. (2) evaluated outside the library
// (tests/data/scaling_reference.csv: k and m from the material, gamma at gamma0 = 1),
// so that a wrong scaling cannot cancel between calibrate and e_for_deck.
TEST(DemConventions, DeckScalingMatchesIndependentReference) {
  struct case_ {
    const char *code, *damping, *law;
  };
  for (const case_& c : {case_{"lammps", "velocity", "hertz_linear_damping"}, case_{"lammps", "tsuji", "tsuji"},
                         case_{"lammps", "viscoelastic", "kuwabara_kono"}, case_{"liggghts", "hertz", "tsuji"}}) {
    SCOPED_TRACE(std::string(c.code) + " " + c.damping);
    const test::scaling_reference_row ref = test::scaling_reference("dem_steel_wall_unit_damping", c.law);
    dem_impact<double> impact;
    impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.kind = contact_kind::wall, impact.v0 = 0.01, impact.gravity = 9.81;
    const dem_deck<double> d = dem_deck_for(find_dem_model(c.code, c.damping), impact, 0.7);
    EXPECT_NEAR(d.contact.stiffness, std::stod(ref.k), 1e-14 * std::stod(ref.k));
    EXPECT_NEAR(d.calibration.scaled.g, std::stod(ref.g), 1e-14 * std::stod(ref.g));
    EXPECT_NEAR(d.gamma0 * std::stod(ref.gamma), d.calibration.scaled.gamma, 1e-14 * d.calibration.scaled.gamma);
  }
}

template <class Real>
class DemRoundTrip : public ::testing::Test {};
using round_trip_types = ::testing::Types<double, long double>;
TYPED_TEST_SUITE(DemRoundTrip, round_trip_types);

// e(deck(target)) = target to 1e-10 at every model, contact and load.
TYPED_TEST(DemRoundTrip, DeckReproducesTarget) {
  using Real = TypeParam;
  bead_material<Real> bead{Real(3e9), Real(35) / 100, Real(1) / 1000, Real(1200)};
  for (const auto& model : dem_models)
    for (contact_kind kind : {contact_kind::wall, contact_kind::pair})
      for (const char* gravity : {"0", "9.81"}) {
        SCOPED_TRACE(std::string(model.code_name) + " " + std::string(model.damping_name) + " " +
                     std::string(to_string(kind)) + " gravity " + gravity);
        dem_impact<Real> impact;
        impact.bead = bead, impact.kind = kind, impact.v0 = Real(1) / 100;
        impact.gravity = parse_real<Real>(gravity, "gravity");
        impact.force = kind == contact_kind::pair ? Real(1) / 10000 : Real(0);
        impact.stiffness = Real(10000);  // N/m, YADE visco-elastic only
        const Real target = Real(7) / 10;
        const dem_deck<Real> d = dem_deck_for(model, impact, target);
        // the deck as printed (round-trip decimal), read back as the code would
        const Real deck = parse_real<Real>(to_decimal_string(d.damping), "deck");
        const Real e = e_for_deck(model, impact, deck).e;
        EXPECT_LE(static_cast<double>(abs(e - target)), 1e-10) << to_decimal_string(e);
      }
}

// LIGGGHTS' conversion is exact without load: its 2 sqrt(5/6) factor makes the
// damping sqrt(5) b sqrt(m* k) delta^(1/4), the Tsuji law whose e is the closed
// form of exact_tsuji (Antypov-Elliott map to a linear oscillator).
TEST(DemBuiltin, LiggghtsExactWithoutLoad) {
  const dem_model& model = find_dem_model("liggghts", "hertz");
  dem_impact<double> impact;
  impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.v0 = 1;
  for (double e : {0.05, 0.3, 0.8, 0.99}) {
    impact.gravity = 0;
    const dem_deck<double> d = dem_deck_for(model, impact, e);
    EXPECT_NEAR(*d.builtin_e, e, 1e-10);
    // independent: the exact Tsuji CoR at the scaled damping of deck e
    const double gamma = d.calibration.scaled.gamma;
    EXPECT_NEAR(exact_tsuji(gamma).e, e, 1e-12);
    // under gravity at a slow impact the conversion misses (the load lowers e)
    impact.gravity = 9.81, impact.v0 = 0.01;
    const dem_deck<double> loaded = dem_deck_for(model, impact, e);
    EXPECT_LT(*loaded.builtin_e, e);
    impact.v0 = 1;
  }
}

// LAMMPS tsuji: the polynomial of the code (values at 0 and 1 by hand from its
// coefficients), decreasing, and its inverse.
TEST(DemBuiltin, LammpsTsujiPolynomial) {
  EXPECT_NEAR(lammps_tsuji_damping(0.0), 1.2728, 1e-15);
  EXPECT_NEAR(lammps_tsuji_damping(1.0), 1.2728 - 4.2783 + 11.087 - 22.348 + 27.467 - 18.022 + 4.8218, 1e-13);
  for (int i = 0; i < 1000; ++i) EXPECT_GT(lammps_tsuji_damping(i / 1000.0), lammps_tsuji_damping((i + 1) / 1000.0));
  for (double e : {0.0, 0.1, 0.5, 0.8, 0.99, 1.0})
    EXPECT_NEAR(lammps_tsuji_deck_e(lammps_tsuji_damping(e)), e, 1e-13);
  EXPECT_THROW(lammps_tsuji_deck_e(1.5), unreachable_target);
  EXPECT_THROW(lammps_tsuji_deck_e(1e-5), unreachable_target);
}

// Its miss without load: exact damping number sqrt(5) b(e) (the LIGGGHTS form,
// exact by exact_tsuji) versus the polynomial; e = 0.8 comes back as 0.853.
TEST(DemBuiltin, LammpsTsujiMissesWithoutLoad) {
  const dem_model& model = find_dem_model("lammps", "tsuji");
  dem_impact<double> impact;
  impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.v0 = 1, impact.gravity = 0;
  const dem_deck<double> d = dem_deck_for(model, impact, 0.8);
  EXPECT_NEAR(d.damping_number, std::sqrt(5.0) * liggghts_damping_ratio(0.8), 1e-10);
  const double gamma_builtin = d.calibration.scaled.gamma * lammps_tsuji_damping(0.8) / d.damping_number;
  EXPECT_NEAR(*d.builtin_e, exact_tsuji(gamma_builtin).e, 1e-12);
  EXPECT_NEAR(*d.builtin_e, 0.8534, 1e-4);
}

// YADE's visco-elastic law is the clamped linear impact, whose e has a closed form
// (exact/exact_linear_clamped.hpp). Without load: viscor's deck gives the target, and
// YADE's own ViscElMat(tc, en) takes its damping from the reduced mass m/2, so the
// scaled damping is 2 b(en) / sqrt(2) on a wall (the bead's mass m moves) and 2 b(en)
// for a pair (where m/2 is right; only the clamp then moves e above en).
TEST(DemBuiltin, YadeViscoelasticWithoutLoad) {
  const dem_model& model = find_dem_model("yade", "viscoelastic");
  dem_impact<double> impact;
  impact.bead = {3e9, 0.35, 1e-3, 1200}, impact.v0 = 1, impact.stiffness = 1e4;
  for (contact_kind kind : {contact_kind::wall, contact_kind::pair})
    for (double e : {0.1, 0.5, 0.9}) {
      SCOPED_TRACE(std::string(to_string(kind)) + " e = " + std::to_string(e));
      impact.kind = kind;
      const dem_deck<double> d = dem_deck_for(model, impact, e);
      EXPECT_NEAR(exact_linear_clamped(d.calibration.scaled.gamma, 0.0).e, e, 1e-12);
      const double b = liggghts_damping_ratio(e);
      const double gamma_builtin = kind == contact_kind::wall ? std::sqrt(2.0) * b : 2 * b;
      EXPECT_NEAR(*d.builtin_e, exact_linear_clamped(gamma_builtin, 0.0).e, 1e-12);
      EXPECT_GT(*d.builtin_e, e);  // less damping (wall) and the clamp: YADE's en gives more than en
    }
}

TEST(DemErrors, NamesTheValue) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const invalid_parameter& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { find_dem_model("foo", "tsuji"); }).find("'foo'"), std::string::npos);
  EXPECT_NE(message([] { find_dem_model("lammps", "bar"); }).find("'bar'"), std::string::npos);
  EXPECT_NE(message([] { find_dem_model("lammps", "coeff_restitution"); }).find("not in the installed"),
            std::string::npos);
  EXPECT_NE(message([] { find_dem_model("yade", "tsuji"); }).find("'tsuji'"), std::string::npos);
  EXPECT_NE(message([] { parse_contact_kind("floor"); }).find("'floor'"), std::string::npos);
  dem_impact<double> impact;
  impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.v0 = 1;
  const dem_model& model = find_dem_model("lammps", "velocity");
  EXPECT_NE(message([&] { dem_deck_for(model, impact, 1.0); }).find("target_e"), std::string::npos);
  EXPECT_NE(message([&] { dem_deck_for(model, impact, -0.1); }).find("target_e"), std::string::npos);
  impact.bead.poisson_ratio = 0.7;
  EXPECT_NE(message([&] { dem_deck_for(model, impact, 0.5); }).find("poisson_ratio"), std::string::npos);
  // LIGGGHTS: a damping ratio >= 1 has no deck e
  EXPECT_THROW(liggghts_deck_e(1.0), unreachable_target);
}

TEST(DemSnippet, CarriesTheDeckValues) {
  const deck_strings s{"3.0769230769230768e+11", "2.9999999999999999e-01", "7.3086002562598373e-01", std::nullopt};
  const std::string lammps = deck_snippet(find_dem_model("lammps", "tsuji"), contact_kind::wall, s);
  EXPECT_NE(lammps.find("fix wall all wall/gran granular hertz/material 3.0769230769230768e+11 7.3086002562598373e-01 "
                        "2.9999999999999999e-01 damping tsuji"),
            std::string::npos)
      << lammps;
  deck_strings l = s;
  l.wall_youngs_modulus = "1e30";
  const std::string liggghts = deck_snippet(find_dem_model("liggghts", "hertz"), contact_kind::wall, l);
  EXPECT_NE(liggghts.find("youngsModulus peratomtype 3.0769230769230768e+11 1e30"), std::string::npos) << liggghts;
  EXPECT_NE(liggghts.find("coefficientRestitution peratomtypepair 2 7.3086002562598373e-01"), std::string::npos);
}

}  // namespace
