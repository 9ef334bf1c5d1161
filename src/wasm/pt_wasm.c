/*
** src/wasm/pt_wasm.c -- both cameras' stages as a WebAssembly module
** See LICENSE for copyright and license.
**
** Compiled with the stages' own files (pt_stage.c, pt_round.c, s1..s6,
** pt_classic.c; pt_mat4.c, pt_matrix.c, m1..m7) by clang --target=wasm32
** -nostdlib and linked by wasm-ld into $B/stages.wasm (the Makefile's wasm
** part); the journey page (src/tools/journey/journey_wasm.c) embeds it and
** calls the functions below when a slider moves.  Nothing here computes a
** coordinate: pt_wasm_run() calls pt_classic_journey(), as pt_run() does;
** pt_wasm_matrix_run() builds the matrices with pt_lookat(), pt_perspective()
** and pt_matrix_world(), as the scene reader and pt_plan_make() do, and calls
** pt_matrix_journey().  Both keep the record each stage reports; the page
** reads them back one value at a time, so it needs to know nothing of
** pt_vrec's layout.
**
**   pt_wasm_run(x_m, y_m, z_m, x_t, y_t, z_t, perspective, w, h, x_ul, y_ul, W, H)
**   pt_wasm_in()            the address of the matrix camera's inputs (PT_WASM_IN_*)
**   pt_wasm_table(n)        the address of the sin and cos table for n rows
**   pt_wasm_matrix_run(target, aspect_auto, w, h, x_ul, y_ul, W, H)
**   pt_wasm_cam_error(e)    the address of pt_cam_error_text(e), a C string
**   pt_wasm_reported(st)    1 when stage st reported in the last run
**   pt_wasm_real(st, k)     value k (0..3) of a real stage: x, y, z, w
**   pt_wasm_int(st, k)      value k of an integer stage (ix, iy; i; code), an i64
**   pt_wasm_has(st, k)      1 when value k of stage st has a value (null per value)
**   pt_wasm_flags(st), pt_wasm_warn(st)   the record's PT_REC_*, PT_WARN_* bits
**
** The course's renderers 7 and 9 work on whole models, so their run takes
** the position's model (vertices, colours, primitives, as the driver built
** it) and runs it through their stages as src/core/course.c's do_step()
** does, stage after stage: r7_model2view or r9_model2world and
** r9_world2view, r7_view2camera or r9_view2camera, rv_nearclip (when on),
** rv_project, rv_clip; then the rasterizer's first two steps for the
** vertex's pixel, as io/explain_course.c takes them (s3_image2pixel's
** x_pp = 0.5 + w/2.001 * (x_p + 1), Java's Math.round), and its place in
** the W x H framebuffer and pixel array as the rasterizer writes it
** (pt_rv_fb_index(): y_fb*W + x_fb in Java ints, rows wrap).  That order is
** a copy of course.c's; tests/journey/journey_wasm.sh ties it to the
** command line, bit for bit.
**
**   pt_wasm_course_in(nv, nc, np)   the address of the inputs (PT_WASM_CIN_*,
**                                   then the model), the arena emptied
**   pt_wasm_course_in_at()          the same address, the arena kept
**   pt_wasm_course_ops(n)           the address of n operations of renderer 9's
**                                   position matrix (PT_WASM_COP doubles each)
**   pt_wasm_course_run(renderer, perspective, nearclip, v, w, h, x_ul, y_ul, W, H, nops)
**                                   nops >= 0: the matrix built from the
**                                   operations (r9_matrix.c), sin and cos
**                                   from the table
**   pt_wasm_course_have(st)         1 when vertex v exists after course stage st
**   pt_wasm_course_at(st, k)        its x, y, z, w (k = 0..3) after st
**   pt_wasm_course_px(k)            x_vp, y_vp, x_fb, y_fb (k = 0..3); k = 4:
**                                   1 when it has a pixel (inside after the clip);
**                                   k = 5: its index in the pixel array, -1
**                                   when the rasterizer drops it (outside W*H)
*/
#include <stdlib.h>                         /* src/wasm/stdlib.h: the arena */
#include <string.h>                         /* src/wasm/string.h: strcmp */
#include "stages/pt_classic.h"
#include "stages/pt_matrix.h"
#include "wasm/pt_wasm_libm.h"            /* the sin and cos table */
#include "stages/wasm/pt_wasm_in.h"
#include "stages/r7_model2view.h"
#include "stages/r7_view2camera.h"
#include "stages/r9_model2world.h"
#include "stages/r9_world2view.h"
#include "stages/r9_view2camera.h"
#include "stages/rv_nearclip.h"
#include "stages/rv_project.h"
#include "stages/rv_clip.h"
#include "stages/rv_raster.h"
#include "stages/s3_image2pixel.h"
#include "stages/pt_round.h"
#include "wasm/pt_wasm_alloc.h"

