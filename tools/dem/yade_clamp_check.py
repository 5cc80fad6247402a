# YADE 2023.02a: both normal-force laws clamp the total normal force at zero.
# yade -n -x yade_clamp_check.py  -> "Fz on b 0.0" when separating, > 0 when approaching.
# sphere (R=1e-3) overlapping a fixed sphere by 2e-6, separating at 0.05 m/s: is the force clamped at 0?
import sys
R=1e-3
for law in ['mindlin','viscel']:
    O.reset()
    if law=='mindlin':
        mat=O.materials.append(FrictMat(young=1e8,poisson=0.3,density=2500,frictionAngle=0))
        ip=Ip2_FrictMat_FrictMat_MindlinPhys(betan=0.9); lw=Law2_ScGeom_MindlinPhys_Mindlin()
    else:
        mat=O.materials.append(ViscElMat(kn=1e4,ks=0,cn=10.0,cs=0,density=2500,frictionAngle=0))
        ip=Ip2_ViscElMat_ViscElMat_ViscElPhys(); lw=Law2_ScGeom_ViscElPhys_Basic()
    a=O.bodies.append(sphere((0,0,0),R,material=mat,fixed=True))
    b=O.bodies.append(sphere((0,0,2*R-2e-6),R,material=mat))
    for sign in (-1, 1):
        O.bodies[b].state.pos=(0,0,2*R-2e-6); O.bodies[b].state.vel=(0,0,sign*0.05)
        O.interactions.clear()
        O.engines=[ForceResetter(),InsertionSortCollider([Bo1_Sphere_Aabb()]),InteractionLoop([Ig2_Sphere_Sphere_ScGeom()],[ip],[lw]),NewtonIntegrator(damping=0)]
        O.dt=1e-12
        O.step()
        i=O.interactions[a,b]
        print('LAW',law,'vel',sign*0.05,'Fz on b',O.forces.f(b)[2], 'normalForce', i.phys.normalForce[2] if i.isReal else None)
