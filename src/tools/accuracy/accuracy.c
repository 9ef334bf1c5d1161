/*
** src/tools/accuracy/accuracy.c -- the pipeline in float, double and double-double, and its errors
** See LICENSE for copyright and license.
**
** The driver: each arithmetic's stages and DDA are in a file of their own
** (acc_float.c, acc_double.c, acc_dd.c), one function per stage in a table;
** here they are chosen by arithmetic, strung together into journeys, run over
** a scene (every used vertex, every segment, into an image), compared with
** the reference row by row, and run one stage at a time for the timing
** (pt_acc_work: the same functions on inputs copied from the journeys).
*/
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/accuracy.h"
#include "tools/accuracy/acc_float.h"
#include "tools/accuracy/acc_double.h"
#include "tools/accuracy/acc_dd.h"

/* Each arithmetic's stages and DDA, by pt_arith. */
static const pt_acc_ops *const ops[PT_NARITH] = {
    &pt_acc_float_ops, &pt_acc_double_ops, &pt_acc_dd_ops
};

const char *const pt_arith_names[PT_NARITH] = { "float", "double", "double-double" };
const int pt_arith_bits[PT_NARITH] = { 24, 53, PT_DD_BITS };

/* ===== the rows as data ===== */

#define TWO  PT_ACC_TWO
#define RE   PT_ACC_RECOMPUTE

static const pt_acc_rowinfo classic_rows[PT_ACC_NROWS] = {
    [PT_ACC_MODEL]       = { PT_STAGE_MODEL,       "model",       1, PT_ACC_FN_STAGE,  0,   PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_CAMERA]      = { PT_STAGE_CAMERA,      "camera",      1, PT_ACC_FN_STAGE,  0,   PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_IMAGE]       = { PT_STAGE_IMAGE,       "image",       1, PT_ACC_FN_STAGE,  0,   PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_PIXEL]       = { PT_STAGE_PIXEL,       "pixel",       1, PT_ACC_FN_STAGE,  TWO, PT_ACC_PANEL_PIXEL, 0, NULL },
    [PT_ACC_VIEWPORT]    = { PT_STAGE_VIEWPORT,    "viewport",    0, PT_ACC_FN_STAGE,  TWO, PT_ACC_PANEL_PIXEL, 0, NULL },
    [PT_ACC_FRAMEBUFFER] = { PT_STAGE_FRAMEBUFFER, "framebuffer", 0, PT_ACC_FN_STAGE,  0,   PT_ACC_PANEL_PIXEL, 0, NULL },
    [PT_ACC_INDEX]       = { PT_STAGE_INDEX,       "index",       0, PT_ACC_FN_STAGE,  0,   PT_ACC_PANEL_INDEX, 0, NULL },
    [PT_ACC_RASTER]      = { -1,                   "raster",      1, PT_ACC_FN_RASTER, RE,  PT_ACC_PANEL_RASTER, 0, NULL }
};

/* The cvv's row counts outcodes unlike the reference's: no error, no panel.
** Rows ndc .. index take the vertices inside the view volume and the points
** clipping makes (pt_acc_mtail). */
static const pt_acc_rowinfo matrix_rows[PT_ACC_M_NROWS] = {
    [PT_ACC_M_MODEL]       = { PT_STAGE_MODEL,       "model",       1, PT_ACC_FN_MSTAGE, 0,  PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_M_WORLD]       = { PT_STAGE_WORLD,       "world",       1, PT_ACC_FN_MSTAGE, 0,  PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_M_VIEW]        = { PT_STAGE_VIEW,        "view",        1, PT_ACC_FN_MSTAGE, 0,  PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_M_CLIP]        = { PT_STAGE_CLIP,        "clip",        1, PT_ACC_FN_MSTAGE, 0,  PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_M_CVV]         = { PT_STAGE_CVV,         "cvv",         0, PT_ACC_FN_MSTAGE, 0,  -1, 0, NULL },
    [PT_ACC_M_NDC]         = { PT_STAGE_NDC,         "ndc",         1, PT_ACC_FN_TAIL,   0,  PT_ACC_PANEL_COORD, 0, NULL },
    [PT_ACC_M_SCREEN]      = { PT_STAGE_SCREEN,      "screen",      1, PT_ACC_FN_TAIL,   0,  PT_ACC_PANEL_PIXEL, 0, NULL },
    [PT_ACC_M_VIEWPORT]    = { PT_STAGE_VIEWPORT,    "viewport",    0, PT_ACC_FN_TAIL,   0,  PT_ACC_PANEL_PIXEL, 0, NULL },
    [PT_ACC_M_FRAMEBUFFER] = { PT_STAGE_FRAMEBUFFER, "framebuffer", 0, PT_ACC_FN_TAIL,   0,  PT_ACC_PANEL_PIXEL, 0, NULL },
    [PT_ACC_M_INDEX]       = { PT_STAGE_INDEX,       "index",       0, PT_ACC_FN_TAIL,   0,  PT_ACC_PANEL_INDEX, 0, NULL },
    [PT_ACC_M_RASTER]      = { -1,                   "raster",      1, PT_ACC_FN_RASTER, RE, PT_ACC_PANEL_RASTER, 0, NULL }
};

/* Renderers 7 and 9: nearclip and clip count segments (their t and new
** points); image takes the vertices and the points the near clip made;
** pixel .. index take the ends of the segments drawn, in either run. */
#define RV   PT_ACC_FN_RV
#define END  PT_ACC_FN_RVEND
#define COORD PT_ACC_PANEL_COORD
#define PIX  PT_ACC_PANEL_PIXEL

#define R_MODEL   { PT_STAGE_MODEL,  "model",    1, RV, 0, COORD, 0, NULL }
#define R_VIEW    { PT_STAGE_VIEW,   "view",     1, RV, 0, COORD, 2, NULL }
#define R_CAMERA  { PT_STAGE_CAMERA, "camera",   1, RV, 0, COORD, 3, NULL }
#define R_NEAR    { -2,              "nearclip", 1, PT_ACC_FN_RVNEAR, 0, COORD, 0, "segments" }
#define R_IMAGE   { PT_STAGE_IMAGE,  "image",    1, RV, 0, COORD, 4, "points" }
#define R_CLIP    { -2,              "clip",     1, PT_ACC_FN_RVCLIP, 0, COORD, 0, "segments" }
#define R_PIXEL   { PT_STAGE_PIXEL,  "pixel",    1, END, TWO, PIX, PT_ACC_PIXEL, "ends" }
#define R_VP      { PT_STAGE_VIEWPORT, "viewport", 0, END, TWO, PIX, PT_ACC_VIEWPORT, "ends" }
#define R_FB      { PT_STAGE_FRAMEBUFFER, "framebuffer", 0, END, 0, PIX, PT_ACC_FRAMEBUFFER, "ends" }
#define R_INDEX   { PT_STAGE_INDEX,  "index",    0, END, 0, PT_ACC_PANEL_INDEX, PT_ACC_INDEX, "ends" }
#define R_RASTER  { -1,              "raster",   1, PT_ACC_FN_RASTER, RE, PT_ACC_PANEL_RASTER, 0, NULL }

static const pt_acc_rowinfo r9_rows[PT_ACC_R_NROWS] = {
    R_MODEL, { PT_STAGE_WORLD, "world", 1, RV, 0, COORD, 1, NULL }, R_VIEW, R_CAMERA,
    R_NEAR, R_IMAGE, R_CLIP, R_PIXEL, R_VP, R_FB, R_INDEX, R_RASTER
};

static const pt_acc_rowinfo r7_rows[PT_ACC_R_NROWS - 1] = {     /* no world */
    R_MODEL, R_VIEW, R_CAMERA, R_NEAR, R_IMAGE, R_CLIP, R_PIXEL, R_VP, R_FB, R_INDEX, R_RASTER
};

#undef R_MODEL
#undef R_VIEW
#undef R_CAMERA
#undef R_NEAR
#undef R_IMAGE
#undef R_CLIP
#undef R_PIXEL
#undef R_VP
#undef R_FB
#undef R_INDEX
#undef R_RASTER
#undef RV
#undef END
#undef COORD
#undef PIX
#undef TWO
#undef RE

