/* Reads requests from stdin, one a line, and prints the exported C surrogate's answer
 * to each in hexadecimal floating point (exact), for surrogate_export_test:
 *   c LAW gamma g                      -> outcome e one_minus_e e_squared (viscor_cor_at)
 *   i LAW e_target g                   -> gamma (viscor_gamma_for)
 *   t LAW g                            -> gamma_c (viscor_critical_gamma)
 *   p LAW m k gamma0 v0 gravity force  -> outcome e one_minus_e e_squared (viscor_cor_physical)
 *   d LAW e_target m k v0 gravity force -> gamma0 (viscor_damping_for)
 * Numbers are read with strtod (hexadecimal or decimal). Built with no viscor include
 * path: only the exported pair and the C standard library. */
#include "viscor_surrogates.h"

#include <stdio.h>
#include <stdlib.h>

int main(void) {
    char kind[4], law[64];
    double a[6];
    while (scanf("%3s %63s", kind, law) == 2) {
        const viscor_surrogate* s = viscor_surrogate_named(law);
        char text[6][64];
        int i, count = kind[0] == 'c' ? 2 : kind[0] == 'i' ? 2 : kind[0] == 't' ? 1 : kind[0] == 'p' ? 6 : 6;
        for (i = 0; i < count; ++i) {
            if (scanf("%63s", text[i]) != 1) return 2;
            a[i] = strtod(text[i], 0);
        }
        if (!s) {
            fprintf(stderr, "unknown law %s\n", law);
            return 3;
        }
        if (kind[0] == 'c' || kind[0] == 'p') {
            const viscor_cor v = kind[0] == 'c' ? viscor_cor_at(s, a[0], a[1])
                                                : viscor_cor_physical(s, a[0], a[1], a[2], a[3], a[4], a[5]);
            printf("%d %a %a %a\n", (int)v.outcome, v.e, v.one_minus_e, v.e_squared);
        } else if (kind[0] == 'i') {
            printf("%a\n", viscor_gamma_for(s, a[0], a[1]));
        } else if (kind[0] == 't') {
            printf("%a\n", viscor_critical_gamma(s, a[0]));
        } else {
            printf("%a\n", viscor_damping_for(s, a[0], a[1], a[2], a[3], a[4], a[5]));
        }
    }
    return 0;
}
