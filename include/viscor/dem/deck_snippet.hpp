// Ready-to-paste input lines for the deck values of dem_deck_for: the contact
// model lines, with every property the code requires declared (a tangential model
// needs its friction: frictionless placeholders here, a head-on impact does not
// feel them). The calibrated entries are those of the contact asked for (bead-wall,
// or bead and other bead); the entries of like beads, where the code reads them
// separately (LAMMPS pair_coeff 1 1 and 2 2, LIGGGHTS type pairs (1,1) and (2,2)),
// are calibrated for two such beads at the same e and approach speed without load
// and labelled so. Numbers are written as the shortest decimal that reads back as
// the same double (what the DEM code reads).
#pragma once

#include <viscor/dem/dem_model.hpp>
#include <viscor/dem/hertz_contact.hpp>

#include <charconv>
#include <optional>
#include <string>

namespace viscor::dem {

/// The deck values as the decimal strings written into the DEM input.
struct deck_strings {
  std::string youngs_modulus, poisson_ratio, damping;
  std::optional<std::string> wall_youngs_modulus;  ///< LIGGGHTS wall type, YADE wall material (1e30: rigid)
  std::optional<std::string> wall_poisson_ratio;   ///< LIGGGHTS wall type's, YADE wall material's own nu
  bool wall_material = false;  ///< the wall has a material of its own (not rigid)
  std::optional<std::string> other_youngs_modulus, other_poisson_ratio;  ///< the pair's other bead (type 2)
  std::optional<std::string> cross_youngs_modulus;  ///< LAMMPS, two bead types: the explicit pair_coeff 1 2 modulus
  std::string stiffness;  ///< YADE visco-elastic: the bead material's kn, N/m (damping: its cn, N s/m)
  /// The like-bead entries (1,1) a code reads apart: two beads, same e and v0, no load.
  std::optional<std::string> bead_bead_youngs_modulus, bead_bead_damping;
  std::optional<std::string> other_other_damping;  ///< the like-bead entry (2,2) of the other bead
};

/// `x` as the shortest decimal that reads back as the same double: a DEM code
/// reads doubles, and 0.35 stays 0.35 rather than 3.4999999999999998e-01.
template <class Real>
std::string deck_number(const Real& x) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, static_cast<double>(x));
  if (error != std::errc()) throw invalid_parameter("deck value does not fit a double: " + to_decimal_string(x));
  return std::string(buffer, end);
}

/// The comment line that says where a like-bead entry comes from.
inline constexpr const char* bead_bead_comment =
    "# like beads: calibrated for two such beads at the same e and approach speed, without load (viscor calibrates\n"
    "# the contact you measured; if like beads rebound differently, run viscor dem --contact pair with their e)\n";

