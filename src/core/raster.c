/*
** src/core/raster.c -- draw one line segment of the pixel plane into a viewport
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include <float.h>
#include <limits.h>
#include <stddef.h>
#include <string.h>
#include <math.h>
#include "core/raster.h"
#include "stages/pt_round.h"
#include "stages/pt_color.h"
#include "stages/s4_pixel2viewport.h"
#include "stages/s5_viewport2fb.h"
#include "stages/s6_fb2index.h"

#if defined(__GNUC__)
#define ALWAYS_INLINE __attribute__((always_inline))
#define FLATTEN __attribute__((flatten))
#else
#define ALWAYS_INLINE
#define FLATTEN
#endif

/* ===== Java's rounding of the ends (the course's renderer 4) ===== */

double pt_raster_java_round(double x)
{
    if (x != x) return 0.0;                         /* Math.round(NaN) = 0 */
    if (x >= 0x1p63) return 0x1p63;                 /* Long.MAX_VALUE, as a double */
    if (x <= -0x1p63) return -0x1p63;               /* Long.MIN_VALUE */
    return pt_java_round(x);
}

int64_t pt_raster_java_int(double d)
{
    if (d >= (double)INT_MAX) return INT_MAX;       /* (int) saturates */
    if (d <= (double)INT_MIN) return INT_MIN;
    return (int64_t)d;
}

/* d, a whole number or +-2^63, as an int64_t, saturated. */
static int64_t sat64(double d)
{
    if (d >= 0x1p63) return INT64_MAX;
    if (d <= -0x1p63) return INT64_MIN;
    return (int64_t)d;
}

/* 1 when the segment (x0, y0) - (x1, y1) steps in y: |slope| > 1. */
static int ymajor(double x0, double y0, double x1, double y1)
{
    return fabs(y1 - y0) > fabs(x1 - x0);
}

/* 1 when an end of p0-p1 has no integer pixel (not finite, or |x| >= 2^62):
** the course's rounding takes over (pt_raster_java_round). */
static int no_pixel(pt_vec2 p0, pt_vec2 p1)
{
    return !(fabs(p0.x) < PT_PIX_LIMIT && fabs(p0.y) < PT_PIX_LIMIT &&
             fabs(p1.x) < PT_PIX_LIMIT && fabs(p1.y) < PT_PIX_LIMIT);
}

int pt_raster_endless(pt_vec2 p0, pt_vec2 p1)
{
    double x0 = pt_raster_java_round(p0.x), y0 = pt_raster_java_round(p0.y);
    double x1 = pt_raster_java_round(p1.x), y1 = pt_raster_java_round(p1.y);

    if (!no_pixel(p0, p1) || (x0 == x1 && y0 == y1)) return 0;   /* int64 steps; one pixel */
    if (ymajor(x0, y0, x1, y1)) return pt_raster_java_int(fmax(y0, y1)) == INT_MAX;
    return pt_raster_java_int(fmax(x0, x1)) == INT_MAX;
}

/* ===== the DDA ===== */

/* A run of clipped steps being gathered, reported when it ends. */
typedef struct clip_run {
    uint64_t count;
    pt_pix first, last;
} clip_run;

static void run_add(clip_run *run, uint64_t n, pt_pix first, pt_pix last)
{
    if (run->count == 0) run->first = first;
    run->count += n;
    run->last = last;
}

static void run_flush(clip_run *run, const pt_raster_out *out)
{
    if (run->count) {
        out->clip(out->ud, run->count, run->first, run->last);
        run->count = 0;
    }
}

/* Where a pixel inside goes, in colour rgb covering share cov of it:
** out->pixel (pt_raster_segment, which has no colours), or straight through
** the framebuffer and index stages into an image (pt_raster_draw). */
typedef void pixel_fn(void *ud, int64_t x_vp, int64_t y_vp, const unsigned char rgb[3],
                      float cov);

/* The segment being stepped: s is the stepped coordinate (x, or y when
** transposed), acc the other one, accumulated.  Its colours are in stepping
** order (stages/pt_color.h). */
typedef struct dda {
    int w, h;                    /* the viewport */
    pt_raster_vp to_vp;          /* pixel plane -> viewport pixel */
    pixel_fn *pixel;             /* where a pixel inside goes, */
    void *pixel_ud;              /* with this */
    const pt_raster_out *out;    /* where runs of clipped steps go */
    const pt_raster_steps *ls;   /* the listener of steps, or NULL */
    const pt_raster_setup *su;   /* with one: the segment's setup */
    const struct tint *t;        /* its colours */
} dda;

