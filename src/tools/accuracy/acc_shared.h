/*
** src/tools/accuracy/acc_shared.h -- what the three arithmetics share: journeys, integers, DDA steps
** See LICENSE for copyright and license.
**
** acc_float.c, acc_double.c and acc_dd.c each write the stages and the DDA in
** one arithmetic; accuracy.c runs them and compares.  This header holds what
** they all use: the journeys' types (every real value widened to pt_dd
** without rounding), the camera of one arithmetic, the integer stages
** (framebuffer and index, the same in every arithmetic), the DDA's integer
** bookkeeping (endpoints, order, band, steps), and the table of one
** arithmetic's stage functions (pt_acc_ops): one function per stage, which
** the journeys of the error runs call in order and the timing calls one at a
** time.
*/
#ifndef PT_ACC_SHARED_H
#define PT_ACC_SHARED_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "tools/accuracy/dd.h"

typedef enum pt_arith {
    PT_ARITH_FLOAT,
    PT_ARITH_DOUBLE,
    PT_ARITH_DD                  /* the reference */
} pt_arith;

/* How many arithmetics there are (the tables' length): not one of them, so
** that a switch over pt_arith lists exactly the arithmetics (-Wswitch-enum). */
#define PT_NARITH ((int)PT_ARITH_DD + 1)

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

/* The matrix camera's journey from clip coordinates on (stages/pt_matrix.c's
** pt_matrix_tail()): an inside vertex's, or a point that clipping made. */
typedef struct pt_acc_mtail {
    pt_dd k[4];                  /* the clip coordinates it starts from */
    double kerr[4];              /* the reference: bounds on k's rounding error */
    double en[3], es[2];         /* the reference: bounds on n's and sc's (x, y) */
    pt_dd n[3];                  /* ndc (x_n, y_n, z_n) */
    pt_dd sc[3];                 /* screen (x_s, y_s, z_s) */
    pt_pix vp, fb;               /* viewport (floor), framebuffer; ok == 0: no pixel */
    int64_t idx;                 /* index, or -1 outside the framebuffer */
    pt_dd pp[2];                 /* for the rasterizer: (x_vp + 1, h - y_vp); NaN: none */
} pt_acc_mtail;

/* One vertex's journey through the matrix camera, widened to pt_dd like
** pt_acc_journey. */
typedef struct pt_acc_mjourney {
    pt_dd m[3];                  /* model (x_m, y_m, z_m) as the arithmetic holds it */
    pt_dd w[4], v[4], k[4];      /* world, view, clip: (x y z w) */
    double werr[4], verr[4];     /* the reference: bounds on w's and v's rounding
                                 ** error (float, double: 0) */
    double kerr[4];              /* the reference: a bound on k's rounding error
                                 ** (float, double: 0) */
    unsigned code;               /* cvv outcode (PT_CVV_* bits); 0: inside */
    pt_acc_mtail t;              /* ndc .. index, when code == 0 (else all zero) */
} pt_acc_mjourney;

/* One segment of the matrix camera after clipping in clip space. */
typedef struct pt_acc_mseg {
    int visible;                 /* 0: culled, nothing of it is inside */
    int made[2];                 /* end e (0: first, 1: last) is a point clipping made */
    pt_dd t[2];                  /* its parameter on the segment, 0 <= t <= 1 */
    pt_acc_mtail end[2];         /* its journey from clip coordinates on */
} pt_acc_mseg;

typedef struct pt_acc_mat4f { float m[4][4]; } pt_acc_mat4f;   /* m[row][col] */

/* The matrix camera's matrices in one arithmetic: only that arithmetic's set
** is filled (float by acc_float.c, double by acc_double.c, the reference by
** acc_dd.c), and freed by pt_acc_mcam_free() (accuracy.h). */
typedef struct pt_acc_mcam {
    const pt_scene *s;           /* not owned */
    pt_arith arith;
    pt_acc_mat4f view_f, proj_f, *world_f;      /* float: world_f[k]; owned */
    pt_plan plan;                               /* double: the pipeline's own plan */
    pt_dd_mat4 view_dd, proj_dd, *world_dd;     /* double-double: world_dd[k]; owned */
    pt_mat4 view_e, proj_e, *world_e;           /* bounds on its entries' errors; owned */
} pt_acc_mcam;

