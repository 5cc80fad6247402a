# Normal forces of YADE 2023.02a for one bead at a set overlap and overlap rate
# (tests/dem_static_force_data.hpp, yade_static_forces): one O.step() with
# dt = 1e-12 s computes the forces of the initial configuration.
#   yade -n -x tools/dem/static_force_yade.py
# Bead: R = 1e-3 m, density 2500 kg/m^3, E = 1e8 Pa, nu = 0.3.
#   wall: utils.wall(0, axis=2) of a material with young WALL_E, bead at z = R - 2e-6
#         (overlap 1e-3 - 0.000998 in double), velocity -RATE along z; printed fz of the bead.
#   pair: beads at x = 0 and x = 0.001998, velocities +RATE/2 and -RATE/2; printed -fx of bead 0.
# Overlap rate RATE > 0 approaching; RATE = -0.5 m/s separating fast enough to clamp.
from yade import utils

R, E, NU, RHO = 1e-3, 1e8, 0.3, 2500.0


def force(contact, law, ip, mat, rate, wall_e=1e30, wall_mat=None):
    O.reset()
    bead = O.materials.append(mat)
    if contact == 'wall':
        if wall_mat:
            wm = O.materials.append(wall_mat)
        else:
            wm = O.materials.append(FrictMat(young=wall_e, poisson=NU, density=RHO, frictionAngle=0)) if wall_e else bead
        s = utils.sphere((0, 0, 0.000998), R, material=bead)
        O.bodies.append([utils.wall(0, axis=2, material=wm), s])
        s.state.vel = (0, 0, -rate)
        geoms, bounds = [Ig2_Wall_Sphere_ScGeom()], [Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]
    else:
        a = utils.sphere((0, 0, 0), R, material=bead)
        b = utils.sphere((0.001998, 0, 0), R, material=bead)
        O.bodies.append([a, b])
        a.state.vel, b.state.vel = (rate / 2, 0, 0), (-rate / 2, 0, 0)
        geoms, bounds = [Ig2_Sphere_Sphere_ScGeom()], [Bo1_Sphere_Aabb()]
    O.engines = [ForceResetter(), InsertionSortCollider(bounds), InteractionLoop(geoms, [ip], [law]),
                 NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
    O.dt = 1e-12
    O.step()
    return O.forces.f(1)[2] if contact == 'wall' else -O.forces.f(0)[0]


frict = FrictMat(young=E, poisson=NU, density=RHO, frictionAngle=0)
mindlin = Law2_ScGeom_MindlinPhys_Mindlin
for contact, rate in (('wall', 0.05), ('wall', -0.05), ('wall', -0.5), ('pair', 0.1)):
    f = force(contact, mindlin(), Ip2_FrictMat_FrictMat_MindlinPhys(betan=0.3), frict, rate)
    print('YADE mindlin betan %s 0.3 %r %.17g' % (contact, rate, f))
f = force('wall', mindlin(), Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(algo='val', val=0.5)), frict, 0.05)
print('YADE mindlin en wall 0.5 0.05 %.17g' % f)
# Visco-elastic law, per-material kn = 1e4 N/m, cn = 0.2 N s/m on bead and wall alike
# (the pair takes half of each: 1 / (1/kn1 + 1/kn2)).
visc = ViscElMat(kn=1e4, cn=0.2, ks=0, cs=0, density=RHO, frictionAngle=0)
for rate in (0.05, -0.5):
    f = force('wall', Law2_ScGeom_ViscElPhys_Basic(), Ip2_ViscElMat_ViscElMat_ViscElPhys(), visc, rate, wall_e=None)
    print('YADE viscel kn_cn wall 0.2 %r %.17g' % (rate, f))
# Visco-elastic law on a rigid wall (its material kn = cn = 1e30 N/m, N s/m), and a pair of
# beads (half of each material value), as viscor dem yade --damping viscoelastic writes them.
rigid = ViscElMat(kn=1e30, cn=1e30, ks=0, cs=0, density=RHO, frictionAngle=0)
for contact, rate in (('wall', 0.05), ('wall', -0.5), ('pair', 0.1)):
    f = force(contact, Law2_ScGeom_ViscElPhys_Basic(), Ip2_ViscElMat_ViscElMat_ViscElPhys(), visc, rate, wall_mat=rigid)
    print('YADE viscel_rigid kn_cn %s 0.2 %r %.17g' % (contact, rate, f))
# YADE's own conversion: ViscElMat(tc=1e-5 s, en=0.5, et=0.5) on bead and wall alike.
def tcen():  # a fresh material each time: one instance appended twice confuses YADE's material ids
    return ViscElMat(tc=1e-5, en=0.5, et=0.5, density=RHO, frictionAngle=0)


for contact, rate in (('wall', 0.05), ('pair', 0.1)):
    f = force(contact, Law2_ScGeom_ViscElPhys_Basic(), Ip2_ViscElMat_ViscElMat_ViscElPhys(), tcen(), rate,
              wall_mat=tcen())
    print('YADE viscel_tc_en en %s 0.5 %r %.17g' % (contact, rate, f))
