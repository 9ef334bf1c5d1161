/*
** src/io/numfmt.h -- numbers as text: shortest round-trip, fixed decimals, integers
** See LICENSE for copyright and license.
*/
#ifndef PT_NUMFMT_H
#define PT_NUMFMT_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define PT_NUMLEN 40             /* room for any number these functions write */
#define PT_SHORTLEN 24           /* the longest pt_fmt_shortest() spelling, NUL
                                 ** not counted: "-2.2250738585072014e-308" */

/* Write the shortest decimal that reads back (strtod) to exactly x, as "%g"
** would spell it ("0.1", "-1", "1e+300", "5e-324"); non-finite x as "nan",
** "inf", "-inf".  buf has PT_NUMLEN bytes.  Returns the length.  Can't fail. */
size_t pt_fmt_shortest(char *buf, double x);

/* Write x with prec digits after the point ("%.*f"), or in "%.*e" form when
** |x| >= 1e15; non-finite as above.  0 <= prec <= 17.  Returns the length.
** Can't fail. */
size_t pt_fmt_fixed(char *buf, double x, int prec);

/* Write x's decimal digits at buf (20 bytes at most; no NUL: the writers put
** them in place in a longer line).  Returns the length.  Can't fail. */
size_t pt_fmt_u64(char *buf, uint64_t x);

/* The number of digits pt_fmt_u64() writes for x.  Can't fail. */
size_t pt_fmt_ulen(uint64_t x);

/* The four digits of each of 0 .. 9999, zero-padded ("0000" .. "9999"), and
** four spare bytes: a writer that formats millions of small integers (a
** trace's pixels) keeps one and copies from it, four bytes at a time. */
typedef struct pt_digits4 {
    char d[4 * 10000 + 4];
    unsigned char n[10000];      /* how many digits each has: 1 .. 4 */
} pt_digits4;

/* Fill *t.  This function can't fail. */
void pt_digits4_init(pt_digits4 *t);

/* pt_fmt_u64() for x < 10^4, from table t: one four-byte copy (buf has 4
** bytes of room), its n digits, then bytes to spare.  Can't fail. */
static inline size_t pt_fmt_u4_tab(const pt_digits4 *t, char *buf, uint32_t x)
{
    size_t n = t->n[x];

    memcpy(buf, t->d + 4 * x + 4 - n, 4);
    return n;
}

/* pt_fmt_u64() for x < 10^8, from table t: the same digits, written as two
** four-byte copies at most (buf has 8 bytes of room).  Can't fail. */
static inline size_t pt_fmt_u32_tab(const pt_digits4 *t, char *buf, uint32_t x)
{
    uint32_t hi = x, lo = 0;
    size_t n;

    if (x >= 10000) { hi = x / 10000; lo = x % 10000; }
    n = pt_fmt_u4_tab(t, buf, hi);          /* hi's digits */
    if (x < 10000) return n;
    memcpy(buf + n, t->d + 4 * lo, 4);      /* lo's four, zeros too */
    return n + 4;
}

#endif
