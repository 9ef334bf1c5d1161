/*
** src/tools/accuracy/acc_double.c -- both cameras in double: the real stages and rasterizer
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/acc_double.h"

/* ===== the classic camera ===== */

/* s3_image2pixel with 2 for 2.001: the choice PT_ACC_TWO. */
static pt_vec2 image2pixel_two(pt_vec3 ip, int w, int h)
{
    pt_vec2 pp;

    pp.x = 0.5 + w / 2.0 * (ip.x + 1);      /* x_pp = 0.5 + w/2 * (x_ip + 1) */
    pp.y = 0.5 + h / 2.0 * (ip.y + 1);      /* y_pp = 0.5 + h/2 * (y_ip + 1) */
    return pp;
}

/* Each stage reads its input from the journey (doubles, lo = 0) and calls
** the stage function of stages/ on it. */

static void model(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)c;
    j->m[0] = pt_acc_dd(v.x); j->m[1] = pt_acc_dd(v.y); j->m[2] = pt_acc_dd(v.z);
}

static void camera(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    pt_vec3 m, cc;

    (void)v;
    m.x = j->m[0].hi; m.y = j->m[1].hi; m.z = j->m[2].hi;
    cc = ptref_model2camera(m, c->par.translate, NULL);
    j->c[0] = pt_acc_dd(cc.x); j->c[1] = pt_acc_dd(cc.y); j->c[2] = pt_acc_dd(cc.z);
}

static void image(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    pt_vec3 cc, ip;

    (void)v;
    cc.x = j->c[0].hi; cc.y = j->c[1].hi; cc.z = j->c[2].hi;
    ip = ptref_camera2image(cc, fmax(fabs(j->m[2].hi), fabs(c->par.translate.z)),
                         c->par.perspective, NULL);
    j->ip[0] = pt_acc_dd(ip.x); j->ip[1] = pt_acc_dd(ip.y);
}

static void pixel(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    pt_vec3 ip;
    pt_vec2 pp;

    (void)v;
    ip.x = j->ip[0].hi; ip.y = j->ip[1].hi; ip.z = 0.0;     /* z_ip: not used */
    pp = c->choices & PT_ACC_TWO ? image2pixel_two(ip, c->par.w, c->par.h)
                                 : ptref_image2pixel(ip, c->par.w, c->par.h, NULL);
    j->pp[0] = pt_acc_dd(pp.x); j->pp[1] = pt_acc_dd(pp.y);
}

static void viewport(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    pt_vec2 pp;

    (void)v;
    pp.x = j->pp[0].hi; pp.y = j->pp[1].hi;
    j->vp = ptref_pixel2viewport(pp, c->par.w, c->par.h, NULL);
}

static void framebuffer(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)v;
    j->fb = ptref_viewport2fb(j->vp, c->par.x_ul, c->par.y_ul, NULL);
}

static void index_stage(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)v;
    j->idx = ptref_fb2index(j->fb, c->par.W, c->par.H, NULL);
}

/* ===== the DDA ===== */

static void forward_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    const pt_acc_dda *o = ud;

    o->pixel(o->ud, x_vp, y_vp);
}

static void ignore_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    (void)ud; (void)count; (void)first; (void)last;
}

