/*
** src/tools/accuracy/acc_float.c -- both cameras' stages and the DDA in float
** See LICENSE for copyright and license.
**
** binary32, 24 significant bits: the scene's doubles are rounded to float
** first (that rounding is float's error too), then every formula runs in
** float, in the stages' order, each computing line echoing its formula.  The
** literal 2.001 stands here as a float, as the teaching renderer would have it.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/acc_float.h"

static const double PI = 3.14159265358979323846;       /* stages/pt_mat4.c's */

/* ===== numbers ===== */

/* x rounded to float.  IEEE rounding, spelled out only for overflow, which C
** leaves undefined: from 2^128 - 2^103 (half an ulp above FLT_MAX) on, inf. */
static float to_float(double x)
{
    if (fabs(x) >= 0x1.ffffffp127) return x > 0 ? (float)INFINITY : -(float)INFINITY;
    return (float)x;
}

/* pt_pix_round() in float: Java's rounding, no value beyond 2^62. */
static int pix_round_f(float x, int64_t *out)
{
    float r;

    *out = 0;
    if (!isfinite(x)) return 0;
    r = floorf(x);
    if (x - r >= 0.5f) r += 1.0f;              /* ties go up: toward +infinity */
    if (fabsf(r) >= 0x1p62f) return 0;
    *out = (int64_t)r;
    return 1;
}

/* The binade [lo, 2 lo) that y1 and y2 share, both finite, of one sign and
** not near zero: returns 1 and sets *lo, else 0 (then take real steps). */
static int one_binade_f(float y1, float y2, float *lo)
{
    int e1, e2;

    if (!isfinite(y2) || y1 == 0.0f || y2 == 0.0f || (y1 > 0) != (y2 > 0)) return 0;
    frexpf(y1, &e1);
    frexpf(y2, &e2);
    *lo = ldexpf(1.0f, e2 - 1);
    return e1 == e2 && *lo >= 0x1p-100f;
}

/* pt_raster_advance() in float: y after k steps of y += m, exactly as k float
** additions leave it, in O(binades crossed).  The argument of src/core/raster.c
** holds word for word with 24 bits for 53: two real steps settle the parity,
** the third measures the constant increment d, and a jump of j steps adds
** j*d exactly while the sum stays 4|m| + 4|d| inside the binade. */
static float advance_f(float y, float m, uint64_t k)
{
    float y1, lo, d, room;
    uint64_t jump;

    if (m == 0.0f) return k ? y + m : y;            /* y + 0 is y (or +0 for -0) */
    for (; k >= 3; k -= jump) {
        y1 = y + m;                                 /* two real steps */
        y = y1 + m;
        k -= 2;
        jump = 0;
        if (!one_binade_f(y1, y, &lo)) continue;
        d = (y + m) - y;                            /* the constant increment */
        if (d == 0.0f) return y;                    /* m too small: y stays put */
        room = (y > 0) == (d > 0) ? 2 * lo - fabsf(y) : fabsf(y) - lo;
        room -= 4 * fabsf(m) + 4 * fabsf(d);
        if (room <= 0) continue;
        jump = (uint64_t)fminf(room / fabsf(d), 0x1p62f);
        if (jump > k) jump = k;
        y += (float)jump * d;                       /* exact: jump < 2^24 */
    }
    for (; k > 0; k--) y += m;                      /* the last one or two */
    return y;
}

/* n floats widened to pt_dd (exact). */
static void widen_f(const float *a, pt_dd *r, int n)
{
    int k;

    for (k = 0; k < n; k++) r[k] = pt_acc_dd((double)a[k]);
}

/* ===== the classic camera ===== */

/* Each stage reads its input from the journey (floats widened exactly, so
** (float)hi gives them back) and writes its output there. */

static void model(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    (void)c;
    j->m[0] = pt_acc_dd((double)to_float(v.x));     /* the scene's x_m rounded to float */
    j->m[1] = pt_acc_dd((double)to_float(v.y));
    j->m[2] = pt_acc_dd((double)to_float(v.z));
}