#define EXPORT(name) __attribute__((export_name(name)))

static pt_vrec recs[PT_NSTAGES_ALL];        /* the last run's records, by stage */
static unsigned reported;                   /* bit st: stage st reported */

static void keep(void *ud, const pt_vrec *r)
{
    (void)ud;
    if ((int)r->stage >= 0 && r->stage < PT_NSTAGES_ALL) {
        recs[r->stage] = *r;
        reported |= 1u << r->stage;
    }
}

/* Forget the last run; sinks[] all report to keep(). */
static void start(const pt_sink *sinks[PT_NSTAGES_ALL])
{
    static const pt_sink sink = {keep, 0};
    static const pt_vrec none = {0};
    int k;

    for (k = 0; k < PT_NSTAGES_ALL; k++) { sinks[k] = &sink; recs[k] = none; }
    reported = 0;
}

/* Run one vertex through the classic stages.  Returns 0, or -1 (no run) when
** a size is below 1.  This function can't fail otherwise. */
EXPORT("pt_wasm_run") int pt_wasm_run(double x_m, double y_m, double z_m, double x_t,
                                      double y_t, double z_t, int perspective, int w, int h,
                                      int x_ul, int y_ul, int W, int H);
int pt_wasm_run(double x_m, double y_m, double z_m, double x_t, double y_t, double z_t,
                int perspective, int w, int h, int x_ul, int y_ul, int W, int H)
{
    const pt_sink *sinks[PT_NSTAGES_ALL];
    pt_stage_params par;
    pt_vec3 v_m;
    double z_c;

    if (w < 1 || h < 1 || W < 1 || H < 1) return -1;
    start(sinks);
    par.translate.x = x_t; par.translate.y = y_t; par.translate.z = z_t;
    par.perspective = perspective != 0;
    par.w = w; par.h = h; par.x_ul = x_ul; par.y_ul = y_ul; par.W = W; par.H = H;
    v_m.x = x_m; v_m.y = y_m; v_m.z = z_m;
    pt_classic_journey(&par, v_m, sinks, &z_c);
    return 0;
}

/* The matrix camera's inputs (pt_wasm_in.h). */
static double in[PT_WASM_NIN];

EXPORT("pt_wasm_in") double *pt_wasm_in(void);
double *pt_wasm_in(void)
{
    return in;
}

/* n rows of (argument, sin, cos) to be written at the address returned;
** NULL when n is more than the table holds. */
EXPORT("pt_wasm_table") double *pt_wasm_table(int n);
double *pt_wasm_table(int n)
{
    if (n < 0 || n > PT_WASM_NSINCOS) return 0;
    pt_wasm_nsincos = n;
    return &pt_wasm_sincos[0][0];
}

static pt_vec3 vec(int at)
{
    pt_vec3 v;

    v.x = in[at]; v.y = in[at + 1]; v.z = in[at + 2];
    return v;
}

/* Run one vertex through the matrix camera's stages with the inputs in in[]
** and the journey page's view matrix (up re-derived, pipetrace's default).
** Returns 0; -1 when a size is below 1; -2 when sin or cos was asked for an
** argument not in the table (nothing is run); 100 + the pt_cam_error when
** the camera can't be built (the scene reader's error). */
EXPORT("pt_wasm_matrix_run") int pt_wasm_matrix_run(int target, int aspect_auto, int w, int h,
                                                    int x_ul, int y_ul, int W, int H);