namespace detail {

inline std::string lammps_snippet(const dem_model& model, contact_kind kind, const deck_strings& d) {
  const std::string tail = " damping " + std::string(model.damping_name) + " tangential linear_nohistory 0 0";
  auto entry = [&](const std::string& E, const std::string& damping, const std::string& nu) {
    return "hertz/material " + E + " " + damping + " " + nu + tail;
  };
  std::string s = "# tangential linear_nohistory 0 0: frictionless; put your own (a head-on impact does not feel it)\n";
  if (kind == contact_kind::wall) {
    s += d.wall_material ? "# bead-wall: a plane z = 0 of its own material; LAMMPS' wall has no material and reads "
                                "E_deck/(2(1-nu)): E_deck = 2(1-nu) E*, E* of bead and wall\n"
                              : "# bead-wall: a rigid plane z = 0 (LAMMPS' wall reads E_deck/(2(1-nu)): E_deck = 2E/(1+nu))\n";
    s += "fix wall all wall/gran granular " + entry(d.youngs_modulus, d.damping, d.poisson_ratio) + " zplane 0.0 NULL\n";
    if (d.bead_bead_damping) {
      s += bead_bead_comment;
      s += "pair_style granular\n";
      s += "pair_coeff * * " + entry(d.bead_bead_youngs_modulus.value_or(d.youngs_modulus), *d.bead_bead_damping,
                                     d.poisson_ratio) + "\n";
    }
    return s;
  }
  s += "pair_style granular\n";
  if (!d.other_youngs_modulus) return s + "pair_coeff * * " + entry(d.youngs_modulus, d.damping, d.poisson_ratio) + "\n";
  s += "# type 1: the bead, type 2: the other bead. (1,2) is the contact calibrated; LAMMPS 29 Sep 2021 mixes\n"
       "# hertz/material entries wrongly, so it is explicit: E_deck = 2(1-nu^2) E*, E* of the two materials\n";
  s += "pair_coeff 1 2 " + entry(d.cross_youngs_modulus.value_or(d.youngs_modulus), d.damping, d.poisson_ratio) + "\n";
  s += bead_bead_comment;
  s += "pair_coeff 1 1 " + entry(d.youngs_modulus, d.bead_bead_damping.value_or(d.damping), d.poisson_ratio) + "\n";
  s += "pair_coeff 2 2 " + entry(*d.other_youngs_modulus, d.other_other_damping.value_or(d.damping),
                                 d.other_poisson_ratio.value_or(d.poisson_ratio)) + "\n";
  return s;
}

inline std::string yade_snippet(const dem_model& model, contact_kind kind, const deck_strings& d) {
  // NOTE: NewtonIntegrator damps every body by 0.2 unless told otherwise: damping=0.
  const bool wall = kind == contact_kind::wall;
  const bool viscel = model.damping == damping_model::yade_viscoelastic;
  std::string s, ip2, law;
  if (viscel) {
    s += "# YADE 2023.02a, visco-elastic law: linear spring kn, dashpot cn (the total normal force is clamped at 0)\n";
    s += "# the contact takes 1/(1/x1 + 1/x2) of the two materials' kn and cn: " +
         std::string(wall ? "a 1e30 wall is rigid\n" : "two beads of this material, half of each\n");
    s += "bead = O.materials.append(ViscElMat(kn=" + d.stiffness + ", cn=" + d.damping +
         ", ks=0, cs=0, density=DENSITY, frictionAngle=0))\n";
    if (wall) {
      s += "# bead-wall only: two beads of this material would take half its kn and cn (viscor dem --contact pair)\n";
      s += "rigid = O.materials.append(ViscElMat(kn=" + d.wall_youngs_modulus.value_or(d.stiffness) + ", cn=" +
           d.wall_youngs_modulus.value_or(d.damping) + ", ks=0, cs=0, density=DENSITY, frictionAngle=0))\n";
    }
    ip2 = "Ip2_ViscElMat_ViscElMat_ViscElPhys()", law = "Law2_ScGeom_ViscElPhys_Basic()";
  } else {
    s += "# YADE 2023.02a, Hertz-Mindlin with viscous damping betan (the total normal force is clamped at 0)\n";
    s += "bead = O.materials.append(FrictMat(young=" + d.youngs_modulus + ", poisson=" + d.poisson_ratio +
         ", density=DENSITY, frictionAngle=0))\n";
    if (wall) {
      s += d.wall_material
               ? "# a wall of its own material; YADE takes R* = R/2 on a wall, hence young = sqrt(2) E for bead and\n"
                 "# wall: bead-wall only, two beads of these would be too stiff (for bead-bead run viscor dem --contact pair)\n"
               : "# rigid wall; YADE takes R* = R/2 on a wall, hence the bead's young = sqrt(2) E: bead-wall only,\n"
                 "# two beads of this material would be too stiff (for bead-bead run viscor dem --contact pair)\n";
      s += std::string(d.wall_material ? "plate" : "rigid") + " = O.materials.append(FrictMat(young=" +
           d.wall_youngs_modulus.value_or(d.youngs_modulus) + ", poisson=" +
           d.wall_poisson_ratio.value_or(d.poisson_ratio) + ", density=DENSITY, frictionAngle=0))\n";
    } else if (d.other_youngs_modulus) {
      s += "other = O.materials.append(FrictMat(young=" + *d.other_youngs_modulus + ", poisson=" +
           d.other_poisson_ratio.value_or(d.poisson_ratio) + ", density=OTHER_DENSITY, frictionAngle=0))\n";
    }
    ip2 = "Ip2_FrictMat_FrictMat_MindlinPhys(betan=" + d.damping + ")", law = "Law2_ScGeom_MindlinPhys_Mindlin()";
  }
  if (wall) {
    s += "O.bodies.append([utils.wall(0, axis=2, material=" + std::string(d.wall_material ? "plate" : "rigid") +
         "), utils.sphere((0, 0, RADIUS), RADIUS, material=bead)])\n";
    s += "O.bodies[1].state.vel = (0, 0, -V0)  # the impact speed\n";
  } else if (d.other_youngs_modulus) {
    s += "O.bodies.append([utils.sphere((0, 0, 0), RADIUS, material=bead), "
         "utils.sphere((0, 0, RADIUS + OTHER_RADIUS), OTHER_RADIUS, material=other)])\n";
    s += "O.bodies[0].state.vel, O.bodies[1].state.vel = (0, 0, V0 / 2), (0, 0, -V0 / 2)  # approaching at V0\n";
  } else {
    s += "O.bodies.append([utils.sphere((0, 0, 0), RADIUS, material=bead), "
         "utils.sphere((0, 0, 2 * RADIUS), RADIUS, material=bead)])\n";
    s += "O.bodies[0].state.vel, O.bodies[1].state.vel = (0, 0, V0 / 2), (0, 0, -V0 / 2)  # approaching at V0\n";
  }
  s += "O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()" +
       std::string(wall ? ", Bo1_Wall_Aabb()" : "") + "]),\n";
  s += "    InteractionLoop([" + std::string(wall ? "Ig2_Wall_Sphere_ScGeom()" : "Ig2_Sphere_Sphere_ScGeom()") +
       "], [" + ip2 + "], [" + law + "]),\n";
  s += "    NewtonIntegrator(damping=0, gravity=(0, 0, -GRAVITY))]\n";
  return s;
}

// LIGGGHTS: type 1 = the bead, type 2 = the wall or the other bead.
inline std::string liggghts_snippet(contact_kind kind, const deck_strings& d) {
  const bool wall = kind == contact_kind::wall;
  const std::string type2_modulus = wall ? d.wall_youngs_modulus.value_or(d.youngs_modulus)
                                         : d.other_youngs_modulus.value_or(d.youngs_modulus);
  const std::string type2_nu = (wall ? d.wall_poisson_ratio : d.other_poisson_ratio).value_or(d.poisson_ratio);
  std::string s = "hard_particles yes  # allows youngsModulus > 1e9 Pa in SI units\n";
  s += std::string(wall ? "# type 1: the bead, type 2: the wall" : "# type 1: the bead, type 2: the other bead") +
       " (LIGGGHTS combines the two types' Y and nu)\n";
  s += "fix m1 all property/global youngsModulus peratomtype " + d.youngs_modulus + " " + type2_modulus + "\n";
  s += "fix m2 all property/global poissonsRatio peratomtype " + d.poisson_ratio + " " + type2_nu + "\n";
  const std::string e = d.damping;
  const std::string e11 = d.bead_bead_damping.value_or(e);
  const std::string e22 = wall ? e : d.other_other_damping.value_or(e);
  if (wall || d.bead_bead_damping) {
    s += "# coefficientRestitution (i,j): (1,1) bead-bead = " + e11 + ", (1,2) = (2,1) " +
         (wall ? "bead-wall" : "bead-other bead") + " = " + e + ", (2,2) " + (wall ? "unused" : "= " + e22) + "\n";
    s += bead_bead_comment;
  }
  s += "fix m3 all property/global coefficientRestitution peratomtypepair 2 " + e11 + " " + e + " " + e + " " + e22 +
       "\n";
  s += "# tangential history needs coefficientFriction: frictionless here; put your own (a head-on impact does not feel it)\n";
  s += "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n";
  s += "pair_style gran model hertz tangential history\npair_coeff * *\n";
  if (wall) s += "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n";
  return s;
}

}  // namespace detail

/// A ready-to-paste input snippet of the model's code with the deck values `d`.
inline std::string deck_snippet(const dem_model& model, contact_kind kind, const deck_strings& d) {
  switch (model.code) {
    case dem_code::lammps: return detail::lammps_snippet(model, kind, d);
    case dem_code::yade: return detail::yade_snippet(model, kind, d);
    case dem_code::liggghts: return detail::liggghts_snippet(kind, d);
  }
  return {};
}

}  // namespace viscor::dem
