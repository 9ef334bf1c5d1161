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
*/
#include <string.h>                         /* src/wasm/string.h: strcmp */
#include "stages/pt_classic.h"
#include "stages/pt_matrix.h"
#include "wasm/pt_wasm_libm.h"            /* the sin and cos table */
#include "stages/wasm/pt_wasm_in.h"

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

/* strcmp for stages/pt_stage.c's pt_stage_by_name() (src/wasm/string.h). */
int strcmp(const char *a, const char *b)
{
    while (*a && *a == *b) { a++; b++; }
    return (unsigned char)*a - (unsigned char)*b;
}
