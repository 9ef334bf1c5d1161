/*
** tests/unit/test_matrix.c -- the matrix camera: matrices, its stages, clipping
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <string.h>
#include "testhelp.h"
#include "stages/pt_mat4.h"
#include "stages/m1_model2world.h"
#include "stages/m2_world2view.h"
#include "stages/m3_view2clip.h"
#include "stages/m4_clip2cvv.h"
#include "stages/m5_clip2ndc.h"
#include "stages/m6_ndc2screen.h"
#include "stages/m7_screen2viewport.h"
#include "stages/s4_pixel2viewport.h"
#include "stages/ms_clip_segment.h"

static pt_vrec last;
static void keep(void *ud, const pt_vrec *r) { (void)ud; last = *r; }
static const pt_sink sink = {keep, NULL};

static int near_eq(double a, double b, double tol)
{
    return fabs(a - b) <= tol * (1 + fabs(a) + fabs(b));
}

static void test_matrices(void)
{
    pt_mat4 r = pt_mat4_rotate(2, 90), t = pt_mat4_translate(1, 2, 3), rt;
    pt_vec4 v = {1, 0, 0, 1}, q;

    q = pt_vec4_mul(v, &r);
    PT_CHECK("mat-1.1 rotate z by 90: x axis -> y axis, exactly", q.x == 0 && q.y == 1 && q.z == 0);
    rt = pt_mat4_mul(&r, &t);
    q = pt_vec4_mul(v, &rt);
    PT_CHECK("mat-1.2 (rotate then translate): (1,0,0) -> (1,3,3)", q.x == 1 && q.y == 3 && q.z == 3 && q.w == 1);
    rt = pt_mat4_mul(&t, &r);
    q = pt_vec4_mul(v, &rt);
    PT_CHECK("mat-1.3 (translate then rotate): (1,0,0) -> (-2,2,3)", q.x == -2 && q.y == 2 && q.z == 3);
    q = pt_vec4_mul((pt_vec4){0, 0, 1, 1}, &(pt_mat4){{{1,0,0,0},{0,1,0,0},{0,0,1,0},{0,0,0,1}}});
    PT_CHECK("mat-1.4 identity", q.z == 1 && q.w == 1);
    r = pt_mat4_rotate(0, 90);
    q = pt_vec4_mul((pt_vec4){0, 1, 0, 1}, &r);
    PT_CHECK("mat-1.5 rotate x by 90: y -> z", q.y == 0 && q.z == 1);
    r = pt_mat4_rotate(1, -270);
    q = pt_vec4_mul((pt_vec4){0, 0, 1, 1}, &r);
    PT_CHECK("mat-1.6 rotate y by -270 (= 90): z -> x", q.x == 1 && q.z == 0);
}

static void test_cameras(void)
{
    pt_mat4 view, proj;
    int skewed = 0;
    pt_vec4 p;

    PT_CHECK("cam-1.1 look-at from (0,0,-5) along +z",
             pt_lookat(&view, (pt_vec3){0, 0, -5}, (pt_vec3){0, 0, 2}, (pt_vec3){0, 3, 0}, 0, &skewed) == PT_CAM_OK && !skewed);
    p = pt_vec4_mul((pt_vec4){1, 2, 0, 1}, &view);
    PT_CHECK("cam-1.2 the point (1,2,0) is at view (1,2,5)", p.x == 1 && p.y == 2 && p.z == 5 && p.w == 1);
    PT_CHECK("cam-1.3 up parallel to direction is refused",
             pt_lookat(&view, (pt_vec3){0, 0, 0}, (pt_vec3){0, 1, 0}, (pt_vec3){0, -2, 0}, 0, &skewed) == PT_CAM_UP_PARALLEL);
    PT_CHECK("cam-1.4 zero direction is refused",
             pt_lookat(&view, (pt_vec3){0, 0, 0}, (pt_vec3){0, 0, 0}, (pt_vec3){0, 1, 0}, 0, &skewed) == PT_CAM_DIR_ZERO);
    pt_lookat(&view, (pt_vec3){0, 0, 0}, (pt_vec3){0, 0, 1}, (pt_vec3){0, 1, 1}, 0, &skewed);
    PT_CHECK("cam-1.5 an up that is not perpendicular is noticed", skewed);
    PT_CHECK("cam-1.6 ... and re-derived: the basis is orthonormal",
             fabs(view.m[0][1] * view.m[0][2] + view.m[1][1] * view.m[1][2] + view.m[2][1] * view.m[2][2]) < 1e-15);
    pt_lookat(&view, (pt_vec3){0, 0, 0}, (pt_vec3){0, 0, 1}, (pt_vec3){0, 1, 1}, 1, &skewed);
    PT_CHECK("cam-1.7 raw look-at keeps the seed's skewed up",
             fabs(view.m[1][1] * view.m[1][2] + view.m[2][1] * view.m[2][2]) > 0.5);

    PT_CHECK("cam-2.1 perspective 90 degrees, aspect 2, near 1, far 10",
             pt_perspective(&proj, 90, 2, 1, 10) == PT_CAM_OK);
    PT_CHECK("cam-2.2 cot(45) is exactly 1: m00 = 0.5, m11 = 1", proj.m[0][0] == 0.5 && proj.m[1][1] == 1);
    p = pt_vec4_mul((pt_vec4){0, 0, 1, 1}, &proj);
    PT_CHECK("cam-2.3 the near plane maps to z/w = 0", p.z / p.w == 0);
    p = pt_vec4_mul((pt_vec4){0, 0, 10, 1}, &proj);
    PT_CHECK("cam-2.4 the far plane maps to z/w = 1", p.z / p.w == 1);
    p = pt_vec4_mul((pt_vec4){3, -4, 5, 1}, &proj);
    PT_CHECK("cam-2.5 w' = z", p.w == 5 && p.x == 1.5 && p.y == -4);
    PT_CHECK("cam-2.6 bad fov, aspect, near, far are refused",
             pt_perspective(&proj, 0, 1, 1, 2) == PT_CAM_FOV && pt_perspective(&proj, 180, 1, 1, 2) == PT_CAM_FOV &&
             pt_perspective(&proj, 60, 0, 1, 2) == PT_CAM_ASPECT && pt_perspective(&proj, 60, 1, 0, 2) == PT_CAM_NEAR &&
             pt_perspective(&proj, 60, 1, 2, 2) == PT_CAM_FAR);
    PT_CHECK("cam-2.7 fov 1e-320: cot(fov/2) overflows, refused",
             pt_perspective(&proj, 1e-320, 1, 0.5, 100) == PT_CAM_FOV_RANGE);
    PT_CHECK("cam-2.8 aspect 1e-320: cot(fov/2)/aspect overflows, refused",
             pt_perspective(&proj, 60, 1e-320, 0.5, 100) == PT_CAM_ASPECT_RANGE);
    PT_CHECK("cam-2.9 near 1e300, far 1e308: f*n/(n-f) overflows, refused",
             pt_perspective(&proj, 90, 1, 1e300, 1e308) == PT_CAM_DEPTH_RANGE);
}

/* A direction or up of 1e200 or 1e-200 has a squared length that overflows or
** underflows; scaled by a power of two first, it gives the same matrix as
** (1, 0, 1).  An eye so far away that -eye.d overflows is refused. */
static void test_camera_ranges(void)
{
    pt_mat4 ref, big, small;
    int skewed, same = 1, i, j;

    pt_lookat(&ref, (pt_vec3){1, 2, 3}, (pt_vec3){1, 0, 1}, (pt_vec3){0, 1, 0}, 0, &skewed);
    PT_CHECK("cam-3.1 direction (1e200, 0, 1e200) is accepted",
             pt_lookat(&big, (pt_vec3){1, 2, 3}, (pt_vec3){1e200, 0, 1e200}, (pt_vec3){0, 1e200, 0}, 0, &skewed) == PT_CAM_OK);
    PT_CHECK("cam-3.2 direction (1e-200, 0, 1e-200), up (0, 1e-310, 0) are accepted",
             pt_lookat(&small, (pt_vec3){1, 2, 3}, (pt_vec3){1e-200, 0, 1e-200}, (pt_vec3){0, 1e-310, 0}, 0, &skewed) == PT_CAM_OK);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            same &= big.m[i][j] == ref.m[i][j] && fabs(small.m[i][j] - ref.m[i][j]) <= 0x1p-52 * 4;
    PT_CHECK("cam-3.3 ... and give the matrix of (1, 0, 1) (1e200: bit for bit)", same);
    PT_CHECK("cam-3.4 an eye at 1e308 along the view direction overflows -eye.d: refused",
             pt_lookat(&big, (pt_vec3){1.5e308, 0, 1.5e308}, (pt_vec3){1, 0, 1}, (pt_vec3){0, 1, 0}, 0, &skewed) == PT_CAM_EYE_RANGE);
    PT_CHECK("cam-3.5 every error has its own message",
             strstr(pt_cam_error_text(PT_CAM_EYE_RANGE), "position") && strstr(pt_cam_error_text(PT_CAM_FOV_RANGE), "field of view") &&
             strstr(pt_cam_error_text(PT_CAM_ASPECT_RANGE), "aspect") && strstr(pt_cam_error_text(PT_CAM_DEPTH_RANGE), "near and far"));
}

