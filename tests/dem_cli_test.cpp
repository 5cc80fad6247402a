// viscor dem (src/cli/cmd_dem.cpp): the deck fields as decimal strings that give
// the target e back through the library's reverse map, the reverse table, the
// snippet, and bad input: exit 2, the offending value named, no output file.
#include <viscor/dem/dem_calibration.hpp>

#include "scaling_reference.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

const std::string steel = " --youngs-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800";

TEST(CliDem, DeckFieldsReproduceTheTarget) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  for (const char* model : {"lammps --damping velocity", "lammps --damping viscoelastic", "lammps --damping tsuji",
                            "liggghts --damping hertz"}) {
    SCOPED_TRACE(model);
    const auto r = run_cli(std::string("dem ") + model + steel + " --target-e 0.7 --v0 0.01 --gravity 9.81 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (const char* field : {"youngs_modulus", "damping", "poisson_ratio"}) ASSERT_TRUE(j["deck"][field].is_string());
    const auto& m = viscor::dem::find_dem_model(j["code"], j["damping_model"]);
    viscor::dem::dem_impact<double> impact;
    impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.v0 = 0.01, impact.gravity = 9.81;
    const double deck = std::stod(j["deck"]["damping"].get<std::string>());
    EXPECT_NEAR(viscor::dem::e_for_deck(m, impact, deck).e, 0.7, 1e-10);
    // k, g, T and gamma0 against eq. (2) evaluated outside the library (gamma at gamma0 = 1).
    const auto ref = viscor::test::scaling_reference("dem_steel_wall_unit_damping", j["law"]["name"]);
    auto number = [&](const char* field) { return std::stod(j[field].get<std::string>()); };
    EXPECT_NEAR(number("k"), std::stod(ref.k), 1e-15 * std::stod(ref.k));
    EXPECT_NEAR(number("g"), std::stod(ref.g), 1e-14 * std::stod(ref.g));
    EXPECT_NEAR(number("time_scale_s"), std::stod(ref.time_scale), 1e-14 * std::stod(ref.time_scale));
    EXPECT_NEAR(number("gamma0") * std::stod(ref.gamma), number("gamma"), 1e-14 * number("gamma"));
    // the wall modulus as the code needs it
    const double E = std::stod(j["deck"]["youngs_modulus"].get<std::string>());
    EXPECT_NEAR(E, j["code"] == "lammps" ? 2 * 2e11 / 1.3 : 2e11, 1e-15 * E);
    EXPECT_NE(j["snippet"].get<std::string>().find(j["deck"]["damping"].get<std::string>()), std::string::npos);
    if (m.deck_kind == viscor::dem::deck_damping_kind::coefficient_of_restitution) {
      ASSERT_TRUE(j.contains("builtin_e"));
      const double builtin = std::stod(j["builtin_e"].get<std::string>());
      EXPECT_NEAR(std::stod(j["builtin_error_percent_of_one_minus_e"].get<std::string>()),
                  100 * (builtin - 0.7) / 0.3, 1e-9);
    } else {
      EXPECT_FALSE(j.contains("builtin_e"));
    }
  }
}

// YADE: betan as a decimal string that gives the target through the clamped law,
// the deck modulus sqrt(2) E (R* = R/2 on YADE's wall), builtin_e from `en`
// (Thornton's fit), the snippet with the values filled in, and the reverse table.
TEST(CliDem, YadeMindlin) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("dem yade --damping mindlin" + steel + " --target-e 0.7 --v0 0.01 --gravity 9.81 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["clamped"].get<bool>());
  const auto& m = viscor::dem::find_dem_model("yade", "mindlin");
  viscor::dem::dem_impact<double> impact;
  impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.v0 = 0.01, impact.gravity = 9.81;
  const double betan = std::stod(j["deck"]["damping"].get<std::string>());
  EXPECT_NEAR(viscor::dem::e_for_deck(m, impact, betan).e, 0.7, 1e-10);
  EXPECT_NEAR(std::stod(j["deck"]["youngs_modulus"].get<std::string>()), std::sqrt(2.0) * 2e11, 1e-15 * 3e11);
  EXPECT_EQ(j["deck"]["wall_youngs_modulus"], "1e30");
  const double builtin = std::stod(j["builtin_e"].get<std::string>());
  EXPECT_NEAR(builtin, viscor::dem::e_for_deck(m, impact, viscor::dem::yade_thornton_betan(0.7)).e, 1e-12);
  EXPECT_NEAR(std::stod(j["builtin_error_percent_of_one_minus_e"].get<std::string>()), 100 * (builtin - 0.7) / 0.3, 1e-9);
  const std::string snippet = j["snippet"];
  for (const std::string& text : {std::string("betan=") + j["deck"]["damping"].get<std::string>(),
                                  std::string("density=7800"), std::string("gravity=(0, 0, -9.81)"),
                                  std::string("NewtonIntegrator(damping=0")})
    EXPECT_NE(snippet.find(text), std::string::npos) << text << " in\n" << snippet;
  const auto rev = run_cli("dem yade --damping mindlin" + steel + " --deck-damping " + j["deck"]["damping"].get<std::string>() +
                           " --gravity 9.81 --speeds 0.01 --json");
  ASSERT_EQ(rev.status, 0) << rev.err;
  const auto table = nlohmann::json::parse(rev.out)["table"];
  ASSERT_EQ(table.size(), 2u);
  EXPECT_NEAR(std::stod(table[1]["e"].get<std::string>()), 0.7, 1e-10);  // under gravity, as calibrated
  EXPECT_GT(std::stod(table[0]["e"].get<std::string>()), 0.7);            // without load the bead rebounds more
}

