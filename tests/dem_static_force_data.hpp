// Normal forces printed by the real programs for one bead at a set overlap and
// overlap rate, after `run 0` (forces of the initial configuration), as the
// reference for the conventions in include/viscor/dem/deck_convention.hpp.
// Measured 2026-12-01 on Debian 12 with
//   LAMMPS 29 Sep 2021 update 2 (package lammps 20220106.git7586adbb6a+ds1-2+b2)
//   LIGGGHTS-PUBLIC 3.8.0 (package liggghts 3.8.0+repack1-9+b2)
// Common setup, SI units: R = 1e-3 m, density 2500 kg/m^3, E = 1e8 Pa, nu = 0.3.
//   pair: atoms at x = 0 and x = 0.001998 (overlap 2R - 0.001998), velocities
//         +0.05 and -0.05 m/s (overlap rate 0.1 m/s); printed fx of atom 1 (= -F).
//     LAMMPS: pair_style granular; pair_coeff * * hertz/material 1e8 DAMP 0.3
//             damping MODEL tangential linear_nohistory 0 0
//     LIGGGHTS: pair_style gran model hertz tangential history, two types of the
//             same material, coefficientRestitution E_DECK; printed fz (axis z).
//   wall: atom at z = 0.000998 above the plane z = 0 (overlap R - 0.000998),
//         velocity -0.05 m/s; printed fz of the atom (= F).
//     LAMMPS: fix wall/gran granular hertz/material 1e8 DAMP 0.3 damping MODEL
//             tangential linear_nohistory 0 0 zplane 0 NULL
//     LIGGGHTS: fix wall/gran model hertz tangential history primitive type 2
//             zplane 0.0, wall type 2 with youngsModulus WALL_E, nu 0.3.
// Values printed with %.17g (LAMMPS: variable format; LIGGGHTS: thermo_modify).
#pragma once

#include <array>

namespace viscor::test {

struct static_force_case {
  const char* code;
  const char* damping;
  const char* contact;
  double deck_damping;  ///< damp (LAMMPS) or coefficientRestitution (LIGGGHTS)
  double wall_modulus;  ///< LIGGGHTS wall type's youngsModulus (0: not used)
  double force;         ///< |printed force|, N
};

inline constexpr std::array<static_force_case, 11> static_forces{{
    {"lammps", "velocity", "pair", 0.3, 0, 0.034633373861051982},
    {"lammps", "mass_velocity", "pair", 1e4, 0, 0.0098693616170349736},
    {"lammps", "viscoelastic", "pair", 3e8, 0, 0.0096006679939498255},
    {"lammps", "tsuji", "pair", 0.3, 0, 0.010866555316274475},
    {"lammps", "velocity", "wall", 0.3, 0, 0.023518354199999508},
    {"lammps", "mass_velocity", "wall", 1e4, 0, 0.013754341955982498},
    {"lammps", "viscoelastic", "wall", 3e8, 0, 0.015543168931040321},
    {"lammps", "tsuji", "wall", 0.3, 0, 0.014494538016737182},
    {"liggghts", "hertz", "pair", 0.5, 0, 0.0099394327931831127},
    {"liggghts", "hertz", "wall", 0.5, 1e8, 0.011014426088999916},
    {"liggghts", "hertz", "wall", 0.5, 1e30, 0.019415163342405797},
}};

}  // namespace viscor::test

namespace viscor::test {

// YADE 2023.02a (package yade 2023.02a-1), measured 2026-12-02 by
// tools/dem/static_force_yade.py (one O.step() at dt = 1e-12 s; see its header):
// same bead, overlap and positions as above; overlap rate > 0 approaching, and
// -0.5 m/s separating, where elastic + viscous force pulls and YADE prints 0.
struct yade_static_force_case {
  const char* law;      ///< "mindlin" (betan given, or en: Thornton's betan), "viscel" (kn, cn per material; wall
                        ///< of the bead's material), "viscel_rigid" (wall material kn = cn = 1e30) or
                        ///< "viscel_tc_en" (ViscElMat(tc = 1e-5 s, en, et = en) on both bodies)
  const char* contact;  ///< wall (utils.wall of a material with young 1e30, or as above) or pair
  double deck_damping;  ///< betan, en, or the per-material cn (N s/m; kn = 1e4 N/m)
  bool deck_is_en;      ///< mindlin with `en` instead of betan
  double overlap_rate;  ///< m/s
  double force;         ///< printed normal force, N
};

inline constexpr std::array<yade_static_force_case, 12> yade_static_forces{{
    {"mindlin", "wall", 0.3, false, 0.05, 0.017360126483443698},
    {"mindlin", "wall", 0.3, false, -0.05, 0.0011733689607672567},
    {"mindlin", "wall", 0.3, false, -0.5, 0},
    {"mindlin", "pair", 0.3, false, 0.1, 0.012726752622389984},
    {"mindlin", "wall", 0.5, true, 0.05, 0.015553275835568923},
    {"viscel", "wall", 0.2, false, 0.05, 0.015000000000000244},
    {"viscel", "wall", 0.2, false, -0.5, 0},
    {"viscel_rigid", "wall", 0.2, false, 0.05, 0.030000000000000488},
    {"viscel_rigid", "wall", 0.2, false, -0.5, 0},
    {"viscel_rigid", "pair", 0.2, false, 0.1, 0.019999999999999161},
    {"viscel_tc_en", "wall", 0.5, true, 0.05, 1.1201485794790966},
    {"viscel_tc_en", "pair", 0.5, true, 0.1, 1.156441680984039},
}};

}  // namespace viscor::test
