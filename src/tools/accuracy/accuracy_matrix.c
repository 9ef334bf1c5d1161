/*
** src/tools/accuracy/accuracy_matrix.c -- the matrix camera in float, double and double-double
** See LICENSE for copyright and license.
**
** The matrix camera's part of `pipetrace accuracy` (src/tools/accuracy/accuracy.h): View,
** Projection and each World built in each arithmetic; a vertex's journey
** model -> world -> view -> clip -> cvv -> ndc -> screen -> viewport ->
** framebuffer -> index; a segment clipped in clip space; and the errors of
** these stages against the reference.  As in src/tools/accuracy/accuracy.c each arithmetic is
** written out in its own type, and each computing line echoes its formula.
** Double is the pipeline itself: stages/pt_mat4.c's product, stages/m4..m7
** and src/core/clip.c called as they are, with pt_lookat()'s and pt_perspective()'s
** matrices; tests/test_accuracy.c checks it value for value against the
** pipeline's records.
**
** Float and the reference have a small function per stage: vmul (world, view
** and clip are the same row-vector product), cvv, ndc, screen and viewport;
** framebuffer and index are integers, the same in every arithmetic (tail_int).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/accuracy/accuracy.h"
#include "core/pipetrace.h"

static const double PI = 3.14159265358979323846;       /* stages/pt_mat4.c's */

/* pi = hi + lo, to about 2^-107 relative (hi is PI). */
static const pt_dd PI_DD = { 0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53 };

typedef struct mat_f { float m[4][4]; } mat_f;          /* m[row][col] */

/* The matrices of one arithmetic; only that arithmetic's set is filled. */
struct pt_acc_mcam {
    const pt_scene *s;           /* not owned */
    pt_arith arith;
    mat_f view_f, proj_f, *world_f;             /* float: world_f[k]; owned */
    pt_mat4 view_d, proj_d, *world_d;           /* double */
    pt_dd_mat4 view_dd, proj_dd, *world_dd;     /* double-double */
    pt_mat4 view_e, proj_e, *world_e;           /* bounds on its entries' errors */
};

/* ===== double-double: helpers, cot, matrices ===== */

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

static pt_dd dd(double x)                   /* x exactly: pt_dd_from(), inlined */
{
    pt_dd r;

    r.hi = x;
    r.lo = 0.0;
    return r;
}

static pt_dd dd_sub(pt_dd a, pt_dd b) { return pt_dd_add(a, pt_dd_neg(b)); }

/* a < b for the values hi + lo (both normalised: hi = fl(hi + lo)). */
static int dd_lt(pt_dd a, pt_dd b)
{
    return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}

/* sin x and cos x for |x| <= pi/4: their Taylor series, term by term, until
** both terms fall below 2^-110 of their sums. */
static void dd_sincos(pt_dd x, pt_dd *s, pt_dd *c)
{
    pt_dd mx2 = pt_dd_neg(pt_dd_mul(x, x)), ts = x, tc = dd(1.0);
    double n;

    *s = ts;
    *c = tc;
    for (n = 1; n < 60; n += 2) {
        tc = pt_dd_div(pt_dd_mul(tc, mx2), dd(n * (n + 1)));        /* (-1)^k x^2k/(2k)! */
        ts = pt_dd_div(pt_dd_mul(ts, mx2), dd((n + 1) * (n + 2)));  /* (-1)^k x^(2k+1)/(2k+1)! */
        *c = pt_dd_add(*c, tc);
        *s = pt_dd_add(*s, ts);
        if (fabs(tc.hi) < 0x1p-110 * fabs(c->hi) && fabs(ts.hi) < 0x1p-110 * fabs(s->hi))
            break;
    }
}

pt_dd pt_dd_cot_deg(double deg)
{
    int above = deg > 45;                   /* cot(deg) = tan(90 - deg) */
    double a = above ? 90 - deg : deg;      /* exact (Sterbenz) */
    pt_dd s, c;

    if (deg == 45) return dd(1.0);
    dd_sincos(pt_dd_div(pt_dd_mul(dd(a), PI_DD), dd(180.0)), &s, &c);  /* x = a * pi/180 */
    return above ? pt_dd_div(s, c) : pt_dd_div(c, s);
}