/*
** The steps inside the viewport's band, in double.  recompute: y = y0 + m*(x -
** x0) each step, drawn here (the pipeline has no such rasterizer).  Else the
** y of src/core/raster.c's steps, y += m from the same start (pt_raster_advance()
** skips to the band exactly), only handed to o->step: the rasterizer itself
** draws them.
*/
static void steps_d(const pt_dd p0[2], const pt_dd p1[2], int recompute, const pt_acc_dda *o)
{
    int64_t e[4], s, first, last, r;
    double x0, y0, x1, y1, m, y;
    pt_acc_line ln;

    if (!pt_pix_round(p0[0].hi, &e[0]) || !pt_pix_round(p0[1].hi, &e[1]) ||
        !pt_pix_round(p1[0].hi, &e[2]) || !pt_pix_round(p1[1].hi, &e[3]))
        return;
    x0 = (double)e[0]; y0 = (double)e[1];           /* the rounded endpoints */
    x1 = (double)e[2]; y1 = (double)e[3];
    if (x0 == x1 && y0 == y1) {                     /* one pixel, no step */
        if (recompute) pt_acc_dda_dot(o, e[0], e[1]);
        return;
    }
    pt_acc_dda_setup(&ln, fabs(y1 - y0) > fabs(x1 - x0), e, o, &first, &last);
    x0 = (double)e[0]; y0 = (double)e[1];           /* in stepping order */
    x1 = (double)e[2]; y1 = (double)e[3];
    m = (y1 - y0) / (x1 - x0);                      /* m = dy / dx */
    if (first > last) return;
    y = recompute || m == 0.0 ? y0                  /* (pt_raster_advance() steps */
      : pt_raster_advance(y0, m, (uint64_t)(first - e[0]));  /* y = 0, m = 0 one by one) */
    for (s = first; s <= last; s++) {
        if (recompute) {
            int ok;

            y = y0 + m * ((double)s - x0);          /* y = y0 + m*(x - x0) */
            ok = pt_pix_round(y, &r);
            pt_acc_dda_step(o, &ln, s, ok, r, y);
        } else {
            o->step(o->ud, &ln, s, y);
            y += m;                                 /* y += m */
        }
    }
}

static int raster(const pt_dd p0[2], const pt_dd p1[2], unsigned choices,
                  const pt_acc_dda *o)
{
    int recompute = (choices & PT_ACC_RECOMPUTE) != 0;
    pt_vec2 a, b;
    pt_raster_out out;
    int64_t r;

    if (!pt_pix_round(p0[0].hi, &r) || !pt_pix_round(p0[1].hi, &r) ||
        !pt_pix_round(p1[0].hi, &r) || !pt_pix_round(p1[1].hi, &r))
        return -1;
    if (recompute || o->step) steps_d(p0, p1, recompute, o);
    if (recompute) return 0;
    a.x = p0[0].hi; a.y = p0[1].hi;
    b.x = p1[0].hi; b.y = p1[1].hi;
    out.pixel = forward_pixel;
    out.clip = ignore_clip;
    out.ud = (void *)o;
    pt_raster_segment(a, b, o->w, o->h, o->to_vp, &out);
    return 0;
}

/* ===== the matrix camera ===== */

static int mcam(pt_acc_mcam *c)
{
    pt_options o;

    pt_options_default(&o);
    return pt_plan_make(&c->plan, c->s, &o);
}

static void widen4(pt_vec4 v, pt_dd r[4])
{
    r[0] = pt_acc_dd(v.x); r[1] = pt_acc_dd(v.y); r[2] = pt_acc_dd(v.z); r[3] = pt_acc_dd(v.w);
}

static pt_vec4 narrow4(const pt_dd r[4])
{
    pt_vec4 v;

    v.x = r[0].hi; v.y = r[1].hi; v.z = r[2].hi; v.w = r[3].hi;
    return v;
}

static void m_model(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)c; (void)k;
    j->m[0] = pt_acc_dd(v.x); j->m[1] = pt_acc_dd(v.y); j->m[2] = pt_acc_dd(v.z);
}

static void m_world(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    pt_matrices mx;
    pt_vec3 m;

    (void)v;
    pt_matrices_of(&mx, &c->plan, k);
    m.x = j->m[0].hi; m.y = j->m[1].hi; m.z = j->m[2].hi;
    widen4(pt_model2world(m, mx.world, NULL), j->w);
}

static void m_view(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    pt_matrices mx;

    (void)v;
    pt_matrices_of(&mx, &c->plan, k);
    widen4(pt_world2view(narrow4(j->w), mx.view, NULL), j->v);
}