int pt_wasm_matrix_run(int target, int aspect_auto, int w, int h, int x_ul, int y_ul,
                       int W, int H)
{
    const pt_sink *sinks[PT_NSTAGES_ALL];
    pt_stage_params par = {{0, 0, 0}, 1, 0, 0, 0, 0, 0, 0};
    pt_mat4 lines, world, view, proj;
    pt_matrices mx;
    pt_vec3 eye = vec(PT_WASM_IN_EYE), dir = vec(PT_WASM_IN_DIR);
    pt_vec4 clip;
    unsigned code;
    double aspect = in[PT_WASM_IN_ASPECT];
    int k, skewed;
    pt_cam_error e;

    if (w < 1 || h < 1 || W < 1 || H < 1) return -1;
    start(sinks);
    if (target) dir = pt_lookat_dir(eye, dir);
    if (aspect_auto) aspect = pt_aspect_auto(w, h);
    e = pt_lookat(&view, eye, dir, vec(PT_WASM_IN_UP), 0, &skewed);
    if (e != PT_CAM_OK) return 100 + (int)e;
    pt_wasm_libm_missed = 0;
    e = pt_perspective(&proj, in[PT_WASM_IN_FOV], aspect, in[PT_WASM_IN_NEAR],
                       in[PT_WASM_IN_FAR]);
    if (pt_wasm_libm_missed) return -2;
    if (e != PT_CAM_OK) return 100 + (int)e;
    for (k = 0; k < 16; k++) lines.m[k / 4][k % 4] = in[PT_WASM_IN_WORLD + k];
    world = pt_matrix_world(&lines, vec(PT_WASM_IN_T));
    mx.world = &world; mx.view = &view; mx.proj = &proj;
    par.w = w; par.h = h; par.x_ul = x_ul; par.y_ul = y_ul; par.W = W; par.H = H;
    (void)pt_matrix_journey(&par, &mx, vec(PT_WASM_IN_V), sinks, &clip, &code);
    return 0;
}

EXPORT("pt_wasm_cam_error") const char *pt_wasm_cam_error(int e);
const char *pt_wasm_cam_error(int e)
{
    return pt_cam_error_text((pt_cam_error)e);
}

static const pt_vrec *rec(int st)
{
    static const pt_vrec none = {0};
    return st >= 0 && st < PT_NSTAGES_ALL ? &recs[st] : &none;
}

EXPORT("pt_wasm_reported") int pt_wasm_reported(int st);
int pt_wasm_reported(int st)
{
    return st >= 0 && st < PT_NSTAGES_ALL && (reported >> st & 1);
}

EXPORT("pt_wasm_real") double pt_wasm_real(int st, int k);
double pt_wasm_real(int st, int k)
{
    return k == 0 ? rec(st)->x : k == 1 ? rec(st)->y : k == 2 ? rec(st)->z : rec(st)->w;
}

EXPORT("pt_wasm_int") int64_t pt_wasm_int(int st, int k);
int64_t pt_wasm_int(int st, int k)
{
    if (st == PT_STAGE_INDEX) return rec(st)->i;
    if (st == PT_STAGE_CVV) return rec(st)->code;
    return k == 0 ? rec(st)->ix : rec(st)->iy;
}

EXPORT("pt_wasm_has") int pt_wasm_has(int st, int k);
int pt_wasm_has(int st, int k)
{
    return pt_rec_has(rec(st), k);
}

EXPORT("pt_wasm_flags") unsigned pt_wasm_flags(int st);
unsigned pt_wasm_flags(int st)
{
    return rec(st)->flags;
}

EXPORT("pt_wasm_warn") unsigned pt_wasm_warn(int st);
unsigned pt_wasm_warn(int st)
{
    return rec(st)->warn;
}

/* ===== the course's renderers 7 and 9 ===== */

/* The course inputs (stages/wasm/pt_wasm_in.h) and the last run's vertex. */
static double *cin;
static int cnv, cnc, cnp;
static int chave[PT_NCOURSE];
static pt_vec4 cat[PT_NCOURSE];
static int64_t cpx[6];

EXPORT("pt_wasm_course_in") double *pt_wasm_course_in(int nv, int nc, int np);
double *pt_wasm_course_in(int nv, int nc, int np)
{
    if (nv < 0 || nc < 0 || np < 0 || nv > 1000000 || nc > 1000000 || np > 1000000) return 0;
    pt_wasm_alloc_reset(1);
    cin = malloc(((size_t)PT_WASM_CIN_MODEL + 4u * (size_t)nv + 3u * (size_t)nc + 6u * (size_t)np) *
                 sizeof *cin);
    pt_wasm_alloc_mark();
    cnv = nv; cnc = nc; cnp = np;
    return cin;
}

