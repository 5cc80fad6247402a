// The drop decks of `viscor dem ... --drop-deck FILE` run as written in the real
// programs (lmp, liggghts, yade) and print a rebound e within 1e-4 of the target;
// the LIGGGHTS paste snippet runs inside a minimal deck this test writes, and the
// LAMMPS snippet's bead-bead entries reproduce the target for two beads. The bead
// is the new user's: a 2 mm glass bead, e = 0.8 measured at 0.5 m/s under gravity.
// A program missing from PATH is skipped with a message (tools/install-deps.sh
// installs them).
#include "dem_drop_utils.hpp"
#include "required_dependencies.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

using viscor::test::scratch_dir;

using namespace viscor::test;

const std::string glass =
    " --youngs-modulus 7e10 --poisson-ratio 0.22 --radius 1e-3 --density 2500 --target-e 0.8 --v0 0.5 --gravity 9.81";
constexpr double target_e = 0.8;

/// The agreement the issue asks of a generated deck (the measured misses at dt = T/400 for a
/// glass-like bead are about 1e-5: docs/dem.md, "Validation").
constexpr double deck_tolerance = 1e-4;

/// Runs `command` in `dir`, returning its exit status and output (stdout, then stderr, in `out`).
cli_run run_in(const std::filesystem::path& dir, const std::string& command) {
  cli_run r = run_cli("", "cd '" + dir.string() + "' && " + command);
  r.out += r.err;
  return r;
}

/// The e a deck printed ("rebound e = X"), or -1.
double printed_rebound_e(const std::string& output) {
  static const std::regex line(R"(rebound e = ([-+0-9.eE]+))");
  std::smatch m;
  return std::regex_search(output, m, line) ? std::stod(m[1]) : -1;
}

/// Writes the drop deck of `model_args` (followed by the bead's material and impact,
/// `bead`) with the CLI, runs it as written with `program` and checks the e it prints.
void expect_deck_rebounds_at_target(const std::string& program_name, const std::string& model_args,
                                    const std::string& run_flags, const std::string& bead = glass) {
  SCOPED_TRACE(model_args);
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program(program_name);
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name << " is not installed (tools/install-deps.sh installs it)");
  scratch_dir dir{"viscor_drop_deck"};
  ASSERT_FALSE(dir.path.empty());
  const std::string deck_name = program_name == "yade" ? "drop.py" : "drop.in";
  const std::string deck = (dir.path / deck_name).string();
  const auto written = run_cli("dem " + model_args + bead + " --drop-deck " + deck);
  ASSERT_EQ(written.status, 0) << written.err;
  EXPECT_NE(written.out.find("wrote " + deck), std::string::npos) << written.out;
  const auto ran = run_in(dir.path, "'" + *program + "' " + run_flags + " " + deck_name);
  ASSERT_EQ(ran.status, 0) << ran.out;
  const double e = printed_rebound_e(ran.out);
  EXPECT_NEAR(e, target_e, deck_tolerance) << ran.out.substr(ran.out.size() > 3000 ? ran.out.size() - 3000 : 0);
  std::printf("[deck] %s: rebound e = %.9f\n", model_args.c_str(), e);
}

TEST(DemDropDeck, LammpsTsujiRunsAsWritten) { expect_deck_rebounds_at_target("lmp", "lammps --damping tsuji", "-in"); }
TEST(DemDropDeck, LammpsVelocityRunsAsWritten) {
  expect_deck_rebounds_at_target("lmp", "lammps --damping velocity", "-in");
}
TEST(DemDropDeck, LiggghtsHertzRunsAsWritten) {
  expect_deck_rebounds_at_target("liggghts", "liggghts --damping hertz", "-in");
}
TEST(DemDropDeck, YadeMindlinRunsAsWritten) { expect_deck_rebounds_at_target("yade", "yade --damping mindlin", "-n -x"); }
// the linear spring takes the contact stiffness --k (here 1e6 N/m) instead of E and nu
TEST(DemDropDeck, YadeViscoelasticRunsAsWritten) {
  expect_deck_rebounds_at_target("yade", "yade --damping viscoelastic", "-n -x",
                                 " --k 1e6 --radius 1e-3 --density 2500 --target-e 0.8 --v0 0.5 --gravity 9.81");
}