pt_dd_mat4 pt_dd_mat4_mul(const pt_dd_mat4 *a, const pt_dd_mat4 *b)
{
    pt_dd_mat4 r;
    int i, j, k;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {           /* (a*b)_ij = sum_k a_ik b_kj */
            r.m[i][j] = pt_dd_mul(a->m[i][0], b->m[0][j]);
            for (k = 1; k < 4; k++)
                r.m[i][j] = pt_dd_add(r.m[i][j], pt_dd_mul(a->m[i][k], b->m[k][j]));
        }
    return r;
}

void pt_dd_vec4_mul(const pt_dd v[4], const pt_dd_mat4 *m, pt_dd r[4])
{
    int c, k;

    for (c = 0; c < 4; c++) {               /* x' = x*m0c + y*m1c + z*m2c + w*m3c */
        r[c] = pt_dd_mul(v[0], m->m[0][c]);
        for (k = 1; k < 4; k++) r[c] = pt_dd_add(r[c], pt_dd_mul(v[k], m->m[k][c]));
    }
}

/* ===== the matrices in float ===== */

/*
** stages/pt_mat4.c's formulas from the scene's numbers rounded to float, with
** sqrtf (correctly rounded) and sinf, cosf.  The parser's checks are not
** repeated: a camera that float cannot build (a direction whose squared
** length overflows float, say) gets inf or NaN entries, and every vertex shows
** it.  Up is re-derived as d x h, pipetrace's default (not --raw-lookat).
*/

static void identity_f(mat_f *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = i == j ? 1.0f : 0.0f;
}

static mat_f mul_f(const mat_f *a, const mat_f *b)
{
    mat_f r;
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)             /* (a*b)_ij = sum_k a_ik b_kj */
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j]
                      + a->m[i][2] * b->m[2][j] + a->m[i][3] * b->m[3][j];
    return r;
}

static void vec3_f(pt_vec3 v, float r[3])
{
    r[0] = pt_acc_to_float(v.x);
    r[1] = pt_acc_to_float(v.y);
    r[2] = pt_acc_to_float(v.z);
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

static void lookat_f(const pt_scene *s, mat_f *r)
{
    float eye[3], d[3], u[3], h[3];
    int i;

    vec3_f(s->eye, eye);
    vec3_f(s->dir, d);
    vec3_f(s->up, u);
    normalize_f(d);                         /* d = dir/|dir| */
    normalize_f(u);                         /* u = up/|up| */
    cross_f(u, d, h);                       /* h = (u x d)/|u x d| */
    normalize_f(h);
    cross_f(d, h, u);                       /* u = d x h */
    identity_f(r);
    for (i = 0; i < 3; i++) { r->m[i][0] = h[i]; r->m[i][1] = u[i]; r->m[i][2] = d[i]; }
    r->m[3][0] = -dot_f(eye, h);            /* last row (-eye.h, -eye.u, -eye.d, 1) */
    r->m[3][1] = -dot_f(eye, u);
    r->m[3][2] = -dot_f(eye, d);
}

static void perspective_f(const pt_scene *s, mat_f *r)
{
    float fov = pt_acc_to_float(s->fov), aspect = pt_acc_to_float(s->aspect);
    float n = pt_acc_to_float(s->znear), f = pt_acc_to_float(s->zfar);
    float a = fov / 2 * ((float)PI / 180), cot;

    cot = fov == 90 ? 1.0f : cosf(a) / sinf(a);     /* cot(fov/2); exact at 90 degrees */
    memset(r, 0, sizeof *r);
    r->m[0][0] = cot / aspect;              /* x' = x * cot(fov/2) / aspect */
    r->m[1][1] = cot;                       /* y' = y * cot(fov/2) */
    r->m[2][2] = f / (f - n);               /* z' = z * f/(f-n) ... */
    r->m[3][2] = f * n / (n - f);           /*      - f*n/(f-n) */
    r->m[2][3] = 1.0f;                      /* w' = z */
}

static void world_f(const pt_model *m, mat_f *r)
{
    mat_f w, t;
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) w.m[i][j] = pt_acc_to_float(m->world.m[i][j]);
    identity_f(&t);
    vec3_f(m->translate, t.m[3]);           /* T(translate): the last row */
    *r = mul_f(&w, &t);                     /* World = (world lines) * T */
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
    r[0] = dd(v.x);
    r[1] = dd(v.y);
    r[2] = dd(v.z);
}

