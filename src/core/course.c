/*
** src/core/course.c -- renderers 7 and 9 of the course: a scene through their stages
** See LICENSE for copyright and license.
**
** One loop for both drivers: a position's work is its setup (hidden checks,
** warnings, the model built from the scene's) and then its steps, one per
** stage.  Pipeline.render takes each position through all its steps in
** turn; renderer 9's Pipeline2 takes every position through step 1, then
** every one still drawn through step 2, and so on.
*/
#include <stdlib.h>
#include <string.h>
#include "core/course.h"
#include "stages/r7_model2view.h"
#include "stages/r7_view2camera.h"
#include "stages/r9_model2world.h"
#include "stages/r9_world2view.h"
#include "stages/r9_view2camera.h"
#include "stages/rv_nearclip.h"
#include "stages/rv_project.h"
#include "stages/rv_clip.h"

/* The steps after the setup, as each renderer orders them. */
typedef enum step { ST_WORLD, ST_VIEW, ST_CAMERA, ST_NEARCLIP, ST_IMAGE, ST_CLIP,
                    ST_RASTER } step;
static const step steps7[] = {ST_VIEW, ST_CAMERA, ST_NEARCLIP, ST_IMAGE, ST_CLIP, ST_RASTER};
static const step steps9[] = {ST_WORLD, ST_VIEW, ST_CAMERA, ST_NEARCLIP, ST_IMAGE, ST_CLIP,
                              ST_RASTER};

/* One position's state. */
typedef struct cpos {
    pt_course_pos pos;
    pt_rv_model m;
    int live;                    /* 1: visible, its model drawn */
} cpos;

/* The pieces of the render (pt_course_ls.piece): the one going on, and how
** much is in it so far. */
typedef struct pieces {
    uint64_t n;
    uint64_t vertices, prims, pixels;   /* pixels: pixel lines (pt_rv_raster_steps) */
    int taken;                   /* 1: its records are wanted */
} pieces;

/* What every step needs. */
typedef struct run {
    const pt_scene *s;
    const pt_course_ls *ls;
    pt_course_cam cam;
    pt_rv_raster_par par;
    pt_fb *fb;
    pieces *pc;                  /* NULL: one piece, wanted */
} run;

static const pt_rv_clip_ls no_clip_ls = {NULL, NULL, NULL, NULL, NULL};

/* ===== the camera and the framebuffer ===== */

void pt_course_camera(const pt_scene *s, pt_course_cam *out)
{
    memset(out, 0, sizeof *out);
    out->cam.perspective = s->perspective;
    out->cam.l = s->cam_l;
    out->cam.r = s->cam_r;
    out->cam.b = s->cam_b;
    out->cam.t = s->cam_t;
    out->cam.n = s->cam_n;
    if (s->renderer == 9) {
        out->cam.view = s->view;
        out->norm = pt_r9_normalize_matrix(&out->cam);
    } else {
        pt_matop id;
        memset(&id, 0, sizeof id);
        id.mul = PT_MATMUL_SET;
        id.kind = PT_MATOP_IDENTITY;
        out->norm = pt_r9_position_matrix(&id, 1);
    }
}

/* new FrameBuffer(W, H, bg), then vp.clearVP() (its Bad pixel lines, if
** any, to the rasterizer's listener).  The background goes into the first
** pixel and is copied on, a doubling block at a time (no pixels: none). */
static void clear_fb(const pt_scene *s, pt_fb *fb, const pt_rv_raster_par *par,
                     const pt_rv_raster_ls *rls)
{
    size_t n = fb->rgb ? 3 * (size_t)fb->w * (size_t)fb->h : 0, k;

    if (n > 0) memcpy(fb->rgb, s->background, 3);
    for (k = 3; k < n; k *= 2) memcpy(fb->rgb + k, fb->rgb, k < n - k ? k : n - k);
    pt_rv_clear_vp(par, fb->rgb, rls);
}

/* ===== the pieces ===== */

/* A cut may fall here, before the work on nv vertices or on prims primitives
** drawn. */
static void cut(const run *r, uint64_t nv, uint64_t prims)
{
    const pt_course_ls *ls = r->ls;
    pieces *pc = r->pc;

    if (!pc) return;
    if (pc->vertices >= (ls->piece_vertices ? ls->piece_vertices : PT_COURSE_PIECE_VERTICES) ||
        pc->prims >= (ls->piece_prims ? ls->piece_prims : PT_COURSE_PIECE_PRIMS) ||
        pc->pixels >= (ls->piece_pixels ? ls->piece_pixels : PT_COURSE_PIECE_PIXELS)) {
        pc->n++;
        pc->vertices = pc->prims = pc->pixels = 0;
        pc->taken = ls->piece(ls->ud, pc->n, 0);
    }
    pc->vertices += nv;
    pc->prims += prims;
}