const pt_acc_rows pt_acc_rows_of[PT_NPIPES] = {
    [PT_PIPE_CLASSIC] = {
        classic_rows, PT_ACC_NROWS, 0,
        { ": model, camera, image", ": pixel plane, viewport, framebuffer", "", "" },
        "", NULL, 0
    },
    [PT_PIPE_MATRIX] = {
        matrix_rows, PT_ACC_M_NROWS, 1,
        { ": model .. ndc", ": screen, viewport, framebuffer", "", "" },
        "; cvv (outcodes) has no error to plot",
        "choice: 2.001 or 2.0 does not apply to the matrix camera: its screen stage,\n"
        "x_s = (x_n + 1) * w * 0.5, has no 2.001\n", 0
    }
};

const pt_acc_rows pt_acc_rows_r7 = {
    r7_rows, PT_ACC_R_NROWS - 1, 0,
    { ": model .. clip", ": pixel plane, viewport, framebuffer", "", "" }, "", NULL, 7
};

const pt_acc_rows pt_acc_rows_r9 = {
    r9_rows, PT_ACC_R_NROWS, 0,
    { ": model .. clip", ": pixel plane, viewport, framebuffer", "", "" }, "", NULL, 9
};

const pt_acc_rows *pt_acc_scene_rows(const pt_scene *s)
{
    if (s->renderer == 7) return &pt_acc_rows_r7;
    if (s->renderer == 9) return &pt_acc_rows_r9;
    return &pt_acc_rows_of[pt_scene_pipeline(s)->id];
}

int pt_acc_row_of(const pt_acc_rows *rows, int st)
{
    int row;

    for (row = 0; row < rows->nrows; row++)
        if (rows->row[row].stage == st) return row;
    return -1;
}

int pt_acc_row_varied(const pt_acc_rows *rows, unsigned choices)
{
    int row;

    for (row = 0; row < rows->nrows; row++)
        if (rows->row[row].variants & choices) return row;
    return -1;
}

int pt_acc_last_real(const pt_acc_rows *rows)
{
    int row, last = -1;

    for (row = 0; row + 1 < rows->nrows; row++)
        if (rows->row[row].real) last = row;
    return last;
}

/* ===== one arithmetic ===== */

/* The two tables of rows and the stage counts of acc_shared.h must agree. */
typedef char rows_agree[PT_ACC_RASTER == PT_ACC_NSTAGES
                       && PT_ACC_M_RASTER == PT_ACC_M_NFRONT + PT_ACC_M_NTAIL
                       && PT_ACC_M_NDC == PT_ACC_M_NFRONT ? 1 : -1];

void pt_acc_sctx_make(pt_acc_sctx *c, const pt_scene *s, const pt_model *m, unsigned choices)
{
    c->s = s;
    c->m = m;
    c->choices = choices;
    pt_stage_params_of(&c->par, s, m);
}

pt_acc_stage_fn pt_acc_stage_of(pt_arith a, int row)
{
    return ops[a]->stage[row];
}

pt_acc_mstage_fn pt_acc_mstage_of(pt_arith a, int row)
{
    return ops[a]->mstage[row];
}

pt_acc_tail_fn pt_acc_tail_of(pt_arith a, int row)
{
    return ops[a]->tail[row - PT_ACC_M_NDC];
}

/* The classic journey: the stages in order. */
static void journey(pt_arith a, const pt_acc_sctx *c, pt_vec3 v_m, pt_acc_journey *j)
{
    int row;

    for (row = 0; row < PT_ACC_NSTAGES; row++) ops[a]->stage[row](c, v_m, j);
}

void pt_acc_journey_of(pt_arith a, unsigned choices, const pt_scene *s,
                       const pt_model *m, pt_vec3 v_m, pt_acc_journey *j)
{
    pt_acc_sctx c;

    pt_acc_sctx_make(&c, s, m, a == PT_ARITH_DD ? 0 : choices);
    journey(a, &c, v_m, j);
}

/* From clip coordinates t->k on: ndc .. index in order. */
static void mtail(pt_arith a, const pt_scene *s, pt_acc_mtail *t)
{
    int i;

    for (i = 0; i < PT_ACC_M_NTAIL; i++) ops[a]->tail[i](s, t);
}

void pt_acc_mjourney_of(const pt_acc_mcam *c, size_t k, pt_vec3 v_m, pt_acc_mjourney *j)
{
    int row;

    for (row = 0; row < PT_ACC_M_NFRONT; row++) ops[c->arith]->mstage[row](c, k, v_m, j);
    if (j->code != 0) { pt_acc_no_tail(&j->t); return; }
    memcpy(j->t.k, j->k, sizeof j->t.k);            /* inside: on to the index */
    memcpy(j->t.kerr, j->kerr, sizeof j->t.kerr);
    mtail(c->arith, c->s, &j->t);
}

void pt_acc_mseg_of(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                    const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    int e;

    memset(g, 0, sizeof *g);
    g->made[0] = a->code != 0;              /* an end outside gets a new point */
    g->made[1] = b->code != 0;
    if (!g->made[0] && !g->made[1]) { g->visible = 1; return; }    /* all inside */
    g->visible = ops[c->arith]->mseg(c, a, b, g);
    if (!g->visible) { g->made[0] = g->made[1] = 0; return; }
    for (e = 0; e < 2; e++)
        if (g->made[e]) mtail(c->arith, c->s, &g->end[e]);
}

int pt_acc_raster_segment(pt_arith a, unsigned choices, pt_dd x0, pt_dd y0,
                          pt_dd x1, pt_dd y1, int w, int h,
                          void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp),
                          void *ud)
{
    pt_acc_dda o;
    pt_dd p0[2], p1[2];

    o.pixel = pixel; o.step = NULL; o.ud = ud; o.w = w; o.h = h;
    o.to_vp = ptref_pixel2viewport;
    p0[0] = x0; p0[1] = y0; p1[0] = x1; p1[1] = y1;
    return ops[a]->raster(p0, p1, a == PT_ARITH_DD ? 0 : choices, &o);
}

/* Matrix camera: clip segment q of model k, then draw what is left between
** the pixel-plane points of its ends (the vertices' own, or the points
** clipping made).  The clipping goes to *g. */
static void raster_mseg(const pt_acc_run *r, size_t k, size_t q, const pt_acc_dda *o,
                        pt_acc_mseg *g)
{
    const pt_segment *sg = &r->s->models[k].seg[q];
    const pt_acc_mjourney *a = &r->mj[k][sg->a], *b = &r->mj[k][sg->b];

    pt_acc_mseg_of(r->cam, a, b, g);
    if (!g->visible || !o) return;                  /* culled, or not drawn */
    ops[r->arith]->raster(g->made[0] ? g->end[0].pp : a->t.pp,
                          g->made[1] ? g->end[1].pp : b->t.pp, r->choices, o);
}

/* ===== renderers 7 and 9 ===== */

/* 1 when model k is not drawn (`hidden-position`, `hidden-model`): its
** vertices are not used and its segments take part in no row. */
static int rv_hidden(const pt_scene *s, size_t k)
{
    return s->renderer != 4 && (s->models[k].hidden_position || s->models[k].hidden_model);
}

/* Segment q of model k through the near clip, the projection of the point it
** made, the clip to -1..1 and, when kept, the stages pixel .. index on its
** ends (context c), into *g. */
static void rv_segment(const pt_acc_run *r, size_t k, size_t q, const pt_acc_sctx *c,
                       pt_acc_rvseg *g)
{
    const pt_acc_ops *op = ops[r->arith];
    const pt_segment *sg = &r->s->models[k].seg[q];
    const pt_acc_rvjourney *a = &r->rj[k][sg->a], *b = &r->rj[k][sg->b];
    pt_dd e[2][2];
    int i, row;

    memset(g, 0, sizeof *g);
    memcpy(e[0], a->ip, sizeof e[0]);
    memcpy(e[1], b->ip, sizeof e[1]);
    g->near = r->s->nearclip ? op->rvnear(r->rv, a->c, b->c, &g->nc) : 1;
    if (g->near == 0) return;                       /* behind the near plane */
    if (g->near < 0) {                              /* the new point, projected */
        pt_acc_rvjourney t;

        memcpy(t.c, g->nc.p, sizeof t.c);
        op->rvstage[PT_ACC_RV_NFRONT - 1](r->rv, k, r->s->models[k].v[sg->a], &t);
        memcpy(g->nip, t.ip, sizeof g->nip);
        memcpy(e[g->nc.off], t.ip, sizeof e[0]);
        g->made[g->nc.off] = 1;
    }
    g->keep = op->rvclip(e, g);
    if (!g->keep) return;
    for (i = 0; i < 2; i++) {
        memcpy(g->end[i].ip, e[i], sizeof e[i]);
        for (row = PT_ACC_PIXEL; row < PT_ACC_NSTAGES; row++)
            op->stage[row](c, r->s->models[k].v[sg->a], &g->end[i]);
    }
}

