// A complete single-bead drop for each DEM code, with the deck values of
// dem_deck_for: a LAMMPS or LIGGGHTS input, or a YADE Python script, that drops
// one bead on the rigid plane z = 0 at the calibrated impact and prints the
// rebound e at the end.
//
// The bead starts touching the plane (centre at z = R) moving down at v0, under
// the calibration's gravity and force. The time step is dt = T/400, T the time
// scale of the impact (eq. 2 of the report; the contact lasts about 3.2 T to
// 3.6 T): the rule the drop tests in the real programs use (docs/dem.md,
// "Validation"). YADE's visco-elastic law steps with T/2000: its dashpot reads the
// half-step velocity, a first-order error of about 0.1/n in e at dt = T/n
// (4e-4 at T/400 for e = 0.5). The deck runs the compression in blocks of steps until the
// bead moves back up, then the restitution one step at a time until the overlap is zero,
// with budgets of 50 times viscor's contact time: entries edited by hand (a before/after
// comparison) contact for longer or shorter than the calibrated ones and still report e:
//
// - LAMMPS and LIGGGHTS (velocity Verlet, unclamped force): from the last two
//   in-contact steps, fitting v = v_e + A delta^beta (near the end of contact the
//   damping dominates dv/d(delta)); plain interpolation carries an error that
//   depends on where in a step contact ends.
// - YADE (leapfrog, the force clamped at zero): after the clamp lets go the bead
//   moves under a constant force, so its positions lie on a parabola: the speed
//   at zero overlap is exact from the last three positions.
#pragma once

#include <viscor/core/real_io.hpp>
#include <viscor/dem/dem_calibration.hpp>
#include <viscor/dem/deck_snippet.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace viscor::dem {

/// Time steps per time scale T of the drop deck (docs/dem.md, "Validation").
inline constexpr int drop_steps_per_time_scale = 400;
/// YADE's visco-elastic law: its first-order stepping error needs a finer step for 1e-4 in e.
inline constexpr int viscoelastic_drop_steps_per_time_scale = 2000;

/// The steps per time scale T of the model's drop deck and recommended time step.
inline int drop_steps_per_time_scale_of(const dem_model& model) {
  return model.damping == damping_model::yade_viscoelastic ? viscoelastic_drop_steps_per_time_scale
                                                           : drop_steps_per_time_scale;
}

/// The first line of every drop deck viscor writes (the CLI overwrites only files that start with it).
inline constexpr const char* drop_deck_marker = "# viscor dem drop deck";

/// How long the contact lasts and the time step the drop deck uses, s.
template <class Real>
struct drop_timing {
  Real contact_time = 0;  ///< viscor's exact contact time at the calibrated deck
  Real time_scale = 0;    ///< T of eq. (2)
  int steps_per_time_scale = drop_steps_per_time_scale;
  Real time_step = 0;     ///< T / steps_per_time_scale
};

/// The contact time of the deck `d` at `impact` (the exact solve of the code's law) and the time step.
template <class Real>
drop_timing<Real> drop_timing_for(const dem_model& model, const dem_impact<Real>& impact, const dem_deck<Real>& d) {
  drop_timing<Real> t;
  t.time_scale = d.calibration.time_scale;
  // NOTE: a deck calibrated to a target e > 0 rebounds, so the time is known; were it
  // not, the deck's comment and the JSON would print nan.
  const std::optional<Real> scaled = e_for_deck(model, impact, d.damping).contact_time;
  t.contact_time = scaled ? Real(*scaled * t.time_scale) : std::numeric_limits<Real>::quiet_NaN();
  t.steps_per_time_scale = drop_steps_per_time_scale_of(model);
  t.time_step = t.time_scale / t.steps_per_time_scale;
  return t;
}

/// What a drop deck needs besides the deck entries: the impact as decimal strings
/// (as the user wrote them), the time step and how many steps run before stepping singly.
struct drop_deck_inputs {
  std::string radius, density, v0, gravity, force = "0";
  std::string diameter;        ///< 2 R, m (the codes take the bead's diameter)
  std::string box_half_width;  ///< the simulation box: |x|, |y| and -z up to this, m
  std::string box_top;         ///< the box's top, m
  std::string target_e;
  std::string time_step;      ///< s
  std::string steps_per_time_scale;  ///< n of dt = T/n, for the header
  std::string contact_time;   ///< s, for the header
  long block_steps = 1;       ///< the compression runs in blocks of these steps
  long max_blocks = 0;        ///< and gives up after these blocks
  long max_single_steps = 0;  ///< the restitution runs singly and gives up after these steps
};

/// How many contact times of viscor's the drop's loops allow before they say the bead sticks.
inline constexpr long drop_contact_time_budget = 50;

