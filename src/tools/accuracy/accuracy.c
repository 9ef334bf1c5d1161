/*
** src/tools/accuracy/accuracy.c -- the pipeline in float, double and double-double, and its errors
** See LICENSE for copyright and license.
**
** Three journeys and three DDAs, one per arithmetic, each written out in its
** own type so that its run time is that arithmetic's: no generic layer, no
** macros.  Each computing line echoes its formula; the double ones are
** operation for operation the stages' and src/core/raster.c's.  The matrix
** camera's journeys and clipping are in src/tools/accuracy/accuracy_matrix.c; the runs, the
** DDAs and the errors here serve both cameras.
*/
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/accuracy.h"
#include "core/pipetrace.h"

const char *const pt_arith_names[PT_NARITH] = { "float", "double", "double-double" };
const int pt_arith_bits[PT_NARITH] = { 24, 53, PT_DD_BITS };
const char *const pt_acc_row_names[PT_ACC_NROWS] = {
    "model", "camera", "image", "pixel", "viewport", "framebuffer", "index", "raster"
};
const char *const pt_acc_mrow_names[PT_ACC_M_NROWS] = {
    "model", "world", "view", "clip", "cvv", "ndc", "screen", "viewport", "framebuffer",
    "index", "raster"
};

/* ===== double-double ===== */

/*
** The classic error-free transformations (Dekker 1971, Knuth TAOCP 4.2.2): for
** doubles a and b, a + b = s + e and a * b = p + e exactly, where s and p are
** the rounded results and e is a double.  fma(a, b, -p) is exact because fma
** rounds once and a*b - p is representable.  The sums and products below are
** the "accurate" versions of Hida, Li and Bailey's QD library (2001), written
** from the formulas, not copied.
*/

/* 2001/1000 = hi + lo, hi the double 2.001, lo = 2001/1000 - hi rounded:
** within 2^-110 of 2001/1000 (tests/test_accuracy.c measures it). */
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

/* ===== float ===== */

/* x rounded to float.  IEEE rounding, spelled out only for overflow, which C
** leaves undefined: from 2^128 - 2^103 (half an ulp above FLT_MAX) on, inf. */
static float to_float(double x)
{
    if (fabs(x) >= 0x1.ffffffp127) return x > 0 ? (float)INFINITY : -(float)INFINITY;
    return (float)x;
}

float pt_acc_to_float(double x)                /* the same, for src/tools/accuracy/accuracy_matrix.c */
{
    return to_float(x);
}

/* pt_pix_round() in float: Java's rounding, no value beyond 2^62. */
static int pix_round_f(float x, int64_t *out)
{
    float r;

    *out = 0;
    if (!isfinite(x)) return 0;
    r = floorf(x);
    if (x - r >= 0.5f) r += 1.0f;              /* ties go up: toward +infinity */
    if (fabsf(r) >= 0x1p62f) return 0;
    *out = (int64_t)r;
    return 1;
}

/* pt_raster_advance() in float: y after k steps of y += m, exactly as k float
** additions leave it, in O(binades crossed).  The argument of src/core/raster.c
** holds word for word with 24 bits for 53. */
static float advance_f(float y, float m, uint64_t k)
{
    if (m == 0.0f) return k ? y + m : y;            /* y + 0 is y (or +0 for -0) */
    while (k > 0) {
        float y1, y2, d, lo, room;
        int e1, e2;
        uint64_t jump;

        if (k < 3) { y += m; k--; continue; }
        y1 = y + m;                                 /* two real steps */
        y2 = y1 + m;
        k -= 2;
        y = y2;
        if (!isfinite(y2) || y1 == 0.0f || y2 == 0.0f) continue;
        frexpf(y1, &e1);
        frexpf(y2, &e2);
        if (e1 != e2 || (y1 > 0) != (y2 > 0)) continue;
        lo = ldexpf(1.0f, e2 - 1);
        if (lo < 0x1p-100f) continue;               /* near zero: just step */
        d = (y2 + m) - y2;                          /* the constant increment */
        if (d == 0.0f) return y2;
        if ((y2 > 0) == (d > 0)) room = 2 * lo - fabsf(y2);
        else room = fabsf(y2) - lo;
        room -= 4 * fabsf(m) + 4 * fabsf(d);
        if (room <= 0) continue;
        jump = (uint64_t)fminf(room / fabsf(d), 0x1p62f);
        if (jump > k) jump = k;
        y = y2 + (float)jump * d;                   /* exact: jump < 2^24 */
        k -= jump;
    }
    return y;
}

/* ===== the journeys ===== */