/* Every segment of every model, in file order; *rgb (when not NULL) is set to
** each model's color before its segments.  Matrix camera, renderers 7 and 9:
** each segment's clipping goes to r->seg (r->rseg) when keep is set (else
** nowhere); o NULL: clipped only, nothing drawn. */
static void raster_scene(const pt_acc_run *r, const pt_acc_dda *o, uint32_t *rgb, int keep)
{
    size_t k, q;
    pt_acc_mseg g;

    pt_acc_rvseg rg;
    pt_acc_sctx c;

    for (k = 0; k < r->s->nmodels; k++) {
        const pt_model *m = &r->s->models[k];

        if (rgb) *rgb = (uint32_t)m->color[0] << 16 | (uint32_t)m->color[1] << 8 | m->color[2];
        if (r->rv) pt_acc_sctx_make(&c, r->s, m, r->choices);
        if (r->rv && rv_hidden(r->s, k)) continue;
        for (q = 0; q < m->nseg; q++)
            if (r->rv) {
                pt_acc_rvseg *gp = keep ? &r->rseg[k][q] : &rg;

                rv_segment(r, k, q, &c, gp);
                if (gp->keep && o) ops[r->arith]->raster(gp->end[0].pp, gp->end[1].pp, r->choices, o);
            } else if (r->cam) raster_mseg(r, k, q, o, keep ? &r->seg[k][q] : &g);
            else if (o) ops[r->arith]->raster(r->j[k][m->seg[q].a].pp,
                                       r->j[k][m->seg[q].b].pp, r->choices, o);
    }
}

/* ===== the matrix camera's matrices ===== */

pt_acc_mcam *pt_acc_mcam_make(const pt_scene *s, pt_arith a)
{
    pt_acc_mcam *c = calloc(1, sizeof *c);

    if (!c) return NULL;
    c->s = s;
    c->arith = a;
    if (ops[a]->mcam(c) == 0) return c;
    pt_acc_mcam_free(c);
    return NULL;
}

void pt_acc_mcam_free(pt_acc_mcam *c)
{
    if (!c) return;
    free(c->world_f);
    pt_plan_free(&c->plan);
    free(c->world_dd);
    free(c->world_e);
    free(c);
}

static void widen_mat_f(const pt_acc_mat4f *a, pt_dd_mat4 *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = pt_acc_dd((double)a->m[i][j]);
}

static void widen_mat_d(const pt_mat4 *a, pt_dd_mat4 *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = pt_acc_dd(a->m[i][j]);
}

void pt_acc_mcam_matrices(const pt_acc_mcam *c, size_t k, pt_dd_mat4 *world,
                          pt_dd_mat4 *view, pt_dd_mat4 *proj)
{
    pt_matrices mx;

    switch (c->arith) {
    case PT_ARITH_FLOAT:
        if (world) widen_mat_f(&c->world_f[k], world);
        if (view) widen_mat_f(&c->view_f, view);
        if (proj) widen_mat_f(&c->proj_f, proj);
        break;
    case PT_ARITH_DOUBLE:
        pt_matrices_of(&mx, &c->plan, k);
        if (world) widen_mat_d(mx.world, world);
        if (view) widen_mat_d(mx.view, view);
        if (proj) widen_mat_d(mx.proj, proj);
        break;
    case PT_ARITH_DD:
        if (world) *world = c->world_dd[k];
        if (view) *view = c->view_dd;
        if (proj) *proj = c->proj_dd;
        break;
    }
}

/* ===== errors ===== */

/* The spacing of doubles at a finite r: 2^(e - 52) for a normal r = 1.f *
** 2^e, the subnormal spacing 2^-1074 below.  2^e is r with its sign and
** fraction bits cleared, and 2^e * 2^-52 is exact (e >= -1022); ldexp(1.0,
** ilogb(r) - 52), the same value, took a tenth of a large scene's
** instructions (every value compared asks). */
static double ulp_of(double r)
{
    uint64_t bits;
    double e;

    r = fabs(r);
    if (r < DBL_MIN) return 0x1p-1074;
    memcpy(&bits, &r, sizeof bits);
    bits &= UINT64_C(0x7ff0000000000000);           /* 2^e */
    memcpy(&e, &bits, sizeof e);
    return e * 0x1p-52;
}

/* Count and return |v - ref|: 0 for the same non-finite value, infinite for
** another. */
static double err_add(pt_acc_err *e, double v, double ref)
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

/* Consecutive rows e[0 .. rows-1] of real coordinates: row i compares the
** n[i] values v[i] with the reference's ref[i]; a vertex differs when any
** value differs from the reference double. */
static void err_rows(pt_acc_err *e, const pt_dd *const v[], const pt_dd *const ref[],
                     const int n[], int rows)
{
    int i, k, differ;

    for (i = 0; i < rows; i++) {
        for (differ = 0, k = 0; k < n[i]; k++)
            if (err_add(&e[i], v[i][k].hi, ref[i][k].hi) != 0.0) differ = 1;
        e[i].differ += (uint64_t)differ;
    }
}

/* A pixel: no pixel on one side only counts as an infinite error. */
static int err_pix(pt_acc_err *e, pt_pix v, pt_pix ref)
{
    if (v.ok && ref.ok) {
        err_add(e, (double)v.x, (double)ref.x);
        err_add(e, (double)v.y, (double)ref.y);
        return v.x != ref.x || v.y != ref.y;
    }
    if (v.ok == ref.ok) {
        err_add(e, 0.0, 0.0);
        err_add(e, 0.0, 0.0);
        return 0;
    }
    err_add(e, (double)INFINITY, 0.0);
    err_add(e, (double)INFINITY, 0.0);
    return 1;
}

/* ===== runs ===== */

/* What the rasterizer leaves while runs are made: the images of up to
** PT_ACC_MAXIMG runs in one hash table by index (open addressing, at most
** half full), each pixel lit by any of them once, with each run's last colour
** written there (PT_ACC_UNLIT: that run lit it not); per run its pixels, the
** writes counted and the DDA's error against the exact line.  A run draws
** through its own pt_acc_imgrun, the DDA's callbacks' user data. */
#define PT_ACC_UNLIT 0xffffffffu         /* no colour: rgb has 24 bits */

typedef struct upixel {
    int64_t idx;                 /* y_fb * W + x_fb; -1: an empty slot (a pixel
                                 ** inside the viewport has idx >= 0) */
    uint32_t rgb[PT_ACC_MAXIMG]; /* each run's last colour, or PT_ACC_UNLIT */
} upixel;

typedef struct imgrun {
    struct pt_acc_image *img;    /* the image it draws into */
    int i;                       /* its place in upixel.rgb */
    uint32_t rgb;                /* the current model's color */
    size_t n;                    /* pixels it lit */
    uint64_t writes;             /* pixels written, overdraw included */
    pt_acc_err line;             /* the DDA's y against the exact line */
} imgrun;

struct pt_acc_image {
    const pt_scene *s;
    upixel *tab;                 /* cap slots */
    size_t n, cap;               /* pixels in tab (lit by any run); slots, a power of two */
    size_t max;                  /* the most pixels one run may light */
    int nrun;                    /* runs: run[0 .. nrun-1] */
    int oom;                     /* 1: out of memory; 2: past max pixels */
    imgrun run[PT_ACC_MAXIMG];
};

/* The slot of idx in a table of cap slots: where it is, or the empty slot
** where it goes. */
static size_t slot_of(const upixel *tab, size_t cap, int64_t idx)
{
    size_t i = (size_t)(((uint64_t)idx * UINT64_C(0x9e3779b97f4a7c15)) >> 32) & (cap - 1);

    while (tab[i].idx != idx && tab[i].idx != -1) i = (i + 1) & (cap - 1);
    return i;
}

/* Room for one more pixel in c->tab: twice the slots, every pixel moved.
** Returns 0, or -1 when out of memory. */
static int image_grow(pt_acc_image *c)
{
    size_t cap = c->cap ? 2 * c->cap : 1024, k;
    upixel *tab = malloc(cap * sizeof *tab);

    if (!tab) return -1;
    for (k = 0; k < cap; k++) tab[k].idx = -1;
    for (k = 0; k < c->cap; k++)
        if (c->tab[k].idx != -1) tab[slot_of(tab, cap, c->tab[k].idx)] = c->tab[k];
    free(c->tab);
    c->tab = tab;
    c->cap = cap;
    return 0;
}

