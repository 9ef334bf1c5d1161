/*
** stages/rv_raster.c -- renderers 7 and 9: rasterize a clipped primitive into the viewport
** See LICENSE for copyright and license.
**
** Java's int arithmetic wraps and its (int) of a double saturates (NaN is
** 0): both are spelled out below (jint, wrap32), as C leaves them undefined.
** Float expressions stay float (FLT_EVAL_METHOD 0, -ffp-contract=off).
*/
#include <math.h>
#include <string.h>
#include <stdint.h>
#include "rv_raster.h"
#include "pt_color.h"
#include "pt_round.h"
#include "pt_ref.h"

#if defined(__GNUC__)
#define ALWAYS_INLINE __attribute__((always_inline))
#else
#define ALWAYS_INLINE
#endif

typedef struct draw {
    const pt_rv_raster_par *par;
    unsigned char *rgb;
    const pt_rv_raster_ls *ls;
    uint64_t n;                  /* pixels written */
    uint64_t steps;              /* with count_steps, the pixel lines */
    int count_steps;             /*   (pt_rv_raster_steps) */
    int quiet;                   /* 1: nobody hears the pixels (ls or its
                                 ** pixel NULL): the quiet steps write
                                 ** bytes, with par->lut */
    int runs;                    /* 1: the listener hears loop steps in runs
                                 ** (ls->pixels: bytes_only, no bad) */
    int bytes;                   /* 1: quiet, or the listener reads bytes
                                 ** alone (bytes_only): no float gamma */
    unsigned char *vp0;          /* the viewport's pixel (0, 0) in rgb (NULL
                                 ** without rgb), */
    unsigned vw, vh;             /*   and its size when it lies inside the
                                 ** framebuffer (else 0 0): a pixel inside it
                                 ** needs none of Java's int arithmetic */
    size_t W;                    /* the framebuffer's width (par->W) */
    float bg[3];                 /* the viewport's background, byte / 255f */
    int flat;                    /* 1: the segment's colour is the same at every
                                 ** step (its slopes are 0): computed once */
    pt_rgb flat_c;               /*   that colour, */
    pt_rgb flat_g;               /*   as written (gamma-encoded when on), */
    unsigned char flat_b[3];     /*   and its bytes */
} draw;

/* Java's (int) of a double: toward zero, NaN 0, saturated. */
static int jint(double x)
{
    if (x != x) return 0;
    if (x >= 2147483647.0) return INT32_MAX;
    if (x <= -2147483648.0) return INT32_MIN;
    return (int)x;
}

/* The low 32 bits of v as a Java int (two's complement). */
static int wrap32(int64_t v)
{
    uint32_t u = (uint32_t)(uint64_t)v;
    return u <= (uint32_t)INT32_MAX ? (int)u : (int)(int32_t)(u - 2147483648u) + INT32_MIN;
}

/* Java's Math.round: a long, NaN 0, saturated at the long's ends. */
static int64_t jround(double x)
{
    double r = pt_java_round(x);
    if (r >= 9223372036854775807.0) return INT64_MAX;
    if (r <= -9223372036854775808.0) return INT64_MIN;
    return (int64_t)r;
}

/* The state a primitive (or the viewport's clearing) starts from. */
static void start(draw *d, const pt_rv_raster_par *par, unsigned char *rgb,
                  const pt_rv_raster_ls *ls)
{
    int k;

    d->par = par;
    d->rgb = rgb;
    d->ls = ls;
    d->n = d->steps = 0;
    d->count_steps = 0;
    d->quiet = ls == NULL || ls->pixel == NULL;
    d->bytes = d->quiet || ls->bytes_only;
    d->runs = !d->quiet && ls->bytes_only && ls->pixels && !ls->bad;
    d->vp0 = NULL;
    d->vw = d->vh = 0;
    d->W = 0;
    d->flat = 0;
    memset(&d->flat_c, 0, sizeof d->flat_c);
    memset(&d->flat_g, 0, sizeof d->flat_g);
    memset(d->flat_b, 0, sizeof d->flat_b);
    memset(d->bg, 0, sizeof d->bg);
    if (par->x_ul >= 0 && par->y_ul >= 0 && par->w >= 0 && par->h >= 0 &&
        (int64_t)par->x_ul + par->w <= par->W && (int64_t)par->y_ul + par->h <= par->H &&
        (rgb || !d->quiet)) {                   /* no pixels, nobody told: no shortcut */
        if (rgb) d->vp0 = rgb + 3 * ((size_t)par->y_ul * (size_t)par->W + (size_t)par->x_ul);
        d->vw = (unsigned)par->w;
        d->vh = (unsigned)par->h;
        d->W = (size_t)par->W;
    }
    if (par->antialias)                         /* only AA blends with it */
        for (k = 0; k < 3; k++) d->bg[k] = pt_color_float(par->bg[k]);   /* bg / 255f */
}