static void camera(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    float x_m = (float)j->m[0].hi, y_m = (float)j->m[1].hi, z_m = (float)j->m[2].hi;

    (void)v;
    j->c[0] = pt_acc_dd((double)(x_m + to_float(c->m->translate.x)));  /* x_c = x_m + x_t */
    j->c[1] = pt_acc_dd((double)(y_m + to_float(c->m->translate.y)));  /* y_c = y_m + y_t */
    j->c[2] = pt_acc_dd((double)(z_m + to_float(c->m->translate.z)));  /* z_c = z_m + z_t */
}

static void image(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    float x_c = (float)j->c[0].hi, y_c = (float)j->c[1].hi, z_c = (float)j->c[2].hi;
    float x_ip, y_ip;

    (void)v;
    if (c->s->perspective) {
        x_ip = x_c / -z_c;                          /* x_ip = x_c / -z_c */
        y_ip = y_c / -z_c;                          /* y_ip = y_c / -z_c */
    } else {
        x_ip = x_c;                                 /* x_ip = x_c */
        y_ip = y_c;                                 /* y_ip = y_c */
    }
    j->ip[0] = pt_acc_dd((double)x_ip);
    j->ip[1] = pt_acc_dd((double)y_ip);
}

static void pixel(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    float x_ip = (float)j->ip[0].hi, y_ip = (float)j->ip[1].hi;
    float k = c->choices & PT_ACC_TWO ? 2.0f : 2.001f;
    float w = (float)c->s->vp_w, h = (float)c->s->vp_h;

    (void)v;
    j->pp[0] = pt_acc_dd((double)(0.5f + w / k * (x_ip + 1.0f)));
                                                    /* x_pp = 0.5 + w/2.001 * (x_ip + 1) */
    j->pp[1] = pt_acc_dd((double)(0.5f + h / k * (y_ip + 1.0f)));
                                                    /* y_pp = 0.5 + h/2.001 * (y_ip + 1) */
}

static void viewport(const pt_acc_sctx *c, pt_vec3 v, pt_acc_journey *j)
{
    int64_t rx = 0, ry = 0;
    int ok = pix_round_f((float)j->pp[0].hi, &rx) && pix_round_f((float)j->pp[1].hi, &ry);

    (void)v;
    j->vp = pt_acc_vp_of(c->s, ok, rx, ry);         /* x_vp = round(x_pp) - 1, ... */
}

/* ===== the DDA ===== */

static int raster_f(float px0, float py0, float px1, float py1, int recompute,
                    const pt_acc_dda *o)
{
    int64_t e[4], s, first, last, r;
    float x0, y0, x1, y1, m, acc;
    pt_acc_line ln;
    int tr;

    if (!pix_round_f(px0, &e[0]) || !pix_round_f(py0, &e[1]) ||
        !pix_round_f(px1, &e[2]) || !pix_round_f(py1, &e[3]))
        return -1;
    x0 = (float)e[0]; y0 = (float)e[1];             /* the rounded endpoints */
    x1 = (float)e[2]; y1 = (float)e[3];             /* (exact: they were floats) */
    if (x0 == x1 && y0 == y1) { pt_acc_dda_dot(o, e[0], e[1]); return 0; }
    tr = fabsf(y1 - y0) > fabsf(x1 - x0);           /* |slope| > 1: step in y */
    pt_acc_dda_setup(&ln, tr, e, o, &first, &last);
    x0 = (float)e[0]; y0 = (float)e[1];
    x1 = (float)e[2]; y1 = (float)e[3];
    m = (y1 - y0) / (x1 - x0);                      /* m = dy / dx */
    if (first > last) return 0;
    if (recompute) {
        for (s = first; s <= last; s++) {
            float y = y0 + m * ((float)s - x0);     /* y = y0 + m*(x - x0) */
            int ok = pix_round_f(y, &r);
            pt_acc_dda_step(o, &ln, s, ok, r, (double)y);
        }
        return 0;
    }
    acc = advance_f(y0, m, (uint64_t)(first - e[0]));
    for (s = first; s <= last; s++) {
        int ok = pix_round_f(acc, &r);
        pt_acc_dda_step(o, &ln, s, ok, r, (double)acc);
        acc += m;                                   /* y += m */
    }
    return 0;
}

static int raster(const pt_dd p0[2], const pt_dd p1[2], unsigned choices,
                  const pt_acc_dda *o)
{
    return raster_f(to_float(p0[0].hi), to_float(p0[1].hi), to_float(p1[0].hi),
                    to_float(p1[1].hi), (choices & PT_ACC_RECOMPUTE) != 0, o);
}

