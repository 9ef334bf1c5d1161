/*
** src/tools/quiz79.c -- pipetrace quiz for the course's renderers 7 and 9
** See LICENSE for copyright and license.
**
** The vertex's segment runs through the renderer's stages on a model of its
** own (its two ends, their colours, the segment), one pt_course_step() a
** stage, and the model before each stage is kept: an answer that follows
** from the sheet's answer before it is found by putting that answer in the
** kept model and running the same stages again.  No formula is computed
** here: the numbers are the stages' (and the pixel-to-viewport rounding is
** the reference pixel stage's, ptref_pixel2viewport, the same rounding the
** rasterizer does to a segment's ends: tests/teach/quiz79.sh checks the
** two give the same pixel).  The colour is the whole scene's: one more
** render, whose rasterizer's listener keeps the last write at the pixel.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/quiz79.h"
#include "io/explain_course.h"
#include "io/numfmt.h"

#define TOL     1e-6             /* absolute and relative tolerance for reals */
#define NSTEP   8                /* the steps, at most: model .. raster */
#define MAXCUT  8                /* clip cuts of one end that get a question */

typedef enum qkind { QK_MODEL, QK_WORLD, QK_VIEW, QK_CAMERA, QK_NEAR, QK_IMAGE, QK_CLIP,
                     QK_PIXEL, QK_VIEWPORT, QK_COLOR } qkind;
enum { A_VAL, A_NONE, A_DROP };  /* an answer's form */

static const struct { const char *name, *values; int n, exact; } kinds[] = {
    [QK_MODEL]    = {"model",    "x_m y_m z_m",   3, 0},
    [QK_WORLD]    = {"world",    "x_w y_w z_w",   3, 0},
    [QK_VIEW]     = {"view",     "x_v y_v z_v",   3, 0},
    [QK_CAMERA]   = {"camera",   "x_c y_c z_c",   3, 0},
    [QK_NEAR]     = {"nearclip", "t x y z",       4, 0},
    [QK_IMAGE]    = {"image",    "x_p y_p z_p",   3, 0},
    [QK_CLIP]     = {"clip",     "edge t x y",    4, 0},
    [QK_PIXEL]    = {"pixel",    "x_pp y_pp",     2, 0},
    [QK_VIEWPORT] = {"viewport", "x_vp y_vp",     2, 1},
    [QK_COLOR]    = {"color",    "r g b",         3, 1},
};

/* The clip's edges as a sheet writes them (pt_rv_edge's order). */
static const char *const edges[] = {"z=n", "x=+1", "x=-1", "y=+1", "y=-1"};

typedef struct qa {              /* a question and its right answer */
    qkind kind;
    int step;                    /* the step that answers it (index in steps) */
    int first;                   /* 1: the step's first question */
    int ans;                     /* A_VAL, A_NONE, A_DROP */
    double v[4];                 /* the values (clip: the edge's number, t, x, y) */
    char name[16];               /* "clip2" */
    pt_vec4 in, at;              /* V's end before its stage and after it (pixel,
                                 ** viewport: after the clip), for the worked formula */
    int has_cut;                 /* 1: cut is the cut the answer is */
    pt_rv_cut cut;
} qa;

struct pt_q79 {
    const pt_scene *s;
    pt_course_pos pos;           /* the position as the render had it */
    int steps[NSTEP];            /* PT_CST_*: the stages run, in order */
    int nsteps;
    pt_rv_model snap[NSTEP];     /* the model before steps[i] */
    int slot;                    /* V's end of the primitive: 0 or 1 */
    int prim;                    /* 1: the model has the primitive */
    size_t pick;                 /* which of the scene model's primitives */
    pt_rv_prim p;                /* it, as the scene model has it */
    unsigned long long v;        /* the vertex, 1-based */
    qa q[PT_Q79_MAX];
    int nq;
    pt_fb_pixel col_at;          /* the colour's pixel (idx -1: the course drops it) */
    uint64_t nwrites;            /* the render's writes there, */
    pt_cx_write last;            /*   the last of them */
};

/* ===== running the segment through the stages ===== */

typedef struct cap {             /* what the stages tell about V's end */
    int slot;
    pt_rv_cut cut[MAXCUT];
    int ncut;
    double x_pp, y_pp;
    int have_pp;
} cap;

static void on_cut(void *ud, const pt_rv_cut *c)
{
    cap *k = ud;
    if (c->off == k->slot && k->ncut < MAXCUT) k->cut[k->ncut++] = *c;
}

