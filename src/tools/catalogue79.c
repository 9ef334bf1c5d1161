/*
** src/tools/catalogue79.c -- the known mistakes of renderers 7 and 9's stages
** See LICENSE for copyright and license.
**
** The camera stage's mistakes are the real stage (pt_r7_view2camera(), or
** renderer 9's matrix from pt_r9_normalize_matrix()) called with a camera
** that makes the mistake: the rectangle moved so that r + l = 0 (the skew
** forgotten), or mirrored (its sign wrong), keeping r - l; the half-size
** mistake halves what the stage gives (dividing 2x by 2(r - l) is exact in
** binary).  The view stage's is pt_r9_world2view() with the view vector
** negated, read off EXPECTED's own world and view values.  The pixel
** mistakes act on EXPECTED's colours: gamma (pt_gamma()) applied once more,
** or undone, or the two pixels of an anti-aliased step swapped.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread79.h"
#include "tools/catalogue79.h"

pt_rv_camera pt_c79cam_stages(const pt_c79cam *c)
{
    pt_rv_camera k;
    memset(&k, 0, sizeof k);
    k.perspective = c->persp;
    k.l = c->l; k.r = c->r; k.b = c->b; k.t = c->t; k.n = c->n;
    return k;
}

/* The real camera stage of c's renderer on prev with camera k into out. */
static void camera_stage(const pt_c79cam *c, const pt_rv_camera *k, const double prev[4],
                         double out[4])
{
    pt_vec4 v = {prev[0], prev[1], prev[2], c->renderer == 9 ? prev[3] : 1.0}, o;
    if (c->renderer == 9) {
        pt_jmat m = pt_r9_normalize_matrix(k);
        o = pt_r9_view2camera(v, &m);
    } else {
        o = pt_r7_view2camera(v, k);
    }
    out[0] = o.x; out[1] = o.y; out[2] = o.z; out[3] = o.w;
}

/* x = x_v (no (z_v*(r+l))/2; orthographic: no -(r+l)/2): the rectangle
** centred, its width kept. */
static void skew_forgotten(const pt_c79cam *c, const double prev[4], const double right[4],
                           double out[4])
{
    pt_rv_camera k = pt_c79cam_stages(c);
    (void)right;
    k.l = -(c->r - c->l) / 2; k.r = (c->r - c->l) / 2;
    k.b = -(c->t - c->b) / 2; k.t = (c->t - c->b) / 2;
    camera_stage(c, &k, prev, out);
}

/* x = x_v - (z_v*(r+l))/2: the rectangle mirrored, r + l negated. */
static void skew_sign(const pt_c79cam *c, const double prev[4], const double right[4],
                      double out[4])
{
    pt_rv_camera k = pt_c79cam_stages(c);
    (void)right;
    k.l = -c->r; k.r = -c->l;
    k.b = -c->t; k.t = -c->b;
    camera_stage(c, &k, prev, out);
}

/* x_c = x/(r-l): scaled by the whole width, half the right value. */
static void half_size(const pt_c79cam *c, const double prev[4], const double right[4],
                      double out[4])
{
    pt_rv_camera k = pt_c79cam_stages(c);
    (void)right;
    camera_stage(c, &k, prev, out);
    out[0] /= 2;                        /* (2x)/(r-l) / 2 == x/(r-l) exactly */
    out[1] /= 2;
}

/* x_c = (4x)/(r-l): scaled by the half-width twice, twice the right value. */
static void double_size(const pt_c79cam *c, const double prev[4], const double right[4],
                        double out[4])
{
    pt_rv_camera k = pt_c79cam_stages(c);
    (void)right;
    camera_stage(c, &k, prev, out);
    out[0] *= 2;
    out[1] *= 2;
}

/* v + view for v - view: the view vector, EXPECTED's world - view, negated. */
static void view_added(const pt_c79cam *c, const double prev[4], const double right[4],
                       double out[4])
{
    pt_vec4 w = {prev[0], prev[1], prev[2], prev[3]}, o;
    pt_vec3 neg;
    (void)c;
    neg.x = right[0] - prev[0];         /* -view = view_v - world */
    neg.y = right[1] - prev[1];
    neg.z = right[2] - prev[2];
    o = pt_r9_world2view(w, neg);
    out[0] = o.x; out[1] = o.y; out[2] = o.z; out[3] = o.w;
}