/* ===== the matrix camera: matrices ===== */

/*
** stages/pt_mat4.c's formulas from the scene's numbers rounded to float, with
** sqrtf (correctly rounded) and sinf, cosf.  The parser's checks are not
** repeated: a camera that float cannot build (a direction whose squared
** length overflows float, say) gets inf or NaN entries, and every vertex shows
** it.  Up is re-derived as d x h, pipetrace's default (not --raw-lookat).
*/

static void vmul_f(const float v[4], const pt_acc_mat4f *m, float r[4])
{
    int c;

    for (c = 0; c < 4; c++)                 /* x' = x*m0c + y*m1c + z*m2c + w*m3c */
        r[c] = v[0] * m->m[0][c] + v[1] * m->m[1][c] + v[2] * m->m[2][c] + v[3] * m->m[3][c];
}

static void identity_f(pt_acc_mat4f *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = i == j ? 1.0f : 0.0f;
}

/* a * b: row i of the product is row i of a times b (vmul_f), so each
** entry is summed in k order. */
static pt_acc_mat4f mul_f(const pt_acc_mat4f *a, const pt_acc_mat4f *b)
{
    pt_acc_mat4f r;
    int i;

    for (i = 0; i < 4; i++) vmul_f(a->m[i], b, r.m[i]);
    return r;
}

static void vec3_f(pt_vec3 v, float r[3])
{
    r[0] = to_float(v.x);
    r[1] = to_float(v.y);
    r[2] = to_float(v.z);
}

static float dot_f(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross_f(const float a[3], const float b[3], float r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static void normalize_f(float v[3])
{
    float len = sqrtf(dot_f(v, v));         /* v / |v| */

    v[0] = v[0] / len; v[1] = v[1] / len; v[2] = v[2] / len;
}

/* v rounded to float and made a unit vector. */
static void unit_f(pt_vec3 v, float r[3])
{
    vec3_f(v, r);
    normalize_f(r);                         /* v / |v| */
}

static void lookat_f(const pt_scene *s, pt_acc_mat4f *r)
{
    float eye[3], d[3], u[3], h[3];
    const float *axis[3];
    int c, i;

    vec3_f(s->eye, eye);
    unit_f(s->dir, d);                      /* d = dir/|dir| */
    unit_f(s->up, u);                       /* u = up/|up| */
    cross_f(u, d, h);                       /* h = (u x d)/|u x d| */
    normalize_f(h);
    cross_f(d, h, u);                       /* u = d x h */
    axis[0] = h; axis[1] = u; axis[2] = d;
    identity_f(r);
    for (c = 0; c < 3; c++) {               /* columns h, u, d; last row -eye.h, ... */
        for (i = 0; i < 3; i++) r->m[i][c] = axis[c][i];
        r->m[3][c] = -dot_f(eye, axis[c]);  /* (-eye.h, -eye.u, -eye.d, 1) */
    }
}

static void perspective_f(const pt_scene *s, pt_acc_mat4f *r)
{
    float fov = to_float(s->fov), aspect = to_float(s->aspect);
    float n = to_float(s->znear), f = to_float(s->zfar);
    float a = fov / 2 * ((float)PI / 180), cot;

    cot = fov == 90 ? 1.0f : cosf(a) / sinf(a);     /* cot(fov/2); exact at 90 degrees */
    memset(r, 0, sizeof *r);
    r->m[0][0] = cot / aspect;              /* x' = x * cot(fov/2) / aspect */
    r->m[1][1] = cot;                       /* y' = y * cot(fov/2) */
    r->m[2][2] = f / (f - n);               /* z' = z * f/(f-n) ... */
    r->m[3][2] = f * n / (n - f);           /*      - f*n/(f-n) */
    r->m[2][3] = 1.0f;                      /* w' = z */
}

static void world_f(const pt_model *m, pt_acc_mat4f *r)
{
    pt_acc_mat4f w, t;
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) w.m[i][j] = to_float(m->world.m[i][j]);
    identity_f(&t);
    vec3_f(m->translate, t.m[3]);           /* T(translate): the last row */
    *r = mul_f(&w, &t);                     /* World = (world lines) * T */
}

static int mcam(pt_acc_mcam *c)
{
    const pt_scene *s = c->s;
    size_t k;

    c->world_f = malloc((s->nmodels ? s->nmodels : 1) * sizeof *c->world_f);
    if (!c->world_f) return -1;
    lookat_f(s, &c->view_f);
    perspective_f(s, &c->proj_f);
    for (k = 0; k < s->nmodels; k++) world_f(&s->models[k], &c->world_f[k]);
    return 0;
}

/* ===== the matrix camera: journeys ===== */

static void cvv_dist_f(const float k[4], float d[PT_CVV_NPLANES])
{
    d[0] = k[2];                            /* near:   z >= 0 */
    d[1] = k[3] - k[2];                     /* far:    z <= w */
    d[2] = k[3] + k[0];                     /* left:   x >= -w */
    d[3] = k[3] - k[0];                     /* right:  x <= w */
    d[4] = k[3] + k[1];                     /* bottom: y >= -w */
    d[5] = k[3] - k[1];                     /* top:    y <= w */
}

/* n values of a journey, floats widened exactly, back to float. */
static void narrow_f(const pt_dd *a, float *r, int n)
{
    int k;

    for (k = 0; k < n; k++) r[k] = (float)a[k].hi;
}

static void m_model(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    float m[3];

    (void)c; (void)k;
    vec3_f(v, m);                           /* the scene's numbers rounded to float */
    widen_f(m, j->m, 3);
}

static void m_world(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    float m[4], w[4];

    (void)v;
    narrow_f(j->m, m, 3);
    m[3] = 1;
    vmul_f(m, &c->world_f[k], w);           /* (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World */
    widen_f(w, j->w, 4);
}

/* out = in * m, in and out as the journey holds them. */
static void vmul_jf(const pt_dd in[4], const pt_acc_mat4f *m, pt_dd out[4])
{
    float a[4], r[4];

    narrow_f(in, a, 4);
    vmul_f(a, m, r);
    widen_f(r, out, 4);
}

static void m_view(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)k; (void)v;
    vmul_jf(j->w, &c->view_f, j->v);        /* (x_v y_v z_v w_v) = world * View */
}