/* Viewport, framebuffer and index: integers, the same in every arithmetic. */
static void journey_tail(pt_acc_journey *j, const pt_scene *s, int ok,
                         int64_t rx, int64_t ry)
{
    pt_pix vp = {0, 0, 0}, fb = {0, 0, 0};

    if (ok) {
        vp.x = rx - 1;                              /* x_vp = round(x_pp) - 1 */
        vp.y = s->vp_h - ry;                        /* y_vp = h - round(y_pp) */
        vp.ok = 1;
        fb.x = s->vp_x + vp.x;                      /* x_fb = x_ul + x_vp */
        fb.y = s->vp_y + vp.y;                      /* y_fb = y_ul + y_vp */
        fb.ok = 1;
    }
    j->vp = vp;
    j->fb = fb;
    j->idx = fb.ok && fb.x >= 0 && fb.x < s->fb_w && fb.y >= 0 && fb.y < s->fb_h
           ? fb.y * (int64_t)s->fb_w + fb.x : -1;   /* idx = y_fb * W + x_fb */
}

static void journey_f(const pt_scene *s, const pt_model *m, pt_vec3 v,
                      unsigned choices, pt_acc_journey *j)
{
    float x_m = to_float(v.x), y_m = to_float(v.y), z_m = to_float(v.z);
    float x_c, y_c, z_c, x_ip, y_ip, x_pp, y_pp;
    float k = choices & PT_ACC_TWO ? 2.0f : 2.001f;
    float w = (float)s->vp_w, h = (float)s->vp_h;
    int64_t rx = 0, ry = 0;
    int ok;

    x_c = x_m + to_float(m->translate.x);           /* x_c = x_m + x_t */
    y_c = y_m + to_float(m->translate.y);           /* y_c = y_m + y_t */
    z_c = z_m + to_float(m->translate.z);           /* z_c = z_m + z_t */
    if (s->perspective) {
        x_ip = x_c / -z_c;                          /* x_ip = x_c / -z_c */
        y_ip = y_c / -z_c;                          /* y_ip = y_c / -z_c */
    } else {
        x_ip = x_c;                                 /* x_ip = x_c */
        y_ip = y_c;                                 /* y_ip = y_c */
    }
    x_pp = 0.5f + w / k * (x_ip + 1.0f);            /* x_pp = 0.5 + w/2.001 * (x_ip + 1) */
    y_pp = 0.5f + h / k * (y_ip + 1.0f);            /* y_pp = 0.5 + h/2.001 * (y_ip + 1) */
    ok = pix_round_f(x_pp, &rx) && pix_round_f(y_pp, &ry);
    j->m[0] = dd_plain((double)x_m); j->m[1] = dd_plain((double)y_m);
    j->m[2] = dd_plain((double)z_m);
    j->c[0] = dd_plain((double)x_c); j->c[1] = dd_plain((double)y_c);
    j->c[2] = dd_plain((double)z_c);
    j->ip[0] = dd_plain((double)x_ip); j->ip[1] = dd_plain((double)y_ip);
    j->pp[0] = dd_plain((double)x_pp); j->pp[1] = dd_plain((double)y_pp);
    journey_tail(j, s, ok, rx, ry);
}

static void journey_d(const pt_scene *s, const pt_model *m, pt_vec3 v,
                      unsigned choices, pt_acc_journey *j)
{
    double x_c, y_c, z_c, x_ip, y_ip, x_pp, y_pp;
    double k = choices & PT_ACC_TWO ? 2.0 : 2.001;
    int64_t rx = 0, ry = 0;
    int ok;

    x_c = v.x + m->translate.x;                     /* x_c = x_m + x_t */
    y_c = v.y + m->translate.y;                     /* y_c = y_m + y_t */
    z_c = v.z + m->translate.z;                     /* z_c = z_m + z_t */
    if (s->perspective) {
        x_ip = x_c / -z_c;                          /* x_ip = x_c / -z_c */
        y_ip = y_c / -z_c;                          /* y_ip = y_c / -z_c */
    } else {
        x_ip = x_c;                                 /* x_ip = x_c */
        y_ip = y_c;                                 /* y_ip = y_c */
    }
    x_pp = 0.5 + s->vp_w / k * (x_ip + 1);          /* x_pp = 0.5 + w/2.001 * (x_ip + 1) */
    y_pp = 0.5 + s->vp_h / k * (y_ip + 1);          /* y_pp = 0.5 + h/2.001 * (y_ip + 1) */
    ok = pt_pix_round(x_pp, &rx) && pt_pix_round(y_pp, &ry);
    j->m[0] = dd_plain(v.x); j->m[1] = dd_plain(v.y); j->m[2] = dd_plain(v.z);
    j->c[0] = dd_plain(x_c); j->c[1] = dd_plain(y_c); j->c[2] = dd_plain(z_c);
    j->ip[0] = dd_plain(x_ip); j->ip[1] = dd_plain(y_ip);
    j->pp[0] = dd_plain(x_pp); j->pp[1] = dd_plain(y_pp);
    journey_tail(j, s, ok, rx, ry);
}