/* ===== renderers 7 and 9 =====
**
** The course's renderers 7 and 9 (src/core/course.h) take a segment's ends
** through model, (r9: world,) view and camera; clip it at the near plane
** (a new point in camera coordinates); project; clip it to the square
** -1..1 (new points in the image plane, a cut at a time); and draw it
** between its ends' pixels, renderer 4's pixel stage (2.001) and Math.round. */

#define PT_ACC_RV_MAXCUTS 4      /* the clip's cuts a segment keeps: two an end
                                 ** (an edge, then the other axis's); more are
                                 ** counted, not kept (the stage allows 64) */

/* One vertex of renderers 7 and 9 up to the image plane, widened to pt_dd. */
typedef struct pt_acc_rvjourney {
    pt_dd m[3];                  /* model (x_m, y_m, z_m) as the arithmetic holds it */
    pt_dd w[4];                  /* r9: world (x y z w); r7: not used */
    pt_dd v[3];                  /* view */
    pt_dd c[3];                  /* camera (the view volume normalized) */
    pt_dd ip[2];                 /* image (x_p, y_p) */
} pt_acc_rvjourney;

/* One cut of a clip stage. */
typedef struct pt_acc_rvcut {
    int edge;                    /* pt_rv_edge: near, or x = +1, x = -1, y = +1, y = -1 */
    int off;                     /* the end it replaces: 0 or 1 */
    pt_dd t;                     /* the stage's t */
    pt_dd p[3];                  /* the new point (near: camera x y z; clip: x_p y_p) */
} pt_acc_rvcut;

/* One segment of renderers 7 and 9 through both clips. */
typedef struct pt_acc_rvseg {
    int near;                    /* 1 kept whole, 0 dropped, -1 cut (nearclip off: 1) */
    pt_acc_rvcut nc;             /* near == -1: the cut */
    pt_dd nip[2];                /* near == -1: the new point projected */
    int keep;                    /* after the clip to -1..1: 1 drawn */
    int ncuts;                   /* the clip's cuts (the first PT_ACC_RV_MAXCUTS kept) */
    pt_acc_rvcut cut[PT_ACC_RV_MAXCUTS];
    int made[2];                 /* drawn end e: 0 its vertex, 1 the near point,
                                 ** 2 a point the clip made */
    pt_acc_journey end[2];       /* keep: the drawn ends, ip .. idx (m, c unused) */
} pt_acc_rvseg;

/* The camera and matrices of renderers 7 and 9 in one arithmetic: the
** numbers as it holds them (float: rounded; the reference: the scene's
** doubles, exact); N and each position's matrix (r9) built in it, but the
** position matrices' own entries, which every arithmetic takes from the
** double stage (their sines and cosines).  world is owned. */
typedef struct pt_acc_rvcam {
    const pt_scene *s;           /* not owned */
    pt_arith arith;
    pt_dd l, r, b, t, n;         /* the view volume, the near plane's z */
    pt_dd view[3];               /* r9: the view vector */
    pt_dd norm[4][4];            /* r9: N, row i column j */
    pt_dd (*world)[4][4];        /* r9: world[k], model k's position matrix */
} pt_acc_rvcam;

#define PT_ACC_RV_NFRONT 5       /* model, world, view, camera, image */

/* A stage of renderers 7 and 9 up to the image plane, for vertex v of model
** k (r7's world: nothing).  Can't fail. */
typedef void (*pt_acc_rvstage_fn)(const pt_acc_rvcam *c, size_t k, pt_vec3 v,
                                  pt_acc_rvjourney *j);

/* Fill c (c->s set) with the scene's doubles as they are: l, r, b, t, n,
** the view vector, and c->world[k], each model's position matrix as the
** stage builds it in double (stages/r9_matrix.h; renderer 7: the identity);
** not c->norm.  Returns 0, or -1 when out of memory (c->world NULL). */
int pt_acc_rvcam_exact(pt_acc_rvcam *c);

/* ===== the integer stages ===== */

/* A value held exactly as the reference does: v, lo = 0.  This function can't
** fail. */
static inline pt_dd pt_acc_dd(double v)
{
    pt_dd r;

    r.hi = v;
    r.lo = 0.0;
    return r;
}

/* Classic camera: the viewport pixel of the pixel (rx, ry) that round() gave
** in another arithmetic (ok == 0: none): x_vp = rx - 1, y_vp = h - ry, by the
** reference viewport stage, handed rx and ry as the doubles they are (a
** whole number rounds to itself); beyond 2^53, where a double no longer
** holds every whole number, by the formula written out (unit test
** acc-9.x ties the two).  This function can't fail. */
pt_pix pt_acc_vp_of(const pt_scene *s, int ok, int64_t rx, int64_t ry);

/* x_fb = x_ul + x_vp, y_fb = y_ul + y_vp (s5_viewport2fb); none for none.
** This function can't fail. */
pt_pix pt_acc_fb_of(const pt_scene *s, pt_pix vp);

/* idx = y_fb * W + x_fb (s6_fb2index), or -1 outside the framebuffer.  This
** function can't fail. */
int64_t pt_acc_index_of(const pt_scene *s, pt_pix fb);

/* Matrix camera: the pixel-plane point of the viewport pixel t->vp for the
** rasterizer, (x_vp + 1, h - y_vp), held exactly (pt_dd_from_i64) when exact
** is set; NaN when t->vp has none.  This function can't fail. */
void pt_acc_mtail_pp(const pt_scene *s, pt_acc_mtail *t, int exact);

/* A vertex outside the view volume: its journey stops at the cvv.  This
** function can't fail. */
void pt_acc_no_tail(pt_acc_mtail *t);

/* ===== the DDA's integer bookkeeping ===== */

/* A segment after rounding its ends, in stepping order: s runs from s0 to
** s0 + ds, and the exact line is y = y0 + (s - s0) * dy / ds. */
typedef struct pt_acc_line {
    int64_t s0, y0;              /* the first endpoint */
    int64_t ds, dy;              /* ds >= 1 */
    int transposed;              /* 1: s is y and "y" is x (|slope| > 1) */
} pt_acc_line;

/* Where the steps go. */
typedef struct pt_acc_dda {
    void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp);  /* a pixel inside */
    void (*step)(void *ud, const pt_acc_line *ln, int64_t s, double y);
                                 /* every step in the band with its y, or NULL */
    void *ud;
    int w, h;                    /* the viewport */
    pt_raster_vp to_vp;          /* the viewport stage the double run's rasterizer
                                 ** asks (src/core/raster.h): ptref_pixel2viewport,
                                 ** or pt_pixelplane2viewport (matrix camera) */
} pt_acc_dda;

