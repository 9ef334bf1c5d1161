/*
** src/tools/accuracy/acc_rv_tmpl.h -- renderers 7 and 9's formulas, written once for any arithmetic
** See LICENSE for copyright and license.
**
** The stages of renderers 7 and 9 (stages/r7_*, r9_*, rv_*) once more, in a
** number type the includer chooses: acc_float.c includes this file with
** float, acc_dd.c with double-double, and tests/unit/test_accuracy.c with
** double, where every function must give the stage's result bit for bit
** (acc-12.x): the deliberate copies are tied to their stages that way.  No
** include guard: each includer instantiates it once, defining first
**   RV_T            the number type
**   RV_NUM(x)       the double constant x as an RV_T
**   RV_ADD, RV_SUB, RV_MUL, RV_DIV (a, b), RV_NEG(a)
**   RV_GT(a, b)     a > b, false when either is NaN
**   RV_LE(a, b)     a <= b, false when either is NaN
**   RV_FN(name)     the name of the instance of function name
** The formulas, in the stages' order:
**   r7 view     v = t + m                               (r7_model2view)
**   r7 camera   x = x_v + (z_v*(r+l))/2.0  (ortho: x_v - (r+l)/2.0),
**               x_c = (2.0*x)/(r-l), likewise y; z_c = z_v  (r7_view2camera)
**   r9 matrix   A.times(v), A.times(B): each row summed left to right over all
**               four products (r9_matrix); N = m2.times(m1)  (r9_view2camera)
**   r9 view     v = (-1*e) + w                          (r9_world2view)
**   image       x_p = x_c / -z_c (ortho: x_c)           (rv_project)
**   near clip   t = (n - z1)/(z0 - z1), x = (1 - t)*x1 + t*x0, z = n
**   clip        t = (e - x_o)/(x_i - x_o), y = (1 - t)*y_o + t*y_i  (rv_clip)
*/

/* Renderer 7's view stage: the position's translation t plus m. */
static void RV_FN(r7_view)(const RV_T m[3], const RV_T t[3], RV_T v[3])
{
    int i;

    for (i = 0; i < 3; i++) v[i] = RV_ADD(t[i], m[i]);     /* x_v = t_x + x_m */
}

/* Renderer 7's camera stage: the view volume l..r, b..t normalized. */
static void RV_FN(r7_camera)(const RV_T v[3], int persp, RV_T l, RV_T r, RV_T b, RV_T t,
                             RV_T c[3])
{
    RV_T x, y;

    if (persp) {
        x = RV_ADD(v[0], RV_DIV(RV_MUL(v[2], RV_ADD(r, l)), RV_NUM(2.0)));  /* x + (z*(r+l))/2 */
        y = RV_ADD(v[1], RV_DIV(RV_MUL(v[2], RV_ADD(t, b)), RV_NUM(2.0)));
    } else {
        x = RV_SUB(v[0], RV_DIV(RV_ADD(r, l), RV_NUM(2.0)));  /* x - (r+l)/2 */
        y = RV_SUB(v[1], RV_DIV(RV_ADD(t, b), RV_NUM(2.0)));
    }
    c[0] = RV_DIV(RV_MUL(RV_NUM(2.0), x), RV_SUB(r, l));      /* x_c = (2x)/(r-l) */
    c[1] = RV_DIV(RV_MUL(RV_NUM(2.0), y), RV_SUB(t, b));
    c[2] = v[2];
}

/* Java's A.times(v): o_i = (A_i0*v0) + (A_i1*v1) + (A_i2*v2) + (A_i3*v3);
** a[i][j] is row i, column j. */
static void RV_FN(times_vec)(RV_T a[4][4], const RV_T v[4], RV_T o[4])
{
    int i;

    for (i = 0; i < 4; i++)
        o[i] = RV_ADD(RV_ADD(RV_ADD(RV_MUL(a[i][0], v[0]), RV_MUL(a[i][1], v[1])),
                             RV_MUL(a[i][2], v[2])), RV_MUL(a[i][3], v[3]));
}