int pt_rv_fb_index(const pt_rv_raster_par *par, int x_vp, int y_vp, int *x_fb, int *y_fb)
{
    int x = wrap32((int64_t)par->x_ul + x_vp);                     /* x_ul + x */
    int y = wrap32((int64_t)par->y_ul + y_vp);                     /* y_ul + y */
    int idx = wrap32((int64_t)wrap32((int64_t)y * par->W) + x);    /* y*width + x */

    *x_fb = x;
    *y_fb = y;
    return idx < 0 || (int64_t)idx >= (int64_t)par->W * par->H ? -1 : idx;
}

/* FrameBuffer.setPixelVP(x, y, c) -> setPixelFB(x_ul + x, y_ul + y, c) for
** a pixel outside the viewport's shortcut (put_bytes): the pixel's bytes b
** at its wrapped index, or a "bad" report when the index is outside. */
static void put_wrapped(draw *d, int x_vp, int y_vp, const unsigned char *b)
{
    const pt_rv_raster_par *par = d->par;
    unsigned char *o;
    int x, y, idx;

    idx = pt_rv_fb_index(par, x_vp, y_vp, &x, &y);
    if (idx < 0) {
        if (d->ls && d->ls->bad) d->ls->bad(d->ls->ud, x, y, par->W, par->H);
        return;
    }
    if (d->rgb) {
        o = d->rgb + (size_t)idx * 3;
        o[0] = b[0];
        o[1] = b[1];
        o[2] = b[2];
    }
    d->n++;
}

/* FrameBuffer.setPixelVP(x, y, c): a pixel inside a viewport that lies in
** the framebuffer needs none of Java's int arithmetic (inline: every step
** writes one); any other goes through put_wrapped.  quiet: nobody listens,
** so there are pixels to write (start): the quiet loops ask no more. */
static inline ALWAYS_INLINE void put_bytes_q(draw *d, int x_vp, int y_vp, const unsigned char *b,
                                             int quiet)
{
    unsigned char *o;

    if ((unsigned)x_vp < d->vw && (unsigned)y_vp < d->vh) {
        if (quiet || d->vp0) {                      /* (none: nothing written) */
            o = d->vp0 + 3 * ((size_t)y_vp * (size_t)d->W + (size_t)x_vp);
            memcpy(o, b, 3);                        /* two stores, not three */
        }
        d->n++;
        return;
    }
    put_wrapped(d, x_vp, y_vp, b);
}

static inline ALWAYS_INLINE void put_bytes(draw *d, int x_vp, int y_vp, const unsigned char *b)
{
    put_bytes_q(d, x_vp, y_vp, b, 0);
}

static void tell(const draw *d, pt_rv_pixel *px)
{
    px->par = d->par;
    if (d->ls && d->ls->pixel) d->ls->pixel(d->ls->ud, px);
}

static pt_rgb gamma3(pt_rgb c)
{
    pt_rgb g;
    g.r = pt_gamma(c.r);                            /* (float)Math.pow(c, 1/2.2) */
    g.g = pt_gamma(c.g);
    g.b = pt_gamma(c.b);
    return g;
}

/* c as new Color(r, g, b) keeps it: byte(c) of each component. */
static void bytes3(pt_rgb c, unsigned char b[3])
{
    b[0] = pt_color_byte(c.r);
    b[1] = pt_color_byte(c.g);
    b[2] = pt_color_byte(c.b);
}

static inline unsigned char lut_byte(const pt_rv_gamma_lut *lut, float c);

/* The byte of component c as written: gamma-encoded when on (through the
** table when there is one), as java.awt.Color(float) keeps it. */
static inline unsigned char out_byte(const draw *d, float c)
{
    return d->par->gamma ? lut_byte(d->par->lut, c) : pt_color_byte(c);
}

/* The bytes b of colour c as written (out_byte of each component), a
** component equal to the one before taking its byte: a grey (white, the
** blend of white with black) looks the table up once.  (-0 == +0: both
** give byte 0; NaN equals nothing.) */
static inline void out_bytes(const draw *d, float r, float g, float bl, unsigned char b[3])
{
    b[0] = out_byte(d, r);
    b[1] = g == r ? b[0] : out_byte(d, g);
    b[2] = bl == g ? b[1] : out_byte(d, bl);
}

/* Colour c of a loop step or a point as written: *g the colour the listener
** hears (gamma-encoded when on, unless it reads bytes alone: then c) and b
** its bytes, byte(gamma(c)), by table when the floats are not wanted. */
static void written(const draw *d, pt_rgb c, pt_rgb *g, unsigned char b[3])
{
    if (d->bytes) {
        *g = c;
        out_bytes(d, c.r, c.g, c.b, b);
        return;
    }
    *g = d->par->gamma ? gamma3(c) : c;
    bytes3(*g, b);
}

