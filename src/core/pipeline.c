/*
** src/core/pipeline.c -- plan the stages, run every vertex through them, rasterize
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include "core/pipeline.h"
#include "core/raster.h"
#include "stages/ms_clip_segment.h"
#include "stages/pt_classic.h"
#include "stages/pt_matrix.h"
#include "stages/pt_color.h"
#include "stages/s4_pixel2viewport.h"
#include "stages/m7_screen2viewport.h"
#include "stages/s5_viewport2fb.h"
#include "stages/s6_fb2index.h"

void pt_stage_params_of(pt_stage_params *par, const pt_scene *s, const pt_model *m)
{
    par->translate = m->translate;
    par->perspective = s->perspective;
    par->w = s->vp_w;
    par->h = s->vp_h;
    par->x_ul = s->vp_x;
    par->y_ul = s->vp_y;
    par->W = s->fb_w;
    par->H = s->fb_h;
}

/* ===== the pipelines (core/pipelines.h) ===== */

static void classic_in(pt_pipe_in *in, const pt_scene *s, const pt_plan *p, size_t k)
{
    (void)p;
    pt_stage_params_of(&in->par, s, &s->models[k]);
    in->mx.world = in->mx.view = in->mx.proj = NULL;
}

static void classic_vertex(const pt_pipe_in *in, pt_vec3 v_m,
                           const pt_sink *const sinks[PT_NSTAGES_ALL], pt_vtx *out)
{
    double z_c;

    out->pp = pt_classic_journey(&in->par, v_m, sinks, &z_c);
    out->behind = in->par.perspective && z_c > 0;
    out->code = 0;
    out->norder = PT_CLASSIC_NORDER;
}

/* The matrix camera's View and Projection, and each model's World: its
** `world` lines, then its translate.  The parser has already checked that the
** camera can be built. */
static void matrix_plan(pt_plan *p, const pt_scene *s, int raw_lookat)
{
    size_t k;
    int skewed = 0;

    pt_lookat(&p->view, s->eye, s->dir, s->up, raw_lookat, &skewed);
    pt_perspective(&p->proj, s->fov, s->aspect, s->znear, s->zfar);
    p->up_skewed = skewed;
    p->up_adjusted = skewed && !raw_lookat;
    for (k = 0; k < s->nmodels; k++) {
        p->models[k].world = pt_matrix_world(&s->models[k].world, s->models[k].translate);
    }
}

static void matrix_in(pt_pipe_in *in, const pt_scene *s, const pt_plan *p, size_t k)
{
    pt_stage_params_of(&in->par, s, &s->models[k]);
    pt_matrices_of(&in->mx, p, k);
}

static void matrix_vertex(const pt_pipe_in *in, pt_vec3 v_m,
                          const pt_sink *const sinks[PT_NSTAGES_ALL], pt_vtx *out)
{
    out->pp = pt_matrix_journey(&in->par, &in->mx, v_m, sinks, &out->h, &out->code);
    out->behind = out->h.w < 0;
    out->norder = pt_pipeline_norder(&pt_pipe_matrix, out->code);
}

/* A point clipping made lies in the view volume: its journey starts with its
** clip coordinates, at the clip and cvv stages (outcode 0: on a plane at
** most). */
static int matrix_seed(const pt_made *mp, pt_vrec rec[2])
{
    memset(rec, 0, 2 * sizeof *rec);
    rec[0].stage = PT_STAGE_CLIP;
    rec[0].x = mp->q.x; rec[0].y = mp->q.y; rec[0].z = mp->q.z; rec[0].w = mp->q.w;
    rec[1] = rec[0];
    rec[1].stage = PT_STAGE_CVV;
    return 2;
}

static void matrix_made(const pt_pipe_in *in, const pt_made *mp,
                        const pt_sink *const sinks[PT_NSTAGES_ALL], pt_vtx *out)
{
    out->pp = pt_matrix_tail(&in->par, mp->q, fabs(mp->q.w), sinks);
    out->h = mp->q;
    out->code = 0;
    out->behind = 0;
    out->norder = PT_MATRIX_NORDER;
}

static const pt_segstage matrix_segstages[] = {
    { PT_STAGE_CVV, "clip the segment to the canonical view volume, in clip space",
      "outside the view volume", pt_clip_cut },
};

const pt_pipeline pt_pipe_classic = {
    PT_PIPE_CLASSIC, "classic", "classic camera", NULL, pt_classic_order, PT_CLASSIC_NORDER,
    PT_STAGE_INDEX, &pt_stage_infos[PT_STAGE_VIEWPORT], 0,
    1u << PT_STAGE_CAMERA | 1u << PT_STAGE_IMAGE | 1u << PT_STAGE_PIXEL |
    1u << PT_STAGE_VIEWPORT | 1u << PT_STAGE_FRAMEBUFFER | 1u << PT_STAGE_INDEX,
    NULL, classic_in, classic_vertex, NULL, 0, NULL, NULL,
    pt_pixel2viewport, 1,
};

const pt_pipeline pt_pipe_matrix = {
    PT_PIPE_MATRIX, "matrix", "matrix camera", "lookat", pt_matrix_order, PT_MATRIX_NORDER,
    PT_STAGE_CVV, &pt_matrix_viewport_info, 1,
    1u << PT_STAGE_FRAMEBUFFER | 1u << PT_STAGE_INDEX,   /* the stages it shares */
    matrix_plan, matrix_in, matrix_vertex,
    matrix_segstages, (int)(sizeof matrix_segstages / sizeof matrix_segstages[0]),
    matrix_seed, matrix_made,
    pt_pixelplane2viewport, 0,
};

const pt_pipeline *const pt_pipelines[PT_NPIPES] = { &pt_pipe_classic, &pt_pipe_matrix };

const pt_pipeline *pt_scene_pipeline(const pt_scene *s)
{
    return pt_pipelines[s->pipe];
}