static void on_ends(void *ud, double x0, double y0, double x1, double y1)
{
    cap *k = ud;
    k->x_pp = k->slot ? x1 : x0;
    k->y_pp = k->slot ? y1 : y0;
    k->have_pp = 1;
}

static void on_point(void *ud, double x, double y)
{
    cap *k = ud;
    k->x_pp = x;
    k->y_pp = y;
    k->have_pp = 1;
}

/* dst = a copy of src.  0, or -1 when out of memory (dst then empty). */
static int copy_model(pt_rv_model *dst, const pt_rv_model *src)
{
    size_t k;
    int bad = 0;

    memset(dst, 0, sizeof *dst);
    for (k = 0; k < src->nv && !bad; k++) bad = pt_rv_add_vertex(dst, src->v[k]) != 0;
    for (k = 0; k < src->nc && !bad; k++) bad = pt_rv_add_color(dst, src->c[k]) != 0;
    for (k = 0; k < src->np && !bad; k++) bad = pt_rv_add_prim(dst, &src->p[k]) != 0;
    if (bad) pt_rv_model_free(dst);
    return bad ? -1 : 0;
}

/* The vertex standing for V's end in m. */
static size_t vend(const pt_q79 *z, const pt_rv_model *m)
{
    return z->prim && m->np ? m->p[0].v[z->slot] : 0;
}

/* Append question kind k with form ans to out[*n]. */
static qa *add_q(qa *out, int *n, qkind k, int step, int ans)
{
    qa *a;
    int same = 0, i;

    if (*n >= PT_Q79_MAX) return NULL;
    for (i = 0; i < *n; i++) same += out[i].kind == k;
    a = &out[(*n)++];
    memset(a, 0, sizeof *a);
    a->kind = k;
    a->step = step;
    a->ans = ans;
    a->first = *n == 1 || out[*n - 2].step != step;
    if (same) snprintf(a->name, sizeof a->name, "%s%d", kinds[k].name, same + 1);
    else snprintf(a->name, sizeof a->name, "%s", kinds[k].name);
    return a;
}

static void put3(qa *a, pt_vec4 p)
{
    if (!a) return;
    a->v[0] = p.x; a->v[1] = p.y; a->v[2] = p.z;
}