static void journey_dd(const pt_scene *s, const pt_model *m, pt_vec3 v,
                       pt_acc_journey *j)
{
    const pt_dd one = {1.0, 0.0}, half = {0.5, 0.0};
    pt_dd x_c, y_c, z_c, x_ip, y_ip, x_pp, y_pp, w_k, h_k;
    int64_t rx = 0, ry = 0;
    int ok;

    j->m[0] = dd_plain(v.x); j->m[1] = dd_plain(v.y); j->m[2] = dd_plain(v.z);
    x_c = pt_dd_add(j->m[0], dd_plain(m->translate.x));     /* x_c = x_m + x_t */
    y_c = pt_dd_add(j->m[1], dd_plain(m->translate.y));     /* y_c = y_m + y_t */
    z_c = pt_dd_add(j->m[2], dd_plain(m->translate.z));     /* z_c = z_m + z_t */
    if (s->perspective) {
        x_ip = pt_dd_div(x_c, pt_dd_neg(z_c));              /* x_ip = x_c / -z_c */
        y_ip = pt_dd_div(y_c, pt_dd_neg(z_c));              /* y_ip = y_c / -z_c */
    } else {
        x_ip = x_c;                                         /* x_ip = x_c */
        y_ip = y_c;                                         /* y_ip = y_c */
    }
    w_k = pt_dd_div(dd_plain(s->vp_w), pt_dd_2001);         /* w/2.001 */
    h_k = pt_dd_div(dd_plain(s->vp_h), pt_dd_2001);         /* h/2.001 */
    x_pp = pt_dd_add(half, pt_dd_mul(w_k, pt_dd_add(x_ip, one)));  /* x_pp = 0.5 + w/2.001 * (x_ip + 1) */
    y_pp = pt_dd_add(half, pt_dd_mul(h_k, pt_dd_add(y_ip, one)));  /* y_pp = 0.5 + h/2.001 * (y_ip + 1) */
    ok = pt_dd_pix_round(x_pp, &rx) && pt_dd_pix_round(y_pp, &ry);
    j->c[0] = x_c; j->c[1] = y_c; j->c[2] = z_c;
    j->ip[0] = x_ip; j->ip[1] = y_ip;
    j->pp[0] = x_pp; j->pp[1] = y_pp;
    journey_tail(j, s, ok, rx, ry);
}

void pt_acc_journey_of(pt_arith a, unsigned choices, const pt_scene *s,
                       const pt_model *m, pt_vec3 v_m, pt_acc_journey *j)
{
    switch (a) {
    case PT_ARITH_FLOAT:  journey_f(s, m, v_m, choices, j); break;
    case PT_ARITH_DOUBLE: journey_d(s, m, v_m, choices, j); break;
    default:              journey_dd(s, m, v_m, j); break;
    }
}

/* ===== the DDA ===== */

/* A segment after rounding its ends, in stepping order: s runs from s0 to
** s0 + ds, and the exact line is y = y0 + (s - s0) * dy / ds. */
typedef struct dda_line {
    int64_t s0, y0;              /* the first endpoint */
    int64_t ds, dy;              /* ds >= 1 */
    int transposed;              /* 1: s is y and "y" is x (|slope| > 1) */
} dda_line;

/* Where the steps go. */
typedef struct dda_out {
    void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp);  /* a pixel inside */
    void (*step)(void *ud, const dda_line *ln, int64_t s, double y);
                                 /* every step in the band with its y, or NULL */
    void *ud;
    int w, h;                    /* the viewport */
} dda_out;

/* The exact line at step s, to about 2^-104: y0 + ((s - s0) * dy) / ds.  The
** product is exact below 2^53, and then so is a quotient that is a double
** (IEEE division is exact when it can be), ties included. */
static pt_dd line_y(const dda_line *ln, int64_t s)
{
    pt_dd num = pt_dd_mul(pt_dd_from_i64(s - ln->s0), pt_dd_from_i64(ln->dy));

    return pt_dd_add(pt_dd_from_i64(ln->y0),
                     pt_dd_div(num, pt_dd_from_i64(ln->ds)));  /* y = y0 + k*dy/dx */
}

