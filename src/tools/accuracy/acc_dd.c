/*
** src/tools/accuracy/acc_dd.c -- both cameras' stages and the DDA in double-double: the reference
** See LICENSE for copyright and license.
**
** The same formulas in the same order, evaluated in double-double (dd.h) from
** the scene's doubles taken as exact; 2.001 is the decimal number 2001/1000
** (pt_dd_2001), Java's rounding is applied to the exact value, and the DDA
** does not accumulate: at step s it computes the exact line through the
** rounded endpoints (pt_acc_line_y()).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/acc_dd.h"

/*
** Ties.  A reference value is off the exact one by a few roundings of 2^-104
** of the magnitudes it is computed from; e (a double) bounds that, to first
** order, with TIE_U per operation standing for the few roundings of each and
** for the matrices' own.  A value within its bound of 0 is taken as 0, and a
** screen coordinate within its bound of an integer as that integer: there,
** exact arithmetic puts the point on a plane or a pixel edge (the look-at
** target at the centre of the screen, a point clipping put on a plane), and
** the reference's own rounding must not pick the side.
*/
#define TIE_U 0x1p-100

/* ===== the classic camera ===== */

/* Each stage reads its input from the journey and writes its output there. */

static void model(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)c;
    j->m[0] = pt_acc_dd(v.x); j->m[1] = pt_acc_dd(v.y); j->m[2] = pt_acc_dd(v.z);
}

static void camera(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)v;
    j->c[0] = pt_dd_add(j->m[0], pt_acc_dd(c->m->translate.x));  /* x_c = x_m + x_t */
    j->c[1] = pt_dd_add(j->m[1], pt_acc_dd(c->m->translate.y));  /* y_c = y_m + y_t */
    j->c[2] = pt_dd_add(j->m[2], pt_acc_dd(c->m->translate.z));  /* z_c = z_m + z_t */
}

static void image(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)v;
    if (c->s->perspective) {
        j->ip[0] = pt_dd_div(j->c[0], pt_dd_neg(j->c[2]));  /* x_ip = x_c / -z_c */
        j->ip[1] = pt_dd_div(j->c[1], pt_dd_neg(j->c[2]));  /* y_ip = y_c / -z_c */
    } else {
        j->ip[0] = j->c[0];                                 /* x_ip = x_c */
        j->ip[1] = j->c[1];                                 /* y_ip = y_c */
    }
}

static void pixel(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    const pt_dd one = {1.0, 0.0}, half = {0.5, 0.0};
    pt_dd w_k = pt_dd_div(pt_acc_dd(c->s->vp_w), pt_dd_2001);   /* w/2.001 */
    pt_dd h_k = pt_dd_div(pt_acc_dd(c->s->vp_h), pt_dd_2001);   /* h/2.001 */

    (void)v;                                        /* the reference has no choices */
    j->pp[0] = pt_dd_add(half, pt_dd_mul(w_k, pt_dd_add(j->ip[0], one)));
                                                    /* x_pp = 0.5 + w/2.001 * (x_ip + 1) */
    j->pp[1] = pt_dd_add(half, pt_dd_mul(h_k, pt_dd_add(j->ip[1], one)));
                                                    /* y_pp = 0.5 + h/2.001 * (y_ip + 1) */
}

static void viewport(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    int64_t rx = 0, ry = 0;
    int ok = pt_dd_pix_round(j->pp[0], &rx) && pt_dd_pix_round(j->pp[1], &ry);

    (void)v;
    j->vp = pt_acc_vp_of(c->s, ok, rx, ry);         /* x_vp = round(x_pp) - 1, ... */
}

/* ===== the DDA: the exact line ===== */

static int64_t i64_abs(int64_t v) { return v < 0 ? -v : v; }  /* |v| < 2^63 */

