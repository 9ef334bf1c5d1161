/*
** tests/unit/test_numfmt.c -- shortest round-trip and fixed formatting of doubles
** See LICENSE for copyright and license.
**
** pt_fmt_shortest() computes its digits exactly (src/io/numfmt.c).  The oracle
** below is the printf-and-strtod search it replaced: slow, but its correctness
** rests only on a correctly rounded printf and strtod.  Every value tested must
** be spelled byte for byte as the oracle spells it, and read back bit for bit.
** pt_fmt_fixed() likewise: its oracle is the snprintf("%.*f") it replaced, and
** every value below is compared at every precision 0..17.  Random values come
** from a fixed-seed xorshift, so every run tests the same.  `test_numfmt N`
** runs N times as many random values for pt_fmt_fixed (a longer, one-off check).
*/
#include <float.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "io/numfmt.h"

/* ===== the oracle: pt_fmt_shortest as it was, by printf and strtod ===== */

/* Shortest round-trip without a big algorithm: for a normal double, the 15-digit
** rounding, trailing zeros removed, is the shortest string when any string of at
** most 15 digits reads back to x (15 = DBL_DIG: no two such decimals share a
** double, so the one that reads back to x is the 15-digit rounding of x).  Else
** 16 digits: the nearest 16-digit decimal, or failing that (x at a binade edge,
** where the interval is lopsided) its neighbours; else 17, which always works.
** Subnormals carry fewer digits, so for them every precision from 1 is tried. */

static size_t oracle_nonfinite(char *buf, double x)
{
    const char *s = isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
    strcpy(buf, s);
    return strlen(s);
}

/* x is an integer with |x| < 1e15: by printf, like the rest of the oracle
** (numfmt.c writes it digit by digit; "%.0f" is exact here and writes -0.0 as
** "-0" too), so that the test does not check numfmt.c against a copy of
** itself. */
static size_t oracle_int_digits(char *buf, double x)
{
    return (size_t)snprintf(buf, PT_NUMLEN, "%.0f", x);
}

static int reads_back(const char *buf, double x)
{
    return strtod(buf, NULL) == x;
}

/* Spell sign, digits d[0..n) times 10^(exp10 - n + 1) the way "%.*g" with
** precision P does: trailing zeros dropped, exponent form when exp10 < -4 or
** exp10 >= P. */
static void oracle_g_style(char *buf, int neg, const char *d, int n, int exp10, int P)
{
    char *o = buf;
    int k;

    while (n > 1 && d[n - 1] == '0') n--;
    if (neg) *o++ = '-';
    if (exp10 < -4 || exp10 >= P) {
        *o++ = d[0];
        if (n > 1) { *o++ = '.'; memcpy(o, d + 1, (size_t)n - 1); o += n - 1; }
        sprintf(o, "e%c%02d", exp10 < 0 ? '-' : '+', exp10 < 0 ? -exp10 : exp10);
        return;
    }
    if (exp10 < 0) {                        /* 0.000ddd */
        *o++ = '0'; *o++ = '.';
        for (k = -1; k > exp10; k--) *o++ = '0';
        memcpy(o, d, (size_t)n); o += n;
    } else {                                /* ddd.ddd */
        for (k = 0; k <= exp10; k++) *o++ = k < n ? d[k] : '0';
        if (n > exp10 + 1) {
            *o++ = '.';
            memcpy(o, d + exp10 + 1, (size_t)(n - exp10 - 1));
            o += n - exp10 - 1;
        }
    }
    *o = '\0';
}

/* The two 16-digit decimals next to the nearest one (which did not read back):
** at a power of two the interval that reads back to x is lopsided, and the
** second-nearest decimal may lie inside it.  Returns 1 with buf filled. */
static int oracle_neighbours(char *buf, double x)
{
    char e[PT_NUMLEN], d[17], t[PT_NUMLEN];
    int neg, exp10, step, i;

    snprintf(e, sizeof e, "%.15e", x);      /* [-]d.ddddddddddddddde[+-]XX */
    neg = e[0] == '-';
    d[0] = e[neg];
    memcpy(d + 1, e + neg + 2, 15);
    d[16] = '\0';
    exp10 = atoi(e + neg + 18);
    for (step = -1; step <= 1; step += 2) {
        char n[17];
        int ex = exp10;
        memcpy(n, d, 17);
        for (i = 15; i >= 0; i--) {         /* n += step in the last digit */
            int c = n[i] - '0' + step;
            if (c >= 0 && c <= 9) { n[i] = (char)('0' + c); break; }
            n[i] = step > 0 ? '0' : '9';
        }
        if (i < 0 && step > 0) { memmove(n + 1, n, 15); n[0] = '1'; ex++; }
        if (n[0] == '0') { memmove(n, n + 1, 15); n[15] = '9'; ex--; }
        snprintf(t, sizeof t, "%s%c.%.15se%d", neg ? "-" : "", n[0], n + 1, ex);
        if (reads_back(t, x)) { oracle_g_style(buf, neg, n, 16, ex, 16); return 1; }
    }
    return 0;
}