const char *pt_scene_camera_title(const pt_scene *s, char *buf, size_t len)
{
    const pt_pipeline *pl = pt_scene_pipeline(s);

    if (!pl->camera) snprintf(buf, len, "%s", pt_scene_camera_word(s));
    else snprintf(buf, len, "%s (%s)", pl->camera, pl->title);
    return buf;
}

const char *pt_camera_word(const pt_pipeline *pl, int perspective)
{
    return pl->camera ? pl->camera : perspective ? "perspective" : "orthographic";
}

const char *pt_scene_camera_word(const pt_scene *s)
{
    return pt_camera_word(pt_scene_pipeline(s), s->perspective);
}

const pt_pipeline *pt_pipeline_by_camera(const char *word)
{
    int k;

    for (k = 0; k < PT_NPIPES; k++)
        if (pt_pipelines[k]->camera && strcmp(pt_pipelines[k]->camera, word) == 0)
            return pt_pipelines[k];
    return strcmp(word, "perspective") == 0 || strcmp(word, "orthographic") == 0
           ? &pt_pipe_classic : NULL;
}

const pt_pipeline *pt_pipeline_by_name(const char *name)
{
    int k;

    for (k = 0; k < PT_NPIPES; k++)
        if (strcmp(pt_pipelines[k]->name, name) == 0) return pt_pipelines[k];
    return NULL;
}

void pt_options_default(pt_options *o)
{
    memset(o, 0, sizeof *o);
    o->stage_mask = (1u << PT_NSTAGES_ALL) - 1;
    o->trace_raster = 1;
    o->rasterize = 1;
    o->piece_vertices = PT_PIECE_VERTICES;
    o->piece_segments = PT_PIECE_SEGMENTS;
    o->piece_pixels = PT_PIECE_PIXELS;
}

/* ===== plan ===== */

/* 1 when adding t changes no value: every component is zero.  (x + 0.0 still
** turns -0.0 into +0.0; the stage is computed anyway, only its record goes.) */
static int is_zero(pt_vec3 t)
{
    return t.x == 0 && t.y == 0 && t.z == 0;
}

static int is_identity(const pt_mat4 *a)
{
    pt_mat4 id = pt_mat4_identity();
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            if (a->m[i][j] != id.m[i][j]) return 0;
    return 1;
}

/* Why stage st is the identity for model k under plan p, or NULL. */
static const char *identity_why(const pt_scene *s, const pt_plan *p, size_t k, int st)
{
    if (st == PT_STAGE_CAMERA && is_zero(s->models[k].translate))
        return "identity: translation 0 0 0";
    if (st == PT_STAGE_WORLD && is_identity(&p->models[k].world))
        return "identity: world matrix";
    if (st == PT_STAGE_VIEW && is_identity(&p->view))
        return "identity: view matrix";
    if (st == PT_STAGE_FRAMEBUFFER && s->vp_x == 0 && s->vp_y == 0)
        return "identity: viewport at 0,0";
    return NULL;
}

void pt_matrices_of(pt_matrices *mx, const pt_plan *p, size_t k)
{
    mx->world = &p->models[k].world;
    mx->view = &p->view;
    mx->proj = &p->proj;
}

int pt_plan_make(pt_plan *p, const pt_scene *s, const pt_options *o)
{
    size_t k, j;
    int st, i;

    memset(p, 0, sizeof *p);
    p->nmodels = s->nmodels;
    p->models = calloc(s->nmodels ? s->nmodels : 1, sizeof *p->models);
    if (!p->models) return -1;
    p->pipe = pt_scene_pipeline(s);
    p->order = p->pipe->order;
    p->norder = p->pipe->norder;
    if (p->pipe->plan) p->pipe->plan(p, s, o->raw_lookat);
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        pt_model_plan *mp = &p->models[k];

        mp->selected = !o->model || strcmp(o->model, m->name) == 0;
        mp->hidden = p->pipe == &pt_pipe_classic && (m->hidden_position || m->hidden_model);
        mp->used = calloc(m->nv ? m->nv : 1, 1);
        if (!mp->used) { pt_plan_free(p); return -1; }
        for (j = 0; j < m->nseg; j++) {
            mp->used[m->seg[j].a] = 1;
            mp->used[m->seg[j].b] = 1;
        }
        for (j = 0; j < m->npts; j++) mp->used[m->pts[j].v] = 1;   /* the course's points */
        for (j = 0; j < m->nv; j++) mp->nused += mp->used[j];
        for (st = 0; st < PT_NSTAGES_ALL; st++) mp->why[st] = PT_WHY_OTHER_CAMERA;
        for (i = 0; i < p->norder; i++) {
            const char *why;
            st = p->order[i];
            mp->why[st] = PT_WHY_TRACED;
            mp->why_text[st] = NULL;
            if (!(o->stage_mask & (1u << st))) {
                mp->why[st] = PT_WHY_FILTER;
                mp->why_text[st] = "not chosen by --stage";
            } else if (!o->all_stages && (why = identity_why(s, p, k, st)) != NULL) {
                mp->why[st] = PT_WHY_IDENTITY;
                mp->why_text[st] = why;
            }
        }
    }
    return 0;
}

void pt_plan_free(pt_plan *p)
{
    size_t k;

    for (k = 0; k < p->nmodels; k++) free(p->models[k].used);
    free(p->models);
    p->models = NULL;
    p->nmodels = 0;
}

/* ===== run the stages ===== */

/* The sinks of a vertex that reports to nobody and is counted by nobody. */
static const pt_sink *const no_sinks[PT_NSTAGES_ALL];

/* A sink in front of the listener's: counts warnings, forwards when traced. */
typedef struct counting_sink {
    pt_summary *sum;
    const pt_sink *next;         /* NULL: the stage is not traced */
} counting_sink;