/* ===== a position's matrix ===== */

/* Solve a x = b for x (a n x n, b its column n; n <= 4) by elimination with
** partial pivoting: 0, or -1 when a is too near singular to fix x. */
static int solve(int n, double a[4][5], double x[4])
{
    double big = 0;
    int i, j, k;

    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) big = fmax(big, fabs(a[i][j]));
    for (k = 0; k < n; k++) {
        int p = k;
        for (i = k + 1; i < n; i++)
            if (fabs(a[i][k]) > fabs(a[p][k])) p = i;
        if (!(fabs(a[p][k]) > 1e-9 * big)) return -1;
        for (j = 0; j <= n; j++) { double s = a[k][j]; a[k][j] = a[p][j]; a[p][j] = s; }
        for (i = k + 1; i < n; i++) {
            double f = a[i][k] / a[k][k];
            for (j = k; j <= n; j++) a[i][j] -= f * a[k][j];
        }
    }
    for (k = n - 1; k >= 0; k--) {
        double s = a[k][n];
        for (j = k + 1; j < n; j++) s -= a[k][j] * x[j];
        x[k] = s / a[k][k];
    }
    return 0;
}

/* The affine matrix M = [A | t] that takes EXPECTED's model vertices (prev)
** to its world vertices (right), least squares over all n: rows[r] = row r
** of [A | t].  0, or -1 when the vertices lie in one plane (M not fixed). */
static int fit_matrix(size_t n, const double (*prev)[4], const double (*right)[4],
                      double rows[3][4])
{
    int r, i, j;
    size_t k;
    if (n < 4) return -1;
    for (r = 0; r < 3; r++) {
        double a[4][5];
        memset(a, 0, sizeof a);
        for (k = 0; k < n; k++) {           /* normal equations: sum h h^T m = sum h w_r */
            const double h[4] = {prev[k][0], prev[k][1], prev[k][2], 1.0};
            for (i = 0; i < 4; i++) {
                for (j = 0; j < 4; j++) a[i][j] += h[i] * h[j];
                a[i][4] += h[i] * right[k][r];
            }
        }
        if (solve(4, a, rows[r]) != 0) return -1;
    }
    return 0;
}

/* [A | 0] as a buildFromRows op, applied by mul. */
static pt_matop linear_op(pt_matmul mul, double rows[3][4])
{
    pt_matop op;
    int i, j;
    memset(&op, 0, sizeof op);
    op.mul = mul;
    op.kind = PT_MATOP_ROWS;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) op.a[4*i + j] = rows[i][j];
    op.a[15] = 1;
    return op;
}

static pt_matop translate_op(pt_matmul mul, double x, double y, double z)
{
    pt_matop op;
    memset(&op, 0, sizeof op);
    op.mul = mul;
    op.kind = PT_MATOP_TRANSLATE;
    op.a[0] = x; op.a[1] = y; op.a[2] = z;
    return op;
}

/* The real stage (pt_r9_model2world()) on each vertex with matrix m. */
static void world_of(const pt_jmat *m, size_t n, const double (*prev)[4], double (*out)[4])
{
    size_t k;
    for (k = 0; k < n; k++) {
        pt_vec4 v = {prev[k][0], prev[k][1], prev[k][2], prev[k][3]}, o;
        o = pt_r9_model2world(v, m);
        out[k][0] = o.x; out[k][1] = o.y; out[k][2] = o.z; out[k][3] = o.w;
    }
}

