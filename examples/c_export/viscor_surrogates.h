/* viscor_surrogates.h: the coefficient of restitution e of a bead hitting a wall, as fast
 * double-precision surrogates of viscor's certified solutions, exported as self-contained
 * C99 by `viscor surrogate export --language c` (docs/surrogate.md, "Exporting to C").
 * Do not edit: export again (the last line seals the file with the SHA-256 of the rest;
 * an export replaces only a file whose seal still matches). Needs only the C standard
 * library (<math.h>, <float.h>);
 * no allocation, no state written (every table is const): safe from any thread.
 *
 * SPDX-License-Identifier: MIT
 *
 * MIT License
 *
 * Copyright (c) 2026 the viscor developers
 *
 * Permission is hereby granted, free of charge, to any person obtaining a copy
 * of this software and associated documentation files (the "Software"), to deal
 * in the Software without restriction, including without limitation the rights
 * to use, copy, modify, merge, publish, distribute, sublicense, and/or sell
 * copies of the Software, and to permit persons to whom the Software is
 * furnished to do so, subject to the following conditions:
 *
 * The above copyright notice and this permission notice shall be included in all
 * copies or substantial portions of the Software.
 *
 * THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
 * IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
 * FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
 * AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
 * LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
 * OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
 * SOFTWARE.
 *
 * Provenance (format: viscor C export 1). Made from these files of viscor's
 * reference_data/surrogates/, SHA-256 of each:
 *   linear.surrogate
 *     5d94cc95878239e3b4f74b38e0e0757132d327babbd41426adb583c98567e35e
 *   linear.surrogate.verification.csv
 *     a0ca9ad9a130d07e5200fe7ddaf94096fc9d91e27c3e73b40fe9be9dd2340db0
 *   hertz_linear_damping.surrogate
 *     2fc2b5d55cb34a6b3d5b07c21f5307e444fb7525cd7340de42c05758be2b7251
 *   hertz_linear_damping.surrogate.verification.csv
 *     e37337d719c3b669e73428a36433504ca6899f0d628be47114b26e3de2aa5ea0
 *   tsuji.surrogate
 *     5897dad24a165261a34587aea16f703f3019cc3f913cd3f9c21a39303b489b4b
 *   tsuji.surrogate.verification.csv
 *     82e56fe67a13fa468d0ebead7c6d6058b4ccc54f9e65fcb706503af9d14ded85
 *   kuwabara_kono.surrogate
 *     546ee7202fe7dbbd4b212d6a998915f097f309f7ae5b94cab388f4698052bb33
 *   kuwabara_kono.surrogate.verification.csv
 *     52750d4976762a31e1c6eeb1041d4ed2e314c6cbc14fa6e92e71118a9990b0b2
 *   hunt_crossley.surrogate
 *     f86dcb6d5da62da296e6cdfe9a8797e2140e8d676149e725119addcb090ef65a
 *   hunt_crossley.surrogate.verification.csv
 *     99c4cf6ec7072c8964a5c045ddf6afe32f192ca8cc9c52c37b5d971d77369393
 *
 * Accuracy. The stated bound (per law, the field `bound` of its viscor_surrogate) is the
 * measured maximum over the law's 20,000 certified verification points times a safety
 * factor of 2, for |e_s - e| where e >= 1e-2, |e_s^2 - e^2| everywhere, and the relative
 * error of 1 - e where gamma <= 1e-2 and e >= 1e-2; the outcome is correct except within
 * relative 1e-10 in g of the sticking threshold. Measured maxima per region at export
 * (this code gives the library's values: docs/surrogate.md, "Exporting to C"); the
 * regions overlap: small_gamma gamma <= 1e-2, near_threshold within relative 5% in g
 * of the threshold, large_g g >= 100, negative_g g < 0:
 *   law / region       points   max|de|    max|de^2|  rel d(1-e)  wrong outcomes
 *   linear (bound: 1.06e-13, 1.20e-14, 4.92e-14)
 *      all              20000   5.31e-14   5.99e-15   2.46e-14        0
 *      small_gamma       9914   2.44e-14   2.74e-15   2.46e-14        0
 *      near_threshold    4022   5.31e-14   2.57e-15   2.46e-14        0
 *      large_g           7008   2.44e-14   2.74e-15   2.46e-14        0
 *      negative_g        4912   6.12e-15   5.99e-15   8.10e-16        0
 *   hertz_linear_damping (bound: 1.51e-13, 1.35e-14, 9.34e-14)
 *      all              20000   7.55e-14   6.73e-15   4.67e-14        0
 *      small_gamma       9368   4.63e-14   1.72e-15   4.67e-14        0
 *      near_threshold    3882   5.83e-14   2.94e-15   4.67e-14        0
 *      large_g           6832   2.51e-14   1.35e-15   2.54e-14        0
 *      negative_g        4901   1.73e-14   4.75e-15   5.52e-16        0
 *   tsuji (bound: 2.88e-13, 1.56e-14, 2.92e-13)
 *      all              20000   1.44e-13   7.80e-15   1.46e-13        0
 *      small_gamma       9726   1.44e-13   7.63e-15   1.46e-13        0
 *      near_threshold    3982   1.44e-13   7.63e-15   1.46e-13        0
 *      large_g           6925   1.20e-13   5.42e-15   1.22e-13        0
 *      negative_g        4889   9.81e-15   2.54e-15   1.36e-15        0
 *   kuwabara_kono (bound: 2.92e-13, 1.66e-14, 2.95e-13)
 *      all              20000   1.46e-13   8.32e-15   1.48e-13        0
 *      small_gamma       9862   1.46e-13   5.84e-15   1.48e-13        0
 *      near_threshold    3993   1.46e-13   5.84e-15   1.48e-13        0
 *      large_g           6985   1.31e-13   5.84e-15   1.32e-13        0
 *      negative_g        4916   1.25e-14   8.32e-15   6.79e-15        0
 *   hunt_crossley (bound: 1.12e-13, 1.52e-14, 1.11e-13)
 *      all              20000   5.61e-14   7.61e-15   5.53e-14        0
 *      small_gamma      10287   5.46e-14   3.68e-15   5.53e-14        0
 *      near_threshold    4057   5.61e-14   2.97e-15   5.53e-14        0
 *      large_g           7098   2.61e-14   9.32e-16   2.64e-14        0
 *      negative_g        4889   5.29e-15   7.61e-15   1.21e-14        0
 *
 * Model. Scaled: u'' + gamma d/dtau(u^beta) + u^alpha = g while u > 0, u(0) = 0, u'(0) = 1;
 * e = -u' when u returns to 0 (rebound), e = 0 if it never does (stick). Physical: a bead
 * of mass m hits a rigid wall at speed v0; with the overlap x >= 0,
 *   m x'' = -(k x^alpha + gamma0 k d/dt(x^beta)) + m gravity + F,   x(0) = 0, x'(0) = v0,
 * gravity (m/s^2) and the force F (N) pushing the bead towards the wall. The scaling
 * (viscor's core/scaling.hpp, eq. 2 of the report): x = v0 T u, t = T tau, with
 *   T     = (m/k)^(1/(alpha+1)) v0^((1-alpha)/(alpha+1)),
 *   gamma = gamma0 v0^(2 beta/(alpha+1) - 1) (k/m)^(1 - beta/(alpha+1)),
 *   g     = (m/k)^(1/(alpha+1)) v0^(-2 alpha/(alpha+1)) (gravity + F/m).
 * Domain: 0 <= gamma <= gamma_max, g_min <= g <= g_max (viscor_surrogate fields).
 */