static void collect_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    imgrun *ir = ud;
    pt_acc_image *c = ir->img;
    int64_t idx = (c->s->vp_y + y_vp) * (int64_t)c->s->fb_w + (c->s->vp_x + x_vp);
    size_t i = 0;
    int k;

    if (c->oom) return;
    ir->writes++;
    if (c->cap) {
        i = slot_of(c->tab, c->cap, idx);
        if (c->tab[i].idx == idx && c->tab[i].rgb[ir->i] != PT_ACC_UNLIT) {
            c->tab[i].rgb[ir->i] = ir->rgb;                 /* the last wins */
            return;
        }
    }
    if (ir->n == c->max) { c->oom = 2; return; }
    ir->n++;
    if (c->cap && c->tab[i].idx == idx) { c->tab[i].rgb[ir->i] = ir->rgb; return; }
    if (c->n == 2 * c->max) { c->oom = 2; return; }         /* all runs together */
    if (2 * (c->n + 1) > c->cap && image_grow(c) != 0) { c->oom = 1; return; }
    i = slot_of(c->tab, c->cap, idx);
    c->tab[i].idx = idx;
    for (k = 0; k < PT_ACC_MAXIMG; k++) c->tab[i].rgb[k] = PT_ACC_UNLIT;
    c->tab[i].rgb[ir->i] = ir->rgb;
    c->n++;
}

static void collect_step(void *ud, const pt_acc_line *ln, int64_t s, double y)
{
    imgrun *ir = ud;

    (void)err_add(&ir->line, y, pt_acc_line_y(ln, s).hi);
}

static int by_idx(const void *pa, const void *pb)
{
    const pt_acc_pixel *a = pa, *b = pb;

    return a->idx < b->idx ? -1 : a->idx > b->idx;
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
            if (r->rj) free(r->rj[k]);
            if (r->rseg) free(r->rseg[k]);
        }
    if (r->rv) free(r->rv->world);
    free(r->rv);
    free(r->rj);
    free(r->rseg);
    free(r->used);
    free(r->j);
    free(r->mj);
    free(r->seg);
    pt_acc_mcam_free(r->cam);
    free(r->img);
    memset(r, 0, sizeof *r);
}

/* Room for n things of size bytes (at least one), zeroed when zero is set:
** a block's run computes every journey and clips every segment, so it
** leaves them as malloc() gives them (zeroing them took a sixth of a large
** scene's instructions). */
static void *arr_alloc(size_t n, size_t size, int zero)
{
    return zero ? calloc(n ? n : 1, size) : malloc((n ? n : 1) * size);
}

/* The arrays of the journeys: j[k] (classic camera), or the matrix camera's
** mj[k], seg[k] and its matrices; zero: zeroed (a whole run's; a block's
** run, every vertex used, leaves them unset).  Returns 0, or -1 when out of
** memory. */
static int run_alloc(pt_acc_run *r, int zero)
{
    const pt_scene *s = r->s;
    size_t k, nm = s->nmodels ? s->nmodels : 1;

    r->used = calloc(nm, sizeof *r->used);
    if (!r->used) return -1;
    if (pt_acc_scene_rows(s)->rv) {
        r->rv = calloc(1, sizeof *r->rv);
        r->rj = calloc(nm, sizeof *r->rj);
        r->rseg = calloc(nm, sizeof *r->rseg);
        if (!r->rv || !r->rj || !r->rseg) return -1;
        r->rv->s = s;
        r->rv->arith = r->arith;
        if (ops[r->arith]->rvcam(r->rv) != 0) return -1;
        for (k = 0; k < s->nmodels; k++) {
            const pt_model *m = &s->models[k];

            r->rj[k] = arr_alloc(m->nv, sizeof **r->rj, zero);
            r->rseg[k] = arr_alloc(m->nseg, sizeof **r->rseg, zero);
            if (!r->rj[k] || !r->rseg[k]) return -1;
        }
        return 0;
    }
    if (!pt_acc_scene_rows(s)->mcam) {
        r->j = calloc(nm, sizeof *r->j);
        for (k = 0; r->j && k < s->nmodels; k++)
            if ((r->j[k] = arr_alloc(s->models[k].nv, sizeof **r->j, zero)) == NULL)
                return -1;
        return r->j ? 0 : -1;
    }
    r->cam = pt_acc_mcam_make(s, r->arith);
    r->mj = calloc(nm, sizeof *r->mj);
    r->seg = calloc(nm, sizeof *r->seg);
    if (!r->cam || !r->mj || !r->seg) return -1;
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        r->mj[k] = arr_alloc(m->nv, sizeof **r->mj, zero);
        r->seg[k] = arr_alloc(m->nseg, sizeof **r->seg, zero);
        if (!r->mj[k] || !r->seg[k]) return -1;
    }
    return 0;
}

/* The used flags of s: used[k][v] is 1 when a segment of model k uses vertex
** v (renderers 7, 9: none of a hidden model); all_used: every vertex of a
** model drawn.  Returns NULL when out of memory. */
static unsigned char **used_make(const pt_scene *s, int all_used)
{
    unsigned char **used = calloc(s->nmodels ? s->nmodels : 1, sizeof *used);
    size_t k, q;

    for (k = 0; used && k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        if ((used[k] = calloc(m->nv ? m->nv : 1, 1)) == NULL) {
            pt_acc_used_free(s, used);
            return NULL;
        }
        if (rv_hidden(s, k)) continue;
        if (all_used) memset(used[k], 1, m->nv);
        else
            for (q = 0; q < m->nseg; q++) used[k][m->seg[q].a] = used[k][m->seg[q].b] = 1;
    }
    return used;
}

unsigned char **pt_acc_used_make(const pt_scene *s)
{
    return used_make(s, 0);
}

void pt_acc_used_free(const pt_scene *s, unsigned char **used)
{
    size_t k;

    for (k = 0; used && k < s->nmodels; k++) free(used[k]);
    free(used);
}

/* The DDA's callbacks into run ir of an image, for arithmetic a. */
static void dda_of(pt_acc_dda *o, const pt_scene *s, pt_arith a, imgrun *ir)
{
    o->pixel = collect_pixel;
    o->step = a == PT_ARITH_DD ? NULL : collect_step;  /* the reference is the line */
    o->ud = ir;
    o->w = s->vp_w;
    o->h = s->vp_h;
    o->to_vp = pt_pipeline_ref(pt_scene_pipeline(s), PT_STAGE_VIEWPORT) ? ptref_pixel2viewport
                                                                  : pt_scene_pipeline(s)->to_viewport;
}

/* Run scene s in arithmetic a into *r: every used vertex's journey (all_used:
** every vertex's), then the segments clipped and, when ir is not NULL, drawn
** into its image (ir->rgb: the colour).  Returns 0, or -1 when out of memory,
** -2 when the image holds more than its pixels (then *r is empty). */
static int run_fill(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices,
                    int all_used, imgrun *ir)
{
    size_t k, q;
    pt_acc_dda o;

    memset(r, 0, sizeof *r);
    r->s = s;
    r->arith = a;
    r->choices = a == PT_ARITH_DD ? 0 : choices;
    r->line.real = 1;
    if (run_alloc(r, !all_used) != 0) { pt_acc_run_free(r); return -1; }
    free(r->used);
    if ((r->used = used_make(s, all_used)) == NULL) { pt_acc_run_free(r); return -1; }
    for (k = 0; k < s->nmodels; k++)
        for (q = 0; q < s->models[k].nv; q++) r->nused += r->used[k][q];
    pt_acc_vertex_pass(r);

    if (ir) dda_of(&o, s, a, ir);
    raster_scene(r, ir ? &o : NULL, ir ? &ir->rgb : NULL, 1);
    if (ir && ir->img->oom) { int oom = ir->img->oom; pt_acc_run_free(r); return oom == 2 ? -2 : -1; }
    for (k = 0; r->seg && k < s->nmodels; k++)
        for (q = 0; q < s->models[k].nseg; q++) {
            r->made += (uint64_t)(r->seg[k][q].made[0] + r->seg[k][q].made[1]);
            r->culled += !r->seg[k][q].visible;
        }
    for (k = 0; r->rseg && k < s->nmodels; k++)
        for (q = 0; q < s->models[k].nseg && !rv_hidden(s, k); q++) {
            const pt_acc_rvseg *g = &r->rseg[k][q];

            r->made += (uint64_t)(g->near < 0) + (uint64_t)g->ncuts;
            r->culled += !g->keep;
        }
    return 0;
}