// A glass bead on a steel plate (a wall of its own material): the decks run as written.
const std::string steel_plate = glass + " --wall-youngs-modulus 200e9 --wall-poisson-ratio 0.3";
TEST(DemDropDeck, LammpsTsujiOnSteelPlateRunsAsWritten) {
  expect_deck_rebounds_at_target("lmp", "lammps --damping tsuji", "-in", steel_plate);
}
TEST(DemDropDeck, LiggghtsHertzOnSteelPlateRunsAsWritten) {
  expect_deck_rebounds_at_target("liggghts", "liggghts --damping hertz", "-in", steel_plate);
}
TEST(DemDropDeck, YadeMindlinOnSteelPlateRunsAsWritten) {
  expect_deck_rebounds_at_target("yade", "yade --damping mindlin", "-n -x", steel_plate);
}

/// Replaces every occurrence of `from` in the file at `path` by `to`; how many.
std::size_t replace_in_file(const std::string& path, const std::string& from, const std::string& to) {
  std::string text;
  {
    std::ifstream in(path);
    std::stringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  std::size_t edits = 0;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to), ++edits;
  std::ofstream(path) << text;
  return edits;
}

/// A deck whose damping entry was edited by hand, for a before/after comparison: the
/// drop deck of `model_args` with every occurrence of its calibrated damping entry
/// replaced by `edited`, run as written, must still report its e, and that e must be the
/// one viscor predicts for the edited entry (`expected_field` of `viscor dem --json`:
/// builtin_e when the edit writes the target itself into the code's own e input).
void expect_edited_deck_reports(const std::string& program_name, const std::string& model_args,
                                const std::string& run_flags, const std::string& edited,
                                const std::string& expected_command, const std::string& expected_field) {
  SCOPED_TRACE(model_args + ", damping entry edited to " + edited);
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program(program_name);
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name << " is not installed (tools/install-deps.sh installs it)");
  scratch_dir dir{"viscor_drop_deck"};
  ASSERT_FALSE(dir.path.empty());
  const std::string deck_name = program_name == "yade" ? "drop.py" : "drop.in";
  const std::string deck = (dir.path / deck_name).string();
  const auto written = run_cli("dem " + model_args + glass + " --drop-deck " + deck + " --json");
  ASSERT_EQ(written.status, 0) << written.err;
  const std::string calibrated = nlohmann::json::parse(written.out)["deck"]["damping"];
  const std::size_t edits = replace_in_file(deck, calibrated, edited);
  ASSERT_GT(edits, 0u) << "the deck does not hold its damping entry " << calibrated;
  const auto predicted = run_cli(expected_command + glass.substr(0, glass.find(" --target-e")) +
                                 " --v0 0.5 --gravity 9.81 --json");
  ASSERT_EQ(predicted.status, 0) << predicted.err;
  const nlohmann::json p = nlohmann::json::parse(predicted.out);
  const double expected = expected_field == "builtin_e" ? std::stod(p["builtin_e"].get<std::string>())
                                                        : std::stod(p["table"][1]["e"].get<std::string>());
  const auto ran = run_in(dir.path, "'" + *program + "' " + run_flags + " " + deck_name);
  ASSERT_EQ(ran.status, 0) << ran.out;
  const double e = printed_rebound_e(ran.out);
  EXPECT_NEAR(e, expected, deck_tolerance) << ran.out.substr(ran.out.size() > 3000 ? ran.out.size() - 3000 : 0);
  std::printf("[edited deck] %s, damping %s -> %s: rebound e = %.9f, viscor predicts %.9f\n", model_args.c_str(),
              calibrated.c_str(), edited.c_str(), e, expected);
}

// Before/after: the code's own conversion (the measured e written into its e input) in
// the deck viscor wrote; the deck reports the e viscor predicts for it (builtin_e).
TEST(DemDropDeck, LammpsTsujiDeckWithTheBuiltinEntryReportsItsE) {
  expect_edited_deck_reports("lmp", "lammps --damping tsuji", "-in", "0.8",
                             "dem lammps --damping tsuji --target-e 0.8", "builtin_e");
}
TEST(DemDropDeck, LiggghtsHertzDeckWithTheBuiltinEntryReportsItsE) {
  expect_edited_deck_reports("liggghts", "liggghts --damping hertz", "-in", "0.8",
                             "dem liggghts --damping hertz --target-e 0.8", "builtin_e");
}
// About four times the damping: a shorter rebound and a contact time other than the calibrated one.
TEST(DemDropDeck, YadeMindlinDeckWithEditedDampingReportsItsE) {
  expect_edited_deck_reports("yade", "yade --damping mindlin", "-n -x", "0.3",
                             "dem yade --damping mindlin --deck-damping 0.3 --speeds 0.5", "table");
}


