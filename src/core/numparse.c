/*
** src/core/numparse.c -- decimal text -> the nearest double, fast for ordinary numbers
** See LICENSE for copyright and license.
*/
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "core/numparse.h"

/* 10^0 .. 10^22: every one a double exactly (10^22 = 2^22 * 5^22, 5^22 < 2^53). */
static const double ten_to[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13,
    1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

#define MAX_DIGITS 19            /* significant digits a uint64_t always holds */
#define EXP_CAP    100000        /* exponents saturate here: far past any double */
#define TWO53      (UINT64_C(1) << 53)

/* The slow path: strtod() on a NUL-terminated copy.  Returns 0 or -2. */
static int slow(const char *p, size_t n, double *out)
{
    char small[128], *buf = small;

    if (n >= sizeof small && (buf = malloc(n + 1)) == NULL) return -2;
    memcpy(buf, p, n);
    buf[n] = '\0';
    *out = strtod(buf, NULL);           /* "C" locale: '.' is the decimal point */
    if (buf != small) free(buf);
    return 0;
}

int pt_parse_decimal(const char *p, size_t n, double *out)
{
    const char *s = p, *e = p + n;
    uint64_t m = 0;                     /* the significant digits kept */
    int neg = 0, kept = 0, exact = 1;   /* exact: no nonzero digit dropped */
    int64_t k = 0;                      /* value = m * 10^k */
    size_t before = 0, after = 0;       /* digits before and after the point */
    double d;

    if (s < e && (*s == '+' || *s == '-')) neg = *s++ == '-';
    for (; s < e && (unsigned)(*s - '0') < 10; s++, before++) {
        if (kept < MAX_DIGITS) {
            m = m * 10 + (uint64_t)(*s - '0');
            kept += m != 0;             /* leading zeros are not significant */
        } else {
            k++;                        /* a digit dropped: one more power of ten */
            exact &= *s == '0';
        }
    }
    if (s < e && *s == '.')
        for (s++; s < e && (unsigned)(*s - '0') < 10; s++, after++) {
            if (kept < MAX_DIGITS) {
                m = m * 10 + (uint64_t)(*s - '0');
                kept += m != 0;
                k--;
            } else {
                exact &= *s == '0';
            }
        }
    if (before == 0 && after == 0) return -1;
    if (s < e && (*s == 'e' || *s == 'E')) {
        int eneg = 0;
        int64_t x = 0;
        s++;
        if (s < e && (*s == '+' || *s == '-')) eneg = *s++ == '-';
        if (s == e || (unsigned)(*s - '0') >= 10) return -1;
        for (; s < e && (unsigned)(*s - '0') < 10; s++)
            if (x < EXP_CAP) x = x * 10 + (*s - '0');
        k += eneg ? -x : x;
    }
    if (s != e) return -1;
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0
    if (m == 0) {                       /* every digit zero: +-0 */
        *out = neg ? -0.0 : 0.0;
        return 0;
    }
    if (exact && m <= TWO53) {
        if (k >= -22 && k <= 22) {
            d = (double)m;              /* exact: m <= 2^53 */
            d = k >= 0 ? d * ten_to[k] : d / ten_to[-k];  /* one rounding */
            *out = neg ? -d : d;
            return 0;
        }
        if (k > 22 && k <= 22 + 15) {   /* m * 10^(k-22) may still be exact */
            uint64_t big = m;
            int64_t j;
            for (j = 22; j < k && big <= TWO53 / 10; j++) big *= 10;
            if (j == k) {
                d = (double)big * 1e22;  /* big <= 2^53: exact; one rounding */
                *out = neg ? -d : d;
                return 0;
            }
        }
    }
#endif
    return slow(p, n, out);
}