/* The exact line at step s, to about 2^-104: y0 + ((s - s0) * dy) / ds.  This
** function can't fail. */
pt_dd pt_acc_line_y(const pt_acc_line *ln, int64_t s);

/* Step along y (swap x and y of both integer ends e = (x0, y0, x1, y1)) when
** transposed, order the ends so that s increases, and fill ln; sets the band
** of steps that can be inside, [max(s0, 1), min(s1, w or h)].  This function
** can't fail. */
void pt_acc_dda_setup(pt_acc_line *ln, int transposed, int64_t e[4],
                      const pt_acc_dda *o, int64_t *first, int64_t *last);

/* Step s with y rounded to r (ok == 0: y has no integer, it drifted past
** 2^62): the pixel (s - 1, h - r), or (r - 1, h - s) when transposed, if
** inside; then o->step.  This function can't fail. */
void pt_acc_dda_step(const pt_acc_dda *o, const pt_acc_line *ln, int64_t s, int ok,
                     int64_t r, double y);

/* Both ends on the pixel (ix, iy): that pixel, if inside.  This function
** can't fail. */
void pt_acc_dda_dot(const pt_acc_dda *o, int64_t ix, int64_t iy);

/* ===== one arithmetic ===== */

#define PT_ACC_NSTAGES 7         /* classic: model .. index (rows of accuracy.h) */
#define PT_ACC_M_NFRONT 5        /* matrix camera: model, world, view, clip, cvv */
#define PT_ACC_M_NTAIL 5         /* ... then ndc, screen, viewport, framebuffer, index */