static pt_dd dot_dd(const pt_dd a[3], const pt_dd b[3])
{
    return pt_dd_add(pt_dd_add(pt_dd_mul(a[0], b[0]), pt_dd_mul(a[1], b[1])),
                     pt_dd_mul(a[2], b[2]));
}

static void cross_dd(const pt_dd a[3], const pt_dd b[3], pt_dd r[3])
{
    r[0] = dd_sub(pt_dd_mul(a[1], b[2]), pt_dd_mul(a[2], b[1]));
    r[1] = dd_sub(pt_dd_mul(a[2], b[0]), pt_dd_mul(a[0], b[2]));
    r[2] = dd_sub(pt_dd_mul(a[0], b[1]), pt_dd_mul(a[1], b[0]));
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
        for (j = 0; j < 4; j++) r->m[i][j] = dd(i == j ? 1.0 : 0.0);
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
    pt_dd n = dd(s->znear), f = dd(s->zfar);
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = dd(0.0);
    r->m[0][0] = pt_dd_div(cot, dd(s->aspect));                 /* x' = x * cot(fov/2) / aspect */
    r->m[1][1] = cot;                                           /* y' = y * cot(fov/2) */
    r->m[2][2] = pt_dd_div(f, dd_sub(f, n));                    /* z' = z * f/(f-n) ... */
    r->m[3][2] = pt_dd_div(pt_dd_mul(f, n), dd_sub(n, f));      /*      - f*n/(f-n) */
    r->m[2][3] = dd(1.0);                                       /* w' = z */
}

static void world_dd(const pt_model *m, pt_dd_mat4 *r, pt_mat4 *e)
{
    pt_dd_mat4 w, t;
    int i, j, k;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) w.m[i][j] = dd(m->world.m[i][j]);
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

/* ===== the camera of one arithmetic ===== */

pt_acc_mcam *pt_acc_mcam_make(const pt_scene *s, pt_arith a)
{
    pt_acc_mcam *c = calloc(1, sizeof *c);
    size_t k, n = s->nmodels ? s->nmodels : 1;
    int skewed = 0;

    if (!c) return NULL;
    c->s = s;
    c->arith = a;
    switch (a) {
    case PT_ARITH_FLOAT:
        if ((c->world_f = malloc(n * sizeof *c->world_f)) == NULL) break;
        lookat_f(s, &c->view_f);
        perspective_f(s, &c->proj_f);
        for (k = 0; k < s->nmodels; k++) world_f(&s->models[k], &c->world_f[k]);
        return c;
    case PT_ARITH_DOUBLE:                   /* stages/pt_matrix.c's pt_matrix_plan() */
        if ((c->world_d = malloc(n * sizeof *c->world_d)) == NULL) break;
        pt_lookat(&c->view_d, s->eye, s->dir, s->up, 0, &skewed);
        pt_perspective(&c->proj_d, s->fov, s->aspect, s->znear, s->zfar);
        for (k = 0; k < s->nmodels; k++) {
            const pt_model *m = &s->models[k];
            pt_mat4 t = pt_mat4_translate(m->translate.x, m->translate.y, m->translate.z);

            c->world_d[k] = pt_mat4_mul(&m->world, &t);      /* world lines, then translate */
        }
        return c;
    default:
        c->world_dd = malloc(n * sizeof *c->world_dd);
        c->world_e = malloc(n * sizeof *c->world_e);
        if (!c->world_dd || !c->world_e) break;
        lookat_dd(s, &c->view_dd);
        perspective_dd(s, &c->proj_dd);
        camera_bounds_dd(s, &c->view_dd, &c->proj_dd, &c->view_e, &c->proj_e);
        for (k = 0; k < s->nmodels; k++)
            world_dd(&s->models[k], &c->world_dd[k], &c->world_e[k]);
        return c;
    }
    pt_acc_mcam_free(c);
    return NULL;
}

void pt_acc_mcam_free(pt_acc_mcam *c)
{
    if (!c) return;
    free(c->world_f);
    free(c->world_d);
    free(c->world_dd);
    free(c->world_e);
    free(c);
}

