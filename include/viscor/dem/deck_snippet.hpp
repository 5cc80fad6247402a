// Ready-to-paste input lines for the deck values of dem_deck_for: the contact
// model lines, with every property the code requires declared (a tangential model
// needs its friction: frictionless placeholders here, a head-on impact does not
// feel them). On a wall the bead-wall entries are the calibrated ones; the
// bead-bead entries, where the code reads them separately (LAMMPS pair_coeff,
// LIGGGHTS type pair (1,1)), are calibrated for two beads at the same e and approach
// speed without load and labelled so.
#pragma once

#include <viscor/dem/dem_model.hpp>
#include <viscor/dem/hertz_contact.hpp>

#include <optional>
#include <string>

namespace viscor::dem {

/// The deck values as the exact decimal strings written into the DEM input.
struct deck_strings {
  std::string youngs_modulus, poisson_ratio, damping;
  std::optional<std::string> wall_youngs_modulus;  ///< LIGGGHTS wall type, YADE wall material
  std::string stiffness;  ///< YADE visco-elastic: the bead material's kn, N/m (damping: its cn, N s/m)
  /// A wall deck of LAMMPS or LIGGGHTS: the bead-bead entries (two beads, same e and v0, no load).
  std::optional<std::string> bead_bead_youngs_modulus, bead_bead_damping;
};

/// The comment line that says where a bead-bead entry comes from.
inline constexpr const char* bead_bead_comment =
    "# bead-bead: calibrated for two beads at the same e and approach speed, without load (viscor calibrates your\n"
    "# bead-wall measurement; if two beads rebound differently, run viscor dem --contact pair with their e)\n";

/// A ready-to-paste input snippet of the model's code with the deck values `d`.
inline std::string deck_snippet(const dem_model& model, contact_kind kind, const deck_strings& d) {
  const std::string damping_name(model.damping_name);
  std::string s;
  if (model.code == dem_code::lammps) {
    const std::string normal = "hertz/material " + d.youngs_modulus + " " + d.damping + " " + d.poisson_ratio +
                               " damping " + damping_name + " tangential linear_nohistory 0 0";
    if (kind == contact_kind::wall) {
      s += "# tangential linear_nohistory 0 0: frictionless; put your own (a head-on impact does not feel it)\n";
      s += "# bead-wall: a rigid plane z = 0 (LAMMPS' wall reads E_deck/(2(1-nu)): E_deck = 2E/(1+nu))\n";
      s += "fix wall all wall/gran granular " + normal + " zplane 0.0 NULL\n";
      if (d.bead_bead_damping) {
        s += bead_bead_comment;
        s += "pair_style granular\n";
        s += "pair_coeff * * hertz/material " + d.bead_bead_youngs_modulus.value_or(d.youngs_modulus) + " " +
             *d.bead_bead_damping + " " + d.poisson_ratio + " damping " + damping_name +
             " tangential linear_nohistory 0 0\n";
      }
    } else {
      s += "pair_style granular\n";
      s += "pair_coeff * * " + normal + "\n";
    }
    return s;
  }
  if (model.code == dem_code::yade) {
    // NOTE: NewtonIntegrator damps every body by 0.2 unless told otherwise: damping=0.
    const bool wall = kind == contact_kind::wall;
    const bool viscel = model.damping == damping_model::yade_viscoelastic;
    std::string ip2, law;
    if (viscel) {
      s += "# YADE 2023.02a, visco-elastic law: linear spring kn, dashpot cn (the total normal force is clamped at 0)\n";
      s += "# the contact takes 1/(1/x1 + 1/x2) of the two materials' kn and cn: " +
           std::string(wall ? "a 1e30 wall is rigid\n" : "two beads of this material, half of each\n");
      s += "bead = O.materials.append(ViscElMat(kn=" + d.stiffness + ", cn=" + d.damping +
           ", ks=0, cs=0, density=DENSITY, frictionAngle=0))\n";
      if (wall)
        s += "# bead-wall only: two beads of this material would take half its kn and cn (viscor dem --contact pair)\n";
      if (wall)
        s += "rigid = O.materials.append(ViscElMat(kn=" + d.wall_youngs_modulus.value_or(d.stiffness) + ", cn=" +
             d.wall_youngs_modulus.value_or(d.damping) + ", ks=0, cs=0, density=DENSITY, frictionAngle=0))\n";
      ip2 = "Ip2_ViscElMat_ViscElMat_ViscElPhys()", law = "Law2_ScGeom_ViscElPhys_Basic()";
    } else {
      s += "# YADE 2023.02a, Hertz-Mindlin with viscous damping betan (the total normal force is clamped at 0)\n";
      s += "bead = O.materials.append(FrictMat(young=" + d.youngs_modulus + ", poisson=" + d.poisson_ratio +
           ", density=DENSITY, frictionAngle=0))\n";
      if (wall) {
        s += "# rigid wall; YADE takes R* = R/2 on a wall, hence the bead's young = sqrt(2) E: bead-wall only,\n"
             "# two beads of this material would be too stiff (for bead-bead run viscor dem --contact pair)\n";
        s += "rigid = O.materials.append(FrictMat(young=" + d.wall_youngs_modulus.value_or(d.youngs_modulus) +
             ", poisson=" + d.poisson_ratio + ", density=DENSITY, frictionAngle=0))\n";
      }
      ip2 = "Ip2_FrictMat_FrictMat_MindlinPhys(betan=" + d.damping + ")", law = "Law2_ScGeom_MindlinPhys_Mindlin()";
    }
    if (wall) {
      s += "O.bodies.append([utils.wall(0, axis=2, material=rigid), utils.sphere((0, 0, RADIUS), RADIUS, material=bead)])\n";
      s += "O.bodies[1].state.vel = (0, 0, -V0)  # the impact speed\n";
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
  // LIGGGHTS: type 1 = beads, type 2 = wall.
  const bool wall = kind == contact_kind::wall;
  const std::string wall_modulus = wall ? d.wall_youngs_modulus.value_or(d.youngs_modulus) : d.youngs_modulus;
  s += "hard_particles yes  # allows youngsModulus > 1e9 Pa in SI units\n";
  s += "fix m1 all property/global youngsModulus peratomtype " + d.youngs_modulus + " " + wall_modulus + "\n";
  s += "fix m2 all property/global poissonsRatio peratomtype " + d.poisson_ratio + " " + d.poisson_ratio + "\n";
  const std::string e = d.damping;
  if (wall) {
    const std::string bead_bead = d.bead_bead_damping.value_or(e);
    s += "# coefficientRestitution (i,j): (1,1) bead-bead = " + bead_bead + ", (1,2) = (2,1) bead-wall = " + e +
         ", (2,2) unused\n";
    s += bead_bead_comment;
    s += "fix m3 all property/global coefficientRestitution peratomtypepair 2 " + bead_bead + " " + e + " " + e + " " +
         e + "\n";
    s += "# tangential history needs coefficientFriction: frictionless here; put your own (a head-on impact does not feel it)\n";
    s += "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n";
  } else {
    s += "fix m3 all property/global coefficientRestitution peratomtypepair 2 " + e + " " + e + " " + e + " " + e + "\n";
    s += "# tangential history needs coefficientFriction: frictionless here; put your own (a head-on impact does not feel it)\n";
    s += "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n";
  }
  s += "pair_style gran model hertz tangential history\npair_coeff * *\n";
  if (wall) s += "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n";
  return s;
}

}  // namespace viscor::dem