/* The colours of the segment being stepped, apart from the dda: kept small,
** the dda's function pointers stay known constants to the compiler. */
typedef struct tint {
    int shade;                   /* 1: each step's colour is its own */
    int gamma, aa;               /* the course's switches (pt_raster_colors) */
    float bg[3];                 /* with aa: the viewport's background */
    float c0[3];                 /* the colour at s0, */
    double dc[3];                /* its change a step (pt_color_slope) */
    double s0;                   /* the first step's s */
    float c[3];                  /* shade 0: every step's colour, gamma-encoded, */
    unsigned char rgb[3];        /* and its bytes */
} tint;

/* The viewport pixel of step (s, acc): the point (s, acc), or (acc, s) when
** transposed, through the viewport stage.  s is a whole number. */
static inline ALWAYS_INLINE pt_pix step_pixel(const dda *d, int transposed, double s,
                                              double acc)
{
    pt_vec2 p;

    if (transposed) { p.x = acc; p.y = s; }
    else            { p.x = s; p.y = acc; }
    return d->to_vp(p, d->w, d->h, NULL);
}

/* The colour of step s before gamma (pt_color_at). */
static inline ALWAYS_INLINE void step_raw(const tint *t, double s, float c[3])
{
    int i;

    for (i = 0; i < 3; i++) c[i] = pt_color_at(t->c0[i], t->dc[i], s, t->s0);
}

/* c gamma-encoded when the segment's switch says so, and as bytes. */
static inline ALWAYS_INLINE void encode(const tint *t, float c[3], unsigned char rgb[3])
{
    int i;

    for (i = 0; i < 3; i++) {
        if (t->gamma) c[i] = pt_gamma(c[i]);
        rgb[i] = pt_color_byte(c[i]);
    }
}

/* The step record of step (si, acc): its pixel p, its colour c and bytes rgb;
** with hi (anti-aliasing) the upper pixel's too, the step's weight w. */
static void tell_step(const dda *d, int transposed, int si, double acc, pt_pix p,
                      int inside, const float c[3], const unsigned char rgb[3],
                      const pt_raster_step *hi)
{
    const pt_raster_steps *ls = d->ls;
    pt_raster_step st;

    if (!ls->step) return;
    if (hi) st = *hi;
    else st.aa = 0;
    st.s = si;
    st.a = acc;
    if (transposed) { st.pp.x = acc; st.pp.y = (double)si; }
    else            { st.pp.x = (double)si; st.pp.y = acc; }
    st.vp = p;
    st.inside = inside;
    memcpy(st.color, c, sizeof st.color);
    memcpy(st.paint.rgb, rgb, sizeof st.paint.rgb);
    st.paint.coverage = hi ? 1.0f - hi->weight : 1.0f;
    ls->step(ls->ud, &st);
}

/* One anti-aliased step (si, acc): the pixels at floor(acc) and floor(acc) + 1
** of the other coordinate, the step's colour blended with the background by
** the weight (stages/pt_color.h), each pixel clip-tested on its own.  These
** helpers are inline: a call that took d's address would keep the compiler
** from seeing that to_vp and pixel stay the stages it inlines. */
static inline ALWAYS_INLINE void aa_step(const dda *d, int transposed, int stepping, int si,
                                          double acc, clip_run *run)
{
    double lo = floor(acc);                         /* a_low = floor(a) */
    float w = pt_aa_weight(acc, lo), c[3], cl[3];
    unsigned char bl[3];
    pt_raster_step hi;
    pt_pix p = step_pixel(d, transposed, (double)si, lo);
    int in = p.ok && pt_inside(p.x, p.y, d->w, d->h), i;

    hi.aa = 1;
    hi.weight = w;
    hi.vp_hi = step_pixel(d, transposed, (double)si, lo + 1.0);   /* a_hi = a_low + 1 */
    hi.inside_hi = hi.vp_hi.ok && pt_inside(hi.vp_hi.x, hi.vp_hi.y, d->w, d->h);
    step_raw(d->t, (double)si, c);
    for (i = 0; i < 3; i++) pt_aa_blend(c[i], d->t->bg[i], w, &cl[i], &hi.color_hi[i]);
    encode(d->t, cl, bl);
    encode(d->t, hi.color_hi, hi.rgb_hi);
    if (stepping) tell_step(d, transposed, si, acc, p, in, cl, bl, &hi);
    if (in) {
        run_flush(run, d->out);
        d->pixel(d->pixel_ud, p.x, p.y, bl, 1.0f - w);
    } else {
        run_add(run, 1, p, p);
    }
    if (hi.inside_hi) {
        run_flush(run, d->out);
        d->pixel(d->pixel_ud, hi.vp_hi.x, hi.vp_hi.y, hi.rgb_hi, w);
    } else {
        run_add(run, 1, hi.vp_hi, hi.vp_hi);
    }
}