/* Step s with y rounded to r (ok == 0: y has no integer, it drifted past
** 2^62): the pixel (s - 1, h - r), or (r - 1, h - s) when transposed. */
static void dda_step(const dda_out *o, const dda_line *ln, int64_t s, int ok,
                     int64_t r, double y)
{
    pt_pix p;

    if (!ok) r = y > 0 ? (int64_t)PT_PIX_LIMIT : -(int64_t)PT_PIX_LIMIT;
    if (ln->transposed) { p.x = r - 1; p.y = o->h - s; }   /* (round(x) - 1, h - y) */
    else                { p.x = s - 1; p.y = o->h - r; }   /* (x - 1, h - round(y)) */
    if (pt_inside(p.x, p.y, o->w, o->h)) o->pixel(o->ud, p.x, p.y);
    if (o->step) o->step(o->ud, ln, s, y);
}

/* Both ends on one pixel: that pixel. */
static void dda_dot(const dda_out *o, int64_t ix, int64_t iy)
{
    if (pt_inside(ix - 1, o->h - iy, o->w, o->h)) o->pixel(o->ud, ix - 1, o->h - iy);
}

/* Fill ln from the integer ends e = (x0, y0, x1, y1), already transposed and
** ordered; set the band of steps that can be inside: [max(s0, 1), min(s1, w or h)]. */
static void dda_setup(dda_line *ln, int transposed, const int64_t e[4],
                      const dda_out *o, int64_t *first, int64_t *last)
{
    int64_t band = transposed ? o->h : o->w;

    ln->transposed = transposed;
    ln->s0 = e[0]; ln->y0 = e[1];
    ln->ds = e[2] - e[0]; ln->dy = e[3] - e[1];     /* |e| < 2^62: no overflow */
    *first = e[0] < 1 ? 1 : e[0];
    *last = e[2] < band ? e[2] : band;
}

static void swap64(int64_t *a, int64_t *b)
{
    int64_t t = *a;

    *a = *b;
    *b = t;
}

/* Step along y (swap x and y of both ends) when transposed, then order the
** ends so that s increases.  The ends are integers, so comparing them is
** exact in any arithmetic; only the transposition test is the arithmetic's. */
static void dda_order(int64_t e[4], int transposed)
{
    if (transposed) { swap64(&e[0], &e[1]); swap64(&e[2], &e[3]); }
    if (e[2] < e[0]) { swap64(&e[0], &e[2]); swap64(&e[1], &e[3]); }
}

static int raster_f(float px0, float py0, float px1, float py1, int recompute,
                    const dda_out *o)
{
    int64_t e[4], s, first, last, r;
    float x0, y0, x1, y1, m, acc;
    dda_line ln;
    int tr;

    if (!pix_round_f(px0, &e[0]) || !pix_round_f(py0, &e[1]) ||
        !pix_round_f(px1, &e[2]) || !pix_round_f(py1, &e[3]))
        return -1;
    x0 = (float)e[0]; y0 = (float)e[1];             /* the rounded endpoints */
    x1 = (float)e[2]; y1 = (float)e[3];             /* (exact: they were floats) */
    if (x0 == x1 && y0 == y1) { dda_dot(o, e[0], e[1]); return 0; }
    tr = fabsf(y1 - y0) > fabsf(x1 - x0);           /* |slope| > 1: step in y */
    dda_order(e, tr);
    x0 = (float)e[0]; y0 = (float)e[1];
    x1 = (float)e[2]; y1 = (float)e[3];
    m = (y1 - y0) / (x1 - x0);                      /* m = dy / dx */
    dda_setup(&ln, tr, e, o, &first, &last);
    if (first > last) return 0;
    if (recompute) {
        for (s = first; s <= last; s++) {
            float y = y0 + m * ((float)s - x0);     /* y = y0 + m*(x - x0) */
            int ok = pix_round_f(y, &r);
            dda_step(o, &ln, s, ok, r, (double)y);
        }
        return 0;
    }
    acc = advance_f(y0, m, (uint64_t)(first - e[0]));
    for (s = first; s <= last; s++) {
        int ok = pix_round_f(acc, &r);
        dda_step(o, &ln, s, ok, r, (double)acc);
        acc += m;                                   /* y += m */
    }
    return 0;
}