static size_t oracle_shortest(char *buf, double x)
{
    int prec;

    if (!isfinite(x)) return oracle_nonfinite(buf, x);
    if (fabs(x) < 1e15 && x == (double)(int64_t)x)  /* an integer: its digits, */
        return oracle_int_digits(buf, x);           /* as %.15g writes them */
    if (x != 0 && fabs(x) < DBL_MIN) {      /* subnormal: search from 1 digit */
        for (prec = 1; prec < 17; prec++) {
            snprintf(buf, PT_NUMLEN, "%.*g", prec, x);
            if (reads_back(buf, x)) return strlen(buf);
        }
    } else {
        snprintf(buf, PT_NUMLEN, "%.15g", x);
        if (reads_back(buf, x)) return strlen(buf);
        snprintf(buf, PT_NUMLEN, "%.16g", x);
        if (reads_back(buf, x)) return strlen(buf);
        if (oracle_neighbours(buf, x)) return strlen(buf);
    }
    snprintf(buf, PT_NUMLEN, "%.17g", x);
    return strlen(buf);
}

/* ===== the oracle for pt_fmt_fixed: printf itself ===== */

static size_t oracle_fixed(char *buf, double x, int prec)
{
    if (!isfinite(x)) return oracle_nonfinite(buf, x);
    if (fabs(x) >= 1e15) return (size_t)snprintf(buf, PT_NUMLEN, "%.*e", prec, x);
    return (size_t)snprintf(buf, PT_NUMLEN, "%.*f", prec, x);
}

/* ===== helpers ===== */

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

static uint64_t rng = 88172645463325252ULL;

static uint64_t next_random(void)           /* xorshift64 (Marsaglia 2003) */
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return rng;
}

/* A group of values compared with the oracle: how many, how many differ. */
static long group_n, group_bad;

/* x spelled as the oracle spells it, and read back bit for bit. */
static void agrees(double x)
{
    char got[PT_NUMLEN], want[PT_NUMLEN];
    size_t n = pt_fmt_shortest(got, x);
    double y = strtod(got, NULL);
    int ok;

    oracle_shortest(want, x);
    ok = strcmp(got, want) == 0 && n == strlen(got) && n <= PT_SHORTLEN &&
         (isnan(x) || memcmp(&x, &y, sizeof x) == 0);
    group_n++;
    if (!ok && group_bad++ < 5)
        printf("  %a spelled '%s', oracle '%s', reads back %a\n", x, got, want, y);
}

static void agrees_pm(double x) { agrees(x); agrees(-x); }

/* Ends a group: prints its size, returns 1 when every value agreed. */
static int group_done(const char *what)
{
    int ok = group_bad == 0;
    printf("%-52s %8ld values, %ld differ\n", what, group_n, group_bad);
    group_n = group_bad = 0;
    return ok;
}

static void agrees_around(double x, int ulps)   /* +-x and neighbours */
{
    double lo = x, hi = x;
    int k;

    agrees_pm(x);
    for (k = 0; k < ulps; k++) {
        lo = nextafter(lo, -(double)INFINITY);
        hi = nextafter(hi, (double)INFINITY);
        agrees_pm(lo);
        agrees_pm(hi);
    }
}

/* x spelled as the oracle spells it at every precision 0..17: one value. */
static void fixed_agrees(double x)
{
    char got[PT_NUMLEN], want[PT_NUMLEN];
    int prec, bad = 0;

    for (prec = 0; prec <= 17; prec++) {
        size_t n = pt_fmt_fixed(got, x, prec);
        oracle_fixed(want, x, prec);
        if (strcmp(got, want) == 0 && n == strlen(got)) continue;
        if (!bad++ && group_bad < 5)
            printf("  %a at %d spelled '%s', oracle '%s'\n", x, prec, got, want);
    }
    group_n++;
    group_bad += bad != 0;
}