/* Step s from s0 to s1 with acc from acc0, acc += m: the steps in the band
** through the viewport stage, the others clipped and skipped.  Inline with
** transposed a constant, so that each of the two loops knows which
** coordinate it steps; and stepping, 1 for a listener of steps: when it
** listens to steps, the band is every step within the range of an int, each
** step told.  A segment of one colour without anti-aliasing has that colour
** at hand (d->t->rgb); the others compute each step's. */
static inline ALWAYS_INLINE void walk(const dda *d, int transposed, int stepping,
                                      int64_t s0, int64_t s1, double acc0, double m)
{
    int64_t s = s0, band_lo, band_hi, margin, end;
    double acc = acc0;
    clip_run run = {0, {0, 0, 0}, {0, 0, 0}};
    const int aa = d->t->aa, shade = d->t->shade;   /* kept in registers: the image's
                                                    ** bytes may alias *d->t */
    const unsigned char *rgb1 = d->t->rgb;          /* shade 0: the one colour */
    uint64_t per = aa ? 2 : 1;                      /* pixels a step */
    pt_pix p;
    int every;

    /* The steps the viewport stage is asked about: 1 <= s <= w (or h), where
    ** x_vp = s - 1 lies inside, widened by a margin of max(w, h) on each side
    ** for a student's stage that moves pixels (docs/teaching.md).  Steps
    ** beyond are clipped without asking, and skipped by the exact
    ** fast-forward: drawing costs time in proportion to the band.  The band
    ** stays inside the range of an int (it is, for any w and h below 2^30), so
    ** that the compiler, seeing (double) of an int, knows the stepped
    ** coordinate is whole and in range, and drops the viewport stage's
    ** rounding and range check of it. */
    margin = d->w > d->h ? d->w : d->h;
    every = stepping && d->ls->step;                /* each step told */
    band_lo = every ? INT_MIN : 1 - margin;
    band_hi = every ? INT_MAX - 1 : (transposed ? d->h : d->w) + margin;
    if (band_hi > INT_MAX - 1) band_hi = INT_MAX - 1;

    if (s < band_lo) {                              /* before the band: skip */
        int64_t last = s1 < band_lo - 1 ? s1 : band_lo - 1;
        uint64_t n = (uint64_t)(last - s) + 1;
        double acc_last = pt_raster_advance(acc, m, n - 1);
        run_add(&run, per * n, step_pixel(d, transposed, (double)s, acc),
                step_pixel(d, transposed, (double)last, acc_last));
        acc = acc_last + m;
        s = last + 1;
    }
    end = s1 < band_hi ? s1 : band_hi;
    if (s <= end) {                                 /* inside the band: step */
        int si, si_end = (int)end;

        for (si = (int)s; si <= si_end; si++) {
            if (aa) {
                aa_step(d, transposed, stepping, si, acc, &run);
                acc += m;
                continue;
            }
            p = step_pixel(d, transposed, (double)si, acc);
            if (p.ok && pt_inside(p.x, p.y, d->w, d->h)) {
                if (shade || stepping) {
                    float c[3];
                    unsigned char rgb[3];
                    step_raw(d->t, (double)si, c);
                    encode(d->t, c, rgb);
                    if (stepping) tell_step(d, transposed, si, acc, p, 1, c, rgb, NULL);
                    run_flush(&run, d->out);
                    d->pixel(d->pixel_ud, p.x, p.y, rgb, 1.0f);
                } else {
                    run_flush(&run, d->out);
                    d->pixel(d->pixel_ud, p.x, p.y, rgb1, 1.0f);
                }
            } else {
                if (stepping) {
                    float c[3];
                    unsigned char rgb[3];
                    step_raw(d->t, (double)si, c);
                    encode(d->t, c, rgb);
                    tell_step(d, transposed, si, acc, p, 0, c, rgb, NULL);
                }
                run_add(&run, 1, p, p);
            }
            acc += m;                               /* y += m */
        }
        s = end + 1;
    }
    if (s <= s1) {                                  /* after the band: skip */
        uint64_t n = (uint64_t)(s1 - s) + 1;
        double acc_last = pt_raster_advance(acc, m, n - 1);
        run_add(&run, per * n, step_pixel(d, transposed, (double)s, acc),
                step_pixel(d, transposed, (double)s1, acc_last));
    }
    run_flush(&run, d->out);
}

