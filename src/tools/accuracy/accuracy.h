/*
** src/tools/accuracy/accuracy.h -- the pipeline in float, double and double-double, and its errors
** See LICENSE for copyright and license.
**
** `pipetrace accuracy` (src/tools/accuracy/cmd_accuracy.c) runs a scene's whole pipeline --
** every stage of its camera and the rasterizer -- in three arithmetics and
** measures how far each lands from a reference:
**
**   float          binary32, 24 significant bits.  The scene's doubles are
**                  rounded to float first; that rounding is float's error too.
**   double         binary64, 53 bits: the stages of stages/ (their
**                  reference copy, ptref_*, in a student build too),
**                  stages/ms_clip_segment.c and src/core/raster.c themselves
**                  (acc_double.c), so their values are the reference
**                  build's trace's (tests/unit/test_accuracy.c checks it).
**   double-double  the reference: a value is hi + lo, two doubles, 106 bits
**                  (dd.h).  Two-sum and two-product (with fma(), exactly
**                  rounded) make add, mul and div accurate to about 2^-104
**                  relative.
**
** One file per arithmetic: acc_float.c, acc_double.c, acc_dd.c, each with
** both cameras' stages and the DDA; acc_shared.c holds what they share (the
** journeys' types, the integer stages, the DDA's bookkeeping); this module
** runs them and measures the errors.
**
** Reference semantics.  The same formulas in the same order, evaluated in
** double-double from the scene's doubles (taken as exact); 2.001 is the decimal
** number 2001/1000 (to 2^-110), not the double nearest it; Java's rounding is
** applied to the exact double-double value.  The reference DDA does not
** accumulate: at step s it computes y = y0 + ((s - s0) * dy) / dx from the
** rounded integer endpoints, the exact line (ties are exact while (s - s0) * dy
** < 2^53).  Errors are measured against the reference rounded to double.
**
** The matrix camera (its pipeline has matrices): each arithmetic builds View, Projection and
** every World itself, with stages/pt_mat4.c's formulas: float from the
** scene's numbers rounded to float (sqrtf, sinf, cosf), double by the
** pipeline's own plan (pt_lookat(), pt_perspective()), the reference in
** double-double (a double-double sqrt; cot(fov/2) from Taylor series, to about
** 2^-104).  World = (product of the `world` lines) * T(translate): the scene
** keeps only that product, multiplied out in double by the parser, so every
** arithmetic takes it as an input -- the reference as exact, float rounded --
** and its rotations' sines and cosines are double's.  Segments are clipped in
** clip space in each arithmetic (stages/ms_clip_segment.c's Liang-Barsky), and the points
** clipping makes go on through ndc .. index in that arithmetic.  Ties: the
** reference carries a bound on each value's rounding error (2^-100 of the
** magnitudes it comes from, first order) and takes a value within its bound of
** 0 as 0, a screen coordinate within its bound of an integer as that integer:
** exact arithmetic puts a point on a plane or a pixel edge there (the look-at
** target at the screen's centre, say), and 2^-104 of rounding must not pick
** the side.
**
** Renderers 7 and 9 (the course's, src/core/course.h): their own stages in
** each arithmetic (float and the reference from acc_rv_tmpl.h, the stages'
** formulas written once for any number type; double the stages themselves),
** each segment through the near clip and the clip to -1..1, the ends drawn
** through renderer 4's pixel .. index stages and the DDA.  The clips' rows
** compare t and the new points of segments cut alike; a segment cut otherwise
** counts as decided otherwise (pt_acc_err.decided) and its values as inf.
** The reference has no tie rule here.
**
** USAGE
**   pt_acc_run ref, r;  pt_acc_err e[PT_ACC_MAXROWS];
**   pt_acc_run_make(&ref, &s, PT_ARITH_DD, 0);
**   pt_acc_run_make(&r, &s, PT_ARITH_FLOAT, 0);
**   pt_acc_compare(&ref, &r, e);                   e[row]: that stage's errors
**                      (rows: pt_acc_scene_rows(&s))
**   w = pt_acc_work_make(&r, row);  pt_acc_stage_pass(w, row);   one stage, timed
**   pt_acc_work_free(w);  pt_acc_raster_pass(&r, &n);       the rasterizer, timed
**   pt_acc_run_free(&r);  pt_acc_run_free(&ref);
** or, memory bounded by a block, not by the scene: pt_acc_block below.
** Nothing here prints; only allocation can fail.
*/
#ifndef PT_ACCURACY_H
#define PT_ACCURACY_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "tools/accuracy/acc_shared.h"