static void test_stages(void)
{
    pt_mat4 world = pt_mat4_translate(0, 0, 5), view, proj;
    int skewed;
    pt_vec4 w, v, k;
    pt_vec3 n, s;
    pt_pix vp;
    unsigned code;

    pt_lookat(&view, (pt_vec3){0, 0, 0}, (pt_vec3){0, 0, 1}, (pt_vec3){0, 1, 0}, 0, &skewed);
    pt_perspective(&proj, 90, 1, 1, 100);
    w = pt_model2world((pt_vec3){1, 1, 0}, &world, &sink);
    PT_CHECK("ms-1.1 world: (1,1,0) + (0,0,5), w = 1", w.x == 1 && w.y == 1 && w.z == 5 && w.w == 1 && last.stage == PT_STAGE_WORLD);
    v = pt_world2view(w, &view, &sink);
    PT_CHECK("ms-2.1 view: identity camera", v.x == 1 && v.z == 5 && last.stage == PT_STAGE_VIEW);
    k = pt_view2clip(v, &proj, &sink);
    PT_CHECK("ms-3.1 clip: w = z_v = 5", k.w == 5 && k.x == 1 && last.stage == PT_STAGE_CLIP);
    code = pt_clip2cvv(k, &sink);
    PT_CHECK("ms-4.1 cvv: inside, code 0", code == 0 && last.code == 0);
    n = pt_clip2ndc(k, fabs(k.w), &sink);
    PT_CHECK("ms-5.1 ndc: (0.2, 0.2, z)", n.x == 0.2 && n.y == 0.2 && n.z > 0 && n.z < 1);
    s = pt_ndc2screen(n, 10, 10, &sink);
    PT_CHECK("ms-6.1 screen: (6, 4): x right, y down", s.x == 6 && s.y == 4);
    vp = pt_screen2viewport(s, 10, 10, &sink);
    PT_CHECK("ms-7.1 viewport: floor -> (6, 4), inside", vp.ok && vp.x == 6 && vp.y == 4 && (last.flags & PT_REC_INSIDE));
    {
        pt_vec2 pp = pt_viewport2pixelplane(vp, 10);
        PT_CHECK("ms-7.2 the rasterizer's pixel plane rounds back to the same pixel",
                 pt_java_round(pp.x) - 1 == 6 && 10 - pt_java_round(pp.y) == 4);
    }
    code = pt_clip2cvv((pt_vec4){-3, 0, -1, 1}, &sink);
    PT_CHECK("ms-4.2 left of and behind the near plane: left|near", code == (PT_CVV_LEFT | PT_CVV_NEAR));
    code = pt_clip2cvv((pt_vec4){0, 9, 2, 1}, NULL);
    PT_CHECK("ms-4.3 far and top", code == (PT_CVV_FAR | PT_CVV_TOP));
    vp = pt_screen2viewport((pt_vec3){10, 9.999, 0}, 10, 10, NULL);
    PT_CHECK("ms-7.3 x_s = w belongs to no pixel of the viewport", vp.x == 10);
}