/* The segment's colours in stepping order into d (swapped: p1's first), over
** the steps s0 .. s1; col NULL: none (black, pt_raster_segment). */
static inline ALWAYS_INLINE void colors_start(tint *t, const pt_raster_colors *col,
                                               int swapped, double s0, double s1)
{
    int i, same = 1;

    memset(t->bg, 0, sizeof t->bg);
    t->gamma = t->aa = 0;
    t->s0 = s0;
    for (i = 0; i < 3; i++) {
        float a = col ? (swapped ? col->c1[i] : col->c0[i]) : 0.0f;
        float b = col ? (swapped ? col->c0[i] : col->c1[i]) : 0.0f;
        t->c0[i] = a;
        t->dc[i] = s1 > s0 ? pt_color_slope(a, b, s1 - s0) : 0.0;
        same &= a == b;
    }
    if (col) {
        t->gamma = col->gamma;
        t->aa = col->aa;
        memcpy(t->bg, col->bg, sizeof t->bg);
    }
    t->shade = !same;                               /* one colour: gamma it once */
    if (col && col->one) {                          /* done by the caller */
        memcpy(t->c, col->c, sizeof t->c);
        memcpy(t->rgb, col->rgb, sizeof t->rgb);
        return;
    }
    step_raw(t, s0, t->c);
    encode(t, t->c, t->rgb);
}

void pt_raster_colors_prepare(pt_raster_colors *col)
{
    int i;

    col->one = col->c0[0] == col->c1[0] && col->c0[1] == col->c1[1] &&
               col->c0[2] == col->c1[2];
    for (i = 0; col->one && i < 3; i++) {
        col->c[i] = col->gamma ? pt_gamma(col->c0[i]) : col->c0[i];   /* |c0 + 0| = c0 */
        col->rgb[i] = pt_color_byte(col->c[i]);
    }
}

/* The setup record of a drawn segment (stepping): su->x0 .. y1 and kind
** set, the ends in stepping order s0, s1 (a0 the other coordinate at s0,
** p0's end first unless swapped), the slope m. */
static void tell_setup(const dda *d, pt_raster_setup *su, int transposed, int swapped,
                       int64_t s0, int64_t s1, double a0, double a1, double m)
{
    const pt_raster_steps *ls = d->ls;
    const pt_raster_colors *col = &ls->col;
    int i;

    su->ymajor = transposed;
    su->swapped = swapped;
    su->s0 = s0;
    su->s1 = s1;
    su->a0 = a0;
    su->m = m;
    su->vp0 = step_pixel(d, transposed, (double)s0, a0);
    su->vp1 = step_pixel(d, transposed, (double)s1, a1);
    for (i = 0; i < 3; i++) {
        su->c0[i] = swapped ? col->c1[i] : col->c0[i];
        su->c1[i] = swapped ? col->c0[i] : col->c1[i];
        su->dc[i] = d->t->dc[i];
    }
    if (ls->setup) ls->setup(ls->ud, su);
}