pt_acc_image *pt_acc_image_make(const pt_scene *s, size_t maxpix, int nrun)
{
    pt_acc_image *c = calloc(1, sizeof *c);
    int k;

    if (!c) return NULL;
    c->s = s;
    c->max = maxpix;
    c->nrun = nrun < 1 ? 1 : nrun > PT_ACC_MAXIMG ? PT_ACC_MAXIMG : nrun;
    for (k = 0; k < PT_ACC_MAXIMG; k++) {
        c->run[k].img = c;
        c->run[k].i = k;
        c->run[k].line.real = 1;
    }
    return c;
}

void pt_acc_image_free(pt_acc_image *c)
{
    if (!c) return;
    free(c->tab);
    free(c);
}

int pt_acc_image_take(pt_acc_image *c, int i, pt_acc_run *r)
{
    size_t q, n;

    free(r->img);
    r->pixels = c->run[i].writes;
    r->line = c->run[i].line;
    r->img = malloc((c->run[i].n ? c->run[i].n : 1) * sizeof *r->img);
    if (!r->img) return -1;
    for (q = n = 0; q < c->cap; q++)
        if (c->tab[q].idx != -1 && c->tab[q].rgb[i] != PT_ACC_UNLIT) {
            r->img[n].idx = c->tab[q].idx;
            r->img[n++].rgb = c->tab[q].rgb[i];
        }
    if (n) qsort(r->img, n, sizeof *r->img, by_idx);
    r->nimg = n;
    return 0;
}

void pt_acc_image_count(const pt_acc_image *c, int i, pt_acc_run *r)
{
    r->nimg = c->run[i].n;
    r->pixels = c->run[i].writes;
    r->line = c->run[i].line;
}

void pt_acc_image_end(const pt_acc_image *c, int iref, int i, pt_acc_err *e)
{
    size_t q;

    *e = c->run[i].line;
    e->real = 1;
    e->differ = e->of = 0;
    for (q = 0; q < c->cap; q++) {
        uint32_t a, b;

        if (c->tab[q].idx == -1) continue;
        a = c->tab[q].rgb[i];
        b = c->tab[q].rgb[iref];
        if (a == PT_ACC_UNLIT && b == PT_ACC_UNLIT) continue;
        e->of++;
        e->differ += a != b;                /* lit on one side only, or another colour */
    }
}

int pt_acc_run_make(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices)
{
    return pt_acc_run_make_max(r, s, a, choices, PT_ACC_MAXPIX);
}

int pt_acc_run_make_max(pt_acc_run *r, const pt_scene *s, pt_arith a, unsigned choices,
                        size_t maxpix)
{
    pt_acc_image *c = pt_acc_image_make(s, maxpix, 1);
    int rc = c ? run_fill(r, s, a, choices, 0, &c->run[0]) : -1;

    if (rc == 0 && pt_acc_image_take(c, 0, r) != 0) {
        pt_acc_run_free(r);
        rc = -1;
    }
    pt_acc_image_free(c);
    return rc;
}

int pt_acc_run_block(pt_acc_run *r, const pt_acc_block *b, pt_arith a, unsigned choices,
                     pt_acc_image *img, int i)
{
    return run_fill(r, &b->s, a, choices, 1, b->segs && img ? &img->run[i] : NULL);
}

int pt_acc_draw_again(const pt_acc_run *r, unsigned choices, pt_acc_image *img, int i)
{
    pt_acc_run again = *r;                  /* the same journeys, other choices */
    pt_acc_dda o;

    again.choices = r->arith == PT_ARITH_DD ? 0 : choices;
    dda_of(&o, r->s, r->arith, &img->run[i]);
    raster_scene(&again, &o, &img->run[i].rgb, 0);
    return img->oom == 2 ? -2 : img->oom ? -1 : 0;
}

/* ===== a scene in blocks ===== */

int pt_acc_block_init(pt_acc_block *b, const pt_scene *s, unsigned char *const *used)
{
    size_t k, v;

    memset(b, 0, sizeof *b);
    b->whole = s;
    b->used = used;
    b->v = malloc(2 * PT_ACC_BLOCK * sizeof *b->v);
    b->seg = malloc(PT_ACC_BLOCK * sizeof *b->seg);
    b->key = malloc(PT_ACC_ENDSLOTS * sizeof *b->key);
    b->at = malloc(PT_ACC_ENDSLOTS * sizeof *b->at);
    if (!b->v || !b->seg || !b->key || !b->at) { pt_acc_block_free(b); return -1; }
    for (k = 0; k < s->nmodels; k++) {
        size_t n = 0;

        for (v = 0; v < s->models[k].nv; v++) n += used[k][v];
        b->nused += n;
        if (n) b->nseg += s->models[k].nseg;
    }
    return 0;
}

void pt_acc_block_free(pt_acc_block *b)
{
    free(b->v);
    free(b->seg);
    free(b->key);
    free(b->at);
    b->v = NULL;
    b->seg = NULL;
    b->key = b->at = NULL;
}

/* Vertex v of model m as an end of the segment block being made: its place
** in b->v, taken the first time (*nv: the places taken so far). */
static uint32_t block_end(pt_acc_block *b, const pt_model *m, uint32_t v, size_t *nv)
{
    size_t i = (size_t)(((uint64_t)v * UINT64_C(0x9e3779b97f4a7c15)) >> 32)
               & (PT_ACC_ENDSLOTS - 1);

    while (b->key[i] != 0 && b->key[i] != v + 1u) i = (i + 1) & (PT_ACC_ENDSLOTS - 1);
    if (b->key[i] == 0) {
        b->key[i] = v + 1u;
        b->at[i] = (uint32_t)*nv;
        b->v[(*nv)++] = m->v[v];
    }
    return b->at[i];
}

int pt_acc_block_next(pt_acc_block *b)
{
    const pt_scene *s = b->whole;

    for (; b->k < s->nmodels; b->k++, b->pos = 0, b->segs = 0) {
        const pt_model *m = &s->models[b->k];
        size_t n = 0, nv = 0, q;

        b->m = *m;
        b->s = *s;
        b->s.models = &b->m;
        b->s.nmodels = 1;
        b->m.v = b->v;
        if (!b->segs) {                             /* used vertices, in order */
            for (; b->pos < m->nv && n < PT_ACC_BLOCK; b->pos++)
                if (b->used[b->k][b->pos]) b->v[n++] = m->v[b->pos];
            if (n) {
                b->m.nv = n;
                b->m.seg = NULL;
                b->m.nseg = 0;
                return 1;
            }
            b->segs = 1;
            b->pos = 0;
            for (q = 0; q < m->nv && !b->used[b->k][q]; q++) {}
            if (q == m->nv) continue;               /* nothing drawn */
        }
        memset(b->key, 0, PT_ACC_ENDSLOTS * sizeof *b->key);
        for (; b->pos < m->nseg && n < PT_ACC_BLOCK; b->pos++, n++) {   /* each end once */
            b->seg[n] = m->seg[b->pos];
            b->seg[n].a = block_end(b, m, m->seg[b->pos].a, &nv);
            b->seg[n].b = block_end(b, m, m->seg[b->pos].b, &nv);
        }
        if (n) {
            b->m.nv = nv;
            b->m.seg = b->seg;
            b->m.nseg = n;
            return 1;
        }
    }
    return 0;
}

double pt_acc_vertex_pass(pt_acc_run *r)
{
    double sum = 0.0;
    size_t k, v;
    pt_acc_sctx c;

    for (k = 0; k < r->s->nmodels; k++) {
        const pt_model *m = &r->s->models[k];

        pt_acc_sctx_make(&c, r->s, m, r->choices);
        for (v = 0; v < m->nv; v++) {
            if (!r->used[k][v]) continue;
            if (r->rv) {
                pt_acc_rvjourney *j = &r->rj[k][v];
                int i;

                for (i = 0; i < PT_ACC_RV_NFRONT; i++) ops[r->arith]->rvstage[i](r->rv, k, m->v[v], j);
                sum += j->ip[0].hi;
            } else if (r->cam) {
                pt_acc_mjourney *j = &r->mj[k][v];

                pt_acc_mjourney_of(r->cam, k, m->v[v], j);
                sum += j->k[0].hi + (double)j->t.idx;
            } else {
                pt_acc_journey *j = &r->j[k][v];

                journey(r->arith, &c, m->v[v], j);
                sum += j->pp[0].hi + (double)j->idx;
            }
        }
    }
    return sum;
}

/* ===== one stage at a time: the timed work ===== */