/* The rasterizer's listener for what the piece going on wants. */
static const pt_rv_raster_ls *raster_ls(const run *r)
{
    return r->ls && (!r->pc || r->pc->taken) ? r->ls->raster_ls : NULL;
}

/* ===== the setup: the model as the course's client builds it ===== */

/* The scene's model as a pt_rv_model: vertices (w = 1), the colour list the
** scene gives (empty without `color`/`vcolor`), segments and points in file
** order.  0 or -1 (out of memory). */
static int build_model(const pt_model *sm, pt_rv_model *m)
{
    size_t k, seg = 0, pt = 0, nc;

    nc = !sm->colors_given ? 0 : sm->ncolors > 0 ? sm->ncolors : sm->nv;
    if (pt_rv_reserve(m, sm->nv, nc, sm->nseg + sm->npts) != 0) return -1;
    for (k = 0; k < sm->nv; k++) {
        pt_vec4 v = {sm->v[k].x, sm->v[k].y, sm->v[k].z, 1.0};
        m->v[m->nv++] = v;
    }
    if (sm->colors_given && sm->ncolors > 0) {
        for (k = 0; k < sm->ncolors; k++) m->c[m->nc++] = sm->colors[k];
    } else if (sm->colors_given) {               /* `color R G B`: one a vertex */
        pt_rgb c = {(float)sm->color[0] / 255.0f, (float)sm->color[1] / 255.0f,
                    (float)sm->color[2] / 255.0f};
        for (k = 0; k < sm->nv; k++) m->c[m->nc++] = c;
    }
    while (seg < sm->nseg || pt < sm->npts) {    /* a point after `after` segments */
        pt_rv_prim *p = &m->p[m->np++];
        memset(p, 0, sizeof *p);
        if (pt < sm->npts && sm->pts[pt].after <= seg) {
            p->kind = PT_RV_POINT;
            p->v[0] = p->v[1] = sm->pts[pt].v;
            p->c[0] = p->c[1] = sm->pts[pt].c;
            p->radius = sm->pts[pt].radius;
            pt++;
        } else {
            p->kind = PT_RV_LINE;
            p->v[0] = sm->seg[seg].a;
            p->v[1] = sm->seg[seg].b;
            p->c[0] = sm->seg[seg].ca;
            p->c[1] = sm->seg[seg].cb;
            seg++;
        }
    }
    return 0;
}

static void warn(const run *r, pt_course_warn w, const cpos *c)
{
    if (r->ls && r->ls->warn) r->ls->warn(r->ls->ud, w, &c->pos, &c->m);
}

static void mark(const run *r, pt_course_mark k, const pt_course_pos *pos)
{
    if (r->ls && r->ls->mark) r->ls->mark(r->ls->ud, k, &r->cam, pos);
}

static void report(const run *r, pt_course_stage st, const cpos *c)
{
    if (r->ls && r->ls->stage) r->ls->stage(r->ls->ud, st, &c->pos, &c->m);
}

/* The position's setup, up to its "0. Model" list: hidden checks, the
** model, CheckModel's warnings, the default colours.  Leaves c->live 0 for
** a hidden position or model.  0 or -1 (out of memory). */
static int setup(const run *r, cpos *c)
{
    const pt_model *sm = c->pos.sm;
    size_t k;

    cut(r, sm->nv, 0);
    if (sm->hidden_position) { mark(r, PT_CMK_POSITION_HIDDEN, &c->pos); return 0; }
    mark(r, PT_CMK_POSITION, &c->pos);
    if (sm->hidden_model) {
        mark(r, PT_CMK_MODEL_HIDDEN, &c->pos);
        mark(r, PT_CMK_POSITION_END, &c->pos);
        return 0;
    }
    mark(r, PT_CMK_MODEL, &c->pos);
    if (build_model(sm, &c->m) != 0) return -1;
    {                                            /* CheckModel.check */
        int nov = c->m.nv == 0 && c->m.np > 0, nop = c->m.nv > 0 && c->m.np == 0;
        if (nov) warn(r, PT_CWN_NO_VERTICES, c);
        if (nop) warn(r, PT_CWN_NO_PRIMITIVES, c);
        if (c->m.nv > 0 && c->m.nc == 0) warn(r, PT_CWN_NO_COLORS, c);
        if (nov || nop) warn(r, PT_CWN_DUMP, c);
    }
    if (c->m.nc == 0 && c->m.nv > 0) {           /* Pipeline.DEFAULT_COLOR */
        pt_rgb white = {1.0f, 1.0f, 1.0f};
        for (k = 0; k < c->m.nv; k++)
            if (pt_rv_add_color(&c->m, white) != 0) return -1;
        warn(r, PT_CWN_DEFAULT_COLOR, c);
    }
    report(r, PT_CST_MODEL, c);
    c->live = 1;
    return 0;
}

