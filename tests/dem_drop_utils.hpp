// Single-bead drops on a rigid wall in the real DEM programs (lmp, liggghts), run
// with the deck entries viscor dem computes. The bead starts touching the plane
// z = 0 (centre at z = R) moving down at v0, under gravity if asked. e is the
// upward speed at overlap zero over v0, from the last two in-contact steps by
// fitting v = v_e + A delta^beta (near the end of contact the damping term
// c delta^(beta-1) delta' dominates dv/d(delta), so v - v_e ~ delta^beta): this
// removes the in-step interpolation error that otherwise depends on where in a
// step contact ends.
#pragma once

#include <viscor/dem/dem_calibration.hpp>

#include <gtest/gtest.h>

#include "required_dependencies.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace viscor::test::dem_drop {

using namespace viscor::dem;

/// The program's path if it is on PATH.
inline std::optional<std::string> find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return std::nullopt;
}

inline const char* program_name(dem_code code) { return code == dem_code::lammps ? "lmp" : "liggghts"; }

/// Deck of a head-on collision of two identical beads (touching at the start,
/// approaching at v0, pressed together by F on each): prints the gap between
/// centres and the separation speed.
inline std::string pair_deck(const dem_model& model) {
  const std::string tail =
      "group a id 1\ngroup b id 2\nfix fa a addforce ${F} 0 0\nfix fb b addforce ${Fneg} 0 0\n"
      "fix i all nve/sphere\ntimestep ${dt}\nvariable gap equal x[2]-x[1]\nvariable vsep equal vx[2]-vx[1]\n"
      "thermo_style custom step v_gap v_vsep\nthermo_modify format float %.17g\nthermo 1\nrun ${n}\n";
  if (model.code == dem_code::lammps)
    return "units si\natom_style sphere\natom_modify map array\nboundary f f f\ncomm_modify vel yes\n"
           "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1\ncreate_box 1 box\n"
           "create_atoms 1 single ${xl} 0 0\ncreate_atoms 1 single ${R} 0 0\nset atom * diameter ${D}\n"
           "set atom * density ${rho}\nvelocity all set 0 0 0\nset atom 1 vx ${vhalf}\nset atom 2 vx ${vhalfneg}\n"
           "neighbor ${skin} bin\npair_style granular\npair_coeff * * hertz/material ${E} ${damp} ${nu} damping " +
           std::string(model.damping_name) + " tangential linear_nohistory 0 0\n" + tail;
  return "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\n"
         "units si\nhard_particles yes\nregion reg block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box\ncreate_box 1 reg\n"
         "neighbor ${skin} bin\nneigh_modify delay 0\n"
         "fix m1 all property/global youngsModulus peratomtype ${E}\n"
         "fix m2 all property/global poissonsRatio peratomtype ${nu}\n"
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 ${damp}\n"
         "fix m4 all property/global coefficientFriction peratomtypepair 1 0\n"
         "pair_style gran model hertz tangential history\npair_coeff * *\n"
         "create_atoms 1 single ${xl} 0 0 units box\ncreate_atoms 1 single ${R} 0 0 units box\n"
         "set atom * diameter ${D} density ${rho}\nset atom 1 vx ${vhalf}\nset atom 2 vx ${vhalfneg}\n" + tail;
}

/// Deck of a single drop; variables are passed with -var.
inline std::string drop_deck(const dem_model& model) {
  if (model.code == dem_code::lammps)
    return "units si\natom_style sphere\natom_modify map array\nboundary f f f\ncomm_modify vel yes\n"
           "region box block -0.1 0.1 -0.1 0.1 -0.1 0.1\ncreate_box 1 box\n"
           "create_atoms 1 single 0 0 ${R}\nset atom * diameter ${D}\nset atom * density ${rho}\n"
           "velocity all set 0 0 ${vdown}\npair_style none\n"
           "fix w all wall/gran granular hertz/material ${E} ${damp} ${nu} damping " +
           std::string(model.damping_name) +
           " tangential linear_nohistory 0 0 zplane 0 NULL\n"
           "fix g all gravity ${grav} vector 0 0 -1\nfix i all nve/sphere\ntimestep ${dt}\n"
           "variable z equal z[1]\nvariable vz equal vz[1]\n"
           "thermo_style custom step v_z v_vz\nthermo_modify format float %.17g\nthermo 1\nrun ${n}\n";
  return "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\n"
         "units si\nhard_particles yes\nregion reg block -0.1 0.1 -0.1 0.1 -0.1 0.1 units box\ncreate_box 2 reg\n"
         "neighbor ${skin} bin\nneigh_modify delay 0\n"
         "fix m1 all property/global youngsModulus peratomtype ${E} ${Ewall}\n"
         "fix m2 all property/global poissonsRatio peratomtype ${nu} ${nu}\n"
         "fix m3 all property/global coefficientRestitution peratomtypepair 2 ${damp} ${damp} ${damp} ${damp}\n"
         "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n"
         "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep ${dt}\n"
         "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n"
         "create_atoms 1 single 0 0 ${R} units box\nset atom 1 diameter ${D} density ${rho}\n"
         "velocity all set 0 0 ${vdown} units box\nfix grav all gravity ${grav} vector 0 0 -1\n"
         "fix integr all nve/sphere\nvariable z equal z[1]\nvariable vz equal vz[1]\n"
         "thermo_style custom step v_z v_vz\nthermo_modify format float %.17g\nthermo 1\nrun ${n}\n";
}

