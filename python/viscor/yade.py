"""Per-contact damping for YADE's Hertz-Mindlin law (docs/dem.md, "Per-contact damping").

YADE gives every contact the damping ratio betan of its Ip2 functor, one number for all.
``per_contact_damping`` returns a function for a ``PyRunner`` that gives each new
bead-bead and bead-wall contact the betan ``viscor.dem("yade", damping="mindlin", ...)``
calibrates for its own two bodies (masses, radii, materials), its approach speed when it
starts and the load along its normal (gravity's component into a wall; none between two
beads, where uniform gravity drops out), and the stiffness of the physical contact
(YADE counts a wall with R* = R/2, so a wall contact's kno is scaled by sqrt(2); a
bead-bead kno is already right). Put it right after the InteractionLoop::

    from viscor.yade import per_contact_damping
    hook = per_contact_damping(target_e=0.8, gravity=(0, 0, -9.81))
    O.engines = [ForceResetter(), InsertionSortCollider([...]),
                 InteractionLoop([...], [Ip2_FrictMat_FrictMat_MindlinPhys()],
                                 [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 PyRunner(command="hook()", iterPeriod=1),
                 NewtonIntegrator(damping=0, gravity=(0, 0, -9.81))]

The bodies' materials are FrictMat (young, poisson, density: the physical ones, not
the sqrt(2) E of a single-contact deck); walls are ``utils.wall`` bodies (a rigid wall
material: young 1e30). The first step of each contact still runs with the Ip2's own
betan and kno (the PyRunner sees a contact once YADE has made it): measured 2e-5 in e
with the Ip2's betan near the contacts' values, up to 8e-5 with betan = 0, at dt = T/400.
"""
import math

from ._commands import dem

# A wall material at least this stiff is rigid for viscor (deck_convention.hpp: 1e30).
_RIGID = 1e29


def _is_wall(body):
    return type(body.shape).__name__ == "Wall"


def _wall_normal(wall, bead):
    """The unit normal of an axis-aligned YADE wall, pointing towards the bead."""
    axis = wall.shape.axis
    n = [0.0, 0.0, 0.0]
    n[axis] = 1.0 if bead.state.pos[axis] >= wall.state.pos[axis] else -1.0
    return n


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def per_contact_damping(target_e, gravity):
    """A function for a PyRunner (every step, right after the InteractionLoop) that sets
    betan and kno of each new Hertz-Mindlin contact for target_e (a number, or a function
    of the two bodies giving one) under `gravity` (the NewtonIntegrator's vector, m/s^2).
    ``calls`` on the returned function lists (ids, approach speed, load, betan) per contact."""
    from yade import Omega  # only inside YADE

    O = Omega()

    seen = set()
    calls = []

    def material(body):
        m = body.material
        return m.young, m.poisson, m.density

    def hook():
        for i in O.interactions:
            if not i.isReal or (i.id1, i.id2) in seen:
                continue
            seen.add((i.id1, i.id2))
            b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
            e = target_e(b1, b2) if callable(target_e) else target_e
            if _is_wall(b1) or _is_wall(b2):
                wall, bead = (b1, b2) if _is_wall(b1) else (b2, b1)
                n = _wall_normal(wall, bead)  # from the wall to the bead
                v0 = -_dot(bead.state.vel, n)
                load = -_dot(gravity, n)  # gravity's push into the wall
                young, poisson, density = material(bead)
                options = dict(contact="wall", youngs_modulus=young, poisson_ratio=poisson,
                               radius=bead.shape.radius, density=density)
                wall_young, wall_poisson, _ = material(wall)
                if wall_young < _RIGID:
                    options.update(wall_youngs_modulus=wall_young, wall_poisson_ratio=wall_poisson)
                kno_factor = math.sqrt(2.0)  # YADE: R* = R/2 on a wall
            else:
                d = [y - x for x, y in zip(b1.state.pos, b2.state.pos)]
                n = [x / math.sqrt(_dot(d, d)) for x in d]  # from bead 1 to bead 2
                v0 = _dot([x - y for x, y in zip(b1.state.vel, b2.state.vel)], n)
                load = 0.0  # uniform gravity moves both beads alike
                young, poisson, density = material(b1)
                o_young, o_poisson, o_density = material(b2)
                options = dict(contact="pair", youngs_modulus=young, poisson_ratio=poisson,
                               radius=b1.shape.radius, density=density, other_youngs_modulus=o_young,
                               other_poisson_ratio=o_poisson, other_radius=b2.shape.radius,
                               other_density=o_density)
                kno_factor = 1.0
            if not v0 > 0:
                continue  # a contact that does not close (a resting or grazing one) keeps the Ip2's values
            # a load away from the wall (a ceiling) is a pulling force on the bead
            bead_mass = 4.0 / 3.0 * math.pi * options["radius"] ** 3 * options["density"]
            loads = dict(gravity=load, force=0.0) if load >= 0 else dict(gravity=0.0, force=load * bead_mass)
            deck = dem("yade", damping="mindlin", target_e=e, v0=v0, **loads, **options)
            i.phys.betan = float(deck.deck.damping)
            i.phys.kno = i.phys.kno * kno_factor
            calls.append(((i.id1, i.id2), v0, load, i.phys.betan))

    hook.calls = calls
    return hook