extern const char *const pt_arith_names[PT_NARITH];  /* "float", ... */
extern const int pt_arith_bits[PT_NARITH];           /* 24, 53, 106 */

/* A pixel of the final image: the last color written there. */
typedef struct pt_acc_pixel {
    int64_t idx;                 /* y_fb * W + x_fb */
    uint32_t rgb;                /* 0xRRGGBB */
} pt_acc_pixel;

/* Errors of one stage against the reference.  Absolute errors are
** |value - reference rounded to double| over every coordinate of every used
** vertex (raster: the accumulated y of every step inside the viewport's band,
** against the exact line through the same rounded endpoints).  A value with no
** counterpart (one side not finite or without a pixel) counts as infinite.
** Matrix camera: ndc .. index compare the used vertices inside the view volume
** and the points clipping makes (by segment end), in either run; one that
** exists in one run only counts as infinite and as differing; the cvv row
** counts outcodes unlike the reference's (differ) and has no error (n = 0). */
typedef struct pt_acc_err {
    double max_abs;              /* largest absolute error */
    double sum_abs;              /* their sum: mean = sum_abs / n */
    double max_ulp;              /* largest error in ulps of the reference double */
    uint64_t n;                  /* values compared (0: no error to show) */
    int real;                    /* 1: real values (max_ulp means something) */
    uint64_t differ;             /* vertices (raster: pixels) unlike the reference */
    uint64_t of;                 /* used vertices (raster: pixels lit in either image) */
    uint64_t left, entered;      /* viewport: inside -> outside, outside -> inside */
    uint64_t decided;            /* renderers 7, 9, the clips: segments cut, kept
                                 ** or dropped otherwise than by the reference */
} pt_acc_err;

/* The rows of the error table: the seven stages, then the rasterizer. */
typedef enum pt_acc_row {
    PT_ACC_MODEL, PT_ACC_CAMERA, PT_ACC_IMAGE, PT_ACC_PIXEL, PT_ACC_VIEWPORT,
    PT_ACC_FRAMEBUFFER, PT_ACC_INDEX, PT_ACC_RASTER, PT_ACC_NROWS
} pt_acc_row;

/* The matrix camera's rows: its ten stages, then the rasterizer. */
typedef enum pt_acc_mrow {
    PT_ACC_M_MODEL, PT_ACC_M_WORLD, PT_ACC_M_VIEW, PT_ACC_M_CLIP, PT_ACC_M_CVV,
    PT_ACC_M_NDC, PT_ACC_M_SCREEN, PT_ACC_M_VIEWPORT, PT_ACC_M_FRAMEBUFFER,
    PT_ACC_M_INDEX, PT_ACC_M_RASTER, PT_ACC_M_NROWS
} pt_acc_mrow;

/* Renderer 9's rows: its stages, the two clips among them, then the
** rasterizer; renderer 7's are the same without world. */
typedef enum pt_acc_rvrow {
    PT_ACC_R_MODEL, PT_ACC_R_WORLD, PT_ACC_R_VIEW, PT_ACC_R_CAMERA, PT_ACC_R_NEARCLIP,
    PT_ACC_R_IMAGE, PT_ACC_R_CLIP, PT_ACC_R_PIXEL, PT_ACC_R_VIEWPORT, PT_ACC_R_FRAMEBUFFER,
    PT_ACC_R_INDEX, PT_ACC_R_RASTER, PT_ACC_R_NROWS
} pt_acc_rvrow;

