/*
** tests/unit/test_accuracy.c -- the three arithmetics of src/tools/accuracy/
** See LICENSE for copyright and license.
**
** Usage: test_accuracy [REFERENCE_DIR], from the repository root.  Checks:
** the double-double operations (sqrt, cot, a matrix product included) and Java
** rounding of a double-double; that the double journey is the stages' journey,
** value for value, for every vertex of every scene in REFERENCE_DIR (default
** tests/reference), tests/extreme and docs/examples; for the matrix camera's
** scenes the same with its matrices, its clipping and its image; that the
** double DDA lights exactly src/core/raster.c's pixels; that the float DDA (with
** its fast-forward) lights the plain float loop's; that the reference DDA
** lights the exact line's, ties included; and what pt_acc_compare() reports on
** scenes whose answer is known.  Renderers 7 and 9: their row tables; the
** formula copies of acc_rv_tmpl.h, instantiated in double, against the stages
** bit for bit; the double run against the course driver on tests/course79/;
** and the timed work against the error runs.
*/
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "tools/accuracy/accuracy.h"
#include "core/pipeline.h"
#include "core/raster.h"
#include "stages/m4_clip2cvv.h"
#include "stages/s4_pixel2viewport.h"
#include "core/course.h"
#include "stages/r7_model2view.h"
#include "stages/r7_view2camera.h"
#include "stages/r9_model2world.h"
#include "stages/r9_world2view.h"
#include "stages/r9_view2camera.h"
#include "stages/rv_nearclip.h"
#include "stages/rv_project.h"
#include "stages/rv_clip.h"

/* ===== double-double ===== */

static pt_dd dd(double hi, double lo)
{
    pt_dd r;
    r.hi = hi;
    r.lo = lo;
    return r;
}

static int64_t round_dd(double hi, double lo)
{
    int64_t r;
    return pt_dd_pix_round(dd(hi, lo), &r) ? r : -999999;
}

static void test_dd(void)
{
    pt_dd third = pt_dd_div(pt_dd_from(1.0), pt_dd_from(3.0));
    pt_dd k = pt_dd_div(pt_dd_from(2001.0), pt_dd_from(1000.0));
    pt_dd d = pt_dd_add(k, pt_dd_neg(pt_dd_2001));
    pt_dd one = pt_dd_mul(third, pt_dd_from(3.0));
    pt_dd s = pt_dd_add(pt_dd_from(1.0), pt_dd_from(1e-30));
    double r;
    int64_t big = 4611686018427387903LL, v;

    PT_CHECK("acc-1.1 1 + 1e-30 keeps both parts", s.hi == 1.0 && s.lo == 1e-30);
    r = fma(-3.0, third.lo, fma(-3.0, third.hi, 1.0));
    PT_CHECK("acc-1.2 1/3 within 2^-104", fabs(r) < 0x1p-104);
    PT_CHECK("acc-1.3 (1/3) * 3 = 1 within 2^-104",
             fabs(pt_dd_add(one, pt_dd_from(-1.0)).hi) < 0x1p-104);
    PT_CHECK("acc-1.4 2001/1000 computed = the constant, within 2^-104",
             fabs(d.hi) < 0x1p-104 * 2.001);
    PT_CHECK("acc-1.5 the constant's hi is the double 2.001", pt_dd_2001.hi == 2.001);
    r = fma(-1000.0, pt_dd_2001.lo, fma(-1000.0, pt_dd_2001.hi, 2001.0));
    PT_CHECK("acc-1.6 the constant is within 2^-110 of 2001/1000", fabs(r / 2001.0) < 0x1p-110);
    s = pt_dd_from_i64(big);
    PT_CHECK("acc-1.7 2^62 - 1 held exactly",
             (int64_t)s.hi - big + (int64_t)s.lo == 0 && s.hi == 0x1p62 && s.lo == -1.0);
    s = pt_dd_from_i64(-big);
    PT_CHECK("acc-1.8 -(2^62 - 1) held exactly", s.hi == -0x1p62 && s.lo == 1.0);
    PT_CHECK("acc-1.9 -0 + -0 = -0, as in double",
             signbit(pt_dd_add(pt_dd_from(-0.0), pt_dd_from(-0.0)).hi) != 0);
    PT_CHECK("acc-1.10 -0 + 0 = +0, as in double",
             signbit(pt_dd_add(pt_dd_from(-0.0), pt_dd_from(0.0)).hi) == 0);
    PT_CHECK("acc-1.11 1 / -0 = -inf",
             pt_dd_div(pt_dd_from(1.0), pt_dd_neg(pt_dd_from(0.0))).hi == -(double)INFINITY);
    PT_CHECK("acc-1.12 0 / 0 = NaN", isnan(pt_dd_div(pt_dd_from(0.0), pt_dd_from(0.0)).hi));
    PT_CHECK("acc-1.13 1e308 + 1e308 = inf, lo 0",
             isinf(pt_dd_add(pt_dd_from(1e308), pt_dd_from(1e308)).hi));

    PT_CHECK("acc-2.1 round 2.5 = 3 (tie up)", round_dd(2.5, 0.0) == 3);
    PT_CHECK("acc-2.2 round 2.5 - 1e-30 = 2", round_dd(2.5, -1e-30) == 2);
    PT_CHECK("acc-2.3 round -2.5 = -2 (tie up)", round_dd(-2.5, 0.0) == -2);
    PT_CHECK("acc-2.4 round -2.5 - 1e-30 = -3", round_dd(-2.5, -1e-30) == -3);
    PT_CHECK("acc-2.5 round -2.5 + 1e-30 = -2", round_dd(-2.5, 1e-30) == -2);
    PT_CHECK("acc-2.6 round 0.49999999999999994 = 0", round_dd(0.49999999999999994, 0.0) == 0);
    PT_CHECK("acc-2.7 round 2^53 + 0.5 = 2^53 + 1", round_dd(0x1p53, 0.5) == (1LL << 53) + 1);
    PT_CHECK("acc-2.8 round 2^53 - 0.5 = 2^53", round_dd(0x1p53, -0.5) == (1LL << 53));
    PT_CHECK("acc-2.9 round 2^53 - 0.75 = 2^53 - 1", round_dd(0x1p53, -0.75) == (1LL << 53) - 1);
    PT_CHECK("acc-2.10 round 7 - 1e-20 = 7", round_dd(7.0, -1e-20) == 7);
    PT_CHECK("acc-2.11 no pixel at 2^62", !pt_dd_pix_round(dd(0x1p62, 0.0), &v));
    PT_CHECK("acc-2.12 no pixel for NaN", !pt_dd_pix_round(dd((double)NAN, 0.0), &v));
    PT_CHECK("acc-2.13 round 2^62 - 1 exists", round_dd(0x1p62, -1.0) == big);
}

/* |got - want| / |want|, for two close double-doubles. */
static double dd_rel(pt_dd got, pt_dd want)
{
    return fabs((got.hi - want.hi) + (got.lo - want.lo)) / fabs(want.hi);
}

/* The matrix camera's double-double tools: sqrt, cot, a matrix product. */
static void test_dd_matrix(void)
{
    const double eps = 0x1p-50;
    pt_dd q = pt_dd_sqrt(pt_dd_from(2.0)), c30 = pt_dd_cot_deg(30.0), c60 = pt_dd_cot_deg(60.0);
    pt_dd one = pt_dd_from(1.0);
    pt_dd_mat4 a, b, r;
    pt_mat4 ad, bd, rd;
    int i, j, k, exact = 1, dbl = 1;
    double r2;

    r2 = fma(-2.0 * q.hi, q.lo, fma(-q.hi, q.hi, 2.0));      /* 2 - q^2 */
    PT_CHECK("acc-1.20 sqrt(2) within 2^-104", fabs(r2 / 4.0) < 0x1p-104);
    q = pt_dd_sqrt(pt_dd_from(4.0));
    PT_CHECK("acc-1.21 sqrt(4) = 2 exactly", q.hi == 2.0 && q.lo == 0.0);
    PT_CHECK("acc-1.22 sqrt(0) = 0, sqrt(-1) = NaN",
             pt_dd_sqrt(pt_dd_from(0.0)).hi == 0.0 && isnan(pt_dd_sqrt(pt_dd_from(-1.0)).hi));
    q = pt_dd_sqrt(pt_dd_add(pt_dd_from(1.0), pt_dd_from(0x1p-80)));   /* 1 + 2^-81 - ... */
    PT_CHECK("acc-1.23 sqrt(1 + 2^-80) = 1 + 2^-81 within 2^-104",
             dd_rel(q, pt_dd_add(one, pt_dd_from(0x1p-81))) < 0x1p-104);
    r2 = fma(-2.0 * c30.hi, c30.lo, fma(-c30.hi, c30.hi, 3.0));     /* 3 - cot(30)^2 */
    PT_CHECK("acc-1.24 cot(30 degrees) = sqrt(3) within 2^-102", fabs(r2 / 6.0) < 0x1p-102);
    PT_CHECK("acc-1.25 cot(60) * cot(30) = 1 within 2^-102",
             dd_rel(pt_dd_mul(c60, c30), one) < 0x1p-102);
    PT_CHECK("acc-1.26 cot(45) = 1 exactly", pt_dd_cot_deg(45.0).hi == 1.0
             && pt_dd_cot_deg(45.0).lo == 0.0);
    PT_CHECK("acc-1.27 cot(22.5) = 1 + sqrt(2) within 2^-102",
             dd_rel(pt_dd_cot_deg(22.5), pt_dd_add(one, pt_dd_sqrt(pt_dd_from(2.0)))) < 0x1p-102);
    PT_CHECK("acc-1.28 cot(10), cot(0.001), cot(89.999) within 2^-102 of 200-bit values",
             dd_rel(pt_dd_cot_deg(10.0), dd(0x1.6af648056a136p+2, 0x1.27c9baa1ca563p-52)) < 0x1p-102
             && dd_rel(pt_dd_cot_deg(0.001), dd(0x1.bf9f8f1b93808p+15, 0x1.52c388a4ac858p-39))
                < 0x1p-102
             && dd_rel(pt_dd_cot_deg(89.999), dd(0x1.24d1521218fbbp-16, 0x1.52a34b89b814bp-70))
                < 0x1p-102);

    /* a_ik = 1 + p_ik eps, b_kj = 1 + q_kj eps, eps = 2^-50: the product's
    ** entry is 4 + eps sum(p + q) + eps^2 sum(p q), 101 bits, a double-double
    ** exactly; double keeps 4 + eps sum(p + q) and drops the eps^2 part. */
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            ad.m[i][j] = 1 + (double)(i + 2 * j + 1) * eps;
            bd.m[i][j] = 1 + (double)(3 * i - j - 5) * eps;
            a.m[i][j] = pt_dd_from(ad.m[i][j]);
            b.m[i][j] = pt_dd_from(bd.m[i][j]);
        }
    r = pt_dd_mat4_mul(&a, &b);
    rd = pt_mat4_mul(&ad, &bd);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            double s1 = 0, s2 = 0;

            for (k = 0; k < 4; k++) {
                s1 += (double)(i + 2 * k + 1) + (double)(3 * k - j - 5);
                s2 += (double)(i + 2 * k + 1) * (double)(3 * k - j - 5);
            }
            exact &= r.m[i][j].hi == 4 + s1 * eps && r.m[i][j].lo == s2 * eps * eps;
            dbl &= rd.m[i][j] == 4 + s1 * eps;
        }
    PT_CHECK("acc-1.29 a double-double matrix product keeps the 2^-100 terms exactly", exact);
    PT_CHECK("acc-1.30 ... that double's product (pt_mat4_mul) drops", dbl);
}