/* Matrix.times(Matrix) giving m * this for this * m: the position's matrix
** composed backwards.  Which two factors it had, EXPECTED's numbers do not
** say; its M = [A | t] is either T(t)*L, composed backwards L*T(t) = [A | A t]
** (alt 0), or L*T(A^-1 t), backwards T(A^-1 t)*L = [A | A^-1 t] (alt 1). */
static int order_swapped(size_t n, const double (*prev)[4], const double (*right)[4], int alt,
                         double (*out)[4])
{
    double rows[3][4];
    pt_matop op[2];
    pt_jmat m;

    if (alt > 1 || fit_matrix(n, prev, right, rows) != 0) return -1;
    if (alt == 0) {
        op[0] = linear_op(PT_MATMUL_SET, rows);
        op[1] = translate_op(PT_MATMUL_POST, rows[0][3], rows[1][3], rows[2][3]);
    } else {
        double a[4][5], t0[4];
        int i, j;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) a[i][j] = rows[i][j];
            a[i][3] = rows[i][3];           /* A t0 = t */
        }
        if (solve(3, a, t0) != 0) return -1;
        op[0] = translate_op(PT_MATMUL_SET, t0[0], t0[1], t0[2]);
        op[1] = linear_op(PT_MATMUL_POST, rows);
    }
    m = pt_r9_position_matrix(op, 2);      /* built as Matrix.java builds it */
    world_of(&m, n, prev, out);
    return 0;
}

/* Matrix.times(Vertex) summing each column with v for each row: M^T v. */
static int product_transposed(size_t n, const double (*prev)[4], const double (*right)[4],
                              int alt, double (*out)[4])
{
    double rows[3][4];
    pt_jmat m;
    int j;

    if (alt > 0 || fit_matrix(n, prev, right, rows) != 0) return -1;
    for (j = 0; j < 3; j++) {               /* column j of M^T: row j of M */
        m.col[j].x = rows[j][0]; m.col[j].y = rows[j][1];
        m.col[j].z = rows[j][2]; m.col[j].w = rows[j][3];
    }
    m.col[3].x = 0; m.col[3].y = 0; m.col[3].z = 0; m.col[3].w = 1;
    world_of(&m, n, prev, out);
    return 0;
}

/* ===== the clip stages ===== */

/* The cuts a clip stage made, heard through its listener. */
typedef struct cutlog {
    pt_rv_cut c[4096];           /* in order */
    size_t prim[4096];           /* the primitive each cut belongs to */
    size_t n, nprim;
    int full;                    /* 1: more than fit */
} cutlog;

static void hear_prim(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    cutlog *cl = ud;
    (void)m; (void)p;
    cl->nprim++;
}

static void hear_cut(void *ud, const pt_rv_cut *cut)
{
    cutlog *cl = ud;
    if (cl->n < sizeof cl->c / sizeof cl->c[0]) {
        cl->prim[cl->n] = cl->nprim;
        cl->c[cl->n++] = *cut;
    } else {
        cl->full = 1;
    }
}

/* The real stage st on m (near plane n), its cuts into *cl when cl is not NULL. */
static int run_stage(int st, double n, pt_rv_model *m, cutlog *cl)
{
    pt_rv_clip_ls ls;
    int rc;

    memset(&ls, 0, sizeof ls);
    ls.begin = hear_prim;
    ls.cut = hear_cut;
    ls.ud = cl;
    rc = st == PT_T79_NEARCLIP ? pt_rv_nearclip(m, n, cl ? &ls : NULL) : pt_rv_clip(m, cl ? &ls : NULL);
    return rc < 0 || (cl && cl->full) ? -1 : 0;
}

/* z <= -n kept for z <= n: the near plane on the camera's other side. */
static int near_sign(const pt_c79cam *c, pt_rv_model *m)
{
    return run_stage(PT_T79_NEARCLIP, -c->n, m, NULL);
}

/* No near clip at all: nothing cut, nothing made. */
static int near_ignored(const pt_c79cam *c, pt_rv_model *m)
{
    (void)c; (void)m;
    return 0;
}

/* The colours of cut k's two ends (pt_rv_cut's c[0], c[1]) as the mistake
** made them: an end an earlier cut of the same primitive made has the colour
** the mistake gave it (already in m), not the stage's. */
static void ends_of(const cutlog *cl, size_t k, const pt_rv_model *m, pt_rgb e[2])
{
    size_t j;
    int i;
    for (i = 0; i < 2; i++) {
        e[i] = cl->c[k].c[i];
        for (j = k; j-- > 0 && cl->prim[j] == cl->prim[k];)
            if (!memcmp(&e[i], &cl->c[j].c[2], sizeof e[i])) {
                e[i] = m->c[cl->c[j].c_new];
                break;
            }
    }
}