/* Run m (consumed) through z's steps from index from, appending the questions
** they answer to out (*n of them), and keeping the model before each step in
** snap (NULL: not kept).  0 or -1 (out of memory). */
static int run_from(const pt_q79 *z, int from, pt_rv_model *m, qa *out, int *n,
                    pt_rv_model *snap)
{
    const pt_scene *s = z->s;
    pt_course_ls ls;
    pt_fb fb;
    pt_vec4 before;
    cap k;
    int i, rc = 0, nq0;

    memset(&fb, 0, sizeof fb);
    for (i = from; i < z->nsteps && rc == 0; i++) {
        int st = z->steps[i], j;
        pt_rv_raster_ls rls;
        qa *a;

        if (snap && copy_model(&snap[i], m) != 0) { rc = -1; break; }
        memset(&ls, 0, sizeof ls);
        memset(&k, 0, sizeof k);
        memset(&rls, 0, sizeof rls);
        k.slot = z->slot;
        ls.nearclip.cut = ls.clip.cut = on_cut;
        ls.nearclip.ud = ls.clip.ud = &k;
        rls.ends = on_ends;
        rls.point = on_point;
        rls.ud = &k;
        ls.raster_ls = &rls;
        if (st == PT_CST_MODEL) {
            if ((a = add_q(out, n, QK_MODEL, i, A_VAL))) {
                put3(a, m->v[vend(z, m)]);
                a->in = a->at = m->v[vend(z, m)];
            }
            continue;
        }
        if (st == PT_CST_RASTER) {
            if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->vp_background) != 0) { rc = -1; break; }
        }
        before = m->v[vend(z, m)];
        nq0 = *n;
        if (pt_course_step(s, &z->pos, st, m, &fb, &ls) != 0) { rc = -1; break; }
        switch (st) {
        case PT_CST_WORLD: put3(add_q(out, n, QK_WORLD, i, A_VAL), m->v[vend(z, m)]); break;
        case PT_CST_VIEW: put3(add_q(out, n, QK_VIEW, i, A_VAL), m->v[vend(z, m)]); break;
        case PT_CST_CAMERA: put3(add_q(out, n, QK_CAMERA, i, A_VAL), m->v[vend(z, m)]); break;
        case PT_CST_IMAGE: put3(add_q(out, n, QK_IMAGE, i, A_VAL), m->v[vend(z, m)]); break;
        case PT_CST_NEARCLIP:
        case PT_CST_CLIP: {
            qkind qk = st == PT_CST_CLIP ? QK_CLIP : QK_NEAR;
            if (m->np == 0) { add_q(out, n, qk, i, A_DROP); i = z->nsteps; break; }
            if (k.ncut == 0) { add_q(out, n, qk, i, A_NONE); break; }
            for (j = 0; j < k.ncut; j++) {
                if (!(a = add_q(out, n, qk, i, A_VAL))) break;
                if (qk == QK_NEAR) {
                    a->v[0] = k.cut[j].t;
                    a->v[1] = k.cut[j].p[2].x;
                    a->v[2] = k.cut[j].p[2].y;
                    a->v[3] = k.cut[j].p[2].z;
                } else {
                    a->v[0] = (double)k.cut[j].edge;
                    a->v[1] = k.cut[j].t;
                    a->v[2] = k.cut[j].p[2].x;
                    a->v[3] = k.cut[j].p[2].y;
                }
            }
            break;
        }
        case PT_CST_RASTER: {
            pt_vec2 pp;
            pt_pix vp;
            if (!k.have_pp) break;
            pp.x = k.x_pp;
            pp.y = k.y_pp;
            if ((a = add_q(out, n, QK_PIXEL, i, A_VAL))) { a->v[0] = pp.x; a->v[1] = pp.y; }
            vp = ptref_pixel2viewport(pp, s->vp_w, s->vp_h, NULL);
            if ((a = add_q(out, n, QK_VIEWPORT, i, vp.ok ? A_VAL : A_NONE))) {
                a->v[0] = (double)vp.x;
                a->v[1] = (double)vp.y;
            }
            add_q(out, n, QK_COLOR, i, A_NONE);     /* the whole render's: pt_q79_make */
            break;
        }
        default:
            break;
        }
        for (j = nq0; j < *n; j++) {        /* the numbers its worked formula puts in */
            out[j].in = before;
            out[j].at = m->np ? m->v[vend(z, m)] : before;
            if (out[j].kind == QK_NEAR || out[j].kind == QK_CLIP) {
                out[j].has_cut = out[j].ans == A_VAL;
                if (out[j].has_cut) out[j].cut = k.cut[j - nq0];
                if (out[j].has_cut) out[j].at = k.cut[j - nq0].p[2];
            }
        }
    }
    pt_fb_free(&fb);
    pt_rv_model_free(m);
    return rc;
}

/* ===== the colour: the last write at the vertex's pixel ===== */

typedef struct lastw {           /* the render's writes at one pixel */
    int64_t idx;                 /* its index (pt_raster_fb_pixel) */
    int wrap;                    /* 1: the viewport sticks out of the framebuffer */
    const pt_scene *s;
    uint64_t raster_no;          /* the primitive being drawn, 1-based */
    pt_cx_write cur;             /* it */
    pt_cx_write last;            /* the last write at idx */
    uint64_t nwrites;
} lastw;

/* The rasterizer numbers the primitives the clip left, from 1 a position. */
static void lw_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    (void)st; (void)pos; (void)m;
    ((lastw *)ud)->raster_no = 0;
}

static void lw_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    lastw *l = ud;
    pt_cx_write *w = &l->cur;
    int e1 = p->kind == PT_RV_LINE;

    memset(w, 0, sizeof *w);
    w->model = pos->sm->name;
    w->position = pos->pos_name;
    w->prim = ++l->raster_no;
    w->p = *p;
    w->v[0] = (uint64_t)p->v[0] + 1;
    w->v[1] = (uint64_t)p->v[e1] + 1;
    w->c[0] = m->c[p->c[0]];
    w->c[1] = m->c[p->c[e1]];
}

static void lw_ends(void *ud, double x0, double y0, double x1, double y1)
{
    lastw *l = ud;
    l->cur.ends[0] = x0; l->cur.ends[1] = y0;
    l->cur.ends[2] = x1; l->cur.ends[3] = y1;
}

static void lw_slopes(void *ud, const pt_rv_slopes *sl)
{
    lastw *l = ud;
    l->cur.sl = *sl;
    l->cur.has_slopes = 1;
}