// YADE's own conversion in the reverse table: --deck-en E is betan = Thornton's fit of E.
TEST(CliDem, YadeDeckEnIsThorntonsBetan) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("dem yade --damping mindlin" + steel + " --deck-en 0.5 --gravity 9.81 --speeds 0.01 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["deck_en"], "0.5");
  EXPECT_NEAR(std::stod(j["deck_damping"].get<std::string>()), 0.2330248576834424, 2e-16);  // printed by yade
  viscor::dem::dem_impact<double> impact;
  impact.bead = {2e11, 0.3, 1e-3, 7800}, impact.v0 = 0.01, impact.gravity = 9.81;
  const auto& m = viscor::dem::find_dem_model("yade", "mindlin");
  EXPECT_NEAR(std::stod(j["table"][1]["e"].get<std::string>()), *viscor::dem::dem_deck_for(m, impact, 0.5).builtin_e,
              1e-12);
}

// YADE visco-elastic: a linear spring of stiffness --k; the deck is the bead material's
// kn and cn (the wall's 1e30: rigid), cn reproduces the target through the clamped linear
// law, builtin_e is YADE's own ViscElMat(tc, en), and the reverse table takes cn.
TEST(CliDem, YadeViscoelastic) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string bead = " --k 1e4 --radius 1e-3 --density 1200";
  const auto r = run_cli("dem yade --damping viscoelastic" + bead + " --target-e 0.5 --v0 0.01 --gravity 9.81 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["clamped"].get<bool>());
  EXPECT_EQ(j["law"]["name"], "linear");
  EXPECT_EQ(std::stod(j["deck"]["kn"].get<std::string>()), 1e4) << j["deck"];
  EXPECT_EQ(j["deck"]["wall_kn"], "1e30");
  EXPECT_EQ(j["deck"]["wall_cn"], "1e30");
  EXPECT_EQ(j["deck"]["cn"], j["deck"]["damping"]);
  const auto& m = viscor::dem::find_dem_model("yade", "viscoelastic");
  viscor::dem::dem_impact<double> impact;
  impact.bead.radius = 1e-3, impact.bead.density = 1200, impact.v0 = 0.01, impact.gravity = 9.81;
  impact.stiffness = 1e4;
  const double cn = std::stod(j["deck"]["cn"].get<std::string>());
  EXPECT_NEAR(viscor::dem::e_for_deck(m, impact, cn).e, 0.5, 1e-10);
  EXPECT_TRUE(j.contains("builtin_e") && j.contains("builtin_tc_s"));
  const std::string snippet = j["snippet"];
  for (const std::string& text : {"ViscElMat(kn=" + j["deck"]["kn"].get<std::string>() + ", cn=" + j["deck"]["cn"].get<std::string>(),
                                  std::string("ViscElMat(kn=1e30, cn=1e30"), std::string("density=1200"),
                                  std::string("Law2_ScGeom_ViscElPhys_Basic()")})
    EXPECT_NE(snippet.find(text), std::string::npos) << text << " in\n" << snippet;
  const auto rev = run_cli("dem yade --damping viscoelastic" + bead + " --deck-damping " + j["deck"]["cn"].get<std::string>() +
                           " --gravity 9.81 --speeds 0.01 --json");
  ASSERT_EQ(rev.status, 0) << rev.err;
  const auto table = nlohmann::json::parse(rev.out)["table"];
  ASSERT_EQ(table.size(), 2u);
  EXPECT_NEAR(std::stod(table[1]["e"].get<std::string>()), 0.5, 1e-10);
}