static void m_clip(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    (void)k; (void)v;
    vmul_jf(j->v, &c->proj_f, j->k);        /* (x_k y_k z_k w_k) = view * Projection */
    memset(j->kerr, 0, sizeof j->kerr);
}

static void m_cvv(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    float kc[4], d[PT_CVV_NPLANES];
    unsigned code = 0;
    int i;

    (void)c; (void)k; (void)v;
    narrow_f(j->k, kc, 4);
    cvv_dist_f(kc, d);
    for (i = 0; i < PT_CVV_NPLANES; i++)
        if (!(d[i] >= 0)) code |= 1u << i;  /* NaN counts as outside */
    j->code = code;
}

static void t_ndc(const pt_scene *s, pt_acc_mtail *t)
{
    float k[4], n[3];

    (void)s;
    narrow_f(t->k, k, 4);
    n[0] = k[0] / k[3];                     /* x_n = x_k / w_k */
    n[1] = k[1] / k[3];                     /* y_n = y_k / w_k */
    n[2] = k[2] / k[3];                     /* z_n = z_k / w_k */
    widen_f(n, t->n, 3);
}

static void t_screen(const pt_scene *s, pt_acc_mtail *t)
{
    float n[3], sc[3];

    narrow_f(t->n, n, 3);
    sc[0] = (n[0] + 1) * (float)s->vp_w * 0.5f;     /* x_s = (x_n + 1) * w * 0.5 */
    sc[1] = (1 - n[1]) * (float)s->vp_h * 0.5f;     /* y_s = (1 - y_n) * h * 0.5 */
    sc[2] = n[2];                                   /* z_s = z_n */
    widen_f(sc, t->sc, 3);
}