struct pt_acc_work {
    pt_arith arith;
    const pt_acc_run *r;
    pt_acc_sctx *ctx;            /* ctx[k]: model k's */
    size_t n;                    /* inputs */
    size_t *model;               /* model[i]: input i's model */
    pt_vec3 *v;                  /* v[i]: its scene vertex */
    pt_acc_journey *j;           /* classic: copies of the run's journeys */
    pt_acc_mjourney *mj;         /* matrix, model .. cvv: likewise */
    pt_acc_mtail *t;             /* matrix, ndc .. index: the inside vertices' tails */
    pt_acc_fn fn;                /* the kind of row it was made for */
    pt_acc_rvjourney *rj;        /* renderers 7, 9, model .. image: copies */
    pt_acc_rvseg *rseg;          /* ... the clips: copies of the segments */
    size_t *seg;                 /* ... seg[i]: input i's segment in its model */
};

void pt_acc_work_free(pt_acc_work *w)
{
    if (!w) return;
    free(w->ctx);
    free(w->model);
    free(w->v);
    free(w->j);
    free(w->mj);
    free(w->t);
    free(w->rj);
    free(w->rseg);
    free(w->seg);
    free(w);
}

/* Renderers 7 and 9: the inputs of row (its kind fn) of run r into w, whose
** arrays hold n.  Segments' rows take every segment that reaches the stage
** (the clip: not dropped by the near clip; pixel .. index: both ends of
** each drawn). */
static void rv_work_fill(pt_acc_work *w, const pt_acc_run *r, size_t n)
{
    const pt_scene *s = r->s;
    size_t k, v, q, i = 0;
    int e;

    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        if (w->fn == PT_ACC_FN_RV) {
            for (v = 0; v < m->nv && i < n; v++) {
                if (!r->used[k][v]) continue;
                w->model[i] = k;
                w->v[i] = m->v[v];
                w->rj[i++] = r->rj[k][v];
            }
            continue;
        }
        for (q = 0; q < m->nseg && i < n && !rv_hidden(s, k); q++) {
            const pt_acc_rvseg *g = &r->rseg[k][q];

            if (w->fn == PT_ACC_FN_RVCLIP && g->near == 0) continue;
            if (w->fn == PT_ACC_FN_RVEND) {
                for (e = 0; g->keep && e < 2 && i < n; e++) {
                    w->model[i] = k;
                    w->v[i] = m->v[m->seg[q].a];
                    w->j[i++] = g->end[e];
                }
                continue;
            }
            w->model[i] = k;
            w->seg[i] = q;
            w->v[i] = m->v[m->seg[q].a];
            w->rseg[i++] = *g;
        }
    }
    w->n = i;
}

pt_acc_work *pt_acc_work_make(const pt_acc_run *r, int row)
{
    const pt_scene *s = r->s;
    pt_acc_work *w = calloc(1, sizeof *w);
    size_t k, v, n = r->nused ? (size_t)r->nused : 1, i = 0;
    pt_acc_fn fn = pt_acc_scene_rows(s)->row[row].fn;

    if (!w) return NULL;
    w->arith = r->arith;
    w->r = r;
    w->fn = fn;
    if (r->rv) {                                    /* renderers 7 and 9 */
        size_t nseg = 0;

        for (k = 0; k < s->nmodels; k++) nseg += s->models[k].nseg;
        if (fn == PT_ACC_FN_RVEND) n = nseg ? 2 * nseg : 1;     /* two ends a segment */
        else if (fn != PT_ACC_FN_RV) n = nseg ? nseg : 1;
        w->ctx = calloc(s->nmodels ? s->nmodels : 1, sizeof *w->ctx);
        w->model = calloc(n, sizeof *w->model);
        w->v = calloc(n, sizeof *w->v);
        w->seg = calloc(n, sizeof *w->seg);
        if (fn == PT_ACC_FN_RV) w->rj = calloc(n, sizeof *w->rj);
        else if (fn == PT_ACC_FN_RVEND) w->j = calloc(n, sizeof *w->j);
        else w->rseg = calloc(n, sizeof *w->rseg);
        if (!w->ctx || !w->model || !w->v || !w->seg || !(w->rj || w->j || w->rseg)) {
            pt_acc_work_free(w);
            return NULL;
        }
        for (k = 0; k < s->nmodels; k++) pt_acc_sctx_make(&w->ctx[k], s, &s->models[k], r->choices);
        rv_work_fill(w, r, n);
        return w;
    }
    w->ctx = calloc(s->nmodels ? s->nmodels : 1, sizeof *w->ctx);
    w->model = calloc(n, sizeof *w->model);
    w->v = calloc(n, sizeof *w->v);
    if (fn == PT_ACC_FN_TAIL) w->t = calloc(n, sizeof *w->t);
    else if (fn == PT_ACC_FN_MSTAGE) w->mj = calloc(n, sizeof *w->mj);
    else w->j = calloc(n, sizeof *w->j);
    if (!w->ctx || !w->model || !w->v || !(w->t || w->mj || w->j)) {
        pt_acc_work_free(w);
        return NULL;
    }
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        pt_acc_sctx_make(&w->ctx[k], s, m, r->choices);
        for (v = 0; v < m->nv; v++) {
            if (!r->used[k][v]) continue;
            if (fn == PT_ACC_FN_TAIL && r->mj[k][v].code != 0) continue;    /* stops at the cvv */
            w->model[i] = k;
            w->v[i] = m->v[v];
            if (fn == PT_ACC_FN_TAIL) w->t[i] = r->mj[k][v].t;
            else if (fn == PT_ACC_FN_MSTAGE) w->mj[i] = r->mj[k][v];
            else w->j[i] = r->j[k][v];
            i++;
        }
    }
    w->n = i;
    return w;
}

size_t pt_acc_work_size(const pt_acc_work *w)
{
    return w->n;
}

void pt_acc_work_poison(pt_acc_work *w)
{
    size_t i;

    for (i = 0; i < w->n; i++)
        if (w->rj) memset(&w->rj[i], 0xab, sizeof w->rj[i]);
        else if (w->rseg) memset(&w->rseg[i], 0xab, sizeof w->rseg[i]);
        else if (w->t) {                                 /* all but the clip coordinates */
            pt_acc_mtail keep = w->t[i];

            memset(&w->t[i], 0xab, sizeof w->t[i]);
            memcpy(w->t[i].k, keep.k, sizeof keep.k);
            memcpy(w->t[i].kerr, keep.kerr, sizeof keep.kerr);
        } else if (w->mj) memset(&w->mj[i], 0xab, sizeof w->mj[i]);
        else {
            pt_dd ip[2];                            /* renderers 7, 9: the ends' input */

            memcpy(ip, w->j[i].ip, sizeof ip);
            memset(&w->j[i], 0xab, sizeof w->j[i]);
            if (w->r->rv) memcpy(w->j[i].ip, ip, sizeof ip);
        }
}

/* Renderers 7 and 9: one stage on every input of w.  The clips read their
** inputs (camera coordinates; the image-plane ends after the near clip) from
** the run, and write the segment's copy. */
static double rv_stage_pass(pt_acc_work *w, int row)
{
    const pt_acc_run *r = w->r;
    const pt_acc_ops *op = ops[w->arith];
    int sub = pt_acc_scene_rows(r->s)->row[row].sub;
    size_t i;

    for (i = 0; i < w->n; i++) {
        size_t k = w->model[i];
        pt_acc_rvseg *g = w->rseg ? &w->rseg[i] : NULL;
        const pt_segment *sg = g ? &r->s->models[k].seg[w->seg[i]] : NULL;

        switch (w->fn) {
        case PT_ACC_FN_RV:
            op->rvstage[sub](r->rv, k, w->v[i], &w->rj[i]);
            break;
        case PT_ACC_FN_RVNEAR:
            g->near = op->rvnear(r->rv, r->rj[k][sg->a].c, r->rj[k][sg->b].c, &g->nc);
            break;
        case PT_ACC_FN_RVCLIP: {
            const pt_acc_rvseg *rg = &r->rseg[k][w->seg[i]];
            pt_dd e[2][2];

            memcpy(e[0], r->rj[k][sg->a].ip, sizeof e[0]);
            memcpy(e[1], r->rj[k][sg->b].ip, sizeof e[1]);
            if (rg->near < 0) memcpy(e[rg->nc.off], rg->nip, sizeof e[0]);
            g->made[0] = g->made[1] = 0;
            g->keep = op->rvclip(e, g);
            break;
        }
        case PT_ACC_FN_RVEND:
            op->stage[sub](&w->ctx[k], w->v[i], &w->j[i]);
            break;
        case PT_ACC_FN_STAGE: case PT_ACC_FN_MSTAGE: case PT_ACC_FN_TAIL:
        case PT_ACC_FN_RASTER:
            break;
        }
    }
    if (w->rj) return w->rj[0].ip[0].hi;
    if (w->rseg) return (double)w->rseg[0].near + w->rseg[0].nc.t.hi + (double)w->rseg[0].keep;
    return w->j[0].pp[0].hi + (double)w->j[0].idx;
}

