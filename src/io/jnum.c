/*
** src/io/jnum.c -- doubles as Java prints them: Double.toString and Formatter's %f
** See LICENSE for copyright and license.
**
** Both start from the same decimal: x = d1.d2...dn * 10^e, n <= 17 digits, no
** trailing zero, the digits Double.toString shows (java_digits()).  toString
** spells them; %f rounds them half up at the requested decimal (Java's
** Formatter rounds the decimal string, not the binary value).  The one
** snprintf and strtod here run in the "C" locale, as every program does that
** never calls setlocale (pipetrace does not), so the point is a '.'.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/jnum.h"
#include "io/numfmt.h"

/* ===== Double.toString's digits ===== */

/* Read the decimal s ("123", "0.0015", "1.5e-05", "1e+300", as numfmt spells
** them) into digits dig[0..n) without leading or trailing zeros and exponent
** *e: value = dig[0].dig[1]... * 10^e.  Returns n (0 for zero). */
static int parse_decimal(const char *s, char *dig, int *e)
{
    int n = 0, point = -1, lead = 0, k = 0, exp10 = 0;

    for (; *s && *s != 'e' && *s != 'E'; s++) {
        if (*s < '0' || *s > '9') { point = k; continue; }   /* the point */
        if (n == 0 && *s == '0') { lead++; k++; continue; }  /* leading zero */
        if (n < 17) dig[n++] = *s;
        k++;
    }
    if (*s) exp10 = atoi(s + 1);
    if (point < 0) point = k;                    /* digits before the point */
    while (n > 0 && dig[n - 1] == '0') n--;
    *e = point - lead - 1 + exp10;
    return n;
}

/* The digits of Double.toString(ax), ax > 0 finite: the shortest that read
** back (pt_fmt_shortest), and when that is one digit, the nearest two-digit
** decimal instead if it reads back too (JDK 19's rule).  Returns n. */
static int java_digits(double ax, char *dig, int *e)
{
    char buf[PT_NUMLEN], two[32];
    int n, e2, n2;
    char dig2[20];

    pt_fmt_shortest(buf, ax);
    n = parse_decimal(buf, dig, e);
    if (n != 1) return n;
    snprintf(two, sizeof two, "%.1e", ax);       /* nearest two-digit decimal */
    if (strtod(two, NULL) != ax) return n;       /* does not read back */
    n2 = parse_decimal(two, dig2, &e2);
    memcpy(dig, dig2, (size_t)n2);
    *e = e2;
    return n2;
}

/* ===== Double.toString ===== */

size_t pt_jnum_dtoa(char *buf, double x)
{
    char dig[20];
    size_t len = 0;
    int n, e, k;

    if (isnan(x)) { strcpy(buf, "NaN"); return 3; }
    if (signbit(x)) buf[len++] = '-';
    if (isinf(x)) { strcpy(buf + len, "Infinity"); return len + 8; }
    if (x == 0.0) { strcpy(buf + len, "0.0"); return len + 3; }
    n = java_digits(fabs(x), dig, &e);
    if (e >= -3 && e < 7) {                      /* 1e-3 <= |x| < 1e7: plain */
        if (e < 0) {
            buf[len++] = '0';
            buf[len++] = '.';
            for (k = -1; k > e; k--) buf[len++] = '0';
            for (k = 0; k < n; k++) buf[len++] = dig[k];
        } else {
            for (k = 0; k <= e; k++) buf[len++] = k < n ? dig[k] : '0';
            buf[len++] = '.';
            if (n <= e + 1) buf[len++] = '0';
            for (k = e + 1; k < n; k++) buf[len++] = dig[k];
        }
        buf[len] = '\0';
        return len;
    }
    buf[len++] = dig[0];                         /* else d.dddE-n */
    buf[len++] = '.';
    if (n == 1) buf[len++] = '0';
    for (k = 1; k < n; k++) buf[len++] = dig[k];
    len += (size_t)sprintf(buf + len, "E%d", e);
    return len;
}

/* ===== Formatter's %f ===== */

size_t pt_jnum_f(char *buf, double x, int width, int prec, unsigned flags)
{
    char body[PT_JNUM_LEN], dig[20];
    size_t len = 0, k;
    int n, e, i, neg = signbit(x) != 0;

    if (isnan(x)) { strcpy(body, "NaN"); len = 3; }
    else {
        if (neg) body[len++] = '-';
        else if (flags & PT_JNUM_SPACE) body[len++] = ' ';
        if (isinf(x)) { strcpy(body + len, "Infinity"); len += 8; }
        else {
            /* r[0..nr): the digits of |x| from 10^top down to 10^-prec */
            char r[PT_JNUM_LEN];
            int top, nr;

            n = x == 0.0 ? 0 : java_digits(fabs(x), dig, &e);
            if (n == 0) e = 0;
            top = e > 0 ? e : 0;
            nr = top + 1 + prec;
            for (i = 0; i < nr; i++) {           /* digit of 10^(top - i) */
                int pos = e - (top - i);         /* its index in dig */
                r[i] = pos >= 0 && pos < n ? dig[pos] : '0';
            }
            /* half up: look at the first digit dropped, 10^-(prec+1) */
            i = e - (top - nr);
            if (n > 0 && i >= 0 && i < n && dig[i] >= '5') {
                for (i = nr - 1; i >= 0; i--) {
                    if (r[i] != '9') { r[i]++; break; }
                    r[i] = '0';
                }
                if (i < 0) {                     /* 9.99 -> 10.00 */
                    memmove(r + 1, r, (size_t)nr);
                    r[0] = '1';
                    nr++;
                    top++;
                }
            }
            for (i = 0; i <= top; i++) body[len++] = r[i];
            if (prec > 0) {
                body[len++] = '.';
                for (i = top + 1; i < nr; i++) body[len++] = r[i];
            }
        }
    }
    k = 0;
    while ((int)(len + k) < width) buf[k++] = ' ';
    memcpy(buf + k, body, len);
    buf[k + len] = '\0';
    return k + len;
}