static void t_viewport(const pt_scene *s, pt_acc_mtail *t)
{
    float x_s = (float)t->sc[0].hi, y_s = (float)t->sc[1].hi;
    pt_pix vp = {0, 0, 0};

    if (fabsf(x_s) < 0x1p62f && fabsf(y_s) < 0x1p62f) {     /* false for NaN */
        vp.x = (int64_t)floorf(x_s);        /* x_vp = floor(x_s) */
        vp.y = (int64_t)floorf(y_s);        /* y_vp = floor(y_s) */
        vp.ok = 1;
    }
    t->vp = vp;
    pt_acc_mtail_pp(s, t, 0);               /* the rasterizer's point */
}

/* ===== the matrix camera: clipping ===== */

static void lerp_f(const float p0[4], const float p1[4], float t, float r[4])
{
    int c;

    for (c = 0; c < 4; c++) r[c] = p0[c] + t * (p1[c] - p0[c]);   /* P(t) = P0 + t (P1 - P0) */
}

static int mseg(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    float p0[4], p1[4], q[4], d0[PT_CVV_NPLANES], d1[PT_CVV_NPLANES], t[2] = {0, 1};
    int i, e;

    (void)c;
    for (i = 0; i < 4; i++) { p0[i] = (float)a->k[i].hi; p1[i] = (float)b->k[i].hi; }  /* exact */
    cvv_dist_f(p0, d0);
    cvv_dist_f(p1, d1);
    for (i = 0; i < PT_CVV_NPLANES; i++) {
        if (!(d0[i] >= 0) && !(d1[i] >= 0)) return 0;  /* both outside: gone */
        if (d0[i] < 0) {                                /* entering through plane i */
            float u = d0[i] / (d0[i] - d1[i]);          /* t = d0 / (d0 - d1) */
            if (u > t[0]) t[0] = u;
        } else if (d1[i] < 0) {                         /* leaving through plane i */
            float u = d0[i] / (d0[i] - d1[i]);
            if (u < t[1]) t[1] = u;
        }
    }
    if (t[0] > t[1]) return 0;                          /* enters after it has left */
    for (e = 0; e < 2; e++) {
        if (!g->made[e]) continue;
        if (t[e] == e) memcpy(q, e ? p1 : p0, sizeof q);
        else lerp_f(p0, p1, t[e], q);
        g->t[e] = pt_acc_dd((double)t[e]);
        widen_f(q, g->end[e].k, 4);
    }
    return 1;
}

/* ===== renderers 7 and 9 ===== */

#define RV_T float
#define RV_NUM(x) ((float)(x))
#define RV_ADD(a, b) ((a) + (b))
#define RV_SUB(a, b) ((a) - (b))
#define RV_MUL(a, b) ((a) * (b))
#define RV_DIV(a, b) ((a) / (b))
#define RV_NEG(a) (-(a))
#define RV_GT(a, b) ((a) > (b))
#define RV_LE(a, b) ((a) <= (b))
#define RV_FN(name) rvf_##name
#include "tools/accuracy/acc_rv_tmpl.h"

static pt_dd round_f(pt_dd x)                       /* a double rounded to float */
{
    return pt_acc_dd((double)to_float(x.hi));
}

static int rvcam(pt_acc_rvcam *c)
{
    float n[4][4];
    size_t k;
    int i;

    if (pt_acc_rvcam_exact(c) != 0) return -1;      /* then each number rounded */
    for (k = 0; k < c->s->nmodels; k++)
        for (i = 0; i < 16; i++) c->world[k][i / 4][i % 4] = round_f(c->world[k][i / 4][i % 4]);
    c->l = round_f(c->l); c->r = round_f(c->r); c->b = round_f(c->b); c->t = round_f(c->t);
    c->n = round_f(c->n);
    for (i = 0; i < 3; i++) c->view[i] = round_f(c->view[i]);
    rvf_r9_normalize(c->s->perspective, (float)c->l.hi, (float)c->r.hi, (float)c->b.hi,
                     (float)c->t.hi, n);
    for (i = 0; i < 16; i++) c->norm[i / 4][i % 4] = pt_acc_dd((double)n[i / 4][i % 4]);
    return 0;
}

static void rv_model(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    (void)c; (void)k;
    j->m[0] = pt_acc_dd((double)to_float(v.x));     /* the scene's x_m rounded to float */
    j->m[1] = pt_acc_dd((double)to_float(v.y));
    j->m[2] = pt_acc_dd((double)to_float(v.z));
}