static void fixed_agrees_pm(double x) { fixed_agrees(x); fixed_agrees(-x); }

static double random_sign(double x) { return next_random() & 1 ? -x : x; }

/* A uniform random double in [0, 1). */
static double random_unit(void) { return (double)(next_random() >> 11) * 0x1p-53; }

/* A small decimal: +-d / 10^p with d < 10^4, p < 4 ("12.5", "-0.07"). */
static double small_decimal(void)
{
    static const double scale[4] = { 1, 10, 100, 1000 };
    uint64_t r = next_random();
    double d = (double)(r % 10000) / scale[r >> 20 & 3];
    return r >> 30 & 1 ? -d : d;
}

/* pt_fmt_u64() and pt_fmt_ulen() against "%" PRIu64: x and its neighbours. */
static int u64_agrees(uint64_t x)
{
    char got[PT_NUMLEN], want[PT_NUMLEN];
    int d, ok = 1;

    for (d = -1; d <= 1; d++) {
        uint64_t y = x + (uint64_t)(int64_t)d;
        size_t n = pt_fmt_u64(got, y);
        snprintf(want, sizeof want, "%" PRIu64, y);
        if (n != strlen(want) || pt_fmt_ulen(y) != n || memcmp(got, want, n) != 0) {
            if (ok) printf("  %s spelled '%.*s'\n", want, (int)n, got);
            ok = 0;
        }
    }
    return ok;
}

