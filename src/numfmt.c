/*
** src/numfmt.c -- doubles as text: shortest round-trip, and fixed decimals
** See LICENSE for copyright and license.
**
** Shortest round-trip without a big algorithm: for a normal double, the 15-digit
** rounding, trailing zeros removed, is the shortest string when any string of at
** most 15 digits reads back to x (15 = DBL_DIG: no two such decimals share a
** double, so the one that reads back to x is the 15-digit rounding of x).  Else
** 16 digits: the nearest 16-digit decimal, or failing that (x at a binade edge,
** where the interval is lopsided) its neighbours; else 17, which always works.
** Subnormals carry fewer digits, so for them every precision from 1 is tried.
** printf and strtod here are correctly rounded (glibc, musl) and the program
** never calls setlocale, so the decimal point is '.'.
*/
#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "numfmt.h"

static size_t nonfinite(char *buf, double x)
{
    const char *s = isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";
    strcpy(buf, s);
    return strlen(s);
}

/* x is an integer with |x| < 1e15: write it digit by digit ("-0" for -0.0). */
static size_t int_digits(char *buf, double x)
{
    char b[24], *o = b + sizeof b;
    uint64_t u = (uint64_t)fabs(x);
    size_t n;

    do { *--o = (char)('0' + u % 10); u /= 10; } while (u);
    if (signbit(x)) *--o = '-';
    n = (size_t)(b + sizeof b - o);
    memcpy(buf, o, n);
    buf[n] = '\0';
    return n;
}

static int reads_back(const char *buf, double x)
{
    return strtod(buf, NULL) == x;
}

/* Spell sign, digits d[0..n) times 10^(exp10 - n + 1) the way "%.*g" with
** precision P does: trailing zeros dropped, exponent form when exp10 < -4 or
** exp10 >= P. */
static void g_style(char *buf, int neg, const char *d, int n, int exp10, int P)
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
static int try_neighbours(char *buf, double x)
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
        if (reads_back(t, x)) { g_style(buf, neg, n, 16, ex, 16); return 1; }
    }
    return 0;
}

size_t pt_fmt_shortest(char *buf, double x)
{
    int prec;

    if (!isfinite(x)) return nonfinite(buf, x);
    if (fabs(x) < 1e15 && x == (double)(int64_t)x)  /* an integer: its digits, */
        return int_digits(buf, x);                  /* as %.15g writes them */
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
        if (try_neighbours(buf, x)) return strlen(buf);
    }
    snprintf(buf, PT_NUMLEN, "%.17g", x);
    return strlen(buf);
}

size_t pt_fmt_fixed(char *buf, double x, int prec)
{
    assert(prec >= 0 && prec <= 17);
    if (!isfinite(x)) return nonfinite(buf, x);
    if (fabs(x) >= 1e15) return (size_t)snprintf(buf, PT_NUMLEN, "%.*e", prec, x);
    return (size_t)snprintf(buf, PT_NUMLEN, "%.*f", prec, x);
}