/* The pixel-plane map of v: renderer 4's pixel stage, 0.5 + w/2.001 * (x + 1)
** (its reference copy, which a student's stage file does not replace). */
static pt_vec2 to_pp(const pt_rv_raster_par *par, pt_vec4 v)
{
    pt_vec3 ip = {v.x, v.y, 0.0};

    return ptref_image2pixel(ip, par->w, par->h, NULL);
}

/* The end pixel (x_pp, y_pp rounded, in the viewport's orientation): raw colour. */
static void end_pixel(draw *d, double x_pp, double y_pp, pt_rgb c)
{
    pt_rv_pixel px;
    unsigned char b[3];

    if (d->quiet) {                                 /* the same write, untold */
        bytes3(c, b);
        put_bytes(d, wrap32((int64_t)jint(x_pp) - 1),           /* (int)x - 1 */
                  wrap32((int64_t)d->par->h - jint(y_pp)), b);  /* h - (int)y */
        return;
    }
    memset(&px, 0, sizeof px);
    px.kind = PT_RV_PX_END;
    px.x_pp = x_pp;
    px.y_pp = y_pp;
    px.x_vp = wrap32((int64_t)jint(x_pp) - 1);     /* (int)x - 1 */
    px.y_vp = wrap32((int64_t)d->par->h - jint(y_pp));  /* h - (int)y */
    px.c[0] = c;
    bytes3(c, px.b[0]);
    tell(d, &px);
    put_bytes(d, px.x_vp, px.y_vp, px.b[0]);
}

/* One AA step's pair of pixels: y between rows (int)y and (int)y + 1 (in
** transposed coordinates), each blended with the background. */
typedef struct aa_pair {
    float f;                     /* the weight, fraction of y */
    int y_low, y_hi;
    int x_vp[2], y_vp[2];        /* the low pixel, the high one */
    float lo[3], hi[3];          /* their colours, before gamma */
} aa_pair;

/* small: |y| < 2^31 (line() checks), so (int)y needs no saturation;
** grey: c and the background each have three equal components, so one is
** blended for all (the same float operations give the same float). */
static inline ALWAYS_INLINE void aa_blend(const draw *d, int x, double y, int tr, pt_rgb c,
                                          aa_pair *a, int small, int grey)
{
    const pt_rv_raster_par *par = d->par;
    float f, in[3];
    int k;

    a->y_low = small ? (int)y : jint(y);
    a->y_hi = wrap32((int64_t)a->y_low + 1);
    if (!tr && y == (double)par->h) a->y_hi = par->h;   /* the top edge */
    if (tr && y == (double)par->w) a->y_hi = par->w;    /* the right edge */
    f = pt_aa_weight(y, (double)a->y_low);              /* weight = fraction of y */
    a->f = f;
    in[0] = c.r; in[1] = c.g; in[2] = c.b;
    for (k = 0; k < (grey ? 1 : 3); k++)                /* (1-f)*c + f*bg, f*c + (1-f)*bg */
        pt_aa_blend(in[k], d->bg[k], f, &a->lo[k], &a->hi[k]);
    if (grey) {
        a->lo[1] = a->lo[2] = a->lo[0];
        a->hi[1] = a->hi[2] = a->hi[0];
    }
    if (!tr) {
        a->x_vp[0] = a->x_vp[1] = wrap32((int64_t)x - 1);       /* x - 1 */
        a->y_vp[0] = wrap32((int64_t)par->h - a->y_low);        /* h - y_low */
        a->y_vp[1] = wrap32((int64_t)par->h - a->y_hi);
    } else {
        a->y_vp[0] = a->y_vp[1] = wrap32((int64_t)par->h - x);  /* h - x */
        a->x_vp[0] = wrap32((int64_t)a->y_low - 1);             /* y_low - 1 */
        a->x_vp[1] = wrap32((int64_t)a->y_hi - 1);
    }
}

/* One loop step with AA, told to the listener in *px (its kind and
** transposed set by the loop, the rest here). */
static inline ALWAYS_INLINE void step_aa(draw *d, int x, double y, int tr, pt_rgb c,
                                         pt_rv_pixel *px)
{
    aa_pair a;
    pt_rgb lo, hi;

    aa_blend(d, x, y, tr, c, &a, 0, 0);
    lo.r = a.lo[0]; lo.g = a.lo[1]; lo.b = a.lo[2];
    hi.r = a.hi[0]; hi.g = a.hi[1]; hi.b = a.hi[2];
    written(d, lo, &px->c[0], px->b[0]);
    written(d, hi, &px->c[1], px->b[1]);
    if (!tr) {
        px->x_pp = (double)x;
        px->y_pp = y;
        px->x_vp = a.x_vp[0];
        px->lo = a.y_vp[0];
        px->hi = a.y_vp[1];
    } else {
        px->x_pp = y;
        px->y_pp = (double)x;
        px->y_vp = a.y_vp[0];
        px->lo = a.x_vp[0];
        px->hi = a.x_vp[1];
    }
    tell(d, px);
    put_bytes(d, a.x_vp[0], a.y_vp[0], px->b[0]);
    put_bytes(d, a.x_vp[1], a.y_vp[1], px->b[1]);
}