int main(int argc, char **argv)
{
    char b[PT_NUMLEN];
    int k, j, round_trips = 1, shortest = 1;
    long scale = argc > 1 ? atol(argv[1]) : 1, i;  /* pt_fmt_fixed: random values times scale */

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
    PT_CHECK("num-1.11 largest double", spells(DBL_MAX, "1.7976931348623157e+308"));
    PT_CHECK("num-1.16 the longest spelling is PT_SHORTLEN bytes",
             pt_fmt_shortest(b, -2.2250738585072014e-308) == PT_SHORTLEN);
    {   /* every length 1..17 with the point at every place of the fixed
        ** form, and on either side of it: digits 1..9 cycled, and all 9s */
        static const char *const fill[] = {"12345678912345678", "98765432198765432",
                                           "99999999999999999", "10000000000000001"};
        char s[64];
        int f;
        for (f = 0; f < 4; f++)
            for (k = 1; k <= 17; k++)
                for (j = -7; j <= 18; j++) {
                    snprintf(s, sizeof s, "%.*se%d", k, fill[f], j - k + 1);
                    agrees_pm(strtod(s, NULL));
                }
        PT_CHECK("num-1.18 1..17 digits, the point before, in and after them",
                 group_done("num-1.18 1..17 digits, every place of the point"));
    }
    PT_CHECK("num-1.12 1e15 and 1e16 switch to exponent form",
             spells(1e15, "1e+15") && spells(1e16, "1e+16") && spells(999999999999999, "999999999999999"));
    PT_CHECK("num-1.13 exponent form below 1e-4",
             spells(0.0001, "0.0001") && spells(0.00001, "1e-05") && spells(1.5e-5, "1.5e-05"));
    PT_CHECK("num-1.14 17-digit tie, even digit kept", spells(1234567890123456.25, "1234567890123456.2"));
    PT_CHECK("num-1.15 exact integers above 2^64", spells(1e20, "1e+20") && spells(1e22, "1e+22") &&
             spells(123456789012345678e5, "1.2345678901234568e+22"));
    for (k = 0; k < 30000; k++) {           /* every kind of double */
        uint64_t r = next_random();
        double x = from_bits(k % 5 == 0 ? r & 0xfff0000000000000ULL :   /* powers of 2 */
                             k % 5 == 1 ? r & 0x800fffffffffffffULL :   /* subnormals */
                             r);
        if (!isfinite(x)) continue;
        pt_fmt_shortest(b, x);
        if (strtod(b, NULL) != x) round_trips = 0;
        if (strlen(b) > slow_shortest_len(x)) shortest = 0;
    }
    PT_CHECK("num-2.1 30000 doubles read back exactly", round_trips);
    PT_CHECK("num-2.2 ... and are never longer than the shortest %g", shortest);

    /* Every group below: x and -x, spelled as the oracle does, read back. */
    for (k = -1074; k <= 1023; k++) agrees_around(ldexp(1, k), 2);
    PT_CHECK("num-4.1 powers of two, 2 ulps either side",
             group_done("num-4.1 powers of two +- 2 ulps"));
    for (k = -323; k <= 308; k++) {
        char s[16];
        snprintf(s, sizeof s, "1e%d", k);
        agrees_around(strtod(s, NULL), 2);
        for (j = 2; j <= 9; j++) agrees_pm(j * strtod(s, NULL));
    }
    PT_CHECK("num-4.2 powers of ten, 2 ulps either side, and 2..9 times them",
             group_done("num-4.2 powers of ten +- 2 ulps, 2..9 times"));
    for (k = -1074; k <= 1023; k++) {       /* each binade's low end: lopsided */
        for (j = 0; j < 16; j++) {
            agrees_pm(ldexp(1 + j * DBL_EPSILON, k));
            agrees_pm(ldexp(1 - j * DBL_EPSILON / 2, k));
        }
    }
    PT_CHECK("num-4.3 binade edges (lopsided intervals), 16 ulps either side",
             group_done("num-4.3 binade edges +- 16 ulps"));
    agrees_around(DBL_TRUE_MIN, 1000);
    agrees_around(DBL_MIN, 1000);
    for (k = 1; k <= 20000; k++) agrees(from_bits(next_random() & 0x800fffffffffffffULL));
    for (k = 1; k <= 1000; k++) agrees_pm(from_bits((uint64_t)k));
    PT_CHECK("num-4.4 subnormals: smallest, largest, random, few bits",
             group_done("num-4.4 subnormals"));
    for (k = -3000; k <= 3000; k++) {
        agrees_pm(1e15 + k);
        agrees_pm(1e15 + k / 8.0);
        agrees_pm(9007199254740992.0 + 2 * k);             /* 2^53 */
        agrees_pm(9007199254740992.0 + k / 2.0);
        agrees_pm(1e16 + 2 * k);
        agrees_pm(1e17 + 16 * k);
    }
    agrees_around(1e15, 100);
    agrees_around(9007199254740992.0, 100);
    agrees_around(DBL_MAX, 100);
    agrees_pm(0.0);
    PT_CHECK("num-4.5 integers near 1e15, 2^53, 1e16, 1e17; the largest doubles; +-0",
             group_done("num-4.5 near 1e15, 2^53, 1e16, 1e17, DBL_MAX; 0"));
    /* x = n 2^-k = n 5^k 10^-k, n odd, has exactly digits(n 5^k) significant
    ** digits, the last a 5: a tie when rounded to one digit fewer. */
    for (j = 16; j <= 18; j++) {            /* ties at 15, 16, 17 digits */
        for (k = 1; k <= 25; k++) {
            double lo = pow(10, j - 1) / pow(5, k), hi = pow(10, j) / pow(5, k);
            int tries;
            if (lo > 9007199254740991.0) continue;
            if (hi > 9007199254740991.0) hi = 9007199254740991.0;
            for (tries = 0; tries < 400; tries++) {
                double n = floor(lo + (hi - lo) * (double)(next_random() >> 11) * 0x1p-53);
                if (fmod(n, 2) == 0) n += 1;
                if (n >= hi || n < lo) continue;
                agrees_pm(ldexp(n, -k));
                agrees_pm(ldexp(n, -k) * 1e-20);           /* not ties: nearby shapes */
            }
        }
    }
    PT_CHECK("num-4.6 exact decimals that tie at 15, 16, 17 digits",
             group_done("num-4.6 ties at 15, 16, 17 digits"));
    for (k = 0; k < 2000000; k++) {
        double x = from_bits(next_random());
        agrees(x);
    }
    PT_CHECK("num-4.7 random bit patterns", group_done("num-4.7 random bit patterns"));
    for (k = 0; k < 1000000; k++) {
        double a = small_decimal(), c = small_decimal(), d = small_decimal();
        agrees(k % 2 ? a / c * d : a * c + d);
    }
    PT_CHECK("num-4.8 typical values: a/b*c, a*b+c of small decimals",
             group_done("num-4.8 a/b*c, a*b+c of small decimals"));
    /* numfmt.c's short_decimal() path: decimals of 1 to 17 digits over its
    ** range (about 2e-9 .. 1.4e14) and past both ends, with a neighbour each. */
    for (k = 0; k < 300000; k++) {
        uint64_t r = next_random(), d = next_random() % 100000000000000000ULL;
        int digits = 1 + (int)(r % 17), exp10 = (int)(r >> 8 & 31) - 12;   /* -12 .. 19 */
        char s[48];
        double x;
        for (j = digits; j < 17; j++) d /= 10;  /* d has at most that many digits */
        snprintf(s, sizeof s, "%" PRIu64 "e%d", d, exp10 - digits + 1);
        x = strtod(s, NULL);
        agrees_pm(x);
        agrees(nextafter(x, (double)INFINITY));
    }
    PT_CHECK("num-4.9 decimals of 1..17 digits from 1e-12 to 1e19, and their neighbours",
             group_done("num-4.9 decimals of 1..17 digits, 1e-12 .. 1e19"));
    /* numfmt.c's fixed_form(): doubles of every binade from 2^-15 to 2^51
    ** (0.000ddd and ddd.ddd, and both ends of each), and 64 ulps around the
    ** powers of ten where the form or its leading zeros change. */
    for (k = 0; k < 300000; k++) {
        uint64_t r = next_random();
        agrees_pm(ldexp(1 + (double)(r >> 11) * 0x1p-53, (int)(r % 67) - 15));
    }
    {
        static const double edges[] = { 1e-4, 1e-3, 1e-2, 1e-1, 1, 10, 1e4, 1e15 };
        for (k = 0; k < (int)(sizeof edges / sizeof edges[0]); k++) agrees_around(edges[k], 64);
    }
    PT_CHECK("num-4.10 the fixed forms: every binade from 2^-15 to 2^51, and where they change",
             group_done("num-4.10 fixed forms, 2^-15 .. 2^51, their edges +- 64 ulps"));

    {
        uint64_t p = 1;
        int ok = u64_agrees(0) && u64_agrees(UINT64_MAX) && u64_agrees(UINT64_MAX - 1);
        for (k = 0; k < 20; k++, p *= 10) ok &= u64_agrees(p);    /* 10^k - 1, 10^k, + 1 */
        PT_CHECK("num-6.1 integers: 0, 10^k +- 1, the largest, as %" PRIu64 " writes them", ok);
        for (k = 0; k < 100000; k++) ok &= u64_agrees(next_random() >> (next_random() % 64));
        PT_CHECK("num-6.2 integers: 100000 random ones of every length", ok);
    }
    {
        static pt_digits4 t;
        char got[PT_NUMLEN], want[PT_NUMLEN];
        uint32_t x;
        int ok = 1;

        pt_digits4_init(&t);
        static const uint32_t edges[] = {999999, 1000000, 9999999, 10000000, 99999999};
        for (x = 0; x < 100000000; x += x < 200000 ? 1 : 997) {   /* every one below */
            size_t n = pt_fmt_u32_tab(&t, got, x), m = pt_fmt_u64(want, x);   /* 200000 */
            if (n != m || memcmp(got, want, n) != 0) ok = 0;
        }
        for (k = 0; k < 5; k++) {
            size_t n = pt_fmt_u32_tab(&t, got, edges[k]), m = pt_fmt_u64(want, edges[k]);
            if (n != m || memcmp(got, want, n) != 0) ok = 0;
        }
        PT_CHECK("num-6.3 integers below 10^8 from the digit table: pt_fmt_u64()'s digits", ok);
    }

    pt_fmt_fixed(b, 5.497501249375313, 6);
    PT_CHECK("num-3.1 fixed, 6 digits", strcmp(b, "5.497501") == 0);
    pt_fmt_fixed(b, -0.5, 0);
    PT_CHECK("num-3.2 fixed, 0 digits rounds half to even", strcmp(b, "-0") == 0);
    pt_fmt_fixed(b, 1e300, 3);
    PT_CHECK("num-3.3 huge values switch to exponent form", strcmp(b, "1.000e+300") == 0);
    pt_fmt_fixed(b, -(double)INFINITY, 3);
    PT_CHECK("num-3.4 fixed non-finite", strcmp(b, "-inf") == 0);
    pt_fmt_fixed(b, 0.125, 2);
    PT_CHECK("num-3.5 fixed, a tie goes to the even digit: 0.125 -> 0.12", strcmp(b, "0.12") == 0);
    pt_fmt_fixed(b, 2.5, 0);
    PT_CHECK("num-3.6 fixed, 2.5 -> 2, 1.5 -> 2",
             strcmp(b, "2") == 0 && pt_fmt_fixed(b, 1.5, 0) == 1 && strcmp(b, "2") == 0);
    pt_fmt_fixed(b, -1e-10, 6);
    PT_CHECK("num-3.7 fixed, a negative that rounds to 0 keeps its sign",
             strcmp(b, "-0.000000") == 0);
    pt_fmt_fixed(b, 999999999999999.5, 0);
    PT_CHECK("num-3.8 fixed, the carry past 15 digits", strcmp(b, "1000000000000000") == 0);

    /* Every group below: each value at every precision 0..17, as printf spells it. */
    fixed_agrees_pm(0.0);
    for (k = 1; k <= 18; k++)               /* odd j / 2^k ties at precision k - 1 */
        for (j = 1; j < 256; j += 2) fixed_agrees_pm(ldexp(j, -k));
    for (k = 0; k <= 17; k++) {             /* d.dd..d5 with k + 1 decimals: a tie at k */
        for (i = 0; i < 500 * scale; i++) {     /* odd m / 2^(k+1), m of 1..53 bits */
            uint64_t m = next_random(), bits = 1 + next_random() % 53;
            double x = ldexp((double)((m >> (64 - bits)) | 1), -(k + 1));
            if (fabs(x) >= 1e15) continue;
            fixed_agrees(random_sign(x));
            fixed_agrees(random_sign(nextafter(x, 0)));      /* just below, just above */
            fixed_agrees(random_sign(nextafter(x, 1e300)));
        }
    }
    PT_CHECK("num-5.1 exact ties j/2^k (0.5, 1.5, 2.5, 0.125, 0.375, ...), +-1 ulp",
             group_done("num-5.1 ties j/2^k, +-1 ulp"));
    for (i = 0; i < 90000 * scale; i++) {   /* bit patterns, 1e-20 <= |x| < 1e15 */
        uint64_t r = next_random(), e = 956 + r % 117;   /* 2^-67 .. 2^49 */
        double x = from_bits((r & 0x800fffffffffffffULL) | e << 52);
        if (fabs(x) < 1e15) fixed_agrees(x);
    }
    PT_CHECK("num-5.2 random bit patterns, 1e-20 <= |x| < 1e15",
             group_done("num-5.2 random bit patterns 1e-20..1e15"));
    for (i = 0; i < 90000 * scale; i++) {   /* d / 10^p: 1..17 digits, p = 0..20 */
        static const double p10[21] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9,
            1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20};
        uint64_t r = next_random();
        double d = floor(random_unit() * p10[1 + r % 17]), x = d / p10[(r >> 8) % 21];
        if (x < 1e15) fixed_agrees(random_sign(x));
    }
    PT_CHECK("num-5.3 decimals d / 10^p (d of 1..17 digits, p <= 20)",
             group_done("num-5.3 decimals d / 10^p"));
    for (i = 0; i < 45000 * scale; i++) {   /* uniform in [0, 10^k), k = -20..15 */
        double u = random_unit(), x = u * pow(10, (double)(next_random() % 36) - 20);
        fixed_agrees(random_sign(x));
    }
    PT_CHECK("num-5.4 uniform in [0, 10^k), k = -20..15",
             group_done("num-5.4 uniform in [0, 10^k)"));
    {
        double lo = 1e15, hi = 0x1p-20;
        for (k = 0; k < 2000; k++) {        /* below 1e15; above 2^-20 ~ 1e-6 */
            lo = nextafter(lo, 0);
            fixed_agrees_pm(lo);
            fixed_agrees_pm(hi);
            hi = nextafter(hi, 1);
        }
    }
    for (k = 0; k < 2000; k++) fixed_agrees_pm(1e15 - 1 - k / 8.0);
    for (k = 1; k <= 1000; k++) fixed_agrees_pm(from_bits((uint64_t)k));     /* tiniest */
    for (i = 0; i < 2000 * scale; i++)
        fixed_agrees(from_bits(next_random() & 0x800fffffffffffffULL));      /* subnormals */
    for (k = -1074; k < 50; k++) fixed_agrees_pm(ldexp(1, k));               /* 2^k */
    fixed_agrees_pm(DBL_MIN);
    fixed_agrees_pm(1e15);                  /* exponent form from here */
    fixed_agrees_pm(DBL_MAX);
    fixed_agrees_pm((double)INFINITY);
    fixed_agrees((double)NAN);
    PT_CHECK("num-5.5 just below 1e15, above 2^-20, subnormals, 2^k, 1e15 up, non-finite",
             group_done("num-5.5 edges: 1e15, 0, subnormals, 2^k"));
    return pt_test_report();
}