static void count_warnings(pt_summary *sum, const pt_vrec *r)
{
    int k;

    if (!r->warn) return;                   /* the usual record */
    for (k = 0; k < PT_NWARN; k++)
        if (r->warn & (1u << k)) sum->warnings[k]++;
}

static void count_record(void *ud, const pt_vrec *r)
{
    counting_sink *cs = ud;

    count_warnings(cs->sum, r);
    if (cs->next) cs->next->vertex(cs->next->ud, r);
}

/* The sinks of one model: traced[st] for a traced vertex, quiet[st] (counts
** only) for the others.  All NULL when nobody listens (no sink, no summary):
** then the stages build no record and no warning is counted. */
typedef struct model_sinks {
    counting_sink counters[2];   /* [0]: count only, [1]: count and forward */
    pt_sink sink_of[2];
    const pt_sink *traced[PT_NSTAGES_ALL], *quiet[PT_NSTAGES_ALL];
} model_sinks;

static void sinks_init(model_sinks *ms, const pt_model_plan *mp, const pt_listener *l,
                       pt_summary *sum)
{
    int st;

    ms->counters[0].sum = ms->counters[1].sum = sum;
    ms->counters[0].next = NULL;
    ms->counters[1].next = l->sink.vertex ? &l->sink : NULL;
    ms->sink_of[0].vertex = ms->sink_of[1].vertex = count_record;
    ms->sink_of[0].ud = &ms->counters[0];
    ms->sink_of[1].ud = &ms->counters[1];
    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        int listens = l->sink.vertex || l->summary;
        ms->traced[st] = listens ? &ms->sink_of[mp->why[st] == PT_WHY_TRACED] : NULL;
        ms->quiet[st] = listens ? &ms->sink_of[0] : NULL;
    }
}

/* A traced point's journey while its stages run, for a listener with a
** journey callback: every stage reports to filing's sink, which counts the
** warnings (as count_record) and files the record; then the listener gets
** the whole journey, then the records of the traced stages in the order they
** came, as the sinks of model_sinks would have forwarded them. */
typedef struct filing {
    pt_journey j;                /* the records, filed by stage */
    pt_summary *sum;
    pt_stage came[PT_NSTAGES_ALL];  /* the stages, in the order they reported */
    int ncame;
    pt_sink sink;                /* file_record, this */
    const pt_sink *sinks[PT_NSTAGES_ALL];   /* all &sink */
} filing;

static void file_record(void *ud, const pt_vrec *r)
{
    filing *f = ud;

    count_warnings(f->sum, r);
    pt_journey_file(&f->j, r);
    if (f->ncame < PT_NSTAGES_ALL) f->came[f->ncame++] = r->stage;
}

/* Start filing the journey of a point of model k. */
static void filing_start(filing *f, const pt_scene *s, const pt_plan *p, size_t k,
                         pt_summary *sum)
{
    pt_pipe_in in;
    int st;

    p->pipe->model_in(&in, s, p, k);
    pt_journey_start(&f->j, p->pipe, &in);
    f->sum = sum;
    f->ncame = 0;
    f->sink.vertex = file_record;
    f->sink.ud = f;
    for (st = 0; st < PT_NSTAGES_ALL; st++) f->sinks[st] = &f->sink;
}

/* Hand the journey over (v: 1-based vertex, 0: a point clipping made), then
** the records of the stages model plan mp traces. */
static void filing_end(filing *f, const pt_listener *l, const pt_model *m, uint64_t v,
                       const pt_model_plan *mp)
{
    int i;

    l->journey(l->ud, m, v, &f->j);
    if (!l->sink.vertex) return;
    for (i = 0; i < f->ncame; i++)
        if (mp->why[f->came[i]] == PT_WHY_TRACED)
            l->sink.vertex(l->sink.ud, &f->j.rec[f->came[i]]);
}

/* What the rasterizer needs of a vertex: its pixel-plane point (pt_vec2,
** for every pipeline) and, for a pipeline with segment stages only, this.
** Kept apart so that the classic camera keeps 16 bytes a vertex, not 56
** (peak memory). */
typedef struct vtx_clip {
    pt_vec4 clip;                /* the coordinates segment stages cut in */
    unsigned code;               /* the runner's code (matrix: CVV outcode) */
} vtx_clip;

/* The pieces of the trace (pt_listener.piece): the one records go to now,
** and how much is in it so far.  Without l->piece, one piece, always taken. */
typedef struct pieces {
    const pt_listener *l;
    uint64_t max_vertices, max_segments, max_pixels;    /* pt_options.piece_* */
    uint64_t n;                  /* the piece the records go to */
    uint64_t vertices, segments, pixels;    /* in it so far */
    int segment_cuts;            /* 1: segments are cut (their records come here) */
    int taken;                   /* 1: its records come to l */
} pieces;

static void pieces_start(pieces *pc, const pt_scene *s, const pt_options *o,
                         const pt_listener *l)
{
    memset(pc, 0, sizeof *pc);
    pc->l = l;
    pc->max_vertices = o->piece_vertices ? o->piece_vertices : 1;
    pc->max_segments = o->piece_segments ? o->piece_segments : 1;
    pc->max_pixels = o->piece_pixels ? o->piece_pixels : 1;
    pc->segment_cuts = l->pixels || l->point_pixels || l->clip || l->skip || l->setup ||
                       l->step ||
                       pt_scene_pipeline(s)->nsegstages > 0;
    pc->taken = l->piece ? l->piece(l->ud, 0, 0) : 1;
}

/* Begin the next piece; the last is the summary's. */
static void piece_next(pieces *pc, int last)
{
    pc->n++;
    pc->vertices = pc->segments = pc->pixels = 0;
    pc->taken = pc->l->piece(pc->l->ud, pc->n, last);
}

/* Count in the next vertex; returns 1 when its piece is taken. */
static int piece_vertex(pieces *pc)
{
    if (!pc->l->piece) return 1;
    if (pc->vertices >= pc->max_vertices) piece_next(pc, 0);
    pc->vertices++;
    return pc->taken;
}