/* ===== scenes ===== */

/* Every record of one run of the stages, indexed by vertex and stage. */
typedef struct got {
    const pt_scene *s;
    size_t *base, cur;
    pt_vrec *rec;
    unsigned char *have;
} got;

static void on_begin(void *ud, const pt_model *m, uint64_t v)
{
    got *g = ud;
    g->cur = g->base[m - g->s->models] + (size_t)(v - 1);
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    got *g = ud;

    if (!pt_pipeline_has(&pt_pipe_classic, r->stage)) return;
    g->rec[g->cur * PT_NSTAGES_ALL + r->stage] = *r;
    g->have[g->cur * PT_NSTAGES_ALL + r->stage] = 1;
}

static int same(double a, double b)             /* bit for bit, -0 is not 0 */
{
    return a == b ? signbit(a) == signbit(b) : (isnan(a) && isnan(b));
}

/* Pixels of one segment, as x_vp, y_vp pairs. */
typedef struct pixels { int64_t xy[2 * 40000]; size_t n; int over; } pixels;

static void px_add(void *ud, int64_t x, int64_t y)
{
    pixels *p = ud;

    if (p->n >= 40000) { p->over = 1; return; }
    p->xy[2 * p->n] = x;
    p->xy[2 * p->n + 1] = y;
    p->n++;
}

static void px_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    (void)ud; (void)count; (void)first; (void)last;
}

static int same_pixels(const pixels *a, const pixels *b)
{
    return !a->over && !b->over && a->n == b->n &&
           memcmp(a->xy, b->xy, 2 * a->n * sizeof a->xy[0]) == 0;
}

static pixels pa, pb;                           /* big: not on the stack */

/* The oracle: the teaching renderer's DDA in double, every step taken (no
** fast-forward, no band), pixel (s - 1, h - round(y)) or, steep, (round(x) - 1,
** h - s), kept when inside the viewport; nothing for an endpoint without a
** pixel (not finite; here also beyond 1e15, which the caller does not pass). */
static void plain_dda(pt_vec2 p0, pt_vec2 p1, int w, int h, pixels *out)
{
    double x0 = pt_java_round(p0.x), y0 = pt_java_round(p0.y);
    double x1 = pt_java_round(p1.x), y1 = pt_java_round(p1.y), m, y, t;
    int steep;
    int64_t s, px, py;

    if (!(fabs(p0.x) < 1e15 && fabs(p0.y) < 1e15 && fabs(p1.x) < 1e15 && fabs(p1.y) < 1e15))
        return;                             /* no pixel (NaN too): the segment is skipped */
    steep = fabs(y1 - y0) > fabs(x1 - x0);
    if (steep) { t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; }
    m = x1 == x0 ? 0 : (y1 - y0) / (x1 - x0);
    for (s = (int64_t)x0, y = y0; s <= (int64_t)x1; s++, y += m) {
        if (steep) { px = (int64_t)pt_java_round(y) - 1; py = h - s; }
        else       { px = s - 1; py = h - (int64_t)pt_java_round(y); }
        if (px >= 0 && px < w && py >= 0 && py < h) px_add(out, px, py);
    }
}

/* The accuracy tool's double DDA (the pipeline's rasterizer) against the
** plain loop above, or, for a segment of more than 2e6 steps (the extreme
** scenes' 1e15-pixel lines), against pt_raster_segment() itself, whose
** fast-forward tests/unit/test_raster.c checks against the plain additions.
** Returns 1 when they light the same pixels. */
static int dda_agrees(pt_vec2 p0, pt_vec2 p1, int w, int h)
{
    double steps = fmax(fabs(pt_java_round(p1.x) - pt_java_round(p0.x)),
                        fabs(pt_java_round(p1.y) - pt_java_round(p0.y)));

    pa.n = pb.n = 0;
    pa.over = pb.over = 0;
    if (steps <= 2e6) {
        plain_dda(p0, p1, w, h, &pa);
    } else {
        pt_raster_out out = {px_add, px_clip, &pa};
        pt_raster_segment(p0, p1, w, h, pt_pixel2viewport, &out);
    }
    pt_acc_raster_segment(PT_ARITH_DOUBLE, 0, pt_dd_from(p0.x), pt_dd_from(p0.y),
                          pt_dd_from(p1.x), pt_dd_from(p1.y), w, h, px_add, &pb);
    return same_pixels(&pa, &pb);
}

/* ===== the matrix camera against the pipeline ===== */

#define NALL PT_NSTAGES_ALL

/* What the matrix checks found, over all matrix scenes. */
static struct {
    size_t scenes, vertices, bad_vertices, points, bad_points, bad_culled;
    size_t bad_images, bad_matrices, pixels;
    double ref_matrix_ulps;      /* the reference's matrices against double's */
} mc;

/* Every record of one matrix-camera run: slot v for vertex v (all models in
** a row), then two slots per segment for the points clipping makes; and the
** color + 1 last written to each pixel (0: none). */
typedef struct mgot {
    const pt_scene *s;
    size_t *vbase, *sbase;       /* model k's first vertex slot, first segment */
    size_t nvslots, cur;         /* vertex slots; the slot records go to */
    pt_vrec *rec;                /* rec[slot * NALL + stage] */
    unsigned char *have;
    double *t;                   /* a clip slot's t */
    int64_t *px;                 /* px[idx] */
} mgot;

static void m_begin(void *ud, const pt_model *m, uint64_t v)
{
    mgot *g = ud;
    g->cur = g->vbase[m - g->s->models] + (size_t)(v - 1);
}

/* End 0 is made when the first end is outside (cvv code not 0) and comes
** first; otherwise (or the second time) it is end 1. */
static void m_clipvertex(void *ud, const pt_model *m, uint64_t seg, uint64_t from,
                         uint64_t to, double t, pt_vec4 q)
{
    mgot *g = ud;
    size_t k = (size_t)(m - g->s->models);
    size_t slot = g->nvslots + 2 * (g->sbase[k] + (size_t)(seg - 1));
    const pt_vrec *cvv = &g->rec[(g->vbase[k] + (size_t)(from - 1)) * NALL + PT_STAGE_CVV];

    (void)to;
    (void)q;
    if (cvv->code == 0 || g->have[slot * NALL + PT_STAGE_NDC]) slot++;
    g->cur = slot;
    g->t[slot] = t;
}

static void m_vertex(void *ud, const pt_vrec *r)
{
    mgot *g = ud;

    g->rec[g->cur * NALL + r->stage] = *r;
    g->have[g->cur * NALL + r->stage] = 1;
}

static void m_pixel(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                    size_t n)
{
    mgot *g = ud;
    size_t k;

    (void)seg;
    for (k = 0; k < n; k++)
        g->px[px[k].idx] = ((int64_t)m->color[0] << 16 | (int64_t)m->color[1] << 8 |
                            m->color[2]) + 1;
}

static int same4(const pt_dd *v, const pt_vrec *r)
{
    return same(v[0].hi, r->x) && same(v[1].hi, r->y) && same(v[2].hi, r->z) && same(v[3].hi, r->w);
}

static int same_pix(pt_pix p, const pt_vrec *r)
{
    return p.ok == !(r->flags & PT_REC_NULL) && (!p.ok || (p.x == r->ix && p.y == r->iy));
}

/* A journey from clip coordinates on against the records of one slot. */
static int same_tail(const pt_acc_mtail *t, const pt_vrec *r, const unsigned char *have)
{
    return have[PT_STAGE_NDC] && have[PT_STAGE_SCREEN] && have[PT_STAGE_VIEWPORT]
        && have[PT_STAGE_FRAMEBUFFER] && have[PT_STAGE_INDEX]
        && same(t->n[0].hi, r[PT_STAGE_NDC].x) && same(t->n[1].hi, r[PT_STAGE_NDC].y)
        && same(t->n[2].hi, r[PT_STAGE_NDC].z)
        && same(t->sc[0].hi, r[PT_STAGE_SCREEN].x) && same(t->sc[1].hi, r[PT_STAGE_SCREEN].y)
        && same(t->sc[2].hi, r[PT_STAGE_SCREEN].z)
        && same_pix(t->vp, &r[PT_STAGE_VIEWPORT]) && same_pix(t->fb, &r[PT_STAGE_FRAMEBUFFER])
        && (t->idx < 0) == !!(r[PT_STAGE_INDEX].flags & PT_REC_NULL)
        && (t->idx < 0 || t->idx == r[PT_STAGE_INDEX].i);
}

static int same_mat(const pt_dd_mat4 *a, const pt_mat4 *b)
{
    int i, j, ok = 1;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) ok &= same(a->m[i][j].hi, b->m[i][j]);
    return ok;
}

/* The largest distance between a's entries rounded to double and b's, in ulps
** of b's largest entry (an entry exactly 0 in one may be 1e-32 in the other). */
static double mat_ulps(const pt_dd_mat4 *a, const pt_mat4 *b)
{
    double worst = 0, big = 0, u;
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            if (fabs(a->m[i][j].hi - b->m[i][j]) > worst) worst = fabs(a->m[i][j].hi - b->m[i][j]);
            if (fabs(b->m[i][j]) > big) big = fabs(b->m[i][j]);
        }
    u = big > 0 ? ldexp(1.0, ilogb(big) - 52) : 0x1p-1074;
    return worst / u;
}