#define PT_ACC_MAXROWS PT_ACC_R_NROWS    /* room for any pipeline's rows */


/* ===== the rows as data: one table per pipeline =====
**
** What accuracy needs of each stage of a pipeline, and of its rasterizer, is
** a row of that pipeline's table (pt_acc_rows_of[], indexed by pt_pipe_id),
** in the order of its error table: nothing else here or in cmd_accuracy.c
** asks which pipeline a scene has.  A new pipeline adds its table beside
** the others (accuracy.c), with its arithmetics' functions (acc_float.c,
** acc_dd.c, acc_double.c); tests/unit/test_accuracy.c checks that every
** pipeline has a table whose rows cover its order. */

/* The panels of the plot, one per unit of error. */
typedef enum pt_acc_panel {
    PT_ACC_PANEL_COORD,          /* coordinates */
    PT_ACC_PANEL_PIXEL,          /* pixels */
    PT_ACC_PANEL_INDEX,          /* array places */
    PT_ACC_PANEL_RASTER          /* the DDA's y, per pixel */
} pt_acc_panel;

#define PT_ACC_NPANELS ((int)PT_ACC_PANEL_RASTER + 1)

/* Which table of an arithmetic's functions computes a row (acc_shared.h). */
typedef enum pt_acc_fn {
    PT_ACC_FN_STAGE,             /* pt_acc_stage_of: a pt_acc_journey's stage */
    PT_ACC_FN_MSTAGE,            /* pt_acc_mstage_of: a pt_acc_mjourney's, up to the cvv */
    PT_ACC_FN_TAIL,              /* pt_acc_tail_of: a pt_acc_mtail's, from clip
                                 ** coordinates on (vertices and made points) */
    PT_ACC_FN_RASTER,            /* the rasterizer's pass */
    PT_ACC_FN_RV,                /* renderers 7, 9: pt_acc_ops.rvstage[sub], a vertex's */
    PT_ACC_FN_RVNEAR,            /* ... the near clip, a segment's */
    PT_ACC_FN_RVCLIP,            /* ... the clip to -1..1, a segment's */
    PT_ACC_FN_RVEND              /* ... pt_acc_ops.stage[sub] (pixel .. index) on the
                                 ** ends of the segments drawn */
} pt_acc_fn;

/* One row of the error table. */
typedef struct pt_acc_rowinfo {
    int stage;                   /* its pt_stage, or -1: the rasterizer */
    const char *name;            /* "model", ..., "raster" */
    int real;                    /* 1: real values (max_ulp means something);
                                 ** 0: integers, or outcodes */
    pt_acc_fn fn;                /* the functions that compute it */
    unsigned variants;           /* the choices (PT_ACC_TWO, PT_ACC_RECOMPUTE)
                                 ** that change it: their runs time it and plot it */
    int panel;                   /* its pt_acc_panel, or -1: no error to plot */
    int sub;                     /* renderers 7, 9: the function's place in its table */
    const char *of;              /* what differ counts; NULL: "vertices" (raster: pixels) */
} pt_acc_rowinfo;

/* A pipeline's rows. */
typedef struct pt_acc_rows {
    const pt_acc_rowinfo *row;   /* its stages in pipeline order, then the */
    int nrows;                   /*   rasterizer, the last; and how many */
    int mcam;                    /* 1: each arithmetic builds the pipeline's
                                 ** matrices and clips its segments (pt_acc_mcam,
                                 ** pt_acc_mjourney, pt_acc_mseg); 0: journeys are
                                 ** pt_acc_journey */
    const char *panel_sub[PT_ACC_NPANELS];  /* after a panel's title: ": model .. ndc" */
    const char *no_plot;         /* the plot's note on rows with no panel, or "" */
    const char *no_two;          /* what is said when no row has PT_ACC_TWO */
    int rv;                      /* 7 or 9: the course's renderer (pt_acc_rvjourney,
                                 ** pt_acc_rvseg); 0: neither */
} pt_acc_rows;

extern const pt_acc_rows pt_acc_rows_of[PT_NPIPES];