TEST(CliDem, ReverseTableListsSpeedsAndLoads) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("dem lammps --damping tsuji" + steel + " --deck-damping 0.8 --gravity 9.81 --speeds 0.01,1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["table"].size(), 4u);  // 2 speeds x (no load, gravity)
  viscor::dem::dem_impact<double> impact;
  impact.bead = {2e11, 0.3, 1e-3, 7800};
  for (const auto& row : j["table"]) {
    impact.v0 = std::stod(row["v0"].get<std::string>());
    impact.gravity = std::stod(row["gravity"].get<std::string>());
    const double e = viscor::dem::e_for_deck(viscor::dem::find_dem_model("lammps", "tsuji"), impact, 0.8).e;
    EXPECT_NEAR(std::stod(row["e"].get<std::string>()), e, 1e-14);
  }
}

TEST(CliDem, BadInputExitsTwoNamingTheValue) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string tail = steel + " --v0 1 --gravity 9.81";
  struct bad { std::string args, named; };
  for (const bad& b : {bad{"dem foo --damping tsuji --target-e 0.5" + tail, "'foo'"},
                       bad{"dem lammps --damping wiggle --target-e 0.5" + tail, "'wiggle'"},
                       bad{"dem lammps --damping coeff_restitution --target-e 0.5" + tail, "coeff_restitution"},
                       bad{"dem lammps --damping tsuji --target-e 1.5" + tail, "target_e"},
                       bad{"dem lammps --damping tsuji --target-e 0" + tail, "target_e"},
                       bad{"dem lammps --damping tsuji --target-e 0.5 --contact floor" + tail, "'floor'"},
                       bad{"dem lammps --damping tsuji --target-e 0.5" + steel + " --v0 1", "--gravity"},
                       bad{"dem liggghts --damping hertz --deck-damping 1.5" + tail, "1.5"},
                       bad{"dem yade --damping viscoelastic --target-e 0.5 --radius 1e-3 --density 7800 --v0 1 --gravity 9.81",
                           "--k"},
                       bad{"dem yade --damping viscoelastic --k 1e4 --target-e 0.5" + tail, "--youngs-modulus"},
                       bad{"dem yade --damping viscoelastic --k -5 --target-e 0.5 --radius 1e-3 --density 7800 --v0 1 "
                           "--gravity 9.81", "parameter k"},
                       bad{"dem lammps --damping tsuji --k 1e4 --target-e 0.5" + tail, "--k"},
                       bad{"dem lammps --damping tsuji --deck-en 0.5" + tail, "--deck-en"},
                       bad{"dem yade --damping mindlin --deck-en 1.5" + tail, "deck_en"},
                       bad{"dem yade --damping mindlin --target-e 1" + tail, "target_e"},
                       bad{"dem yade --damping mindlin --deck-damping -0.1" + tail, "deck damping"},
                       // needs less damping than the tsuji polynomial gives at e = 1 (0.0003)
                       bad{"dem lammps --damping tsuji --target-e 0.9999" + steel + " --v0 1 --gravity 0", "target_e = 9.999"},
                       // a pulling force: the bead cannot lose enough energy
                       bad{"dem lammps --damping velocity --target-e 0.01" + steel + " --v0 0.01 --gravity 9.81 --force -1", "target_e"},
                       // a time step calibrates a forward deck by the solve
                       bad{"dem lammps --damping tsuji --target-e 0.8 --timestep T/0" + steel + " --v0 0.5 --gravity 9.81",
                           "--timestep"},
                       bad{"dem lammps --damping tsuji --deck-damping 0.5 --timestep T/20" + steel + " --v0 0.5 --gravity 9.81",
                           "--timestep"},
                       bad{"dem yade --damping viscoelastic --k 1e6 --radius 1e-3 --density 2500 --target-e 0.8 "
                           "--timestep T/20 --v0 0.5 --gravity 9.81",
                           "--timestep"},
                       bad{"dem lammps --damping tsuji --target-e 0.8 --method guess" + steel + " --v0 0.5 --gravity 9.81",
                           "'guess'"}}) {
    SCOPED_TRACE(b.args);
    const std::string out_file = ::testing::TempDir() + "viscor_dem_bad.json";
    std::filesystem::remove(out_file);
    const auto r = run_cli(b.args + " -o " + out_file);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(b.named), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out_file));
  }
}

}  // namespace