static int raster(const pt_dd p0[2], const pt_dd p1[2], unsigned choices, const pt_acc_dda *o)
{
    int64_t e[4], s, first, last, r;
    pt_acc_line ln;
    int tr;

    (void)choices;                                  /* the reference has none */
    if (!pt_dd_pix_round(p0[0], &e[0]) || !pt_dd_pix_round(p0[1], &e[1]) ||
        !pt_dd_pix_round(p1[0], &e[2]) || !pt_dd_pix_round(p1[1], &e[3]))
        return -1;
    if (e[0] == e[2] && e[1] == e[3]) { pt_acc_dda_dot(o, e[0], e[1]); return 0; }
    tr = i64_abs(e[3] - e[1]) > i64_abs(e[2] - e[0]);  /* |slope| > 1: step in y */
    pt_acc_dda_setup(&ln, tr, e, o, &first, &last);
    for (s = first; s <= last; s++) {
        pt_dd y = pt_acc_line_y(&ln, s);                   /* y = y0 + (s - s0) * dy/dx */
        int ok = pt_dd_pix_round(y, &r);
        pt_acc_dda_step(o, &ln, s, ok, r, y.hi);
    }
    return 0;
}

/* ===== the matrices in double-double ===== */

/*
** The same formulas from the scene's doubles taken as exact: sqrt and every
** division in double-double, cot(fov/2) by pt_dd_cot_deg().  The world lines'
** product reaches the reference only as the parser's double matrix, taken as
** exact; T(translate) is appended here.
*/

static void vec3_dd(pt_vec3 v, pt_dd r[3])
{
    r[0] = pt_acc_dd(v.x);
    r[1] = pt_acc_dd(v.y);
    r[2] = pt_acc_dd(v.z);
}

static pt_dd dot_dd(const pt_dd a[3], const pt_dd b[3])
{
    return pt_dd_add(pt_dd_add(pt_dd_mul(a[0], b[0]), pt_dd_mul(a[1], b[1])),
                     pt_dd_mul(a[2], b[2]));
}

static void cross_dd(const pt_dd a[3], const pt_dd b[3], pt_dd r[3])
{
    r[0] = pt_dd_sub(pt_dd_mul(a[1], b[2]), pt_dd_mul(a[2], b[1]));
    r[1] = pt_dd_sub(pt_dd_mul(a[2], b[0]), pt_dd_mul(a[0], b[2]));
    r[2] = pt_dd_sub(pt_dd_mul(a[0], b[1]), pt_dd_mul(a[1], b[0]));
}

static void normalize_dd(pt_dd v[3])
{
    int e = pt_vec3_exp(v[0].hi, v[1].hi, v[2].hi), i;      /* as pt_lookat() */
    pt_dd len;

    for (i = 0; i < 3; i++) { v[i].hi = ldexp(v[i].hi, -e); v[i].lo = ldexp(v[i].lo, -e); }
    len = pt_dd_sqrt(dot_dd(v, v));         /* v / |v| */

    v[0] = pt_dd_div(v[0], len); v[1] = pt_dd_div(v[1], len); v[2] = pt_dd_div(v[2], len);
}

static void identity_dd(pt_dd_mat4 *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = pt_acc_dd(i == j ? 1.0 : 0.0);
}

static void lookat_dd(const pt_scene *s, pt_dd_mat4 *r)
{
    pt_dd eye[3], d[3], u[3], h[3];
    int i;

    vec3_dd(s->eye, eye);
    vec3_dd(s->dir, d);
    vec3_dd(s->up, u);
    normalize_dd(d);                        /* d = dir/|dir| */
    normalize_dd(u);                        /* u = up/|up| */
    cross_dd(u, d, h);                      /* h = (u x d)/|u x d| */
    normalize_dd(h);
    cross_dd(d, h, u);                      /* u = d x h */
    identity_dd(r);
    for (i = 0; i < 3; i++) { r->m[i][0] = h[i]; r->m[i][1] = u[i]; r->m[i][2] = d[i]; }
    r->m[3][0] = pt_dd_neg(dot_dd(eye, h)); /* last row (-eye.h, -eye.u, -eye.d, 1) */
    r->m[3][1] = pt_dd_neg(dot_dd(eye, u));
    r->m[3][2] = pt_dd_neg(dot_dd(eye, d));
}