/* One matrix scene: the double matrices against the plan's, every used
** vertex's double journey and every segment's double clipping against the
** pipeline's records (all stages, every point clipping makes), and the double
** run's image against the pipeline's pixels. */
static void check_matrix_scene(const char *path)
{
    char err[PT_ERRLEN];
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    pt_acc_mcam *cd, *cr;
    pt_acc_run run;
    mgot g;
    size_t k, v, q, nv = 0, ns = 0, culled = 0, lit = 0;
    int e, bad_image = 0;

    if (pt_scene_load(&s, path, err, sizeof err) != 0) return;
    pt_options_default(&o);
    o.all_stages = 1;
    if (pt_plan_make(&p, &s, &o) != 0) { pt_scene_free(&s); return; }
    memset(&g, 0, sizeof g);
    g.s = &s;
    g.vbase = calloc(s.nmodels + 1, sizeof *g.vbase);
    g.sbase = calloc(s.nmodels + 1, sizeof *g.sbase);
    for (k = 0; k < s.nmodels; k++) {
        g.vbase[k] = nv; nv += s.models[k].nv;
        g.sbase[k] = ns; ns += s.models[k].nseg;
    }
    g.nvslots = nv;
    g.rec = calloc((nv + 2 * ns) * NALL + 1, sizeof *g.rec);
    g.have = calloc((nv + 2 * ns) * NALL + 1, 1);
    g.t = calloc(nv + 2 * ns + 1, sizeof *g.t);
    g.px = calloc((size_t)s.fb_w * (size_t)s.fb_h, sizeof *g.px);
    memset(&l, 0, sizeof l);
    l.vertex_begin = m_begin;
    l.clipvertex_begin = m_clipvertex;
    l.pixels = m_pixel;
    l.sink.vertex = m_vertex;
    l.sink.ud = &g;
    l.ud = &g;
    pt_run(&s, &p, &o, &l, NULL, &sum);
    cd = pt_acc_mcam_make(&s, PT_ARITH_DOUBLE);
    cr = pt_acc_mcam_make(&s, PT_ARITH_DD);
    mc.scenes++;

    for (k = 0; k < s.nmodels; k++) {
        const pt_model *m = &s.models[k];
        pt_dd_mat4 wd, vd, pd, wr, vr, pr;

        pt_acc_mcam_matrices(cd, k, &wd, &vd, &pd);
        pt_acc_mcam_matrices(cr, k, &wr, &vr, &pr);
        if (!same_mat(&wd, &p.models[k].world) || !same_mat(&vd, &p.view)
            || !same_mat(&pd, &p.proj)) {
            mc.bad_matrices++;
            printf("  %s: model %s: the double matrices are not the plan's\n", path, m->name);
        }
        if (mat_ulps(&wr, &p.models[k].world) > mc.ref_matrix_ulps)
            mc.ref_matrix_ulps = mat_ulps(&wr, &p.models[k].world);
        if (mat_ulps(&vr, &p.view) > mc.ref_matrix_ulps) mc.ref_matrix_ulps = mat_ulps(&vr, &p.view);
        if (mat_ulps(&pr, &p.proj) > mc.ref_matrix_ulps) mc.ref_matrix_ulps = mat_ulps(&pr, &p.proj);

        for (v = 0; v < m->nv; v++) {                   /* the vertices */
            size_t slot = g.vbase[k] + v;
            const pt_vrec *r = &g.rec[slot * NALL];
            const unsigned char *have = &g.have[slot * NALL];
            pt_acc_mjourney j;
            int ok;

            if (!have[PT_STAGE_CVV]) continue;          /* not used: not transformed */
            pt_acc_mjourney_of(cd, k, m->v[v], &j);
            ok = same(j.m[0].hi, r[PT_STAGE_MODEL].x) && same(j.m[1].hi, r[PT_STAGE_MODEL].y)
              && same(j.m[2].hi, r[PT_STAGE_MODEL].z)
              && have[PT_STAGE_WORLD] && same4(j.w, &r[PT_STAGE_WORLD])
              && have[PT_STAGE_VIEW] && same4(j.v, &r[PT_STAGE_VIEW])
              && have[PT_STAGE_CLIP] && same4(j.k, &r[PT_STAGE_CLIP])
              && j.code == r[PT_STAGE_CVV].code
              && (j.code ? !have[PT_STAGE_NDC] : same_tail(&j.t, r, have));
            mc.vertices++;
            if (!ok) { mc.bad_vertices++; printf("  %s: model %s vertex %zu differs\n", path, m->name, v + 1); }
        }
        for (q = 0; q < m->nseg; q++) {                 /* the points clipping makes */
            pt_acc_mjourney ja, jb;
            pt_acc_mseg sg;

            pt_acc_mjourney_of(cd, k, m->v[m->seg[q].a], &ja);
            pt_acc_mjourney_of(cd, k, m->v[m->seg[q].b], &jb);
            pt_acc_mseg_of(cd, &ja, &jb, &sg);
            culled += !sg.visible;
            for (e = 0; e < 2; e++) {
                size_t slot = g.nvslots + 2 * (g.sbase[k] + q) + (size_t)e;
                const unsigned char *have = &g.have[slot * NALL];

                if (!sg.made[e] && !have[PT_STAGE_NDC]) continue;
                mc.points++;
                if (!sg.made[e] || !same(sg.t[e].hi, g.t[slot])
                    || !same_tail(&sg.end[e], &g.rec[slot * NALL], have)) {
                    mc.bad_points++;
                    printf("  %s: model %s segment %zu end %d: the clipping differs\n", path,
                           m->name, q + 1, e);
                }
            }
        }
    }
    if (culled != sum.segments_culled) mc.bad_culled++;

    if (pt_acc_run_make(&run, &s, PT_ARITH_DOUBLE, 0) == 0) {   /* the image */
        for (q = 0; q < run.nimg; q++)
            bad_image |= g.px[run.img[q].idx] != (int64_t)run.img[q].rgb + 1;
        for (q = 0; q < (size_t)s.fb_w * (size_t)s.fb_h; q++) lit += g.px[q] != 0;
        bad_image |= lit != run.nimg;
        mc.pixels += lit;
        pt_acc_run_free(&run);
    } else bad_image = 1;
    if (bad_image) { mc.bad_images++; printf("  %s: the double image differs\n", path); }

    pt_acc_mcam_free(cd);
    pt_acc_mcam_free(cr);
    free(g.vbase); free(g.sbase); free(g.rec); free(g.have); free(g.t); free(g.px);
    pt_plan_free(&p);
    pt_scene_free(&s);
}

/* One scene: the double journey of every used vertex against the stages'
** records, and every segment's double DDA against src/core/raster.c. */
static void check_scene(const char *path, size_t *nvertices, size_t *nsegments,
                        size_t *bad_vertices, size_t *bad_segments)
{
    char err[PT_ERRLEN];
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    got g;
    size_t k, v, q, nv = 0;

    if (pt_scene_load(&s, path, err, sizeof err) != 0) return;
    if (s.pipe == PT_PIPE_MATRIX) { pt_scene_free(&s); check_matrix_scene(path); return; }
    pt_options_default(&o);
    o.all_stages = 1;
    o.trace_raster = 0;
    o.rasterize = 0;
    if (pt_plan_make(&p, &s, &o) != 0) { pt_scene_free(&s); return; }
    memset(&g, 0, sizeof g);
    g.s = &s;
    g.base = calloc(s.nmodels + 1, sizeof *g.base);
    for (k = 0; k < s.nmodels; k++) { g.base[k] = nv; nv += s.models[k].nv; }
    g.rec = calloc(nv * PT_NSTAGES_ALL + 1, sizeof *g.rec);
    g.have = calloc(nv * PT_NSTAGES_ALL + 1, 1);
    memset(&l, 0, sizeof l);
    l.vertex_begin = on_begin;
    l.sink.vertex = on_vertex;
    l.sink.ud = &g;
    l.ud = &g;
    pt_run(&s, &p, &o, &l, NULL, &sum);

    for (k = 0; k < s.nmodels; k++) {
        const pt_model *m = &s.models[k];

        for (v = 0; v < m->nv; v++) {
            const pt_vrec *r = &g.rec[(g.base[k] + v) * PT_NSTAGES_ALL];
            const unsigned char *have = &g.have[(g.base[k] + v) * PT_NSTAGES_ALL];
            pt_acc_journey j;
            int ok;

            if (!have[PT_STAGE_INDEX]) continue;    /* not used: not transformed */
            pt_acc_journey_of(PT_ARITH_DOUBLE, 0, &s, m, m->v[v], &j);
            ok = same(j.c[0].hi, r[PT_STAGE_CAMERA].x) && same(j.c[1].hi, r[PT_STAGE_CAMERA].y)
              && same(j.c[2].hi, r[PT_STAGE_CAMERA].z)
              && same(j.ip[0].hi, r[PT_STAGE_IMAGE].x) && same(j.ip[1].hi, r[PT_STAGE_IMAGE].y)
              && same(j.pp[0].hi, r[PT_STAGE_PIXEL].x) && same(j.pp[1].hi, r[PT_STAGE_PIXEL].y)
              && j.vp.ok == !(r[PT_STAGE_VIEWPORT].flags & PT_REC_NULL)
              && (!j.vp.ok || (j.vp.x == r[PT_STAGE_VIEWPORT].ix
                               && j.vp.y == r[PT_STAGE_VIEWPORT].iy))
              && j.fb.ok == !(r[PT_STAGE_FRAMEBUFFER].flags & PT_REC_NULL)
              && (!j.fb.ok || (j.fb.x == r[PT_STAGE_FRAMEBUFFER].ix
                               && j.fb.y == r[PT_STAGE_FRAMEBUFFER].iy))
              && (j.idx < 0) == !!(r[PT_STAGE_INDEX].flags & PT_REC_NULL)
              && (j.idx < 0 || j.idx == r[PT_STAGE_INDEX].i);
            (*nvertices)++;
            if (!ok) { (*bad_vertices)++; printf("  %s: model %s vertex %zu differs\n", path, m->name, v + 1); }
        }
        for (q = 0; q < m->nseg; q++) {
            const pt_vrec *a = &g.rec[(g.base[k] + m->seg[q].a) * PT_NSTAGES_ALL + PT_STAGE_PIXEL];
            const pt_vrec *b = &g.rec[(g.base[k] + m->seg[q].b) * PT_NSTAGES_ALL + PT_STAGE_PIXEL];
            pt_vec2 p0 = {a->x, a->y}, p1 = {b->x, b->y};

            (*nsegments)++;
            if (!dda_agrees(p0, p1, s.vp_w, s.vp_h)) {
                (*bad_segments)++;
                printf("  %s: model %s segment %zu: pixels differ\n", path, m->name, q + 1);
            }
        }
    }
    free(g.base); free(g.rec); free(g.have);
    pt_plan_free(&p);
    pt_scene_free(&s);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static void check_dir(const char *dir, size_t *nscenes, size_t *nv, size_t *ns,
                      size_t *bv, size_t *bs)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char *names[4096], path[4096];
    size_t n = 0, k;

    while (d && (e = readdir(d)) != NULL && n < 4096) {
        size_t len = strlen(e->d_name);
        if (len > 6 && strcmp(e->d_name + len - 6, ".scene") == 0) {
            names[n] = malloc(len + 1);
            memcpy(names[n], e->d_name, len + 1);
            n++;
        }
    }
    if (d) closedir(d);
    qsort(names, n, sizeof names[0], by_name);
    for (k = 0; k < n; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, names[k]);
        check_scene(path, nv, ns, bv, bs);
        free(names[k]);
    }
    *nscenes += n;
}

/* ===== the DDAs on random segments ===== */

static uint64_t rng = 0x9e3779b97f4a7c15ULL;

static double uniform(double lo, double hi)     /* xorshift64*, reproducible */
{
    rng ^= rng >> 12; rng ^= rng << 25; rng ^= rng >> 27;
    return lo + (hi - lo) * (double)((rng * 2685821657736338717ULL) >> 11) * 0x1p-53;
}

static float jround_f(float x)                  /* Java's Math.round, in float */
{
    float r = floorf(x);
    return x - r >= 0.5f ? r + 1.0f : r;
}

/* The plain float DDA: every step, y += m in float, no fast-forward. */
static void plain_float_dda(float px0, float py0, float px1, float py1, int w, int h,
                            pixels *out)
{
    float x0 = jround_f(px0), y0 = jround_f(py0), x1 = jround_f(px1), y1 = jround_f(py1);
    float m, acc, t;
    int tr;
    int64_t s;

    if (x0 == x1 && y0 == y1) {
        int64_t xv = (int64_t)x0 - 1, yv = h - (int64_t)y0;
        if (xv >= 0 && xv < w && yv >= 0 && yv < h) px_add(out, xv, yv);
        return;
    }
    tr = fabsf(y1 - y0) > fabsf(x1 - x0);
    if (tr) { t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; }
    m = (y1 - y0) / (x1 - x0);
    acc = y0;
    for (s = (int64_t)x0; s <= (int64_t)x1; s++) {
        int64_t r = (int64_t)jround_f(acc);
        int64_t xv = tr ? r - 1 : s - 1, yv = tr ? h - s : h - r;

        if (xv >= 0 && xv < w && yv >= 0 && yv < h) px_add(out, xv, yv);
        acc += m;
    }
}

/* The exact DDA in integers: at step s, y = y0 + (s - s0) * dy / ds exactly,
** rounded the Java way: floor((2 * num + den) / (2 * den)). */
static void exact_dda(int64_t x0, int64_t y0, int64_t x1, int64_t y1, int w, int h,
                      pixels *out)
{
    int64_t s, t;
    int tr;

    if (x0 == x1 && y0 == y1) {
        if (x0 - 1 >= 0 && x0 - 1 < w && h - y0 >= 0 && h - y0 < h) px_add(out, x0 - 1, h - y0);
        return;
    }
    tr = llabs(y1 - y0) > llabs(x1 - x0);
    if (tr) { t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; }
    for (s = x0; s <= x1; s++) {
        int64_t num = y0 * (x1 - x0) + (s - x0) * (y1 - y0), den = x1 - x0;
        int64_t a = 2 * num + den, b = 2 * den;
        int64_t r = a >= 0 ? a / b : -((-a + b - 1) / b);      /* floor(a / b) */
        int64_t xv = tr ? r - 1 : s - 1, yv = tr ? h - s : h - r;

        if (xv >= 0 && xv < w && yv >= 0 && yv < h) px_add(out, xv, yv);
    }
}