#ifndef VISCOR_SURROGATES_H
#define VISCOR_SURROGATES_H

#ifdef __cplusplus
extern "C" {
#endif

/* The outcome of one impact. */
typedef enum viscor_outcome {
    VISCOR_OUTSIDE_DOMAIN = -1, /* (gamma, g) outside the fitted domain: no value */
    VISCOR_REBOUND = 0,         /* the bead leaves the wall, e > 0 */
    VISCOR_STICK = 1            /* it never leaves: e = 0 */
} viscor_outcome;

/* One evaluation. Outside the domain: outcome VISCOR_OUTSIDE_DOMAIN, the rest NaN. */
typedef struct viscor_cor {
    viscor_outcome outcome;
    double e;           /* 0 for a stick */
    double one_minus_e; /* 1 - e with its relative digits (1 for a stick) */
    double e_squared;   /* 1 - w G before the square root (<= 0 past the threshold) */
} viscor_cor;

/* The stated bound (see the comment at the top). */
typedef struct viscor_sg_bound {
    double abs_e;           /* |e_s - e| where e >= 1e-2 */
    double abs_e_squared;   /* |e_s^2 - e^2| everywhere */
    double rel_one_minus_e; /* relative error of 1 - e where gamma <= 1e-2 and e >= 1e-2 */
    double safety_factor;   /* the measured maximum was multiplied by this */
} viscor_sg_bound;

/* The tables of one law (read-only; the layout of viscor's surrogate/cor_surrogate.hpp). */
typedef struct viscor_sg_node {
    double split; /* inner node: the value of x (dim 0) or y (dim 1) where it splits */
    int dim;      /* 0, 1: inner; 2: leaf */
    int child;    /* inner: the lower child (the upper is child + 1); leaf: the patch */
} viscor_sg_node;
typedef struct viscor_sg_patch {
    double cx, sx, cy, sy; /* (x - cx) sx and (y - cy) sy lie in [-1, 1] */
} viscor_sg_patch;
typedef struct viscor_sg_tree {
    double x0, x1, y0, y1; /* the box */
    int order;             /* Chebyshev points per direction (at most 64) */
    const viscor_sg_node* nodes;
    const viscor_sg_patch* patches;
    const double* coefficients; /* patch p: T_i(x) T_j(y) at p n^2 + j n + i */
} viscor_sg_tree;
typedef struct viscor_surrogate {
    const char* law;              /* the viscor name of the law, e.g. "tsuji" */
    const char* alpha_text;       /* exponents as exact texts, e.g. "3/2" */
    const char* beta_text;
    double alpha, beta;
    double gamma_max, g_min, g_max; /* the domain */
    double gamma_ext, g_split;      /* low loads: g <= g_split (no sticking for gamma <= gamma_max) */
    viscor_sg_bound bound;
    int threshold_order, threshold_breaks;
    const double* threshold_break;        /* breaks in ln g */
    const double* threshold_coefficients; /* interval k: [k order, (k + 1) order) */
    double threshold_power;               /* ln gamma_c = h(ln g) - power ln g */
    viscor_sg_tree low_load;  /* x = gamma, y = g; G = (1 - e^2) / gamma */
    viscor_sg_tree high_load; /* x = ln g, y = sqrt(1 - r), r = gamma / gamma_c(g); G = (1 - e^2) / r */
} viscor_surrogate;

/* The surrogate of the law called `law` ("tsuji", ...), or a null pointer. */
const viscor_surrogate* viscor_surrogate_named(const char* law);

/* Every function below takes a null `s` as a point outside the domain: NaN, or the
   outcome VISCOR_OUTSIDE_DOMAIN with NaN values. */

/* ---- scaled variables ---- */

/* e, 1 - e, e^2 and the outcome at (gamma, g). */
viscor_cor viscor_cor_at(const viscor_surrogate* s, double gamma, double g);
/* e at (gamma, g); NaN outside the domain. */
double viscor_e(const viscor_surrogate* s, double gamma, double g);
/* 1 - e at (gamma, g), with its relative digits as gamma -> 0; NaN outside the domain. */
double viscor_one_minus_e(const viscor_surrogate* s, double gamma, double g);
/* VISCOR_REBOUND, VISCOR_STICK or VISCOR_OUTSIDE_DOMAIN at (gamma, g). */
viscor_outcome viscor_outcome_at(const viscor_surrogate* s, double gamma, double g);
/* The sticking threshold gamma_c(g): the bead sticks for gamma >= gamma_c (to the
   bound on the outcome). HUGE_VAL for g_min <= g <= g_split (no sticking below
   gamma_ext > gamma_max), NaN outside [g_min, g_max]. */
double viscor_critical_gamma(const viscor_surrogate* s, double g);
/* The inverse: the gamma in [0, gamma_max] with e(gamma, g) = e_target, for
   0.01 <= e_target < 1 and g in the domain; NaN if outside those ranges or no gamma
   in the domain reaches e_target. The library's gamma_for, the same bits. */
double viscor_gamma_for(const viscor_surrogate* s, double e_target, double g);

/* ---- physical variables (SI units; see "Model" at the top) ---- */

/* T = (m/k)^(1/(alpha+1)) v0^((1-alpha)/(alpha+1)): physical time = T tau. */
double viscor_time_scale(const viscor_surrogate* s, double m, double k, double v0);
/* gamma / gamma0 = v0^(2 beta/(alpha+1) - 1) (k/m)^(1 - beta/(alpha+1)). */
double viscor_damping_scale(const viscor_surrogate* s, double m, double k, double v0);
/* g / (gravity + F/m) = (m/k)^(1/(alpha+1)) v0^(-2 alpha/(alpha+1)). */
double viscor_load_scale(const viscor_surrogate* s, double m, double k, double v0);
/* The scaled load g of gravity (m/s^2, >= 0: towards the wall) and the force F (N,
   towards the wall; negative: away from it). NaN for a negative or NaN gravity. */
double viscor_scaled_g(const viscor_surrogate* s, double m, double k, double v0, double gravity, double force);
/* The impact of a bead (m > 0, k > 0, gamma0 >= 0, v0 > 0, gravity >= 0): e, 1 - e and
   the outcome (VISCOR_OUTSIDE_DOMAIN, values NaN, for invalid inputs, such as a negative
   gravity, or outside the domain). */
viscor_cor viscor_cor_physical(const viscor_surrogate* s, double m, double k, double gamma0, double v0,
                               double gravity, double force);
/* The damping coefficient gamma0 at which the bead rebounds with e_target
   (0.01 <= e_target < 1) under gravity and F: viscor_gamma_for at the scaled load,
   divided by viscor_damping_scale. NaN for invalid inputs (as viscor_cor_physical) or
   if no gamma in the domain gives e_target. */
double viscor_damping_for(const viscor_surrogate* s, double e_target, double m, double k, double v0,
                          double gravity, double force);

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

/* The laws of this export. */
extern const viscor_surrogate viscor_surrogate_linear; /* alpha = 1, beta = 1 */
extern const viscor_surrogate viscor_surrogate_hertz_linear_damping; /* alpha = 3/2, beta = 1 */
extern const viscor_surrogate viscor_surrogate_tsuji; /* alpha = 3/2, beta = 5/4 */
extern const viscor_surrogate viscor_surrogate_kuwabara_kono; /* alpha = 3/2, beta = 3/2 */
extern const viscor_surrogate viscor_surrogate_hunt_crossley; /* alpha = 3/2, beta = 5/2 */

#ifdef __cplusplus
}
#endif

#endif /* VISCOR_SURROGATES_H */
/* viscor sha256 fdb9a56db8aba936cc7eef4036707c0bc53f813851e78d916fcbb5f43417e6f9 */