struct sample {
  double z, vz;
};

struct drop_result {
  bool ok = false;
  std::string message;  ///< why not ok
  double e = 0;
};

/// One drop: deck entries as decimal strings (exactly what a user pastes).
struct drop_setup {
  const dem_model* model = nullptr;
  contact_kind kind = contact_kind::wall;  ///< pair: two beads, gravity unused, force F presses them together
  std::string youngs_modulus, poisson_ratio, damping;
  double radius = 0, density = 0, v0 = 0, gravity = 0, force = 0;
  double dt = 0;
  long steps = 0;
};

inline std::string format_double(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

/// Runs `command` (its output on stdout), collecting the thermo lines "step z vz"
/// (step = 0, 1, 2, ...) as samples and the first 4000 characters of the rest as `log`;
/// returns the exit status.
inline int run_collecting_samples(const std::string& command, std::vector<sample>& samples, std::string& log) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> line{};
  while (std::fgets(line.data(), line.size(), pipe)) {
    long step = 0;
    double z = 0, vz = 0;
    char tail = 0;
    if (std::sscanf(line.data(), " %ld %lf %lf %c", &step, &z, &vz, &tail) == 3 && step == long(samples.size()))
      samples.push_back({z, vz});
    else if (log.size() < 4000)
      log += line.data();
  }
  return ::pclose(pipe);
}

/// The speed at the end of contact: the first sample back at `touch` (z >= touch,
/// moving up) ends contact; the last two in-contact samples are fitted to
/// v = v_e + A (touch - z)^beta. Empty if contact never ended.
inline std::optional<double> fitted_exit_speed(const std::vector<sample>& samples, double touch, double beta) {
  for (std::size_t i = 2; i < samples.size(); ++i) {
    if (samples[i - 1].z < touch && samples[i].z >= touch && samples[i].vz > 0) {
      const double xa = std::pow(touch - samples[i - 2].z, beta), xb = std::pow(touch - samples[i - 1].z, beta);
      const double slope = (samples[i - 2].vz - samples[i - 1].vz) / (xa - xb);
      return samples[i - 1].vz - slope * xb;
    }
  }
  return std::nullopt;
}

inline drop_result run_drop(const std::string& program, const drop_setup& s) {
  drop_result r;
  std::string dir_template = ::testing::TempDir() + "viscor_dem_dropXXXXXX";
  const char* dir = ::mkdtemp(dir_template.data());
  if (!dir) {
    r.message = "mkdtemp failed";
    return r;
  }
  const std::filesystem::path deck = std::filesystem::path(dir) / "in.drop";
  const bool pair = s.kind == contact_kind::pair;
  std::ofstream(deck) << (pair ? pair_deck(*s.model) : drop_deck(*s.model));
  std::string cmd = "cd '" + std::string(dir) + "' && '" + program + "' -echo none -log none -in in.drop";
  auto var = [&](const std::string& name, const std::string& value) { cmd += " -var " + name + " " + value; };
  var("E", s.youngs_modulus), var("nu", s.poisson_ratio), var("damp", s.damping);
  var("R", format_double(s.radius)), var("D", format_double(2 * s.radius)), var("rho", format_double(s.density));
  var("vdown", format_double(-s.v0)), var("grav", format_double(s.gravity)), var("dt", format_double(s.dt));
  var("n", std::to_string(s.steps)), var("skin", format_double(s.radius / 2)), var("Ewall", liggghts_rigid_wall_modulus);
  var("xl", format_double(-s.radius)), var("vhalf", format_double(s.v0 / 2)), var("vhalfneg", format_double(-s.v0 / 2));
  var("F", format_double(s.force)), var("Fneg", format_double(-s.force));
  cmd += " 2>&1";
  std::vector<sample> samples;
  std::string log;
  const int status = run_collecting_samples(cmd, samples, log);
  std::filesystem::remove_all(dir);
  if (status != 0) {
    r.message = program + " failed (status " + std::to_string(status) + "):\n" + log;
    return r;
  }
  // (z, vz) is (gap, separation speed) for a pair.
  const double touch = pair ? 2 * s.radius : s.radius;
  if (const auto v_exit = fitted_exit_speed(samples, touch, law_of(*s.model).beta.value<double>())) {
    r.e = *v_exit / s.v0;
    r.ok = true;
    return r;
  }
  r.message = "no rebound within " + std::to_string(samples.size()) + " samples; output:\n" + log;
  return r;
}