static void widen_mat_f(const mat_f *a, pt_dd_mat4 *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = dd((double)a->m[i][j]);
}

static void widen_mat_d(const pt_mat4 *a, pt_dd_mat4 *r)
{
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r->m[i][j] = dd(a->m[i][j]);
}

void pt_acc_mcam_matrices(const pt_acc_mcam *c, size_t k, pt_dd_mat4 *world,
                          pt_dd_mat4 *view, pt_dd_mat4 *proj)
{
    switch (c->arith) {
    case PT_ARITH_FLOAT:
        if (world) widen_mat_f(&c->world_f[k], world);
        if (view) widen_mat_f(&c->view_f, view);
        if (proj) widen_mat_f(&c->proj_f, proj);
        break;
    case PT_ARITH_DOUBLE:
        if (world) widen_mat_d(&c->world_d[k], world);
        if (view) widen_mat_d(&c->view_d, view);
        if (proj) widen_mat_d(&c->proj_d, proj);
        break;
    default:
        if (world) *world = c->world_dd[k];
        if (view) *view = c->view_dd;
        if (proj) *proj = c->proj_dd;
    }
}

/* ===== the journeys ===== */

/* Framebuffer and index of the viewport pixel t->vp, and the pixel-plane point
** the rasterizer gets, x_pp = x_vp + 1, y_pp = h - y_vp: integers, the same in
** every arithmetic.  exact: hold the point exactly (the reference), else as
** pt_viewport2pixelplane()'s doubles. */
static void tail_int(const pt_scene *s, pt_acc_mtail *t, int exact)
{
    pt_pix vp = t->vp, fb = {0, 0, 0};

    if (vp.ok) {
        fb.x = s->vp_x + vp.x;              /* x_fb = x_ul + x_vp */
        fb.y = s->vp_y + vp.y;              /* y_fb = y_ul + y_vp */
        fb.ok = 1;
        t->pp[0] = exact ? pt_dd_from_i64(vp.x + 1) : dd((double)(vp.x + 1));  /* x_pp = x_vp + 1 */
        t->pp[1] = exact ? pt_dd_from_i64(s->vp_h - vp.y)                      /* y_pp = h - y_vp */
                         : dd((double)(s->vp_h - vp.y));
    } else {
        t->pp[0] = t->pp[1] = dd((double)NAN);
    }
    t->fb = fb;
    t->idx = fb.ok && fb.x >= 0 && fb.x < s->fb_w && fb.y >= 0 && fb.y < s->fb_h
           ? fb.y * (int64_t)s->fb_w + fb.x : -1;   /* idx = y_fb * W + x_fb */
}

/* A vertex outside the view volume: its journey stops at the cvv. */
static void no_tail(pt_acc_mtail *t)
{
    memset(t, 0, sizeof *t);
    t->idx = -1;
    t->pp[0] = t->pp[1] = dd((double)NAN);
}

static void widen_f(const float *a, pt_dd *r, int n)
{
    int k;

    for (k = 0; k < n; k++) r[k] = dd((double)a[k]);
}

static void widen_d(const double *a, pt_dd *r, int n)
{
    int k;

    for (k = 0; k < n; k++) r[k] = dd(a[k]);
}

/* ----- float ----- */

static void vmul_f(const float v[4], const mat_f *m, float r[4])
{
    int c;

    for (c = 0; c < 4; c++)                 /* x' = x*m0c + y*m1c + z*m2c + w*m3c */
        r[c] = v[0] * m->m[0][c] + v[1] * m->m[1][c] + v[2] * m->m[2][c] + v[3] * m->m[3][c];
}

static void cvv_dist_f(const float k[4], float d[PT_CVV_NPLANES])
{
    d[0] = k[2];                            /* near:   z >= 0 */
    d[1] = k[3] - k[2];                     /* far:    z <= w */
    d[2] = k[3] + k[0];                     /* left:   x >= -w */
    d[3] = k[3] - k[0];                     /* right:  x <= w */
    d[4] = k[3] + k[1];                     /* bottom: y >= -w */
    d[5] = k[3] - k[1];                     /* top:    y <= w */
}