/* The pixels of a run being gathered for ls->pixels (bytes_run). */
typedef struct run {
    pt_rv_px_out px[PT_RV_RUN];
    size_t n;
} run;

static inline ALWAYS_INLINE void run_flush(const draw *d, run *r)
{
    if (r->n) d->ls->pixels(d->ls->ud, d->par, r->px, r->n);
    r->n = 0;
}

static inline ALWAYS_INLINE void run_add(const draw *d, run *r, int x_vp, int y_vp,
                                         const unsigned char b[3], float coverage)
{
    pt_rv_px_out *o = &r->px[r->n++];

    o->x_vp = x_vp;
    o->y_vp = y_vp;
    o->coverage = coverage;
    memcpy(o->b, b, 3);
    if (r->n == PT_RV_RUN) run_flush(d, r);
}

/* One loop step with AA whose bytes come by table (nobody listens, or a
** listener of runs: d->runs); small and grey as for aa_blend (grey: one
** byte for three).  r: NULL when nobody listens, else the run the step's
** two pixels join. */
static inline ALWAYS_INLINE void step_aa_bytes(draw *d, int x, double y, int tr, pt_rgb c,
                                               int small, int grey, run *r)
{
    aa_pair a;
    unsigned char lo[3], hi[3];

    aa_blend(d, x, y, tr, c, &a, small, grey);
    if (grey) {
        lo[0] = lo[1] = lo[2] = out_byte(d, a.lo[0]);
        hi[0] = hi[1] = hi[2] = out_byte(d, a.hi[0]);
    } else {
        out_bytes(d, a.lo[0], a.lo[1], a.lo[2], lo);
        out_bytes(d, a.hi[0], a.hi[1], a.hi[2], hi);
    }
    if (r) {                                        /* low, then high */
        run_add(d, r, a.x_vp[0], a.y_vp[0], lo, 1.0f - a.f);
        run_add(d, r, a.x_vp[1], a.y_vp[1], hi, a.f);
    }
    put_bytes_q(d, a.x_vp[0], a.y_vp[0], lo, r == NULL);
    put_bytes_q(d, a.x_vp[1], a.y_vp[1], hi, r == NULL);
}

/* A loop step's pixel without AA: the row Math.round(y) (in transposed
** coordinates); in: |y| < PT_PIX_LIMIT is known (the loops of a segment
** whose ends lie within 2^30), so the rounding needs no range test. */
static inline ALWAYS_INLINE void plain_pixel(const draw *d, int x, double y, int tr, int in,
                                             int *x_vp, int *y_vp)
{
    int64_t r;                                      /* (int)Math.round(y): low 32 bits */
    int ry = wrap32(in ? pt_pix_round_in(y)
                       : pt_pix_round(y, &r) ? r : jround(y));  /* inline below 2^62 */

    if (!tr) {
        *x_vp = wrap32((int64_t)x - 1);             /* x - 1 */
        *y_vp = wrap32((int64_t)d->par->h - ry);    /* h - round(y) */
    } else {
        *x_vp = wrap32((int64_t)ry - 1);            /* round(y) - 1 */
        *y_vp = wrap32((int64_t)d->par->h - x);     /* h - x */
    }
}

/* One loop step without AA, told to the listener in *px (its kind and
** transposed set by the loop, and for a flat segment its colour and bytes:
** d->flat_g, d->flat_b); in as for plain_pixel. */
static inline ALWAYS_INLINE void step_plain(draw *d, int x, double y, int tr, pt_rgb c,
                                            pt_rv_pixel *px, int in)
{
    if (!d->flat) written(d, c, &px->c[0], px->b[0]);
    px->x_pp = tr ? y : (double)x;
    px->y_pp = tr ? (double)x : y;
    plain_pixel(d, x, y, tr, in, &px->x_vp, &px->y_vp);
    tell(d, px);
    put_bytes(d, px->x_vp, px->y_vp, px->b[0]);
}

/* One loop step without AA whose bytes come by table (d->bytes): flat, the
** segment's (d->flat_b); in as for plain_pixel; r as for step_aa_bytes. */
static inline ALWAYS_INLINE void step_plain_bytes(draw *d, int x, double y, int tr, pt_rgb c,
                                                  int flat, int in, run *r)
{
    unsigned char b[3];
    int x_vp, y_vp;

    plain_pixel(d, x, y, tr, in, &x_vp, &y_vp);
    if (!flat) out_bytes(d, c.r, c.g, c.b, b);
    if (r) run_add(d, r, x_vp, y_vp, flat ? d->flat_b : b, 1.0f);
    put_bytes_q(d, x_vp, y_vp, flat ? d->flat_b : b, r == NULL);
}