/* Renderer 9's normalize matrix N = m2.times(m1) for the view volume. */
static void RV_FN(r9_normalize)(int persp, RV_T l, RV_T r, RV_T b, RV_T t, RV_T n[4][4])
{
    RV_T m1[4][4], m2[4][4];
    int i, j, k;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            m1[i][j] = RV_NUM(i == j ? 1.0 : 0.0);
            m2[i][j] = RV_NUM(i == j ? 1.0 : 0.0);
        }
    if (persp) {                                            /* skew: column 3 */
        m1[0][2] = RV_DIV(RV_ADD(r, l), RV_NUM(2.0));      /* (r+l)/2 */
        m1[1][2] = RV_DIV(RV_ADD(t, b), RV_NUM(2.0));      /* (t+b)/2 */
    } else {                                                /* translate: column 4 */
        m1[0][3] = RV_DIV(RV_NEG(RV_ADD(r, l)), RV_NUM(2.0));  /* -(r+l)/2 */
        m1[1][3] = RV_DIV(RV_NEG(RV_ADD(t, b)), RV_NUM(2.0));
    }
    m2[0][0] = RV_DIV(RV_NUM(2.0), RV_SUB(r, l));          /* 2/(r-l) */
    m2[1][1] = RV_DIV(RV_NUM(2.0), RV_SUB(t, b));          /* 2/(t-b) */
    for (i = 0; i < 4; i++)                                 /* m2.times(m1) */
        for (j = 0; j < 4; j++) {
            RV_T col[4], o[4];

            for (k = 0; k < 4; k++) col[k] = m1[k][j];
            RV_FN(times_vec)(m2, col, o);
            n[i][j] = o[i];
        }
}

/* Renderer 9's view stage: the camera's view vector e taken off. */
static void RV_FN(r9_view)(const RV_T w[3], const RV_T e[3], RV_T v[3])
{
    int i;

    for (i = 0; i < 3; i++) v[i] = RV_ADD(RV_MUL(RV_NUM(-1.0), e[i]), w[i]);  /* (-1*e) + w */
}

/* The image stage (projection). */
static void RV_FN(project)(const RV_T c[3], int persp, RV_T p[2])
{
    if (persp) {
        p[0] = RV_DIV(c[0], RV_NEG(c[2]));                 /* x_p = x_c / -z_c */
        p[1] = RV_DIV(c[1], RV_NEG(c[2]));
    } else {
        p[0] = c[0];                                        /* x_p = x_c */
        p[1] = c[1];
    }
}

/* The near clip of segment v0-v1 at z = n: 1 kept whole, 0 dropped, -1 cut:
** then *t, the new point p (z = n) and *off, the end it replaces (v0 when
** z0 > n, else v1). */
static int RV_FN(nearclip)(RV_T n, const RV_T v0[3], const RV_T v1[3], RV_T *t, RV_T p[3],
                           int *off)
{
    RV_T z0 = v0[2], z1 = v1[2], u;

    if (RV_LE(z0, n) && RV_LE(z1, n)) return 1;            /* on the plane counts as in */
    if (RV_GT(z0, n) && RV_GT(z1, n)) return 0;
    u = RV_DIV(RV_SUB(n, z1), RV_SUB(z0, z1));              /* t = (n - z1)/(z0 - z1) */
    p[0] = RV_ADD(RV_MUL(RV_SUB(RV_NUM(1.0), u), v1[0]), RV_MUL(u, v0[0]));  /* (1-t) x1 + t x0 */
    p[1] = RV_ADD(RV_MUL(RV_SUB(RV_NUM(1.0), u), v1[1]), RV_MUL(u, v0[1]));
    p[2] = n;
    *t = u;
    *off = RV_GT(z0, n) ? 0 : 1;
    return -1;
}

