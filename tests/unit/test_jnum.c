/*
** tests/unit/test_jnum.c -- doubles spelled as Java spells them (src/io/jnum.c)
** See LICENSE for copyright and license.
**
** tests/data/jnum-vectors.txt holds what JDK 17, the course's Java, printed
** for 4,200 doubles (tests/data/JnumVectors.java, and the command that made
** the file, at its top): Double.toString and String.format with "%.5f",
** "% 10.5f", "%9.4f", "%.4f" and "%.2f".  tests/data/jnum-hard.txt holds JDK
** 17's Double.toString of 3,100 doubles where it is not the shortest decimal
** that JDK 19 and later print (tests/data/JnumHard.java): integers above 2^53,
** powers of two, random bits and decimals.  Every line must come out byte for
** byte.  Usage: test_jnum [VECTORS [HARD]]; without them, the files in
** tests/data/.
*/
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "io/jnum.h"

/* The checks the course's log needs, spelled out (jn-1.*). */
static void known_cases(void)
{
    char b[PT_JNUM_LEN];

    pt_jnum_f(b, 0.125, 0, 2, 0);
    PT_CHECK("jn-1.1 %.2f of 0.125 rounds half up: 0.13 (printf: 0.12)", !strcmp(b, "0.13"));
    pt_jnum_dtoa(b, 1e-5);
    PT_CHECK("jn-1.2 toString(1e-5) = 1.0E-5", !strcmp(b, "1.0E-5"));
    pt_jnum_dtoa(b, 5e-324);
    PT_CHECK("jn-1.3 toString(MIN_VALUE) = 4.9E-324 (two digits when one is enough)",
             !strcmp(b, "4.9E-324"));
    pt_jnum_dtoa(b, 0x1p-44);
    PT_CHECK("jn-1.4 toString(2^-44): JDK 17's, 5.6843418860808015E-14 (not the shortest)",
             !strcmp(b, "5.6843418860808015E-14"));
    pt_jnum_f(b, -0.0, 10, 5, PT_JNUM_SPACE);
    PT_CHECK("jn-1.5 % 10.5f of -0.0 keeps the sign", !strcmp(b, "  -0.00000"));
    pt_jnum_f(b, 12345.678901, 10, 5, PT_JNUM_SPACE);
    PT_CHECK("jn-1.6 % 10.5f of a wide number: space flag shows", !strcmp(b, " 12345.67890"));
    pt_jnum_f(b, 9.999995, 0, 5, 0);
    PT_CHECK("jn-1.7 carry through every digit: 10.00000", !strcmp(b, "10.00000"));
    pt_jnum_dtoa(b, -0x1p-31);
    PT_CHECK("jn-1.8 toString(-2^-31) = -4.6566128730773926E-10 (clip-edge-right-04's slope)",
             !strcmp(b, "-4.6566128730773926E-10"));
    pt_jnum_dtoa(b, 1e23);
    PT_CHECK("jn-1.9 toString(1e23) = 9.999999999999999E22", !strcmp(b, "9.999999999999999E22"));
    pt_jnum_dtoa(b, 0x1p60);
    PT_CHECK("jn-1.10 toString(2^60) has 18 digits: 1.15292150460684698E18",
             !strcmp(b, "1.15292150460684698E18"));
    pt_jnum_f(b, 1e23, 0, 2, 0);
    PT_CHECK("jn-1.11 %.2f of 1e23 from the same digits: 99999999999999990000000.00",
             !strcmp(b, "99999999999999990000000.00"));
}

/* Split line at '|' into at most n fields. */
static int split(char *line, char **f, int n)
{
    int k = 0;
    char *p = line;

    f[k++] = p;
    while (*p && k < n) {
        if (*p == '|') { *p = '\0'; f[k++] = p + 1; }
        p++;
    }
    p = f[k - 1] + strcspn(f[k - 1], "\r\n");
    *p = '\0';
    return k;
}

static void vectors(const char *path)
{
    static const struct { int width, prec; unsigned flags; } fmts[] = {
        {0, 5, 0}, {10, 5, PT_JNUM_SPACE}, {9, 4, 0}, {0, 4, 0}, {0, 2, 0}};
    char line[4096], b[PT_JNUM_LEN], *f[8], what[600];
    FILE *in = fopen(path, "r");
    int n = 0, bad = 0, k;

    PT_CHECK("jn-2.0 the vectors can be read", in != NULL);
    if (!in) return;
    while (fgets(line, sizeof line, in)) {
        uint64_t bits;
        double x;

        if (split(line, f, 8) != 7) { bad++; continue; }
        bits = strtoull(f[0], NULL, 16);
        memcpy(&x, &bits, sizeof x);
        n++;
        pt_jnum_dtoa(b, x);
        if (strcmp(b, f[1])) {
            snprintf(what, sizeof what, "jn-2.1 toString(%s): %s, Java %s", f[0], b, f[1]);
            PT_CHECK(what, 0);
        }
        for (k = 0; k < 5; k++) {
            pt_jnum_f(b, x, fmts[k].width, fmts[k].prec, fmts[k].flags);
            if (strcmp(b, f[2 + k])) {
                snprintf(what, sizeof what, "jn-2.2 format %d of %s: '%.200s', Java '%.200s'",
                         k, f[1], b, f[2 + k]);
                PT_CHECK(what, 0);
            }
        }
    }
    fclose(in);
    PT_CHECK("jn-2.3 every line has 7 fields", bad == 0);
    PT_CHECK("jn-2.4 more than 4000 vectors", n > 4000);
    PT_CHECK("jn-2.5 all vectors match", pt_test_failed == 0);
}

/* JDK 17's Double.toString where it is not the shortest (jn-3.*). */
static void hard(const char *path)
{
    char line[256], b[PT_JNUM_LEN], *f[3], what[300];
    FILE *in = fopen(path, "r");
    int n = 0, bad = 0, wrong = 0;

    PT_CHECK("jn-3.0 the hard cases can be read", in != NULL);
    if (!in) return;
    while (fgets(line, sizeof line, in)) {
        uint64_t bits;
        double x;

        if (line[0] == '#') continue;
        if (split(line, f, 3) != 2) { bad++; continue; }
        bits = strtoull(f[0], NULL, 16);
        memcpy(&x, &bits, sizeof x);
        n++;
        pt_jnum_dtoa(b, x);
        if (strcmp(b, f[1])) {
            snprintf(what, sizeof what, "jn-3.1 toString(%.20s): %.40s, Java %.40s", f[0], b, f[1]);
            if (wrong++ < 20) PT_CHECK(what, 0);
        }
    }
    fclose(in);
    PT_CHECK("jn-3.2 every line has 2 fields", bad == 0);
    PT_CHECK("jn-3.3 more than 3000 hard cases", n > 3000);
    PT_CHECK("jn-3.4 all hard cases match", wrong == 0);
}

int main(int argc, char **argv)
{
    known_cases();
    vectors(argc > 1 ? argv[1] : "tests/data/jnum-vectors.txt");
    hard(argc > 2 ? argv[2] : "tests/data/jnum-hard.txt");
    return pt_test_report();
}