/* One write of px (its pixel upper: 0 or 1) at viewport pixel (x_vp, y_vp). */
static void lw_write(lastw *l, const pt_rv_pixel *px, int x_vp, int y_vp, int upper, float f)
{
    const pt_scene *s = l->s;
    pt_fb_pixel at;

    if (pt_raster_fb_pixel(x_vp, y_vp, s->vp_x, s->vp_y, s->fb_w, s->fb_h, l->wrap, &at) != l->idx)
        return;
    l->nwrites++;
    l->last = l->cur;
    l->last.px = *px;
    l->last.px.par = NULL;
    l->last.upper = upper;
    l->last.coverage = f;
    l->last.at = at;
    memcpy(l->last.at.paint.rgb, px->b[upper], 3);
    l->last.at.paint.coverage = f;
}

/* The pixels a pixel line writes, as the trace's pixel records have them. */
static void lw_pixel(void *ud, const pt_rv_pixel *px)
{
    lastw *l = ud;

    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
        lw_write(l, px, px->x_vp, px->y_vp, 0, 1.0f);
        break;
    case PT_RV_PX_POINT:
        if (!px->clipped) lw_write(l, px, px->x_vp, px->y_vp, 0, 1.0f);
        break;
    case PT_RV_PX_AA: {
        double a = px->transposed ? px->x_pp : px->y_pp;
        float f = pt_aa_weight(a, floor(a));
        if (px->transposed) {
            lw_write(l, px, px->lo, px->y_vp, 0, 1.0f - f);
            lw_write(l, px, px->hi, px->y_vp, 1, f);
        } else {
            lw_write(l, px, px->x_vp, px->lo, 0, 1.0f - f);
            lw_write(l, px, px->x_vp, px->hi, 1, f);
        }
        break;
    }
    }
}

/* The colour question c, for the vertex's viewport pixel vp: the pixel the
** course writes it to (pt_raster_fb_pixel, wrapped where the viewport sticks
** out), the bytes the whole render leaves there and the last write.
** 0, or -1 when out of memory. */
static int colour_key(pt_q79 *z, qa *c, const qa *vp)
{
    const pt_scene *s = z->s;
    pt_rv_raster_ls rls;
    pt_course_ls ls;
    lastw l;
    pt_fb fb;
    int rc;

    if (vp->ans != A_VAL) return 0;
    memset(&l, 0, sizeof l);
    l.s = s;
    l.wrap = !pt_scene_vp_inside(s);
    l.idx = pt_raster_fb_pixel((int64_t)vp->v[0], (int64_t)vp->v[1], s->vp_x, s->vp_y,
                               s->fb_w, s->fb_h, l.wrap, &z->col_at);
    if (l.idx < 0) return 0;                /* "Bad pixel coordinate": none */
    memset(&rls, 0, sizeof rls);
    rls.ends = lw_ends;
    rls.slopes = lw_slopes;
    rls.pixel = lw_pixel;
    rls.ud = &l;
    memset(&ls, 0, sizeof ls);
    ls.stage = lw_stage;
    ls.raster = lw_raster;
    ls.raster_ls = &rls;
    ls.ud = &l;
    if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) return -1;
    rc = pt_course_render(s, &fb, &ls);
    if (rc == 0) {
        const unsigned char *b = fb.rgb + 3 * l.idx;
        c->ans = A_VAL;
        c->v[0] = b[0]; c->v[1] = b[1]; c->v[2] = b[2];
        z->nwrites = l.nwrites;
        z->last = l.last;
    }
    pt_fb_free(&fb);
    return rc;
}

/* ===== the reference ===== */

typedef struct grab {            /* the vertex's model as the render built it */
    const pt_model *sm;
    pt_course_pos pos;
    pt_rv_model m;
    int found, failed;
} grab;

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    grab *g = ud;

    if (st != PT_CST_MODEL || pos->sm != g->sm || g->found) return;
    g->found = 1;
    g->pos = *pos;
    if (copy_model(&g->m, m) != 0) g->failed = 1;
}