/* Each new vertex gets the kept end's colour instead of (1-t)*c_1 + t*c_0. */
static int color_kept(int st, const pt_c79cam *c, pt_rv_model *m)
{
    cutlog *cl = calloc(1, sizeof *cl);
    size_t k;
    if (!cl || run_stage(st, c->n, m, cl) != 0) { free(cl); return -1; }
    for (k = 0; k < cl->n; k++) {
        pt_rgb e[2];
        ends_of(cl, k, m, e);
        m->c[cl->c[k].c_new] = st == PT_T79_NEARCLIP ? e[cl->c[k].off == 0 ? 1 : 0] : e[0];
    }
    free(cl);
    return 0;
}

static int near_color_kept(const pt_c79cam *c, pt_rv_model *m) { return color_kept(PT_T79_NEARCLIP, c, m); }
static int clip_color_kept(const pt_c79cam *c, pt_rv_model *m) { return color_kept(PT_T79_CLIP, c, m); }

/* One component in bytes: (int)((1-t)*B_1 + t*B_0), B = the Color's byte. */
static float byte_mix(double t, float c1, float c0)
{
    int b = (int)((1 - t) * pt_color_byte(c1) + t * pt_color_byte(c0));
    return (float)b / 255.0f;                   /* new Color(int, int, int) */
}

/* Each new colour interpolated in the Color's bytes (getRed() ..), not its floats. */
static int color_bytes(int st, const pt_c79cam *c, pt_rv_model *m)
{
    cutlog *cl = calloc(1, sizeof *cl);
    size_t k;
    if (!cl || run_stage(st, c->n, m, cl) != 0) { free(cl); return -1; }
    for (k = 0; k < cl->n; k++) {
        pt_rgb e[2], *o = &m->c[cl->c[k].c_new];
        ends_of(cl, k, m, e);
        o->r = byte_mix(cl->c[k].t, e[1].r, e[0].r);
        o->g = byte_mix(cl->c[k].t, e[1].g, e[0].g);
        o->b = byte_mix(cl->c[k].t, e[1].b, e[0].b);
    }
    free(cl);
    return 0;
}

static int near_color_bytes(const pt_c79cam *c, pt_rv_model *m) { return color_bytes(PT_T79_NEARCLIP, c, m); }
static int clip_color_bytes(const pt_c79cam *c, pt_rv_model *m) { return color_bytes(PT_T79_CLIP, c, m); }

/* ===== a cut made the wrong way ===== */

/* Cut k again, t from p[1] (t = 0) to p[0] (t = 1) where coordinate i (0: x,
** 1: y, 2: z) reaches e: t = (e - a_i)/(b_i - a_i); coordinate `at` set to
** `val`, the others (1-t)*a + t*b (the rectangle clip's z 0).  The stages'
** own interpolation (rv_nearclip.c, rv_clip.c), here to take the mistake's
** i and e: same_cut() checks, on every cut, that the right i and e give the
** stage's own point bit for bit. */
static pt_rv_cut recut(int st, const pt_rv_cut *k, int i, double e, int at, double val)
{
    pt_rv_cut q = *k;
    const double a[3] = {k->p[1].x, k->p[1].y, k->p[1].z};
    const double b[3] = {k->p[0].x, k->p[0].y, k->p[0].z};
    double t = (e - a[i]) / (b[i] - a[i]), o[3];
    int j;

    for (j = 0; j < 2; j++) o[j] = (1 - t)*a[j] + t*b[j];     /* x = (1-t) x_1 + t x_0 */
    o[2] = st == PT_T79_NEARCLIP ? val : 0;
    o[at] = val;
    q.t = t;
    q.plane = val;
    q.p[2].x = o[0]; q.p[2].y = o[1]; q.p[2].z = o[2]; q.p[2].w = 1.0;
    return q;
}

