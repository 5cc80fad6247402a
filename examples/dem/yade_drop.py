# A YADE script that asks viscor for its damping while it is read: one bead of its own
# (radius, density, modulus), dropped on its own rigid wall under its own gravity,
# with Hertz-Mindlin's betan and the bead's deck modulus from viscor.dem() for a
# measured e (YADE's law clamps the force at zero; viscor.dem calibrates that law).
# Run with viscor's Python module on the path (build/python in a build tree):
#
#   PYTHONPATH=build/python yade -n -x examples/dem/yade_drop.py
#
# It drops the bead at viscor's recommended time step and at half of it and prints
# the rebound e at zero overlap for each; docs/dem.md ("Decks that ask viscor").
import sys

import viscor
from yade import utils

# the scene's own inputs (SI units)
R, density = 1e-3, 1200.0           # bead radius, m; density, kg/m^3
young, poisson = 3e9, 0.35          # the bead's Young's modulus, Pa, and Poisson ratio
v0, gravity = 0.01, 9.81            # impact speed, m/s; gravity towards the wall, m/s^2
target_e = 0.5                      # the measured coefficient of restitution

# viscor: the deck of YADE's Hertz-Mindlin law (its clamp included) for this bead and load
deck = viscor.dem("yade", damping="mindlin", youngs_modulus=young, poisson_ratio=poisson, radius=R,
                  density=density, target_e=target_e, v0=v0, gravity=gravity)
betan = float(deck.deck.damping)
bead_young = float(deck.deck.youngs_modulus)     # sqrt(2) E: YADE counts a wall with R* = R/2
wall_young = float(deck.deck.wall_youngs_modulus)  # a rigid wall material
time_step = float(deck.time_step_s)              # viscor's recommended step, T/400
contact_time = float(deck.contact_time_s)
print("viscor: betan = %s, bead young = %s, dt = %s s" % (deck.deck.damping, deck.deck.youngs_modulus,
                                                          deck.time_step_s))


def drop(dt):
    """One drop at time step dt: the rebound e at zero overlap."""
    O.reset()
    bead = O.materials.append(FrictMat(young=bead_young, poisson=poisson, density=density, frictionAngle=0))
    rigid = O.materials.append(FrictMat(young=wall_young, poisson=poisson, density=density, frictionAngle=0))
    O.bodies.append([utils.wall(0, axis=2, material=rigid), utils.sphere((0, 0, R), R, material=bead)])
    body = O.bodies[1]
    body.state.vel = (0, 0, -v0)
    # NewtonIntegrator damps every body by 0.2 unless told otherwise
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys(betan=betan)],
                                 [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 NewtonIntegrator(damping=0, gravity=(0, 0, -gravity))]
    O.dt = dt
    O.run(max(0, int(contact_time / dt) - 20), True)
    # step singly until the overlap is zero; once the clamp has let go the bead moves under
    # gravity alone, so its last three positions lie on a parabola: the speed at zero overlap is exact
    overlaps, forces = [R - body.state.pos[2]], []
    for _ in range(400):
        O.step()
        i = O.interactions[0, 1] if O.interactions.has(0, 1) else None
        forces.append(i.phys.normalForce.norm() if i is not None and i.isReal else 0.0)
        overlaps.append(R - body.state.pos[2])
        if overlaps[-1] <= 0 and len(overlaps) >= 3 and overlaps[-2] > 0:
            break
    else:
        raise SystemExit("no rebound within the steps allowed")
    if forces[-1] != 0 or forces[-2] != 0:
        print("warning: the contact force was not zero over the last steps; e carries a step error")
    x0, x1, x2 = overlaps[-3:]
    a, b = (x2 - 2 * x1 + x0) / dt ** 2, (x2 - x0) / (2 * dt)
    return (b * b - 2 * a * x1) ** 0.5 / v0


for divisor in (1, 2):
    print("rebound e = %.15g at dt = %.6g s (viscor's step / %d; target %g)"
          % (drop(time_step / divisor), time_step / divisor, divisor, target_e))
sys.stdout.flush()  # yade leaves without flushing a redirected output