static unsigned cvv_f(const float k[4])
{
    float d[PT_CVV_NPLANES];
    unsigned code = 0;
    int i;

    cvv_dist_f(k, d);
    for (i = 0; i < PT_CVV_NPLANES; i++)
        if (!(d[i] >= 0)) code |= 1u << i;  /* NaN counts as outside */
    return code;
}

static void ndc_f(const float k[4], float n[3])
{
    n[0] = k[0] / k[3];                     /* x_n = x_k / w_k */
    n[1] = k[1] / k[3];                     /* y_n = y_k / w_k */
    n[2] = k[2] / k[3];                     /* z_n = z_k / w_k */
}

static void screen_f(const pt_scene *s, const float n[3], float sc[3])
{
    sc[0] = (n[0] + 1) * (float)s->vp_w * 0.5f;     /* x_s = (x_n + 1) * w * 0.5 */
    sc[1] = (1 - n[1]) * (float)s->vp_h * 0.5f;     /* y_s = (1 - y_n) * h * 0.5 */
    sc[2] = n[2];                                   /* z_s = z_n */
}

static pt_pix viewport_f(const float sc[3])
{
    pt_pix vp = {0, 0, 0};

    if (fabsf(sc[0]) < 0x1p62f && fabsf(sc[1]) < 0x1p62f) {   /* false for NaN */
        vp.x = (int64_t)floorf(sc[0]);      /* x_vp = floor(x_s) */
        vp.y = (int64_t)floorf(sc[1]);      /* y_vp = floor(y_s) */
        vp.ok = 1;
    }
    return vp;
}

static void tail_f(const pt_scene *s, const float k[4], pt_acc_mtail *t)
{
    float n[3], sc[3];

    ndc_f(k, n);
    screen_f(s, n, sc);
    t->vp = viewport_f(sc);
    widen_f(n, t->n, 3);
    widen_f(sc, t->sc, 3);
    tail_int(s, t, 0);
}

static void journey_f(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    float m[4], w[4], vw[4], kc[4];

    vec3_f(v, m);
    m[3] = 1;
    vmul_f(m, &c->world_f[k], w);           /* (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World */
    vmul_f(w, &c->view_f, vw);              /* (x_v y_v z_v w_v) = world * View */
    vmul_f(vw, &c->proj_f, kc);             /* (x_k y_k z_k w_k) = view * Projection */
    j->code = cvv_f(kc);
    widen_f(m, j->m, 3);
    widen_f(w, j->w, 4);
    widen_f(vw, j->v, 4);
    widen_f(kc, j->k, 4);
    memset(j->kerr, 0, sizeof j->kerr);
    if (j->code == 0) tail_f(c->s, kc, &j->t);
    else no_tail(&j->t);
}

/* ----- double: the pipeline's own functions, so its values are the trace's ----- */

static pt_vec4 vec4_of(const double a[4]) { pt_vec4 v = {a[0], a[1], a[2], a[3]}; return v; }

static void arr_of(pt_vec4 v, double a[4]) { a[0] = v.x; a[1] = v.y; a[2] = v.z; a[3] = v.w; }

static void tail_d(const pt_scene *s, const double k[4], pt_acc_mtail *t)
{
    pt_vec3 n = pt_clip2ndc(vec4_of(k), fabs(k[3]), NULL);      /* stages/m5..m7 */
    pt_vec3 sc = pt_ndc2screen(n, s->vp_w, s->vp_h, NULL);
    const double na[3] = {n.x, n.y, n.z}, sa[3] = {sc.x, sc.y, sc.z};

    t->vp = pt_screen2viewport(sc, s->vp_w, s->vp_h, NULL);
    widen_d(na, t->n, 3);
    widen_d(sa, t->sc, 3);
    tail_int(s, t, 0);
}

static void journey_d(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    double m[4] = {v.x, v.y, v.z, 1}, w[4], vw[4], kc[4];

    arr_of(pt_vec4_mul(vec4_of(m), &c->world_d[k]), w);     /* world = (m, 1) * World */
    arr_of(pt_vec4_mul(vec4_of(w), &c->view_d), vw);        /* view = world * View */
    arr_of(pt_vec4_mul(vec4_of(vw), &c->proj_d), kc);       /* clip = view * Projection */
    j->code = pt_clip2cvv(vec4_of(kc), NULL);
    widen_d(m, j->m, 3);
    widen_d(w, j->w, 4);
    widen_d(vw, j->v, 4);
    widen_d(kc, j->k, 4);
    memset(j->kerr, 0, sizeof j->kerr);
    if (j->code == 0) tail_d(c->s, kc, &j->t);
    else no_tail(&j->t);
}