/* Ask for the framebuffer lines the steps x .. xe - 1 will write (near
** enough: the rows y rounds to) before the first write, for a listener:
** a segment's pixels lie on as many lines as it is long when it is steep,
** and with a record written between two writes each write would wait for
** its line in turn.  (Without one the processor finds them as fast.) */
static inline ALWAYS_INLINE void prefetch(const draw *d, int x, int xe, double y, double m,
                                          int tr)
{
#if defined(__GNUC__)
    int x_vp, y_vp;

    for (; x < xe; x++, y += m) {
        plain_pixel(d, x, y, tr, 1, &x_vp, &y_vp);
        if ((unsigned)x_vp < d->vw && (unsigned)y_vp < d->vh && d->vp0)
            __builtin_prefetch(d->vp0 + 3 * ((size_t)y_vp * d->W + (size_t)x_vp), 1);
    }
#else
    (void)d; (void)x; (void)xe; (void)y; (void)m; (void)tr;
#endif
}

/* The loop x = x .. xe - 1, y += m, when nobody listens or a listener of
** runs does (told: ls->pixels), and |y| < 2^31 at every step: the steps of
** line() below, in a copy of its own for each constant tr, aa, flat, grey
** (aa_blend) and told, so that no step asks them again.  c0 and mc: the
** colour at x0 and its slopes (unused when flat: d->flat_c). */
static inline ALWAYS_INLINE void bytes_run(draw *d, int x, int xe, double y, double m, int tr,
                                           int aa, int flat, int grey, int told, pt_rgb c0,
                                           const double mc[3], double x0)
{
    pt_rgb c = d->flat_c;
    run r;

    r.n = 0;
    if (told) prefetch(d, x, xe, y, m, tr);       /* the records between the writes */
    for (; x < xe; x++, y += m) {                   /* y accumulated: y += m */
        if (!flat) {
            c.r = pt_color_at(c0.r, mc[0], (double)x, x0);  /* |c0 + mc*(x - x0)| */
            c.g = pt_color_at(c0.g, mc[1], (double)x, x0);
            c.b = pt_color_at(c0.b, mc[2], (double)x, x0);
        }
        if (aa) step_aa_bytes(d, x, y, tr, c, 1, grey, told ? &r : NULL);
        else step_plain_bytes(d, x, y, tr, c, flat, 1, told ? &r : NULL);
    }
    if (told) run_flush(d, &r);
}

static void bytes_loop(draw *d, int x, int xe, double y, double m, int tr, pt_rgb c0,
                       const double mc[3], double x0)
{
    const float *bg = d->bg;
    pt_rgb f = d->flat_c;
    int aa = d->par->antialias, flat = d->flat, told = d->runs;
    int grey = aa && flat && f.r == f.g && f.g == f.b && bg[0] == bg[1] && bg[1] == bg[2];

#define BYTES_RUN(TR, TOLD) do {                                                          \
        if (!aa && flat) bytes_run(d, x, xe, y, m, TR, 0, 1, 0, TOLD, c0, mc, x0);        \
        else if (!aa)    bytes_run(d, x, xe, y, m, TR, 0, 0, 0, TOLD, c0, mc, x0);        \
        else if (grey)   bytes_run(d, x, xe, y, m, TR, 1, 1, 1, TOLD, c0, mc, x0);        \
        else if (flat)   bytes_run(d, x, xe, y, m, TR, 1, 1, 0, TOLD, c0, mc, x0);        \
        else             bytes_run(d, x, xe, y, m, TR, 1, 0, 0, TOLD, c0, mc, x0);        \
    } while (0)
    if (!told) { if (!tr) BYTES_RUN(0, 0); else BYTES_RUN(1, 0); }
    else       { if (!tr) BYTES_RUN(0, 1); else BYTES_RUN(1, 1); }
#undef BYTES_RUN
}

/* A segment's ends as the DDA takes them, from its ends p0, p1 in the pixel
** plane: rounded to logical pixels (Math.round, kept in doubles); unless
** both round to one pixel, transposed when |slope| > 1 and ordered so that
** x0 <= x1.  The loop then steps x = (int)x0 .. (int)x1 - 1, and the last
** pixel ends it. */
typedef struct dda_ends {
    double x0, y0, x1, y1;
    int one;                     /* 1: one pixel, (x0, y0) (not transposed) */
    int tr;                      /* 1: transposed */
    int swapped;                 /* 1: the ends swapped (their colours too) */
} dda_ends;