/* z's model of its own: V's primitive (the first segment using index v, else
** the first point) with its ends and colours, or V alone. */
static int own_model(pt_q79 *z, const pt_rv_model *m, uint32_t v, pt_rv_model *out)
{
    size_t k, pick = m->np;
    pt_rv_prim p;
    pt_rgb white = {1.0f, 1.0f, 1.0f};

    memset(out, 0, sizeof *out);
    for (k = 0; k < m->np && pick == m->np; k++)
        if (m->p[k].kind == PT_RV_LINE && (m->p[k].v[0] == v || m->p[k].v[1] == v)) pick = k;
    for (k = 0; k < m->np && pick == m->np; k++)
        if (m->p[k].kind == PT_RV_POINT && m->p[k].v[0] == v) pick = k;
    if (pick == m->np) {
        z->prim = 0;
        return pt_rv_add_vertex(out, m->v[v]) | pt_rv_add_color(out, v < m->nc ? m->c[v] : white);
    }
    z->prim = 1;
    z->pick = pick;
    z->p = p = m->p[pick];
    z->slot = p.kind == PT_RV_LINE && p.v[0] != v;
    if (pt_rv_add_vertex(out, m->v[p.v[0]]) || pt_rv_add_vertex(out, m->v[p.v[1]]) ||
        pt_rv_add_color(out, m->c[p.c[0]]) || pt_rv_add_color(out, m->c[p.c[1]]))
        return -1;
    p.v[0] = p.c[0] = 0;
    p.v[1] = p.c[1] = p.kind == PT_RV_LINE ? 1 : 0;
    return pt_rv_add_prim(out, &p);
}

pt_q79 *pt_q79_make(const pt_scene *s, const pt_model *m, unsigned long long v)
{
    pt_q79 *z = calloc(1, sizeof *z);
    pt_course_ls ls;
    pt_rv_model own;
    grab g;
    pt_fb fb;
    int rc;

    memset(&g, 0, sizeof g);
    memset(&ls, 0, sizeof ls);
    memset(&own, 0, sizeof own);
    g.sm = m;
    ls.stage = on_stage;
    ls.ud = &g;
    if (!z || pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) {
        free(z);
        fputs("pipetrace quiz: out of memory\n", stderr);
        return NULL;
    }
    rc = pt_course_render(s, &fb, &ls);
    pt_fb_free(&fb);
    if (rc == 0 && !g.failed && !g.found) {
        fprintf(stderr, "pipetrace quiz: %s: model %s is hidden: the renderer draws none of "
                "its vertices\n", s->path, m->name);
        pt_rv_model_free(&g.m);
        free(z);
        return NULL;
    }
    z->s = s;
    z->pos = g.pos;
    z->v = v;
    if (rc == 0 && !g.failed && own_model(z, &g.m, (uint32_t)(v - 1), &own) != 0) rc = -1;
    z->steps[z->nsteps++] = PT_CST_MODEL;   /* the renderer's stages, in its order */
    if (s->renderer == 9) z->steps[z->nsteps++] = PT_CST_WORLD;
    z->steps[z->nsteps++] = PT_CST_VIEW;
    z->steps[z->nsteps++] = PT_CST_CAMERA;
    if (s->nearclip && z->prim) z->steps[z->nsteps++] = PT_CST_NEARCLIP;
    z->steps[z->nsteps++] = PT_CST_IMAGE;
    if (z->prim) {                          /* a vertex no primitive uses ends here */
        z->steps[z->nsteps++] = PT_CST_CLIP;
        z->steps[z->nsteps++] = PT_CST_RASTER;
    }
    z->col_at.idx = -1;
    if (rc == 0 && !g.failed) {
        if (run_from(z, 0, &own, z->q, &z->nq, z->snap) != 0) rc = -1;
        memset(&own, 0, sizeof own);        /* run_from freed it */
    }
    if (rc == 0 && !g.failed && z->nq >= 2 && z->q[z->nq - 1].kind == QK_COLOR &&
        colour_key(z, &z->q[z->nq - 1], &z->q[z->nq - 2]) != 0) rc = -1;
    if (rc != 0 || g.failed) {
        pt_rv_model_free(&g.m);
        pt_rv_model_free(&own);
        pt_q79_free(z);
        fputs("pipetrace quiz: out of memory\n", stderr);
        return NULL;
    }
    pt_rv_model_free(&g.m);
    return z;
}

void pt_q79_free(pt_q79 *z)
{
    int i;

    if (!z) return;
    for (i = 0; i < NSTEP; i++) pt_rv_model_free(&z->snap[i]);
    free(z);
}

int pt_q79_count(const pt_q79 *z) { return z->nq; }
const char *pt_q79_name(const pt_q79 *z, int k) { return z->q[k].name; }
const char *pt_q79_values(const pt_q79 *z, int k) { return kinds[z->q[k].kind].values; }

/* ===== answers ===== */

static void answer_text(const qa *a, char *b, size_t n)
{
    size_t len = 0;
    int i;

    if (a->ans != A_VAL) { snprintf(b, n, "%s", a->ans == A_NONE ? "none" : "dropped"); return; }
    b[0] = '\0';
    for (i = 0; i < kinds[a->kind].n && len < n; i++) {
        char d[PT_NUMLEN];
        if (a->kind == QK_CLIP && i == 0) snprintf(d, sizeof d, "%s", edges[(int)a->v[0]]);
        else pt_fmt_shortest(d, a->v[i]);
        len += (size_t)snprintf(b + len, n - len, "%s%s", i ? " " : "", d);
    }
}