/* The one step of a degenerate segment at (x, y), pixel p, told to the
** listener of steps: in the colour of p0, without gamma. */
static void tell_degenerate(const dda *d, pt_raster_setup *su, double x, double y,
                            pt_pix p, int inside)
{
    const pt_raster_steps *ls = d->ls;
    pt_raster_step st;
    int i;

    su->s0 = su->s1 = sat64(x);
    su->a0 = y;
    su->vp0 = su->vp1 = p;
    for (i = 0; i < 3; i++) { su->c0[i] = su->c1[i] = ls->col.c0[i]; su->dc[i] = 0.0; }
    if (ls->setup) ls->setup(ls->ud, su);
    if (!ls->step) return;
    st.s = su->s0;
    st.a = y;
    st.pp.x = x; st.pp.y = y;
    st.vp = p;
    st.inside = inside;
    st.aa = 0;
    for (i = 0; i < 3; i++) {
        st.color[i] = ls->col.c0[i];
        st.paint.rgb[i] = pt_color_byte(ls->col.c0[i]);
    }
    st.paint.coverage = 1.0f;
    ls->step(ls->ud, &st);
}

/* The DDA, once for both entry points below: inline in each, so that where
** to_vp and pixel are known functions whose code the compiler sees (the
** Makefile compiles this file with the chosen viewport, framebuffer and index
** stages), the calls in the loop become plain code.  stepping (a constant):
** 1 tells ls of the setup and of every step (walk()).  col: the colours
** (NULL: none). */
static inline ALWAYS_INLINE int segment(pt_vec2 p0, pt_vec2 p1, int w, int h,
                                        pt_raster_vp to_vp, pixel_fn *pixel,
                                        void *pixel_ud, const pt_raster_out *out,
                                        const pt_raster_steps *ls, int stepping,
                                        const pt_raster_colors *col)
{
    int64_t ix0, iy0, ix1, iy1, s0, s1;
    double x0, y0, x1, y1, m;
    int transposed, swapped = 0, java = col && col->java && no_pixel(p0, p1);
    pt_raster_setup su;
    dda d;
    tint tn;
    pt_pix p;

    if (java) {                                     /* the course's rounding, not skipped */
        x0 = pt_raster_java_round(p0.x); y0 = pt_raster_java_round(p0.y);
        x1 = pt_raster_java_round(p1.x); y1 = pt_raster_java_round(p1.y);
        ix0 = sat64(x0); iy0 = sat64(y0);
        ix1 = sat64(x1); iy1 = sat64(y1);
    } else if (!pt_pix_round(p0.x, &ix0) || !pt_pix_round(p0.y, &iy0) ||
               !pt_pix_round(p1.x, &ix1) || !pt_pix_round(p1.y, &iy1)) {
        if (stepping && ls->setup) {
            memset(&su, 0, sizeof su);
            su.kind = PT_RASTER_SKIPPED;
            ls->setup(ls->ud, &su);
        }
        return PT_RASTER_SKIPPED;
    } else {
        x0 = (double)ix0; y0 = (double)iy0;         /* the rounded endpoints */
        x1 = (double)ix1; y1 = (double)iy1;
    }
    d.w = w; d.h = h; d.to_vp = to_vp;
    d.pixel = pixel; d.pixel_ud = pixel_ud; d.out = out;
    d.ls = ls;
    d.su = &su;
    d.t = &tn;
    if (stepping) {
        memset(&su, 0, sizeof su);
        su.kind = PT_RASTER_DRAWN;
        su.x0 = ix0; su.y0 = iy0; su.x1 = ix1; su.y1 = iy1;
    }

    if (x0 == x1 && y0 == y1) {                     /* degenerate: one pixel */
        int in, i;
        unsigned char rgb[3];
        p = step_pixel(&d, 0, x0, y0);
        in = p.ok && pt_inside(p.x, p.y, w, h);
        if (stepping) {
            su.kind = PT_RASTER_DEGENERATE;
            tell_degenerate(&d, &su, x0, y0, p, in);
        }
        for (i = 0; i < 3; i++)                     /* c0, raw: no gamma, no AA */
            rgb[i] = pt_color_byte(col ? col->c0[i] : 0.0f);
        if (in) pixel(pixel_ud, p.x, p.y, rgb, 1.0f);
        else out->clip(out->ud, 1, p, p);
        return PT_RASTER_DEGENERATE;
    }
    transposed = ymajor(x0, y0, x1, y1);
    if (transposed) {
        double t;
        t = x0; x0 = y0; y0 = t;
        t = x1; x1 = y1; y1 = t;
    }
    if (x1 < x0) {                                  /* step toward increasing s */
        double t;
        t = x0; x0 = x1; x1 = t;
        t = y0; y0 = y1; y1 = t;
        swapped = 1;
    }
    m = (y1 - y0) / (x1 - x0);                      /* m = dy / dx */
    colors_start(&tn, col, swapped, x0, x1);
    if (java) {                                     /* for (int x = (int)x0; x <= (int)x1; ...) */
        s0 = pt_raster_java_int(x0);
        s1 = pt_raster_java_int(x1);
    } else {
        s0 = (int64_t)x0;
        s1 = (int64_t)x1;
    }
    if (stepping) tell_setup(&d, &su, transposed, swapped, s0, s1, y0, y1, m);
    if (transposed) walk(&d, 1, stepping, s0, s1, y0, m);
    else            walk(&d, 0, stepping, s0, s1, y0, m);
    return PT_RASTER_DRAWN;
}

