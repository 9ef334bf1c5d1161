/*
** src/accuracy.h -- the pipeline in float, double and double-double, and its errors
** See LICENSE for copyright and license.
**
** `pipetrace accuracy` (src/cmd_accuracy.c) runs a scene's whole classic
** pipeline -- the six stages and the rasterizer -- in three arithmetics and
** measures how far each lands from a reference:
**
**   float          binary32, 24 significant bits.  The scene's doubles are
**                  rounded to float first; that rounding is float's error too.
**   double         binary64, 53 bits: exactly what the stages and src/raster.c
**                  compute (tests/test_accuracy.c checks it value for value).
**   double-double  the reference: a value is hi + lo, two doubles, 106 bits.
**                  Two-sum and two-product (with fma(), exactly rounded) make
**                  add, mul and div accurate to about 2^-104 relative.
**
** Reference semantics.  The same formulas in the same order, evaluated in
** double-double from the scene's doubles (taken as exact); 2.001 is the decimal
** number 2001/1000 (to 2^-110), not the double nearest it; Java's rounding is
** applied to the exact double-double value.  The reference DDA does not
** accumulate: at step s it computes y = y0 + ((s - s0) * dy) / dx from the
** rounded integer endpoints, the exact line (ties are exact while (s - s0) * dy
** < 2^53).  Errors are measured against the reference rounded to double.
**
** USAGE
**   pt_acc_run ref, r;  pt_acc_err e[PT_ACC_NROWS];
**   pt_acc_run_make(&ref, &s, PT_ARITH_DD, 0);
**   pt_acc_run_make(&r, &s, PT_ARITH_FLOAT, 0);
**   pt_acc_compare(&ref, &r, e);                   e[row]: that stage's errors
**   pt_acc_vertex_pass(&r);  pt_acc_raster_pass(&r, &n);     the timed work
**   pt_acc_run_free(&r);  pt_acc_run_free(&ref);
** Nothing here prints; only allocation can fail.
*/
#ifndef PT_ACCURACY_H
#define PT_ACCURACY_H

#include <stddef.h>
#include <stdint.h>
#include "scene.h"

/* ===== double-double ===== */

/* hi + lo with hi = fl(hi + lo): the unevaluated sum of two doubles.  A
** non-finite value has lo = 0. */
typedef struct pt_dd { double hi, lo; } pt_dd;

#define PT_DD_BITS 106           /* significant bits: 2 x 53 */

/* The double-double nearest 2001/1000, the constant of s3_image2pixel. */
extern const pt_dd pt_dd_2001;

/* x exactly.  This function can't fail. */
pt_dd pt_dd_from(double x);
/* v exactly (any int64_t).  This function can't fail. */
pt_dd pt_dd_from_i64(int64_t v);
/* a + b, a * b, a / b, -a: accurate to about 2^-104 relative; an infinite or
** NaN result is what double gives for hi.  These functions can't fail. */
pt_dd pt_dd_add(pt_dd a, pt_dd b);
pt_dd pt_dd_mul(pt_dd a, pt_dd b);
pt_dd pt_dd_div(pt_dd a, pt_dd b);
pt_dd pt_dd_neg(pt_dd a);

/* Java's Math.round of the exact value hi + lo, as pt_pix_round() does for a
** double: returns 1 and the integer in *out, or 0 (and *out = 0) when x is not
** finite or the result is at least 2^62 in magnitude.  This function can't fail. */
int pt_dd_pix_round(pt_dd x, int64_t *out);

/* ===== the pipeline in three arithmetics ===== */

typedef enum pt_arith {
    PT_ARITH_FLOAT,
    PT_ARITH_DOUBLE,
    PT_ARITH_DD,                 /* the reference */
    PT_NARITH
} pt_arith;

extern const char *const pt_arith_names[PT_NARITH];  /* "float", ... */
extern const int pt_arith_bits[PT_NARITH];           /* 24, 53, 106 */

/* Algorithm choices, for float and double (the reference ignores them). */
#define PT_ACC_TWO        0x01u  /* x_pp = 0.5 + w/2.0 * (x_ip + 1): 2 for 2.001 */
#define PT_ACC_RECOMPUTE  0x02u  /* DDA: y = y0 + m*(x - x0) each step, not y += m */

/* One vertex's journey, every real value widened to pt_dd without rounding
** (float and double: lo = 0).  z_ip is -1 or 0 in every arithmetic: not kept. */
typedef struct pt_acc_journey {
    pt_dd m[3];                  /* model (x_m, y_m, z_m) as the arithmetic holds it */
    pt_dd c[3];                  /* camera (x_c, y_c, z_c) */
    pt_dd ip[2];                 /* image (x_ip, y_ip) */
    pt_dd pp[2];                 /* pixel (x_pp, y_pp) */
    pt_pix vp, fb;               /* viewport, framebuffer; ok == 0: no pixel */
    int64_t idx;                 /* index, or -1 outside the framebuffer */
} pt_acc_journey;