static void perspective_dd(const pt_scene *s, pt_dd_mat4 *r)
{
    pt_dd cot = pt_dd_cot_deg(s->fov / 2);  /* cot(fov/2) */
    pt_dd n = pt_acc_dd(s->znear), f = pt_acc_dd(s->zfar);
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = pt_acc_dd(0.0);
    r->m[0][0] = pt_dd_div(cot, pt_acc_dd(s->aspect));                 /* x' = x * cot(fov/2) / aspect */
    r->m[1][1] = cot;                                           /* y' = y * cot(fov/2) */
    r->m[2][2] = pt_dd_div(f, pt_dd_sub(f, n));                    /* z' = z * f/(f-n) ... */
    r->m[3][2] = pt_dd_div(pt_dd_mul(f, n), pt_dd_sub(n, f));      /*      - f*n/(f-n) */
    r->m[2][3] = pt_acc_dd(1.0);                                       /* w' = z */
}

static void world_dd(const pt_model *m, pt_dd_mat4 *r, pt_mat4 *e)
{
    pt_dd_mat4 w, t;
    int i, j, k;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) w.m[i][j] = pt_acc_dd(m->world.m[i][j]);
    identity_dd(&t);
    vec3_dd(m->translate, t.m[3]);          /* T(translate): the last row */
    *r = pt_dd_mat4_mul(&w, &t);            /* World = (world lines) * T */
    for (i = 0; i < 4; i++)                 /* from exact entries: the rounding */
        for (j = 0; j < 4; j++)
            for (e->m[i][j] = 0, k = 0; k < 4; k++)
                e->m[i][j] += TIE_U * fabs(w.m[i][k].hi) * fabs(t.m[k][j].hi);
}

/* Bounds on View's and Projection's entries: h, u, d are unit vectors, each
** entry within TIE_U, times 1/|u x d| (normalising u x d divides its error by
** that); the eye's row within that times |eye| (summed); every entry of
** Projection within TIE_U of itself (relative).  view is View. */
static void camera_bounds_dd(const pt_scene *s, const pt_dd_mat4 *view,
                             const pt_dd_mat4 *proj, pt_mat4 *ve, pt_mat4 *pe)
{
    double eye = fabs(s->eye.x) + fabs(s->eye.y) + fabs(s->eye.z);
    int e = pt_vec3_exp(s->up.x, s->up.y, s->up.z);
    double ux = ldexp(s->up.x, -e), uy = ldexp(s->up.y, -e), uz = ldexp(s->up.z, -e);
    double len = sqrt(ux * ux + uy * uy + uz * uz);
    double u[3], d[3], cond, ud = 0;
    int i, j;

    u[0] = ux / len; u[1] = uy / len; u[2] = uz / len;                  /* up/|up| */
    for (i = 0; i < 3; i++) d[i] = view->m[i][2].hi;                      /* d */
    for (i = 0; i < 3; i++) {                                             /* |u x d|^2 */
        double c = u[(i + 1) % 3] * d[(i + 2) % 3] - u[(i + 2) % 3] * d[(i + 1) % 3];

        ud += c * c;
    }
    cond = ud > 0 ? 1 / sqrt(ud) : 1;                                     /* 1/|u x d| */
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            ve->m[i][j] = i == 3 ? TIE_U * cond * eye : TIE_U * cond;
            pe->m[i][j] = TIE_U * fabs(proj->m[i][j].hi);
        }
}

/* ----- double-double ----- */

static int mcam(pt_acc_mcam *c)
{
    const pt_scene *s = c->s;
    size_t k, n = s->nmodels ? s->nmodels : 1;

    c->world_dd = malloc(n * sizeof *c->world_dd);
    c->world_e = malloc(n * sizeof *c->world_e);
    if (!c->world_dd || !c->world_e) return -1;
    lookat_dd(s, &c->view_dd);
    perspective_dd(s, &c->proj_dd);
    camera_bounds_dd(s, &c->view_dd, &c->proj_dd, &c->view_e, &c->proj_e);
    for (k = 0; k < s->nmodels; k++)
        world_dd(&s->models[k], &c->world_dd[k], &c->world_e[k]);
    return 0;
}