static void m_clip(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    pt_matrices mx;

    (void)v;
    pt_matrices_of(&mx, &c->plan, k);
    widen4(pt_view2clip(narrow4(j->v), mx.proj, NULL), j->k);
    memset(j->kerr, 0, sizeof j->kerr);
}

static void m_cvv(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)c; (void)k; (void)v;
    j->code = pt_clip2cvv(narrow4(j->k), NULL);
}

/* From clip coordinates on: m5 .. m7, s5, s6 and the rasterizer's point. */

static void t_ndc(const pt_scene *s, pt_acc_mtail *t)
{
    pt_vec4 k = narrow4(t->k);
    pt_vec3 n = pt_clip2ndc(k, fabs(k.w), NULL);

    (void)s;
    t->n[0] = pt_acc_dd(n.x); t->n[1] = pt_acc_dd(n.y); t->n[2] = pt_acc_dd(n.z);
}

static void t_screen(const pt_scene *s, pt_acc_mtail *t)
{
    pt_vec3 n, sc;

    n.x = t->n[0].hi; n.y = t->n[1].hi; n.z = t->n[2].hi;
    sc = pt_ndc2screen(n, s->vp_w, s->vp_h, NULL);
    t->sc[0] = pt_acc_dd(sc.x); t->sc[1] = pt_acc_dd(sc.y); t->sc[2] = pt_acc_dd(sc.z);
}

static void t_viewport(const pt_scene *s, pt_acc_mtail *t)
{
    pt_vec3 sc;
    pt_vec2 pp;

    sc.x = t->sc[0].hi; sc.y = t->sc[1].hi; sc.z = t->sc[2].hi;
    t->vp = pt_screen2viewport(sc, s->vp_w, s->vp_h, NULL);
    pp = pt_viewport2pixelplane(t->vp, s->vp_h);   /* the rasterizer's point */
    t->pp[0] = pt_acc_dd(t->vp.ok ? pp.x : (double)NAN);
    t->pp[1] = pt_acc_dd(t->vp.ok ? pp.y : (double)NAN);
}

static void t_framebuffer(const pt_scene *s, pt_acc_mtail *t)
{
    t->fb = ptref_viewport2fb(t->vp, s->vp_x, s->vp_y, NULL);
}

static void t_index(const pt_scene *s, pt_acc_mtail *t)
{
    t->idx = ptref_fb2index(t->fb, s->fb_w, s->fb_h, NULL);
}

static int mseg(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    pt_vec4 p[2], q[2];
    double t[2];
    int e;

    (void)c;
    p[0].x = a->k[0].hi; p[0].y = a->k[1].hi; p[0].z = a->k[2].hi; p[0].w = a->k[3].hi;
    p[1].x = b->k[0].hi; p[1].y = b->k[1].hi; p[1].z = b->k[2].hi; p[1].w = b->k[3].hi;
    if (!pt_clip_segment(p[0], p[1], &t[0], &t[1], &q[0], &q[1]))
        return 0;                           /* stages/ms_clip_segment.c's, as the pipeline clips */
    for (e = 0; e < 2; e++) {
        if (!g->made[e]) continue;
        g->t[e] = pt_acc_dd(t[e]);
        widen4(q[e], g->end[e].k);
    }
    return 1;
}

/* ===== renderers 7 and 9 =====
**
** The stages of stages/r7_*, r9_* and rv_* themselves.  The two clips work on
** a model: each segment is handed to them as a model of its two ends (and
** two white colours), and their cuts are heard as the course's log hears
** them.  Out of memory there (two vertices), the segment counts as kept. */

static pt_jmat jmat_of(const pt_dd a[4][4])
{
    pt_jmat m;
    int j;

    for (j = 0; j < 4; j++) {
        m.col[j].x = a[0][j].hi; m.col[j].y = a[1][j].hi;
        m.col[j].z = a[2][j].hi; m.col[j].w = a[3][j].hi;
    }
    return m;
}

