/*
** tests/test_numfmt.c -- shortest round-trip and fixed formatting of doubles
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "numfmt.h"

static int spells(double x, const char *want)
{
    char b[PT_NUMLEN];
    pt_fmt_shortest(b, x);
    if (strcmp(b, want) != 0) printf("  %.17g spelled '%s', want '%s'\n", x, b, want);
    return strcmp(b, want) == 0;
}

/* The shortest "%.*g" that reads back, found the slow way. */
static size_t slow_shortest_len(double x)
{
    char b[64];
    int p;
    for (p = 1; p <= 17; p++) {
        snprintf(b, sizeof b, "%.*g", p, x);
        if (strtod(b, NULL) == x) break;
    }
    return strlen(b);
}

static double from_bits(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

int main(void)
{
    char b[PT_NUMLEN];
    int k, round_trips = 1, shortest = 1;
    uint64_t state = 88172645463325252ULL;

    PT_CHECK("num-1.1 0.1", spells(0.1, "0.1"));
    PT_CHECK("num-1.2 -1", spells(-1, "-1"));
    PT_CHECK("num-1.3 -0 keeps its sign", spells(-0.0, "-0"));
    PT_CHECK("num-1.4 0.30000000000000004", spells(0.1 + 0.2, "0.30000000000000004"));
    PT_CHECK("num-1.5 142.50000000000003", spells(142.50000000000003, "142.50000000000003"));
    PT_CHECK("num-1.6 smallest subnormal 5e-324", spells(5e-324, "5e-324"));
    PT_CHECK("num-1.7 1e+300", spells(1e300, "1e+300"));
    PT_CHECK("num-1.8 5.497501249375313 (a pixel-plane value)",
             spells(5.497501249375313, "5.497501249375313"));
    PT_CHECK("num-1.9 2^-1022", spells(2.2250738585072014e-308, "2.2250738585072014e-308"));
    PT_CHECK("num-1.10 non-finite", spells((double)NAN, "nan") && spells((double)INFINITY, "inf") &&
             spells(-(double)INFINITY, "-inf"));
    for (k = 0; k < 30000; k++) {           /* xorshift: every kind of double */
        double x;
        state ^= state << 13; state ^= state >> 7; state ^= state << 17;
        x = from_bits(k % 5 == 0 ? state & 0xfff0000000000000ULL :   /* powers of 2 */
                      k % 5 == 1 ? state & 0x800fffffffffffffULL :   /* subnormals */
                      state);
        if (!isfinite(x)) continue;
        pt_fmt_shortest(b, x);
        if (strtod(b, NULL) != x) round_trips = 0;
        if (strlen(b) > slow_shortest_len(x)) shortest = 0;
    }
    PT_CHECK("num-2.1 30000 doubles read back exactly", round_trips);
    PT_CHECK("num-2.2 ... and are never longer than the shortest %g", shortest);

    pt_fmt_fixed(b, 5.497501249375313, 6);
    PT_CHECK("num-3.1 fixed, 6 digits", strcmp(b, "5.497501") == 0);
    pt_fmt_fixed(b, -0.5, 0);
    PT_CHECK("num-3.2 fixed, 0 digits rounds half to even", strcmp(b, "-0") == 0);
    pt_fmt_fixed(b, 1e300, 3);
    PT_CHECK("num-3.3 huge values switch to exponent form", strcmp(b, "1.000e+300") == 0);
    pt_fmt_fixed(b, -(double)INFINITY, 3);
    PT_CHECK("num-3.4 fixed non-finite", strcmp(b, "-inf") == 0);
    return pt_test_report();
}
