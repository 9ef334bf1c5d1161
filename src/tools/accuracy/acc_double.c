/*
** src/tools/accuracy/acc_double.c -- both cameras in double: the real stages and rasterizer
** See LICENSE for copyright and license.
*/
#include <math.h>
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

const pt_acc_ops pt_acc_double_ops = {
    { model, camera, image, pixel, viewport, framebuffer, index_stage },
    raster, mcam,
    { m_model, m_world, m_view, m_clip, m_cvv },
    { t_ndc, t_screen, t_viewport, t_framebuffer, t_index },
    mseg
};