/* ===== the steps ===== */

/* Run step st on c's model.  0 or -1 (out of memory). */
static int do_step(const run *r, step st, cpos *c)
{
    pt_rv_model *m = &c->m;
    const pt_course_ls *ls = r->ls;
    size_t k;

    if (st != ST_RASTER) cut(r, m->nv, 0);
    switch (st) {
    case ST_WORLD:
        pt_r9_model2world_all(m->v, m->nv, &c->pos.matrix);
        report(r, PT_CST_WORLD, c);
        break;
    case ST_VIEW:
        if (r->s->renderer == 9) pt_r9_world2view_all(m->v, m->nv, r->cam.cam.view);
        else pt_r7_model2view_all(m->v, m->nv, c->pos.translate);
        report(r, PT_CST_VIEW, c);
        break;
    case ST_CAMERA:
        if (r->s->renderer == 9) pt_r9_view2camera_all(m->v, m->nv, &r->cam.norm);
        else pt_r7_view2camera_all(m->v, m->nv, &r->cam.cam);
        report(r, PT_CST_CAMERA, c);
        break;
    case ST_NEARCLIP:
        if (r->s->nearclip &&
            pt_rv_nearclip(m, r->cam.cam.n, ls ? &ls->nearclip : &no_clip_ls) != 0)
            return -1;
        report(r, PT_CST_NEARCLIP, c);
        break;
    case ST_IMAGE:
        pt_rv_project_all(m->v, m->nv, r->cam.cam.perspective);
        report(r, PT_CST_IMAGE, c);
        break;
    case ST_CLIP:
        if (pt_rv_clip(m, ls ? &ls->clip : &no_clip_ls) != 0) return -1;
        report(r, PT_CST_CLIP, c);
        break;
    case ST_RASTER:
        for (k = 0; k < m->np; k++) {
            uint64_t n = 0, steps;
            int wanted;
            cut(r, 0, 1);
            wanted = !r->pc || r->pc->taken;
            if (ls && ls->tally) ls->tally->prims_wanted += (uint64_t)wanted;
            if (ls && ls->raster) ls->raster(ls->ud, &c->pos, m, &m->p[k]);
            if (ls && ls->measure) {
                if (r->pc) r->pc->pixels += pt_rv_raster_steps(m, &m->p[k], &r->par);
                continue;
            }
            if (!r->pc) {                        /* one piece: no cuts to count for */
                n = pt_rv_raster_prim(m, &m->p[k], &r->par, r->fb->rgb, raster_ls(r));
                if (ls && ls->tally) ls->tally->prims_drawn++;
            } else if (wanted || !ls->skip_unwanted) {
                n = pt_rv_raster_prim_steps(m, &m->p[k], &r->par, r->fb->rgb, raster_ls(r),
                                            &steps);
                if (ls->tally) ls->tally->prims_drawn++;
                r->pc->pixels += steps;          /* the cut's count, drawn or not */
            } else {
                r->pc->pixels += pt_rv_raster_steps(m, &m->p[k], &r->par);
            }
            if (ls && ls->drawn) ls->drawn(ls->ud, &c->pos, m, &m->p[k], n);
        }
        break;
    }
    return 0;
}

/* ===== the drivers ===== */

/* r ready for s's steps into fb, told to ls. */
static void start(run *r, const pt_scene *s, pt_fb *fb, const pt_course_ls *ls)
{
    memset(r, 0, sizeof *r);
    r->s = s;
    r->ls = ls;
    r->fb = fb;
    pt_course_camera(s, &r->cam);
    r->par.w = s->vp_w;
    r->par.h = s->vp_h;
    r->par.x_ul = s->vp_x;
    r->par.y_ul = s->vp_y;
    r->par.W = fb->w;
    r->par.H = fb->h;
    memcpy(r->par.bg, s->vp_background, 3);
    r->par.antialias = s->antialias;
    r->par.gamma = s->gamma;
}

/* Pipeline.render: each position through every step. */
static int pipeline1(const run *r, cpos *c, size_t nc, const step *sts, size_t nst)
{
    size_t k, j;

    for (k = 0; k < nc; k++) {
        if (k > 0) {                             /* done with: its room serves the next */
            c[k].m = c[k - 1].m;
            memset(&c[k - 1].m, 0, sizeof c[k - 1].m);
            pt_rv_model_empty(&c[k].m);
        }
        if (setup(r, &c[k]) != 0) return -1;
        if (!c[k].live) continue;
        for (j = 0; j < nst; j++)
            if (do_step(r, sts[j], &c[k]) != 0) return -1;
        mark(r, PT_CMK_MODEL_END, &c[k].pos);
        mark(r, PT_CMK_POSITION_END, &c[k].pos);
    }
    return 0;
}