/* The same for the next segment, a to b in the pixel plane of scene s. */
static int piece_segment(pieces *pc, const pt_scene *s, pt_vec2 a, pt_vec2 b)
{
    double steps, most;

    if (!pc->l->piece || !pc->segment_cuts) return 1;
    steps = fmax(fabs(b.x - a.x), fabs(b.y - a.y));
    most = (double)s->vp_w + s->vp_h;
    if (pc->segments >= pc->max_segments || pc->pixels >= pc->max_pixels)
        piece_next(pc, 0);
    pc->segments++;
    pc->pixels += 1 + (uint64_t)(steps < most ? steps : most);  /* NaN: most */
    return pc->taken;
}

/* Run every vertex of model k that needs it; fill pp[] (and cl[] when not
** NULL) for the rasterizer.  fl: room for a journey (used when the listener
** wants journeys).  The vertices of pieces not taken are counted into the
** summary when there is one, else they run with no record. */
static void run_model(const pt_scene *s, const pt_plan *p, const pt_options *o,
                      const pt_listener *l, size_t k, const model_sinks *ms,
                      pt_vec2 *pp, vtx_clip *cl, filing *fl, pt_summary *sum,
                      pieces *pc)
{
    const pt_model *m = &s->models[k];
    const pt_model_plan *mp = &p->models[k];
    pt_pipe_in in;
    size_t j;

    p->pipe->model_in(&in, s, p, k);
    for (j = 0; j < m->nv; j++) {
        int traced = mp->selected && (!o->vertex || o->vertex == j + 1);
        int taken = piece_vertex(pc), report = taken && traced;
        const pt_sink *const *sinks = report ? ms->traced
                                    : taken || l->summary ? ms->quiet : no_sinks;
        filing *f = report && l->journey ? fl : NULL;
        pt_vtx out;

        if (mp->hidden) continue;           /* the course runs none of it */
        if (!traced && !o->rasterize) continue;
        if (!mp->used[j] && !(traced && o->every_vertex)) continue;
        if (report && l->vertex_begin) l->vertex_begin(l->ud, m, j + 1);
        if (f) {
            filing_start(f, s, p, k, sum);
            sinks = f->sinks;
        }
        p->pipe->run_vertex(&in, m->v[j], sinks, &out);
        if (f) {
            /* from the runner, not from the records that came: a student's
            ** stage that does not report must not shorten the journey */
            f->j.norder = out.norder;
            filing_end(f, l, m, j + 1, mp);
        }
        if (traced) {
            sum->vertices_traced++;
            sum->behind += out.behind;
        }
        if (o->rasterize) pp[j] = out.pp;
        if (o->rasterize && cl) { cl[j].clip = out.h; cl[j].code = out.code; }
    }
}

/* ===== rasterize ===== */

/* What the raster callbacks need to turn viewport pixels into records. */
typedef struct raster_ctx {
    const pt_scene *s;
    const pt_model *m;
    uint64_t seg;                /* 1-based segment number */
    const pt_listener *l;        /* NULL: nothing to report */
    pt_fb *fb;                   /* NULL: nothing to draw */
    int64_t npix;                /* W * H: the pixel array's length */
    pt_summary *sum;
    int x_ul, y_ul, W, H;        /* the scene's, at hand for every pixel */
    int wrap;                    /* 1: the viewport sticks out of the
                                 ** framebuffer (pt_raster_fb_pixel) */
} raster_ctx;

/* A pixel of the classic camera's segments walked step by step
** (pt_raster_walk), in the course's colour of its step.  A student's
** framebuffer or index stage may name no pixel of the array, nor may the
** course's index of a viewport that sticks out (pt_raster_fb_pixel): the
** trace shows it, the image is left alone. */
static void on_paint(void *ud, int64_t x_vp, int64_t y_vp, const pt_fb_paint *pa)
{
    raster_ctx *rc = ud;
    pt_fb_pixel px;
    int64_t idx = pt_raster_fb_pixel(x_vp, y_vp, rc->x_ul, rc->y_ul, rc->W, rc->H, rc->wrap,
                                     &px);

    rc->sum->pixels++;
    if (rc->l && rc->l->pixels) {
        px.paint = *pa;
        rc->l->pixels(rc->l->ud, rc->m, rc->seg, &px, 1);
    }
    if (rc->fb && idx >= 0 && idx < rc->npix) pt_fb_set(rc->fb, idx, pa->rgb);
}

/* A pixel of the matrix camera's segments (pt_raster_segment): the model's
** one colour, all of the pixel; the classic camera's are drawn by
** pt_raster_draw(), its stages inlined. */
static void on_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    const raster_ctx *rc = ud;
    pt_fb_paint pa;

    memcpy(pa.rgb, rc->m->color, sizeof pa.rgb);
    pa.coverage = 1.0f;
    on_paint(ud, x_vp, y_vp, &pa);
}

static void on_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    raster_ctx *rc = ud;

    rc->sum->clipped += count;
    if (rc->sum->clipped < count) rc->sum->clipped_hi++;    /* carried past 2^64 */
    rc->sum->clip_runs++;
    if (rc->l && rc->l->clip) rc->l->clip(rc->l->ud, rc->m, rc->seg, count, first, last);
}

/* Say which endpoint of a skipped segment has no pixel, and why. */
static void skip_report(const pt_listener *l, const pt_model *m, uint64_t seg,
                        pt_vec2 a, pt_vec2 b)
{
    const pt_segment *sg = &m->seg[seg - 1];
    int a_bad = !(fabs(a.x) < PT_PIX_LIMIT && fabs(a.y) < PT_PIX_LIMIT);
    pt_vec2 p = a_bad ? a : b;
    const char *why = isfinite(p.x) && isfinite(p.y)
        ? "endpoint beyond 2^62 in the pixel plane: no integer pixel"
        : "endpoint not finite in the pixel plane";

    l->skip(l->ud, m, seg, (a_bad ? sg->a : sg->b) + 1, why);
}