/* What a classic stage needs besides the journey. */
typedef struct pt_acc_sctx {
    const pt_scene *s;
    const pt_model *m;           /* the vertex's model */
    unsigned choices;            /* PT_ACC_* (the reference ignores them) */
    pt_stage_params par;         /* pt_stage_params_of(s, m) */
} pt_acc_sctx;

/* A classic stage: reads the earlier stages' values from j (the model stage:
** the scene's vertex v), writes its own.  Can't fail. */
typedef void (*pt_acc_stage_fn)(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j);

/* The matrix camera's stages up to the cvv, for vertex v of model k; as above. */
typedef void (*pt_acc_mstage_fn)(const pt_acc_mcam *c, size_t k, pt_vec3 v,
                                 pt_acc_mjourney *j);

/* The matrix camera's stages from ndc on, on a point from its clip coordinates
** t->k (a vertex inside the view volume, or a point clipping made). */
typedef void (*pt_acc_tail_fn)(const pt_scene *s, pt_acc_mtail *t);

/* One arithmetic's stages and DDA: acc_float.c's pt_acc_float_ops,
** acc_double.c's pt_acc_double_ops, acc_dd.c's pt_acc_dd_ops.  None can fail
** but by running out of memory (mcam).  The reference ignores choices.
** accuracy.c strings the stages together into journeys (pt_acc_journey_of,
** pt_acc_mjourney_of) and times them one by one (pt_acc_stage_pass). */
typedef struct pt_acc_ops {
    pt_acc_stage_fn stage[PT_ACC_NSTAGES];      /* classic: model .. index */
    int (*raster)(const pt_dd p0[2], const pt_dd p1[2], unsigned choices,
                  const pt_acc_dda *o);
                                 /* the DDA from p0 to p1 (pixel plane), the
                                 ** steps in the viewport's band to o: 0, or -1
                                 ** when an end has no integer pixel */
    int (*mcam)(pt_acc_mcam *c); /* fill c's matrices (c->s set): 0, or -1
                                 ** when out of memory */
    pt_acc_mstage_fn mstage[PT_ACC_M_NFRONT];   /* matrix: model .. cvv */
    pt_acc_tail_fn tail[PT_ACC_M_NTAIL];        /* matrix: ndc .. index */
    int (*mseg)(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                const pt_acc_mjourney *b, pt_acc_mseg *g);
                                 /* a-b clipped in clip space, g->made set by
                                 ** the caller: 1 with each made end's clip
                                 ** coordinates (g->end[e].k, .kerr) and t, 0
                                 ** culled; the caller runs the tails */
    int (*rvcam)(pt_acc_rvcam *c);   /* renderers 7, 9: fill c (c->s set): 0,
                                 ** or -1 when out of memory */
    pt_acc_rvstage_fn rvstage[PT_ACC_RV_NFRONT];  /* model .. image */
    int (*rvnear)(const pt_acc_rvcam *c, const pt_dd v0[3], const pt_dd v1[3],
                  pt_acc_rvcut *cut);
                                 /* the near clip of v0-v1 (camera): 1 kept,
                                 ** 0 dropped, -1 cut (then *cut) */
    int (*rvclip)(pt_dd e[2][2], pt_acc_rvseg *g);
                                 /* the clip of the image-plane segment e to
                                 ** -1..1: the cuts into g (ncuts, cut[]), e
                                 ** left with the kept piece's ends, g->made[]
                                 ** set to 2 where a cut replaced an end;
                                 ** returns 1 kept, 0 dropped */
} pt_acc_ops;

/* The framebuffer and index stages float and the reference share (integers:
** the same in every arithmetic), classic and from ndc on.  Can't fail. */
void pt_acc_fb_stage(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j);
void pt_acc_index_stage(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j);
void pt_acc_fb_tail(const pt_scene *s, pt_acc_mtail *t);
void pt_acc_index_tail(const pt_scene *s, pt_acc_mtail *t);

#endif