/* The rows of the course's renderers 7 and 9, whose scenes are classic by
** pipeline (pt_scene_pipeline) but run their own stages. */
extern const pt_acc_rows pt_acc_rows_r7, pt_acc_rows_r9;

/* The rows of scene s's pipeline.  This function can't fail. */
const pt_acc_rows *pt_acc_scene_rows(const pt_scene *s);

/* The row of stage st in rows (-1: the rasterizer's), or -1 when it has none.
** This function can't fail. */
int pt_acc_row_of(const pt_acc_rows *rows, int st);

/* The first row that choices change, or -1 when none.  This function can't fail. */
int pt_acc_row_varied(const pt_acc_rows *rows, unsigned choices);

/* The last real row before the rasterizer (classic: pixel; matrix: screen).
** This function can't fail. */
int pt_acc_last_real(const pt_acc_rows *rows);

/* A scene run through the pipeline in one arithmetic.  Invariant: j[k][v]
** (matrix camera: mj[k][v]) is set for every used vertex v of model k;
** matrix camera: seg[k][q] for every segment; img is sorted by idx, one entry
** per pixel written. */
typedef struct pt_acc_run {
    const pt_scene *s;           /* not owned; must outlive the run */
    pt_arith arith;
    unsigned choices;            /* PT_ACC_* */
    unsigned char **used;        /* used[k][v]: a segment uses it; owned */
    pt_acc_journey **j;          /* j[k][v]; owned; NULL for the matrix camera */
    pt_acc_mcam *cam;            /* matrix camera: its matrices; owned, else NULL */
    pt_acc_mjourney **mj;        /* matrix camera: mj[k][v]; owned, else NULL */
    pt_acc_mseg **seg;           /* matrix camera: seg[k][q]; owned, else NULL */
    pt_acc_rvcam *rv;            /* renderers 7, 9: camera and matrices; owned, else NULL */
    pt_acc_rvjourney **rj;       /* renderers 7, 9: rj[k][v]; owned, else NULL */
    pt_acc_rvseg **rseg;         /* renderers 7, 9: rseg[k][q]; owned, else NULL */
    uint64_t made, culled;       /* matrix camera, renderers 7, 9: points clipping
                                 ** made, segments culled (dropped) */
    uint64_t nused;              /* used vertices in all models */
    pt_acc_pixel *img;           /* the final image's lit pixels; owned */
    size_t nimg;
    uint64_t pixels;             /* pixels written, overdraw included */
    pt_acc_err line;             /* the DDA's y against the exact line */
} pt_acc_run;

/* Run scene s in arithmetic a with choices: every used vertex's journey, then
** (matrix camera: each segment clipped) the rasterizer into the image, which
** keeps each pixel written once, with the last colour written there (64
** bytes a pixel at most; overdraw costs nothing).  The matrix camera ignores
** PT_ACC_TWO.  Returns 0, or -1 when out of memory, -2 when the image has
** more than maxpix pixels (then *r is empty).  pt_acc_run_make() takes
** PT_ACC_MAXPIX; a smaller maxpix lets a test reach the cap cheaply. */
#define PT_ACC_MAXPIX 8000000
int pt_acc_run_make(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices);
int pt_acc_run_make_max(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices,
                        size_t maxpix);

/* Free what *r owns.  This function can't fail. */
void pt_acc_run_free(pt_acc_run *r);

/* Compare run r with the reference ref (same scene): e[row] for each row of
** the scene's camera (PT_ACC_NROWS, or PT_ACC_M_NROWS when the pipeline has matrices).  This
** function can't fail. */
void pt_acc_compare(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_MAXROWS]);