static void test_random_ddas(void)
{
    int k, bad_d = 0, bad_f = 0, bad_x = 0, w = 37, h = 23;

    for (k = 0; k < 3000; k++) {                    /* double: src/core/raster.c */
        double far = k % 3 == 0 ? 1e5 : k % 3 == 1 ? 1e4 : 100;
        pt_vec2 p0 = {uniform(-far, w + 1), uniform(-10, h + 10)};
        pt_vec2 p1 = {uniform(-5, w + far), uniform(-h, 2 * h)};
        if (k % 2) { double t = p0.x; p0.x = p0.y; p0.y = t; t = p1.x; p1.x = p1.y; p1.y = t; }
        if (!dda_agrees(p0, p1, w, h)) bad_d++;
    }
    PT_CHECK("acc-4.1 the double DDA lights the plain step-by-step loop's pixels (3000 random segments)",
             bad_d == 0);

    for (k = 0; k < 600; k++) {                     /* float: the plain loop */
        float far = k % 2 ? 1e5f : 50.0f;
        float x0 = (float)uniform(-(double)far, w + 1), y0 = (float)uniform(-10, h + 10);
        float x1 = (float)uniform(-5, w + (double)far), y1 = (float)uniform(-h, 2 * h);

        if (k % 4 == 3) { float t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
        pa.n = pb.n = 0; pa.over = pb.over = 0;
        plain_float_dda(x0, y0, x1, y1, w, h, &pa);
        pt_acc_raster_segment(PT_ARITH_FLOAT, 0, pt_dd_from((double)x0), pt_dd_from((double)y0),
                              pt_dd_from((double)x1), pt_dd_from((double)y1), w, h, px_add, &pb);
        if (!same_pixels(&pa, &pb)) bad_f++;
    }
    PT_CHECK("acc-4.2 the float DDA, fast-forward included, lights the plain float "
             "loop's pixels (600 random segments, up to 1e5 steps)", bad_f == 0);

    for (k = 0; k < 3000; k++) {                    /* reference: the exact line */
        int64_t x0 = (int64_t)uniform(-60, 60), y0 = (int64_t)uniform(-40, 60);
        int64_t x1 = (int64_t)uniform(-60, 100), y1 = (int64_t)uniform(-40, 60);

        pa.n = pb.n = 0; pa.over = pb.over = 0;
        exact_dda(x0, y0, x1, y1, w, h, &pa);
        pt_acc_raster_segment(PT_ARITH_DD, 0, pt_dd_from((double)x0), pt_dd_from((double)y0),
                              pt_dd_from((double)x1), pt_dd_from((double)y1), w, h, px_add, &pb);
        if (!same_pixels(&pa, &pb)) bad_x++;
    }
    PT_CHECK("acc-4.3 the reference DDA lights the exact line's pixels, ties "
             "included (3000 random integer segments)", bad_x == 0);

    pa.n = pb.n = 0;
    pt_acc_raster_segment(PT_ARITH_DD, 0, pt_dd_from(1), pt_dd_from(1), pt_dd_from(7),
                          pt_dd_from(2), 10, 10, px_add, &pa);
    PT_CHECK("acc-4.4 (1,1)-(7,2): at x = 4, y = 1.5 exactly rounds up to 2",
             pa.n == 7 && pa.xy[6] == 3 && pa.xy[7] == 8);
}

/* ===== what pt_acc_compare() reports ===== */

static int load(pt_scene *s, const char *path)
{
    char err[PT_ERRLEN];
    int rc = pt_scene_load(s, path, err, sizeof err);

    if (rc != 0) printf("  %s\n", err);
    return rc == 0;
}

/* The reference, float and double runs of s, and float's (e) and double's
** (ed) errors against the reference. */
static void runs3(const pt_scene *s, pt_acc_run *ref, pt_acc_run *f, pt_acc_run *d,
                  pt_acc_err e[PT_ACC_MAXROWS], pt_acc_err ed[PT_ACC_MAXROWS])
{
    pt_acc_run_make(ref, s, PT_ARITH_DD, 0);
    pt_acc_run_make(f, s, PT_ARITH_FLOAT, 0);
    pt_acc_run_make(d, s, PT_ARITH_DOUBLE, 0);
    pt_acc_compare(ref, f, e);
    pt_acc_compare(ref, d, ed);
}

static void test_compare(void)
{
    pt_scene s;
    pt_acc_run ref, f, d, two;
    pt_acc_err e[PT_ACC_MAXROWS], ed[PT_ACC_MAXROWS];
    int row, zero = 1;

    PT_CHECK("acc-5.0 loads tests/extreme/cancel-translate.scene",
             load(&s, "tests/extreme/cancel-translate.scene"));
    runs3(&s, &ref, &f, &d, e, ed);
    PT_CHECK("acc-5.1 cancel-translate: float's model stage has an error (1000000000.1 "
             "is not a float)", e[PT_ACC_MODEL].max_abs > 0 && e[PT_ACC_MODEL].differ == 1);
    PT_CHECK("acc-5.2 ... and its camera x_c is off by about 0.1 (cancellation)",
             e[PT_ACC_CAMERA].max_abs > 0.05 && e[PT_ACC_CAMERA].max_abs < 0.2);
    PT_CHECK("acc-5.3 double: x_c = x_m + x_t is exactly rounded, so no error",
             ed[PT_ACC_CAMERA].max_abs == 0 && ed[PT_ACC_CAMERA].differ == 0);
    PT_CHECK("acc-5.4 reference: 2 used vertices", e[PT_ACC_MODEL].of == 2);
    pt_acc_run_free(&ref); pt_acc_run_free(&f); pt_acc_run_free(&d);
    pt_scene_free(&s);

    PT_CHECK("acc-5.5 loads tests/extreme/corner-plus-one.scene",
             load(&s, "tests/extreme/corner-plus-one.scene"));
    pt_acc_run_make(&ref, &s, PT_ARITH_DD, 0);
    pt_acc_run_make(&d, &s, PT_ARITH_DOUBLE, 0);
    pt_acc_run_make(&two, &s, PT_ARITH_DOUBLE, PT_ACC_TWO);
    pt_acc_compare(&ref, &d, ed);
    pt_acc_compare(&ref, &two, e);
    PT_CHECK("acc-5.6 corner-plus-one: with 2.001 the corner x_ip = 1 stays inside",
             ed[PT_ACC_VIEWPORT].left == 0 && ed[PT_ACC_VIEWPORT].differ == 0);
    PT_CHECK("acc-5.7 ... with 2.0 it leaves the viewport", e[PT_ACC_VIEWPORT].left == 1);
    pt_acc_compare(&ref, &ref, e);
    for (row = 0; row < PT_ACC_NROWS; row++)
        zero &= e[row].max_abs == 0 && e[row].differ == 0;
    PT_CHECK("acc-5.8 the reference against itself: no error anywhere", zero);
    pt_acc_run_free(&ref); pt_acc_run_free(&d); pt_acc_run_free(&two);
    pt_scene_free(&s);
}

/* The matrix camera: what pt_acc_compare() reports, and the reference's ties. */
static void test_mcompare(void)
{
    static const char target[] =            /* the look-at target is a vertex */
        "framebuffer 64 48\nviewport 4 4 56 40\n"
        "camera lookat-target 3 2 -6  0 0 0  0 1 0\n"
        "projection perspective 60 auto 0.5 50\n"
        "model m\nv 0 0 0\nv 1 1 1\nl 1 2\n";
    char err[PT_ERRLEN];
    pt_scene s;
    pt_acc_run ref, f, d;
    pt_acc_err e[PT_ACC_MAXROWS], ed[PT_ACC_MAXROWS];
    int row, zero = 1;

    PT_CHECK("acc-8.0 loads docs/examples/lookat-near.scene",
             load(&s, "docs/examples/lookat-near.scene"));
    runs3(&s, &ref, &f, &d, e, ed);
    PT_CHECK("acc-8.1 lookat-near: the reference clips 2 ends, culls nothing",
             ref.made == 2 && ref.culled == 0 && d.made == 2 && f.made == 2);
    PT_CHECK("acc-8.2 ... float's clip stage errs (1/aspect = 3/4 of a rounded 4/3), "
             "below 1e-5", e[PT_ACC_M_CLIP].max_abs > 0 && e[PT_ACC_M_CLIP].max_abs < 1e-5);
    PT_CHECK("acc-8.3 ... double's world..clip within 2 ulps",
             ed[PT_ACC_M_WORLD].max_ulp <= 2 && ed[PT_ACC_M_VIEW].max_ulp <= 2
             && ed[PT_ACC_M_CLIP].max_ulp <= 2);
    PT_CHECK("acc-8.4 ... no outcode differs; ndc..index compare 1 vertex + 2 points",
             e[PT_ACC_M_CVV].differ == 0 && ed[PT_ACC_M_CVV].differ == 0
             && e[PT_ACC_M_CVV].of == 3 && ed[PT_ACC_M_VIEWPORT].of == 3
             && e[PT_ACC_M_CVV].n == 0);
    PT_CHECK("acc-8.5 ... no pixel differs", e[PT_ACC_M_RASTER].differ == 0
             && ed[PT_ACC_M_RASTER].differ == 0 && ed[PT_ACC_M_RASTER].of > 20);
    pt_acc_compare(&ref, &ref, e);
    for (row = 0; row < PT_ACC_M_NROWS; row++)
        zero &= e[row].max_abs == 0 && e[row].differ == 0;
    PT_CHECK("acc-8.6 the reference against itself: no error anywhere", zero);
    pt_acc_run_free(&ref); pt_acc_run_free(&f); pt_acc_run_free(&d);
    pt_scene_free(&s);

    PT_CHECK("acc-8.7 loads tests/data/near-tie.scene", load(&s, "tests/data/near-tie.scene"));
    runs3(&s, &ref, &f, &d, e, ed);
    PT_CHECK("acc-8.8 near-tie: the reference keeps the vertex on the near plane inside, "
             "z_k = 0 exactly", ref.mj[0][0].code == 0 && ref.mj[0][0].k[2].hi == 0
             && ref.mj[0][0].k[2].lo == 0);
    PT_CHECK("acc-8.9 ... double's z_k < 0 puts it outside: 1 outcode differs, clipping "
             "makes a point", d.mj[0][0].code == PT_CVV_NEAR && ed[PT_ACC_M_CVV].differ == 1
             && d.made == 1 && ref.made == 0);
    PT_CHECK("acc-8.10 ... the vertex's pixel and the new point's exist on one side only: "
             "inf, 2 of 3 differ", isinf(ed[PT_ACC_M_VIEWPORT].max_abs)
             && ed[PT_ACC_M_VIEWPORT].differ == 2 && ed[PT_ACC_M_VIEWPORT].of == 3);
    PT_CHECK("acc-8.11 ... float keeps it inside; no pixel differs",
             e[PT_ACC_M_CVV].differ == 0 && e[PT_ACC_M_RASTER].differ == 0);
    pt_acc_run_free(&ref); pt_acc_run_free(&f); pt_acc_run_free(&d);
    pt_scene_free(&s);

    PT_CHECK("acc-8.12 parses a scene whose look-at target is a vertex",
             pt_scene_parse(&s, "target", target, sizeof target - 1, err, sizeof err) == 0);
    pt_acc_run_make(&ref, &s, PT_ARITH_DD, 0);
    pt_acc_run_make(&d, &s, PT_ARITH_DOUBLE, 0);
    PT_CHECK("acc-8.13 the target's view x and y are 0 in the reference (-eye.u is 0 "
             "exactly, 1e-32 in double-double)", ref.mj[0][0].v[0].hi == 0
             && ref.mj[0][0].v[1].hi == 0 && ref.mj[0][0].v[1].lo == 0);
    PT_CHECK("acc-8.14 ... so it lands on the screen's centre, pixel (28, 20), like double's",
             ref.mj[0][0].t.vp.x == 28 && ref.mj[0][0].t.vp.y == 20
             && d.mj[0][0].t.vp.x == 28 && d.mj[0][0].t.vp.y == 20);
    pt_acc_run_free(&ref); pt_acc_run_free(&d);
    pt_scene_free(&s);
}

/* ===== the timed stages are the error runs' (pt_acc_work) ===== */

static int same_dd(const pt_dd *a, const pt_dd *b, size_t n)     /* bit for bit */
{
    return memcmp(a, b, n * sizeof *a) == 0;
}

static int same_px(pt_pix a, pt_pix b)
{
    return a.x == b.x && a.y == b.y && a.ok == b.ok;
}

static int same_journey(const pt_acc_journey *a, const pt_acc_journey *b)
{
    return same_dd(a->m, b->m, 3) && same_dd(a->c, b->c, 3) && same_dd(a->ip, b->ip, 2)
           && same_dd(a->pp, b->pp, 2) && same_px(a->vp, b->vp) && same_px(a->fb, b->fb)
           && a->idx == b->idx;
}

static int same_front(const pt_acc_mjourney *a, const pt_acc_mjourney *b)
{
    return same_dd(a->m, b->m, 3) && same_dd(a->w, b->w, 4) && same_dd(a->v, b->v, 4)
           && same_dd(a->k, b->k, 4) && !memcmp(a->kerr, b->kerr, sizeof a->kerr)
           && a->code == b->code;
}

static int same_mtail(const pt_acc_mtail *a, const pt_acc_mtail *b)
{
    return same_dd(a->n, b->n, 3) && same_dd(a->sc, b->sc, 3) && same_px(a->vp, b->vp)
           && same_px(a->fb, b->fb) && a->idx == b->idx && same_dd(a->pp, b->pp, 2);
}

/* Run rows first .. last of work w one at a time, after poisoning it when
** poison is set, and compare every input with run r's journey: 1 when all
** agree bit for bit.  *n counts the inputs. */
static int stages_agree(const pt_acc_run *r, pt_acc_work *w, int first, int last, int poison,
                        size_t *n)
{
    const pt_scene *s = r->s;
    size_t k, v, i = 0;
    int row, ok = 1;

    if (poison) pt_acc_work_poison(w);
    for (row = first; row <= last; row++) pt_acc_stage_pass(w, row);
    for (k = 0; k < s->nmodels; k++)
        for (v = 0; v < s->models[k].nv; v++) {
            if (!r->used[k][v]) continue;
            if (!(s->pipe == PT_PIPE_MATRIX)) ok &= same_journey(pt_acc_work_journey(w, i++), &r->j[k][v]);
            else if (first < PT_ACC_M_NDC)
                ok &= same_front(pt_acc_work_mjourney(w, i++), &r->mj[k][v]);
            else if (r->mj[k][v].code == 0)
                ok &= same_mtail(pt_acc_work_mtail(w, i++), &r->mj[k][v].t);
        }
    *n += i;
    return ok && i == pt_acc_work_size(w);
}

static void test_work(void)
{
    static const char *const scenes[] = {
        "docs/examples/cube.scene", "docs/examples/lookat-cube.scene",
        "docs/examples/lookat-near.scene", "tests/extreme/cancel-translate.scene"
    };
    static const struct { pt_arith a; unsigned choices; } runs[] = {
        { PT_ARITH_FLOAT, 0 }, { PT_ARITH_DOUBLE, 0 }, { PT_ARITH_DD, 0 },
        { PT_ARITH_DOUBLE, PT_ACC_TWO }, { PT_ARITH_FLOAT, PT_ACC_TWO }
    };
    size_t si, ri, n = 0, nagain = 0, bad = 0, badagain = 0, classic = 0, matrix = 0;
    char descr[200];
    pt_scene s;

    for (si = 0; si < sizeof scenes / sizeof scenes[0]; si++) {
        if (!load(&s, scenes[si])) { bad++; continue; }
        for (ri = 0; ri < sizeof runs / sizeof runs[0]; ri++) {
            pt_acc_run r;
            int part, row, first, last;

            if (pt_acc_run_make(&r, &s, runs[ri].a, runs[ri].choices) != 0) { bad++; continue; }
            for (part = 0; part < ((s.pipe == PT_PIPE_MATRIX) ? 2 : 1); part++) {
                first = (s.pipe == PT_PIPE_MATRIX) && part ? PT_ACC_M_NDC : 0;
                last = !(s.pipe == PT_PIPE_MATRIX) ? PT_ACC_INDEX : part ? PT_ACC_M_INDEX : PT_ACC_M_CVV;
                {                       /* all the stages, one at a time, from garbage */
                    pt_acc_work *w = pt_acc_work_make(&r, first);

                    if (!w || !stages_agree(&r, w, first, last, 1, &n)) bad++;
                    pt_acc_work_free(w);
                }
                for (row = first; row <= last; row++) {    /* each alone, as timed */
                    pt_acc_work *w = pt_acc_work_make(&r, row);

                    if (!w || !stages_agree(&r, w, row, row, 0, &nagain)) badagain++;
                    pt_acc_work_free(w);
                }
            }
            if (s.pipe == PT_PIPE_MATRIX) matrix++; else classic++;
            pt_acc_run_free(&r);
        }
        pt_scene_free(&s);
    }
    snprintf(descr, sizeof descr, "acc-7.1 the stages the timing runs one at a time, from "
             "garbage, rebuild the error runs' journeys bit for bit (%zu classic runs, %zu "
             "matrix runs, %zu journeys)", classic, matrix, n);
    PT_CHECK(descr, bad == 0 && classic >= 10 && matrix >= 10 && n > 100);
    snprintf(descr, sizeof descr, "acc-7.2 a timed pass of one stage over its inputs "
             "rewrites the same values (%zu inputs)", nagain);
    PT_CHECK(descr, badagain == 0 && nagain > n);
}

/* pt_acc_vp_of() is the reference viewport stage on whole numbers, and its
** formula written out beyond 2^53 gives what exact integers give. */
static void test_vp_of(void)
{
    static const int64_t e53 = (int64_t)1 << 53;
    static const int64_t xs[] = {1, 0, -1, 2, 320, 321, 12345, -98765, ((int64_t)1 << 53) - 1,
                                 -(((int64_t)1 << 53) - 1)};
    pt_scene s;
    size_t i, j;
    int same = 1, beyond, none;

    memset(&s, 0, sizeof s);
    s.vp_w = 320;
    s.vp_h = 240;
    for (i = 0; i < sizeof xs / sizeof xs[0]; i++)
        for (j = 0; j < sizeof xs / sizeof xs[0]; j++) {
            pt_vec2 pp = {(double)xs[i], (double)xs[j]};
            pt_pix a = pt_acc_vp_of(&s, 1, xs[i], xs[j]);
            pt_pix b = ptref_pixel2viewport(pp, s.vp_w, s.vp_h, NULL);
            same &= a.ok == b.ok && a.x == b.x && a.y == b.y;
        }
    PT_CHECK("acc-9.1 accuracy's viewport pixel is the reference stage's on whole numbers", same);
    {
        pt_pix a = pt_acc_vp_of(&s, 1, e53 + 1, -e53 - 3);
        beyond = a.ok && a.x == e53 && a.y == 240 + e53 + 3;
    }
    PT_CHECK("acc-9.2 ... and beyond 2^53, exact: x_vp = rx - 1, y_vp = h - ry", beyond);
    none = !pt_acc_vp_of(&s, 0, 5, 5).ok;
    PT_CHECK("acc-9.3 ... and no pixel where round() gave none", none);
}

/* Every pipeline has a row table (pt_acc_rows_of[]) whose rows are its order,
** stage for stage, then the rasterizer's: what accuracy knows of a pipeline
** is that table. */
static void test_rows(void)
{
    int p, i, have = 1, cover = 1, sane = 1;
    char descr[160];

    for (p = 0; p < PT_NPIPES; p++) {
        const pt_pipeline *pl = pt_pipelines[p];
        const pt_acc_rows *rows = &pt_acc_rows_of[pl->id];

        if (!rows->row || rows->nrows < 1) { have = 0; continue; }
        cover &= rows->nrows == pl->norder + 1 && rows->nrows <= PT_ACC_MAXROWS
                 && rows->row[rows->nrows - 1].stage == -1
                 && rows->row[rows->nrows - 1].fn == PT_ACC_FN_RASTER;
        for (i = 0; i < pl->norder && i < rows->nrows; i++)
            cover &= rows->row[i].stage == (int)pl->order[i]
                     && rows->row[i].fn != PT_ACC_FN_RASTER;
        for (i = 0; i < rows->nrows; i++)
            sane &= rows->row[i].name && rows->row[i].panel >= -1
                    && rows->row[i].panel < PT_ACC_NPANELS;
        sane &= pt_acc_row_of(rows, PT_STAGE_VIEWPORT) >= 0 && pt_acc_last_real(rows) >= 0
                && (pt_acc_row_varied(rows, PT_ACC_TWO) >= 0 || rows->no_two) && rows->no_plot;
        for (i = 0; i < PT_ACC_NPANELS; i++) sane &= rows->panel_sub[i] != NULL;
    }
    snprintf(descr, sizeof descr, "acc-10.1 each of the %d pipelines has a row table", PT_NPIPES);
    PT_CHECK(descr, have);
    PT_CHECK("acc-10.2 ... whose rows are its order, stage for stage, then the rasterizer", cover);
    PT_CHECK("acc-10.3 ... with names, panels, a viewport row and a last real row", sane);
}

/* ===== renderers 7 and 9 ===== */

/* The formula copies of acc_rv_tmpl.h, instantiated in double: each must
** give its stage's result bit for bit (float and double-double run the same
** text). */
#define RV_T double
#define RV_NUM(x) (x)
#define RV_ADD(a, b) ((a) + (b))
#define RV_SUB(a, b) ((a) - (b))
#define RV_MUL(a, b) ((a) * (b))
#define RV_DIV(a, b) ((a) / (b))
#define RV_NEG(a) (-(a))
#define RV_GT(a, b) ((a) > (b))
#define RV_LE(a, b) ((a) <= (b))
#define RV_FN(name) rvt_##name
#include "tools/accuracy/acc_rv_tmpl.h"

static uint64_t rv_seed = 0x9e3779b97f4a7c15ULL;

/* A random double: mostly of a few binades either side of 1, sometimes one
** of the edges the stages test against (0, -0, +-1, +-0.1, a value a step
** beside them). */
static double rv_rand(void)
{
    static const double edge[] = {0.0, -0.0, 1.0, -1.0, -0.1, 0.1, 0x1.0000000000001p0,
                                  -0x1.0000000000001p0, 0x1.fffffffffffffp-1, 2.0, -2.0};
    uint64_t u;
    double f;

    rv_seed = rv_seed * 6364136223846793005ULL + 1442695040888963407ULL;
    u = rv_seed >> 11;
    if (u % 8 == 0) return edge[(u >> 3) % (sizeof edge / sizeof edge[0])];
    f = (double)(u >> 8) / 0x1p45 - 0.5;                /* -0.5 .. 0.5 */
    return ldexp(f, (int)((u >> 3) % 9) - 2);           /* |x| < 64 */
}

static int same_d(double a, double b)
{
    return (isnan(a) && isnan(b)) || (a == b && signbit(a) == signbit(b));
}

static int same_v4(pt_vec4 a, const double b[], int n)
{
    double v[4];
    int k, ok = 1;

    v[0] = a.x; v[1] = a.y; v[2] = a.z; v[3] = a.w;
    for (k = 0; k < n; k++) ok &= same_d(v[k], b[k]);
    return ok;
}

static pt_vec4 v4(double x, double y, double z, double w)
{
    pt_vec4 v;

    v.x = x; v.y = y; v.z = z; v.w = w;
    return v;
}

/* What the clip stages' listener hears of one segment. */
typedef struct rv_heard {
    pt_rv_cut cut[70];
    int ncuts, accepted;
    pt_vec4 ends[2];
} rv_heard;

static void rv_hear_cut(void *ud, const pt_rv_cut *c)
{
    rv_heard *h = ud;

    if (h->ncuts < 70) h->cut[h->ncuts] = *c;
    h->ncuts++;
}

static void rv_hear_end(void *ud, const pt_rv_model *m, const pt_rv_prim *p, int accepted)
{
    rv_heard *h = ud;

    h->accepted = accepted;
    if (accepted) { h->ends[0] = m->v[p->v[0]]; h->ends[1] = m->v[p->v[1]]; }
}

/* The segment a-b through a clip stage (near: at z = n; else the square). */
static int rv_stage_clip(pt_vec4 a, pt_vec4 b, int near, double n, rv_heard *h)
{
    pt_rv_model m;
    pt_rv_prim p;
    pt_rgb white = {1.0f, 1.0f, 1.0f};
    pt_rv_clip_ls ls = {NULL, NULL, rv_hear_cut, rv_hear_end, NULL};
    int rc;

    memset(&m, 0, sizeof m);
    memset(&p, 0, sizeof p);
    memset(h, 0, sizeof *h);
    ls.ud = h;
    p.kind = PT_RV_LINE;
    p.v[1] = p.c[1] = 1;
    if (pt_rv_add_vertex(&m, a) || pt_rv_add_vertex(&m, b) || pt_rv_add_color(&m, white)
        || pt_rv_add_color(&m, white) || pt_rv_add_prim(&m, &p)) rc = -1;
    else rc = near ? pt_rv_nearclip(&m, n, &ls) : pt_rv_clip(&m, &ls);
    pt_rv_model_free(&m);
    return rc;
}

static void test_rv_copies(void)
{
    size_t i, n = 20000;
    int bad[9] = {0}, k, j, cuts = 0, nearcuts = 0, trivial = 0;

    for (i = 0; i < n; i++) {
        double m[4], t[3], o[4], l, r, b, tt, mat[4][4], nm[4][4];
        int persp = (int)(i % 2), off = 0;
        pt_rv_camera cam;
        pt_jmat jm, jn;
        pt_vec4 sv;
        pt_vec3 tv;

        for (k = 0; k < 4; k++) m[k] = rv_rand();
        for (k = 0; k < 3; k++) t[k] = rv_rand();
        tv.x = t[0]; tv.y = t[1]; tv.z = t[2];
        rvt_r7_view(m, t, o);                           /* r7 view */
        bad[0] += !same_v4(pt_r7_model2view(v4(m[0], m[1], m[2], 1.0), tv), o, 3);
        l = rv_rand(); r = rv_rand(); b = rv_rand(); tt = rv_rand();
        memset(&cam, 0, sizeof cam);
        cam.perspective = persp;
        cam.l = l; cam.r = r; cam.b = b; cam.t = tt;
        rvt_r7_camera(m, persp, l, r, b, tt, o);        /* r7 camera */
        bad[1] += !same_v4(pt_r7_view2camera(v4(m[0], m[1], m[2], 1.0), &cam), o, 3);
        rvt_r9_normalize(persp, l, r, b, tt, nm);       /* r9 normalize matrix */
        jn = pt_r9_normalize_matrix(&cam);
        for (j = 0; j < 4; j++) {
            double col[4] = {nm[0][j], nm[1][j], nm[2][j], nm[3][j]};

            bad[2] += !same_v4(jn.col[j], col, 4);
        }
        for (k = 0; k < 16; k++) mat[k / 4][k % 4] = rv_rand();   /* r9 world: M v */
        for (j = 0; j < 4; j++) jm.col[j] = v4(mat[0][j], mat[1][j], mat[2][j], mat[3][j]);
        rvt_times_vec(mat, m, o);
        bad[3] += !same_v4(pt_r9_model2world(v4(m[0], m[1], m[2], m[3]), &jm), o, 4);
        rvt_times_vec(nm, m, o);                        /* r9 camera: N v */
        bad[3] += !same_v4(pt_r9_view2camera(v4(m[0], m[1], m[2], m[3]), &jn), o, 4);
        rvt_r9_view(m, t, o);                           /* r9 view */
        bad[4] += !same_v4(pt_r9_world2view(v4(m[0], m[1], m[2], m[3]), tv), o, 3);
        rvt_project(m, persp, o);                       /* image */
        sv = pt_rv_project(v4(m[0], m[1], m[2], 1.0), persp);
        bad[5] += !same_v4(sv, o, 2);
        {                                               /* the near clip */
            double a[3] = {m[0], m[1], m[2]}, c[3] = {t[0], t[1], t[2]}, u = 0, p[3];
            double zn = i % 3 ? -0.1 : rv_rand();
            rv_heard h;
            int v;

            if (i % 5 == 0) a[2] = zn;                  /* on the plane */
            v = rvt_nearclip(zn, a, c, &u, p, &off);
            if (rv_stage_clip(v4(a[0], a[1], a[2], 1.0), v4(c[0], c[1], c[2], 1.0), 1, zn, &h))
                bad[6]++;
            else if (v >= 0) bad[6] += h.ncuts != 0 || h.accepted != v;
            else {
                nearcuts++;
                bad[6] += h.ncuts != 1 || !h.accepted || h.cut[0].off != off
                          || !same_d(h.cut[0].t, u) || !same_v4(h.cut[0].p[2], p, 3);
            }
        }
        {                                               /* the clip to -1..1 */
            double e[2][2], e0[2][2], te[8], pe[8][2];
            int edge[8], offs[8], nc = 0, keep, q, ok;
            rv_heard h;

            for (k = 0; k < 4; k++) {
                double x = rv_rand();

                e[k / 2][k % 2] = fabs(x) > 2.0 ? x / 16.0 : x;     /* about -4 .. 4 */
            }
            memcpy(e0, e, sizeof e);
            keep = rvt_clip(e, 8, &nc, edge, offs, te, pe);
            if (rv_stage_clip(v4(e0[0][0], e0[0][1], 0, 1), v4(e0[1][0], e0[1][1], 0, 1), 0,
                              0.0, &h) != 0) { bad[7]++; continue; }
            ok = h.ncuts == nc && h.accepted == keep && nc <= 8;
            for (q = 0; ok && q < nc; q++) {
                double pq[2];

                pq[0] = pe[q][0]; pq[1] = pe[q][1];
                ok = (int)h.cut[q].edge == edge[q] && h.cut[q].off == offs[q]
                     && same_d(h.cut[q].t, te[q]) && same_v4(h.cut[q].p[2], pq, 2);
            }
            if (ok && keep) ok = same_v4(h.ends[0], e[0], 2) && same_v4(h.ends[1], e[1], 2);
            bad[7] += !ok;
            cuts += nc;
            trivial += nc == 0;
        }
    }
    PT_CHECK("acc-12.1 renderer 7's view copy is pt_r7_model2view bit for bit", bad[0] == 0);
    PT_CHECK("acc-12.2 renderer 7's camera copy is pt_r7_view2camera bit for bit", bad[1] == 0);
    PT_CHECK("acc-12.3 renderer 9's normalize matrix is pt_r9_normalize_matrix's", bad[2] == 0);
    PT_CHECK("acc-12.4 Java's A.times(v) copy is the world and camera stages'", bad[3] == 0);
    PT_CHECK("acc-12.5 renderer 9's view copy is pt_r9_world2view bit for bit", bad[4] == 0);
    PT_CHECK("acc-12.6 the image copy is pt_rv_project bit for bit", bad[5] == 0);
    PT_CHECK("acc-12.7 the near clip copy: pt_rv_nearclip's verdict, end, t, point",
             bad[6] == 0 && nearcuts > 1000);
    PT_CHECK("acc-12.8 the clip copy: pt_rv_clip's cuts (edge, end, t, point), verdict, ends",
             bad[7] == 0 && cuts > 5000 && trivial > 1000);
}

/* ===== renderers 7 and 9: the double run is the course driver's ===== */

#define RV_MAXM 64

/* What the course driver reports: each visible position's model after each
** stage (vertices and primitives), and the pixels drawn. */
typedef struct rv_seen {
    pt_vec4 *v[RV_MAXM][PT_NCST];
    size_t nv[RV_MAXM][PT_NCST];
    pt_rv_prim *p[RV_MAXM][PT_NCST];
    size_t np[RV_MAXM][PT_NCST];
    int64_t *px;
    size_t npx, cap;
    const pt_scene *s;
} rv_seen;

static void rv_seen_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                          const pt_rv_model *m)
{
    rv_seen *sn = ud;
    size_t k = pos->index;

    if (k >= RV_MAXM) return;
    free(sn->v[k][st]);
    free(sn->p[k][st]);
    sn->v[k][st] = malloc((m->nv ? m->nv : 1) * sizeof *m->v);
    sn->p[k][st] = malloc((m->np ? m->np : 1) * sizeof *m->p);
    if (!sn->v[k][st] || !sn->p[k][st]) return;
    if (m->nv) memcpy(sn->v[k][st], m->v, m->nv * sizeof *m->v);
    if (m->np) memcpy(sn->p[k][st], m->p, m->np * sizeof *m->p);
    sn->nv[k][st] = m->nv;
    sn->np[k][st] = m->np;
}