static int raster_d(double px0, double py0, double px1, double py1, int recompute,
                    const dda_out *o)
{
    int64_t e[4], s, first, last, r;
    double x0, y0, x1, y1, m, acc;
    dda_line ln;
    int tr;

    if (!pt_pix_round(px0, &e[0]) || !pt_pix_round(py0, &e[1]) ||
        !pt_pix_round(px1, &e[2]) || !pt_pix_round(py1, &e[3]))
        return -1;
    x0 = (double)e[0]; y0 = (double)e[1];           /* the rounded endpoints */
    x1 = (double)e[2]; y1 = (double)e[3];           /* (exact: they were doubles) */
    if (x0 == x1 && y0 == y1) { dda_dot(o, e[0], e[1]); return 0; }
    tr = fabs(y1 - y0) > fabs(x1 - x0);             /* |slope| > 1: step in y */
    dda_order(e, tr);
    x0 = (double)e[0]; y0 = (double)e[1];
    x1 = (double)e[2]; y1 = (double)e[3];
    m = (y1 - y0) / (x1 - x0);                      /* m = dy / dx */
    dda_setup(&ln, tr, e, o, &first, &last);
    if (first > last) return 0;
    if (recompute) {
        for (s = first; s <= last; s++) {
            double y = y0 + m * ((double)s - x0);   /* y = y0 + m*(x - x0) */
            int ok = pt_pix_round(y, &r);
            dda_step(o, &ln, s, ok, r, y);
        }
        return 0;
    }
    acc = m == 0.0 ? y0                             /* (pt_raster_advance() steps */
        : pt_raster_advance(y0, m, (uint64_t)(first - e[0]));  /* y = 0, m = 0 one by one) */
    for (s = first; s <= last; s++) {
        int ok = pt_pix_round(acc, &r);
        dda_step(o, &ln, s, ok, r, acc);
        acc += m;                                   /* y += m */
    }
    return 0;
}

static int64_t i64_abs(int64_t v) { return v < 0 ? -v : v; }  /* |v| < 2^63 */

static int raster_dd(pt_dd px0, pt_dd py0, pt_dd px1, pt_dd py1, const dda_out *o)
{
    int64_t e[4], s, first, last, r;
    dda_line ln;
    int tr;

    if (!pt_dd_pix_round(px0, &e[0]) || !pt_dd_pix_round(py0, &e[1]) ||
        !pt_dd_pix_round(px1, &e[2]) || !pt_dd_pix_round(py1, &e[3]))
        return -1;
    if (e[0] == e[2] && e[1] == e[3]) { dda_dot(o, e[0], e[1]); return 0; }
    tr = i64_abs(e[3] - e[1]) > i64_abs(e[2] - e[0]);  /* |slope| > 1: step in y */
    dda_order(e, tr);
    dda_setup(&ln, tr, e, o, &first, &last);
    for (s = first; s <= last; s++) {
        pt_dd y = line_y(&ln, s);                   /* y = y0 + (s - s0) * dy/dx */
        int ok = pt_dd_pix_round(y, &r);
        dda_step(o, &ln, s, ok, r, y.hi);
    }
    return 0;
}

static int raster_one(pt_arith a, unsigned choices, const pt_dd p0[2],
                      const pt_dd p1[2], const dda_out *o)
{
    int re = (choices & PT_ACC_RECOMPUTE) != 0;

    switch (a) {
    case PT_ARITH_FLOAT:
        return raster_f(to_float(p0[0].hi), to_float(p0[1].hi), to_float(p1[0].hi),
                        to_float(p1[1].hi), re, o);
    case PT_ARITH_DOUBLE:
        return raster_d(p0[0].hi, p0[1].hi, p1[0].hi, p1[1].hi, re, o);
    default:
        return raster_dd(p0[0], p0[1], p1[0], p1[1], o);
    }
}

int pt_acc_raster_segment(pt_arith a, unsigned choices, pt_dd x0, pt_dd y0,
                          pt_dd x1, pt_dd y1, int w, int h,
                          void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp),
                          void *ud)
{
    dda_out o;
    pt_dd p0[2], p1[2];

    o.pixel = pixel; o.step = NULL; o.ud = ud; o.w = w; o.h = h;
    p0[0] = x0; p0[1] = y0; p1[0] = x1; p1[1] = y1;
    return raster_one(a, a == PT_ARITH_DD ? 0 : choices, p0, p1, &o);
}

/* Matrix camera: clip segment q of model k, then draw what is left between
** the pixel-plane points of its ends (the vertices' own, or the points
** clipping made).  The clipping goes to *g. */
static void raster_mseg(const pt_acc_run *r, size_t k, size_t q, const dda_out *o,
                        pt_acc_mseg *g)
{
    const pt_segment *sg = &r->s->models[k].seg[q];
    const pt_acc_mjourney *a = &r->mj[k][sg->a], *b = &r->mj[k][sg->b];

    pt_acc_mseg_of(r->cam, a, b, g);
    if (!g->visible) return;                        /* culled */
    raster_one(r->arith, r->choices, g->made[0] ? g->end[0].pp : a->t.pp,
               g->made[1] ? g->end[1].pp : b->t.pp, o);
}