void pt_q79_answer(const pt_q79 *z, int k, char *b, size_t n)
{
    answer_text(&z->q[k], b, n);
}

/* The step of pipetrace step (io/explain_course.h) that answers kind k. */
static pt_cx_step step_of(qkind k)
{
    switch (k) {
    case QK_MODEL:    return PT_CXS_MODEL;
    case QK_WORLD:    return PT_CXS_WORLD;
    case QK_VIEW:     return PT_CXS_VIEW;
    case QK_CAMERA:   return PT_CXS_CAMERA;
    case QK_NEAR:     return PT_CXS_NEARCLIP;
    case QK_IMAGE:    return PT_CXS_IMAGE;
    case QK_CLIP:     return PT_CXS_CLIP;
    case QK_PIXEL:    return PT_CXS_PIXEL;
    case QK_VIEWPORT: return PT_CXS_VIEWPORT;
    case QK_COLOR:    return PT_CXS_RASTER;
    }
    return PT_CXS_MODEL;
}

const char *pt_q79_formula(const pt_q79 *z, int k)
{
    qkind kd = z->q[k].kind;
    return kd == QK_MODEL ? NULL : pt_cx_formula(z->s->renderer, step_of(kd));
}

/* The colour question's numbers: the last write at the pixel (io/explain_course.h),
** the viewport's background where nothing wrote it, or where the course drops it. */
static size_t colour_worked(const pt_q79 *z, const qa *a, char *b, size_t n, const char *sep)
{
    const pt_scene *s = z->s;
    const pt_fb_pixel *at = &z->col_at;
    int len;

    if (a->ans == A_VAL && z->nwrites)
        return pt_cx_explain_write(b, n, s, &z->last, z->nwrites, sep);
    if (a->ans == A_VAL)
        len = snprintf(b, n, "no primitive writes (x_fb, y_fb) = (%lld, %lld), index %lld: it "
                       "keeps the viewport's background, which clearing the viewport put "
                       "there: (%d, %d, %d)", (long long)at->x_fb, (long long)at->y_fb,
                       (long long)at->idx, s->vp_background[0], s->vp_background[1],
                       s->vp_background[2]);
    else if (z->q[z->nq - 2].ans == A_VAL)  /* the viewport pixel, dropped */
        len = snprintf(b, n, "none: dropped (Bad pixel coordinate): (x_fb, y_fb) = (%lld, "
                       "%lld) lies outside the %d x %d framebuffer, and the course's index "
                       "y_fb*W + x_fb, wrapped past an edge, lies outside its %lld pixels too: "
                       "the course prints \"FrameBuffer: Bad pixel coordinate (%lld, %lld) "
                       "[w=%d, h=%d]\" and writes nothing", (long long)at->x_fb,
                       (long long)at->y_fb, s->fb_w, s->fb_h, (long long)s->fb_w * s->fb_h,
                       (long long)at->x_fb, (long long)at->y_fb, s->fb_w, s->fb_h);
    else
        len = snprintf(b, n, "none: the vertex has no viewport pixel");
    (void)sep;
    return len < 0 ? 0 : (size_t)len;
}

size_t pt_q79_worked(const pt_q79 *z, int k, char *b, size_t n, const char *sep)
{
    const qa *a = &z->q[k];
    static const pt_course_stage stage[] = {
        [QK_MODEL] = PT_CST_MODEL, [QK_WORLD] = PT_CST_WORLD, [QK_VIEW] = PT_CST_VIEW,
        [QK_CAMERA] = PT_CST_CAMERA, [QK_NEAR] = PT_CST_NEARCLIP, [QK_IMAGE] = PT_CST_IMAGE,
        [QK_CLIP] = PT_CST_CLIP, [QK_PIXEL] = PT_CST_CLIP, [QK_VIEWPORT] = PT_CST_CLIP,
        [QK_COLOR] = PT_CST_CLIP};
    pt_course_cam cam;
    pt_cx_rec r;

    if (n) b[0] = '\0';
    if (a->kind == QK_COLOR) return colour_worked(z, a, b, n, sep);
    pt_course_camera(z->s, &cam);
    memset(&r, 0, sizeof r);
    r.st = stage[a->kind];
    r.pos = &z->pos;
    r.prev = a->in;
    r.cur = a->kind == QK_PIXEL || a->kind == QK_VIEWPORT ? a->in : a->at;
    r.cut = a->has_cut ? &a->cut : NULL;
    r.cut_prim = z->pick + 1;
    return pt_cx_explain_step(b, n, z->s, &cam, &r, step_of(a->kind), sep);
}