/* The same in three steps, for a run made a part at a time (pt_acc_block):
** pt_acc_compare_start() empties e, pt_acc_compare_part() adds the parts
** (PT_ACC_VERTICES, PT_ACC_SEGMENTS) of runs ref and r of one scene (a
** block), model by model in order, each model's vertices before its
** segments, pt_acc_compare_end() sets the rasterizer's row from the whole
** runs' images.  Sums add in the order pt_acc_compare() adds them when the
** blocks come in pt_acc_block_next()'s order.  These functions can't fail. */
#define PT_ACC_VERTICES 1u
#define PT_ACC_SEGMENTS 2u
void pt_acc_compare_start(const pt_scene *s, pt_acc_err e[PT_ACC_MAXROWS]);
void pt_acc_compare_part(const pt_acc_run *ref, const pt_acc_run *r, unsigned parts,
                         pt_acc_err e[PT_ACC_MAXROWS]);
void pt_acc_compare_end(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_MAXROWS]);

/* ===== a scene in blocks: memory bounded by a block, not by the scene =====
**
** pt_acc_block_next() hands over a scene a block at a time, as a scene of
** its own with one model (a copy of the model's, sharing all but its
** vertices and segments): for each model in order, its used vertices
** PT_ACC_BLOCK at a time, in order, with no segments; then its segments
** PT_ACC_BLOCK at a time, in order, with the vertices they use, each once
** (a block's segments being mostly near each other in a model, their ends
** are mostly shared: a vertex is computed again about once for its
** segments, not once for each).  pt_acc_run_block() runs a block like
** pt_acc_run_make(), every vertex used, and draws a block of segments into
** its run's place i of an image (pt_acc_image): the images of up to
** PT_ACC_MAXIMG runs, kept across blocks in one table, each pixel lit by any
** run once, with each run's last colour there (32 bytes a pixel, at most 64
** with the hash table's room), and each run's DDA error.  So every run of a
** scene goes through a block beside the others, the reference's journeys
** computed once for them all.  pt_acc_draw_again() draws a block run again
** with other choices (PT_ACC_RECOMPUTE: the journeys are the same) into
** another place.  What stays the size of the scene: the used flags, a byte
** a vertex (pt_acc_used_make()).
**   used = pt_acc_used_make(&s);  pt_acc_block_init(&b, &s, used);
**   img = pt_acc_image_make(&s, maxpix, 2);
**   while (pt_acc_block_next(&b)) {
**       pt_acc_run_block(&ref, &b, PT_ARITH_DD, 0, img, 0);
**       pt_acc_run_block(&r, &b, PT_ARITH_FLOAT, 0, img, 1);
**       pt_acc_compare_part(&ref, &r, ...); pt_acc_run_free(&r); pt_acc_run_free(&ref); }
**   pt_acc_image_end(img, 0, 1, &e[raster]);  pt_acc_image_free(img);
**   pt_acc_block_free(&b);  pt_acc_used_free(&s, used); */
#define PT_ACC_BLOCK 4096
#define PT_ACC_MAXIMG 6
#define PT_ACC_ENDSLOTS (4 * PT_ACC_BLOCK)     /* twice a block's ends at most */

typedef struct pt_acc_block {
    pt_scene s;                  /* the block as a scene: models = &m, nmodels 1 */
    pt_model m;                  /* model k's, with the block's v[] and seg[] */
    unsigned segs;               /* 0: a block of vertices; 1: of segments */
    size_t k, pos;               /* the model, and where the next block starts
                                 ** in it (a vertex, or a segment) */
    pt_vec3 *v;                  /* room for 2 * PT_ACC_BLOCK vertices; owned */
    pt_segment *seg;             /* room for PT_ACC_BLOCK segments; owned */
    uint32_t *key, *at;          /* a segment block's ends: slot s holds model
                                 ** vertex key[s] - 1 (0: empty) at v[at[s]];
                                 ** PT_ACC_ENDSLOTS slots; owned */
    const pt_scene *whole;       /* the scene; not owned */
    unsigned char *const *used;  /* its used flags; not owned */
    uint64_t nused, nseg;        /* the scene's used vertices, and segments of
                                 ** models with any */
} pt_acc_block;

/* used[k][v] of scene s: 1 when a drawn segment uses vertex v of model k.
** Returns NULL when out of memory; pt_acc_used_free() frees (NULL is fine). */
unsigned char **pt_acc_used_make(const pt_scene *s);
void pt_acc_used_free(const pt_scene *s, unsigned char **used);

