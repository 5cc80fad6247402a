# Single-bead drops on a rigid wall in YADE (Hertz-Mindlin or visco-elastic), several per
# run (yade starts slowly): VISCOR_YADE_CASES=cases.json yade -n -x tools/dem/yade_drop.py
# cases.json: a list of {"young", "poisson", "density", "radius", "betan", "v0",
# "gravity", "dt", "max_steps"} with the strings viscor dem prints ("en" instead of
# "betan": YADE's own conversion). With "law": "viscel" the visco-elastic law
# (ViscElMat, Law2_ScGeom_ViscElPhys_Basic): "kn", "cn" of the bead's material and
# "wall_kn", "wall_cn" of the wall's (ks = cs = 0), or "tc", "en" for both (YADE's
# own conversion, et = en). For each case
# prints "DROP i e ok force_free" where e is the rebound speed over v0 at zero
# overlap. After the force has dropped to zero (YADE's clamp) the bead flies
# under gravity alone, and velocity Verlet's positions lie exactly on that
# parabola, so the exit speed is exact from the last three positions once the
# force at the middle one is zero (force_free = 1; else the estimate has the
# step's error).
import json
import os
import sys

from yade import utils


def physics(c):
    if 'en' in c:  # YADE's own conversion (Thornton's fit) instead of betan
        return Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(algo='val', val=float(c['en'])))
    return Ip2_FrictMat_FrictMat_MindlinPhys(betan=float(c['betan']))


def viscel_materials(c):
    rho = float(c['density'])
    if 'tc' in c:  # YADE's own conversion: kn, cn from tc, en and the reduced mass
        tc, en = float(c['tc']), float(c['en'])
        return [ViscElMat(tc=tc, en=en, et=en, density=rho, frictionAngle=0) for _ in range(2)]
    return [ViscElMat(kn=float(c['kn']), cn=float(c['cn']), ks=0, cs=0, density=rho, frictionAngle=0),
            ViscElMat(kn=float(c['wall_kn']), cn=float(c['wall_cn']), ks=0, cs=0, density=rho, frictionAngle=0)]


def drop(c):
    O.reset()
    R = float(c['radius'])
    viscel = c.get('law') == 'viscel'
    if viscel:
        bead_mat, wall_mat = viscel_materials(c)
    else:
        bead_mat = FrictMat(young=float(c['young']), poisson=float(c['poisson']), density=float(c['density']),
                            frictionAngle=0)
        wall_mat = FrictMat(young=1e30, poisson=float(c['poisson']), density=float(c['density']), frictionAngle=0)
    bead = O.materials.append(bead_mat)
    rigid = O.materials.append(wall_mat)
    v0, g, dt = float(c['v0']), float(c['gravity']), float(c['dt'])
    pair = c.get('contact') == 'pair'
    if pair:  # two beads touching on the z axis, approaching at v0, pressed together by `force` each
        s = utils.sphere((0, 0, R), R, material=bead)
        low = utils.sphere((0, 0, -R), R, material=bead)
        O.bodies.append([low, s])
        s.state.vel, low.state.vel = (0, 0, -v0 / 2), (0, 0, v0 / 2)
        F = float(c.get('force', '0'))
        O.forces.setPermF(1, (0, 0, -F))
        O.forces.setPermF(0, (0, 0, F))
        g = 0.0  # uniform gravity drops out of the relative motion
    else:
        s = utils.sphere((0, 0, R), R, material=bead)
        O.bodies.append([utils.wall(0, axis=2, material=rigid), s])
        s.state.vel = (0, 0, -v0)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Wall_Sphere_ScGeom(), Ig2_Sphere_Sphere_ScGeom()],
                                 [Ip2_ViscElMat_ViscElMat_ViscElPhys() if viscel else physics(c)],
                                 [Law2_ScGeom_ViscElPhys_Basic() if viscel else Law2_ScGeom_MindlinPhys_Mindlin()]),
                 NewtonIntegrator(damping=0, gravity=(0, 0, -g))]
    O.dt = dt
    deltas, forces = [0.0], []
    for _ in range(int(c['max_steps'])):
        O.step()
        # the contact force at deltas[-1], computed in this step (without the permanent load)
        forces.append(O.interactions[0, 1].phys.normalForce.norm() if O.interactions.has(0, 1) and O.interactions[0, 1].isReal else 0.0)
        deltas.append(2 * R - (s.state.pos[2] - low.state.pos[2]) if pair else R - s.state.pos[2])
        if deltas[-1] <= 0 and len(deltas) > 3 and deltas[-2] > 0:
            x0, x1, x2 = deltas[-3], deltas[-2], deltas[-1]  # at t = -dt, 0, dt
            a = (x2 - 2 * x1 + x0) / (dt * dt)
            b = (x2 - x0) / (2 * dt)
            # root of x1 + b t + a t^2 / 2 = 0 in (0, dt], and the speed there
            disc = b * b - 2 * a * x1
            speed = disc ** 0.5
            return speed / v0, True, forces[-1] == 0 and forces[-2] == 0
    return 0.0, False, False


cases = json.load(open(os.environ['VISCOR_YADE_CASES']))
for i, c in enumerate(cases):
    e, ok, free = drop(c)
    print('DROP %d %.17g %d %d' % (i, e, int(ok), int(free)))
    sys.stdout.flush()