static void rv_camera_of(const pt_acc_rvcam *c, pt_rv_camera *cam)
{
    cam->perspective = c->s->perspective;
    cam->l = c->l.hi; cam->r = c->r.hi; cam->b = c->b.hi; cam->t = c->t.hi;
    cam->n = c->n.hi;
    cam->view.x = c->view[0].hi; cam->view.y = c->view[1].hi; cam->view.z = c->view[2].hi;
}

static int rvcam(pt_acc_rvcam *c)
{
    pt_rv_camera cam;
    pt_jmat n;
    int i;

    if (pt_acc_rvcam_exact(c) != 0) return -1;      /* the stage's own matrices */
    rv_camera_of(c, &cam);
    n = pt_r9_normalize_matrix(&cam);
    for (i = 0; i < 4; i++) {
        c->norm[0][i] = pt_acc_dd(n.col[i].x); c->norm[1][i] = pt_acc_dd(n.col[i].y);
        c->norm[2][i] = pt_acc_dd(n.col[i].z); c->norm[3][i] = pt_acc_dd(n.col[i].w);
    }
    return 0;
}

static void rv_model(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    (void)c; (void)k;
    j->m[0] = pt_acc_dd(v.x); j->m[1] = pt_acc_dd(v.y); j->m[2] = pt_acc_dd(v.z);
}

static void rv_world(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_vec4 in, o;
    pt_jmat m;

    (void)v;
    if (c->s->renderer != 9) return;                /* renderer 7 has no world */
    m = jmat_of((const pt_dd (*)[4])c->world[k]);
    in.x = j->m[0].hi; in.y = j->m[1].hi; in.z = j->m[2].hi; in.w = 1.0;
    o = pt_r9_model2world(in, &m);
    widen4(o, j->w);
}

static void rv_view(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_vec4 in, o;
    pt_vec3 e;

    (void)v;
    if (c->s->renderer == 9) {
        in = narrow4(j->w);
        e.x = c->view[0].hi; e.y = c->view[1].hi; e.z = c->view[2].hi;
        o = pt_r9_world2view(in, e);
    } else {
        in.x = j->m[0].hi; in.y = j->m[1].hi; in.z = j->m[2].hi; in.w = 1.0;
        o = pt_r7_model2view(in, c->s->models[k].translate);
    }
    j->v[0] = pt_acc_dd(o.x); j->v[1] = pt_acc_dd(o.y); j->v[2] = pt_acc_dd(o.z);
}

static void rv_camera(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_vec4 in, o;

    (void)k; (void)v;
    in.x = j->v[0].hi; in.y = j->v[1].hi; in.z = j->v[2].hi; in.w = 1.0;
    if (c->s->renderer == 9) {
        pt_jmat n = jmat_of(c->norm);

        o = pt_r9_view2camera(in, &n);
    } else {
        pt_rv_camera cam;

        rv_camera_of(c, &cam);
        o = pt_r7_view2camera(in, &cam);
    }
    j->c[0] = pt_acc_dd(o.x); j->c[1] = pt_acc_dd(o.y); j->c[2] = pt_acc_dd(o.z);
}

static void rv_image(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_vec4 in, o;

    (void)k; (void)v;
    in.x = j->c[0].hi; in.y = j->c[1].hi; in.z = j->c[2].hi; in.w = 1.0;
    o = pt_rv_project(in, c->s->perspective);
    j->ip[0] = pt_acc_dd(o.x); j->ip[1] = pt_acc_dd(o.y);
}

/* A model of the segment a-b alone, for the clip stages: 0, or -1. */
static int seg_model(pt_rv_model *m, pt_vec4 a, pt_vec4 b)
{
    pt_rgb white = {1.0f, 1.0f, 1.0f};
    pt_rv_prim p;

    memset(m, 0, sizeof *m);
    memset(&p, 0, sizeof p);
    p.kind = PT_RV_LINE;
    p.v[1] = p.c[1] = 1;
    if (pt_rv_add_vertex(m, a) || pt_rv_add_vertex(m, b) || pt_rv_add_color(m, white)
        || pt_rv_add_color(m, white) || pt_rv_add_prim(m, &p)) {
        pt_rv_model_free(m);
        return -1;
    }
    return 0;
}