/* A number of the pixel plane as a note shows it: nan, inf, -inf, or %.17g. */
static void note_num(char *buf, size_t len, double x)
{
    if (x != x) snprintf(buf, len, "nan");
    else if (isinf(x)) snprintf(buf, len, x > 0 ? "inf" : "-inf");
    else snprintf(buf, len, "%.17g", x);
}

/* Java's Math.round(x), a long, in buf. */
static void note_round(char *buf, size_t len, double x)
{
    double r = pt_raster_java_round(x);

    if (r >= 0x1p63) snprintf(buf, len, "9223372036854775807");   /* Long.MAX_VALUE */
    else snprintf(buf, len, "%lld", (long long)r);
}

/* Tell l what the course's renderer 4 does with segment seg of model m
** (ends a, b in the pixel plane) that its ends do not say: an end without an
** integer pixel (NaN, or beyond PT_PIX_LIMIT) rounded as Java rounds it, a
** loop that would not end (core/raster.h). */
static void course_notes(const pt_listener *l, const pt_model *m, uint64_t seg,
                         pt_vec2 a, pt_vec2 b)
{
    const pt_segment *sg = &m->seg[seg - 1];
    char what[256], x[32], y[32], rx[24], ry[24];
    int e;

    for (e = 0; e < 2; e++) {
        pt_vec2 p = e ? b : a;
        if (fabs(p.x) < PT_PIX_LIMIT && fabs(p.y) < PT_PIX_LIMIT) continue;
        note_num(x, sizeof x, p.x); note_num(y, sizeof y, p.y);
        note_round(rx, sizeof rx, p.x); note_round(ry, sizeof ry, p.y);
        snprintf(what, sizeof what, "endpoint (x_pp, y_pp) = (%s, %s) has no integer pixel; "
                 "the course's Math.round makes it (%s, %s) (NaN 0, beyond a long saturated) "
                 "and draws on", x, y, rx, ry);
        l->note(l->ud, m, seg, (e ? sg->b : sg->a) + 1, what);
    }
    if (pt_raster_endless(a, b))
        l->note(l->ud, m, seg, 0, "the course's loop never ends: its last step is the "
                "largest int, 2147483647, and its int step wraps; pipetrace stops after that step");
}

/* Run point mp, which a segment stage made on segment seg of model k, on
** through the rest of the pipeline (traced when l is not NULL); returns its
** pixel-plane point. */
static pt_vec2 made_point(const pt_scene *s, const pt_plan *p, size_t k, const pt_made *mp,
                          const pt_listener *l, const model_sinks *ms, filing *fl,
                          pt_summary *sum)
{
    const pt_model *m = &s->models[k];
    pt_pipe_in in;
    pt_vrec seed[2];
    pt_vtx out;
    int i, n;

    if (l && l->clipvertex_begin)
        l->clipvertex_begin(l->ud, m, mp->seg, mp->from, mp->to, mp->t, mp->q);
    p->pipe->model_in(&in, s, p, k);
    if (!l || !l->journey) {
        p->pipe->run_made(&in, mp, l ? ms->traced : ms->quiet, &out);
        return out.pp;
    }
    filing_start(fl, s, p, k, sum);
    n = p->pipe->seed(mp, seed);            /* where its journey starts */
    for (i = 0; i < n; i++) pt_journey_file(&fl->j, &seed[i]);
    p->pipe->run_made(&in, mp, fl->sinks, &out);
    fl->j.norder = out.norder;
    filing_end(fl, l, m, 0, &p->models[k]);
    return out.pp;
}

/* Put segment seg of model k, whose ends' runners gave va and vb, through
** the pipeline's segment stages; the points they make run the rest of the
** pipeline (traced when l is not NULL).  Returns NULL when something of it
** goes on to the rasterizer, with *a, *b the pixel-plane points to draw
** between; else why it does not. */
static const char *cut_segment(const pt_scene *s, const pt_plan *p, size_t k, uint64_t seg,
                               const vtx_clip *va, const vtx_clip *vb, const pt_listener *l,
                               const model_sinks *ms, filing *fl, pt_summary *sum,
                               pt_vec2 *a, pt_vec2 *b)
{
    const pt_model *m = &s->models[k];
    const pt_segment *sg = &m->seg[seg - 1];
    pt_segend end[2];
    pt_vec2 pp[2];
    int i, e;

    pp[0] = *a;
    pp[1] = *b;
    end[0].h = va->clip; end[0].code = va->code;
    end[1].h = vb->clip; end[1].code = vb->code;
    for (e = 0; e < 2; e++) {               /* a model's one colour, as floats */
        end[e].color.r = m->color[0] / 255.0f;
        end[e].color.g = m->color[1] / 255.0f;
        end[e].color.b = m->color[2] / 255.0f;
    }
    for (i = 0; i < p->pipe->nsegstages; i++) {
        const pt_segstage *ss = &p->pipe->segstages[i];
        pt_made made[2];
        int moved[2] = {0, 0};

        switch (ss->cut(&end[0], &end[1], made, moved)) {
        case PT_CUT_DROP:
            return ss->dropped;
        case PT_CUT_KEEP:
            break;
        case PT_CUT_NEW:
            for (e = 0; e < 2; e++) {
                if (!moved[e]) continue;
                made[e].seg = seg;
                made[e].from = sg->a + 1;
                made[e].to = sg->b + 1;
                pp[e] = made_point(s, p, k, &made[e], l, ms, fl, sum);
                end[e].h = made[e].q;
                end[e].code = 0;
                end[e].color = made[e].color;
            }
            break;
        }
    }
    *a = pp[0];
    *b = pp[1];
    return NULL;
}