/* Start *b on scene s with its used flags (both must outlive b).  Returns 0,
** or -1 when out of memory.  pt_acc_block_free() frees what b owns. */
int pt_acc_block_init(pt_acc_block *b, const pt_scene *s, unsigned char *const *used);
void pt_acc_block_free(pt_acc_block *b);

/* The next block into b->s: returns 1, or 0 when there is none.  This
** function can't fail. */
int pt_acc_block_next(pt_acc_block *b);

/* The images of nrun (1 .. PT_ACC_MAXIMG) runs made together, each with at
** most maxpix pixels (all together at most 2 * maxpix).  make returns NULL
** when out of memory. */
typedef struct pt_acc_image pt_acc_image;
pt_acc_image *pt_acc_image_make(const pt_scene *s, size_t maxpix, int nrun);
void pt_acc_image_free(pt_acc_image *img);              /* NULL is fine */

/* Move run i's pixels of img (sorted), writes and the DDA's error into r's
** img, nimg, pixels and line.  Returns 0, or -1 when out of memory. */
int pt_acc_image_take(pt_acc_image *img, int i, pt_acc_run *r);

/* Run i's pixel count, writes and DDA error into r's nimg, pixels and line
** (r->img untouched).  This function can't fail. */
void pt_acc_image_count(const pt_acc_image *img, int i, pt_acc_run *r);

/* The rasterizer's row of run i against the reference's, run iref of the
** same image: what pt_acc_compare_end() sets from two whole runs' images.
** This function can't fail. */
void pt_acc_image_end(const pt_acc_image *img, int iref, int i, pt_acc_err *e);

/* Run block b (every vertex of it used) in arithmetic a with choices; a
** block of segments is drawn into place i of img (NULL: clipped only).
** Returns as pt_acc_run_make_max() does; -2: run i lit more than img's
** pixels. */
int pt_acc_run_block(pt_acc_run *r, const pt_acc_block *b, pt_arith a, unsigned choices,
                     pt_acc_image *img, int i);

/* Draw block run r's segments again, with choices in place of r's (only the
** rasterizer's may differ: PT_ACC_RECOMPUTE), into place i of img; r is not
** changed.  Returns 0, -1 when out of memory, -2 past img's pixels. */
int pt_acc_draw_again(const pt_acc_run *r, unsigned choices, pt_acc_image *img, int i);

/* pt_acc_vertex_pass() computes every used vertex's journey again (into r->j
** or r->mj, the same values); pt_acc_raster_pass() rasterizes every segment
** again (matrix camera: clips it first, and runs the points clipping makes
** through ndc .. index), counting the pixels written in *pixels but keeping
** none.  Each returns a checksum of what it computed, for the caller to keep
** the optimizer from skipping the work.  These functions can't fail. */
double pt_acc_vertex_pass(pt_acc_run *r);
double pt_acc_raster_pass(const pt_acc_run *r, uint64_t *pixels);

/* ===== one stage at a time: the timed work =====
**
** A work holds the inputs of one stage of run r, prepared from r's journeys:
** a copy of every used vertex's journey (matrix camera, rows ndc .. index:
** the tails of the vertices inside the view volume in r), with each model's
** context.  pt_acc_stage_pass(w, row) runs that stage -- the very function of
** the table the error runs' journeys call (pt_acc_stage_of and the others) --
** once on every input, which reads the earlier stages' values from its copy
** and writes its own; running it again rewrites the same values. */
typedef struct pt_acc_work pt_acc_work;

/* The inputs of row (a stage row, not the rasterizer) of run r; r must
** outlive the work.  Returns NULL when out of memory. */
pt_acc_work *pt_acc_work_make(const pt_acc_run *r, int row);
void pt_acc_work_free(pt_acc_work *w);          /* NULL is fine */

/* The number of inputs: the vertices each pass computes. */
size_t pt_acc_work_size(const pt_acc_work *w);