/* ----- double-double ----- */

static pt_dd snap0(pt_dd x, double e)   /* within the bound of 0: 0 */
{
    return fabs(x.hi) <= e ? dd(0.0) : x;
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
    d[1] = snap0(dd_sub(k[3], k[2]), ek[3] + ek[2]);            /* far:    z <= w */
    d[2] = snap0(pt_dd_add(k[3], k[0]), ek[3] + ek[0]);         /* left:   x >= -w */
    d[3] = snap0(dd_sub(k[3], k[0]), ek[3] + ek[0]);            /* right:  x <= w */
    d[4] = snap0(pt_dd_add(k[3], k[1]), ek[3] + ek[1]);         /* bottom: y >= -w */
    d[5] = snap0(dd_sub(k[3], k[1]), ek[3] + ek[1]);            /* top:    y <= w */
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
    sc[0] = pt_dd_mul(pt_dd_mul(pt_dd_add(n[0], dd(1.0)), dd(s->vp_w)), dd(0.5));
                                            /* x_s = (x_n + 1) * w * 0.5 */
    sc[1] = pt_dd_mul(pt_dd_mul(dd_sub(dd(1.0), n[1]), dd(s->vp_h)), dd(0.5));
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

    if (fabs(dd_sub(x, dd(n)).hi) <= e) return (int64_t)n;    /* on an edge */
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

static void tail_dd(const pt_scene *s, const pt_dd k[4], const double ek[4], pt_acc_mtail *t)
{
    double en[3], es[2];

    ndc_dd(k, ek, t->n, en);
    screen_dd(s, t->n, en, t->sc, es);
    t->vp = viewport_dd(t->sc, es);
    tail_int(s, t, 1);
}

static void journey_dd(const pt_acc_mcam *c, size_t k, pt_vec3 v, pt_acc_mjourney *j)
{
    static const double exact[4] = {0, 0, 0, 0};
    double ew[4], ev[4];
    pt_dd m[4];

    vec3_dd(v, m);
    m[3] = dd(1.0);
    vmul_dd(m, exact, &c->world_dd[k], &c->world_e[k], j->w, ew);
                                            /* (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World */
    vmul_dd(j->w, ew, &c->view_dd, &c->view_e, j->v, ev);
                                            /* (x_v y_v z_v w_v) = world * View */
    vmul_dd(j->v, ev, &c->proj_dd, &c->proj_e, j->k, j->kerr);
                                            /* (x_k y_k z_k w_k) = view * Projection */
    j->code = cvv_dd(j->k, j->kerr);
    j->m[0] = m[0]; j->m[1] = m[1]; j->m[2] = m[2];
    if (j->code == 0) tail_dd(c->s, j->k, j->kerr, &j->t);
    else no_tail(&j->t);
}

void pt_acc_mjourney_of(const pt_acc_mcam *c, size_t k, pt_vec3 v_m, pt_acc_mjourney *j)
{
    switch (c->arith) {
    case PT_ARITH_FLOAT:  journey_f(c, k, v_m, j); break;
    case PT_ARITH_DOUBLE: journey_d(c, k, v_m, j); break;
    default:              journey_dd(c, k, v_m, j); break;
    }
}

/* ===== clipping ===== */

/*
** src/core/clip.c in each arithmetic: the signed distances d_i of both ends to the
** six planes; a plane both ends are outside of culls the segment; else it cuts
** at t = d0 / (d0 - d1), entering (d0 < 0: the largest t) or leaving (d1 < 0:
** the smallest t); enter > leave culls.  A new end is P(t) = P0 + t (P1 - P0),
** and goes on through ndc .. index in the same arithmetic.
*/

static void lerp_f(const float p0[4], const float p1[4], float t, float r[4])
{
    int c;

    for (c = 0; c < 4; c++) r[c] = p0[c] + t * (p1[c] - p0[c]);   /* P(t) = P0 + t (P1 - P0) */
}

static int mseg_f(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                  const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    float p0[4], p1[4], q[4], d0[PT_CVV_NPLANES], d1[PT_CVV_NPLANES], t[2] = {0, 1};
    int i, e;

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
        g->t[e] = dd((double)t[e]);
        tail_f(c->s, q, &g->end[e]);
    }
    return 1;
}