/* The coordinate cut k's t is computed from, and the plane's value there. */
static void right_of(int st, const pt_rv_cut *k, int *i, double *e)
{
    *i = st == PT_T79_NEARCLIP ? 2 : k->edge == PT_RV_XPOS || k->edge == PT_RV_XNEG ? 0 : 1;
    *e = k->plane;
}

/* 1 when recut() with the right coordinate and plane is the stage's cut k. */
static int same_cut(int st, const pt_rv_cut *k)
{
    int i;
    double e;
    pt_rv_cut q;
    right_of(st, k, &i, &e);
    q = recut(st, k, i, e, i, e);
    return !memcmp(&q.t, &k->t, sizeof q.t) && !memcmp(&q.p[2], &k->p[2], sizeof q.p[2]);
}

/* The first cut the real stage st makes on segment p of m, alone (its cuts
** heard into cl): 1 and *k when it cuts, 0 when it keeps or drops the
** segment as it is, -1 when it cannot be run (out of memory, a colour Java
** refuses). */
static int first_cut(int st, const pt_c79cam *c, const pt_rv_model *m, const pt_rv_prim *p,
                     cutlog *cl, pt_rv_cut *k)
{
    pt_rv_model one;
    pt_rv_prim q;
    int rc = 0, i;

    memset(&one, 0, sizeof one);
    memset(&q, 0, sizeof q);
    q.kind = PT_RV_LINE;
    cl->n = cl->nprim = 0;
    cl->full = 0;
    for (i = 0; i < 2 && rc == 0; i++) {
        q.v[i] = q.c[i] = (uint32_t)i;
        rc = pt_rv_add_vertex(&one, m->v[p->v[i]]) || pt_rv_add_color(&one, m->c[p->c[i]]);
    }
    if (rc == 0) rc = pt_rv_add_prim(&one, &q);
    if (rc == 0) {
        int r = run_stage(st, c->n, &one, cl);
        rc = cl->n ? 1 : r;                     /* its first cut is all that counts */
        if (cl->n) *k = cl->c[0];
    }
    pt_rv_model_free(&one);
    return rc < 0 ? -1 : rc;
}

/* The student's loop on m's segments, one by one as the stage takes them:
** the stage says which end it cuts at which edge (first_cut()), how() makes
** that cut the student's way, its new vertex and colour are appended to m
** and replace the end cut off, and the stage looks at the new segment again,
** until it keeps or drops it (the near clip cuts once).  Every cut must pass
** same_cut().  -1 when a cut cannot be made (a colour Java refuses) or the
** loop does not end within MAXCUTS cuts. */
#define MAXCUTS 64
static int cuts_again(int st, const pt_c79cam *c, pt_rv_model *m,
                      int (*how)(int st, const pt_rv_cut *k, pt_rv_cut *q))
{
    cutlog *cl = calloc(1, sizeof *cl);
    size_t np = m->np, k;
    int bad = !cl;

    for (k = 0; k < np && !bad; k++) {
        pt_rv_prim p = m->p[k];
        int n, rc = 1;
        if (p.kind != PT_RV_LINE) continue;
        for (n = 0; rc == 1 && !bad; n++) {
            pt_rv_cut cut, q;
            if (n == MAXCUTS || (st == PT_T79_NEARCLIP && n == 1)) break;
            rc = first_cut(st, c, m, &p, cl, &cut);
            if (rc != 1) break;
            if (!same_cut(st, &cut) || how(st, &cut, &q) != 0 || pt_rv_cut_finish(m, &q, NULL) != 0) {
                bad = 1;                        /* pt_rv_cut_finish: its colour, in float */
                break;
            }
            p.v[q.off] = q.v_new;
            p.c[q.off] = q.c_new;
        }
        if (rc < 0 || n == MAXCUTS) bad = 1;
    }
    free(cl);
    return bad ? -1 : 0;
}

/* t from the other coordinate: the near clip's y for z, the rectangle's y
** for x and x for y. */
static int t_other(int st, const pt_rv_cut *k, pt_rv_cut *q)
{
    int i;
    double e;
    right_of(st, k, &i, &e);
    *q = recut(st, k, st == PT_T79_NEARCLIP ? 1 : 1 - i, e, i, e);
    return 0;
}