/* The position's model from the inputs.  0, or -1 (out of arena). */
static int course_model(pt_rv_model *m)
{
    const double *v = cin + PT_WASM_CIN_MODEL, *c = v + 4 * cnv, *p = c + 3 * cnc;
    int k;

    for (k = 0; k < cnv; k++) {
        pt_vec4 x;
        x.x = v[4 * k]; x.y = v[4 * k + 1]; x.z = v[4 * k + 2]; x.w = v[4 * k + 3];
        if (pt_rv_add_vertex(m, x) != 0) return -1;
    }
    for (k = 0; k < cnc; k++) {
        pt_rgb x;
        x.r = (float)c[3 * k]; x.g = (float)c[3 * k + 1]; x.b = (float)c[3 * k + 2];
        if (pt_rv_add_color(m, x) != 0) return -1;
    }
    for (k = 0; k < cnp; k++) {
        pt_rv_prim x;
        const double *q = p + 6 * k;
        x.kind = q[0] == 0 ? PT_RV_LINE : PT_RV_POINT;
        x.v[0] = (uint32_t)q[1]; x.v[1] = (uint32_t)q[2];
        x.c[0] = (uint32_t)q[3]; x.c[1] = (uint32_t)q[4];
        x.radius = (int)q[5];
        if (pt_rv_add_prim(m, &x) != 0) return -1;
    }
    return 0;
}

/* Keep vertex v (0-based) of m after course stage st. */
static void ckeep(int st, const pt_rv_model *m, size_t v)
{
    chave[st] = v < m->nv;
    if (chave[st]) cat[st] = m->v[v];
}

/* The inputs' address again (the camera and translation move; the model
** stays).  This function can't fail. */
EXPORT("pt_wasm_course_in_at") double *pt_wasm_course_in_at(void);
double *pt_wasm_course_in_at(void)
{
    return cin;
}

/* Run vertex v (1-based) of the inputs' model through the course's stages,
** renderer 9's matrix from the inputs or (nops >= 0) from the operations,
** into a w x h viewport at (x_ul, y_ul) of a W x H framebuffer.
** Returns 0; -1 when out of arena or a size is below 1; -2 when a clip
** stage refused a colour (the course's render throws); -3 when an angle's
** sin or cos is not in the table (nothing is run). */
static double cops[PT_WASM_NCOPS * PT_WASM_COP];

EXPORT("pt_wasm_course_ops") double *pt_wasm_course_ops(int n);
double *pt_wasm_course_ops(int n)
{
    return n >= 0 && n <= PT_WASM_NCOPS ? cops : 0;
}

/* The position's matrix from the first n operations at cops.  Returns 0,
** or -3 when sin or cos was asked for an argument not in the table. */
static int course_matrix(pt_jmat *mat, int n)
{
    pt_matop ops[PT_WASM_NCOPS];
    int k, i;

    for (k = 0; k < n; k++) {
        const double *o = cops + k * PT_WASM_COP;
        ops[k].mul = o[0] == 0 ? PT_MATMUL_POST : o[0] == 1 ? PT_MATMUL_PRE : PT_MATMUL_SET;
        ops[k].kind = (pt_matop_kind)(int)o[1];
        for (i = 0; i < 16; i++) ops[k].a[i] = o[2 + i];
    }
    pt_wasm_libm_missed = 0;
    *mat = pt_r9_position_matrix(ops, (size_t)n);
    return pt_wasm_libm_missed ? -3 : 0;
}

EXPORT("pt_wasm_course_run") int pt_wasm_course_run(int renderer, int perspective, int nearclip,
                                                    int v, int w, int h, int x_ul, int y_ul,
                                                    int W, int H, int nops);