/* Project then un-project: the un-projection inverts each stage by hand. */
static void test_roundtrip(void)
{
    pt_mat4 view, proj, world = pt_mat4_identity();
    pt_vec3 eye = {1, 2, -3}, dir = {0.2, -0.1, 1}, up = {0, 1, 0};
    double fov = 60, aspect = 1.5, zn = 0.5, zf = 50, worst = 0;
    int skewed, k, ok = 1;

    pt_lookat(&view, eye, dir, up, 0, &skewed);
    pt_perspective(&proj, fov, aspect, zn, zf);
    for (k = 0; k < 200; k++) {
        pt_vec3 p = {sin(k * 1.1) * 3, cos(k * 0.7) * 2, 4 + 10 * fabs(sin(k * 0.3))}, n, s, back;
        pt_vec4 c = pt_view2clip(pt_world2view(pt_model2world(p, &world, NULL), &view, NULL), &proj, NULL);
        double z_v, x_v, y_v, cot = proj.m[1][1];
        n = pt_clip2ndc(c, fabs(c.w), NULL);
        s = pt_ndc2screen(n, 300, 200, NULL);
        n.x = s.x / (300 * 0.5) - 1;                 /* un-screen */
        n.y = 1 - s.y / (200 * 0.5);
        z_v = zf * zn / (zf - s.z * (zf - zn));      /* un-divide: z_n = f/(f-n) (1 - n/z_v) */
        x_v = n.x * z_v * aspect / cot;
        y_v = n.y * z_v / cot;
        back.x = eye.x + x_v * view.m[0][0] + y_v * view.m[0][1] + z_v * view.m[0][2];   /* p = eye + x h + y u + z d */
        back.y = eye.y + x_v * view.m[1][0] + y_v * view.m[1][1] + z_v * view.m[1][2];
        back.z = eye.z + x_v * view.m[2][0] + y_v * view.m[2][1] + z_v * view.m[2][2];
        worst = fmax(worst, fabs(back.x - p.x) + fabs(back.y - p.y) + fabs(back.z - p.z));
        if (!near_eq(back.x, p.x, 1e-9) || !near_eq(back.y, p.y, 1e-9) || !near_eq(back.z, p.z, 1e-9)) ok = 0;
    }
    PT_CHECK("ms-8.1 project then un-project: within 1e-9 (relative) for 200 points", ok);
    PT_CHECK("ms-8.2 ... and the worst error is tiny", worst < 1e-10);
}