/* The rectangle's edges swapped: the end beyond x = +1 cut at x = -1, and so on. */
static int edge_swapped(int st, const pt_rv_cut *k, pt_rv_cut *q)
{
    int i;
    double e;
    right_of(st, k, &i, &e);
    *q = recut(st, k, i, -e, i, -e);
    return 0;
}

static int near_t_other(const pt_c79cam *c, pt_rv_model *m) { return cuts_again(PT_T79_NEARCLIP, c, m, t_other); }
static int clip_t_other(const pt_c79cam *c, pt_rv_model *m) { return cuts_again(PT_T79_CLIP, c, m, t_other); }
static int clip_swapped(const pt_c79cam *c, pt_rv_model *m) { return cuts_again(PT_T79_CLIP, c, m, edge_swapped); }

/* ===== the pixels ===== */

/* c (+- tol) through f, increasing, into [lo, hi], clamped to 0 .. 1. */
static void through(double (*f)(double), const double rgb[3], double tol, double lo[3], double hi[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        double a = rgb[k] - tol, b = rgb[k] + tol;
        lo[k] = f(a < 0 ? 0 : a > 1 ? 1 : a);
        hi[k] = f(b < 0 ? 0 : b > 1 ? 1 : b);
    }
}

static double gamma_once(double c) { return (double)pt_gamma((float)c); }
static double gamma_undone(double c) { return pow(c, 2.2); }   /* pt_gamma's inverse */

/* pow(c, 1/2.2) on top of the gamma already applied. */
static void gamma_twice(const double rgb[3], const double partner[3], int paired, double tol,
                        double lo[3], double hi[3])
{
    (void)partner; (void)paired;
    through(gamma_once, rgb, tol, lo, hi);
}

/* The colour as it was before the gamma: doGamma ignored. */
static void gamma_none(const double rgb[3], const double partner[3], int paired, double tol,
                       double lo[3], double hi[3])
{
    (void)partner; (void)paired;
    through(gamma_undone, rgb, tol, lo, hi);
}

static double same(double c) { return c; }

/* Each pixel of an anti-aliased step gets the other's weight, so the
** other's colour; a pixel without a partner (a point's) keeps its own. */
static void aa_swapped(const double rgb[3], const double partner[3], int paired, double tol,
                       double lo[3], double hi[3])
{
    through(same, paired ? partner : rgb, tol, lo, hi);
}