/* Every segment of every model, in file order; *rgb (when not NULL) is set to
** each model's color before its segments.  Matrix camera: each segment's
** clipping goes to r->seg when keep is set (else nowhere). */
static void raster_scene(const pt_acc_run *r, const dda_out *o, uint32_t *rgb, int keep)
{
    size_t k, q;
    pt_acc_mseg g;

    for (k = 0; k < r->s->nmodels; k++) {
        const pt_model *m = &r->s->models[k];

        if (rgb) *rgb = (uint32_t)m->color[0] << 16 | (uint32_t)m->color[1] << 8 | m->color[2];
        for (q = 0; q < m->nseg; q++)
            if (r->cam) raster_mseg(r, k, q, o, keep ? &r->seg[k][q] : &g);
            else raster_one(r->arith, r->choices, r->j[k][m->seg[q].a].pp,
                            r->j[k][m->seg[q].b].pp, o);
    }
}

/* ===== runs ===== */

/* What the rasterizer leaves while a run is made: every pixel written, and
** the DDA's error against the exact line. */
typedef struct collect {
    uint32_t rgb;                /* the current model's color */
    const pt_scene *s;
    struct written { int64_t idx; uint64_t seq; uint32_t rgb; } *px;
    size_t n, cap;
    int oom;
    pt_acc_err *line;
} collect;

static void collect_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    collect *c = ud;

    if (c->n == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 1024;
        struct written *px = c->oom ? NULL : realloc(c->px, cap * sizeof *px);

        if (!px) { c->oom = 1; return; }
        c->px = px;
        c->cap = cap;
    }
    c->px[c->n].idx = (c->s->vp_y + y_vp) * (int64_t)c->s->fb_w + (c->s->vp_x + x_vp);
    c->px[c->n].seq = c->n;
    c->px[c->n].rgb = c->rgb;
    c->n++;
}

static void collect_step(void *ud, const dda_line *ln, int64_t s, double y)
{
    collect *c = ud;

    (void)pt_acc_err_add(c->line, y, line_y(ln, s).hi);
}

static int by_idx_then_seq(const void *pa, const void *pb)
{
    const struct written *a = pa, *b = pb;

    if (a->idx != b->idx) return a->idx < b->idx ? -1 : 1;
    return a->seq < b->seq ? -1 : a->seq > b->seq;
}

void pt_acc_run_free(pt_acc_run *r)
{
    size_t k;

    if (r->s)
        for (k = 0; k < r->s->nmodels; k++) {
            if (r->used) free(r->used[k]);
            if (r->j) free(r->j[k]);
            if (r->mj) free(r->mj[k]);
            if (r->seg) free(r->seg[k]);
        }
    free(r->used);
    free(r->j);
    free(r->mj);
    free(r->seg);
    pt_acc_mcam_free(r->cam);
    free(r->img);
    memset(r, 0, sizeof *r);
}

/* The arrays of the journeys: j[k] (classic camera), or the matrix camera's
** mj[k], seg[k] and its matrices.  Returns 0, or -1 when out of memory. */
static int run_alloc(pt_acc_run *r)
{
    const pt_scene *s = r->s;
    size_t k, nm = s->nmodels ? s->nmodels : 1;

    r->used = calloc(nm, sizeof *r->used);
    if (!r->used) return -1;
    if (!s->matrix) {
        r->j = calloc(nm, sizeof *r->j);
        for (k = 0; r->j && k < s->nmodels; k++)
            if ((r->j[k] = calloc(s->models[k].nv ? s->models[k].nv : 1, sizeof **r->j)) == NULL)
                return -1;
        return r->j ? 0 : -1;
    }
    r->cam = pt_acc_mcam_make(s, r->arith);
    r->mj = calloc(nm, sizeof *r->mj);
    r->seg = calloc(nm, sizeof *r->seg);
    if (!r->cam || !r->mj || !r->seg) return -1;
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        r->mj[k] = calloc(m->nv ? m->nv : 1, sizeof **r->mj);
        r->seg[k] = calloc(m->nseg ? m->nseg : 1, sizeof **r->seg);
        if (!r->mj[k] || !r->seg[k]) return -1;
    }
    return 0;
}