/// The bead materials of the drop tests (R = 1 mm).
struct material_case {
  const char* name;
  bead_material<double> bead;
  double target_e;
};

inline const std::array<material_case, 2>& drop_materials() {
  static const std::array<material_case, 2> m{{
      {"steel", {2e11, 0.3, 1e-3, 7800}, 0.8},
      {"polymer", {3e9, 0.35, 1e-3, 1200}, 0.5},
  }};
  return m;
}

/// Runs the drop at dt = T/n_per_T (T: viscor's time scale) with the deck of
/// viscor dem, returning e - target.
struct drop_check {
  drop_result coarse, fine;  ///< dt and dt/2
  double target = 0;
};

inline drop_check check_drop(const std::string& program, const dem_model& model, const material_case& m, double v0,
                             double gravity, int n_per_T, contact_kind kind = contact_kind::wall, double force = 0) {
  dem_impact<double> impact;
  impact.bead = m.bead, impact.kind = kind, impact.v0 = v0, impact.gravity = gravity, impact.force = force;
  const dem_deck<double> d = dem_deck_for(model, impact, m.target_e);
  drop_setup s;
  s.model = &model;
  s.kind = kind, s.force = force;
  s.youngs_modulus = to_decimal_string(d.youngs_modulus);
  s.poisson_ratio = to_decimal_string(d.poisson_ratio);
  s.damping = to_decimal_string(d.damping);
  s.radius = m.bead.radius, s.density = m.bead.density, s.v0 = v0, s.gravity = gravity;
  const double T = d.calibration.time_scale;
  // Contact lasts about 3.2-3.6 T for these e; run 6 T.
  drop_check c;
  c.target = m.target_e;
  s.dt = T / n_per_T, s.steps = 6L * n_per_T;
  c.coarse = run_drop(program, s);
  s.dt = T / (2 * n_per_T), s.steps = 12L * n_per_T;
  c.fine = run_drop(program, s);
  return c;
}

/// The agreement stated in docs/dem.md ("Expected agreement", LAMMPS and LIGGGHTS):
/// |e - target| <= 2.5e-4 at dt = T/400 for every (model, material, v0, gravity) of
/// the sweep (velocity Verlet with the damping force taken at the half-step velocity:
/// first order in dt).
inline constexpr double tolerance_at_T_over_400 = 2.5e-4;

inline void expect_drop_reproduces_target(const std::string& program, const dem_model& model, const material_case& m,
                                          double v0, double gravity, contact_kind kind = contact_kind::wall,
                                          double force = 0) {
  SCOPED_TRACE(std::string(model.code_name) + " " + std::string(model.damping_name) + " " + m.name + " " +
               std::string(to_string(kind)) + " v0 = " + format_double(v0) + " gravity = " + format_double(gravity) +
               " force = " + format_double(force));
  const drop_check c = check_drop(program, model, m, v0, gravity, 400, kind, force);
  ASSERT_TRUE(c.coarse.ok) << c.coarse.message;
  ASSERT_TRUE(c.fine.ok) << c.fine.message;
  const double miss = c.coarse.e - c.target, miss_fine = c.fine.e - c.target;
  EXPECT_LE(std::abs(miss), tolerance_at_T_over_400) << "e = " << c.coarse.e << " at dt = T/400";
  EXPECT_LT(std::abs(miss_fine), std::abs(miss)) << "halving dt did not shrink the miss: " << miss << " -> " << miss_fine;
}

}  // namespace viscor::test::dem_drop