/* What drawing needs, the same for every model: the raster callbacks and
** their context, and the image the untraced classic render draws into. */
typedef struct drawing {
    pt_raster_out out;           /* on_pixel, on_clip, &rc */
    pt_raster_vp to_vp;          /* the camera's viewport stage */
    raster_ctx rc;
    pt_raster_image im;          /* the classic camera's image and pixel listener */
    pt_raster_steps ls;          /* the listener's setup and step, with rc */
    pt_raster_steps quiet;       /* no setup or step: the colours alone */
} drawing;

/* The DDA's records, to the listener (pt_raster_walk). */
static void on_setup(void *ud, const pt_raster_setup *su)
{
    raster_ctx *rc = ud;

    if (rc->l->setup) rc->l->setup(rc->l->ud, rc->m, rc->seg, su);
}

static void on_step(void *ud, const pt_raster_step *st)
{
    raster_ctx *rc = ud;

    if (rc->l->step) rc->l->step(rc->l->ud, rc->m, rc->seg, st);
}

/* The classic camera's pixels, to the listener (pt_raster_draw). */
static void on_drawn(void *ud, const pt_fb_pixel *px, size_t n)
{
    raster_ctx *rc = ud;

    rc->l->pixels(rc->l->ud, rc->m, rc->seg, px, n);
}

static void drawing_start(drawing *d, const pt_scene *s, pt_fb *fb, pt_summary *sum)
{
    d->out.pixel = on_pixel;
    d->out.clip = on_clip;
    d->out.ud = &d->rc;
    d->to_vp = pt_scene_pipeline(s)->to_viewport;
    d->rc.s = s; d->rc.fb = fb; d->rc.sum = sum;
    d->rc.npix = (int64_t)s->fb_w * s->fb_h;
    d->rc.x_ul = s->vp_x; d->rc.y_ul = s->vp_y; d->rc.W = s->fb_w; d->rc.H = s->fb_h;
    d->rc.wrap = !pt_scene_vp_inside(s);
    d->im.fb = fb; d->im.W = s->fb_w; d->im.H = s->fb_h;
    d->im.x_ul = s->vp_x; d->im.y_ul = s->vp_y; d->im.pixels = 0;
    d->im.wrap = d->rc.wrap;
    d->im.pixel_ud = &d->rc;
    d->ls.setup = on_setup;
    d->ls.step = on_step;
    d->ls.ud = &d->rc;
    d->ls.paint = pt_scene_pipeline(s) == &pt_pipe_classic ? on_paint : NULL;
    if (fb && d->ls.paint && memcmp(s->vp_background, s->background, 3) != 0)
        pt_fb_fill(fb, s->vp_x, s->vp_y, s->vp_w, s->vp_h, s->vp_background);   /* clearVP */
    memset(&d->quiet, 0, sizeof d->quiet);
    d->quiet.paint = d->ls.paint;
    d->quiet.ud = &d->rc;
    sum->rasterized = 1;
}

float pt_model_color(const pt_model *m, uint32_t ci, int i)
{
    if (m->ncolors) {
        const pt_rgb *c = &m->colors[ci < m->ncolors ? ci : m->ncolors - 1];
        return i == 0 ? c->r : i == 1 ? c->g : c->b;
    }
    return pt_color_float(m->color[i]);
}

/* A pixel of a point (the course's Rasterize_Clip_Point), inside the
** viewport: through the framebuffer and index stages into the image, and to
** the listener's point_pixels, a run at a time (not in the summary's count;
** the course's log shows them too: src/io/trace_kraft.c). */
typedef struct dot_ctx {
    raster_ctx *rc;
    unsigned char rgb[3];        /* the point's colour, gamma-encoded */
    const pt_listener *l;        /* told of the pixels, or NULL */
    uint64_t pt;                 /* the point, 1-based */
    size_t n;                    /* pixels in px[] */
    pt_fb_pixel px[PT_RASTER_RUN];
} dot_ctx;

static void dots_tell(dot_ctx *dc)
{
    if (dc->n) dc->l->point_pixels(dc->l->ud, dc->rc->m, dc->pt, dc->px, dc->n);
    dc->n = 0;
}

static void on_dot(void *ud, const pt_raster_dot *dt)
{
    dot_ctx *dc = ud;
    raster_ctx *rc = dc->rc;
    pt_fb_pixel at;
    int64_t idx = pt_raster_fb_pixel(dt->vp.x, dt->vp.y, rc->x_ul, rc->y_ul, rc->W, rc->H,
                                     rc->wrap, &at);

    if (dc->l) {
        pt_fb_pixel *q = &dc->px[dc->n];
        *q = at;
        memcpy(q->paint.rgb, dc->rgb, sizeof q->paint.rgb);
        q->paint.coverage = 1.0f;
        if (++dc->n == PT_RASTER_RUN) dots_tell(dc);
    }
    if (rc->fb && idx >= 0 && idx < rc->npix) pt_fb_set(rc->fb, idx, dc->rgb);
}

/* Draw the points of model m from *next on whose `after` is at most upto
** (the segments drawn so far), in file order, into the image and to l's
** point_pixels (l NULL: nobody listens): the course's renderer 4 (classic
** camera) only. */
static void draw_points(drawing *d, const pt_scene *s, const pt_model *m,
                        const pt_vec2 *pp, size_t *next, size_t upto, const pt_listener *l)
{
    for (; *next < m->npts && m->pts[*next].after <= upto; (*next)++) {
        const pt_point *pt = &m->pts[*next];
        pt_raster_dot dt;
        dot_ctx dc;
        int i;

        if (!d->rc.fb && !l) continue;
        dc.rc = &d->rc;
        dc.l = l;
        dc.pt = *next + 1;
        dc.n = 0;
        for (i = 0; i < 3; i++) {               /* gamma first (NOTES.md 11.3) */
            float c = pt_model_color(m, pt->c, i);
            dc.rgb[i] = pt_color_byte(s->gamma ? pt_gamma(c) : c);
        }
        pt_raster_point(pp[pt->v], pt->radius, s->vp_w, s->vp_h, 0, 0, &dt, on_dot, &dc);
        if (l) dots_tell(&dc);
    }
}