namespace {
// The clamped (YADE) solve at run-time MPFR precision: its GBS column count came from
// numeric_limits<Real>::digits10, INT_MAX for run-time MPFR, and the overflowed sum
// exhausted the step budget ("step budget of 200000 exhausted" at --digits 40).
TEST(CliDem, YadeDeckAtFortyDigitsAgreesWithDouble) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string args = "dem yade --damping mindlin" + steel + " --target-e 0.5 --v0 0.01 --gravity 9.81 --json";
  const auto r15 = run_cli(args);
  const auto r40 = run_cli(args + " --digits 40");
  ASSERT_EQ(r15.status, 0) << r15.err;
  ASSERT_EQ(r40.status, 0) << r40.err;
  const double d15 = std::stod(nlohmann::json::parse(r15.out)["deck"]["damping"].get<std::string>());
  const double d40 = std::stod(nlohmann::json::parse(r40.out)["deck"]["damping"].get<std::string>());
  EXPECT_NEAR(d40, d15, 1e-12 * d15);  // both calibrate e to 1e-13; the double run carries ~15 digits
}
}  // namespace

namespace {
// The readable output states the contact time and the time step (dt = T/400; the
// contact of these laws lasts about 3.2 T to 3.6 T: docs/dem.md, "Validation").
TEST(CliDem, ReadableOutputStatesContactTimeAndTimeStep) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string args = "dem lammps --damping tsuji" + steel + " --target-e 0.8 --v0 0.5 --gravity 9.81";
  const auto text = run_cli(args);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("the contact lasts"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("dt = T/400"), std::string::npos) << text.out;
  const auto j = nlohmann::json::parse(run_cli(args + " --json").out);
  const double T = std::stod(j["time_scale_s"].get<std::string>());
  EXPECT_NEAR(std::stod(j["time_step_s"].get<std::string>()), T / 400, 1e-12 * T);
  const double contact = std::stod(j["contact_time_s"].get<std::string>());
  EXPECT_GT(contact, 3.0 * T);
  EXPECT_LT(contact, 3.8 * T);
}

// The pasted LIGGGHTS wall snippet declares the friction its tangential model needs
// and keeps the bead-wall entries apart from the bead-bead one, which for this
// conversion (exact without load, and a pair feels no gravity) is the target itself.
TEST(CliDem, LiggghtsSnippetDeclaresFrictionAndSeparatesBeadBead) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("dem liggghts --damping hertz" + steel + " --target-e 0.5 --v0 0.01 --gravity 9.81 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::string snippet = j["snippet"], wall = j["deck"]["damping"], bead_bead = j["deck"]["bead_bead_damping"];
  EXPECT_NE(snippet.find("coefficientFriction peratomtypepair 2"), std::string::npos) << snippet;
  EXPECT_NEAR(std::stod(bead_bead), 0.5, 1e-12);
  EXPECT_GT(std::abs(std::stod(wall) - 0.5), 1e-4);  // under gravity at 0.01 m/s the wall entry differs
  EXPECT_NE(snippet.find("coefficientRestitution peratomtypepair 2 " + bead_bead + " " + wall + " " + wall + " " + wall),
            std::string::npos) << snippet;
}

// --drop-deck: refuses a file viscor did not write (exit 2, the file untouched),
// replaces its own, and needs a wall and a calibration.
TEST(CliDem, DropDeckNeverReplacesAForeignFile) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string deck = ::testing::TempDir() + "viscor_dem_drop_deck_" + std::to_string(::getpid()) + ".in";
  const std::string args = "dem lammps --damping tsuji" + steel + " --v0 0.5 --gravity 9.81 --drop-deck " + deck;
  { std::ofstream(deck) << "my own deck\n"; }
  const auto refused = run_cli(args + " --target-e 0.8");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("--drop-deck " + deck), std::string::npos) << refused.err;
  std::ifstream kept(deck);
  std::string first;
  std::getline(kept, first);
  EXPECT_EQ(first, "my own deck");
  std::filesystem::remove(deck);
  ASSERT_EQ(run_cli(args + " --target-e 0.8").status, 0);
  const auto again = run_cli(args + " --target-e 0.7");
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("wrote " + deck), std::string::npos) << again.out;
  const std::string yade_not_python = "dem yade --damping mindlin" + steel + " --v0 0.5 --gravity 9.81 --target-e 0.8 "
                                      "--drop-deck " + deck;  // yade -x skips files not ending in .py
  for (const std::string& bad : {args + " --target-e 0.8 --contact pair", args + " --deck-damping 0.8", yade_not_python}) {
    SCOPED_TRACE(bad);
    const auto r = run_cli(bad);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--drop-deck"), std::string::npos) << r.err;
  }
  std::filesystem::remove(deck);
}
}  // namespace
