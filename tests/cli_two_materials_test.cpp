// A bead on a wall of its own material and two beads of different materials in
// `viscor cor` and scene files: the scaled point equals the one of the same impact
// given as --m and --k, with m and k from Hertz theory written out here (E*, R*,
// m* of the two bodies); a pair's gravity drops out; misplaced inputs are refused
// naming the option. (The DEM side is tests/dem_two_materials_test.cpp.)
#include "test_utils.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

using viscor::test::run_cli;

constexpr double pi = 3.141592653589793;
const std::string glass = " --model tsuji --youngs-modulus 63e9 --poisson-ratio 0.22 --radius 1e-3 --density 2500";
const std::string impact = " --v0 0.5 --gamma0 1e-8 --gravity 9.81 --digits 30 --json";
const std::string steel_plate = " --wall-youngs-modulus 200e9 --wall-poisson-ratio 0.3";
const std::string steel_bead =
    " --contact pair --other-youngs-modulus 200e9 --other-poisson-ratio 0.3 --other-radius 1.5e-3 --other-density 7800";

std::string text(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

nlohmann::json cor_json(const std::string& args) {
  const auto r = run_cli("cor" + args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

double field(const nlohmann::json& j, const char* name) { return std::stod(j.at(name).get<std::string>()); }

const double glass_mass = 4.0 / 3.0 * pi * 1e-9 * 2500;
const double steel_mass = 4.0 / 3.0 * pi * 1.5e-3 * 1.5e-3 * 1.5e-3 * 7800;
const double compliance = (1 - 0.22 * 0.22) / 63e9 + (1 - 0.3 * 0.3) / 200e9;  // 1/E* of glass and steel

TEST(CliTwoMaterials, SteelPlateIsTheHertzStiffness) {
  const auto plate = cor_json(glass + steel_plate + impact);
  const double k = 4.0 / 3.0 / compliance * std::sqrt(1e-3);
  const auto direct = cor_json(" --model tsuji --m " + text(glass_mass) + " --k " + text(k) + impact);
  ASSERT_TRUE(plate.contains("gamma") && direct.contains("gamma"));
  EXPECT_NEAR(field(plate, "gamma") / field(direct, "gamma"), 1, 1e-14);
  EXPECT_NEAR(field(plate, "g") / field(direct, "g"), 1, 1e-14);
  EXPECT_NEAR(field(plate, "e"), field(direct, "e"), 1e-14);
  // the plate is softer than a rigid wall: a longer contact, a different e
  const auto rigid = cor_json(glass + impact);
  EXPECT_GT(std::abs(field(rigid, "gamma") / field(plate, "gamma") - 1), 1e-3);
  EXPECT_EQ(plate["physical"]["wall_youngs_modulus"], "200e9");  // echoed as typed
}

TEST(CliTwoMaterials, SteelBeadIsTheRelativeMotion) {
  const auto pair = cor_json(glass + steel_bead + impact);
  const double R = 1e-3 * 1.5e-3 / 2.5e-3, m = glass_mass * steel_mass / (glass_mass + steel_mass);
  const double k = 4.0 / 3.0 / compliance * std::sqrt(R);
  // a pair feels no gravity (both beads fall alike): the same as --gravity 0 for the reduced bead
  const std::string no_gravity = " --v0 0.5 --gamma0 1e-8 --gravity 0 --digits 30 --json";
  const auto direct = cor_json(" --model tsuji --m " + text(m) + " --k " + text(k) + no_gravity);
  ASSERT_TRUE(pair.contains("gamma") && direct.contains("gamma"));
  EXPECT_NEAR(field(pair, "gamma") / field(direct, "gamma"), 1, 1e-14);
  EXPECT_EQ(field(pair, "g"), 0);
  EXPECT_NEAR(field(pair, "e"), field(direct, "e"), 1e-14);
}

TEST(CliTwoMaterials, LikeBeadsHalveModulusRadiusAndMass) {
  const auto pair = cor_json(glass + " --contact pair" + impact);
  const double k = 4.0 / 3.0 * (63e9 / (1 - 0.22 * 0.22) / 2) * std::sqrt(0.5e-3);
  const std::string no_gravity = " --v0 0.5 --gamma0 1e-8 --gravity 0 --digits 30 --json";
  const auto direct = cor_json(" --model tsuji --m " + text(glass_mass / 2) + " --k " + text(k) + no_gravity);
  ASSERT_TRUE(pair.contains("gamma") && direct.contains("gamma"));
  EXPECT_NEAR(field(pair, "gamma") / field(direct, "gamma"), 1, 1e-14);
}

TEST(CliTwoMaterials, SceneOfTwoBeadsMatchesCor) {
  const std::string path = ::testing::TempDir() + "viscor_two_beads_" + std::to_string(::getpid()) + ".json";
  std::ofstream(path) << R"({"law": "tsuji",
    "bead": {"density": 2500, "radius": 1e-3, "youngs_modulus": 63e9, "poisson_ratio": 0.22},
    "contact": "pair", "other": {"density": 7800, "radius": 1.5e-3, "youngs_modulus": 200e9, "poisson_ratio": 0.3},
    "damping": {"gamma0": 1e-8}, "gravity": 9.81, "velocities": [0.5], "tolerance": 1e-12})";
  const auto r = run_cli("scene " + path + " --json");
  std::remove(path.c_str());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto scene = nlohmann::json::parse(r.out);
  const auto& row = scene.at("rows").at(0);
  const auto cor = cor_json(glass + steel_bead + impact);
  ASSERT_TRUE(cor.contains("e"));
  EXPECT_NEAR(std::stod(row.at("e").get<std::string>()), field(cor, "e"), 1e-12);
  EXPECT_NEAR(std::stod(row.at("gamma").get<std::string>()) / field(cor, "gamma"), 1, 1e-14);
}

TEST(CliTwoMaterials, MisplacedInputsNameTheOption) {
  const struct {
    std::string args, named;
  } cases[] = {
      {glass + " --other-radius 1e-3" + impact, "--other-"},
      {glass + " --contact pair" + steel_plate + impact, "--wall-youngs-modulus"},
      {glass + " --wall-youngs-modulus 200e9" + impact, "--wall-poisson-ratio"},
      {glass + " --contact pair --other-youngs-modulus 200e9" + impact, "--other-radius"},
      {glass + " --contact plate" + impact, "'plate'"},
      {" --model tsuji --m 1e-5 --k 1e9 --contact pair" + impact, "--k"},
      {glass + " --contact pair --other-youngs-modulus 200e9 --other-poisson-ratio 0.7 --other-radius 1e-3 "
               "--other-density 7800" + impact,
       "other_poisson_ratio"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli("cor" + c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << c.args << "\n" << r.err;
  }
}

}  // namespace