/* The colours of segment sg of model m into col: the course's (renderer 4:
** its colour list, gamma, anti-aliasing) for the classic camera, the model's
** one colour as it is for the others. */
static void segment_colors(pt_raster_colors *col, const pt_scene *s, const pt_model *m,
                           const pt_segment *sg, int course)
{
    int i;

    memset(col, 0, sizeof *col);
    col->gamma = course && s->gamma;
    col->aa = course && s->antialias;
    col->java = course;                         /* Java's rounding of the ends */
    for (i = 0; i < 3; i++) {
        col->c0[i] = course ? pt_model_color(m, sg->ca, i) : pt_color_float(m->color[i]);
        col->c1[i] = course ? pt_model_color(m, sg->cb, i) : pt_color_float(m->color[i]);
        col->bg[i] = pt_color_float(s->vp_background[i]);
    }
    pt_raster_colors_prepare(col);
}

/* Draw the segments of model k, whose vertices' pixel-plane points are pp[]
** (and clip coordinates cl[], matrix camera), and, with the classic camera,
** its points among them in file order.  A hidden position or model (the
** course's `visible = false`) draws nothing with the classic camera. */
static void draw_model(drawing *d, const pt_scene *s, const pt_plan *p, const pt_options *o,
                       const pt_listener *l, size_t k, const model_sinks *ms, filing *fl,
                       pt_summary *sum, const pt_vec2 *pp, const vtx_clip *cl,
                       pieces *pc)
{
    const pt_model *m = &s->models[k];
    int selected = p->models[k].selected && !o->vertex;
    int steps = (l->setup || l->step) && selected && o->trace_raster;   /* DDA records */
    int inlined = p->pipe->inlined_dda && !steps;   /* pt_raster_draw() may draw */
    int course = p->pipe == &pt_pipe_classic;       /* the course's renderer 4 */
    int points = selected && o->trace_raster && l->point_pixels;   /* their records */
    size_t j, next = 0;

    if (p->models[k].hidden) return;
    d->rc.m = m;
    for (j = 0; j < m->nseg; j++) {
        pt_vec2 a = pp[m->seg[j].a], b = pp[m->seg[j].b];
        int taken = piece_segment(pc, s, a, b);
        int traced = taken && selected;                 /* its clip vertices */
        int report = traced && o->trace_raster;         /* its raster records */
        const char *dropped;
        int draw, r;

        if (course) draw_points(d, s, m, pp, &next, j, points && taken ? l : NULL);
        if (j == 0 || m->ncolors) {                 /* no list: one colour, once */
            segment_colors(&d->im.col, s, m, &m->seg[j], course);
            d->ls.col = d->quiet.col = d->im.col;
        }
        if (!taken && !d->im.fb && !l->summary) continue;   /* nothing to do */
        d->rc.seg = j + 1;
        d->rc.l = report ? l : NULL;
        d->im.pixel = report && l->pixels ? on_drawn : NULL;
        draw = inlined && (d->im.fb || d->im.pixel);
        if (p->pipe->nsegstages &&
            (dropped = cut_segment(s, p, k, j + 1, &cl[m->seg[j].a], &cl[m->seg[j].b],
                                   traced ? l : NULL, ms, fl, sum, &a, &b)) != NULL) {
            sum->segments_culled++;
            if (report && l->skip) l->skip(l->ud, m, j + 1, 0, dropped);
            continue;
        }
        if (course && report && l->note) course_notes(l, m, j + 1, a, b);
        if (draw)                           /* the stages inlined in the DDA */
            r = pt_raster_draw(a, b, s->vp_w, s->vp_h, &d->im, &d->out);
        else if (steps && taken) {          /* step by step, each told */
            d->ls.step = l->step ? on_step : NULL;  /* no step listener: the band */
            r = pt_raster_walk(a, b, s->vp_w, s->vp_h, d->to_vp, &d->out, &d->ls);
        } else if (course)                    /* in its colours, nobody told */
            r = pt_raster_walk(a, b, s->vp_w, s->vp_h, d->to_vp, &d->out, &d->quiet);
        else
            r = pt_raster_segment(a, b, s->vp_w, s->vp_h, d->to_vp, &d->out);
        if (r == PT_RASTER_DEGENERATE) sum->segments_degenerate++;
        if (r == PT_RASTER_SKIPPED) {
            sum->segments_skipped++;
            if (report && l->skip) skip_report(l, m, j + 1, a, b);
        }
    }
    if (course)
        draw_points(d, s, m, pp, &next, m->nseg,
                    points && pc->taken ? l : NULL);
}

