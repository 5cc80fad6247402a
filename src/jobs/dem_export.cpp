// The C text of each DEM code's entries (jobs/dem_export.hpp). The C restates, for
// double, these steps of the library, each in the same order of operations:
//   the contact      dem/hertz_contact.hpp make_hertz_contact, core/elastic_contact.hpp
//   the calibration  dem/surrogate_deck.hpp (the surrogate's inverse at the scaled load)
//   the conventions  dem/deck_convention.hpp damping_scale, deck_youngs_modulus, ...,
//                    dem/builtin_conversions.hpp (LAMMPS's polynomial and its inverse,
//                    LIGGGHTS's b(e)), dem/deck_entries.hpp (the like-bead entries)
//   the time step    dem/stepped_drop.hpp (velocity Verlet, the decks' reading of e, the
//                    bisection on gamma0)
// tests/dem_export_test.cpp compiles the export with cc and compares every entry with
// `viscor dem --method surrogate` bit for bit, so a convention changed on one side only
// fails there. YADE's two laws clamp the force at zero, which the surrogates (of the
// unclamped force) do not describe: Hertz-Mindlin has entries at a time step only (the
// stepped calibration needs just a bracket, the unclamped surrogate's), the visco-elastic
// law none.
#include <viscor/jobs/dem_export.hpp>