static void rv_seen_pixel(void *ud, const pt_rv_pixel *px)
{
    rv_seen *sn = ud;

    if (px->kind != PT_RV_PX_STEP && px->kind != PT_RV_PX_END) return;
    if (!pt_inside(px->x_vp, px->y_vp, sn->s->vp_w, sn->s->vp_h)) return;
    if (sn->npx == sn->cap) {
        size_t cap = sn->cap ? 2 * sn->cap : 256;
        int64_t *q = realloc(sn->px, cap * sizeof *q);

        if (!q) return;
        sn->px = q;
        sn->cap = cap;
    }
    sn->px[sn->npx++] = (sn->s->vp_y + (int64_t)px->y_vp) * sn->s->fb_w + sn->s->vp_x + px->x_vp;
}

static int by_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;

    return x < y ? -1 : x > y;
}

/* n values a (pt_dd, lo = 0) against the stage's v. */
static int rv_same(const pt_dd *a, pt_vec4 v, int n)
{
    double b[4];
    int k;

    for (k = 0; k < n; k++) b[k] = a[k].hi;
    return same_v4(v, b, n);
}

typedef struct rv_tally {
    size_t scenes, vertices, near, cuts, ends, pixels, drawn;
    size_t bad_v, bad_near, bad_cuts, bad_ends, bad_px;
} rv_tally;