int pt_run(const pt_scene *s, const pt_plan *p, const pt_options *o,
           const pt_listener *l, pt_fb *fb, pt_summary *sum)
{
    size_t k, n, maxnv = 1;
    pt_vec2 **pps;               /* pps[k][v]: vertex v's pixel-plane point */
    vtx_clip **cls;              /* cls[k][v]: its clip coordinates (matrix) */
    model_sinks *ms;             /* ms[k]: model k's sinks */
    filing fl;                   /* a traced point's journey (l->journey) */
    drawing d;
    pieces pc;
    int status = 0, raster, in_turn;
    int cuts = p->pipe->nsegstages > 0;     /* segment stages: cl[] is kept */

    /* Rasterize for an image, for a listener of pixel, clip, skip, setup, step
    ** or summary records, or for the matrix camera's points clipping makes; else nobody
    ** listens (a CSV trace has no raster rows): skip it.  When nobody listens
    ** to the vertices, or nobody to what drawing reports (a CSV trace with an
    ** image, no segment stages: the matrix camera's clipping makes vertex
    ** records while it draws), each model is drawn right after its vertices
    ** ran ("in turn"), from one buffer the size of the largest model, which
    ** stays in the cache: the records that remain come in the same order as
    ** when every model's vertices run first (the summary comes last). */
    raster = o->rasterize && (fb || l->pixels || l->point_pixels || l->clip || l->skip ||
                              l->setup || l->step ||
                              l->summary || cuts);
    in_turn = raster &&
              (o->model_by_model ||
               (!l->vertex_begin && !l->sink.vertex && !l->clipvertex_begin && !l->journey) ||
               (!cuts && !l->pixels && !l->point_pixels && !l->clip && !l->skip && !l->setup &&
                !l->step));
    memset(sum, 0, sizeof *sum);
    sum->models = s->nmodels;
    n = s->nmodels ? s->nmodels : 1;
    pps = calloc(n, sizeof *pps);
    cls = calloc(n, sizeof *cls);
    ms = malloc(n * sizeof *ms);
    if (!pps || !cls || !ms) { free(pps); free(cls); free(ms); return -1; }
    if (in_turn) {
        for (k = 0; k < s->nmodels; k++) if (s->models[k].nv > maxnv) maxnv = s->models[k].nv;
        pps[0] = malloc(maxnv * sizeof **pps);
        if (cuts) cls[0] = malloc(maxnv * sizeof **cls);
        if (!pps[0] || (cuts && !cls[0])) { status = -1; goto done; }
    }
    pieces_start(&pc, s, o, l);
    if (l->header && pc.taken) l->header(l->ud, s, p);
    if (raster) drawing_start(&d, s, fb, sum);

    for (k = 0; k < s->nmodels; k++) {      /* run the stages */
        const pt_model *m = &s->models[k];
        size_t b = in_turn ? 0 : k;         /* the buffers of model k */

        sum->vertices += m->nv;
        sum->segments += m->nseg;
        sum->vertices_unused += m->nv - p->models[k].nused;
        sinks_init(&ms[k], &p->models[k], l, sum);
        if (o->rasterize && !in_turn) {
            pps[k] = malloc((m->nv ? m->nv : 1) * sizeof **pps);
            if (cuts) cls[k] = malloc((m->nv ? m->nv : 1) * sizeof **cls);
            if (!pps[k] || (cuts && !cls[k])) { status = -1; goto done; }
        }
        run_model(s, p, o, l, k, &ms[k], pps[b], cls[b], &fl, sum, &pc);
        if (in_turn) draw_model(&d, s, p, o, l, k, &ms[k], &fl, sum, pps[0], cls[0], &pc);
    }
    if (raster && !in_turn)                 /* every model's vertices ran: draw */
        for (k = 0; k < s->nmodels; k++)
            draw_model(&d, s, p, o, l, k, &ms[k], &fl, sum, pps[k], cls[k], &pc);
    if (raster) sum->pixels += d.im.pixels; /* those pt_raster_draw() drew */
    if (l->piece) piece_next(&pc, 1);
    if (l->summary && pc.taken) l->summary(l->ud, sum);
done:
    for (k = 0; k < n; k++) { free(pps[k]); free(cls[k]); }
    free(pps);
    free(cls);
    free(ms);
    return status;
}

int pt_run_plain(const pt_scene *s, const pt_options *o, const pt_listener *l)
{
    pt_plan p;
    pt_summary sum;
    int rc;

    if (pt_plan_make(&p, s, o) != 0) return -1;
    rc = pt_run(s, &p, o, l, NULL, &sum);
    pt_plan_free(&p);
    return rc;
}

/* ===== journeys ===== */

/* What pt_run_journey() and pt_run_journeys() keep: the journeys of model m,
** js[v - 1] for vertex v (v in 1 .. nv); js[0] for vertex `only` when set. */
typedef struct keeper {
    const pt_model *m;
    pt_journey *js;
    uint64_t nv;
    uint64_t only;               /* 0, or the one vertex kept */
    int kept;                    /* how many were kept */
} keeper;

static void keep_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    keeper *kp = ud;

    if (m != kp->m || v < 1 || v > kp->nv || (kp->only && v != kp->only)) return;
    kp->js[kp->only ? 0 : v - 1] = *j;
    kp->kept++;
}

/* Run s tracing model m (vertex v alone, or all when v is 0), every vertex
** used or not, nothing drawn, into kp. */
static int run_keeping(const pt_scene *s, const pt_model *m, uint64_t v, int raw_lookat,
                       keeper *kp)
{
    pt_options o;
    pt_listener l;

    pt_options_default(&o);
    o.model = m->name;           /* models of the same name: keep_journey picks m */
    o.vertex = v;
    o.trace_raster = 0;
    o.rasterize = 0;
    o.raw_lookat = raw_lookat;
    o.every_vertex = 1;
    memset(&l, 0, sizeof l);
    l.journey = keep_journey;
    l.ud = kp;
    return pt_run_plain(s, &o, &l);
}

int pt_run_journey(pt_journey *j, const pt_scene *s, const pt_model *m, uint64_t v,
                   int raw_lookat)
{
    keeper kp;

    assert(v >= 1 && v <= m->nv);
    kp.m = m;
    kp.js = j;
    kp.nv = m->nv;
    kp.only = v;
    kp.kept = 0;
    if (run_keeping(s, m, v, raw_lookat, &kp) != 0) return -1;
    assert(kp.kept == 1);
    return 0;
}

pt_journey *pt_run_journeys(const pt_scene *s, const pt_model *m, int raw_lookat)
{
    keeper kp;

    kp.m = m;
    kp.nv = m->nv;
    kp.only = 0;
    kp.kept = 0;
    kp.js = calloc(m->nv ? m->nv : 1, sizeof *kp.js);
    if (!kp.js) return NULL;
    if (run_keeping(s, m, 0, raw_lookat, &kp) != 0) { free(kp.js); return NULL; }
    return kp.js;
}