int pt_acc_run_make(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices)
{
    size_t k, q, n;
    collect c;
    dda_out o;

    memset(r, 0, sizeof *r);
    r->s = s;
    r->arith = a;
    r->choices = a == PT_ARITH_DD ? 0 : choices;
    r->line.real = 1;
    if (run_alloc(r) != 0) { pt_acc_run_free(r); return -1; }
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        r->used[k] = calloc(m->nv ? m->nv : 1, 1);
        if (!r->used[k]) { pt_acc_run_free(r); return -1; }
        for (q = 0; q < m->nseg; q++) r->used[k][m->seg[q].a] = r->used[k][m->seg[q].b] = 1;
        for (q = 0; q < m->nv; q++) r->nused += r->used[k][q];
    }
    pt_acc_vertex_pass(r);

    memset(&c, 0, sizeof c);
    c.s = s;
    c.line = &r->line;
    o.pixel = collect_pixel;
    o.step = a == PT_ARITH_DD ? NULL : collect_step;  /* the reference is the line */
    o.ud = &c;
    o.w = s->vp_w;
    o.h = s->vp_h;
    raster_scene(r, &o, &c.rgb, 1);
    if (c.oom) { free(c.px); pt_acc_run_free(r); return -1; }
    for (k = 0; s->matrix && k < s->nmodels; k++)
        for (q = 0; q < s->models[k].nseg; q++) {
            r->made += (uint64_t)(r->seg[k][q].made[0] + r->seg[k][q].made[1]);
            r->culled += !r->seg[k][q].visible;
        }
    r->pixels = c.n;
    if (c.n) qsort(c.px, c.n, sizeof *c.px, by_idx_then_seq);
    r->img = malloc((c.n ? c.n : 1) * sizeof *r->img);
    if (!r->img) { free(c.px); pt_acc_run_free(r); return -1; }
    for (q = n = 0; q < c.n; q++) {                 /* the last write wins */
        if (q + 1 < c.n && c.px[q + 1].idx == c.px[q].idx) continue;
        r->img[n].idx = c.px[q].idx;
        r->img[n].rgb = c.px[q].rgb;
        n++;
    }
    r->nimg = n;
    free(c.px);
    return 0;
}

double pt_acc_vertex_pass(pt_acc_run *r)
{
    double sum = 0.0;
    size_t k, v;

    for (k = 0; k < r->s->nmodels; k++) {
        const pt_model *m = &r->s->models[k];

        for (v = 0; v < m->nv; v++) {
            if (!r->used[k][v]) continue;
            if (r->cam) {
                pt_acc_mjourney *j = &r->mj[k][v];

                pt_acc_mjourney_of(r->cam, k, m->v[v], j);
                sum += j->k[0].hi + (double)j->t.idx;
            } else {
                pt_acc_journey *j = &r->j[k][v];

                pt_acc_journey_of(r->arith, r->choices, r->s, m, m->v[v], j);
                sum += j->pp[0].hi + (double)j->idx;
            }
        }
    }
    return sum;
}

/* The timed rasterizer's pixel sink: a count and a checksum. */
typedef struct tally { uint64_t n, sum; } tally;

static void tally_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    tally *t = ud;

    t->n++;
    t->sum += (uint64_t)(x_vp ^ y_vp);
}

double pt_acc_raster_pass(const pt_acc_run *r, uint64_t *pixels)
{
    tally t = {0, 0};
    dda_out o;

    o.pixel = tally_pixel;
    o.step = NULL;
    o.ud = &t;
    o.w = r->s->vp_w;
    o.h = r->s->vp_h;
    raster_scene(r, &o, NULL, 0);
    *pixels = t.n;
    return (double)t.sum;
}

/* ===== errors ===== */

/* The spacing of doubles at r: 2^(e - 52) for a normal r = 1.f * 2^e, the
** subnormal spacing 2^-1074 below. */
static double ulp_of(double r)
{
    r = fabs(r);
    if (r < DBL_MIN) return 0x1p-1074;
    return ldexp(1.0, ilogb(r) - 52);
}

/* Count and return |v - ref|: 0 for the same non-finite value, infinite for
** another. */
double pt_acc_err_add(pt_acc_err *e, double v, double ref)
{
    double d, u;

    if (isfinite(v) && isfinite(ref)) d = fabs(v - ref);
    else if ((isnan(v) && isnan(ref)) || v == ref) d = 0.0;
    else d = (double)INFINITY;
    u = isfinite(ref) ? d / ulp_of(ref) : d;
    e->n++;
    e->sum_abs += d;
    if (d > e->max_abs) e->max_abs = d;
    if (u > e->max_ulp) e->max_ulp = u;
    return d;
}