double pt_acc_stage_pass(pt_acc_work *w, int row)
{
    size_t i;

    if (w->n == 0) return 0.0;
    if (w->r->rv) return rv_stage_pass(w, row);
    if (w->t) {
        pt_acc_tail_fn f = pt_acc_tail_of(w->arith, row);

        for (i = 0; i < w->n; i++) f(w->r->s, &w->t[i]);
        return w->t[0].n[0].hi + (double)w->t[0].idx;
    }
    if (w->mj) {
        pt_acc_mstage_fn f = pt_acc_mstage_of(w->arith, row);

        for (i = 0; i < w->n; i++) f(w->r->cam, w->model[i], w->v[i], &w->mj[i]);
        return w->mj[0].k[0].hi + (double)w->mj[0].code;
    }
    {
        pt_acc_stage_fn f = pt_acc_stage_of(w->arith, row);

        for (i = 0; i < w->n; i++) f(&w->ctx[w->model[i]], w->v[i], &w->j[i]);
        return w->j[0].pp[0].hi + (double)w->j[0].idx;
    }
}

const pt_acc_journey *pt_acc_work_journey(const pt_acc_work *w, size_t i)
{
    return w->j ? &w->j[i] : NULL;
}

const pt_acc_mjourney *pt_acc_work_mjourney(const pt_acc_work *w, size_t i)
{
    return w->mj ? &w->mj[i] : NULL;
}

const pt_acc_mtail *pt_acc_work_mtail(const pt_acc_work *w, size_t i)
{
    return w->t ? &w->t[i] : NULL;
}

const pt_acc_rvjourney *pt_acc_work_rvjourney(const pt_acc_work *w, size_t i)
{
    return w->rj ? &w->rj[i] : NULL;
}

const pt_acc_rvseg *pt_acc_work_rvseg(const pt_acc_work *w, size_t i)
{
    return w->rseg ? &w->rseg[i] : NULL;
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
    pt_acc_dda o;

    o.pixel = tally_pixel;
    o.step = NULL;
    o.ud = &t;
    o.w = r->s->vp_w;
    o.h = r->s->vp_h;
    o.to_vp = pt_pipeline_ref(pt_scene_pipeline(r->s), PT_STAGE_VIEWPORT) ? ptref_pixel2viewport
                                                                     : pt_scene_pipeline(r->s)->to_viewport;
    raster_scene(r, &o, NULL, 0);
    *pixels = t.n;
    return (double)t.sum;
}

/* ===== comparing with the reference ===== */

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

/* Rows viewport, framebuffer and index (e[0], e[1], e[2], in that order in
** both cameras' tables) of one vertex: its pixels a (viewport, framebuffer)
** and index ia against the reference's b and ib. */
static void err_pixels(pt_acc_err e[3], const pt_scene *s, pt_pix a_vp, pt_pix a_fb,
                       int64_t ia, pt_pix b_vp, pt_pix b_fb, int64_t ib)
{
    int in_a = a_vp.ok && pt_inside(a_vp.x, a_vp.y, s->vp_w, s->vp_h);
    int in_b = b_vp.ok && pt_inside(b_vp.x, b_vp.y, s->vp_w, s->vp_h);

    e[0].differ += err_pix(&e[0], a_vp, b_vp);
    e[1].differ += err_pix(&e[1], a_fb, b_fb);
    if (ia >= 0 && ib >= 0) err_add(&e[2], (double)ia, (double)ib);
    e[2].differ += ia != ib;
    e[0].left += in_b && !in_a;
    e[0].entered += in_a && !in_b;
}

/* One pair of journeys from clip coordinates on, into rows ndc .. index; NULL:
** none on that side, which counts as infinite and as differing. */
static void tail_err(pt_acc_err e[PT_ACC_MAXROWS], const pt_scene *s,
                     const pt_acc_mtail *a, const pt_acc_mtail *ref)
{
    static const int n[2] = {3, 3};
    const pt_dd *va[2], *vb[2];
    int row, k;

    for (row = PT_ACC_M_NDC; row <= PT_ACC_M_INDEX; row++) e[row].of++;
    if (!a || !ref) {
        for (k = 0; k < 3; k++) {
            err_add(&e[PT_ACC_M_NDC], (double)INFINITY, 0.0);
            err_add(&e[PT_ACC_M_SCREEN], (double)INFINITY, 0.0);
        }
        for (k = 0; k < 2; k++) {
            err_add(&e[PT_ACC_M_VIEWPORT], (double)INFINITY, 0.0);
            err_add(&e[PT_ACC_M_FRAMEBUFFER], (double)INFINITY, 0.0);
        }
        for (row = PT_ACC_M_NDC; row <= PT_ACC_M_INDEX; row++) e[row].differ++;
        return;
    }
    va[0] = a->n; va[1] = a->sc;                    /* ndc, screen */
    vb[0] = ref->n; vb[1] = ref->sc;
    err_rows(&e[PT_ACC_M_NDC], va, vb, n, 2);
    err_pixels(&e[PT_ACC_M_VIEWPORT], s, a->vp, a->fb, a->idx, ref->vp, ref->fb, ref->idx);
}

/* Used vertex v of model k: the rows of its real stages, then its pixels'
** (matrix camera: those from ndc on when it is inside the view volume on
** either side). */
static void vertex_err(pt_acc_err e[PT_ACC_MAXROWS], const pt_acc_run *ref,
                       const pt_acc_run *r, size_t k, size_t v)
{
    static const int nc[4] = {3, 3, 2, 2}, nm[4] = {3, 4, 4, 4};
    const pt_dd *va[4], *vb[4];

    if (r->mj) {
        const pt_acc_mjourney *a = &r->mj[k][v], *b = &ref->mj[k][v];

        va[0] = a->m; va[1] = a->w; va[2] = a->v; va[3] = a->k;
        vb[0] = b->m; vb[1] = b->w; vb[2] = b->v; vb[3] = b->k;
        err_rows(&e[PT_ACC_M_MODEL], va, vb, nm, 4);    /* model, world, view, clip */
        e[PT_ACC_M_CVV].differ += a->code != b->code;
        if (a->code == 0 || b->code == 0)
            tail_err(e, r->s, a->code == 0 ? &a->t : NULL, b->code == 0 ? &b->t : NULL);
    } else {
        const pt_acc_journey *a = &r->j[k][v], *b = &ref->j[k][v];

        va[0] = a->m; va[1] = a->c; va[2] = a->ip; va[3] = a->pp;
        vb[0] = b->m; vb[1] = b->c; vb[2] = b->ip; vb[3] = b->pp;
        err_rows(&e[PT_ACC_MODEL], va, vb, nc, 4);      /* model, camera, image, pixel */
        err_pixels(&e[PT_ACC_VIEWPORT], r->s, a->vp, a->fb, a->idx, b->vp, b->fb, b->idx);
    }
}

/* The matrix camera's rows ndc .. index: the points clipping made in model
** k's segments, by segment end, in either run. */
static void made_points(pt_acc_err e[PT_ACC_MAXROWS], const pt_acc_run *ref,
                        const pt_acc_run *r, size_t k)
{
    size_t q;
    int end;

    for (q = 0; q < r->s->models[k].nseg; q++)
        for (end = 0; end < 2; end++) {
            const pt_acc_mseg *ga = &r->seg[k][q], *gb = &ref->seg[k][q];

            if (ga->made[end] || gb->made[end])
                tail_err(e, r->s, ga->made[end] ? &ga->end[end] : NULL,
                         gb->made[end] ? &gb->end[end] : NULL);
        }
}

/* Renderers 7 and 9: n values a against the reference's b, in row e; NULL on
** one side counts as infinite.  Returns 1 when any differs. */
static int rv_vals(pt_acc_err *e, const pt_dd *a, const pt_dd *b, int n)
{
    int k, differ = 0;

    for (k = 0; k < n; k++)
        if (err_add(e, a && b ? a[k].hi : (double)INFINITY, a && b ? b[k].hi : 0.0) != 0.0)
            differ = 1;
    return differ;
}