/* Run stage row on every input, a row of the kind w was made for (classic; the
** matrix camera's model .. cvv; its ndc .. index).  Returns a checksum.
** This function can't fail. */
double pt_acc_stage_pass(pt_acc_work *w, int row);

/* For tests: overwrite every value the stages of w's kind write (all but the
** clip coordinates a tail starts from, and the image-plane point the ends of
** renderers 7 and 9 start from) with garbage; and input i as it is now
** (NULL when w holds another kind). */
void pt_acc_work_poison(pt_acc_work *w);
const pt_acc_journey *pt_acc_work_journey(const pt_acc_work *w, size_t i);
const pt_acc_mjourney *pt_acc_work_mjourney(const pt_acc_work *w, size_t i);
const pt_acc_mtail *pt_acc_work_mtail(const pt_acc_work *w, size_t i);
const pt_acc_rvjourney *pt_acc_work_rvjourney(const pt_acc_work *w, size_t i);
const pt_acc_rvseg *pt_acc_work_rvseg(const pt_acc_work *w, size_t i);

/* The context of model m's stages in scene s.  This function can't fail. */
void pt_acc_sctx_make(pt_acc_sctx *c, const pt_scene *s, const pt_model *m, unsigned choices);

/* Arithmetic a's function for a stage row: classic (rows model .. index),
** the matrix camera's up to the cvv (model .. cvv), and from ndc on (rows ndc
** .. index of pt_acc_mrow).  These functions can't fail. */
pt_acc_stage_fn pt_acc_stage_of(pt_arith a, int row);
pt_acc_mstage_fn pt_acc_mstage_of(pt_arith a, int row);
pt_acc_tail_fn pt_acc_tail_of(pt_arith a, int row);

/* The DDA of src/core/raster.h in arithmetic a (float and double: y += m, or with
** PT_ACC_RECOMPUTE y = y0 + m*(x - x0); the reference: the exact line), for
** steps inside the viewport's band only.  pixel() gets each pixel inside the
** w x h viewport in step order.  Returns 0, or -1 when an endpoint has no
** integer pixel (nothing drawn).  Requires w, h >= 1.  This function can't fail. */
int pt_acc_raster_segment(pt_arith a, unsigned choices, pt_dd x0, pt_dd y0,
                          pt_dd x1, pt_dd y1, int w, int h,
                          void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp),
                          void *ud);

/* One vertex's journey in arithmetic a with choices (classic camera).  This
** function can't fail. */
void pt_acc_journey_of(pt_arith a, unsigned choices, const pt_scene *s,
                       const pt_model *m, pt_vec3 v_m, pt_acc_journey *j);

/* ===== the matrix camera ===== */

/* View, Projection and each model's World of scene s (its pipeline has matrices) in arithmetic
** a, as described at the top.  Returns NULL when out of memory.  s must outlive
** the result, which pt_acc_mcam_free() frees (NULL is fine). */
pt_acc_mcam *pt_acc_mcam_make(const pt_scene *s, pt_arith a);
void pt_acc_mcam_free(pt_acc_mcam *c);

/* The matrices as c holds them, widened to pt_dd: model k's World, View and
** Projection (any may be NULL).  This function can't fail. */
void pt_acc_mcam_matrices(const pt_acc_mcam *c, size_t k, pt_dd_mat4 *world,
                          pt_dd_mat4 *view, pt_dd_mat4 *proj);

/* The journey of v_m of model k in c's arithmetic: model .. cvv, and on to
** index when inside the view volume.  This function can't fail. */
void pt_acc_mjourney_of(const pt_acc_mcam *c, size_t k, pt_vec3 v_m, pt_acc_mjourney *j);

/* The segment from the vertex of journey a to that of b, clipped in clip space
** in c's arithmetic (src/core/pipeline.c's matrix_segment): culled, or visible with
** new ends where an end was outside.  This function can't fail. */
void pt_acc_mseg_of(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                    const pt_acc_mjourney *b, pt_acc_mseg *g);

#endif