namespace viscor::jobs {

namespace {

constexpr const char* declarations = R"(
/* ---- DEM codes' deck entries (docs/dem.md, "Vendoring the C export") ---- */

/* A DEM code's damping model, as `viscor dem CODE --damping MODEL` names it. */
typedef enum viscor_dem_model {
    VISCOR_LAMMPS_VELOCITY = 0,      /* lammps hertz/material, damping velocity (deck: damp) */
    VISCOR_LAMMPS_MASS_VELOCITY = 1, /* lammps hertz/material, damping mass_velocity (deck: damp) */
    VISCOR_LAMMPS_VISCOELASTIC = 2,  /* lammps hertz/material, damping viscoelastic (deck: damp) */
    VISCOR_LAMMPS_TSUJI = 3,         /* lammps hertz/material, damping tsuji (deck: an e) */
    VISCOR_LIGGGHTS_HERTZ = 4,       /* liggghts model hertz (deck: coefficientRestitution) */
    VISCOR_YADE_MINDLIN = 5          /* yade Hertz-Mindlin (deck: betan; the force clamped at zero): at a time step only */
} viscor_dem_model;

/* A bead's material and size, SI. */
typedef struct viscor_bead {
    double youngs_modulus; /* Pa */
    double poisson_ratio;  /* in (-1, 0.5] */
    double radius;         /* m */
    double density;        /* kg/m^3 */
} viscor_bead;

/* One impact as the code sees it. */
typedef struct viscor_dem_impact {
    viscor_bead bead;
    int pair;           /* 0: the bead hits a wall; 1: a second bead */
    int wall_material;  /* wall: 0 rigid; 1 of wall_youngs_modulus (Pa), wall_poisson_ratio */
    double wall_youngs_modulus, wall_poisson_ratio;
    int other_material; /* pair: 0 a bead like the first; 1 the bead `other` */
    viscor_bead other;
    double v0;      /* impact (approach) speed, m/s, > 0 */
    double gravity; /* m/s^2 towards the wall, >= 0 (drops out of a pair) */
    double force;   /* N pressing the bead on the wall (or the pair together) */
} viscor_dem_impact;

/* Why a deck has no entries. */
typedef enum viscor_deck_status {
    VISCOR_DECK_OK = 0,
    VISCOR_DECK_INVALID_INPUT = 1, /* an input out of its range (as viscor dem refuses it) */
    VISCOR_DECK_UNREACHABLE = 2,   /* no entry of the model gives e_target at this impact */
    VISCOR_DECK_NO_SURROGATE = 3,  /* the model's law is not in this export */
    VISCOR_DECK_NEEDS_TIME_STEP = 4 /* YADE clamps the force, which the surrogates do not describe:
                                       its entries come from the stepped drop (viscor_dem_deck_at_step) */
} viscor_deck_status;

/* The numbers the code's input takes, as `viscor dem CODE --damping MODEL --method
   surrogate` prints them (the same doubles); NaN for an entry the code does not read. */
typedef struct viscor_deck {
    viscor_deck_status status;   /* the rest is NaN unless VISCOR_DECK_OK */
    double damping;              /* the deck's damping entry: a coefficient, or an e (tsuji, hertz) */
    double damping_number;       /* D, what the code multiplies its damping force by */
    double gamma0;               /* viscor's damping of F = k x^alpha + gamma0 k d/dt(x^beta) */
    double youngs_modulus;       /* the bead type's deck modulus (LAMMPS's wall reads it scaled) */
    double poisson_ratio;
    double wall_youngs_modulus;  /* LIGGGHTS's wall type (1e30: rigid) */
    double wall_poisson_ratio;   /* the wall's material, when it has one */
    double other_youngs_modulus, other_poisson_ratio; /* a pair's second bead type */
    double cross_youngs_modulus; /* LAMMPS, two bead types: the explicit pair_coeff 1 2 modulus */
    double bead_bead_youngs_modulus, bead_bead_damping; /* the like-bead entries (1,1) a code reads apart */
    double other_other_damping;  /* the second type's like-bead entry (2,2) */
    double builtin_e;            /* tsuji, hertz: the e the code's own conversion gives for e_target */
} viscor_deck;

/* The contact viscor sees in this impact (no model: the bead, its wall or second bead,
   v0 > 0, gravity >= 0 and a finite force checked): the reduced mass and the Hertz
   stiffness k = (4/3) E* sqrt(R*) that `viscor cor` and `viscor calibrate` take from the
   same materials, and the gravity the relative motion feels (0 for a pair: both beads
   fall alike). valid is 0, the rest NaN, for invalid inputs. */
typedef struct viscor_contact {
    int valid;
    double effective_modulus, effective_radius; /* E* (Pa), R* (m) */
    double mass, stiffness;                     /* m* (kg), k (N/m^1.5) */
    double gravity;                             /* m/s^2 */
} viscor_contact;
viscor_contact viscor_contact_of(const viscor_dem_impact* impact);

/* The deck entries that give e_target (0.01 <= e_target < 1) at this impact, the
   calibration by the surrogate's inverse at the impact's scaled load (YADE: status
   VISCOR_DECK_NEEDS_TIME_STEP). */
viscor_deck viscor_dem_deck(viscor_dem_model model, double e_target, const viscor_dem_impact* impact);
/* The deck entries that give e_target when the code steps the drop with dt (s), as
   LAMMPS's and LIGGGHTS's fix nve/sphere do (velocity Verlet) or YADE's NewtonIntegrator
   (leapfrog, the force clamped at zero), the e read as the drop deck reads it: `viscor dem
   ... --method surrogate --timestep dt` (docs/dem.md, "The e at the code's time step");
   builtin_e also at that step. A few ms: for a deck, not a step. */
viscor_deck viscor_dem_deck_at_step(viscor_dem_model model, double e_target, const viscor_dem_impact* impact,
                                    double dt);
/* The e of a deck damping entry in the drop stepped with dt (NaN for invalid inputs). */
double viscor_dem_stepped_e(viscor_dem_model model, double deck_damping, const viscor_dem_impact* impact, double dt);
/* The damping entry alone (NaN where viscor_dem_deck has no entries). */
double viscor_dem_damping_entry(viscor_dem_model model, double e_target, const viscor_dem_impact* impact);
/* The e a deck damping entry gives at this impact (NaN for an invalid entry or impact, and
   for YADE, whose clamped force only viscor_dem_stepped_e describes). */
double viscor_dem_e_for_entry(viscor_dem_model model, double deck_damping, const viscor_dem_impact* impact);
)";

constexpr const char* definitions = R"(
/* ---- DEM codes' deck entries: dem/deck_convention.hpp and friends, in the same order ---- */

static const double viscor_dk_pi = 3.141592653589793116; /* boost::math::constants::pi<double>() */

static int viscor_dk_finite(double x) { return x == x && x - x == 0; }

static int viscor_dk_valid_bead(const viscor_bead* b) {
    return viscor_dk_finite(b->youngs_modulus) && b->youngs_modulus > 0 && viscor_dk_finite(b->poisson_ratio) &&
           b->poisson_ratio > -1 && b->poisson_ratio <= 0.5 && viscor_dk_finite(b->radius) && b->radius > 0 &&
           viscor_dk_finite(b->density) && b->density > 0;
}

static double viscor_dk_mass(const viscor_bead* b) {
    return 4 * viscor_dk_pi * b->radius * b->radius * b->radius * b->density / 3;
}

static int viscor_dk_representable(double x) { return viscor_dk_finite(x) && x >= DBL_MIN; }

static int viscor_dk_valid_wall(const viscor_dem_impact* in) {
    const double nu = in->wall_poisson_ratio;
    return viscor_dk_finite(in->wall_youngs_modulus) && in->wall_youngs_modulus > 0 && viscor_dk_finite(nu) &&
           nu > -1 && nu <= 0.5;
}

/* dem/hertz_contact.hpp hertz_contact: E*, R*, m*, k. */
typedef struct viscor_dk_contact {
    double effective_modulus, effective_radius, effective_mass, stiffness;
} viscor_dk_contact;

static int viscor_dk_make_contact(const viscor_dem_impact* in, viscor_dk_contact* c) {
    const viscor_bead* b = &in->bead;
    const double mass = viscor_dk_mass(b);
    if (!viscor_dk_valid_bead(b)) return 0;
    if (!in->pair && in->wall_material) {
        const double nu = in->wall_poisson_ratio;
        double compliance;
        if (!viscor_dk_valid_wall(in)) return 0;
        compliance = (1 - b->poisson_ratio * b->poisson_ratio) / b->youngs_modulus;
        compliance += (1 - nu * nu) / in->wall_youngs_modulus;
        c->effective_modulus = 1 / compliance;
        c->effective_radius = b->radius;
        c->effective_mass = mass;
    } else if (in->pair && in->other_material) {
        const viscor_bead* o = &in->other;
        const double other_mass = viscor_dk_mass(o);
        double compliance;
        if (!viscor_dk_valid_bead(o)) return 0;
        compliance = (1 - b->poisson_ratio * b->poisson_ratio) / b->youngs_modulus;
        compliance += (1 - o->poisson_ratio * o->poisson_ratio) / o->youngs_modulus;
        c->effective_modulus = 1 / compliance;
        c->effective_radius = b->radius * o->radius / (b->radius + o->radius);
        c->effective_mass = mass * other_mass / (mass + other_mass);
    } else { /* a rigid wall or a bead like this one */
        const double plane_strain_modulus = b->youngs_modulus / (1 - b->poisson_ratio * b->poisson_ratio);
        c->effective_modulus = in->pair ? plane_strain_modulus / 2 : plane_strain_modulus;
        c->effective_radius = in->pair ? b->radius / 2 : b->radius;
        c->effective_mass = in->pair ? mass / 2 : mass;
    }
    c->stiffness = 4 * c->effective_modulus * sqrt(c->effective_radius) / 3;
    return viscor_dk_representable(c->effective_mass) && viscor_dk_representable(c->effective_radius) &&
           viscor_dk_representable(c->stiffness);
}

static const char* viscor_dk_law(viscor_dem_model model) {
    switch (model) {
    case VISCOR_LAMMPS_VELOCITY: case VISCOR_LAMMPS_MASS_VELOCITY: return "hertz_linear_damping";
    case VISCOR_LAMMPS_VISCOELASTIC: return "kuwabara_kono";
    case VISCOR_LAMMPS_TSUJI: case VISCOR_LIGGGHTS_HERTZ: case VISCOR_YADE_MINDLIN: return "tsuji";
    }
    return 0;
}

/* deck_convention.hpp damping_scale: gamma0 per unit damping number D. */
static double viscor_dk_damping_scale(viscor_dem_model model, const viscor_dk_contact* c) {
    const double k = c->stiffness, m = c->effective_mass;
    switch (model) {
    case VISCOR_LAMMPS_VELOCITY: return 1 / k;
    case VISCOR_LAMMPS_MASS_VELOCITY: return m / k;
    case VISCOR_LAMMPS_VISCOELASTIC: return 2 * m * sqrt(c->effective_radius) / (3 * k);
    case VISCOR_LAMMPS_TSUJI: return 4 * sqrt(m * k) / (5 * k);
    case VISCOR_LIGGGHTS_HERTZ: return 4 * sqrt(5.0) * sqrt(m * k) / (5 * k);
    case VISCOR_YADE_MINDLIN: return 4 * sqrt(6.0) * sqrt(m * k) / (5 * k);
    }
    return NAN;
}

/* builtin_conversions.hpp lammps_tsuji_damping: LAMMPS's polynomial eta'(e). */
static double viscor_dk_tsuji_damping(double e) {
    double p = 4.8218;
    p = p * e - 18.022;
    p = p * e + 27.467;
    p = p * e - 22.348;
    p = p * e + 11.087;
    p = p * e - 4.2783;
    p = p * e + 1.2728;
    return p;
}

/* builtin_conversions.hpp lammps_tsuji_deck_e: bisection to neighbouring doubles. */
static double viscor_dk_tsuji_deck_e(double damping) {
    double lo = 0, hi = 1;
    int i;
    if (!(damping >= viscor_dk_tsuji_damping(1) && damping <= viscor_dk_tsuji_damping(0))) return NAN;
    for (i = 0; i < 4 * DBL_MANT_DIG + 1100; ++i) {
        const double mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        if (viscor_dk_tsuji_damping(mid) >= damping)
            lo = mid;
        else
            hi = mid;
    }
    return fabs(viscor_dk_tsuji_damping(hi) - damping) < fabs(viscor_dk_tsuji_damping(lo) - damping) ? hi : lo;
}

/* builtin_conversions.hpp liggghts_damping_ratio |b(e)| and liggghts_deck_e. */
static double viscor_dk_liggghts_ratio(double e) {
    const double l = log(e);
    return -l / sqrt(l * l + viscor_dk_pi * viscor_dk_pi);
}

static double viscor_dk_liggghts_deck_e(double b) {
    if (!(b >= 0 && b < 1)) return NAN;
    return exp(-viscor_dk_pi * b / sqrt(1 - b * b));
}

/* deck_convention.hpp damping_number and deck_damping_for. */
static double viscor_dk_damping_number(viscor_dem_model model, double entry) {
    if (model == VISCOR_LAMMPS_TSUJI) return viscor_dk_tsuji_damping(entry);
    if (model == VISCOR_LIGGGHTS_HERTZ) return viscor_dk_liggghts_ratio(entry);
    return entry;
}

static double viscor_dk_deck_damping_for(viscor_dem_model model, double damping) {
    if (model == VISCOR_LAMMPS_TSUJI) return viscor_dk_tsuji_deck_e(damping);
    if (model == VISCOR_LIGGGHTS_HERTZ) return viscor_dk_liggghts_deck_e(damping);
    return damping;
}

static int viscor_dk_is_lammps(viscor_dem_model model) { return model <= VISCOR_LAMMPS_TSUJI; }

/* builtin_conversions.hpp yade_thornton_betan: the betan YADE's `en` gives (Thornton et al.'s fit). */
static double viscor_dk_thornton_betan(double e) {
    static const double h[] = {-6.918798, -16.41105, 146.8049, -796.4559, 2928.711,
                               -7206.864, 11494.29,  -11342.18, 6276.757, -1489.915};
    double a = h[9];
    int i;
    if (e == 1) return 0;
    for (i = 8; i >= 0; --i) a = a * e + h[i];
    a *= e;
    return sqrt(1 / (1 - (1 + e) * (1 + e) * exp(a)) - 1);
}

static int viscor_dk_valid_impact(viscor_dem_model model, const viscor_dem_impact* in) {
    return in && (int)model >= 0 && (int)model <= 5 && viscor_dk_finite(in->v0) && in->v0 > 0 &&
           viscor_dk_finite(in->gravity) && in->gravity >= 0 && viscor_dk_finite(in->force);
}

/* physical_inputs.hpp acting_gravity: both beads of a pair fall alike. */
static double viscor_dk_acting_gravity(const viscor_dem_impact* in) { return in->pair ? 0.0 : in->gravity; }

/* The contact, its surrogate, m, k and the load felt. */
typedef struct viscor_dk_setup {
    viscor_dk_contact c;
    const viscor_surrogate* s;
    double gravity;
} viscor_dk_setup;

static viscor_deck_status viscor_dk_set_up(viscor_dem_model model, const viscor_dem_impact* in, viscor_dk_setup* u) {
    if (!viscor_dk_valid_impact(model, in) || !viscor_dk_make_contact(in, &u->c)) return VISCOR_DECK_INVALID_INPUT;
    u->s = viscor_surrogate_named(viscor_dk_law(model));
    if (!u->s) return VISCOR_DECK_NO_SURROGATE;
    u->gravity = viscor_dk_acting_gravity(in);
    return VISCOR_DECK_OK;
}

/* The e of a deck damping entry at this impact (dem_calibration.hpp e_for_deck, by the surrogate). */
static double viscor_dk_e_for_entry(viscor_dem_model model, const viscor_dk_setup* u, const viscor_dem_impact* in,
                                    double entry) {
    const double gamma0 = viscor_dk_damping_number(model, entry) * viscor_dk_damping_scale(model, &u->c);
    return viscor_cor_physical(u->s, u->c.effective_mass, u->c.stiffness, gamma0, in->v0, u->gravity, in->force).e;
}

static viscor_deck viscor_dk_no_deck(viscor_deck_status status) {
    viscor_deck d;
    d.status = status;
    d.damping = d.damping_number = d.gamma0 = d.youngs_modulus = d.poisson_ratio = NAN;
    d.wall_youngs_modulus = d.wall_poisson_ratio = d.other_youngs_modulus = d.other_poisson_ratio = NAN;
    d.cross_youngs_modulus = d.bead_bead_youngs_modulus = d.bead_bead_damping = d.other_other_damping = NAN;
    d.builtin_e = NAN;
    return d;
}

/* deck_convention.hpp validate_deck_damping: a coefficient >= 0, an e in [0, 1] (LIGGGHTS: (0, 1]). */
static int viscor_dk_valid_entry(viscor_dem_model model, double entry) {
    if (!viscor_dk_finite(entry)) return 0;
    if (model == VISCOR_LAMMPS_TSUJI) return entry >= 0 && entry <= 1;
    if (model == VISCOR_LIGGGHTS_HERTZ) return entry > 0 && entry <= 1;
    return entry >= 0;
}

/* ---- the drop as LAMMPS, LIGGGHTS and YADE step it (dem/stepped_drop.hpp) ---- */

typedef struct viscor_dk_force_law {
    double m, k, gamma0, alpha, beta, load, v0;
    int yade; /* YADE: leapfrog, the force clamped at zero, no force at zero overlap */
} viscor_dk_force_law;

static viscor_dk_force_law viscor_dk_force_law_of(viscor_dem_model model, const viscor_dk_setup* u,
                                                  const viscor_dem_impact* in, double gamma0) {
    viscor_dk_force_law l;
    l.yade = model == VISCOR_YADE_MINDLIN;
    l.m = u->c.effective_mass, l.k = u->c.stiffness, l.gamma0 = gamma0;
    l.alpha = u->s->alpha, l.beta = u->s->beta;
    l.load = u->gravity + in->force / l.m;
    l.v0 = in->v0;
    return l;
}

/* overlap_acceleration: the load minus F/m; LAMMPS's wall counts a contact from zero overlap
   on, YADE's Law2 drops it and clamps the force at zero */
static double viscor_dk_acceleration(const viscor_dk_force_law* l, double x, double u) {
    double force;
    if (!(x > 0) && !(!l->yade && x == 0)) return l->load;
    force = l->k * pow(x, l->alpha) + l->gamma0 * l->k * l->beta * pow(x, l->beta - 1) * u;
    if (l->yade && force < 0) force = 0;
    return l->load - force / l->m;
}

/* leapfrog_drop: YADE's leapfrog from zero overlap at v0; e from the parabola through the
   last three positions. */
static int viscor_dk_leapfrog_drop(const viscor_dk_force_law* l, double dt, long max_steps, double* e) {
    double x = 0, u = l->v0, x0 = 0, x1 = 0;
    long n;
    for (n = 0; n < max_steps; ++n) {
        u += dt * viscor_dk_acceleration(l, x, u);
        x0 = x1, x1 = x;
        x += dt * u;
        if (x > 0) continue;
        if (n < 2 || !(x1 > 0)) continue;
        {
            const double a = (x - 2 * x1 + x0) / (dt * dt), b = (x - x0) / (2 * dt);
            *e = sqrt(b * b - 2 * a * x1) / l->v0;
            return 1;
        }
    }
    return 0;
}

/* verlet_drop: velocity Verlet from zero overlap at v0; 1 and *e (the deck's fit of the last
   two in-contact steps) on a rebound, 0 if none within max_steps. */
static int viscor_dk_verlet_drop(const viscor_dk_force_law* l, double dt, long max_steps, double* e) {
    double x = 0, u = l->v0, a, x1 = 0, u1, x2 = 0, u2;
    long n;
    a = viscor_dk_acceleration(l, x, u);
    u1 = u, u2 = u;
    for (n = 0; n < max_steps; ++n) {
        x2 = x1, u2 = u1, x1 = x, u1 = u;
        u += dt / 2 * a;
        x += dt * u;
        a = viscor_dk_acceleration(l, x, u);
        u += dt / 2 * a;
        if (x > 0) continue;
        if (!(u < 0) || !(x1 > 0) || !(x2 > 0)) continue;
        {
            const double xa = pow(x2, l->beta), xb = pow(x1, l->beta);
            *e = (-u1 - (u1 - u2) / (xa - xb) * xb) / l->v0;
            return 1;
        }
    }
    return 0;
}

static int viscor_dk_verlet_drop(const viscor_dk_force_law* l, double dt, long max_steps, double* e);

/* step_drop: the code's own update. */
static int viscor_dk_step_drop(const viscor_dk_force_law* l, double dt, long max_steps, double* e) {
    return l->yade ? viscor_dk_leapfrog_drop(l, dt, max_steps, e) : viscor_dk_verlet_drop(l, dt, max_steps, e);
}

/* stepped_drop_steps: 50 times 20 T */
static long viscor_dk_max_steps(const viscor_dk_setup* u, const viscor_dem_impact* in, double dt) {
    return (long)(1000.0 * viscor_time_scale(u->s, u->c.effective_mass, u->c.stiffness, in->v0) / dt) + 100;
}

/* The stepped e at damping gamma0 minus the target (0 for no rebound). */
static double viscor_dk_stepped_miss(const viscor_dk_force_law* l, double gamma0, double target, double dt, long steps) {
    viscor_dk_force_law at = *l;
    double e = 0;
    at.gamma0 = gamma0;
    if (!viscor_dk_step_drop(&at, dt, steps, &e)) e = 0;
    return e - target;
}

/* calibrate_at_time_step: bisection from [0, 2 gamma0 of the continuous calibration]; NaN if unreachable. */
static double viscor_dk_calibrate_at_step(const viscor_dk_force_law* l, double continuous_gamma0, double target, double dt,
                                          long steps) {
    double lo = 0, hi = 2 * continuous_gamma0, lo_e, hi_e;
    int i;
    if (!(viscor_dk_stepped_miss(l, lo, target, dt, steps) > 0)) return NAN;
    for (i = 0; viscor_dk_stepped_miss(l, hi, target, dt, steps) > 0; ++i) {
        if (i == 60 || !(hi > 0)) return NAN;
        lo = hi, hi *= 2;
    }
    for (i = 0; i < 4 * DBL_MANT_DIG + 1100; ++i) {
        const double mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        if (viscor_dk_stepped_miss(l, mid, target, dt, steps) > 0)
            lo = mid;
        else
            hi = mid;
    }
    lo_e = viscor_dk_stepped_miss(l, lo, target, dt, steps), hi_e = viscor_dk_stepped_miss(l, hi, target, dt, steps);
    return fabs(hi_e) < fabs(lo_e) ? hi : lo;
}

/* stepped_e_for_deck: the stepped e of a deck damping entry. */
static double viscor_dk_stepped_e_for_entry(viscor_dem_model model, const viscor_dk_setup* u,
                                            const viscor_dem_impact* in, double entry, double dt) {
    const double gamma0 = viscor_dk_damping_number(model, entry) * viscor_dk_damping_scale(model, &u->c);
    const viscor_dk_force_law l = viscor_dk_force_law_of(model, u, in, gamma0);
    double e = 0;
    if (!viscor_dk_step_drop(&l, dt, viscor_dk_max_steps(u, in, dt), &e)) e = 0;
    return e;
}

/* The contact's own deck (dem_calibration.hpp dem_deck_for and complete_deck), without
   the like-bead entries; dt > 0: for the drop stepped with dt (dem_deck_at_time_step). */
static viscor_deck viscor_dk_deck(viscor_dem_model model, double e_target, const viscor_dem_impact* in, double dt) {
    viscor_dk_setup u;
    viscor_deck d = viscor_dk_no_deck(VISCOR_DECK_OK);
    const viscor_deck_status status = viscor_dk_set_up(model, in, &u);
    double g;
    if (status != VISCOR_DECK_OK) return viscor_dk_no_deck(status);
    if (!(e_target >= 0.01 && e_target < 1)) return viscor_dk_no_deck(VISCOR_DECK_INVALID_INPUT);
    if (model == VISCOR_YADE_MINDLIN && !(dt > 0)) return viscor_dk_no_deck(VISCOR_DECK_NEEDS_TIME_STEP);
    g = viscor_scaled_g(u.s, u.c.effective_mass, u.c.stiffness, in->v0, u.gravity, in->force);
    if (!(g >= u.s->g_min && g <= u.s->g_max)) return viscor_dk_no_deck(VISCOR_DECK_UNREACHABLE);
    d.gamma0 = viscor_gamma_for(u.s, e_target, g) /
               viscor_damping_scale(u.s, u.c.effective_mass, u.c.stiffness, in->v0);
    if (d.gamma0 != d.gamma0) return viscor_dk_no_deck(VISCOR_DECK_UNREACHABLE);
    if (dt > 0) {
        const viscor_dk_force_law l = viscor_dk_force_law_of(model, &u, in, 0.0);
        d.gamma0 = viscor_dk_calibrate_at_step(&l, d.gamma0, e_target, dt, viscor_dk_max_steps(&u, in, dt));
        if (d.gamma0 != d.gamma0) return viscor_dk_no_deck(VISCOR_DECK_UNREACHABLE);
    }
    d.damping_number = d.gamma0 / viscor_dk_damping_scale(model, &u.c);
    d.damping = viscor_dk_deck_damping_for(model, d.damping_number);
    if (d.damping != d.damping) return viscor_dk_no_deck(VISCOR_DECK_UNREACHABLE);
    /* deck_convention.hpp deck_youngs_modulus; LAMMPS's wall reads only its own entry, YADE
       takes R* = R/2 on a wall (both moduli scaled by sqrt(2)) */
    if (!in->pair && viscor_dk_is_lammps(model))
        d.youngs_modulus = in->wall_material ? 2 * (1 - in->bead.poisson_ratio) * u.c.effective_modulus
                                             : 2 * in->bead.youngs_modulus / (1 + in->bead.poisson_ratio);
    else if (!in->pair && model == VISCOR_YADE_MINDLIN)
        d.youngs_modulus = sqrt(2.0) * in->bead.youngs_modulus;
    else
        d.youngs_modulus = in->bead.youngs_modulus;
    d.poisson_ratio = in->bead.poisson_ratio;
    if (!viscor_dk_is_lammps(model) && !in->pair) { /* wall_deck_modulus: the wall type's or material's own */
        d.wall_youngs_modulus = !in->wall_material              ? 1e30
                                : model == VISCOR_YADE_MINDLIN ? sqrt(2.0) * in->wall_youngs_modulus
                                                               : in->wall_youngs_modulus;
        if (in->wall_material) d.wall_poisson_ratio = in->wall_poisson_ratio;
    }
    if (in->pair && in->other_material) {
        d.other_youngs_modulus = in->other.youngs_modulus;
        d.other_poisson_ratio = in->other.poisson_ratio;
        if (viscor_dk_is_lammps(model)) /* lammps_cross_modulus */
            d.cross_youngs_modulus = 2 * (1 - d.poisson_ratio * d.poisson_ratio) * u.c.effective_modulus;
    }
    if (model == VISCOR_LAMMPS_TSUJI || model == VISCOR_LIGGGHTS_HERTZ)
        d.builtin_e = dt > 0 ? viscor_dk_stepped_e_for_entry(model, &u, in, e_target, dt)
                             : viscor_dk_e_for_entry(model, &u, in, e_target);
    if (model == VISCOR_YADE_MINDLIN) /* the deck's `en` instead of betan, at the step */
        d.builtin_e = viscor_dk_stepped_e_for_entry(model, &u, in, viscor_dk_thornton_betan(e_target), dt);
    return d;
}

/* deck_entries.hpp like_beads_impact: two beads like `bead`, the same speed, no load. */
static viscor_dem_impact viscor_dk_like_beads(const viscor_dem_impact* in, const viscor_bead* bead) {
    viscor_dem_impact pair = *in;
    pair.bead = *bead;
    pair.pair = 1, pair.wall_material = 0, pair.other_material = 0;
    pair.gravity = 0, pair.force = 0;
    return pair;
}

/* The deck with its like-bead entries (deck_entries.hpp), continuous or at step dt. */
static viscor_deck viscor_dk_full_deck(viscor_dem_model model, double e_target, const viscor_dem_impact* impact,
                                       double dt) {
    viscor_deck d = viscor_dk_deck(model, e_target, impact, dt);
    if (d.status != VISCOR_DECK_OK) return d;
    if (model != VISCOR_YADE_MINDLIN && (!impact->pair || impact->other_material)) {
        /* deck_entries.hpp: the like-bead entries LAMMPS and LIGGGHTS read apart */
        const viscor_dem_impact like = viscor_dk_like_beads(impact, &impact->bead);
        const viscor_deck b = viscor_dk_deck(model, e_target, &like, dt);
        if (b.status != VISCOR_DECK_OK) return viscor_dk_no_deck(b.status);
        if (!impact->pair) d.bead_bead_youngs_modulus = b.youngs_modulus;
        d.bead_bead_damping = b.damping;
        if (impact->pair) {
            const viscor_dem_impact other = viscor_dk_like_beads(impact, &impact->other);
            const viscor_deck o = viscor_dk_deck(model, e_target, &other, dt);
            if (o.status != VISCOR_DECK_OK) return viscor_dk_no_deck(o.status);
            d.other_other_damping = o.damping;
        }
    }
    return d;
}

viscor_contact viscor_contact_of(const viscor_dem_impact* impact) {
    viscor_contact out;
    viscor_dk_contact c;
    if (!viscor_dk_valid_impact(VISCOR_LAMMPS_VELOCITY, impact) || !viscor_dk_make_contact(impact, &c)) {
        out.valid = 0;
        out.effective_modulus = out.effective_radius = out.mass = out.stiffness = out.gravity = NAN;
        return out;
    }
    out.valid = 1;
    out.effective_modulus = c.effective_modulus, out.effective_radius = c.effective_radius;
    out.mass = c.effective_mass, out.stiffness = c.stiffness;
    out.gravity = viscor_dk_acting_gravity(impact);
    return out;
}

viscor_deck viscor_dem_deck(viscor_dem_model model, double e_target, const viscor_dem_impact* impact) {
    return viscor_dk_full_deck(model, e_target, impact, 0.0);
}

viscor_deck viscor_dem_deck_at_step(viscor_dem_model model, double e_target, const viscor_dem_impact* impact,
                                    double dt) {
    if (!(dt > 0 && dt <= DBL_MAX)) return viscor_dk_no_deck(VISCOR_DECK_INVALID_INPUT);
    return viscor_dk_full_deck(model, e_target, impact, dt);
}

double viscor_dem_stepped_e(viscor_dem_model model, double deck_damping, const viscor_dem_impact* impact, double dt) {
    viscor_dk_setup u;
    if (!(dt > 0 && dt <= DBL_MAX) || viscor_dk_set_up(model, impact, &u) != VISCOR_DECK_OK ||
        !viscor_dk_valid_entry(model, deck_damping))
        return NAN;
    return viscor_dk_stepped_e_for_entry(model, &u, impact, deck_damping, dt);
}

double viscor_dem_damping_entry(viscor_dem_model model, double e_target, const viscor_dem_impact* impact) {
    return viscor_dk_deck(model, e_target, impact, 0.0).damping;
}

double viscor_dem_e_for_entry(viscor_dem_model model, double deck_damping, const viscor_dem_impact* impact) {
    viscor_dk_setup u;
    if (model == VISCOR_YADE_MINDLIN || viscor_dk_set_up(model, impact, &u) != VISCOR_DECK_OK ||
        !viscor_dk_valid_entry(model, deck_damping))
        return NAN; /* YADE's clamped force: viscor_dem_stepped_e */
    return viscor_dk_e_for_entry(model, &u, impact, deck_damping);
}
)";

}  // namespace

std::string dem_entries_c_declarations() { return declarations; }
std::string dem_entries_c_definitions() { return definitions; }

}  // namespace viscor::jobs
