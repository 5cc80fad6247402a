/* Reads DEM requests from stdin, one a line, and prints the exported C entries for
 * each in hexadecimal floating point (exact), for dem_export_test:
 *   deck  MODEL e_target IMPACT  -> status and the 14 numbers of viscor_deck (viscor_dem_deck)
 *   entry MODEL deck_damping IMPACT -> e (viscor_dem_e_for_entry)
 *   step  MODEL e_target dt IMPACT -> as deck, for the drop stepped with dt (viscor_dem_deck_at_step)
 *   contact 0 0 IMPACT -> valid, E*, R*, m*, k and the gravity felt (viscor_contact_of)
 * IMPACT is: pair wall_material E nu R rho wall_E wall_nu other_material oE onu oR orho v0 gravity force.
 * Numbers are read with strtod (hexadecimal or decimal). Built with no viscor include
 * path: only the exported pair and the C standard library. */
#include "viscor_surrogates.h"

#include <stdio.h>
#include <stdlib.h>

static double number(void) {
    char text[64];
    if (scanf("%63s", text) != 1) exit(2);
    return strtod(text, 0);
}

int main(void) {
    char kind[8];
    int model;
    while (scanf("%7s %d", kind, &model) == 2) {
        viscor_dem_impact in;
        const double value = number();
        const double dt = kind[0] == 's' ? number() : 0;
        in.pair = (int)number(), in.wall_material = (int)number();
        in.bead.youngs_modulus = number(), in.bead.poisson_ratio = number();
        in.bead.radius = number(), in.bead.density = number();
        in.wall_youngs_modulus = number(), in.wall_poisson_ratio = number();
        in.other_material = (int)number();
        in.other.youngs_modulus = number(), in.other.poisson_ratio = number();
        in.other.radius = number(), in.other.density = number();
        in.v0 = number(), in.gravity = number(), in.force = number();
        if (kind[0] == 'c') {
            const viscor_contact c = viscor_contact_of(&in);
            printf("%d %a %a %a %a %a\n", c.valid, c.effective_modulus, c.effective_radius, c.mass, c.stiffness,
                   c.gravity);
        } else if (kind[0] == 'd' || kind[0] == 's') {
            const viscor_deck d = kind[0] == 'd' ? viscor_dem_deck((viscor_dem_model)model, value, &in)
                                                 : viscor_dem_deck_at_step((viscor_dem_model)model, value, &in, dt);
            printf("%d %a %a %a %a %a %a %a %a %a %a %a %a %a %a\n", (int)d.status, d.damping, d.damping_number,
                   d.gamma0, d.youngs_modulus, d.poisson_ratio, d.wall_youngs_modulus, d.wall_poisson_ratio,
                   d.other_youngs_modulus, d.other_poisson_ratio, d.cross_youngs_modulus,
                   d.bead_bead_youngs_modulus, d.bead_bead_damping, d.other_other_damping, d.builtin_e);
        } else {
            printf("%a\n", viscor_dem_e_for_entry((viscor_dem_model)model, value, &in));
        }
    }
    return 0;
}