/// The e at the code's time step (dem/stepped_drop.hpp): `viscor dem --timestep T/N
/// --drop-deck` writes the deck at that step with entries calibrated for it, and the real
/// program rebounds within 1e-5 of the target at T/20, T/50 and T/100; the same deck with
/// the continuous calibration's entry drifts by what viscor says it does (within 1e-5),
/// and by more than the step-aware entry misses. The truth is the target and the
/// program's own rebound; viscor's stepped drop is what is checked.
void expect_step_aware_decks_hit_target(const std::string& program_name, const std::string& model_args,
                                        const std::string& run_flags) {
  SCOPED_TRACE(model_args);
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program(program_name);
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name << " is not installed (tools/install-deps.sh installs it)");
  for (const int n : {20, 50, 100}) {
    scratch_dir dir{"viscor_drop_deck"};
    ASSERT_FALSE(dir.path.empty());
    const std::string deck_name = program_name == "yade" ? "drop.py" : "drop.in";
    const std::string deck = (dir.path / deck_name).string();
    const auto written =
        run_cli("dem " + model_args + glass + " --timestep T/" + std::to_string(n) + " --drop-deck " + deck + " --json");
    ASSERT_EQ(written.status, 0) << written.err;
    const nlohmann::json j = nlohmann::json::parse(written.out);
    const auto ran = run_in(dir.path, "'" + *program + "' " + run_flags + " " + deck_name);
    ASSERT_EQ(ran.status, 0) << ran.out;
    const double e = printed_rebound_e(ran.out);
    EXPECT_NEAR(e, target_e, 1e-5) << "T/" << n << ": " << ran.out.substr(ran.out.size() > 2000 ? ran.out.size() - 2000 : 0);
    // the same deck with the entry calibrated for the continuous impact
    const std::string stepped_entry = j["deck"]["damping"], continuous_entry = j["continuous_deck_damping"];
    ASSERT_GT(replace_in_file(deck, stepped_entry, continuous_entry), 0u) << stepped_entry;
    const auto continuous = run_in(dir.path, "'" + *program + "' " + run_flags + " " + deck_name);
    ASSERT_EQ(continuous.status, 0) << continuous.out;
    const double drift = printed_rebound_e(continuous.out) - target_e;
    const double predicted = std::stod(j["continuous_timestep_e"].get<std::string>()) - target_e;
    EXPECT_NEAR(drift, predicted, 1e-5) << "T/" << n << ": the continuous entry's drift, viscor's stepped drop";
    EXPECT_GT(std::abs(drift), std::abs(e - target_e)) << "T/" << n;
    std::printf("[time step] %s at T/%d: step-aware entry %s: e = %.9f (miss %+.1e); continuous entry %s: "
                "e = %.9f (drift %+.2e, viscor's stepped drop %+.2e)\n",
                model_args.c_str(), n, stepped_entry.c_str(), e, e - target_e, continuous_entry.c_str(),
                target_e + drift, drift, predicted);
  }
}

TEST(DemDropDeck, LammpsTsujiStepAwareDecksHitTheTarget) {
  expect_step_aware_decks_hit_target("lmp", "lammps --damping tsuji", "-in");
}
TEST(DemDropDeck, LammpsVelocityStepAwareDecksHitTheTarget) {  // the damping force already acts at zero overlap
  expect_step_aware_decks_hit_target("lmp", "lammps --damping velocity", "-in");
}
TEST(DemDropDeck, LiggghtsHertzStepAwareDecksHitTheTarget) {
  expect_step_aware_decks_hit_target("liggghts", "liggghts --damping hertz", "-in");
}
TEST(DemDropDeck, YadeMindlinStepAwareDecksHitTheTarget) {
  expect_step_aware_decks_hit_target("yade", "yade --damping mindlin", "-n -x");
}
// The C export's YADE entries: the stepped calibration from the unclamped surrogate's bracket.
TEST(DemDropDeck, YadeMindlinStepAwareDecksBySurrogateHitTheTarget) {
  expect_step_aware_decks_hit_target("yade", "yade --damping mindlin --method surrogate", "-n -x");
}

