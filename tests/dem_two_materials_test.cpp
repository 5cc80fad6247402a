// Two materials in the real DEM programs: a glass bead on a steel plate, and a glass
// bead meeting a steel bead. For each code, the deck entries `viscor dem` writes
// (its snippet pasted as is, for LAMMPS and LIGGGHTS) are loaded into the program,
// which computes the normal force of one configuration (run 0 / one step at a tiny
// dt) at a set overlap, once at rest and once approaching. The expected forces come
// from Hertz theory written out here (E*, R*, m* of the two bodies) and viscor's
// force law F = k delta^(3/2) + gamma0 k beta delta^(beta-1) delta' with the gamma0
// the JSON reports: the elastic force checks the effective modulus and radius the
// code forms from the deck, the damped one the damping entry. The drop decks on a
// steel plate are also run as written and rebound at the target.
#include "dem_drop_utils.hpp"
#include "required_dependencies.hpp"
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace {

using viscor::test::scratch_dir;

using namespace viscor::test;

// Glass (the bead) and steel (the plate, or the other bead), SI units.
constexpr double E_glass = 63e9, nu_glass = 0.22, R_glass = 1e-3, rho_glass = 2500;
constexpr double E_steel = 200e9, nu_steel = 0.3, R_steel = 1.5e-3, rho_steel = 7800;
constexpr double overlap = 2e-6, rate = 0.05;  // m, m/s (approaching)
constexpr double pi = 3.141592653589793;

const std::string bead_args = " --youngs-modulus 63e9 --poisson-ratio 0.22 --radius 1e-3 --density 2500"
                              " --target-e 0.8 --v0 0.5 --gravity 9.81";
const std::string plate_args = " --wall-youngs-modulus 200e9 --wall-poisson-ratio 0.3";
const std::string other_args =
    " --contact pair --other-youngs-modulus 200e9 --other-poisson-ratio 0.3 --other-radius 1.5e-3 --other-density 7800";

/// Hertz theory of the two bodies (core/elastic_contact.hpp's formulas, written out independently).
struct two_bodies {
  double E_star, R_star, m_star;
  double k() const { return 4.0 / 3.0 * E_star * std::sqrt(R_star); }
};

two_bodies glass_on_plate() {
  const double m = 4.0 / 3.0 * pi * R_glass * R_glass * R_glass * rho_glass;
  return {1 / ((1 - nu_glass * nu_glass) / E_glass + (1 - nu_steel * nu_steel) / E_steel), R_glass, m};
}

two_bodies glass_on_steel_bead() {
  const double m1 = 4.0 / 3.0 * pi * R_glass * R_glass * R_glass * rho_glass;
  const double m2 = 4.0 / 3.0 * pi * R_steel * R_steel * R_steel * rho_steel;
  return {1 / ((1 - nu_glass * nu_glass) / E_glass + (1 - nu_steel * nu_steel) / E_steel),
          R_glass * R_steel / (R_glass + R_steel), m1 * m2 / (m1 + m2)};
}

/// viscor's normal force at the test overlap for a law with damping exponent beta
/// (5/4: LAMMPS tsuji, LIGGGHTS hertz, YADE mindlin; 1: LAMMPS velocity).
double viscor_force(const two_bodies& b, double gamma0, double overlap_rate, double beta = 1.25) {
  return b.k() * std::pow(overlap, 1.5) + gamma0 * b.k() * beta * std::pow(overlap, beta - 1) * overlap_rate;
}

nlohmann::json dem_json(const std::string& args) {
  const auto r = run_cli("dem " + args + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

double json_number(const nlohmann::json& j, const char* key) { return std::stod(j.at(key).get<std::string>()); }

/// Runs `command` in a scratch folder holding `file` = `text`; returns the lines starting "FORCE".
std::vector<double> printed_forces(const std::string& file, const std::string& text, const std::string& command,
                                   std::string& log) {
  scratch_dir dir{"viscor_two_materials"};
  std::ofstream(dir.path / file) << text;
  const auto r = run_cli("", "cd '" + dir.path.string() + "' && " + command + " 2>&1");
  log = r.out + r.err;
  std::vector<double> forces;
  static const std::regex line(R"(FORCE ([-+0-9.eE]+))");
  for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator(); ++it)
    forces.push_back(std::stod((*it)[1]));
  return forces;
}

// The one-step configurations: bead 1 (glass) at overlap 2e-6 with the plate z = 0 or with
// bead 2 (steel) on the x axis, at rest, then approaching at `rate`. Each prints "FORCE |F|".
std::string lammps_like_configuration(bool liggghts, bool wall, const std::string& snippet, double velocity) {
  const std::string units = liggghts ? " units box" : "";
  std::string s = liggghts ? "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\n"
                             "communicate single vel yes\nunits si\n"
                           : "units si\natom_style sphere\natom_modify map array\nboundary f f f\ncomm_modify vel yes\n";
  s += "region box block -0.01 0.01 -0.01 0.01 -0.01 0.01" + units + "\ncreate_box 2 box\nneighbor 5e-4 bin\n";
  s += snippet;  // as `viscor dem` prints it
  if (wall) {
    s += "create_atoms 1 single 0 0 " + dem_drop::format_double(R_glass - overlap) + units + "\n";
    s += "set atom 1 diameter 2e-3 density 2500\n";
    s += "velocity all set 0 0 " + dem_drop::format_double(-velocity) + units + "\n";
    s += "variable f equal abs(fz[1])\n";
  } else {
    s += "create_atoms 1 single 0 0 0" + units + "\n";
    s += "create_atoms 2 single " + dem_drop::format_double(R_glass + R_steel - overlap) + " 0 0" + units + "\n";
    s += "set atom 1 diameter 2e-3 density 2500\nset atom 2 diameter 3e-3 density 7800\n";
    s += "velocity all set 0 0 0" + units + "\n";
    s += "set atom 1 vx " + dem_drop::format_double(velocity / 2) + "\nset atom 2 vx " +
         dem_drop::format_double(-velocity / 2) + "\n";
    s += "variable f equal abs(fx[1])\n";
  }
  s += liggghts ? "fix integr all nve/sphere\ntimestep 1e-12\n" : "timestep 1e-12\n";
  // LIGGGHTS has no format-style variable: print's own %.15g is enough for the 1e-9 checked
  s += liggghts ? "run 0\nprint \"FORCE ${f}\"\n" : "variable ff format f %.17g\nrun 0\nprint \"FORCE ${ff}\"\n";
  return s;
}

void expect_snippet_forces(const char* program_name, const std::string& code_args, bool wall, double beta = 1.25) {
  SCOPED_TRACE(code_args + (wall ? " on a steel plate" : " against a steel bead"));
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto program = dem_drop::find_program(program_name);
  if (!program) VISCOR_SKIP_OR_FAIL_MISSING(program_name << " is not installed (tools/install-deps.sh installs it)");
  const auto j = dem_json(code_args + bead_args + (wall ? plate_args : other_args));
  ASSERT_TRUE(j.contains("snippet"));
  const two_bodies b = wall ? glass_on_plate() : glass_on_steel_bead();
  EXPECT_NEAR(json_number(j, "effective_modulus_pa") / b.E_star, 1, 1e-14);
  EXPECT_NEAR(json_number(j, "effective_radius_m") / b.R_star, 1, 1e-14);
  EXPECT_NEAR(json_number(j, "effective_mass_kg") / b.m_star, 1, 1e-14);
  const bool liggghts = std::string(program_name) == "liggghts";
  for (const double velocity : {0.0, rate}) {
    std::string log;
    const auto forces = printed_forces(
        "in.force", lammps_like_configuration(liggghts, wall, j["snippet"], velocity),
        "'" + *program + "' -log none -in in.force", log);
    ASSERT_EQ(forces.size(), 1u) << log;
    const double expected = viscor_force(b, json_number(j, "gamma0"), velocity, beta);
    EXPECT_NEAR(forces[0] / expected, 1, 1e-9) << "overlap rate " << velocity << ": printed " << forces[0]
                                                << ", viscor " << expected << "\n" << log;
    std::printf("[two materials] %s %s, rate %g: program %.12g N, viscor %.12g N\n", code_args.c_str(),
                wall ? "plate" : "pair", velocity, forces[0], expected);
  }
}

TEST(DemTwoMaterials, LammpsPlateForceMatchesHertz) { expect_snippet_forces("lmp", "lammps --damping tsuji", true); }
TEST(DemTwoMaterials, LammpsPairForceMatchesHertz) { expect_snippet_forces("lmp", "lammps --damping tsuji", false); }
TEST(DemTwoMaterials, LammpsVelocityPairForceMatchesHertz) {
  expect_snippet_forces("lmp", "lammps --damping velocity", false, 1.0);
}
TEST(DemTwoMaterials, LiggghtsPlateForceMatchesHertz) {
  expect_snippet_forces("liggghts", "liggghts --damping hertz", true);
}
TEST(DemTwoMaterials, LiggghtsPairForceMatchesHertz) {
  expect_snippet_forces("liggghts", "liggghts --damping hertz", false);
}

// YADE: the materials as the JSON deck gives them, in one yade run (its start-up is the cost).
TEST(DemTwoMaterials, YadeMindlinForcesMatchHertz) {
  if (std::string(VISCOR_CLI_PATH).empty()) GTEST_SKIP() << "viscor CLI not built";
  const auto yade = dem_drop::find_program("yade");
  if (!yade) VISCOR_SKIP_OR_FAIL_MISSING("yade is not installed (tools/install-deps.sh installs it)");
  const auto plate = dem_json("yade --damping mindlin" + bead_args + plate_args);
  const auto pair = dem_json("yade --damping mindlin" + bead_args + other_args);
  ASSERT_TRUE(plate.contains("deck") && pair.contains("deck"));
  const auto& dp = plate["deck"];
  const auto& dq = pair["deck"];
  auto str = [](const nlohmann::json& v) { return v.get<std::string>(); };
  std::string script =
      "from yade import utils\n"
      "def force(wall, rate, bead, other, betan):\n"
      "    O.reset()\n"
      "    b = O.materials.append(bead)\n"
      "    o = O.materials.append(other)\n"
      "    if wall:\n"
      "        s = utils.sphere((0, 0, 1e-3 - 2e-6), 1e-3, material=b)\n"
      "        O.bodies.append([utils.wall(0, axis=2, material=o), s])\n"
      "        s.state.vel = (0, 0, -rate)\n"
      "        geoms, bounds = [Ig2_Wall_Sphere_ScGeom()], [Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]\n"
      "    else:\n"
      "        a = utils.sphere((0, 0, 0), 1e-3, material=b)\n"
      "        c = utils.sphere((1e-3 + 1.5e-3 - 2e-6, 0, 0), 1.5e-3, material=o)\n"
      "        O.bodies.append([a, c])\n"
      "        a.state.vel, c.state.vel = (rate / 2, 0, 0), (-rate / 2, 0, 0)\n"
      "        geoms, bounds = [Ig2_Sphere_Sphere_ScGeom()], [Bo1_Sphere_Aabb()]\n"
      "    O.engines = [ForceResetter(), InsertionSortCollider(bounds), InteractionLoop(geoms,\n"
      "        [Ip2_FrictMat_FrictMat_MindlinPhys(betan=betan)], [Law2_ScGeom_MindlinPhys_Mindlin()]),\n"
      "        NewtonIntegrator(damping=0, gravity=(0, 0, 0))]\n"
      "    O.dt = 1e-12\n"
      "    O.step()\n"
      "    return abs(O.forces.f(1)[2]) if wall else abs(O.forces.f(0)[0])\n"
      "for rate in (0.0, 0.05):\n"
      "    print('FORCE %.17g' % force(True, rate, FrictMat(young=" + str(dp["youngs_modulus"]) + ", poisson=" +
      str(dp["poisson_ratio"]) + ", density=2500, frictionAngle=0), FrictMat(young=" + str(dp["wall_youngs_modulus"]) +
      ", poisson=" + str(dp["wall_poisson_ratio"]) + ", density=7800, frictionAngle=0), " + str(dp["damping"]) + "))\n"
      "for rate in (0.0, 0.05):\n"
      "    print('FORCE %.17g' % force(False, rate, FrictMat(young=" + str(dq["youngs_modulus"]) + ", poisson=" +
      str(dq["poisson_ratio"]) + ", density=2500, frictionAngle=0), FrictMat(young=" + str(dq["other_youngs_modulus"]) +
      ", poisson=" + str(dq["other_poisson_ratio"]) + ", density=7800, frictionAngle=0), " + str(dq["damping"]) + "))\n"
      "import sys\nsys.stdout.flush()\n";
  std::string log;
  const auto forces = printed_forces("force.py", script, "'" + *yade + "' -n -x force.py", log);
  ASSERT_EQ(forces.size(), 4u) << log;
  const double expected[4] = {viscor_force(glass_on_plate(), json_number(plate, "gamma0"), 0),
                              viscor_force(glass_on_plate(), json_number(plate, "gamma0"), rate),
                              viscor_force(glass_on_steel_bead(), json_number(pair, "gamma0"), 0),
                              viscor_force(glass_on_steel_bead(), json_number(pair, "gamma0"), rate)};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(forces[i] / expected[i], 1, 1e-9) << "case " << i << ": yade " << forces[i] << ", viscor "
                                                  << expected[i] << "\n" << log;
    std::printf("[two materials] yade mindlin %s, rate %g: program %.12g N, viscor %.12g N\n",
                i < 2 ? "plate" : "pair", i % 2 ? rate : 0.0, forces[i], expected[i]);
  }
}

}  // namespace