/// Fills the numbers the deck derives from the bead and the timing: the diameter, the
/// box, the time step, the compression's block (1/200 of the contact's steps) and the
/// budgets of both loops (50 contact times).
template <class Real>
void set_drop_geometry_and_steps(const Real& radius, const drop_timing<Real>& t, drop_deck_inputs& in) {
  using std::floor;
  in.diameter = to_decimal_string(Real(2 * radius));
  in.box_half_width = to_decimal_string(Real(4 * radius), 6);
  in.box_top = to_decimal_string(Real(8 * radius), 6);
  in.steps_per_time_scale = std::to_string(t.steps_per_time_scale);
  in.time_step = to_decimal_string(t.time_step);
  in.contact_time = to_decimal_string(t.contact_time, 6);
  const long contact_steps = static_cast<long>(floor(double(t.contact_time / t.time_step)));
  in.block_steps = contact_steps >= 400 ? contact_steps / 200 : 1;
  in.max_single_steps = drop_contact_time_budget * contact_steps + 100;
  in.max_blocks = in.max_single_steps / in.block_steps + 1;
}

/// The snippet's last line: the time step to use (YADE: the statement that sets it).
inline std::string snippet_time_step_line(const dem_model& model, const std::string& time_step,
                                          const std::string& contact_time, int steps_per_time_scale) {
  const std::string why = "T/" + std::to_string(steps_per_time_scale) + "; the contact lasts " + contact_time + " s";
  if (model.code == dem_code::yade) return "O.dt = " + time_step + "  # " + why + "\n";
  return "# time step: timestep " + time_step + " or smaller (" + why + ")\n";
}