/* ===== the matrix camera: journeys ===== */

static pt_dd snap0(pt_dd x, double e)   /* within the bound of 0: 0 */
{
    return fabs(x.hi) <= e ? pt_acc_dd(0.0) : x;
}

/* r = v * M with r's bounds from v's (ev) and M's (me): sum v_i m_ic errs by
** at most sum e_i |m_ic| + |v_i| (me_ic + TIE_U |m_ic|), the last for the
** rounding. */
static void vmul_dd(const pt_dd v[4], const double ev[4], const pt_dd_mat4 *m,
                    const pt_mat4 *me, pt_dd r[4], double er[4])
{
    int c, i;

    pt_dd_vec4_mul(v, m, r);                /* x' = x*m0c + y*m1c + z*m2c + w*m3c */
    for (c = 0; c < 4; c++) {
        er[c] = 0;
        for (i = 0; i < 4; i++)
            er[c] += ev[i] * fabs(m->m[i][c].hi)
                   + fabs(v[i].hi) * (me->m[i][c] + TIE_U * fabs(m->m[i][c].hi));
        r[c] = snap0(r[c], er[c]);
    }
}

/* The distances of stages/m4_clip2cvv.c, each within its bound of 0 taken as 0. */
static void cvv_dist_dd(const pt_dd k[4], const double ek[4], pt_dd d[PT_CVV_NPLANES])
{
    d[0] = snap0(k[2], ek[2]);                                  /* near:   z >= 0 */
    d[1] = snap0(pt_dd_sub(k[3], k[2]), ek[3] + ek[2]);            /* far:    z <= w */
    d[2] = snap0(pt_dd_add(k[3], k[0]), ek[3] + ek[0]);         /* left:   x >= -w */
    d[3] = snap0(pt_dd_sub(k[3], k[0]), ek[3] + ek[0]);            /* right:  x <= w */
    d[4] = snap0(pt_dd_add(k[3], k[1]), ek[3] + ek[1]);         /* bottom: y >= -w */
    d[5] = snap0(pt_dd_sub(k[3], k[1]), ek[3] + ek[1]);            /* top:    y <= w */
}

static unsigned cvv_dd(const pt_dd k[4], const double ek[4])
{
    pt_dd d[PT_CVV_NPLANES];
    unsigned code = 0;
    int i;

    cvv_dist_dd(k, ek, d);
    for (i = 0; i < PT_CVV_NPLANES; i++)    /* hi carries the sign of hi + lo */
        if (!(d[i].hi >= 0)) code |= 1u << i;       /* NaN counts as outside */
    return code;
}

static void ndc_dd(const pt_dd k[4], const double ek[4], pt_dd n[3], double en[3])
{
    int i;

    for (i = 0; i < 3; i++) {
        n[i] = pt_dd_div(k[i], k[3]);       /* x_n = x_k / w_k, y_n, z_n alike */
        en[i] = (ek[i] + fabs(n[i].hi) * ek[3]) / fabs(k[3].hi) + TIE_U * fabs(n[i].hi);
        n[i] = snap0(n[i], en[i]);
    }
}

static void screen_dd(const pt_scene *s, const pt_dd n[3], const double en[3],
                      pt_dd sc[3], double es[2])
{
    sc[0] = pt_dd_mul(pt_dd_mul(pt_dd_add(n[0], pt_acc_dd(1.0)), pt_acc_dd(s->vp_w)), pt_acc_dd(0.5));
                                            /* x_s = (x_n + 1) * w * 0.5 */
    sc[1] = pt_dd_mul(pt_dd_mul(pt_dd_sub(pt_acc_dd(1.0), n[1]), pt_acc_dd(s->vp_h)), pt_acc_dd(0.5));
                                            /* y_s = (1 - y_n) * h * 0.5 */
    sc[2] = n[2];                           /* z_s = z_n */
    es[0] = en[0] * s->vp_w * 0.5 + TIE_U * fabs(sc[0].hi);
    es[1] = en[1] * s->vp_h * 0.5 + TIE_U * fabs(sc[1].hi);
}

