/*
** tests/unit/test_jmath.c -- Java's Math.atan (stages/pt_jmath.c)
** See LICENSE for copyright and license.
**
** tests/data/jmath/atan.txt holds what JDK 17's Math.atan (= StrictMath.atan,
** fdlibm's) returned for about 2,000 doubles: the special values, the
** reduction thresholds and their neighbours, and random ones, most of them
** where the C library's atan returns another double.  Every one must come
** out bit for bit.  Usage: test_jmath [VECTORS]; without it, the file in
** tests/data/jmath/.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "stages/pt_jmath.h"

static double from_bits(uint64_t b)
{
    double x;

    memcpy(&x, &b, sizeof x);
    return x;
}

static uint64_t to_bits(double x)
{
    uint64_t b;

    memcpy(&b, &x, sizeof b);
    return b;
}

/* The cases the header names, spelled out (jm-1.*). */
static void known_cases(void)
{
    PT_CHECK("jm-1.1 atan(+0) = +0", to_bits(pt_jmath_atan(0.0)) == 0);
    PT_CHECK("jm-1.2 atan(-0) = -0", to_bits(pt_jmath_atan(-0.0)) == UINT64_C(0x8000000000000000));
    PT_CHECK("jm-1.3 atan(NaN) is NaN", isnan(pt_jmath_atan(NAN)));
    PT_CHECK("jm-1.4 atan(inf) = pi/2 rounded", pt_jmath_atan(INFINITY) == 0x1.921fb54442d18p0);
    PT_CHECK("jm-1.5 atan(-2^66) = -pi/2 rounded", pt_jmath_atan(-0x1p66) == -0x1.921fb54442d18p0);
    PT_CHECK("jm-1.6 atan(1) = pi/4 rounded", pt_jmath_atan(1.0) == 0x1.921fb54442d18p-1);
    PT_CHECK("jm-1.7 atan(2^-30) = 2^-30", pt_jmath_atan(0x1p-30) == 0x1p-30);
    PT_CHECK("jm-1.8 atan(MIN_VALUE) = MIN_VALUE", pt_jmath_atan(0x1p-1074) == 0x1p-1074);
}

static void vectors(const char *path)
{
    char line[256], what[200];
    FILE *in = fopen(path, "r");
    int n = 0, bad = 0, wrong = 0, libc = 0;

    PT_CHECK("jm-2.0 the vectors can be read", in != NULL);
    if (!in) return;
    while (fgets(line, sizeof line, in)) {
        char *end;
        uint64_t xb, yb, got;
        double x, l;

        if (line[0] == '#') continue;
        xb = strtoull(line, &end, 16);
        if (*end != ' ') { bad++; continue; }
        yb = strtoull(end + 1, NULL, 16);
        x = from_bits(xb);
        n++;
        got = to_bits(pt_jmath_atan(x));
        if (got != yb && !(isnan(from_bits(got)) && isnan(from_bits(yb)))) {
            snprintf(what, sizeof what, "jm-2.1 atan(%a) = %a, Java %a", x, from_bits(got),
                     from_bits(yb));
            if (wrong++ < 20) PT_CHECK(what, 0);
        }
        l = atan(x);
        if (to_bits(l) != yb && !isnan(l)) libc++;
    }
    fclose(in);
    PT_CHECK("jm-2.2 every line has two words", bad == 0);
    PT_CHECK("jm-2.3 more than 1900 vectors", n > 1900);
    PT_CHECK("jm-2.4 all vectors match", wrong == 0);
    printf("jmath: %d vectors; the C library's atan differs from Java on %d\n", n, libc);
}

int main(int argc, char **argv)
{
    known_cases();
    vectors(argc > 1 ? argv[1] : "tests/data/jmath/atan.txt");
    return pt_test_report();
}