int pt_wasm_course_run(int renderer, int perspective, int nearclip, int v, int w, int h,
                       int x_ul, int y_ul, int W, int H, int nops)
{
    pt_rv_model m = {0};
    pt_rv_camera cam;
    pt_jmat mat, norm;
    pt_vec3 move;
    size_t k, at = (size_t)v - 1;
    int st, rc;

    if (!cin || w < 1 || h < 1 || W < 1 || H < 1 || v < 1) return -1;
    pt_wasm_alloc_reset(0);
    for (st = 0; st < PT_NCOURSE; st++) chave[st] = 0;
    for (k = 0; k < 6; k++) cpx[k] = 0;
    cam.perspective = perspective != 0;
    cam.l = cin[PT_WASM_CIN_L]; cam.r = cin[PT_WASM_CIN_R]; cam.b = cin[PT_WASM_CIN_B]; cam.t = cin[PT_WASM_CIN_T];
    cam.n = cin[PT_WASM_CIN_N];
    move.x = cin[PT_WASM_CIN_MOVE]; move.y = cin[PT_WASM_CIN_MOVE + 1]; move.z = cin[PT_WASM_CIN_MOVE + 2];
    cam.view = move;
    for (k = 0; k < 4; k++) {
        mat.col[k].x = cin[PT_WASM_CIN_MATRIX + 4 * k]; mat.col[k].y = cin[PT_WASM_CIN_MATRIX + 4 * k + 1];
        mat.col[k].z = cin[PT_WASM_CIN_MATRIX + 4 * k + 2]; mat.col[k].w = cin[PT_WASM_CIN_MATRIX + 4 * k + 3];
    }
    if (nops > PT_WASM_NCOPS) return -1;
    if (nops >= 0 && (rc = course_matrix(&mat, nops)) != 0) return rc;
    norm = pt_r9_normalize_matrix(&cam);    /* as pt_course_camera() builds it */
    if (course_model(&m) != 0) return -1;
    ckeep(PT_WASM_CST_MODEL, &m, at);
    if (renderer == 9) {
        for (k = 0; k < m.nv; k++) m.v[k] = pt_r9_model2world(m.v[k], &mat);
        ckeep(PT_WASM_CST_WORLD, &m, at);
    }
    for (k = 0; k < m.nv; k++)
        m.v[k] = renderer == 9 ? pt_r9_world2view(m.v[k], cam.view)
                               : pt_r7_model2view(m.v[k], move);
    ckeep(PT_WASM_CST_VIEW, &m, at);
    for (k = 0; k < m.nv; k++)
        m.v[k] = renderer == 9 ? pt_r9_view2camera(m.v[k], &norm) : pt_r7_view2camera(m.v[k], &cam);
    ckeep(PT_WASM_CST_CAMERA, &m, at);
    if (nearclip && (rc = pt_rv_nearclip(&m, cam.n, 0)) != 0) return rc == -2 ? -2 : -1;
    ckeep(PT_WASM_CST_NEARCLIP, &m, at);
    for (k = 0; k < m.nv; k++) m.v[k] = pt_rv_project(m.v[k], cam.perspective);
    ckeep(PT_WASM_CST_IMAGE, &m, at);
    if ((rc = pt_rv_clip(&m, 0)) != 0) return rc == -2 ? -2 : -1;
    ckeep(PT_WASM_CST_CLIP, &m, at);
    if (chave[PT_WASM_CST_CLIP]) {
        pt_vec4 p = cat[PT_WASM_CST_CLIP];
        pt_vec3 ip;
        pt_vec2 pp;
        ip.x = p.x; ip.y = p.y; ip.z = 0.0;
        pp = pt_image2pixel(ip, w, h, 0);
        cpx[4] = !(__builtin_fabs(p.x) > 1 || __builtin_fabs(p.y) > 1);   /* the clip kept it */
        if (cpx[4]) {
            pt_rv_raster_par par = {0};
            int x_fb, y_fb;
            cpx[0] = (int64_t)pt_java_round(pp.x) - 1;          /* x_vp = Math.round(x_pp) - 1 */
            cpx[1] = (int64_t)h - (int64_t)pt_java_round(pp.y); /* y_vp = h - Math.round(y_pp) */
            par.w = w; par.h = h; par.x_ul = x_ul; par.y_ul = y_ul; par.W = W; par.H = H;
            cpx[5] = pt_rv_fb_index(&par, (int)cpx[0], (int)cpx[1], &x_fb, &y_fb);
            cpx[2] = x_fb;                                       /* x_fb = x_ul + x_vp */
            cpx[3] = y_fb;                                       /* y_fb = y_ul + y_vp */
        }
    }
    return 0;
}

EXPORT("pt_wasm_course_have") int pt_wasm_course_have(int st);
int pt_wasm_course_have(int st)
{
    return st >= 0 && st < PT_NCOURSE && chave[st];
}

EXPORT("pt_wasm_course_at") double pt_wasm_course_at(int st, int k);
double pt_wasm_course_at(int st, int k)
{
    pt_vec4 a;

    if (!pt_wasm_course_have(st)) return 0;
    a = cat[st];
    return k == 0 ? a.x : k == 1 ? a.y : k == 2 ? a.z : a.w;
}

EXPORT("pt_wasm_course_px") int64_t pt_wasm_course_px(int k);
int64_t pt_wasm_course_px(int k)
{
    return k >= 0 && k < 6 ? cpx[k] : 0;
}

/* strcmp for stages/pt_stage.c's pt_stage_by_name() (src/wasm/string.h). */
int strcmp(const char *a, const char *b)
{
    while (*a && *a == *b) { a++; b++; }
    return (unsigned char)*a - (unsigned char)*b;
}