/* floor(hi + lo), exactly: floor(hi), or hi + floor(lo) when hi is an integer
** (otherwise |lo| <= ulp(hi)/2 cannot reach the next integer); an integer
** within e of x is x's floor (a point on a pixel edge). */
static int64_t floor_dd(pt_dd x, double e)
{
    double f = floor(x.hi), n = floor(x.hi + 0.5);

    if (fabs(pt_dd_sub(x, pt_acc_dd(n)).hi) <= e) return (int64_t)n;    /* on an edge */
    return f == x.hi ? (int64_t)f + (int64_t)floor(x.lo) : (int64_t)f;
}

static pt_pix viewport_dd(const pt_dd sc[3], const double es[2])
{
    pt_pix vp = {0, 0, 0};

    if (fabs(sc[0].hi) < PT_PIX_LIMIT && fabs(sc[1].hi) < PT_PIX_LIMIT) {  /* false for NaN */
        vp.x = floor_dd(sc[0], es[0]);      /* x_vp = floor(x_s) */
        vp.y = floor_dd(sc[1], es[1]);      /* y_vp = floor(y_s) */
        vp.ok = 1;
    }
    return vp;
}

static void m_model(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)c; (void)k;
    vec3_dd(v, j->m);
}

static void m_world(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    static const double exact[4] = {0, 0, 0, 0};
    pt_dd m[4];

    (void)v;
    m[0] = j->m[0]; m[1] = j->m[1]; m[2] = j->m[2];
    m[3] = pt_acc_dd(1.0);
    vmul_dd(m, exact, &c->world_dd[k], &c->world_e[k], j->w, j->werr);
                                            /* (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World */
}

static void m_view(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)k; (void)v;
    vmul_dd(j->w, j->werr, &c->view_dd, &c->view_e, j->v, j->verr);
                                            /* (x_v y_v z_v w_v) = world * View */
}

static void m_clip(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)k; (void)v;
    vmul_dd(j->v, j->verr, &c->proj_dd, &c->proj_e, j->k, j->kerr);
                                            /* (x_k y_k z_k w_k) = view * Projection */
}

static void m_cvv(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)c; (void)k; (void)v;
    j->code = cvv_dd(j->k, j->kerr);
}

static void t_ndc(const pt_scene *s, pt_acc_mtail *t)
{
    (void)s;
    ndc_dd(t->k, t->kerr, t->n, t->en);     /* x_n = x_k / w_k, ... */
}

static void t_screen(const pt_scene *s, pt_acc_mtail *t)
{
    screen_dd(s, t->n, t->en, t->sc, t->es);    /* x_s = (x_n + 1) * w * 0.5, ... */
}

static void t_viewport(const pt_scene *s, pt_acc_mtail *t)
{
    t->vp = viewport_dd(t->sc, t->es);      /* x_vp = floor(x_s), ... */
    pt_acc_mtail_pp(s, t, 1);               /* the rasterizer's point, exact */
}

/* ===== the matrix camera: clipping ===== */

/* P(t) with bounds from P0's, P1's and t's (et), each component within its
** bound of 0 taken as 0. */
static void lerp_dd(const pt_dd p0[4], const double e0[4], const pt_dd p1[4],
                    const double e1[4], pt_dd t, double et, pt_dd r[4], double er[4])
{
    int c;

    for (c = 0; c < 4; c++) {
        pt_dd d = pt_dd_sub(p1[c], p0[c]);

        r[c] = pt_dd_add(p0[c], pt_dd_mul(t, d));               /* P(t) = P0 + t (P1 - P0) */
        er[c] = e0[c] + fabs(t.hi) * (e0[c] + e1[c]) + fabs(d.hi) * et + TIE_U * fabs(r[c].hi);
        r[c] = snap0(r[c], er[c]);
    }
}