/* Model k of the double run r against what the driver reported (sn). */
static void rv_check_model(const pt_acc_run *r, const rv_seen *sn, size_t k, rv_tally *t)
{
    const pt_scene *s = r->s;
    const pt_model *m = &s->models[k];
    size_t v, q, in = m->nv, ic, li = 0;
    int c, e, st;

    if (!sn->v[k][PT_CST_IMAGE] || !sn->v[k][PT_CST_CLIP]) { t->bad_v++; return; }
    for (v = 0; v < m->nv; v++) {
        const pt_acc_rvjourney *j = &r->rj[k][v];

        if (!r->used[k][v]) continue;
        t->vertices++;
        for (st = PT_CST_MODEL; st <= PT_CST_IMAGE; st++) {
            const pt_dd *a = st == PT_CST_MODEL ? j->m : st == PT_CST_WORLD ? j->w
                             : st == PT_CST_VIEW ? j->v : st == PT_CST_CAMERA ? j->c : j->ip;
            int n = st == PT_CST_WORLD ? 4 : st == PT_CST_IMAGE ? 2 : 3;

            if (st == PT_CST_NEARCLIP || !sn->v[k][st]) continue;
            if (!rv_same(a, sn->v[k][st][v], n)) t->bad_v++;
        }
    }
    ic = sn->nv[k][PT_CST_IMAGE];                   /* the clip appends from here */
    for (q = 0; q < m->nseg; q++) {
        const pt_acc_rvseg *g = &r->rseg[k][q];

        if (g->near < 0) {                          /* the near clip's new vertex */
            t->near++;
            if (in >= sn->nv[k][PT_CST_IMAGE] || !sn->v[k][PT_CST_NEARCLIP]
                || !rv_same(g->nc.p, sn->v[k][PT_CST_NEARCLIP][in], 3)
                || !rv_same(g->nip, sn->v[k][PT_CST_IMAGE][in], 2)) t->bad_near++;
            in++;
        }
        for (c = 0; g->near != 0 && c < g->ncuts; c++, ic++) {  /* the clip's */
            t->cuts++;
            if (ic >= sn->nv[k][PT_CST_CLIP] || !rv_same(g->cut[c].p, sn->v[k][PT_CST_CLIP][ic], 2))
                t->bad_cuts++;
        }
        if (!g->keep) continue;
        while (li < sn->np[k][PT_CST_CLIP] && sn->p[k][PT_CST_CLIP][li].kind != PT_RV_LINE) li++;
        for (e = 0; e < 2; e++) {                   /* the ends drawn */
            t->ends++;
            if (li >= sn->np[k][PT_CST_CLIP]
                || !rv_same(g->end[e].ip, sn->v[k][PT_CST_CLIP][sn->p[k][PT_CST_CLIP][li].v[e]], 2))
                t->bad_ends++;
        }
        li++;
    }
    for (; li < sn->np[k][PT_CST_CLIP]; li++)       /* a line the run did not draw */
        if (sn->p[k][PT_CST_CLIP][li].kind == PT_RV_LINE) t->bad_ends++;
}