/* What the clip stages' listener hears of one segment. */
typedef struct heard {
    pt_acc_rvcut cut[PT_ACC_RV_MAXCUTS];
    int ncuts;
    int verdict;                 /* 1 kept (as it is, or cut), 0 dropped */
    pt_vec4 ends[2];             /* kept: its ends */
} heard;

static void hear_cut(void *ud, const pt_rv_cut *c)
{
    heard *h = ud;

    if (h->ncuts < PT_ACC_RV_MAXCUTS) {
        pt_acc_rvcut *k = &h->cut[h->ncuts];

        k->edge = (int)c->edge;
        k->off = c->off;
        k->t = pt_acc_dd(c->t);
        k->p[0] = pt_acc_dd(c->p[2].x); k->p[1] = pt_acc_dd(c->p[2].y);
        k->p[2] = pt_acc_dd(c->p[2].z);
    }
    h->ncuts++;
}

static void hear_end(void *ud, const pt_rv_model *m, const pt_rv_prim *p, int accepted)
{
    heard *h = ud;

    h->verdict = accepted;
    if (accepted) { h->ends[0] = m->v[p->v[0]]; h->ends[1] = m->v[p->v[1]]; }
}

static int rvnear(const pt_acc_rvcam *c, const pt_dd v0[3], const pt_dd v1[3], pt_acc_rvcut *cut)
{
    pt_vec4 a = {v0[0].hi, v0[1].hi, v0[2].hi, 1.0}, b = {v1[0].hi, v1[1].hi, v1[2].hi, 1.0};
    pt_rv_clip_ls ls = {NULL, NULL, hear_cut, hear_end, NULL};
    pt_rv_model m;
    heard h;

    memset(&h, 0, sizeof h);
    ls.ud = &h;
    if (seg_model(&m, a, b) != 0) return 1;
    if (pt_rv_nearclip(&m, c->n.hi, &ls) != 0) h.verdict = 1, h.ncuts = 0;
    pt_rv_model_free(&m);
    if (h.ncuts == 0) return h.verdict;
    *cut = h.cut[0];
    return -1;
}

static int rvclip(pt_dd e[2][2], pt_acc_rvseg *g)
{
    pt_vec4 a = {e[0][0].hi, e[0][1].hi, 0.0, 1.0}, b = {e[1][0].hi, e[1][1].hi, 0.0, 1.0};
    pt_rv_clip_ls ls = {NULL, NULL, hear_cut, hear_end, NULL};
    pt_rv_model m;
    heard h;
    int k;

    memset(&h, 0, sizeof h);
    ls.ud = &h;
    if (seg_model(&m, a, b) != 0) return 1;
    if (pt_rv_clip(&m, &ls) != 0) h.verdict = 0;    /* past 64 cuts: dropped */
    pt_rv_model_free(&m);
    g->ncuts = h.ncuts;
    for (k = 0; k < h.ncuts && k < PT_ACC_RV_MAXCUTS; k++) {
        g->cut[k] = h.cut[k];
        g->made[h.cut[k].off] = 2;
    }
    if (h.verdict) {
        for (k = 0; k < 2; k++) { e[k][0] = pt_acc_dd(h.ends[k].x); e[k][1] = pt_acc_dd(h.ends[k].y); }
    }
    return h.verdict;
}

const pt_acc_ops pt_acc_double_ops = {
    { model, camera, image, pixel, viewport, framebuffer, index_stage },
    raster, mcam,
    { m_model, m_world, m_view, m_clip, m_cvv },
    { t_ndc, t_screen, t_viewport, t_framebuffer, t_index },
    mseg,
    rvcam, { rv_model, rv_world, rv_view, rv_camera, rv_image }, rvnear, rvclip
};