/* A bound on the error of t = d0 / (d0 - d1) from those of d0 and d1. */
static double t_bound(pt_dd t, pt_dd d0, pt_dd d1, double e0, double e1)
{
    return (e0 + fabs(t.hi) * (e0 + e1)) / fabs(d0.hi - d1.hi) + TIE_U * fabs(t.hi);
}

static int mseg(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    pt_dd q[4], d0[PT_CVV_NPLANES], d1[PT_CVV_NPLANES], t[2];
    double ea[PT_CVV_NPLANES], eb[PT_CVV_NPLANES], et[2] = {0, 0}, eq[4];
    int i, e;

    (void)c;
    t[0] = pt_acc_dd(0.0);
    t[1] = pt_acc_dd(1.0);
    cvv_dist_dd(a->k, a->kerr, d0);
    cvv_dist_dd(b->k, b->kerr, d1);
    ea[0] = a->kerr[2]; eb[0] = b->kerr[2];                     /* the distances' bounds */
    ea[1] = a->kerr[3] + a->kerr[2]; eb[1] = b->kerr[3] + b->kerr[2];
    for (i = 2; i < PT_CVV_NPLANES; i++) {
        ea[i] = a->kerr[3] + a->kerr[(i - 2) / 2];
        eb[i] = b->kerr[3] + b->kerr[(i - 2) / 2];
    }
    for (i = 0; i < PT_CVV_NPLANES; i++) {
        if (!(d0[i].hi >= 0) && !(d1[i].hi >= 0)) return 0;    /* both outside: gone */
        if (d0[i].hi < 0) {                                     /* entering through plane i */
            pt_dd u = pt_dd_div(d0[i], pt_dd_sub(d0[i], d1[i]));   /* t = d0 / (d0 - d1) */
            if (pt_dd_lt(t[0], u)) { t[0] = u; et[0] = t_bound(u, d0[i], d1[i], ea[i], eb[i]); }
        } else if (d1[i].hi < 0) {                              /* leaving through plane i */
            pt_dd u = pt_dd_div(d0[i], pt_dd_sub(d0[i], d1[i]));
            if (pt_dd_lt(u, t[1])) { t[1] = u; et[1] = t_bound(u, d0[i], d1[i], ea[i], eb[i]); }
        }
    }
    if (pt_dd_lt(t[1], t[0])) return 0;                            /* enters after it has left */
    for (e = 0; e < 2; e++) {
        if (!g->made[e]) continue;
        if (t[e].hi == e && t[e].lo == 0) {
            memcpy(q, e ? b->k : a->k, sizeof q);
            memcpy(eq, e ? b->kerr : a->kerr, sizeof eq);
        } else lerp_dd(a->k, a->kerr, b->k, b->kerr, t[e], et[e], q, eq);
        g->t[e] = t[e];
        memcpy(g->end[e].k, q, sizeof q);
        memcpy(g->end[e].kerr, eq, sizeof eq);
    }
    return 1;
}

/* ===== renderers 7 and 9 =====
**
** The stages' formulas of acc_rv_tmpl.h in double-double, from the scene's
** doubles taken as exact.  No tie rule here: the near plane and the square's
** edges are compared with exactly (a point a cut makes is on its edge by
** construction, the stage's test then counts it as inside). */

static pt_dd dd_num(double x) { return pt_acc_dd(x); }
static int dd_gt(pt_dd a, pt_dd b) { return pt_dd_lt(b, a); }
static int dd_le(pt_dd a, pt_dd b)
{
    return pt_dd_lt(a, b) || (a.hi == b.hi && a.lo == b.lo);  /* NaN: false */
}

#define RV_T pt_dd
#define RV_NUM(x) dd_num(x)
#define RV_ADD(a, b) pt_dd_add(a, b)
#define RV_SUB(a, b) pt_dd_sub(a, b)
#define RV_MUL(a, b) pt_dd_mul(a, b)
#define RV_DIV(a, b) pt_dd_div(a, b)
#define RV_NEG(a) pt_dd_neg(a)
#define RV_GT(a, b) dd_gt(a, b)
#define RV_LE(a, b) dd_le(a, b)
#define RV_FN(name) rvd_##name
#include "tools/accuracy/acc_rv_tmpl.h"