/* Math.round(x), kept in a double: inline below 2^62. */
static inline double round_end(double x)
{
    int64_t r;
    return (double)(pt_pix_round(x, &r) ? r : jround(x));
}

static inline void dda_order(dda_ends *e, pt_vec2 p0, pt_vec2 p1)
{
    double t;

    e->x0 = round_end(p0.x);                        /* Math.round, kept in a double */
    e->y0 = round_end(p0.y);
    e->x1 = round_end(p1.x);
    e->y1 = round_end(p1.y);
    e->one = e->tr = e->swapped = 0;
    if (e->x0 == e->x1 && e->y0 == e->y1) { e->one = 1; return; }
    if (fabs(e->y1 - e->y0) > fabs(e->x1 - e->x0)) {    /* |slope| > 1: transpose */
        t = e->x0; e->x0 = e->y0; e->y0 = t;
        t = e->x1; e->x1 = e->y1; e->y1 = t;
        e->tr = 1;
    }
    if (e->x1 < e->x0) {                            /* step in increasing x */
        t = e->x0; e->x0 = e->x1; e->x1 = t;
        t = e->y0; e->y0 = e->y1; e->y1 = t;
        e->swapped = 1;
    }
}

/* A point's rows ylo .. yhi and columns xlo .. xhi (pixel plane) around
** its rounded centre (x, y); with clip, only those inside the viewport
** (1 .. h, 1 .. w), which are all that is written. */
typedef struct point_box {
    int64_t xlo, xhi, ylo, yhi;
} point_box;

static void point_rows(point_box *b, const pt_rv_raster_par *par, double x, double y,
                       int radius, int clip)
{
    int ix = jint(x), iy = jint(y);

    b->ylo = wrap32((int64_t)iy - radius);          /* (int)y - radius .. + radius */
    b->yhi = wrap32((int64_t)iy + radius);
    b->xlo = wrap32((int64_t)ix - radius);
    b->xhi = wrap32((int64_t)ix + radius);
    if (!clip) return;
    if (b->ylo < 1) b->ylo = 1;
    if (b->yhi > par->h) b->yhi = par->h;
    if (b->xlo < 1) b->xlo = 1;
    if (b->xhi > par->w) b->xhi = par->w;
}

/* The pixel lines of a segment whose ends are e: the loop's steps
** (int)x0 .. (int)x1 - 1 and the last pixel, or the one pixel. */
static uint64_t line_steps(const dda_ends *e)
{
    int64_t n = (int64_t)jint(e->x1) - jint(e->x0);

    return e->one ? 1 : (uint64_t)(n > 0 ? n : 0) + 1;
}

/* The pixel lines of a point whose clipped rows and columns are b. */
static uint64_t point_steps(const point_box *b)
{
    return b->ylo <= b->yhi && b->xlo <= b->xhi    /* rows x columns inside */
           ? (uint64_t)(b->yhi - b->ylo + 1) * (uint64_t)(b->xhi - b->xlo + 1) : 0;
}

