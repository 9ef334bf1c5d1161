/*
** tests/unit/test_jmath.c -- Java's Math.atan (stages/pt_jmath.c)
** See LICENSE for copyright and license.
**
** tests/data/jmath/atan.txt holds what JDK 17's Math.atan (= StrictMath.atan,
** fdlibm's) returned for about 2,000 doubles: the special values, the
** reduction thresholds and their neighbours, and random ones, most of them
** where the C library's atan returns another double.  Every one must come
** out bit for bit.
**
** tests/data/jmath/trig.txt holds JDK 17's Math.sin and Math.cos of
** (PI/180)*deg (renderer 9's rotate) and Math.tan of ((PI/180)*deg)/2 (the
** top of projPerspective(fovy = deg)) for the integer angles -720..720.  On
** HotSpot x86_64 these are intrinsics (Intel's libm), which pipetrace does not
** reproduce: it calls the C library's.  jm-3 counts the angles where they
** differ, allows one ulp, and at most 1% of the angles (glibc 2.36: sin 4,
** cos 2, tan 12 of 1441; docs/renderer7.md).
**
** Usage: test_jmath [VECTORS [TRIG]]; without them, the files in
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
    PT_CHECK("jm-1.3 atan(NaN) is NaN", isnan(pt_jmath_atan(from_bits(UINT64_C(0x7ff8000000000000)))));
    PT_CHECK("jm-1.4 atan(inf) = pi/2 rounded", pt_jmath_atan(HUGE_VAL) == 0x1.921fb54442d18p0);
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

/* How many doubles lie between a and b (0: the same bits), a and b finite. */
static uint64_t ulps(double a, double b)
{
    int64_t ia = (int64_t)to_bits(a), ib = (int64_t)to_bits(b);

    if (ia < 0) ia = INT64_MIN - ia;             /* order the negatives too */
    if (ib < 0) ib = INT64_MIN - ib;
    return ia > ib ? (uint64_t)ia - (uint64_t)ib : (uint64_t)ib - (uint64_t)ia;
}

/* Java's sin, cos, tan of the course's angles against the C library's (jm-3.*). */
static void trig(const char *path)
{
    static const double JAVA_PI = 3.141592653589793;     /* Math.PI */
    char line[256], what[200];
    FILE *in = fopen(path, "r");
    int n = 0, bad = 0, far = 0, k;
    long diff[3] = {0, 0, 0};

    PT_CHECK("jm-3.0 the angles can be read", in != NULL);
    if (!in) return;
    while (fgets(line, sizeof line, in)) {
        unsigned long long b[3];
        int deg;
        double a, c[3];

        if (line[0] == '#') continue;
        if (sscanf(line, "%d %llx %llx %llx", &deg, &b[0], &b[1], &b[2]) != 4) { bad++; continue; }
        n++;
        a = (JAVA_PI / 180.0) * deg;
        c[0] = sin(a);
        c[1] = cos(a);
        c[2] = tan(((JAVA_PI / 180.0) * deg) / 2.0);
        for (k = 0; k < 3; k++) {
            uint64_t u = ulps(c[k], from_bits((uint64_t)b[k]));

            if (u == 0) continue;
            diff[k]++;
            if (u > 1) {
                snprintf(what, sizeof what, "jm-3.1 %s of %d degrees: %a, Java %a",
                         k == 0 ? "sin" : k == 1 ? "cos" : "tan/2", deg, c[k],
                         from_bits((uint64_t)b[k]));
                if (far++ < 10) PT_CHECK(what, 0);
            }
        }
    }
    fclose(in);
    PT_CHECK("jm-3.2 every line has an angle and three values", bad == 0);
    PT_CHECK("jm-3.3 the 1441 angles -720..720", n == 1441);
    PT_CHECK("jm-3.4 the C library's sin, cos, tan within one ulp of Java's", far == 0);
    PT_CHECK("jm-3.5 and the same double for 99% of the angles",
             diff[0] * 100 <= n && diff[1] * 100 <= n && diff[2] * 100 <= n);
    printf("jmath: of %d angles, the C library's sin differs from Java's on %ld, cos on %ld, "
           "tan of the half angle on %ld\n", n, diff[0], diff[1], diff[2]);
}

int main(int argc, char **argv)
{
    known_cases();
    vectors(argc > 1 ? argv[1] : "tests/data/jmath/atan.txt");
    trig(argc > 2 ? argv[2] : "tests/data/jmath/trig.txt");
    return pt_test_report();
}