static int rvcam(pt_acc_rvcam *c)
{
    if (pt_acc_rvcam_exact(c) != 0) return -1;      /* the scene's doubles, as exact */
    rvd_r9_normalize(c->s->perspective, c->l, c->r, c->b, c->t, c->norm);
    return 0;
}

static void rv_model(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    (void)c; (void)k;
    j->m[0] = pt_acc_dd(v.x); j->m[1] = pt_acc_dd(v.y); j->m[2] = pt_acc_dd(v.z);
}

static void rv_world(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_dd in[4];

    (void)v;
    if (c->s->renderer != 9) return;                /* renderer 7 has no world */
    in[0] = j->m[0]; in[1] = j->m[1]; in[2] = j->m[2]; in[3] = pt_acc_dd(1.0);
    rvd_times_vec(c->world[k], in, j->w);           /* v_w = M v_m */
}

static void rv_view(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_dd t[3];

    (void)v;
    if (c->s->renderer == 9) { rvd_r9_view(j->w, c->view, j->v); return; }  /* (-1*e) + w */
    t[0] = pt_acc_dd(c->s->models[k].translate.x);
    t[1] = pt_acc_dd(c->s->models[k].translate.y);
    t[2] = pt_acc_dd(c->s->models[k].translate.z);
    rvd_r7_view(j->m, t, j->v);                     /* v = t + m */
}

static void rv_camera(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    pt_dd in[4], o[4], n[4][4];

    (void)k; (void)v;
    if (c->s->renderer == 9) {
        memcpy(n, c->norm, sizeof n);
        in[0] = j->v[0]; in[1] = j->v[1]; in[2] = j->v[2]; in[3] = pt_acc_dd(1.0);
        rvd_times_vec(n, in, o);                    /* v_c = N v_v */
        j->c[0] = o[0]; j->c[1] = o[1]; j->c[2] = o[2];
    } else
        rvd_r7_camera(j->v, c->s->perspective, c->l, c->r, c->b, c->t, j->c);
}

static void rv_image(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    (void)k; (void)v;
    rvd_project(j->c, c->s->perspective, j->ip);    /* x_p = x_c / -z_c */
}

static int rvnear(const pt_acc_rvcam *c, const pt_dd v0[3], const pt_dd v1[3], pt_acc_rvcut *cut)
{
    int v = rvd_nearclip(c->n, v0, v1, &cut->t, cut->p, &cut->off);

    if (v < 0) cut->edge = 0;                       /* PT_RV_NEAR */
    return v;
}

static int rvclip(pt_dd e[2][2], pt_acc_rvseg *g)
{
    pt_dd t[PT_ACC_RV_MAXCUTS], p[PT_ACC_RV_MAXCUTS][2];
    int edge[PT_ACC_RV_MAXCUTS], off[PT_ACC_RV_MAXCUTS], keep, k;

    keep = rvd_clip(e, PT_ACC_RV_MAXCUTS, &g->ncuts, edge, off, t, p);
    for (k = 0; k < g->ncuts && k < PT_ACC_RV_MAXCUTS; k++) {
        g->cut[k].edge = edge[k];
        g->cut[k].off = off[k];
        g->cut[k].t = t[k];
        g->cut[k].p[0] = p[k][0];
        g->cut[k].p[1] = p[k][1];
        g->made[off[k]] = 2;
    }
    return keep;
}

const pt_acc_ops pt_acc_dd_ops = {
    { model, camera, image, pixel, viewport, pt_acc_fb_stage, pt_acc_index_stage },
    raster, mcam,
    { m_model, m_world, m_view, m_clip, m_cvv },
    { t_ndc, t_screen, t_viewport, pt_acc_fb_tail, pt_acc_index_tail },
    mseg,
    rvcam, { rv_model, rv_world, rv_view, rv_camera, rv_image }, rvnear, rvclip
};
