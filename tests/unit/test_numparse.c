/*
** tests/unit/test_numparse.c -- pt_parse_decimal() against strtod(), bit for bit
** See LICENSE for copyright and license.
**
** Usage: test_numparse [N].  Ids:
**   numparse-1  the syntax: what is a decimal number and what is not
**   numparse-2  edges: signed zeros, 2^53, 10^22, 19 and 20 digits, the
**               largest and smallest doubles, overflow, underflow
**   numparse-3  N random strings of each kind (default 40,000): the digits of
**               doubles printed %.6f, %.17g and %.Ne; random digit strings
**               with a random point and exponent; the exact halfway points
**               between neighbouring doubles (printed %.800Le from a long
**               double), and a digit either side of them
** Every string is checked against strtod() bit for bit; `make bench` runs
** 2,000,000 of each kind.
*/
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testhelp.h"
#include "core/numparse.h"

static uint64_t state = 0x9E3779B97F4A7C15u;

static uint64_t next(void)   /* xorshift64* */
{
    state ^= state >> 12; state ^= state << 25; state ^= state >> 27;
    return state * 2685821657736338717u;
}

/* A double with random bits: every finite value, subnormals included. */
static double any_double(void)
{
    uint64_t b;
    double d;

    do {
        b = next();
        memcpy(&d, &b, sizeof d);
    } while (d != d || d - d != 0);     /* not NaN, not infinite */
    return d;
}

static long mismatches;

/* Is pt_parse_decimal(s) strtod(s), bit for bit? */
static int same(const char *s)
{
    double a = 0, b = strtod(s, NULL);

    if (pt_parse_decimal(s, strlen(s), &a) != 0 || memcmp(&a, &b, sizeof a) != 0) {
        if (mismatches++ < 10) printf("  mismatch: %s: %.17g, strtod %.17g\n", s, a, b);
        return 0;
    }
    return 1;
}

static int all_same(const char *const *s, size_t n)
{
    size_t i;
    int ok = 1;

    for (i = 0; i < n; i++) ok &= same(s[i]);
    return ok;
}