/* out->pixel, which takes no colour (pt_raster_segment). */
static void plain_pixel(void *ud, int64_t x_vp, int64_t y_vp, const unsigned char rgb[3],
                        float cov)
{
    const pt_raster_out *out = ud;

    (void)rgb; (void)cov;
    out->pixel(out->ud, x_vp, y_vp);
}

/* Where pt_raster_walk() sends a pixel: ls->paint with the colour, or
** out->pixel. */
typedef struct painter {
    const pt_raster_out *out;
    const pt_raster_steps *ls;
} painter;

static void paint_pixel(void *ud, int64_t x_vp, int64_t y_vp, const unsigned char rgb[3],
                        float cov)
{
    const painter *pn = ud;
    pt_fb_paint pa;

    if (!pn->ls->paint) { pn->out->pixel(pn->out->ud, x_vp, y_vp); return; }
    memcpy(pa.rgb, rgb, sizeof pa.rgb);
    pa.coverage = cov;
    pn->ls->paint(pn->ls->ud, x_vp, y_vp, &pa);
}

int pt_raster_segment(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_vp to_vp,
                      const pt_raster_out *out)
{
    return segment(p0, p1, w, h, to_vp, plain_pixel, (void *)out, out, NULL, 0, NULL);
}

int pt_raster_walk(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_vp to_vp,
                   const pt_raster_out *out, const pt_raster_steps *ls)
{
    painter pn;

    pn.out = out;
    pn.ls = ls;
    return segment(p0, p1, w, h, to_vp, paint_pixel, &pn, out, ls, 1, &ls->col);
}

/* The pixels drawn and not yet told to the listener (im->pixel), which
** hears them a run at a time; a report of clipped steps goes to the
** caller's out->clip only after the pixels before it. */
typedef struct telling {
    pt_raster_drawn *listener;   /* im->pixel */
    void *listener_ud;
    const pt_raster_out *out;    /* the caller's, for the clipped steps */
    size_t n;                    /* pixels in px[] */
    pt_fb_pixel px[PT_RASTER_RUN];
} telling;

static void tell(telling *t)
{
    if (t->n) t->listener(t->listener_ud, t->px, t->n);
    t->n = 0;
}

static void tell_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    telling *t = ud;

    tell(t);
    t->out->clip(t->out->ud, count, first, last);
}

/* What pt_raster_draw() draws with: a copy of the pt_raster_image in its own
** frame.  The framebuffer's bytes are chars, which may alias anything the
** compiler cannot see is local: from the caller's struct, the pixel count
** and the framebuffer's size would be loaded and stored again around every
** pixel. */
typedef struct draw_ctx {
    pt_fb fb;                    /* the framebuffer (rgb NULL: only its size) */
    int x_ul, y_ul;              /* the viewport's corner */
    int wrap;                    /* 1: it sticks out: the course's index */
    int64_t npix;                /* W * H: the pixel array's length */
    uint64_t pixels;             /* pixels drawn */
    telling *tell;               /* with a listener: its pixels, else NULL */
} draw_ctx;

/* The index of framebuffer pixel f as the course's setPixelFB has it, with
** x_fb past the width wrapped into a neighbouring row (pt_raster_fb_pixel):
** the pixel (x_fb mod W, y_fb + floor(x_fb / W)) through the index stage;
** -1 for none.  Only called for a pixel the index stage left out, and only
** with the viewport sticking out of the framebuffer. */
static int64_t wrapped_index(pt_pix f, int W, int H)
{
    int64_t q;

    if (!f.ok) return -1;
    q = f.x / W;                                    /* floor(x_fb / W): rows crossed */
    if (f.x % W < 0) q--;
    f.x -= q * W;                                   /* 0 <= x < W */
    f.y += q;                                       /* |x_fb|, |y_fb| < 2^62: no overflow */
    return pt_fb2index(f, W, H, NULL);
}