namespace detail {

inline std::string drop_deck_header(const dem_model& model, const drop_deck_inputs& in, const char* run_with) {
  std::string s = std::string(drop_deck_marker) + ": " + std::string(model.version) + ", " +
                  std::string(model.code_name) + " damping " + std::string(model.damping_name) + "\n";
  s += "# one bead (radius " + in.radius + " m, density " + in.density + " kg/m^3) hits the rigid plane z = 0 at " +
       in.v0 + " m/s under gravity " + in.gravity + " m/s^2 and a force " + in.force + " N\n";
  s += "# target e = " + in.target_e + "; contact time " + in.contact_time + " s, time step " + in.time_step +
       " s (T/" + in.steps_per_time_scale + ")\n";
  s += "# run: " + std::string(run_with) + "\n";
  return s;
}

/// The box around the bead and the wall.
inline std::string box_region(const drop_deck_inputs& in) {
  const std::string w = in.box_half_width;
  return "-" + w + " " + w + " -" + w + " " + w + " -" + w + " " + in.box_top;
}

/// The LAMMPS/LIGGGHTS step-by-step search for the exit and the e it prints, shared by both inputs.
inline std::string lammps_exit_search(const dem_model& model, const drop_deck_inputs& in) {
  const std::string R = in.radius, beta = law_of(model).beta.to_string();
  std::string s;
  s += "variable z equal z[1]\nvariable vz equal vz[1]\n";
  s += "thermo_style custom step v_z v_vz\nthermo 1000000\n";
  s += "# the compression in blocks of steps until the bead moves up, then step by step until the overlap is\n"
       "# zero, keeping the last two in-contact steps (each loop allows " + std::to_string(drop_contact_time_budget) +
       " contact times)\n";
  s += "variable blocks loop " + std::to_string(in.max_blocks) + "\n";
  s += "label compression\n";
  s += "run " + std::to_string(in.block_steps) + " pre no post no\n";
  s += "if \"${vz} > 0\" then \"jump SELF restitution\"\n";
  s += "next blocks\njump SELF compression\n";
  s += "label restitution\n";
  s += "variable z1 equal ${z}\nvariable v1 equal ${vz}\nvariable z2 equal ${z}\nvariable v2 equal ${vz}\n";
  s += "variable single loop " + std::to_string(in.max_single_steps) + "\n";
  s += "label single_step\n";
  s += "variable z2 equal ${z1}\nvariable v2 equal ${v1}\nvariable z1 equal ${z}\nvariable v1 equal ${vz}\n";
  s += "run 1 pre no post no\n";
  s += "if \"${z} >= " + R + " && ${vz} > 0\" then \"jump SELF rebound\"\n";
  s += "next single\njump SELF single_step\n";
  s += "label rebound\n";
  s += "if \"${z} < " + R + "\" then \"print 'viscor: no rebound within " + std::to_string(drop_contact_time_budget) +
       " contact times: the bead sticks'\" \"jump SELF end\"\n";
  s += "if \"${z2} >= " + R + "\" then \"print 'viscor: the contact ended within one block of steps'\" \"jump SELF end\"\n";
  s += "# e from the last two in-contact steps, fitting v = v_e + A delta^beta (beta = " + beta + ")\n";
  s += "variable xa equal (" + R + "-v_z2)^(" + beta + ")\n";
  s += "variable xb equal (" + R + "-v_z1)^(" + beta + ")\n";
  s += "variable e equal (v_v1-(v_v2-v_v1)/(v_xa-v_xb)*v_xb)/" + in.v0 + "\n";
  s += "print \"rebound e = ${e} (target " + in.target_e + ")\"\nlabel end\n";
  return s;
}

inline std::string lammps_drop_deck(const dem_model& model, const deck_strings& d, const drop_deck_inputs& in) {
  const std::string R = in.radius;
  std::string s = drop_deck_header(model, in, "lmp -in FILE");
  s += "units si\natom_style sphere\natom_modify map array\nboundary f f f\ncomm_modify vel yes\n";
  s += "region box block " + box_region(in) + "\n";
  s += "create_box 1 box\n";
  s += "create_atoms 1 single 0 0 " + R + "\n";
  s += "set atom 1 diameter " + in.diameter + "\nset atom 1 density " + in.density + "\n";
  s += "velocity all set 0 0 -" + in.v0 + "\n";
  s += "pair_style none\nneighbor " + R + " bin\n";
  s += d.wall_material ? "# the bead-wall contact; E_deck = 2(1-nu) E* (E* of bead and wall) because this LAMMPS' "
                              "wall reads E_deck/(2(1-nu))\n"
                            : "# the bead-wall contact; E_deck = 2E/(1+nu) because this LAMMPS' wall reads E_deck/(2(1-nu))\n";
  s += "fix wall all wall/gran granular hertz/material " + d.youngs_modulus + " " + d.damping + " " + d.poisson_ratio +
       " damping " + std::string(model.damping_name) + " tangential linear_nohistory 0 0 zplane 0.0 NULL\n";
  s += "fix gravity all gravity " + in.gravity + " vector 0 0 -1\n";
  s += "fix press all addforce 0 0 -" + in.force + "\n";
  s += "fix integrate all nve/sphere\ntimestep " + in.time_step + "\n";
  return s + lammps_exit_search(model, in);
}

inline std::string liggghts_drop_deck(const dem_model& model, const deck_strings& d, const drop_deck_inputs& in) {
  const std::string R = in.radius, e = d.damping;
  std::string s = drop_deck_header(model, in, "liggghts -in FILE");
  s += "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\n";
  s += "units si\nhard_particles yes\n";
  s += "region box block " + box_region(in) + " units box\n";
  s += "create_box 2 box\nneighbor " + R + " bin\nneigh_modify delay 0\n";
  s += std::string("# type 1: the bead, type 2: the ") + (d.wall_material ? "wall's material\n" : "rigid wall\n");
  s += "fix m1 all property/global youngsModulus peratomtype " + d.youngs_modulus + " " +
       d.wall_youngs_modulus.value_or(d.youngs_modulus) + "\n";
  s += "fix m2 all property/global poissonsRatio peratomtype " + d.poisson_ratio + " " +
       d.wall_poisson_ratio.value_or(d.poisson_ratio) + "\n";
  s += "# only the bead-wall entries (1,2) and (2,1) act in this drop\n";
  s += "fix m3 all property/global coefficientRestitution peratomtypepair 2 " + e + " " + e + " " + e + " " + e + "\n";
  s += "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n";
  s += "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep " + in.time_step + "\n";
  s += "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n";
  s += "create_atoms 1 single 0 0 " + R + " units box\n";
  s += "set atom 1 diameter " + in.diameter + " density " + in.density + "\n";
  s += "velocity all set 0 0 -" + in.v0 + " units box\n";
  s += "fix gravity all gravity " + in.gravity + " vector 0 0 -1\n";
  s += "fix press all addforce 0 0 -" + in.force + "\n";
  s += "fix integrate all nve/sphere\n";
  return s + lammps_exit_search(model, in);
}

inline std::string yade_materials(const dem_model& model, const deck_strings& d, const drop_deck_inputs& in) {
  const std::string rho = in.density;
  if (model.damping == damping_model::yade_viscoelastic) {
    const std::string wall = d.wall_youngs_modulus.value_or(yade_rigid_wall_viscel);
    return "bead = O.materials.append(ViscElMat(kn=" + d.stiffness + ", cn=" + d.damping + ", ks=0, cs=0, density=" +
           rho + ", frictionAngle=0))\n" + "rigid = O.materials.append(ViscElMat(kn=" + wall + ", cn=" + wall +
           ", ks=0, cs=0, density=" + rho + ", frictionAngle=0))\n" +
           "physics, law = Ip2_ViscElMat_ViscElMat_ViscElPhys(), Law2_ScGeom_ViscElPhys_Basic()\n";
  }
  return std::string(d.wall_material ? "# YADE takes R* = R/2 on a wall, hence young = sqrt(2) E for the bead "
                                            "and for the wall's material\n"
                                          : "# YADE takes R* = R/2 on a wall, hence young = sqrt(2) E for the bead\n") +
         "bead = O.materials.append(FrictMat(young=" + d.youngs_modulus + ", poisson=" + d.poisson_ratio +
         ", density=" + rho + ", frictionAngle=0))\n" + "rigid = O.materials.append(FrictMat(young=" +
         d.wall_youngs_modulus.value_or(d.youngs_modulus) + ", poisson=" +
         d.wall_poisson_ratio.value_or(d.poisson_ratio) + ", density=" + rho +
         ", frictionAngle=0))\n" + "physics, law = Ip2_FrictMat_FrictMat_MindlinPhys(betan=" + d.damping +
         "), Law2_ScGeom_MindlinPhys_Mindlin()\n";
}

inline std::string yade_drop_script(const dem_model& model, const deck_strings& d, const drop_deck_inputs& in) {
  std::string s = drop_deck_header(model, in, "yade -n -x FILE");
  s += "import sys\nfrom yade import utils\n";
  s += "R, v0 = " + in.radius + ", " + in.v0 + "\n";
  s += yade_materials(model, d, in);
  s += "O.bodies.append([utils.wall(0, axis=2, material=rigid), utils.sphere((0, 0, R), R, material=bead)])\n";
  s += "bead_body = O.bodies[1]\nbead_body.state.vel = (0, 0, -v0)\n";
  s += "O.forces.setPermF(1, (0, 0, -" + in.force + "))\n";
  s += "# NewtonIntegrator damps every body by 0.2 unless told otherwise\n";
  s += "O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),\n"
       "              InteractionLoop([Ig2_Wall_Sphere_ScGeom()], [physics], [law]),\n"
       "              NewtonIntegrator(damping=0, gravity=(0, 0, -" + in.gravity + "))]\n";
  s += "O.dt = " + in.time_step + "\n";
  s += "# the compression in blocks of steps until the bead moves up, then step by step until the overlap is\n"
       "# zero (each loop allows " + std::to_string(drop_contact_time_budget) + " contact times); once the clamp "
       "has let go the bead moves under a\n"
       "# constant force, so the last three positions lie on a parabola: its speed at zero overlap is exact\n";
  s += "for _ in range(" + std::to_string(in.max_blocks) + "):\n"
       "    if bead_body.state.vel[2] > 0:\n"
       "        break\n"
       "    O.run(" + std::to_string(in.block_steps) + ", True)\n";
  s += "overlaps, forces = [R - bead_body.state.pos[2]], []\n";
  s += "for _ in range(" + std::to_string(in.max_single_steps) + "):\n"
       "    O.step()\n"
       "    i = O.interactions[0, 1] if O.interactions.has(0, 1) else None\n"
       "    forces.append(i.phys.normalForce.norm() if i is not None and i.isReal else 0.0)\n"
       "    overlaps.append(R - bead_body.state.pos[2])\n"
       "    if overlaps[-1] <= 0 and len(overlaps) >= 3 and overlaps[-2] > 0:\n"
       "        break\n"
       "else:\n"
       "    raise SystemExit('no rebound within " + std::to_string(drop_contact_time_budget) +
       " contact times: the bead sticks')\n"
       "if overlaps[0] <= 0:\n"
       "    raise SystemExit('the contact ended within one block of steps')\n";
  s += "x0, x1, x2 = overlaps[-3:]\n"
       "a, b = (x2 - 2 * x1 + x0) / O.dt ** 2, (x2 - x0) / (2 * O.dt)\n"
       "e = (b * b - 2 * a * x1) ** 0.5 / v0\n"
       "if forces[-1] != 0 or forces[-2] != 0:\n"
       "    print('warning: the contact force was not zero over the last steps; e carries a step error')\n"
       "print('rebound e = %.15g (target " + in.target_e + ")' % e)\n"
       "sys.stdout.flush()  # yade leaves without flushing a redirected output\n";
  return s;
}

}  // namespace detail

/// The complete drop deck of the model's code: a LAMMPS or LIGGGHTS input, or a YADE script.
inline std::string drop_deck(const dem_model& model, const deck_strings& d, const drop_deck_inputs& in) {
  switch (model.code) {
    case dem_code::lammps: return detail::lammps_drop_deck(model, d, in);
    case dem_code::liggghts: return detail::liggghts_drop_deck(model, d, in);
    case dem_code::yade: return detail::yade_drop_script(model, d, in);
  }
  return {};
}

}  // namespace viscor::dem
