/*
** src/tools/accuracy/dd.c -- double-double arithmetic: 106-bit values and 4x4 matrices
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "tools/accuracy/dd.h"

/*
** The classic error-free transformations (Dekker 1971, Knuth TAOCP 4.2.2): for
** doubles a and b, a + b = s + e and a * b = p + e exactly, where s and p are
** the rounded results and e is a double.  fma(a, b, -p) is exact because fma
** rounds once and a*b - p is representable.  The sums and products below are
** the "accurate" versions of Hida, Li and Bailey's QD library (2001), written
** from the formulas, not copied.
*/

/* 2001/1000 = hi + lo, hi the double 2.001, lo = 2001/1000 - hi rounded:
** within 2^-110 of 2001/1000 (tests/unit/test_accuracy.c measures it). */
const pt_dd pt_dd_2001 = { 0x1.0020c49ba5e35p+1, 0x1.fbe76c8b43958p-54 };

static pt_dd two_sum(double a, double b)       /* a + b = hi + lo exactly */
{
    pt_dd r;
    double bb;

    r.hi = a + b;
    bb = r.hi - a;
    r.lo = (a - (r.hi - bb)) + (b - bb);
    return r;
}

static pt_dd quick_two_sum(double a, double b) /* the same when |a| >= |b| */
{
    pt_dd r;

    r.hi = a + b;
    r.lo = b - (r.hi - a);
    return r;
}

static pt_dd two_prod(double a, double b)      /* a * b = hi + lo exactly */
{
    pt_dd r;

    r.hi = a * b;
    r.lo = fma(a, b, -r.hi);
    return r;
}

static pt_dd dd_plain(double x)                /* a double (or inf, NaN) as is */
{
    pt_dd r;

    r.hi = x;
    r.lo = 0.0;
    return r;
}

pt_dd pt_dd_from(double x)
{
    return dd_plain(x);
}

pt_dd pt_dd_from_i64(int64_t v)
{
    int64_t rest = v % 2048;                   /* |rest| < 2^11: a double */
    int64_t top = v - rest;                    /* 2^11 * q, |q| < 2^52: a double */

    return two_sum((double)top, (double)rest);
}

pt_dd pt_dd_neg(pt_dd a)
{
    a.hi = -a.hi;
    a.lo = -a.lo;
    return a;
}

pt_dd pt_dd_add(pt_dd a, pt_dd b)
{
    pt_dd s = two_sum(a.hi, b.hi), t = two_sum(a.lo, b.lo);

    if (!isfinite(s.hi)) return dd_plain(s.hi);
    s.lo += t.hi;
    s = quick_two_sum(s.hi, s.lo);
    s.lo += t.lo;
    s = quick_two_sum(s.hi, s.lo);
    if (s.hi == 0.0) return dd_plain(a.hi + b.hi);  /* an exact 0: IEEE's sign */
    return s;
}

pt_dd pt_dd_mul(pt_dd a, pt_dd b)
{
    pt_dd p = two_prod(a.hi, b.hi);

    if (!isfinite(p.hi) || p.hi == 0.0) return dd_plain(p.hi);
    p.lo += a.hi * b.lo + a.lo * b.hi;         /* a.lo * b.lo is below 2^-106 */
    return quick_two_sum(p.hi, p.lo);
}

pt_dd pt_dd_div(pt_dd a, pt_dd b)
{
    double q1, q2, q3;
    pt_dd r, q;

    q1 = a.hi / b.hi;                          /* long division, three digits */
    if (!isfinite(q1) || q1 == 0.0) return dd_plain(q1);
    r = pt_dd_add(a, pt_dd_neg(pt_dd_mul(b, dd_plain(q1))));
    q2 = r.hi / b.hi;
    r = pt_dd_add(r, pt_dd_neg(pt_dd_mul(b, dd_plain(q2))));
    q3 = r.hi / b.hi;
    q = quick_two_sum(q1, q2);
    return pt_dd_add(q, dd_plain(q3));
}

/* sqrt(a) = q + (a - q*q) / (2q) for q = sqrt(a.hi): one Newton step doubles
** q's 53 bits; a - q*q is exact up to a.lo's part (two_prod). */
pt_dd pt_dd_sqrt(pt_dd a)
{
    double q;
    pt_dd r;

    if (!(a.hi > 0) || isinf(a.hi)) return dd_plain(sqrt(a.hi));   /* 0, <0, inf, NaN */
    q = sqrt(a.hi);
    r = pt_dd_add(a, pt_dd_neg(two_prod(q, q)));    /* a - q*q */
    return pt_dd_add(dd_plain(q), dd_plain(r.hi / (2.0 * q)));  /* q + r/(2q) */
}