/// Two glass beads head-on (`--contact pair`: gravity drops out) with the entries of
/// `viscor dem --contact pair --timestep T/N`: the real program, stepping each bead with
/// its own velocity Verlet, rebounds within 1e-5 of the target at T/20, T/50 and T/100
/// (the separation speed fitted at the touching gap, tests/dem_drop_utils.hpp run_drop).
/// viscor steps the relative motion of the reduced mass, which Verlet, being linear,
/// reproduces up to rounding: this is what is checked.
void expect_step_aware_pair_hits_target(const std::string& program_name, const std::string& code,
                                        const std::string& damping) {
  SCOPED_TRACE(code + " " + damping);
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program(program_name);
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name << " is not installed (tools/install-deps.sh installs it)");
  for (const int n : {20, 50, 100}) {
    const auto written = run_cli("dem " + code + " --damping " + damping + glass + " --contact pair --timestep T/" +
                                 std::to_string(n) + " --json");
    ASSERT_EQ(written.status, 0) << written.err;
    const nlohmann::json j = nlohmann::json::parse(written.out);
    dem_drop::drop_setup s;
    s.model = &viscor::dem::find_dem_model(code, damping);
    s.kind = viscor::dem::contact_kind::pair;
    s.youngs_modulus = j["deck"]["youngs_modulus"], s.poisson_ratio = j["deck"]["poisson_ratio"];
    s.damping = j["deck"]["damping"];
    s.radius = 1e-3, s.density = 2500, s.v0 = 0.5;
    s.dt = std::stod(j["time_step_s"].get<std::string>());
    s.steps = 6L * n;  // six time scales: the contact lasts about 3.3
    const auto r = dem_drop::run_drop(*program, s);
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_NEAR(r.e, target_e, 1e-5) << "T/" << n;
    std::printf("[time step] %s %s, two beads at T/%d: step-aware entry %s: e = %.9f (miss %+.1e)\n", code.c_str(),
                damping.c_str(), n, s.damping.c_str(), r.e, r.e - target_e);
  }
}

TEST(DemDropDeck, LammpsTsujiStepAwarePairHitsTheTarget) { expect_step_aware_pair_hits_target("lmp", "lammps", "tsuji"); }
TEST(DemDropDeck, LiggghtsHertzStepAwarePairHitsTheTarget) {
  expect_step_aware_pair_hits_target("liggghts", "liggghts", "hertz");
}