static void line(draw *d, const pt_rv_model *m, const pt_rv_prim *p)
{
    const pt_rv_raster_par *par = d->par;
    pt_vec4 v0 = m->v[p->v[0]], v1 = m->v[p->v[1]];
    pt_rgb c0 = m->c[p->c[0]], c1 = m->c[p->c[1]], c;
    pt_vec2 p0 = to_pp(par, v0), p1 = to_pp(par, v1);
    dda_ends e;
    double x0, y0, x1, y1, y;
    pt_rv_slopes s = {0};
    pt_rv_pixel px;
    int x, xe, tr, in;

    if (d->ls && d->ls->ends) d->ls->ends(d->ls->ud, p0.x, p0.y, p1.x, p1.y);
    dda_order(&e, p0, p1);
    if (d->count_steps) d->steps = line_steps(&e);
    x0 = e.x0; y0 = e.y0; x1 = e.x1; y1 = e.y1;
    if (e.one) {                                    /* one pixel: v0's colour */
        end_pixel(d, x0, y0, c0);
        return;
    }
    tr = e.tr;
    if (e.swapped) { c = c0; c0 = c1; c1 = c; }
    s.m = (y1 - y0) / (x1 - x0);                    /* m = dy/dx */
    s.transposed = tr;
    /* (float)(c1 - c0) / dx; dx > 0 here, so equal components give +0
    ** without the division */
    s.mc[0] = c0.r == c1.r ? 0.0 : pt_color_slope(c0.r, c1.r, x1 - x0);
    s.mc[1] = c0.g == c1.g ? 0.0 : pt_color_slope(c0.g, c1.g, x1 - x0);
    s.mc[2] = c0.b == c1.b ? 0.0 : pt_color_slope(c0.b, c1.b, x1 - x0);
    s.x0_vp = x0 - 1.0;
    s.y0_vp = (double)par->h - y0;
    s.x1_vp = x1 - 1.0;
    s.y1_vp = (double)par->h - y1;
    if (d->ls && d->ls->slopes) d->ls->slopes(d->ls->ud, &s);

    y = y0;
    xe = jint(x1);
    /* slopes of 0: |c0 + 0 * (x - x0)| is |c0| at every step (x - x0 finite) */
    d->flat = s.mc[0] == 0.0 && s.mc[1] == 0.0 && s.mc[2] == 0.0;
    if (d->flat) {
        d->flat_c.r = pt_color_at(c0.r, 0.0, x0, x0);
        d->flat_c.g = pt_color_at(c0.g, 0.0, x0, x0);
        d->flat_c.b = pt_color_at(c0.b, 0.0, x0, x0);
        written(d, d->flat_c, &d->flat_g, d->flat_b);
    }
    /* with its ends within 2^30, the loop takes x1 - x0 steps and y runs
    ** from y0 toward y1: it stays within 2^31 (and PT_PIX_LIMIT) */
    in = fabs(x0) <= 1073741824.0 && fabs(x1) <= 1073741824.0 &&
         fabs(y0) <= 1073741824.0 && fabs(y1) <= 1073741824.0;
    if ((d->quiet || d->runs) && in) {
        bytes_loop(d, jint(x0), xe, y, s.m, tr, c0, s.mc, x0);
    } else {
        memset(&px, 0, sizeof px);                  /* what no step changes */
        px.kind = par->antialias ? PT_RV_PX_AA : PT_RV_PX_STEP;
        px.transposed = tr;
        px.c[0] = d->flat_g;
        memcpy(px.b[0], d->flat_b, 3);
        for (x = jint(x0); x < xe; x++, y += s.m) { /* y accumulated: y += m */
            if (d->flat) {
                c = d->flat_c;
            } else {
                c.r = pt_color_at(c0.r, s.mc[0], (double)x, x0);  /* |c0 + mc*(x - x0)| */
                c.g = pt_color_at(c0.g, s.mc[1], (double)x, x0);
                c.b = pt_color_at(c0.b, s.mc[2], (double)x, x0);
            }
            if (d->quiet) {
                if (par->antialias) step_aa_bytes(d, x, y, tr, c, 0, 0, NULL);
                else step_plain_bytes(d, x, y, tr, c, d->flat, 0, NULL);
            } else if (par->antialias) {
                step_aa(d, x, y, tr, c, &px);
            } else if (in) {
                step_plain(d, x, y, tr, c, &px, 1);
            } else {
                step_plain(d, x, y, tr, c, &px, 0);
            }
        }
    }
    d->flat = 0;
    if (!tr) end_pixel(d, x1, y1, c1);              /* the last pixel: raw colour */
    else end_pixel(d, y1, x1, c1);
}

static void point(draw *d, const pt_rv_model *m, const pt_rv_prim *p)
{
    const pt_rv_raster_par *par = d->par;
    pt_vec4 v = m->v[p->v[0]];
    pt_rgb c = m->c[p->c[0]];
    pt_vec2 q = to_pp(par, v);
    double x = q.x, y = q.y;
    int64_t xs, ys;
    point_box b;
    pt_rv_pixel px = {0};

    if (d->ls && d->ls->point) d->ls->point(d->ls->ud, x, y);
    x = (double)jround(x);
    y = (double)jround(y);
    /* nobody hears the clipped pixels: only rows 1..h and columns 1..w are
    ** written, so the loops run over those alone (a radius of thousands
    ** costs the viewport, not (2r + 1)^2) */
    point_rows(&b, par, x, y, p->radius, 1);
    if (d->count_steps) d->steps = point_steps(&b);
    if (d->ls && d->ls->pixel && d->ls->clipped_points)
        point_rows(&b, par, x, y, p->radius, 0);
    px.kind = PT_RV_PX_POINT;
    px.x_pp = x;
    px.y_pp = y;
    written(d, c, &px.c[0], px.b[0]);
    for (ys = b.ylo; ys <= b.yhi; ys++)             /* rows outer, bottom first */
        for (xs = b.xlo; xs <= b.xhi; xs++) {
            px.clipped = !(xs > 0 && xs <= par->w && ys > 0 && ys <= par->h);
            px.x_vp = wrap32(xs - 1);               /* x_ - 1 */
            px.y_vp = wrap32((int64_t)par->h - ys); /* h - y_ */
            tell(d, &px);
            if (!px.clipped) put_bytes(d, px.x_vp, px.y_vp, px.b[0]);
        }
}

uint64_t pt_rv_raster_prim(const pt_rv_model *m, const pt_rv_prim *p,
                           const pt_rv_raster_par *par, unsigned char *rgb,
                           const pt_rv_raster_ls *ls)
{
    return pt_rv_raster_prim_steps(m, p, par, rgb, ls, NULL);
}