/* A vertex's value at stage sub (model, world, view, camera, image). */
static const pt_dd *rv_value(const pt_acc_rvjourney *j, int sub, int *n)
{
    static const int len[PT_ACC_RV_NFRONT] = {3, 4, 3, 3, 2};

    *n = len[sub];
    switch (sub) {
    case 0: return j->m;
    case 1: return j->w;
    case 2: return j->v;
    case 3: return j->c;
    default: return j->ip;
    }
}

/* The near clip of one segment: the same verdict (and end cut) compares t
** and the new point; another counts as decided otherwise, and a cut on one
** side only as an infinite error. */
static void rv_near_err(pt_acc_err *e, const pt_acc_rvseg *a, const pt_acc_rvseg *b)
{
    int same = a->near == b->near && (a->near >= 0 || a->nc.off == b->nc.off), differ = 0;

    e->of++;
    if (!same) {
        e->decided++;
        differ = 1;
    }
    if (a->near < 0 || b->near < 0) {
        const pt_acc_rvcut *ca = same ? &a->nc : NULL, *cb = same ? &b->nc : NULL;

        differ |= rv_vals(e, ca ? &ca->t : NULL, cb ? &cb->t : NULL, 1);
        differ |= rv_vals(e, ca ? ca->p : NULL, cb ? cb->p : NULL, 2);
    }
    e->differ += (uint64_t)differ;
}

/* The clip to -1..1 of one segment that reaches it on either side: cut k
** against the reference's cut k, when both cut the same end at the same edge. */
static void rv_clip_err(pt_acc_err *e, const pt_acc_rvseg *a, const pt_acc_rvseg *b)
{
    int na = a->near != 0 ? a->ncuts : 0, nb = b->near != 0 ? b->ncuts : 0, k, differ = 0;

    if (a->near == 0 && b->near == 0) return;
    e->of++;
    if (a->near == 0 || b->near == 0 || a->keep != b->keep || na != nb) differ = 1;
    if (na > PT_ACC_RV_MAXCUTS) na = PT_ACC_RV_MAXCUTS;
    if (nb > PT_ACC_RV_MAXCUTS) nb = PT_ACC_RV_MAXCUTS;
    for (k = 0; k < na || k < nb; k++) {
        int both = k < na && k < nb && a->cut[k].edge == b->cut[k].edge
                   && a->cut[k].off == b->cut[k].off;

        if (!both) differ = 1;
        (void)rv_vals(e, both ? &a->cut[k].t : NULL, both ? &b->cut[k].t : NULL, 1);
        if (rv_vals(e, both ? a->cut[k].p : NULL, both ? b->cut[k].p : NULL, 2)) differ = 1;
    }
    if (differ && (a->near == 0 || b->near == 0 || a->keep != b->keep || na != nb || k > 0)) {
        int dec = a->near == 0 || b->near == 0 || a->keep != b->keep || na != nb;

        for (k = 0; !dec && k < na; k++)
            dec = a->cut[k].edge != b->cut[k].edge || a->cut[k].off != b->cut[k].off;
        e->decided += (uint64_t)dec;
    }
    e->differ += (uint64_t)differ;
}

/* The drawn ends of one segment drawn on either side, into rows pixel ..
** index (e[0] .. e[3]); an end drawn on one side only counts as infinite. */
static void rv_end_err(pt_acc_err e[4], const pt_scene *s, const pt_acc_rvseg *a,
                       const pt_acc_rvseg *b)
{
    int i, k;

    if (!a->keep && !b->keep) return;
    for (i = 0; i < 2; i++) {
        const pt_acc_journey *ja = a->keep ? &a->end[i] : NULL, *jb = b->keep ? &b->end[i] : NULL;

        for (k = 0; k < 4; k++) e[k].of++;
        if (ja && jb) {
            e[0].differ += (uint64_t)rv_vals(&e[0], ja->pp, jb->pp, 2);
            err_pixels(&e[1], s, ja->vp, ja->fb, ja->idx, jb->vp, jb->fb, jb->idx);
            continue;
        }
        (void)rv_vals(&e[0], NULL, NULL, 2);
        for (k = 1; k < 3; k++) {
            err_add(&e[k], (double)INFINITY, 0.0);
            err_add(&e[k], (double)INFINITY, 0.0);
        }
        for (k = 0; k < 4; k++) e[k].differ++;
    }
}

/* Renderers 7 and 9: every row of rows, model k's parts (PT_ACC_VERTICES:
** its vertices' values; PT_ACC_SEGMENTS: its segments'). */
static void rv_compare(const pt_acc_run *ref, const pt_acc_run *r, const pt_acc_rows *rows,
                       size_t k, unsigned parts, pt_acc_err e[PT_ACC_MAXROWS])
{
    const pt_scene *s = r->s;
    const pt_model *m = &s->models[k];
    int row, n, pix = pt_acc_row_of(rows, PT_STAGE_PIXEL);
    size_t v, q;

    if (rv_hidden(s, k)) return;
    for (row = 0; row + 1 < rows->nrows; row++) {
        const pt_acc_rowinfo *ri = &rows->row[row];

        if (ri->fn == PT_ACC_FN_RV) {
            for (v = 0; parts & PT_ACC_VERTICES && v < m->nv; v++) {
                const pt_dd *a, *b;

                if (!r->used[k][v]) continue;
                a = rv_value(&r->rj[k][v], ri->sub, &n);
                b = rv_value(&ref->rj[k][v], ri->sub, &n);
                e[row].of++;
                e[row].differ += (uint64_t)rv_vals(&e[row], a, b, n);
            }
            if (ri->sub != PT_ACC_RV_NFRONT - 1 || !(parts & PT_ACC_SEGMENTS)) continue;
            for (q = 0; q < m->nseg; q++) {        /* image: the near clip's points */
                const pt_acc_rvseg *ga = &r->rseg[k][q], *gb = &ref->rseg[k][q];
                int same = ga->near < 0 && gb->near < 0 && ga->nc.off == gb->nc.off;

                if (ga->near >= 0 && gb->near >= 0) continue;
                e[row].of++;
                e[row].differ += (uint64_t)rv_vals(&e[row], same ? ga->nip : NULL,
                                                   same ? gb->nip : NULL, 2);
            }
        } else
            for (q = 0; parts & PT_ACC_SEGMENTS && q < m->nseg; q++) {
                const pt_acc_rvseg *ga = &r->rseg[k][q], *gb = &ref->rseg[k][q];

                if (ri->fn == PT_ACC_FN_RVNEAR) rv_near_err(&e[row], ga, gb);
                else if (ri->fn == PT_ACC_FN_RVCLIP) rv_clip_err(&e[row], ga, gb);
                else if (row == pix) rv_end_err(&e[pix], s, ga, gb);
            }
    }
}

void pt_acc_compare_start(const pt_scene *s, pt_acc_err e[PT_ACC_MAXROWS])
{
    const pt_acc_rows *rows = pt_acc_scene_rows(s);
    int row;

    memset(e, 0, (size_t)rows->nrows * sizeof *e);
    for (row = 0; row + 1 < rows->nrows; row++) e[row].real = rows->row[row].real;
}

void pt_acc_compare_part(const pt_acc_run *ref, const pt_acc_run *r, unsigned parts,
                         pt_acc_err e[PT_ACC_MAXROWS])
{
    const pt_scene *s = r->s;
    const pt_acc_rows *rows = pt_acc_scene_rows(s);
    int row;
    size_t k, v;

    for (row = 0; !rows->rv && parts & PT_ACC_VERTICES && row + 1 < rows->nrows; row++)
        if (rows->row[row].fn != PT_ACC_FN_TAIL) e[row].of += r->nused;  /* tails, rv: */
    for (k = 0; k < s->nmodels; k++) {                             /* counted as they come */
        if (rows->rv) { rv_compare(ref, r, rows, k, parts, e); continue; }
        for (v = 0; parts & PT_ACC_VERTICES && v < s->models[k].nv; v++)
            if (r->used[k][v]) vertex_err(e, ref, r, k, v);
        if (r->seg && parts & PT_ACC_SEGMENTS) made_points(e, ref, r, k);
    }
}

void pt_acc_compare_end(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_MAXROWS])
{
    int raster = pt_acc_scene_rows(r->s)->nrows - 1;

    e[raster] = r->line;
    e[raster].real = 1;
    e[raster].differ = image_diff(ref, r, &e[raster].of);
}

void pt_acc_compare(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_MAXROWS])
{
    pt_acc_compare_start(r->s, e);
    pt_acc_compare_part(ref, r, PT_ACC_VERTICES | PT_ACC_SEGMENTS, e);
    pt_acc_compare_end(ref, r, e);
}