/* a is b, within the tolerance (non-finite: the same value). */
static int close_enough(double a, double b)
{
    if (isnan(b)) return isnan(a);
    if (!isfinite(b)) return a == b;
    return fabs(a - b) <= TOL || fabs(a - b) <= TOL * fabs(b);
}

/* Read line as an answer of kind k: its form and values.  0, or -1 with the
** column and what is wrong. */
static int parse(qkind k, const char *line, int *form, double *v, int *col, const char **why)
{
    const char *p = line;
    int n = 0, want = kinds[k].n;

    *form = A_VAL;
    for (;;) {
        char tok[64], *end;
        size_t len = 0;
        int c;

        while (*p == ' ' || *p == '\t' || *p == ',') p++;
        c = (int)(p - line) + 1;
        if (!*p) break;
        while (p[len] && p[len] != ' ' && p[len] != '\t' && p[len] != ',') len++;
        if (n == want || (n == 1 && *form != A_VAL)) {
            *col = c;
            *why = *form != A_VAL ? "nothing may follow 'none' or 'dropped'"
                                  : "more values than the stage has";
            return -1;
        }
        if (len >= sizeof tok) { *col = c; *why = "not a number"; return -1; }
        memcpy(tok, p, len);
        tok[len] = '\0';
        p += len;
        if (n == 0 && (!strcmp(tok, "none") || !strcmp(tok, "dropped"))) {
            *form = tok[0] == 'n' ? A_NONE : A_DROP;
            n++;
            continue;
        }
        if (k == QK_CLIP && n == 0) {
            int e;
            for (e = PT_RV_XPOS; e <= PT_RV_YNEG; e++)
                if (!strcmp(tok, edges[e])) break;
            if (e > PT_RV_YNEG) {
                *col = c;
                *why = "not an edge (x=+1, x=-1, y=+1 or y=-1), 'none' or 'dropped'";
                return -1;
            }
            v[n++] = e;
            continue;
        }
        v[n] = strtod(tok, &end);
        if (end == tok || *end) { *col = c; *why = "not a number"; return -1; }
        n++;
    }
    if (*form != A_VAL) return 0;
    if (n < want) {
        *col = (int)(p - line) + 1;
        *why = n == 0 ? "no answer" : "fewer values than the stage has";
        return -1;
    }
    return 0;
}

/* 1 when form and v are a's answer. */
static int same(const qa *a, int form, const double *v)
{
    int i;

    if (form != a->ans) return 0;
    if (form != A_VAL) return 1;
    for (i = 0; i < kinds[a->kind].n; i++) {
        int exact = kinds[a->kind].exact || (a->kind == QK_CLIP && i == 0);
        if (exact ? v[i] != a->v[i] : !close_enough(v[i], a->v[i])) return 0;
    }
    return 1;
}

/* The point a sheet's answer of kind k gives for V's end (z kept from p). */
static int answer_point(qkind k, const double *v, pt_vec4 *p)
{
    switch (k) {
    case QK_MODEL: case QK_WORLD: case QK_VIEW: case QK_CAMERA: case QK_IMAGE:
        p->x = v[0]; p->y = v[1]; p->z = v[2];
        return 1;
    case QK_NEAR:
        p->x = v[1]; p->y = v[2]; p->z = v[3];
        return 1;
    case QK_CLIP:
        p->x = v[2]; p->y = v[3]; p->z = 0.0;
        return 1;
    case QK_PIXEL: case QK_VIEWPORT: case QK_COLOR:
        return 0;
    }
    return 0;
}

