/* viscor_web.c: the calculator page's door into the C export (web/calculator.js calls it
 * through WebAssembly). It holds the impact the form describes and turns the export's
 * struct results into plain doubles JavaScript can read; every number comes from a
 * function of viscor_surrogates.h, no rule of the model is restated here. */
#include "viscor_surrogates.h"

#include <math.h>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#define VISCOR_WEB EMSCRIPTEN_KEEPALIVE
#else
#define VISCOR_WEB
#endif

/* The form's impact: the export's DEM impact for a material bead, and the contact
   (m, k, the gravity felt) the cor and calibrate functions take. */
static viscor_dem_impact impact;
static viscor_contact contact;

/* A bead of a material against a rigid wall (partner 0), a wall of wall_E, wall_nu (1),
   a bead like it (2) or the bead other_* (3). 1 if the export accepts it, else 0. */
VISCOR_WEB int viscor_web_set_material_impact(double youngs_modulus, double poisson_ratio, double radius,
                                              double density, int partner, double wall_youngs_modulus,
                                              double wall_poisson_ratio, double other_youngs_modulus,
                                              double other_poisson_ratio, double other_radius, double other_density,
                                              double v0, double gravity, double force) {
    viscor_bead bead = {youngs_modulus, poisson_ratio, radius, density};
    viscor_bead other = {other_youngs_modulus, other_poisson_ratio, other_radius, other_density};
    impact.bead = bead;
    impact.pair = partner >= 2;
    impact.wall_material = partner == 1;
    impact.wall_youngs_modulus = wall_youngs_modulus, impact.wall_poisson_ratio = wall_poisson_ratio;
    impact.other_material = partner == 3;
    impact.other = other;
    impact.v0 = v0, impact.gravity = gravity, impact.force = force;
    contact = viscor_contact_of(&impact);
    return contact.valid;
}

/* A bead given by its mass and stiffness on a rigid wall (no DEM deck: codes take materials). */
VISCOR_WEB void viscor_web_set_bead_impact(double m, double k, double v0, double gravity, double force) {
    impact.v0 = v0, impact.gravity = gravity, impact.force = force;
    contact.valid = 1;
    contact.effective_modulus = contact.effective_radius = NAN;
    contact.mass = m, contact.stiffness = k, contact.gravity = gravity;
}

VISCOR_WEB double viscor_web_mass(void) { return contact.mass; }
VISCOR_WEB double viscor_web_stiffness(void) { return contact.stiffness; }

/* The surrogate of the law called `law`, or 0. */
VISCOR_WEB const viscor_surrogate* viscor_web_law(const char* law) { return viscor_surrogate_named(law); }

/* The scaled damping and load of gamma0 at the impact set. */
VISCOR_WEB double viscor_web_scaled_gamma(const viscor_surrogate* s, double gamma0) {
    return gamma0 * viscor_damping_scale(s, contact.mass, contact.stiffness, impact.v0);
}
VISCOR_WEB double viscor_web_scaled_g(const viscor_surrogate* s) {
    return viscor_scaled_g(s, contact.mass, contact.stiffness, impact.v0, contact.gravity, impact.force);
}
VISCOR_WEB double viscor_web_damping_scale(const viscor_surrogate* s) {
    return viscor_damping_scale(s, contact.mass, contact.stiffness, impact.v0);
}

/* The time scale T (s) of the impact set: physical time = T tau. */
VISCOR_WEB double viscor_web_time_scale(const viscor_surrogate* s) {
    return viscor_time_scale(s, contact.mass, contact.stiffness, impact.v0);
}

/* The fitted domain: out[0] gamma_max, out[1] g_min, out[2] g_max. */
VISCOR_WEB void viscor_web_domain(const viscor_surrogate* s, double* out) {
    out[0] = s->gamma_max, out[1] = s->g_min, out[2] = s->g_max;
}

/* The impact at damping gamma0: out[0] outcome, out[1] e, out[2] 1 - e, out[3] e^2. */
VISCOR_WEB void viscor_web_cor(const viscor_surrogate* s, double gamma0, double* out) {
    const viscor_cor c =
        viscor_cor_physical(s, contact.mass, contact.stiffness, gamma0, impact.v0, contact.gravity, impact.force);
    out[0] = c.outcome, out[1] = c.e, out[2] = c.one_minus_e, out[3] = c.e_squared;
}

/* The damping gamma0 that gives e_target at the impact set. */
VISCOR_WEB double viscor_web_damping_for(const viscor_surrogate* s, double e_target) {
    return viscor_damping_for(s, e_target, contact.mass, contact.stiffness, impact.v0, contact.gravity,
                              impact.force);
}

/* The stated bound: out[0] |de|, out[1] |de^2|, out[2] relative d(1 - e). */
VISCOR_WEB void viscor_web_bound(const viscor_surrogate* s, double* out) {
    out[0] = s->bound.abs_e, out[1] = s->bound.abs_e_squared, out[2] = s->bound.rel_one_minus_e;
}

/* The deck of `model` for e_target at the material impact set, for the continuous impact
   (dt 0) or the drop stepped with dt (s): out[0] the status, then the doubles of
   viscor_deck in their order (damping ... builtin_e). */
VISCOR_WEB void viscor_web_deck(int model, double e_target, double dt, double* out) {
    const viscor_deck d = dt > 0 ? viscor_dem_deck_at_step((viscor_dem_model)model, e_target, &impact, dt)
                                 : viscor_dem_deck((viscor_dem_model)model, e_target, &impact);
    const double fields[] = {d.damping, d.damping_number, d.gamma0, d.youngs_modulus, d.poisson_ratio,
                             d.wall_youngs_modulus, d.wall_poisson_ratio, d.other_youngs_modulus,
                             d.other_poisson_ratio, d.cross_youngs_modulus, d.bead_bead_youngs_modulus,
                             d.bead_bead_damping, d.other_other_damping, d.builtin_e};
    unsigned i;
    out[0] = d.status;
    for (i = 0; i < sizeof fields / sizeof fields[0]; ++i) out[i + 1] = fields[i];
}

/* The e the code gets from a deck damping entry at the impact set (NaN if invalid). */
VISCOR_WEB double viscor_web_e_for_entry(int model, double deck_damping) {
    return viscor_dem_e_for_entry((viscor_dem_model)model, deck_damping, &impact);
}