static int mseg_d(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                  const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    double p0[4], p1[4], t[2], q[2][4];
    pt_vec4 q0, q1;
    int i, e;

    for (i = 0; i < 4; i++) { p0[i] = a->k[i].hi; p1[i] = b->k[i].hi; }
    if (!pt_clip_segment(vec4_of(p0), vec4_of(p1), &t[0], &t[1], &q0, &q1))
        return 0;                           /* src/core/clip.c's, as the pipeline clips */
    arr_of(q0, q[0]);
    arr_of(q1, q[1]);
    for (e = 0; e < 2; e++) {
        if (!g->made[e]) continue;
        g->t[e] = dd(t[e]);
        tail_d(c->s, q[e], &g->end[e]);
    }
    return 1;
}

/* P(t) with bounds from P0's, P1's and t's (et), each component within its
** bound of 0 taken as 0. */
static void lerp_dd(const pt_dd p0[4], const double e0[4], const pt_dd p1[4],
                    const double e1[4], pt_dd t, double et, pt_dd r[4], double er[4])
{
    int c;

    for (c = 0; c < 4; c++) {
        pt_dd d = dd_sub(p1[c], p0[c]);

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

static int mseg_dd(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                   const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    pt_dd q[4], d0[PT_CVV_NPLANES], d1[PT_CVV_NPLANES], t[2];
    double ea[PT_CVV_NPLANES], eb[PT_CVV_NPLANES], et[2] = {0, 0}, eq[4];
    int i, e;

    t[0] = dd(0.0);
    t[1] = dd(1.0);
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
            pt_dd u = pt_dd_div(d0[i], dd_sub(d0[i], d1[i]));   /* t = d0 / (d0 - d1) */
            if (dd_lt(t[0], u)) { t[0] = u; et[0] = t_bound(u, d0[i], d1[i], ea[i], eb[i]); }
        } else if (d1[i].hi < 0) {                              /* leaving through plane i */
            pt_dd u = pt_dd_div(d0[i], dd_sub(d0[i], d1[i]));
            if (dd_lt(u, t[1])) { t[1] = u; et[1] = t_bound(u, d0[i], d1[i], ea[i], eb[i]); }
        }
    }
    if (dd_lt(t[1], t[0])) return 0;                            /* enters after it has left */
    for (e = 0; e < 2; e++) {
        if (!g->made[e]) continue;
        if (t[e].hi == e && t[e].lo == 0) {
            memcpy(q, e ? b->k : a->k, sizeof q);
            memcpy(eq, e ? b->kerr : a->kerr, sizeof eq);
        } else lerp_dd(a->k, a->kerr, b->k, b->kerr, t[e], et[e], q, eq);
        g->t[e] = t[e];
        tail_dd(c->s, q, eq, &g->end[e]);
    }
    return 1;
}

void pt_acc_mseg_of(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                    const pt_acc_mjourney *b, pt_acc_mseg *g)
{
    memset(g, 0, sizeof *g);
    g->made[0] = a->code != 0;              /* an end outside gets a new point */
    g->made[1] = b->code != 0;
    if (!g->made[0] && !g->made[1]) { g->visible = 1; return; }    /* all inside */
    switch (c->arith) {
    case PT_ARITH_FLOAT:  g->visible = mseg_f(c, a, b, g); break;
    case PT_ARITH_DOUBLE: g->visible = mseg_d(c, a, b, g); break;
    default:              g->visible = mseg_dd(c, a, b, g); break;
    }
    if (!g->visible) g->made[0] = g->made[1] = 0;
}

/* ===== errors ===== */