uint64_t pt_rv_raster_prim_steps(const pt_rv_model *m, const pt_rv_prim *p,
                                 const pt_rv_raster_par *par, unsigned char *rgb,
                                 const pt_rv_raster_ls *ls, uint64_t *steps)
{
    draw d;

    start(&d, par, rgb, ls);
    d.count_steps = steps != NULL;
    switch (p->kind) {
    case PT_RV_LINE:  line(&d, m, p); break;
    case PT_RV_POINT: point(&d, m, p); break;
    }
    if (steps) *steps = d.steps;
    return d.n;
}

uint64_t pt_rv_raster_steps(const pt_rv_model *m, const pt_rv_prim *p,
                            const pt_rv_raster_par *par)
{
    dda_ends e;
    point_box b;
    pt_vec2 q;

    switch (p->kind) {
    case PT_RV_LINE:
        dda_order(&e, to_pp(par, m->v[p->v[0]]), to_pp(par, m->v[p->v[1]]));
        return line_steps(&e);
    case PT_RV_POINT:
        q = to_pp(par, m->v[p->v[0]]);
        point_rows(&b, par, (double)jround(q.x), (double)jround(q.y), p->radius, 1);
        return point_steps(&b);
    }
    return 0;
}

uint64_t pt_rv_clear_vp(const pt_rv_raster_par *par, unsigned char *rgb,
                        const pt_rv_raster_ls *ls)
{
    draw d;
    int x, y;

    start(&d, par, rgb, ls);
    if (d.vw > 0 && d.vh > 0) {                     /* inside: row 0, copied */
        if (!rgb) return (uint64_t)par->w * (uint64_t)par->h;
        for (x = 0; x < par->w; x++) put_bytes(&d, x, 0, par->bg);
        for (y = 1; y < par->h; y++)
            memcpy(d.vp0 + 3 * (size_t)y * (size_t)par->W, d.vp0, 3 * (size_t)par->w);
        return (uint64_t)par->w * (uint64_t)par->h;
    }
    for (y = 0; y < par->h; y++)                    /* Viewport.clearVP() */
        for (x = 0; x < par->w; x++)
            put_bytes(&d, x, y, par->bg);
    return d.n;
}

/* ===== byte(gamma(c)) by table (rv_raster.h) ===== */

#define LUT_LO  0x35800000u      /* the bits of 2^-20 */
#define LUT_ONE 0x3F800000u      /* of 1.0f */
#define LUT_INF 0x7F800000u      /* of +infinity */

static float from_bits(uint32_t b)
{
    float c;
    memcpy(&c, &b, sizeof c);
    return c;
}

static unsigned char gamma_byte(float c)
{
    return pt_color_byte(pt_gamma(c));              /* byte((float)pow(c, 1/2.2)) */
}

void pt_rv_gamma_lut_init(pt_rv_gamma_lut *lut)
{
    unsigned char last = 0;
    int k;

    lut->ok = gamma_byte(0.0f) == 0 && gamma_byte(from_bits(LUT_LO - 1)) == 0 &&
              gamma_byte(1.0f) == 255 && gamma_byte(from_bits(LUT_INF)) == 255;
    for (k = 0; k < PT_RV_LUT_N; k++) {
        uint32_t a = LUT_LO + ((uint32_t)k << 16), b = a + 0xffffu;
        unsigned char lo = gamma_byte(from_bits(a)), hi = gamma_byte(from_bits(b));

        lut->lo[k] = lo;
        lut->step[k] = b + 1;                       /* no step in this range */
        if (lo < last || hi < lo || hi > lo + 1) lut->ok = 0;
        last = hi;
        if (hi == lo) continue;
        while (b - a > 1) {                         /* byte(a) = lo, byte(b) = lo + 1 */
            uint32_t m = a + (b - a) / 2;
            if (gamma_byte(from_bits(m)) == lo) a = m;
            else b = m;
        }
        lut->step[k] = b;
    }
}

static inline unsigned char lut_byte(const pt_rv_gamma_lut *lut, float c)
{
    uint32_t b;

    memcpy(&b, &c, sizeof b);
    if (lut && lut->ok) {
        if (b - LUT_LO < LUT_ONE - LUT_LO) {        /* 2^-20 <= c < 1 */
            uint32_t k = (b - LUT_LO) >> 16;
            return (unsigned char)(lut->lo[k] + (b >= lut->step[k]));
        }
        if (b < LUT_LO) return 0;                   /* 0 <= c < 2^-20 */
        if (b <= LUT_INF) return 255;               /* 1 <= c <= infinity */
    }
    return gamma_byte(c);                           /* negative, NaN; no table */
}

unsigned char pt_rv_gamma_byte(const pt_rv_gamma_lut *lut, float c)
{
    return lut_byte(lut, c);
}