/* Real coordinates: returns 1 when any differs from the reference double. */
int pt_acc_err_reals(pt_acc_err *e, const pt_dd *v, const pt_dd *ref, int n)
{
    int k, differ = 0;

    for (k = 0; k < n; k++)
        if (pt_acc_err_add(e, v[k].hi, ref[k].hi) != 0.0) differ = 1;
    return differ;
}

/* A pixel: no pixel on one side only counts as an infinite error. */
int pt_acc_err_pix(pt_acc_err *e, pt_pix v, pt_pix ref)
{
    if (v.ok && ref.ok) {
        pt_acc_err_add(e, (double)v.x, (double)ref.x);
        pt_acc_err_add(e, (double)v.y, (double)ref.y);
        return v.x != ref.x || v.y != ref.y;
    }
    if (v.ok == ref.ok) {
        pt_acc_err_add(e, 0.0, 0.0);
        pt_acc_err_add(e, 0.0, 0.0);
        return 0;
    }
    pt_acc_err_add(e, (double)INFINITY, 0.0);
    pt_acc_err_add(e, (double)INFINITY, 0.0);
    return 1;
}

/* Pixels whose final color differs between two images (sorted by idx); in
** *either, the pixels lit in either image. */
static uint64_t image_diff(const pt_acc_run *a, const pt_acc_run *b, uint64_t *either)
{
    size_t i = 0, k = 0;
    uint64_t n = 0;

    *either = 0;
    for (; i < a->nimg || k < b->nimg; (*either)++) {
        if (k == b->nimg || (i < a->nimg && a->img[i].idx < b->img[k].idx)) { n++; i++; }
        else if (i == a->nimg || b->img[k].idx < a->img[i].idx) { n++; k++; }
        else { n += a->img[i].rgb != b->img[k].rgb; i++; k++; }
    }
    return n;
}

/* The classic camera's rows model .. index. */
static void compare_classic(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_NROWS])
{
    const pt_scene *s = r->s;
    size_t k, v;
    int row;

    for (row = 0; row < PT_ACC_NROWS; row++) {
        e[row].real = row <= PT_ACC_PIXEL || row == PT_ACC_RASTER;
        e[row].of = r->nused;
    }
    for (k = 0; k < s->nmodels; k++)
        for (v = 0; v < s->models[k].nv; v++) {
            const pt_acc_journey *a = &r->j[k][v], *b = &ref->j[k][v];
            int in_a, in_b;

            if (!r->used[k][v]) continue;
            e[PT_ACC_MODEL].differ += pt_acc_err_reals(&e[PT_ACC_MODEL], a->m, b->m, 3);
            e[PT_ACC_CAMERA].differ += pt_acc_err_reals(&e[PT_ACC_CAMERA], a->c, b->c, 3);
            e[PT_ACC_IMAGE].differ += pt_acc_err_reals(&e[PT_ACC_IMAGE], a->ip, b->ip, 2);
            e[PT_ACC_PIXEL].differ += pt_acc_err_reals(&e[PT_ACC_PIXEL], a->pp, b->pp, 2);
            e[PT_ACC_VIEWPORT].differ += pt_acc_err_pix(&e[PT_ACC_VIEWPORT], a->vp, b->vp);
            e[PT_ACC_FRAMEBUFFER].differ += pt_acc_err_pix(&e[PT_ACC_FRAMEBUFFER], a->fb, b->fb);
            if (a->idx >= 0 && b->idx >= 0)
                pt_acc_err_add(&e[PT_ACC_INDEX], (double)a->idx, (double)b->idx);
            e[PT_ACC_INDEX].differ += a->idx != b->idx;
            in_a = a->vp.ok && pt_inside(a->vp.x, a->vp.y, s->vp_w, s->vp_h);
            in_b = b->vp.ok && pt_inside(b->vp.x, b->vp.y, s->vp_w, s->vp_h);
            e[PT_ACC_VIEWPORT].left += in_b && !in_a;
            e[PT_ACC_VIEWPORT].entered += in_a && !in_b;
        }
}

void pt_acc_compare(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_MAXROWS])
{
    int raster = r->s->matrix ? PT_ACC_M_RASTER : PT_ACC_RASTER;

    memset(e, 0, (size_t)(raster + 1) * sizeof *e);
    if (r->s->matrix) pt_acc_mcompare(ref, r, e);
    else compare_classic(ref, r, e);
    e[raster] = r->line;
    e[raster].real = 1;
    e[raster].differ = image_diff(ref, r, &e[raster].of);
}