/*
** Java's rounding of hi + lo.  Below 2^52, hi's neighbours n - 0.5 and n + 0.5
** (n = round(hi)) are multiples of hi's ulp, so hi + lo (|lo| <= ulp/2) can be
** on the other side only when hi sits exactly on n - 0.5 and lo < 0.  From
** 2^52 on, hi is an integer and round(hi + lo) = hi + round(lo).
*/
int pt_dd_pix_round(pt_dd x, int64_t *out)
{
    double r;
    int64_t n;

    *out = 0;
    if (!isfinite(x.hi) || fabs(x.hi) > PT_PIX_LIMIT) return 0;   /* n then too */
    if (fabs(x.hi) >= 0x1p52) {
        n = (int64_t)x.hi + (int64_t)pt_java_round(x.lo);
        if (n >= (int64_t)PT_PIX_LIMIT || n <= -(int64_t)PT_PIX_LIMIT) return 0;
        *out = n;
        return 1;
    }
    r = pt_java_round(x.hi);
    if (x.hi - r == -0.5 && x.lo < 0) r -= 1.0;    /* just below the tie */
    *out = (int64_t)r;
    return 1;
}

pt_dd pt_dd_sub(pt_dd a, pt_dd b)
{
    return pt_dd_add(a, pt_dd_neg(b));
}

int pt_dd_lt(pt_dd a, pt_dd b)
{
    return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}

/* ===== cot and matrices ===== */

/* pi = hi + lo, to about 2^-107 relative (hi is stages/pt_mat4.c's PI). */
static const pt_dd PI_DD = { 0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53 };

/* sin x and cos x for |x| <= pi/4: their Taylor series, term by term, until
** both terms fall below 2^-110 of their sums. */
static void dd_sincos(pt_dd x, pt_dd *s, pt_dd *c)
{
    pt_dd mx2 = pt_dd_neg(pt_dd_mul(x, x)), ts = x, tc = dd_plain(1.0);
    double n;

    *s = ts;
    *c = tc;
    for (n = 1; n < 60; n += 2) {
        tc = pt_dd_div(pt_dd_mul(tc, mx2), dd_plain(n * (n + 1)));        /* (-1)^k x^2k/(2k)! */
        ts = pt_dd_div(pt_dd_mul(ts, mx2), dd_plain((n + 1) * (n + 2)));  /* (-1)^k x^(2k+1)/(2k+1)! */
        *c = pt_dd_add(*c, tc);
        *s = pt_dd_add(*s, ts);
        if (fabs(tc.hi) < 0x1p-110 * fabs(c->hi) && fabs(ts.hi) < 0x1p-110 * fabs(s->hi))
            break;
    }
}

pt_dd pt_dd_cot_deg(double deg)
{
    int above = deg > 45;                   /* cot(deg) = tan(90 - deg) */
    double a = above ? 90 - deg : deg;      /* exact (Sterbenz) */
    pt_dd s, c;

    if (deg == 45) return dd_plain(1.0);
    dd_sincos(pt_dd_div(pt_dd_mul(dd_plain(a), PI_DD), dd_plain(180.0)), &s, &c);  /* x = a * pi/180 */
    return above ? pt_dd_div(s, c) : pt_dd_div(c, s);
}

pt_dd_mat4 pt_dd_mat4_mul(const pt_dd_mat4 *a, const pt_dd_mat4 *b)
{
    pt_dd_mat4 r;
    int i;

    for (i = 0; i < 4; i++)                 /* row i of a*b = (row i of a) * b */
        pt_dd_vec4_mul(a->m[i], b, r.m[i]);
    return r;
}

void pt_dd_vec4_mul(const pt_dd v[4], const pt_dd_mat4 *m, pt_dd r[4])
{
    int c, k;

    for (c = 0; c < 4; c++) {               /* x' = x*m0c + y*m1c + z*m2c + w*m3c */
        r[c] = pt_dd_mul(v[0], m->m[0][c]);
        for (k = 1; k < 4; k++) r[c] = pt_dd_add(r[c], pt_dd_mul(v[k], m->m[k][c]));
    }
}
