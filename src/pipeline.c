/*
** src/pipeline.c -- plan the stages, run every vertex through them, rasterize
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "pipeline.h"
#include "raster.h"
#include "../stages/s1_model2camera.h"
#include "../stages/s2_camera2image.h"
#include "../stages/s3_image2pixel.h"
#include "../stages/s4_pixel2viewport.h"
#include "../stages/s5_viewport2fb.h"
#include "../stages/s6_fb2index.h"

void pt_options_default(pt_options *o)
{
    memset(o, 0, sizeof *o);
    o->stage_mask = (1u << PT_NSTAGES) - 1;
    o->trace_raster = 1;
    o->rasterize = 1;
}

/* ===== plan ===== */

/* 1 when adding t changes no value: every component is zero.  (x + 0.0 still
** turns -0.0 into +0.0; the stage is computed anyway, only its record goes.) */
static int is_zero(pt_vec3 t)
{
    return t.x == 0 && t.y == 0 && t.z == 0;
}

int pt_plan_make(pt_plan *p, const pt_scene *s, const pt_options *o)
{
    size_t k, j;

    p->nmodels = s->nmodels;
    p->models = calloc(s->nmodels ? s->nmodels : 1, sizeof *p->models);
    if (!p->models) return -1;
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        pt_model_plan *mp = &p->models[k];
        int st;

        mp->selected = !o->model || strcmp(o->model, m->name) == 0;
        mp->used = calloc(m->nv ? m->nv : 1, 1);
        if (!mp->used) { pt_plan_free(p); return -1; }
        for (j = 0; j < m->nseg; j++) {
            mp->used[m->seg[j].a] = 1;
            mp->used[m->seg[j].b] = 1;
        }
        for (j = 0; j < m->nv; j++) mp->nused += mp->used[j];
        for (st = 0; st < PT_NSTAGES; st++) {
            if (!(o->stage_mask & (1u << st))) {
                mp->why[st] = PT_WHY_FILTER;
                mp->why_text[st] = "not chosen by --stage";
            } else if (o->all_stages) {
                continue;
            } else if (st == PT_STAGE_CAMERA && is_zero(m->translate)) {
                mp->why[st] = PT_WHY_IDENTITY;
                mp->why_text[st] = "identity: translation 0 0 0";
            } else if (st == PT_STAGE_FRAMEBUFFER && s->vp_x == 0 && s->vp_y == 0) {
                mp->why[st] = PT_WHY_IDENTITY;
                mp->why_text[st] = "identity: viewport at 0,0";
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

/* A sink in front of the listener's: counts warnings, forwards when traced. */
typedef struct counting_sink {
    pt_summary *sum;
    const pt_sink *next;         /* NULL: the stage is not traced */
} counting_sink;

static void count_record(void *ud, const pt_vrec *r)
{
    counting_sink *cs = ud;
    int k;

    for (k = 0; k < PT_NWARN; k++)
        if (r->warn & (1u << k)) cs->sum->warnings[k]++;
    if (cs->next) cs->next->vertex(cs->next->ud, r);
}

/* The journey of one vertex; returns its pixel-plane point for the rasterizer.
** sinks[st] is the listener's sink when stage st is traced, else NULL. */
static pt_vec2 journey(const pt_scene *s, const pt_model *m, pt_vec3 v_m,
                       const pt_sink *const sinks[PT_NSTAGES], double *z_c)
{
    pt_vrec r = {0};
    pt_vec3 c, ip;
    pt_vec2 pp;
    pt_pix vp, fb;

    r.stage = PT_STAGE_MODEL;
    r.x = v_m.x; r.y = v_m.y; r.z = v_m.z;
    pt_emit(sinks[PT_STAGE_MODEL], &r);
    c = pt_model2camera(v_m, m->translate, sinks[PT_STAGE_CAMERA]);
    *z_c = c.z;
    ip = pt_camera2image(c, fmax(fabs(v_m.z), fabs(m->translate.z)), s->perspective,
                         sinks[PT_STAGE_IMAGE]);
    pp = pt_image2pixel(ip, s->vp_w, s->vp_h, sinks[PT_STAGE_PIXEL]);
    vp = pt_pixel2viewport(pp, s->vp_w, s->vp_h, sinks[PT_STAGE_VIEWPORT]);
    fb = pt_viewport2fb(vp, s->vp_x, s->vp_y, sinks[PT_STAGE_FRAMEBUFFER]);
    pt_fb2index(fb, s->fb_w, s->fb_h, sinks[PT_STAGE_INDEX]);
    return pp;
}

/* ===== rasterize ===== */

/* What the raster callbacks need to turn viewport pixels into records. */
typedef struct raster_ctx {
    const pt_scene *s;
    const pt_model *m;
    uint64_t seg;                /* 1-based segment number */
    const pt_listener *l;        /* NULL: nothing to report */
    pt_fb *fb;                   /* NULL: nothing to draw */
    pt_summary *sum;
} raster_ctx;

static void on_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    raster_ctx *rc = ud;
    pt_pix vp = {x_vp, y_vp, 1}, f;
    int64_t idx;

    f = pt_viewport2fb(vp, rc->s->vp_x, rc->s->vp_y, NULL);
    idx = pt_fb2index(f, rc->s->fb_w, rc->s->fb_h, NULL);
    rc->sum->pixels++;
    if (rc->l && rc->l->pixel) rc->l->pixel(rc->l->ud, rc->m, rc->seg, f.x, f.y, idx);
    if (rc->fb) pt_fb_set(rc->fb, idx, rc->m->color);
}

static void on_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    raster_ctx *rc = ud;

    rc->sum->clipped += count;
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

int pt_run(const pt_scene *s, const pt_plan *p, const pt_options *o,
           const pt_listener *l, pt_fb *fb, pt_summary *sum)
{
    size_t k, j;
    pt_vec2 **pp;                /* pp[k][v]: pixel-plane point of used vertex v */
    int status = 0;

    memset(sum, 0, sizeof *sum);
    sum->models = s->nmodels;
    pp = calloc(s->nmodels ? s->nmodels : 1, sizeof *pp);
    if (!pp) return -1;
    if (l->header) l->header(l->ud, s, p);

    for (k = 0; k < s->nmodels; k++) {      /* run the stages */
        const pt_model *m = &s->models[k];
        const pt_model_plan *mp = &p->models[k];
        counting_sink counters[2];          /* [1]: forward to the listener */
        pt_sink sink_of[2];
        const pt_sink *sinks[PT_NSTAGES], *quiet[PT_NSTAGES];
        int st;

        sum->vertices += m->nv;
        sum->segments += m->nseg;
        sum->vertices_unused += m->nv - mp->nused;
        counters[0].sum = counters[1].sum = sum;
        counters[0].next = NULL;
        counters[1].next = l->sink.vertex ? &l->sink : NULL;
        sink_of[0].vertex = sink_of[1].vertex = count_record;
        sink_of[0].ud = &counters[0];
        sink_of[1].ud = &counters[1];
        for (st = 0; st < PT_NSTAGES; st++) {
            sinks[st] = &sink_of[mp->why[st] == PT_WHY_TRACED];
            quiet[st] = &sink_of[0];
        }
        if (o->rasterize) {
            pp[k] = malloc((m->nv ? m->nv : 1) * sizeof **pp);
            if (!pp[k]) { status = -1; goto done; }
        }
        for (j = 0; j < m->nv; j++) {
            int traced = mp->selected && (!o->vertex || o->vertex == j + 1);
            double z_c;
            pt_vec2 pt;

            if (!mp->used[j] || (!traced && !o->rasterize)) continue;
            if (traced && l->vertex_begin) l->vertex_begin(l->ud, m, j + 1);
            pt = journey(s, m, m->v[j], traced ? sinks : quiet, &z_c);
            if (traced) {
                sum->vertices_traced++;
                if (s->perspective && z_c > 0) sum->behind++;
            }
            if (o->rasterize) pp[k][j] = pt;
        }
    }

    if (o->rasterize) {                     /* rasterize */
        pt_raster_out out = {on_pixel, on_clip, NULL};
        raster_ctx rc;

        sum->rasterized = 1;
        rc.s = s; rc.fb = fb; rc.sum = sum;
        out.ud = &rc;
        for (k = 0; k < s->nmodels; k++) {
            const pt_model *m = &s->models[k];
            int report = o->trace_raster && p->models[k].selected && !o->vertex;

            rc.m = m;
            rc.l = report ? l : NULL;
            for (j = 0; j < m->nseg; j++) {
                pt_vec2 a = pp[k][m->seg[j].a], b = pp[k][m->seg[j].b];
                int r;

                rc.seg = j + 1;
                r = pt_raster_segment(a, b, s->vp_w, s->vp_h, &out);
                if (r == PT_RASTER_DEGENERATE) sum->segments_degenerate++;
                if (r == PT_RASTER_SKIPPED) {
                    sum->segments_skipped++;
                    if (report && l->skip) skip_report(l, m, j + 1, a, b);
                }
            }
        }
    }
    if (l->summary) l->summary(l->ud, sum);
done:
    for (k = 0; k < s->nmodels; k++) free(pp[k]);
    free(pp);
    return status;
}
