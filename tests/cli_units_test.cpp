// Physical inputs in the wrong unit are warned about (refused under --strict), a
// negative gravity is refused with the sign convention, and the readable output
// echoes the inputs as typed. The ranges come from the quantities (no solid has a
// Young's modulus of 70 Pa), not from the code under test.
#include "test_utils.hpp"

#include <viscor/core/plausible_units.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

using viscor::test::run_cli;

bool cli_built() { return std::string(VISCOR_CLI_PATH).size() > 0; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A 2 mm glass bead dropped at 0.5 m/s, in SI units and in the units a user mixes up
// (GPa, mm, g/cm^3, cm/s, cm/s^2).
const std::string glass_si =
    "dem lammps --damping tsuji --youngs-modulus 70e9 --poisson-ratio 0.22 --radius 1e-3 --density 2500 "
    "--target-e 0.8 --v0 0.5 --gravity 9.81";
const std::string glass_mixed =
    "dem lammps --damping tsuji --youngs-modulus 70 --poisson-ratio 0.22 --radius 1 --density 2.5 "
    "--target-e 0.8 --v0 50 --gravity 981";

TEST(PlausibleUnits, RangesOfTheQuantities) {
  using viscor::implausible_unit;
  using viscor::physical_quantity;
  // Real materials: rubber 1e6 Pa, steel 2e11 Pa; cork 240 kg/m^3, tungsten 19,300.
  for (double e : {1e6, 7e10, 2.1e11, 1.1e12}) EXPECT_FALSE(implausible_unit(physical_quantity::youngs_modulus, e, "--E", "x"));
  for (double rho : {240.0, 1000.0, 7850.0, 19300.0}) EXPECT_FALSE(implausible_unit(physical_quantity::density, rho, "--d", "x"));
  EXPECT_FALSE(implausible_unit(physical_quantity::gravity, 0, "--gravity", "0"));
  EXPECT_FALSE(implausible_unit(physical_quantity::gravity, 9.81, "--gravity", "9.81"));
  EXPECT_FALSE(implausible_unit(physical_quantity::speed, 0.001, "--v0", "0.001"));
  // The mistakes: GPa, g/cm^3, cm/s^2, cm/s, mm.
  const auto modulus = implausible_unit(physical_quantity::youngs_modulus, 70, "--youngs-modulus", "70");
  ASSERT_TRUE(modulus);
  EXPECT_TRUE(contains(*modulus, "--youngs-modulus 70 Pa")) << *modulus;
  EXPECT_TRUE(contains(*modulus, "GPa")) << *modulus;
  const auto density = implausible_unit(physical_quantity::density, 2.5, "--density", "2.5");
  ASSERT_TRUE(density);
  EXPECT_TRUE(contains(*density, "g/cm^3")) << *density;
  const auto gravity = implausible_unit(physical_quantity::gravity, 981, "--gravity", "981");
  ASSERT_TRUE(gravity);
  EXPECT_TRUE(contains(*gravity, "cm/s^2")) << *gravity;
  EXPECT_TRUE(implausible_unit(physical_quantity::speed, 1500, "--v0", "1500"));
  EXPECT_TRUE(implausible_unit(physical_quantity::radius, 20, "--radius", "20"));
}

TEST(PlausibleUnits, MixedUpUnitsWarnAndStrictRefuses) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto sane = run_cli(glass_si);
  ASSERT_EQ(sane.status, 0) << sane.err;
  EXPECT_FALSE(contains(sane.err, "warning")) << sane.err;

  const auto mixed = run_cli(glass_mixed);
  EXPECT_TRUE(contains(mixed.err, "warning: --youngs-modulus 70 Pa")) << mixed.err;
  EXPECT_TRUE(contains(mixed.err, "warning: --density 2.5 kg/m^3")) << mixed.err;
  EXPECT_TRUE(contains(mixed.err, "warning: --gravity 981 m/s^2")) << mixed.err;

  const auto strict = run_cli(glass_mixed + " --strict");
  EXPECT_EQ(strict.status, 2) << strict.err;
  EXPECT_TRUE(contains(strict.err, "--youngs-modulus 70")) << strict.err;
  EXPECT_TRUE(strict.out.empty()) << strict.out;

  const auto cor = run_cli("cor --model kuwabara_kono --youngs-modulus 70e9 --poisson-ratio 0.22 --radius 1e-3 "
                           "--density 2.5 --gamma0 1e-6 --v0 0.5 --gravity 9.81 --strict");
  EXPECT_EQ(cor.status, 2) << cor.err;
  EXPECT_TRUE(contains(cor.err, "--density 2.5")) << cor.err;
}

TEST(PlausibleUnits, NegativeGravityIsRefusedWithTheSignConvention) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  for (const std::string& command :
       {std::string("cor --model kuwabara_kono --m 2.05e-3 --k 6.9716e9 --gamma0 8.49e-7 --v0 0.246 --gravity -9.81"),
        std::string("scale --model kuwabara_kono --m 2.05e-3 --k 6.9716e9 --v0 0.246 --gravity -9.81"),
        std::string("calibrate --model tsuji --target-e 0.8 --m 2.05e-3 --k 6.9716e9 --v0 0.246 --gravity -9.81"),
        std::string("dem lammps --damping tsuji --youngs-modulus 70e9 --poisson-ratio 0.22 --radius 1e-3 "
                    "--density 2500 --target-e 0.8 --v0 0.5 --gravity -9.81")}) {
    SCOPED_TRACE(command);
    const auto r = run_cli(command);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_TRUE(contains(r.err, "--gravity -9.81 is negative")) << r.err;
    EXPECT_TRUE(contains(r.err, "towards the wall")) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(PlausibleUnits, NegativeGravityInASceneFileIsRefused) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const std::string path = ::testing::TempDir() + "viscor_negative_gravity_" + std::to_string(::getpid()) + ".json";
  {
    std::ofstream scene(path);
    scene << R"({"law": "kuwabara_kono", "bead": {"m": 2.05e-3, "k": 6.9716e9}, "damping": {"gamma0": 8.49e-7},
                 "gravity": -9.81, "velocities": [0.246], "tolerance": 1e-6})";
  }
  const auto r = run_cli("scene " + path);
  std::remove(path.c_str());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(contains(r.err, "gravity -9.81 is negative")) << r.err;
}

TEST(PlausibleUnits, ReadableOutputEchoesTheInputsAsTyped) {
  if (!cli_built()) GTEST_SKIP() << "viscor CLI not built";
  const auto r = run_cli("cor --model kuwabara_kono --m 2.05e-3 --k 6.9716e9 --gamma0 8.49e-7 --v0 0.246 --gravity 9.8");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "m = 2.05e-3 kg, k = 6.9716e9 N/m^alpha, gamma0 = 8.49e-7, v0 = 0.246 m/s, "
                              "gravity = 9.8 m/s^2, force = 0 N"))
      << r.out;
}

}  // namespace