const pt_mistake79 pt_mistakes79[PT_NMISTAKES79] = {
    {PT_T79_CAMERA, 0, "the skew forgotten",
     "x_c = (2*x_v)/(r-l) without x_v + (z_v*(r+l))/2 (orthographic: without "
     "x_v - (r+l)/2): the view volume's centre line is not moved onto the -z axis, "
     "so an asymmetric rectangle (r+l != 0) is off centre", skew_forgotten, NULL, NULL, 0, NULL},
    {PT_T79_CAMERA, 0, "the skew's sign wrong",
     "x = x_v - (z_v*(r+l))/2 for x_v + (z_v*(r+l))/2: the centre line moves the "
     "other way, twice as far off", skew_sign, NULL, NULL, 0, NULL},
    {PT_T79_CAMERA, 0, "scaled by the width, not the half-width",
     "x_c = x/(r-l) for (2*x)/(r-l): dividing by r-l makes the half-width 1/2, so "
     "the picture is half as big", half_size, NULL, NULL, 0, NULL},
    {PT_T79_CAMERA, 0, "scaled by the half-width twice",
     "x_c = (2*x)/((r-l)/2): the half-width becomes 2, the picture twice as big",
     double_size, NULL, NULL, 0, NULL},
    {PT_T79_WORLD, 9, "the matrices multiplied in the wrong order",
     "Matrix.times(m) returning m * this for this * m: the position's matrix "
     "lines compose backwards, so rotate-then-translate R*T comes out T*R: the "
     "model is turned about its own origin and then moved, not moved and then "
     "turned about the world's origin (or the other way round); M = [A | t] "
     "becomes [A | A^-1 t] or [A | A t]", NULL, NULL, NULL, 0, order_swapped},
    {PT_T79_WORLD, 9, "the matrix-vector product transposed",
     "x_w = (M00*x_m) + (M10*y_m) + (M20*z_m) + (M30*w_m), a column of M times "
     "v_m for a row (v_w = M^T v_m): each rotation turns the other way and the "
     "translation lands in w_w = t.v_m + 1", NULL, NULL, NULL, 0, product_transposed},
    {PT_T79_VIEW, 9, "the camera translation added",
     "x_v = x_w + x_e for x_w - x_e: the world moves with the camera instead of "
     "against it", view_added, NULL, NULL, 0, NULL},
    {PT_T79_NEARCLIP, 0, "the near plane's sign wrong",
     "a vertex kept when z <= -n (the plane z = -n, behind the camera) for "
     "z <= n: what lies between the two planes is not cut, what lies beyond "
     "-n is cut there", NULL, near_sign, NULL, 0, NULL},
    {PT_T79_NEARCLIP, 0, "the near plane ignored",
     "no segment cut at z = n: what lies behind the camera is projected "
     "through it (x_c / -z_c with z_c > 0) and comes out mirrored", NULL, near_ignored, NULL, 0, NULL},
    {PT_T79_NEARCLIP, 0, "the near clip's colour not interpolated",
     "the new vertex gets the colour of the end kept, for (1-t)*c_1 + t*c_0",
     NULL, near_color_kept, NULL, 0, NULL},
    {PT_T79_CLIP, 0, "the clip's colour not interpolated",
     "the new vertex gets the inside end's colour, for (1-t)*c_o + t*c_i",
     NULL, clip_color_kept, NULL, 0, NULL},
    {PT_T79_NEARCLIP, 0, "the near clip's colour interpolated in bytes",
     "(int)((1-t)*getRed() + t*getRed()) of the two Colors for the float "
     "components (1-t)*r_1 + t*r_0: a byte truncated, not the float kept",
     NULL, near_color_bytes, NULL, 0, NULL},
    {PT_T79_CLIP, 0, "the clip's colour interpolated in bytes",
     "(int)((1-t)*getRed() + t*getRed()) of the two Colors for the float "
     "components (1-t)*r_o + t*r_i: a byte truncated, not the float kept",
     NULL, clip_color_bytes, NULL, 0, NULL},
    {PT_T79_NEARCLIP, 0, "the near clip's t from y",
     "t = (n - y_1)/(y_0 - y_1) for (n - z_1)/(z_0 - z_1): the new vertex is "
     "where the segment's y, not its z, reaches n", NULL, near_t_other, NULL, 0, NULL},
    {PT_T79_CLIP, 0, "the clip's t from the other coordinate",
     "at x = +-1, t = (e - y_o)/(y_i - y_o) for (e - x_o)/(x_i - x_o) (y for x at "
     "y = +-1): the new vertex slides to the square's corner", NULL, clip_t_other, NULL, 0, NULL},
    {PT_T79_CLIP, 0, "the clip's edges swapped",
     "the end beyond x = +1 cut at x = -1 (and x = -1 at +1, y likewise): the new "
     "vertex lies on the segment's far side, past its inside end", NULL, clip_swapped, NULL, 0, NULL},
    {PT_T79_NSTAGES, 0, "gamma applied twice",
     "c = pow(pow(c, 1/2.2), 1/2.2): the colours come out too light", NULL, NULL, gamma_twice, 1, NULL},
    {PT_T79_NSTAGES, 0, "gamma not applied",
     "c written as interpolated, without pow(c, 1/2.2) though gamma is on: the "
     "colours come out too dark", NULL, NULL, gamma_none, 1, NULL},
    {PT_T79_NSTAGES, 0, "the anti-aliasing weights swapped",
     "the pixel nearer the line gets the weight 1 - w of the one farther away "
     "(and the other way round): each step's two colours trade places", NULL, NULL, aa_swapped, 0, NULL},
};