static void rv_check_scene(const char *path, rv_tally *t)
{
    pt_scene s;
    pt_acc_run r;
    pt_fb fb;
    rv_seen *sn;
    pt_course_ls ls;
    pt_rv_raster_ls rls;
    size_t k, i, n;
    int points = 0, st;

    if (!load(&s, path)) { t->bad_v++; return; }
    if ((s.renderer != 7 && s.renderer != 9) || s.nmodels > RV_MAXM) { pt_scene_free(&s); return; }
    sn = calloc(1, sizeof *sn);
    memset(&ls, 0, sizeof ls);
    memset(&rls, 0, sizeof rls);
    if (!sn || pt_fb_init(&fb, s.fb_w, s.fb_h, s.background) != 0) {
        t->bad_v++; free(sn); pt_scene_free(&s); return;
    }
    sn->s = &s;
    ls.stage = rv_seen_stage;
    ls.ud = sn;
    rls.pixel = rv_seen_pixel;
    rls.ud = sn;
    ls.raster_ls = &rls;
    if (pt_course_render(&s, &fb, &ls) != 0 || pt_acc_run_make(&r, &s, PT_ARITH_DOUBLE, 0) != 0) {
        t->bad_v++;
    } else {
        t->scenes++;
        for (k = 0; k < s.nmodels; k++) {
            points |= s.models[k].npts > 0;
            if (!s.models[k].hidden_position && !s.models[k].hidden_model)
                rv_check_model(&r, sn, k, t);
        }
        if (!points && !s.antialias) {              /* the pixels: the same places */
            t->drawn++;
            if (sn->npx) qsort(sn->px, sn->npx, sizeof *sn->px, by_i64);
            for (i = n = 0; i < sn->npx; i++)
                if (i == 0 || sn->px[i] != sn->px[i - 1]) sn->px[n++] = sn->px[i];
            t->pixels += n;
            if (n != r.nimg) t->bad_px++;
            for (i = 0; i < n && i < r.nimg; i++)
                if (sn->px[i] != r.img[i].idx) { t->bad_px++; break; }
        }
        pt_acc_run_free(&r);
    }
    for (k = 0; k < RV_MAXM; k++)
        for (st = 0; st < PT_NCST; st++) { free(sn->v[k][st]); free(sn->p[k][st]); }
    free(sn->px);
    free(sn);
    pt_fb_free(&fb);
    pt_scene_free(&s);
}

static void test_rv_course(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char path[4096];
    rv_tally t;
    char descr[240];

    memset(&t, 0, sizeof t);
    while (d && (e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);

        if (len > 6 && strcmp(e->d_name + len - 6, ".scene") == 0) {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            rv_check_scene(path, &t);
        }
    }
    if (d) closedir(d);
    snprintf(descr, sizeof descr, "acc-13.1 renderers 7 and 9: the double run's vertices are "
             "the course driver's, model to image, bit for bit (%zu vertices, %zu scenes)",
             t.vertices, t.scenes);
    PT_CHECK(descr, t.bad_v == 0 && t.scenes >= 15 && t.vertices > 100);
    snprintf(descr, sizeof descr, "acc-13.2 ... its near clip makes the driver's %zu points "
             "(camera and image plane)", t.near);
    PT_CHECK(descr, t.bad_near == 0 && t.near >= 4);
    snprintf(descr, sizeof descr, "acc-13.3 ... its clip the driver's %zu points", t.cuts);
    PT_CHECK(descr, t.bad_cuts == 0 && t.cuts >= 4);
    snprintf(descr, sizeof descr, "acc-13.4 ... and draws the driver's segments between "
             "the same %zu ends", t.ends);
    PT_CHECK(descr, t.bad_ends == 0 && t.ends > 50);
    snprintf(descr, sizeof descr, "acc-13.5 ... its image lights the driver's %zu pixels "
             "(%zu scenes without points or AA)", t.pixels, t.drawn);
    PT_CHECK(descr, t.bad_px == 0 && t.drawn >= 8 && t.pixels > 500);
}

/* ===== renderers 7 and 9: the timed work ===== */

static int same_rvfront(const pt_acc_rvjourney *a, const pt_acc_rvjourney *b, int r9)
{
    return same_dd(a->m, b->m, 3) && (!r9 || same_dd(a->w, b->w, 4)) && same_dd(a->v, b->v, 3)
           && same_dd(a->c, b->c, 3) && same_dd(a->ip, b->ip, 2);
}

static int same_rvcut(const pt_acc_rvcut *a, const pt_acc_rvcut *b, int n)
{
    return a->edge == b->edge && a->off == b->off && same_dd(&a->t, &b->t, 1)
           && same_dd(a->p, b->p, n);
}

static int same_rvclip(const pt_acc_rvseg *a, const pt_acc_rvseg *b, int fn)
{
    int k, ok = 1;

    if (fn == PT_ACC_FN_RVNEAR)
        return a->near == b->near && (a->near >= 0 || same_rvcut(&a->nc, &b->nc, 3));
    ok = a->keep == b->keep && a->ncuts == b->ncuts;
    for (k = 0; ok && k < a->ncuts && k < PT_ACC_RV_MAXCUTS; k++)
        ok = same_rvcut(&a->cut[k], &b->cut[k], 2);
    return ok;
}

/* Row one of run r on w; from garbage when poison is set, and then every row
** of its kind in order: the values are the run's, input for input. */
static int rv_work_agrees(const pt_acc_run *r, pt_acc_work *w, int one, int poison, size_t *n)
{
    const pt_scene *s = r->s;
    const pt_acc_rows *rows = pt_acc_scene_rows(s);
    pt_acc_fn fn = rows->row[one].fn;
    size_t k, v, q, i = 0;
    int row, e, ok = 1;

    if (poison) pt_acc_work_poison(w);
    for (row = 0; row + 1 < rows->nrows; row++)
        if (row == one || (poison && rows->row[row].fn == fn)) pt_acc_stage_pass(w, row);
    for (k = 0; k < s->nmodels; k++) {
        if (s->models[k].hidden_position || s->models[k].hidden_model) continue;
        if (fn == PT_ACC_FN_RV) {
            for (v = 0; v < s->models[k].nv; v++)
                if (r->used[k][v])
                    ok &= same_rvfront(pt_acc_work_rvjourney(w, i++), &r->rj[k][v], s->renderer == 9);
            continue;
        }
        for (q = 0; q < s->models[k].nseg; q++) {
            const pt_acc_rvseg *g = &r->rseg[k][q];

            if (fn == PT_ACC_FN_RVEND) {
                for (e = 0; g->keep && e < 2; e++) {
                    const pt_acc_journey *a = pt_acc_work_journey(w, i++);

                    ok &= same_dd(a->ip, g->end[e].ip, 2) && same_dd(a->pp, g->end[e].pp, 2)
                          && same_px(a->vp, g->end[e].vp) && same_px(a->fb, g->end[e].fb)
                          && a->idx == g->end[e].idx;
                }
                continue;
            }
            if (fn == PT_ACC_FN_RVCLIP && g->near == 0) continue;
            ok &= same_rvclip(pt_acc_work_rvseg(w, i++), g, fn);
        }
    }
    *n += i;
    return ok && i == pt_acc_work_size(w);
}

static void test_rv_work(void)
{
    static const char *const scenes[] = {
        "tests/course79/r9-mat-14-camera-translate.scene", "tests/course79/r7-near-01.scene",
        "tests/course79/r7-clip-08-corner-ur.scene", "tests/course79/r9-clip-12-through-x.scene"
    };
    static const struct { pt_arith a; unsigned choices; } runs[] = {
        { PT_ARITH_FLOAT, 0 }, { PT_ARITH_DOUBLE, 0 }, { PT_ARITH_DD, 0 },
        { PT_ARITH_DOUBLE, PT_ACC_TWO }
    };
    size_t si, ri, n = 0, nagain = 0, bad = 0, badagain = 0, nruns = 0;
    char descr[200];
    pt_scene s;

    for (si = 0; si < sizeof scenes / sizeof scenes[0]; si++) {
        if (!load(&s, scenes[si])) { bad++; continue; }
        for (ri = 0; ri < sizeof runs / sizeof runs[0]; ri++) {
            const pt_acc_rows *rows = pt_acc_scene_rows(&s);
            pt_acc_run r;
            int row;

            if (pt_acc_run_make(&r, &s, runs[ri].a, runs[ri].choices) != 0) { bad++; continue; }
            for (row = 0; row + 1 < rows->nrows; row++) {
                pt_acc_work *w;
                int first = 0;

                while (rows->row[first].fn != rows->row[row].fn) first++;
                if (first == row) {                         /* a kind's rows, from garbage */
                    w = pt_acc_work_make(&r, row);
                    if (!w || !rv_work_agrees(&r, w, row, 1, &n)) bad++;
                    pt_acc_work_free(w);
                }
                w = pt_acc_work_make(&r, row);              /* each alone, as timed */
                if (!w || !rv_work_agrees(&r, w, row, 0, &nagain)) badagain++;
                pt_acc_work_free(w);
            }
            nruns++;
            pt_acc_run_free(&r);
        }
        pt_scene_free(&s);
    }
    snprintf(descr, sizeof descr, "acc-14.1 renderers 7 and 9: the stages and clips the "
             "timing runs, from garbage, rebuild the error runs' values bit for bit (%zu runs, "
             "%zu inputs)", nruns, n);
    PT_CHECK(descr, bad == 0 && nruns == 16 && n > 200);
    snprintf(descr, sizeof descr, "acc-14.2 ... and a timed pass of one stage rewrites the "
             "same values (%zu inputs)", nagain);
    PT_CHECK(descr, badagain == 0 && nagain > n);
}