/* One pair of journeys from clip coordinates on, into rows ndc .. index; NULL:
** none on that side, which counts as infinite and as differing. */
static void tail_err(pt_acc_err e[PT_ACC_MAXROWS], const pt_scene *s,
                     const pt_acc_mtail *a, const pt_acc_mtail *ref)
{
    int row, k, in_a, in_ref;

    for (row = PT_ACC_M_NDC; row <= PT_ACC_M_INDEX; row++) e[row].of++;
    if (!a || !ref) {
        for (k = 0; k < 3; k++) {
            pt_acc_err_add(&e[PT_ACC_M_NDC], (double)INFINITY, 0.0);
            pt_acc_err_add(&e[PT_ACC_M_SCREEN], (double)INFINITY, 0.0);
        }
        for (k = 0; k < 2; k++) {
            pt_acc_err_add(&e[PT_ACC_M_VIEWPORT], (double)INFINITY, 0.0);
            pt_acc_err_add(&e[PT_ACC_M_FRAMEBUFFER], (double)INFINITY, 0.0);
        }
        for (row = PT_ACC_M_NDC; row <= PT_ACC_M_INDEX; row++) e[row].differ++;
        return;
    }
    e[PT_ACC_M_NDC].differ += pt_acc_err_reals(&e[PT_ACC_M_NDC], a->n, ref->n, 3);
    e[PT_ACC_M_SCREEN].differ += pt_acc_err_reals(&e[PT_ACC_M_SCREEN], a->sc, ref->sc, 3);
    e[PT_ACC_M_VIEWPORT].differ += pt_acc_err_pix(&e[PT_ACC_M_VIEWPORT], a->vp, ref->vp);
    e[PT_ACC_M_FRAMEBUFFER].differ += pt_acc_err_pix(&e[PT_ACC_M_FRAMEBUFFER], a->fb, ref->fb);
    if (a->idx >= 0 && ref->idx >= 0)
        pt_acc_err_add(&e[PT_ACC_M_INDEX], (double)a->idx, (double)ref->idx);
    e[PT_ACC_M_INDEX].differ += a->idx != ref->idx;
    in_a = a->vp.ok && pt_inside(a->vp.x, a->vp.y, s->vp_w, s->vp_h);
    in_ref = ref->vp.ok && pt_inside(ref->vp.x, ref->vp.y, s->vp_w, s->vp_h);
    e[PT_ACC_M_VIEWPORT].left += in_ref && !in_a;
    e[PT_ACC_M_VIEWPORT].entered += in_a && !in_ref;
}

void pt_acc_mcompare(const pt_acc_run *ref, const pt_acc_run *r, pt_acc_err e[PT_ACC_MAXROWS])
{
    const pt_scene *s = r->s;
    size_t k, v, q;
    int row, end;

    for (row = PT_ACC_M_MODEL; row <= PT_ACC_M_INDEX; row++) {
        e[row].real = row <= PT_ACC_M_CLIP || row == PT_ACC_M_NDC || row == PT_ACC_M_SCREEN;
        e[row].of = row <= PT_ACC_M_CVV ? r->nused : 0;    /* ndc ..: counted as they come */
    }
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        for (v = 0; v < m->nv; v++) {                       /* the used vertices */
            const pt_acc_mjourney *a = &r->mj[k][v], *b = &ref->mj[k][v];

            if (!r->used[k][v]) continue;
            e[PT_ACC_M_MODEL].differ += pt_acc_err_reals(&e[PT_ACC_M_MODEL], a->m, b->m, 3);
            e[PT_ACC_M_WORLD].differ += pt_acc_err_reals(&e[PT_ACC_M_WORLD], a->w, b->w, 4);
            e[PT_ACC_M_VIEW].differ += pt_acc_err_reals(&e[PT_ACC_M_VIEW], a->v, b->v, 4);
            e[PT_ACC_M_CLIP].differ += pt_acc_err_reals(&e[PT_ACC_M_CLIP], a->k, b->k, 4);
            e[PT_ACC_M_CVV].differ += a->code != b->code;
            if (a->code == 0 || b->code == 0)
                tail_err(e, s, a->code == 0 ? &a->t : NULL, b->code == 0 ? &b->t : NULL);
        }
        for (q = 0; q < m->nseg; q++)                       /* the points clipping made */
            for (end = 0; end < 2; end++) {
                const pt_acc_mseg *ga = &r->seg[k][q], *gb = &ref->seg[k][q];

                if (ga->made[end] || gb->made[end])
                    tail_err(e, s, ga->made[end] ? &ga->end[end] : NULL,
                             gb->made[end] ? &gb->end[end] : NULL);
            }
    }
}