/* |x| > 1, false for NaN. */
static int RV_FN(out1)(RV_T x)
{
    return RV_GT(x, RV_NUM(1.0)) || RV_GT(RV_NUM(-1.0), x);
}

/* The clip's test of segment a-b (image plane): 1 accept, 0 delete, -1 cut. */
static int RV_FN(clip_test)(const RV_T a[2], const RV_T b[2])
{
    RV_T one = RV_NUM(1.0), m1 = RV_NUM(-1.0);

    if (!(RV_FN(out1)(a[0]) || RV_FN(out1)(a[1]) || RV_FN(out1)(b[0]) || RV_FN(out1)(b[1])))
        return 1;
    if ((RV_GT(a[0], one) && RV_GT(b[0], one)) || (RV_GT(m1, a[0]) && RV_GT(m1, b[0])) ||
        (RV_GT(a[1], one) && RV_GT(b[1], one)) || (RV_GT(m1, a[1]) && RV_GT(m1, b[1])))
        return 0;
    return -1;
}

/* One cut of the clip (the first edge, in the stage's order, that an end
** lies beyond): *edge (pt_rv_edge), *off (the end replaced), *t and the new
** point, which replaces that end of e[2][2]. */
static void RV_FN(clip_cut)(RV_T e[2][2], int *edge, int *off, RV_T *t, RV_T p[2])
{
    RV_T one = RV_NUM(1.0), m1 = RV_NUM(-1.0), pl, u;
    int o, on_x, i;

    if      (RV_GT(e[0][0], one)) { o = 0; on_x = 1; pl = one; *edge = 1; }
    else if (RV_GT(e[1][0], one)) { o = 1; on_x = 1; pl = one; *edge = 1; }
    else if (RV_GT(m1, e[0][0]))  { o = 0; on_x = 1; pl = m1;  *edge = 2; }
    else if (RV_GT(m1, e[1][0]))  { o = 1; on_x = 1; pl = m1;  *edge = 2; }
    else if (RV_GT(e[0][1], one)) { o = 0; on_x = 0; pl = one; *edge = 3; }
    else if (RV_GT(e[1][1], one)) { o = 1; on_x = 0; pl = one; *edge = 3; }
    else if (RV_GT(m1, e[0][1]))  { o = 0; on_x = 0; pl = m1;  *edge = 4; }
    else                          { o = 1; on_x = 0; pl = m1;  *edge = 4; }
    i = on_x ? 0 : 1;                                   /* the coordinate put on the edge */
    u = RV_DIV(RV_SUB(pl, e[o][i]), RV_SUB(e[1 - o][i], e[o][i]));  /* t = (e - x_o)/(x_i - x_o) */
    p[i] = pl;
    p[1 - i] = RV_ADD(RV_MUL(RV_SUB(RV_NUM(1.0), u), e[o][1 - i]),
                      RV_MUL(u, e[1 - o][1 - i]));      /* y = (1-t) y_o + t y_i */
    e[o][0] = p[0];
    e[o][1] = p[1];
    *off = o;
    *t = u;
}

/* The clip of segment e to -1..1, as the stage loops: cut while the test
** says cut, at most 64 times (then dropped, as the stage gives up).  The
** first cap cuts go to edge[], off[], t[] and p[]; *ncuts counts them all.
** Returns 1 when the piece left in e is kept, 0 when dropped. */
static int RV_FN(clip)(RV_T e[2][2], int cap, int *ncuts, int edge[], int off[], RV_T t[],
                       RV_T p[][2])
{
    int k, v, ed, o;
    RV_T u, q[2];

    for (k = 0; (v = RV_FN(clip_test)(e[0], e[1])) < 0; k++) {
        if (k == 64) { *ncuts = k; return 0; }
        RV_FN(clip_cut)(e, &ed, &o, &u, q);
        if (k < cap) { edge[k] = ed; off[k] = o; t[k] = u; p[k][0] = q[0]; p[k][1] = q[1]; }
    }
    *ncuts = k;
    return v;
}