/* A pixel of the final image: the last color written there. */
typedef struct pt_acc_pixel {
    int64_t idx;                 /* y_fb * W + x_fb */
    uint32_t rgb;                /* 0xRRGGBB */
} pt_acc_pixel;

/* Errors of one stage against the reference.  Absolute errors are
** |value - reference rounded to double| over every coordinate of every used
** vertex (raster: the accumulated y of every step inside the viewport's band,
** against the exact line through the same rounded endpoints).  A value with no
** counterpart (one side not finite or without a pixel) counts as infinite. */
typedef struct pt_acc_err {
    double max_abs;              /* largest absolute error */
    double sum_abs;              /* their sum: mean = sum_abs / n */
    double max_ulp;              /* largest error in ulps of the reference double */
    uint64_t n;                  /* values compared (0: no error to show) */
    int real;                    /* 1: real values (max_ulp means something) */
    uint64_t differ;             /* vertices (raster: pixels) unlike the reference */
    uint64_t of;                 /* used vertices (raster: pixels lit in either image) */
    uint64_t left, entered;      /* viewport: inside -> outside, outside -> inside */
} pt_acc_err;

/* The rows of the error table: the seven stages, then the rasterizer. */
typedef enum pt_acc_row {
    PT_ACC_MODEL, PT_ACC_CAMERA, PT_ACC_IMAGE, PT_ACC_PIXEL, PT_ACC_VIEWPORT,
    PT_ACC_FRAMEBUFFER, PT_ACC_INDEX, PT_ACC_RASTER, PT_ACC_NROWS
} pt_acc_row;

extern const char *const pt_acc_row_names[PT_ACC_NROWS];  /* "model", ... "raster" */

/* A scene run through the pipeline in one arithmetic.  Invariant: j[k][v] is
** set for every used vertex v of model k; img is sorted by idx, one entry per
** pixel written. */
typedef struct pt_acc_run {
    const pt_scene *s;           /* not owned; must outlive the run */
    pt_arith arith;
    unsigned choices;            /* PT_ACC_* */
    unsigned char **used;        /* used[k][v]: a segment uses it; owned */
    pt_acc_journey **j;          /* j[k][v]; owned */
    uint64_t nused;              /* used vertices in all models */
    pt_acc_pixel *img;           /* the final image's lit pixels; owned */
    size_t nimg;
    uint64_t pixels;             /* pixels written, overdraw included */
    pt_acc_err line;             /* the DDA's y against the exact line */
} pt_acc_run;

/* Run scene s (classic camera: s->matrix == 0) in arithmetic a with choices:
** every used vertex's journey, then the rasterizer into the image.  Returns 0,
** or -1 when out of memory (then *r is empty). */
int pt_acc_run_make(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices);

/* Free what *r owns.  This function can't fail. */
void pt_acc_run_free(pt_acc_run *r);

/* Compare run r with the reference ref (same scene): e[row] for each row.
** This function can't fail. */
void pt_acc_compare(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_NROWS]);

/* The timed work.  pt_acc_vertex_pass() computes every used vertex's journey
** again (into r->j, the same values); pt_acc_raster_pass() rasterizes every
** segment again, counting the pixels written in *pixels but keeping none.
** Each returns a checksum of what it computed, for the caller to keep the
** optimizer from skipping the work.  These functions can't fail. */
double pt_acc_vertex_pass(pt_acc_run *r);
double pt_acc_raster_pass(const pt_acc_run *r, uint64_t *pixels);

/* The DDA of src/raster.h in arithmetic a (float and double: y += m, or with
** PT_ACC_RECOMPUTE y = y0 + m*(x - x0); the reference: the exact line), for
** steps inside the viewport's band only.  pixel() gets each pixel inside the
** w x h viewport in step order.  Returns 0, or -1 when an endpoint has no
** integer pixel (nothing drawn).  Requires w, h >= 1.  This function can't fail. */
int pt_acc_raster_segment(pt_arith a, unsigned choices, pt_dd x0, pt_dd y0,
                          pt_dd x1, pt_dd y1, int w, int h,
                          void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp),
                          void *ud);

/* One vertex's journey in arithmetic a with choices.  This function can't fail. */
void pt_acc_journey_of(pt_arith a, unsigned choices, const pt_scene *s,
                       const pt_model *m, pt_vec3 v_m, pt_acc_journey *j);

#endif