static void test_clip(void)
{
    pt_vec4 q0, q1;
    double t0, t1;

    PT_CHECK("clip-1.1 a segment inside is kept whole",
             pt_clip_segment((pt_vec4){0, 0, 1, 2}, (pt_vec4){0.5, 0.5, 1, 2}, &t0, &t1, &q0, &q1) && t0 == 0 && t1 == 1);
    PT_CHECK("clip-1.2 crossing the near plane (z from -1 to 1): cut at t = 0.5",
             pt_clip_segment((pt_vec4){0, 0, -1, 0.5}, (pt_vec4){0, 0, 1, 2}, &t0, &t1, &q0, &q1) &&
             t0 == 0.5 && t1 == 1 && q0.z == 0 && q0.w == 1.25);
    PT_CHECK("clip-1.3 both behind the near plane: nothing",
             !pt_clip_segment((pt_vec4){0, 0, -1, -1}, (pt_vec4){0, 0, -2, 1}, &t0, &t1, &q0, &q1));
    PT_CHECK("clip-1.4 through left and right: two cuts",
             pt_clip_segment((pt_vec4){-3, 0, 0.5, 1}, (pt_vec4){3, 0, 0.5, 1}, &t0, &t1, &q0, &q1) &&
             t0 == 1.0 / 3 && t1 == 2.0 / 3 && q0.x == -1 && q1.x == 1);
    PT_CHECK("clip-1.5 outside two different planes, missing the corner: nothing",
             !pt_clip_segment((pt_vec4){-3, 0, 0.5, 1}, (pt_vec4){0, 3, 0.5, 1}, &t0, &t1, &q0, &q1));
}

int main(void)
{
    test_matrices();
    test_cameras();
    test_camera_ranges();
    test_stages();
    test_roundtrip();
    test_clip();
    return pt_test_report();
}