/* Pipeline2.render: each step over every position. */
static int pipeline2(const run *r, cpos *c, size_t nc, const step *sts, size_t nst)
{
    pt_course_pos phase;
    size_t k, j;

    memset(&phase, 0, sizeof phase);
    for (j = 0; j < nst; j++) {
        phase.phase = (int)j + 1;
        mark(r, PT_CMK_PHASE, &phase);
        for (k = 0; k < nc; k++) {
            c[k].pos.phase = (int)j + 1;
            if (j == 0) {
                if (setup(r, &c[k]) != 0) return -1;
                if (c[k].live && do_step(r, sts[j], &c[k]) != 0) return -1;
                if (c[k].live) {
                    mark(r, PT_CMK_MODEL_END, &c[k].pos);
                    mark(r, PT_CMK_POSITION_END, &c[k].pos);
                }
                continue;
            }
            if (!c[k].live) continue;
            mark(r, PT_CMK_STEP, &c[k].pos);
            if (do_step(r, sts[j], &c[k]) != 0) return -1;
            mark(r, PT_CMK_STEP_END, &c[k].pos);
        }
        mark(r, PT_CMK_PHASE_END, &phase);
    }
    return 0;
}

int pt_course_render(const pt_scene *s, pt_fb *fb, const pt_course_ls *ls)
{
    pt_rv_gamma_lut lut;
    run r;
    pieces pc;
    cpos *c;
    size_t k, nst;
    const step *sts;
    int rc;

    start(&r, s, fb, ls);
    memset(&pc, 0, sizeof pc);
    if (ls && ls->piece) {
        pc.taken = ls->piece(ls->ud, 0, 0);
        r.pc = &pc;
    }
    if (s->gamma) {                              /* gamma's bytes by table where */
        pt_rv_gamma_lut_init(&lut);              /*   nobody reads its floats */
        r.par.lut = &lut;
    }
    clear_fb(s, fb, &r.par, raster_ls(&r));

    c = calloc(s->nmodels ? s->nmodels : 1, sizeof *c);
    if (!c) return -1;
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *sm = &s->models[k];
        c[k].pos.sm = sm;
        c[k].pos.index = k;
        c[k].pos.pos_name = sm->position ? sm->position : sm->name;
        c[k].pos.translate = sm->translate;
        c[k].pos.matrix = pt_r9_position_matrix(sm->ops, sm->nops);
    }
    sts = s->renderer == 9 ? steps9 : steps7;
    nst = s->renderer == 9 ? sizeof steps9 / sizeof *steps9 : sizeof steps7 / sizeof *steps7;
    mark(&r, PT_CMK_BEGIN, NULL);
    rc = s->renderer == 9 && s->pipeline2 ? pipeline2(&r, c, s->nmodels, sts, nst)
                                          : pipeline1(&r, c, s->nmodels, sts, nst);
    if (rc == 0) mark(&r, PT_CMK_END, NULL);
    if (rc == 0 && r.pc) ls->piece(ls->ud, pc.n + 1, 1);
    for (k = 0; k < s->nmodels; k++) pt_rv_model_free(&c[k].m);
    free(c);
    return rc;
}

/* ===== one step on a model of one's own ===== */

int pt_course_step(const pt_scene *s, const pt_course_pos *pos, int st, pt_rv_model *m,
                   pt_fb *fb, const pt_course_ls *ls)
{
    static const step by_stage[PT_NCST + 1] = {
        [PT_CST_MODEL] = ST_RASTER, [PT_CST_WORLD] = ST_WORLD, [PT_CST_VIEW] = ST_VIEW,
        [PT_CST_CAMERA] = ST_CAMERA, [PT_CST_NEARCLIP] = ST_NEARCLIP,
        [PT_CST_IMAGE] = ST_IMAGE, [PT_CST_CLIP] = ST_CLIP, [PT_CST_RASTER] = ST_RASTER};
    run r;
    cpos c;
    int rc;

    if (st <= PT_CST_MODEL || st > PT_CST_RASTER) return -1;
    start(&r, s, fb, ls);
    memset(&c, 0, sizeof c);
    c.pos = *pos;
    c.m = *m;
    c.live = 1;
    rc = do_step(&r, by_stage[st], &c);
    *m = c.m;
    return rc;
}