static void rv_world(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    float a[4][4], in[4] = {0, 0, 0, 1.0f}, o[4];
    int i;

    (void)v;
    if (c->s->renderer != 9) return;                /* renderer 7 has no world */
    for (i = 0; i < 16; i++) a[i / 4][i % 4] = (float)c->world[k][i / 4][i % 4].hi;
    narrow_f(j->m, in, 3);
    rvf_times_vec(a, in, o);                        /* v_w = M v_m */
    widen_f(o, j->w, 4);
}

static void rv_view(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    float in[3], e[3], o[3];

    (void)v;
    if (c->s->renderer == 9) {
        narrow_f(j->w, in, 3);
        narrow_f(c->view, e, 3);
        rvf_r9_view(in, e, o);                      /* v = (-1*e) + w */
    } else {
        narrow_f(j->m, in, 3);
        e[0] = to_float(c->s->models[k].translate.x);
        e[1] = to_float(c->s->models[k].translate.y);
        e[2] = to_float(c->s->models[k].translate.z);
        rvf_r7_view(in, e, o);                      /* v = t + m */
    }
    widen_f(o, j->v, 3);
}

static void rv_camera(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    float in[4] = {0, 0, 0, 1.0f}, o[4];

    (void)k; (void)v;
    narrow_f(j->v, in, 3);
    if (c->s->renderer == 9) {
        float n[4][4];
        int i;

        for (i = 0; i < 16; i++) n[i / 4][i % 4] = (float)c->norm[i / 4][i % 4].hi;
        rvf_times_vec(n, in, o);                    /* v_c = N v_v */
    } else
        rvf_r7_camera(in, c->s->perspective, (float)c->l.hi, (float)c->r.hi, (float)c->b.hi,
                      (float)c->t.hi, o);
    widen_f(o, j->c, 3);
}

static void rv_image(const pt_acc_rvcam *c, size_t k, pt_vec3 v, pt_acc_rvjourney *j)
{
    float in[3], o[2];

    (void)k; (void)v;
    narrow_f(j->c, in, 3);
    rvf_project(in, c->s->perspective, o);          /* x_p = x_c / -z_c */
    widen_f(o, j->ip, 2);
}

static int rvnear(const pt_acc_rvcam *c, const pt_dd v0[3], const pt_dd v1[3], pt_acc_rvcut *cut)
{
    float a[3], b[3], t = 0, p[3];
    int v;

    narrow_f(v0, a, 3);
    narrow_f(v1, b, 3);
    v = rvf_nearclip((float)c->n.hi, a, b, &t, p, &cut->off);
    if (v >= 0) return v;
    cut->edge = 0;                                  /* PT_RV_NEAR */
    cut->t = pt_acc_dd((double)t);
    widen_f(p, cut->p, 3);
    return v;
}

static int rvclip(pt_dd e[2][2], pt_acc_rvseg *g)
{
    float f[2][2], t[PT_ACC_RV_MAXCUTS], p[PT_ACC_RV_MAXCUTS][2];
    int edge[PT_ACC_RV_MAXCUTS], off[PT_ACC_RV_MAXCUTS], keep, k;

    narrow_f(e[0], f[0], 2);
    narrow_f(e[1], f[1], 2);
    keep = rvf_clip(f, PT_ACC_RV_MAXCUTS, &g->ncuts, edge, off, t, p);
    for (k = 0; k < g->ncuts && k < PT_ACC_RV_MAXCUTS; k++) {
        g->cut[k].edge = edge[k];
        g->cut[k].off = off[k];
        g->cut[k].t = pt_acc_dd((double)t[k]);
        widen_f(p[k], g->cut[k].p, 2);
        g->made[off[k]] = 2;
    }
    widen_f(f[0], e[0], 2);
    widen_f(f[1], e[1], 2);
    return keep;
}

const pt_acc_ops pt_acc_float_ops = {
    { model, camera, image, pixel, viewport, pt_acc_fb_stage, pt_acc_index_stage },
    raster, mcam,
    { m_model, m_world, m_view, m_clip, m_cvv },
    { t_ndc, t_screen, t_viewport, pt_acc_fb_tail, pt_acc_index_tail },
    mseg,
    rvcam, { rv_model, rv_world, rv_view, rv_camera, rv_image }, rvnear, rvclip
};