/// `viscor dem --json` output for the glass bead.
nlohmann::json dem_json(const std::string& model_args) {
  const auto r = run_cli("dem " + model_args + glass + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

// The snippet as a user pastes it into a deck of their own: the test supplies the
// box, the bead, gravity, the integrator and the output, nothing of the contact model.
TEST(DemDropDeck, LiggghtsSnippetRunsInMinimalDeck) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program("liggghts");
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING("liggghts is not installed (tools/install-deps.sh installs it)");
  const auto j = dem_json("liggghts --damping hertz");
  const double dt = std::stod(j["time_step_s"].get<std::string>());
  const std::string snippet = j["snippet"];
  EXPECT_NE(snippet.find("coefficientFriction"), std::string::npos) << snippet;
  const std::string deck =
      "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\n"
      "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box\ncreate_box 2 box\nneighbor 5e-4 bin\n"
      "neigh_modify delay 0\n" + snippet +
      "timestep " + dem_drop::format_double(dt) + "\ncreate_atoms 1 single 0 0 1e-3 units box\n"
      "set atom 1 diameter 2e-3 density 2500\nvelocity all set 0 0 -0.5 units box\n"
      "fix grav all gravity 9.81 vector 0 0 -1\nfix integr all nve/sphere\nvariable z equal z[1]\n"
      "variable vz equal vz[1]\nthermo_style custom step v_z v_vz\nthermo_modify format float %.17g\nthermo 1\n"
      "run " + std::to_string(static_cast<long>(6 * std::stod(j["time_scale_s"].get<std::string>()) / dt)) + "\n";
  scratch_dir dir{"viscor_drop_deck"};
  ASSERT_FALSE(dir.path.empty());
  std::ofstream(dir.path / "in.snippet") << deck;
  std::vector<dem_drop::sample> samples;
  std::string log;
  const int status =
      dem_drop::run_collecting_samples("cd '" + dir.path.string() + "' && '" + *program + "' -in in.snippet 2>&1", samples, log);
  ASSERT_EQ(status, 0) << log;
  const auto v_exit = dem_drop::fitted_exit_speed(samples, 1e-3, 1.25);  // LIGGGHTS hertz: beta = 5/4
  ASSERT_TRUE(v_exit) << log;
  EXPECT_NEAR(*v_exit / 0.5, target_e, deck_tolerance);
  std::printf("[snippet] liggghts hertz in a minimal deck: rebound e = %.9f\n", *v_exit / 0.5);
}

// The LAMMPS wall snippet's bead-bead entries (pair_coeff) are those of two beads:
// a head-on collision of two glass beads with them rebounds at the target.
TEST(DemDropDeck, LammpsSnippetBeadBeadEntriesFitTwoBeads) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program("lmp");
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING("lmp is not installed (tools/install-deps.sh installs it)");
  const auto j = dem_json("lammps --damping tsuji");
  ASSERT_TRUE(j["deck"].contains("bead_bead_damping")) << j.dump(2);
  const std::string E = j["deck"]["bead_bead_youngs_modulus"], damp = j["deck"]["bead_bead_damping"];
  EXPECT_DOUBLE_EQ(std::stod(E), 7e10);  // a pair reads E/(2(1 - nu^2)): the bead's own E
  const std::string snippet = j["snippet"];
  EXPECT_NE(snippet.find("pair_coeff * * hertz/material " + E + " " + damp), std::string::npos) << snippet;
  dem_drop::drop_setup s;
  s.model = &viscor::dem::find_dem_model("lammps", "tsuji");
  s.kind = viscor::dem::contact_kind::pair;
  s.youngs_modulus = E, s.poisson_ratio = j["deck"]["poisson_ratio"], s.damping = damp;
  s.radius = 1e-3, s.density = 2500, s.v0 = 0.5;
  // the pair's time scale: (m*/k)^(2/5) v0^(-1/5) with m* = m/2, k = (4/3) E/(2(1 - nu^2)) sqrt(R/2)
  const double m = 4.0 / 3 * M_PI * 1e-9 * 2500;
  const double k = 4.0 / 3 * 7e10 / (2 * (1 - 0.22 * 0.22)) * std::sqrt(0.5e-3);
  const double T = std::pow(m / 2 / k, 0.4) * std::pow(0.5, -0.2);
  s.dt = T / 400, s.steps = 6 * 400;
  const auto r = dem_drop::run_drop(*program, s);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.e, target_e, deck_tolerance);
  std::printf("[snippet] lammps tsuji bead-bead entries, two beads head-on: e = %.9f\n", r.e);
}

}  // namespace

namespace {
// The YADE snippet as pasted, followed only by a run of twice the contact time:
// it runs, and the bead leaves the wall upwards at about the target e (the speed
// read after the flight, which gravity has slowed by g t, added back here; the
// exact e at zero overlap is the drop deck's check above).
TEST(DemDropDeck, YadeSnippetRunsAsPasted) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program("yade");
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING("yade is not installed (tools/install-deps.sh installs it)");
  const auto j = dem_json("yade --damping mindlin");
  const double contact = std::stod(j["contact_time_s"].get<std::string>());
  const std::string script = "import sys\n" + j["snippet"].get<std::string>() +
                             "O.run(int(2 * " + dem_drop::format_double(contact) + " / O.dt), True)\n"
                             "v = O.bodies[1].state.vel[2] + 9.81 * (O.time - " + dem_drop::format_double(contact) + ")\n"
                             "print('rebound e = %.15g' % (v / 0.5))\nsys.stdout.flush()\n";
  scratch_dir dir{"viscor_drop_deck"};
  ASSERT_FALSE(dir.path.empty());
  std::ofstream(dir.path / "snippet.py") << script;
  const auto ran = run_in(dir.path, "'" + *program + "' -n -x snippet.py");
  ASSERT_EQ(ran.status, 0) << ran.out;
  const double e = printed_rebound_e(ran.out);
  EXPECT_NEAR(e, target_e, 1e-3) << ran.out;
  std::printf("[snippet] yade mindlin as pasted: e = %.6f\n", e);
}
}  // namespace