int64_t pt_raster_fb_pixel(int64_t x_vp, int64_t y_vp, int x_ul, int y_ul, int W, int H,
                           int wrap, pt_fb_pixel *px)
{
    pt_pix vp = {x_vp, y_vp, 1};
    pt_pix f = pt_viewport2fb(vp, x_ul, y_ul, NULL);
    int64_t idx = pt_fb2index(f, W, H, NULL);

    if (idx < 0 && wrap) idx = wrapped_index(f, W, H);
    px->x_fb = f.x;
    px->y_fb = f.y;
    px->idx = idx;
    return idx;
}

/* A pixel inside the viewport through the framebuffer and index stages into
** the image, and to the listener when `listened`; one the stages put outside
** the pixel array is not drawn (a student's stage can: Java would throw), but
** with c->wrap goes where the course's index puts it (pt_raster_fb_pixel):
** the fast path, a viewport inside the framebuffer, never asks. */
static inline ALWAYS_INLINE void draw_pixel(draw_ctx *c, int listened, int64_t x_vp,
                                            int64_t y_vp, const unsigned char rgb[3],
                                            float cov)
{
    pt_pix vp = {x_vp, y_vp, 1};
    pt_pix f = pt_viewport2fb(vp, c->x_ul, c->y_ul, NULL);
    int64_t idx = pt_fb2index(f, c->fb.w, c->fb.h, NULL);

    if (idx < 0 && c->wrap) idx = wrapped_index(f, c->fb.w, c->fb.h);

    c->pixels++;
    if (listened) {
        telling *t = c->tell;
        pt_fb_pixel *q = &t->px[t->n];
        q->x_fb = f.x; q->y_fb = f.y; q->idx = idx;
        memcpy(q->paint.rgb, rgb, sizeof q->paint.rgb);
        q->paint.coverage = cov;
        if (++t->n == PT_RASTER_RUN) tell(t);
    }
    if ((!listened || c->fb.rgb) && idx >= 0 && idx < c->npix)
        pt_fb_set(&c->fb, idx, rgb);
}

static inline ALWAYS_INLINE void draw_quiet(void *ud, int64_t x_vp, int64_t y_vp,
                                             const unsigned char rgb[3], float cov)
{
    draw_pixel(ud, 0, x_vp, y_vp, rgb, cov);
}

static inline ALWAYS_INLINE void draw_listened(void *ud, int64_t x_vp, int64_t y_vp,
                                                const unsigned char rgb[3], float cov)
{
    draw_pixel(ud, 1, x_vp, y_vp, rgb, cov);
}

FLATTEN int pt_raster_draw(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_image *im,
                           const pt_raster_out *out)
{
    draw_ctx c;
    telling t;
    int r;

    assert(w > 0 && h > 0 && im->W > 0 && im->H > 0);
    assert(im->fb || im->pixel);
    assert(!im->fb || (im->fb->w == im->W && im->fb->h == im->H));
    if (im->fb) c.fb = *im->fb;
    else { c.fb.w = im->W; c.fb.h = im->H; c.fb.rgb = NULL; }
    c.x_ul = im->x_ul;
    c.y_ul = im->y_ul;
    c.wrap = im->wrap;
    c.npix = (int64_t)c.fb.w * c.fb.h;
    c.pixels = 0;
    c.tell = NULL;
    if (im->pixel) {
        pt_raster_out told = {NULL, tell_clip, &t};
        t.listener = im->pixel;
        t.listener_ud = im->pixel_ud;
        t.out = out;
        t.n = 0;
        c.tell = &t;
        r = segment(p0, p1, w, h, pt_pixel2viewport, draw_listened, &c, &told, NULL, 0,
                    &im->col);
        tell(&t);
    } else {
        r = segment(p0, p1, w, h, pt_pixel2viewport, draw_quiet, &c, out, NULL, 0, &im->col);
    }
    im->pixels += c.pixels;
    return r;
}
