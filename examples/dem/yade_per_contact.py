# Per-contact damping in YADE: beads of three materials and sizes hit the floor of a
# box at different speeds, and two beads collide head-on in mid-air, all with YADE's
# Hertz-Mindlin law, in one scene. Every new contact gets from viscor.yade's hook the
# betan calibrated for its own bodies, approach speed and load (gravity into the floor;
# none between the two beads), so each first impact rebounds with the target e, where
# one betan for all would give each its own e. Run with viscor's Python module on the
# path (build/python in a build tree):
#
#   PYTHONPATH=build/python yade -n -x examples/dem/yade_per_contact.py
#
# It prints each first impact's e (the speeds at zero overlap from the free-flight
# positions on either side of the contact) and the betan the hook gave it; docs/dem.md
# ("Per-contact damping").
import math
import sys

import viscor
from viscor.yade import per_contact_damping
from yade import utils

target_e = 0.8
gravity = (0.0, 0.0, -9.81)
# name: (young, poisson, density, radius, speed towards the floor), SI units
floor_beads = {"glass": (7e10, 0.22, 2500.0, 1e-3, 0.3),
               "steel": (2e11, 0.3, 7800.0, 1.5e-3, 0.6),
               "polymer": (3e9, 0.35, 1200.0, 2e-3, 0.02)}
pair_bead, pair_speed = (7e10, 0.22, 2500.0, 1e-3), 0.2  # two glass beads, each at this speed

# the step: T/400 of the quickest contact (viscor's recommended step for each)
steps = []
for young, poisson, density, radius, speed in floor_beads.values():
    steps.append(float(viscor.dem("yade", damping="mindlin", youngs_modulus=young, poisson_ratio=poisson,
                                  radius=radius, density=density, target_e=target_e, v0=speed,
                                  gravity=-gravity[2]).time_step_s))
young, poisson, density, radius = pair_bead
steps.append(float(viscor.dem("yade", damping="mindlin", contact="pair", youngs_modulus=young, poisson_ratio=poisson,
                              radius=radius, density=density, target_e=target_e, v0=2 * pair_speed,
                              gravity=0).time_step_s))
O.dt = min(steps)

rigid = O.materials.append(FrictMat(young=1e30, poisson=0.3, density=1000, frictionAngle=0))
O.bodies.append(utils.wall(0, axis=2, material=rigid))
ids = {}
x = 0.0
for name, (young, poisson, density, radius, speed) in floor_beads.items():
    mat = O.materials.append(FrictMat(young=young, poisson=poisson, density=density, frictionAngle=0))
    x += 0.01
    # 20 steps of free flight above the floor
    ids[name] = O.bodies.append(utils.sphere((x, 0, radius + 20 * speed * O.dt), radius, material=mat))
    O.bodies[ids[name]].state.vel = (0, 0, -speed)
mat = O.materials.append(FrictMat(young=young, poisson=poisson, density=density, frictionAngle=0))
gap = 20 * 2 * pair_speed * O.dt
left = O.bodies.append(utils.sphere((-0.02 - radius - gap / 2, 0, 0.02), radius, material=mat))
right = O.bodies.append(utils.sphere((-0.02 + radius + gap / 2, 0, 0.02), radius, material=mat))
O.bodies[left].state.vel = (pair_speed, 0, 0)
O.bodies[right].state.vel = (-pair_speed, 0, 0)

hook = per_contact_damping(target_e, gravity)
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                             [Ip2_FrictMat_FrictMat_MindlinPhys()], [Law2_ScGeom_MindlinPhys_Mindlin()]),
             PyRunner(command="hook()", iterPeriod=1),
             NewtonIntegrator(damping=0, gravity=gravity)]


def speed_at_zero_overlap(x0, x1, x2):
    """The speed where the overlap is zero, from three positions in free flight (constant
    acceleration: they lie on a parabola) next to the crossing."""
    a, b = (x2 - 2 * x1 + x0) / O.dt ** 2, (x2 - x0) / (2 * O.dt)
    return math.sqrt(b * b - 2 * a * x1)


# each floor bead's overlap with the floor, per step
overlaps = {name: [floor_beads[name][3] - O.bodies[i].state.pos[2]] for name, i in ids.items()}
results = {}
pair_before = O.bodies[left].state.vel[0] - O.bodies[right].state.vel[0]
pair_touched = False
for _ in range(2000000):
    O.step()
    for name, i in ids.items():
        if name in results:
            continue
        xs = overlaps[name]
        xs.append(floor_beads[name][3] - O.bodies[i].state.pos[2])
        entered = [k for k in range(1, len(xs)) if xs[k] > 0 and xs[k - 1] <= 0]
        if entered and xs[-1] <= 0 and xs[-2] > 0:  # out again: the first impact is over
            k = entered[0]
            v_in = speed_at_zero_overlap(xs[k - 3], xs[k - 2], xs[k - 1])
            v_out = speed_at_zero_overlap(xs[-3], xs[-2], xs[-1])
            results[name] = v_out / v_in
    touching = O.interactions.has(left, right) and O.interactions[left, right].isReal
    pair_touched = pair_touched or touching
    if pair_touched and not touching and "pair" not in results:
        # the relative speed along the line of centres is constant in free flight
        results["pair"] = -(O.bodies[left].state.vel[0] - O.bodies[right].state.vel[0]) / pair_before
    if len(results) == len(floor_beads) + 1:
        break
else:
    raise SystemExit("not every first impact ended within the steps allowed")

betan = {ids1: b for ids1, _, _, b in hook.calls}
one_betan = betan[(left, right)]  # what one betan for all (the pair's) would give each floor impact instead
for name in list(floor_beads) + ["pair"]:
    key = (0, ids[name]) if name != "pair" else (left, right)
    line = "first impact %s: e = %.9f (target %g), betan %.9g" % (name, results[name], target_e, betan[key])
    if name != "pair":
        young, poisson, density, radius, speed = floor_beads[name]
        with_one = viscor.dem("yade", damping="mindlin", youngs_modulus=young, poisson_ratio=poisson, radius=radius,
                              density=density, deck_damping=one_betan, v0=speed, speeds=[speed], gravity=-gravity[2])
        line += "; the pair's betan would give %.6f" % float(with_one.table[-1]["e"])
    print(line)
sys.stdout.flush()  # yade leaves without flushing a redirected output
