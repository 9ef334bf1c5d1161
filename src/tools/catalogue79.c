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
#include <string.h>
#include "io/tread79.h"
#include "tools/catalogue79.h"

/* EXPECTED's camera as the stages take it. */
static pt_rv_camera rv_cam(const pt_c79cam *c)
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
    pt_rv_camera k = rv_cam(c);
    (void)right;
    k.l = -(c->r - c->l) / 2; k.r = (c->r - c->l) / 2;
    k.b = -(c->t - c->b) / 2; k.t = (c->t - c->b) / 2;
    camera_stage(c, &k, prev, out);
}

/* x = x_v - (z_v*(r+l))/2: the rectangle mirrored, r + l negated. */
static void skew_sign(const pt_c79cam *c, const double prev[4], const double right[4],
                      double out[4])
{
    pt_rv_camera k = rv_cam(c);
    (void)right;
    k.l = -c->r; k.r = -c->l;
    k.b = -c->t; k.t = -c->b;
    camera_stage(c, &k, prev, out);
}

/* x_c = x/(r-l): scaled by the whole width, half the right value. */
static void half_size(const pt_c79cam *c, const double prev[4], const double right[4],
                      double out[4])
{
    pt_rv_camera k = rv_cam(c);
    (void)right;
    camera_stage(c, &k, prev, out);
    out[0] /= 2;                        /* (2x)/(r-l) / 2 == x/(r-l) exactly */
    out[1] /= 2;
}

/* x_c = (4x)/(r-l): scaled by the half-width twice, twice the right value. */
static void double_size(const pt_c79cam *c, const double prev[4], const double right[4],
                        double out[4])
{
    pt_rv_camera k = rv_cam(c);
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
     "so an asymmetric rectangle (r+l != 0) is off centre", skew_forgotten, NULL, 0},
    {PT_T79_CAMERA, 0, "the skew's sign wrong",
     "x = x_v - (z_v*(r+l))/2 for x_v + (z_v*(r+l))/2: the centre line moves the "
     "other way, twice as far off", skew_sign, NULL, 0},
    {PT_T79_CAMERA, 0, "scaled by the width, not the half-width",
     "x_c = x/(r-l) for (2*x)/(r-l): dividing by r-l makes the half-width 1/2, so "
     "the picture is half as big", half_size, NULL, 0},
    {PT_T79_CAMERA, 0, "scaled by the half-width twice",
     "x_c = (2*x)/((r-l)/2): the half-width becomes 2, the picture twice as big",
     double_size, NULL, 0},
    {PT_T79_VIEW, 9, "the camera translation added",
     "x_v = x_w + x_e for x_w - x_e: the world moves with the camera instead of "
     "against it", view_added, NULL, 0},
    {PT_T79_NSTAGES, 0, "gamma applied twice",
     "c = pow(pow(c, 1/2.2), 1/2.2): the colours come out too light", NULL, gamma_twice, 1},
    {PT_T79_NSTAGES, 0, "gamma not applied",
     "c written as interpolated, without pow(c, 1/2.2) though gamma is on: the "
     "colours come out too dark", NULL, gamma_none, 1},
    {PT_T79_NSTAGES, 0, "the anti-aliasing weights swapped",
     "the pixel nearer the line gets the weight 1 - w of the one farther away "
     "(and the other way round): each step's two colours trade places", NULL, aa_swapped, 0},
};