/* 1 when form, v (the sheet's answer to k) is what k's stage gives from the
** sheet's own wrong answer before it. */
static int follows(const pt_q79 *z, int k, int form, const double *v, const int *res,
                   const char *const *lines)
{
    const qa *a = &z->q[k];
    int j = k - 1, pf, c, slip = 0;
    double pv[4];
    const char *why;

    if (k == 0 || !lines) return 0;
    if (a->kind == QK_VIEWPORT) {           /* the rounding of the sheet's pixel */
        pt_vec2 pp;
        pt_pix vp;
        qa b = *a;
        if (z->q[j].kind != QK_PIXEL || !lines[j] || res[j] == 1 || res[j] < 0 ||
            parse(QK_PIXEL, lines[j], &pf, pv, &c, &why) != 0 || pf != A_VAL) return 0;
        pp.x = pv[0];
        pp.y = pv[1];
        vp = ptref_pixel2viewport(pp, z->s->vp_w, z->s->vp_h, NULL);
        b.ans = vp.ok ? A_VAL : A_NONE;
        b.v[0] = (double)vp.x;
        b.v[1] = (double)vp.y;
        return same(&b, form, v);
    }
    if (!a->first || a->kind == QK_MODEL || a->kind == QK_COLOR) return 0;
    for (;;) {                              /* the sheet's last point for V's end
                                            ** (a cut that does not happen passes it on) */
        pt_vec4 p;
        pt_rv_model m;
        qa out[PT_Q79_MAX];
        int n = 0, i, r = 0;

        if (j < 0 || !lines[j] || res[j] < 0 || parse(z->q[j].kind, lines[j], &pf, pv, &c, &why) != 0)
            return 0;
        slip |= res[j] != 1;
        if (pf == A_NONE && (z->q[j].kind == QK_NEAR || z->q[j].kind == QK_CLIP)) { j--; continue; }
        if (pf != A_VAL || !slip || !answer_point(z->q[j].kind, pv, &p))
            return 0;                       /* right answers: no slip to carry */
        if (copy_model(&m, &z->snap[a->step]) != 0) return 0;
        if (m.nv == 0) { pt_rv_model_free(&m); return 0; }
        if (z->q[j].kind == QK_CLIP) p.z = m.v[vend(z, &m)].z;
        p.w = m.v[vend(z, &m)].w;
        m.v[vend(z, &m)] = p;
        if (run_from(z, a->step, &m, out, &n, NULL) != 0) return 0;
        for (i = 0; i < n; i++)
            if (!strcmp(out[i].name, a->name)) { r = same(&out[i], form, v); break; }
        return r;
    }
}

int pt_q79_grade(const pt_q79 *z, int k, const char *line, const int *res,
                 const char *const *lines, int *col, const char **why)
{
    double v[4] = {0, 0, 0, 0};
    int form;

    if (parse(z->q[k].kind, line, &form, v, col, why) != 0) return -1;
    if (same(&z->q[k], form, v)) return 1;
    return follows(z, k, form, v, res, lines) ? 2 : 0;
}

int pt_q79_r4_sheet(const pt_q79 *z, const char *const *lines, int n)
{
    static const int r4[] = {3, 3, 3, 2, 2, 2, 1};   /* renderer 4's stages' values */
    int i, fits = n == z->nq;

    if (n != (int)(sizeof r4 / sizeof *r4)) return 0;
    for (i = 0; i < n; i++) {
        double v[4];
        int k = 0, form, c;
        const char *why, *p = lines[i];
        while (*p) {                        /* count the tokens */
            while (*p == ' ' || *p == '\t' || *p == ',') p++;
            if (!*p) break;
            k++;
            while (*p && *p != ' ' && *p != '\t' && *p != ',') p++;
        }
        if (k != r4[i] && !(k == 1 && strstr(lines[i], "none"))) return 0;
        if (fits && parse(z->q[i].kind, lines[i], &form, v, &c, &why) != 0) fits = 0;
    }
    return !fits;
}

void pt_q79_describe(const pt_q79 *z, char *b, size_t n)
{
    if (!z->prim) {
        snprintf(b, n, "no segment or point uses vertex %llu: it goes through the stages "
                 "up to the image plane, and is drawn nowhere", z->v);
        return;
    }
    if (z->p.kind == PT_RV_LINE)
        snprintf(b, n, "the questions follow vertex %llu's end of its first segment, from "
                 "vertex %u to vertex %u", z->v, (unsigned)z->p.v[0] + 1, (unsigned)z->p.v[1] + 1);
    else
        snprintf(b, n, "the questions follow vertex %llu as its point (radius %d)", z->v,
                 z->p.radius);
}

int pt_q79_stage_name(const char *name)
{
    int k;
    size_t len;

    for (k = QK_MODEL; k <= QK_COLOR; k++) {
        len = strlen(kinds[k].name);
        if (!strncmp(name, kinds[k].name, len) &&
            (name[len] == '\0' || (name[len] >= '2' && name[len] <= '9' && !name[len + 1])))
            return 1;
    }
    return 0;
}

int pt_q79_renderer(const pt_q79 *z) { return z->s->renderer; }