int main(int argc, char **argv)
{
    static const char *const bad[] = {
        "", "+", "-", ".", "+.", "e5", ".e5", "1e", "1e+", "1e-", "1.2.3", "0x10", "inf",
        "nan", "1f", "1,5", " 1", "1 ", "--1", "+-1", "1e5.0", "1e++5", "1.5e", "١"};
    static const char *const good[] = {
        "0", "1.", ".5", "+.5e-3", "5E2", "-7", "000.000", "1e0", "1E-0", "+0e+0"};
    static const char *const edges[] = {
        "0", "-0", "+0", "-0.0", "-0e400", "0e-400", "-.0e-5", "9007199254740992",
        "9007199254740993", "9007199254740994", "9007199254740995", "-9007199254740993",
        "900719925474099.3", "1e22", "1e23", "1e-22", "1e-23", "9007199254740992e22",
        "9007199254740992e-22", "1e37", "123456789e28", "9007199254740993e15",
        "1234567890123456789", "12345678901234567890", "1234567890123456789e-22",
        "0.1234567890123456789", "0.12345678901234567891", "1.000000000000000000000",
        "1.0000000000000000000001", "100000000000000000000000000000", "3.0000000000000000000",
        "0.000000000000000000000000000000000000000001", "1.7976931348623157e308",
        "1.7976931348623158e308", "1.7976931348623159e308", "1e309", "-1e309",
        "2.2250738585072014e-308", "2.2250738585072011e-308", "4.9406564584124654e-324",
        "2.4703282292062327e-324", "2.4703282292062328e-324", "1e-400", "-1e-400",
        "1e99999999999999999999", "1e-99999999999999999999", "0.1", "0.2", "0.3",
        "-1.200000", "2.001", "1.5", "2.5", "0.5", "4503599627370496.5",
        "4503599627370497.5", "9007199254740993.0000000000000000000001"};
    long n = argc > 1 ? atol(argv[1]) : 40000, i;
    char buf[1024];
    size_t k;
    int ok;
    double d;

    ok = 1;
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++)
        ok &= pt_parse_decimal(bad[k], strlen(bad[k]), &d) == -1;
    PT_CHECK("numparse-1.1 not decimal numbers: hex, inf, nan, spaces, signs, lone e", ok);
    PT_CHECK("numparse-1.2 a NUL inside is not part of a number",
             pt_parse_decimal("1\0" "5", 3, &d) == -1);
    PT_CHECK("numparse-1.3 decimal numbers without digits on one side of the point",
             all_same(good, sizeof good / sizeof good[0]));
    PT_CHECK("numparse-1.4 the text need not end in a NUL: \"2.5\" of \"2.57\"",
             pt_parse_decimal("2.57", 3, &d) == 0 && d == 2.5);
    mismatches = 0;
    PT_CHECK("numparse-2.1 edges: zeros, 2^53, 10^22, 19/20 digits, extremes",
             all_same(edges, sizeof edges / sizeof edges[0]));
    PT_CHECK("numparse-2.2 -0 keeps its sign",
             pt_parse_decimal("-0.000", 6, &d) == 0 && d == 0 && 1 / d < 0);
    memset(buf, '9', 300);
    buf[0] = '.';
    buf[300] = '\0';
    PT_CHECK("numparse-2.3 a number of 300 bytes (strtod's path, with a copy)", same(buf));

    ok = 1;
    for (i = 0; i < n; i++) {                       /* as exporters write them */
        double x = any_double();
        double y = (double)(int64_t)(next() % 2000001) / 1000.0 - 1000.0;
        snprintf(buf, sizeof buf, "%.6f", y * (double)(next() % 1000) / 7.0);
        ok &= same(buf);
        snprintf(buf, sizeof buf, "%.17g", x);
        ok &= same(buf);
        snprintf(buf, sizeof buf, "%.*e", (int)(next() % 25), x);
        ok &= same(buf);
    }
    PT_CHECK("numparse-3.1 printed doubles: %.6f, %.17g, %.Ne", ok);
    ok = 1;
    for (i = 0; i < n; i++) {                       /* random digits */
        int nd = 1 + (int)(next() % 24), dot = (int)(next() % (uint64_t)(nd + 1)), j, at = 0;
        if (next() % 2) buf[at++] = "+-"[next() % 2];
        for (j = 0; j < nd; j++) {
            if (j == dot) buf[at++] = '.';
            buf[at++] = (char)('0' + (j == 0 && next() % 4 ? 1 + next() % 9 : next() % 10));
        }
        if (next() % 3) at += sprintf(buf + at, "e%d", (int)(next() % 700) - 350);
        buf[at] = '\0';
        ok &= same(buf);
    }
    PT_CHECK("numparse-3.2 random digit strings, points and exponents", ok);
    ok = 1;
    for (i = 0; i < n / 10; i++) {                  /* halfway between two doubles */
        double x = any_double(), y;
        long double mid;
        size_t len;
        if (x < 0) x = -x;
        y = nextafter(x, DBL_MAX);
        mid = ((long double)x + (long double)y) / 2;  /* exact: 64-bit significand */
        snprintf(buf, sizeof buf, "%.800Le", mid);
        ok &= same(buf);
        len = strcspn(buf, "e");
        while (len > 2 && buf[len - 1] == '0') len--;  /* the last nonzero digit */
        if (buf[len - 1] > '0' && buf[len - 1] <= '9') {
            buf[len - 1]--;                          /* just below the halfway point */
            ok &= same(buf);
        }
    }
    PT_CHECK("numparse-3.3 exact halfway points and a digit below", ok);
    if (mismatches) printf("  %ld mismatches in all\n", mismatches);
    return pt_test_report();
}