/* The tables of renderers 7 and 9: renderer 9's stages in order, renderer
** 7's without world, each with a viewport row, pixel the last real one, 2.001
** in the pixel row and the rasterizer last. */
static void test_rv_rows(void)
{
    static const char *const r9[] = {"model", "world", "view", "camera", "nearclip", "image",
                                     "clip", "pixel", "viewport", "framebuffer", "index", "raster"};
    const pt_acc_rows *t9 = &pt_acc_rows_r9, *t7 = &pt_acc_rows_r7;
    int i, ok9 = t9->nrows == 12 && t9->rv == 9, ok7 = t7->nrows == 11 && t7->rv == 7, sane = 1;

    for (i = 0; ok9 && i < 12; i++) ok9 = !strcmp(t9->row[i].name, r9[i]);
    for (i = 0; ok7 && i < 11; i++) ok7 = !strcmp(t7->row[i].name, r9[i + (i > 0)]);
    PT_CHECK("acc-11.1 renderer 9's rows: its stages and both clips in order, the rasterizer last", ok9);
    PT_CHECK("acc-11.2 renderer 7's: the same without world", ok7);
    for (i = 0; i < 2; i++) {
        const pt_acc_rows *t = i ? t7 : t9;

        sane &= t->row[t->nrows - 1].stage == -1 && t->row[t->nrows - 1].fn == PT_ACC_FN_RASTER
                && !strcmp(t->row[pt_acc_last_real(t)].name, "pixel")
                && pt_acc_row_varied(t, PT_ACC_TWO) == pt_acc_row_of(t, PT_STAGE_PIXEL)
                && pt_acc_row_of(t, PT_STAGE_VIEWPORT) == pt_acc_row_of(t, PT_STAGE_PIXEL) + 1
                && pt_acc_row_of(t, PT_STAGE_INDEX) == t->nrows - 2 && t->nrows <= PT_ACC_MAXROWS;
    }
    PT_CHECK("acc-11.3 ... each with pixel (2.001) the last real row, viewport .. index after it", sane);
}

/* ===== a scene in blocks ===== */

/* Segment blocks of tests/data/accblock/classic.scene: each block's vertices
** are its segments' ends, each once, at the model's coordinates. */
static void test_block_ends(void)
{
    pt_scene s;
    pt_acc_block b;
    unsigned char **used;
    size_t q, i, nseg = 0, nends = 0, bad = 0;
    unsigned char *seen = calloc(2 * PT_ACC_BLOCK, 1);

    memset(&b, 0, sizeof b);
    if (!load(&s, "tests/data/accblock/classic.scene") || !seen) { free(seen); return; }
    used = pt_acc_used_make(&s);
    if (!used || pt_acc_block_init(&b, &s, used) != 0) bad++;
    while (!bad && pt_acc_block_next(&b)) {
        const pt_model *m = &s.models[b.k];

        if (!b.segs) continue;
        memset(seen, 0, 2 * PT_ACC_BLOCK);
        for (q = 0; q < b.m.nseg; q++) {
            const pt_segment *g = &b.m.seg[q], *o = &m->seg[b.pos - b.m.nseg + q];

            if (g->a >= b.m.nv || g->b >= b.m.nv) { bad++; break; }
            bad += memcmp(&b.m.v[g->a], &m->v[o->a], sizeof *b.m.v) != 0;
            bad += memcmp(&b.m.v[g->b], &m->v[o->b], sizeof *b.m.v) != 0;
            bad += (g->a == g->b) != (o->a == o->b);
            seen[g->a] = seen[g->b] = 1;
        }
        for (i = 0; i < b.m.nv; i++) bad += !seen[i];           /* each one an end */
        for (i = 0; i < b.m.nv; i++)                            /* and once */
            for (q = i + 1; q < b.m.nv && q < i + 8; q++)
                bad += memcmp(&b.m.v[i], &b.m.v[q], sizeof *b.m.v) == 0;
        nseg += b.m.nseg;
        nends += b.m.nv;
    }
    PT_CHECK("acc-15.1 segment blocks: each segment's ends are the model's, its block's "
             "vertices its segments' ends", bad == 0 && nseg == 21765);
    PT_CHECK("acc-15.2 ... each end once a block: a sphere's 21,765 segments, neighbours "
             "in their file, take about one vertex a segment, not two", nends > 0
             && nends * 10 < 11 * nseg);
    pt_acc_block_free(&b);
    pt_acc_used_free(&s, used);
    pt_scene_free(&s);
    free(seen);
}

/* 1 when errors a and b are the same, field for field. */
static int same_err(const pt_acc_err *a, const pt_acc_err *b)
{
    return a->max_abs == b->max_abs && a->sum_abs == b->sum_abs && a->max_ulp == b->max_ulp
           && a->n == b->n && a->real == b->real && a->differ == b->differ && a->of == b->of
           && a->left == b->left && a->entered == b->entered && a->decided == b->decided;
}

/* The rasterizer's rows of three runs made together a block at a time in one
** image -- the reference, float, and float drawn again with y recomputed --
** against those of whole runs (pt_acc_compare). */
static void test_block_image(const char *path, const char *id)
{
    pt_scene s;
    pt_acc_block b;
    pt_acc_run ref, f, wr, wf, wre;
    pt_acc_err e[PT_ACC_MAXROWS], er, ef, ere;
    pt_acc_image *img;
    unsigned char **used;
    int rc = 0, raster, same;
    char descr[200];

    memset(&b, 0, sizeof b);
    if (!load(&s, path)) return;
    raster = pt_acc_scene_rows(&s)->nrows - 1;
    used = pt_acc_used_make(&s);
    img = pt_acc_image_make(&s, PT_ACC_MAXPIX, 3);
    if (!used || !img || pt_acc_block_init(&b, &s, used) != 0) rc = -1;
    while (rc == 0 && pt_acc_block_next(&b)) {
        if ((rc = pt_acc_run_block(&ref, &b, PT_ARITH_DD, 0, img, 0)) != 0) break;
        if ((rc = pt_acc_run_block(&f, &b, PT_ARITH_FLOAT, 0, img, 1)) == 0) {
            if (b.segs) rc = pt_acc_draw_again(&f, PT_ACC_RECOMPUTE, img, 2);
            pt_acc_run_free(&f);
        }
        pt_acc_run_free(&ref);
    }
    pt_acc_image_end(img, 0, 0, &er);
    pt_acc_image_end(img, 0, 1, &ef);
    pt_acc_image_end(img, 0, 2, &ere);
    memset(&f, 0, sizeof f);
    pt_acc_image_count(img, 0, &f);
    pt_acc_run_make(&wr, &s, PT_ARITH_DD, 0);
    pt_acc_run_make(&wf, &s, PT_ARITH_FLOAT, 0);
    pt_acc_run_make(&wre, &s, PT_ARITH_FLOAT, PT_ACC_RECOMPUTE);
    pt_acc_compare(&wr, &wr, e);
    same = rc == 0 && same_err(&er, &e[raster]) && f.nimg == wr.nimg
           && f.pixels == wr.pixels && wr.nimg > 1000;
    pt_acc_compare(&wr, &wf, e);
    same = same && same_err(&ef, &e[raster]) && ef.n > 1000;
    pt_acc_compare(&wr, &wre, e);
    same = same && same_err(&ere, &e[raster]) && ere.sum_abs != ef.sum_abs;
    snprintf(descr, sizeof descr, "acc-15.%s %s: the reference, float and float with y "
             "recomputed drawn a block at a time into one image: the whole runs' raster rows",
             id, path);
    PT_CHECK(descr, same);
    pt_acc_run_free(&wr); pt_acc_run_free(&wf); pt_acc_run_free(&wre);
    pt_acc_block_free(&b);
    pt_acc_image_free(img);
    pt_acc_used_free(&s, used);
    pt_scene_free(&s);
}

int main(int argc, char **argv)
{
    const char *dirs[3];
    size_t k, nscenes = 0, nv = 0, ns = 0, bv = 0, bs = 0;
    char descr[200];

    dirs[0] = argc > 1 ? argv[1] : "tests/reference";
    dirs[1] = "tests/extreme";
    dirs[2] = "docs/examples";
    test_rows();
    test_rv_rows();
    test_rv_copies();
    test_rv_work();
    test_rv_course("tests/course79");
    test_dd();
    test_dd_matrix();
    test_vp_of();
    for (k = 0; k < 3; k++) check_dir(dirs[k], &nscenes, &nv, &ns, &bv, &bs);
    snprintf(descr, sizeof descr, "acc-3.1 the double journey is the stages' for all "
             "%zu vertices of %zu scenes", nv, nscenes);
    PT_CHECK(descr, bv == 0 && nv > 100);
    snprintf(descr, sizeof descr, "acc-3.2 the double DDA lights the plain step-by-step "
             "loop's pixels for all %zu segments", ns);
    PT_CHECK(descr, bs == 0 && ns > 100);
    snprintf(descr, sizeof descr, "acc-6.1 matrix camera: the double View, Projection and "
             "World are the plan's, bit for bit (%zu scenes)", mc.scenes);
    PT_CHECK(descr, mc.bad_matrices == 0 && mc.scenes >= 4);
    snprintf(descr, sizeof descr, "acc-6.2 matrix camera: the double journey is the "
             "pipeline's, model to index, for all %zu vertices", mc.vertices);
    PT_CHECK(descr, mc.bad_vertices == 0 && mc.vertices >= 15);
    snprintf(descr, sizeof descr, "acc-6.3 matrix camera: the double clipping makes the "
             "pipeline's %zu points (t, ndc .. index), culls as many segments", mc.points);
    PT_CHECK(descr, mc.bad_points == 0 && mc.bad_culled == 0 && mc.points >= 2);
    snprintf(descr, sizeof descr, "acc-6.4 matrix camera: the double image is the "
             "pipeline's (%zu pixels)", mc.pixels);
    PT_CHECK(descr, mc.bad_images == 0 && mc.pixels > 50);
    snprintf(descr, sizeof descr, "acc-6.5 matrix camera: the reference's matrices round to "
             "within 4 ulps (of the largest entry) of double's (%.3g)", mc.ref_matrix_ulps);
    PT_CHECK(descr, mc.ref_matrix_ulps <= 4);
    test_random_ddas();
    test_compare();
    test_mcompare();
    test_work();
    test_block_ends();
    test_block_image("tests/data/accblock/classic.scene", "3");
    test_block_image("tests/data/accblock/matrix.scene", "4");
    test_block_image("tests/data/accblock/r9.scene", "5");
    return pt_test_report();
}
