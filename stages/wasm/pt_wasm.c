/*
** stages/wasm/pt_wasm.c -- the classic camera's stages as a WebAssembly module
** See LICENSE for copyright and license.
**
** Compiled with the stages' own files (pt_stage.c, pt_round.c, s1..s6,
** pt_classic.c) by clang --target=wasm32 -nostdlib and linked by wasm-ld
** into $B/stages.wasm (the Makefile's wasm part); the journey page
** (src/tools/journey/journey_wasm.c) embeds it and calls the functions
** below when a slider moves.  Nothing here computes a coordinate:
** pt_wasm_run() calls pt_classic_journey(), as pt_run() does, and keeps the
** record each stage reports.  The page reads them back one value at a time,
** so it needs to know nothing of pt_vrec's layout.
**
**   pt_wasm_run(x_m, y_m, z_m, x_t, y_t, z_t, perspective, w, h, x_ul, y_ul, W, H)
**   pt_wasm_real(st, k)     value k (0..2) of a real stage: x, y, z
**   pt_wasm_int(st, k)      value k of an integer stage (ix, iy; i), an i64
**   pt_wasm_has(st, k)      1 when value k of stage st has a value (null per value)
**   pt_wasm_flags(st), pt_wasm_warn(st)   the record's PT_REC_*, PT_WARN_* bits
*/
#include <string.h>                         /* stages/wasm/string.h: strcmp */
#include "pt_classic.h"

#define EXPORT(name) __attribute__((export_name(name)))

static pt_vrec recs[PT_NSTAGES];            /* the last run's records, by stage */

static void keep(void *ud, const pt_vrec *r)
{
    (void)ud;
    if ((int)r->stage >= 0 && r->stage < PT_NSTAGES) recs[r->stage] = *r;
}

/* Run one vertex through the classic stages.  Returns 0, or -1 (no run) when
** a size is below 1.  This function can't fail otherwise. */
EXPORT("pt_wasm_run") int pt_wasm_run(double x_m, double y_m, double z_m, double x_t,
                                      double y_t, double z_t, int perspective, int w, int h,
                                      int x_ul, int y_ul, int W, int H);
int pt_wasm_run(double x_m, double y_m, double z_m, double x_t, double y_t, double z_t,
                int perspective, int w, int h, int x_ul, int y_ul, int W, int H)
{
    static const pt_sink sink = {keep, 0};
    const pt_sink *sinks[PT_NSTAGES_ALL];
    pt_stage_params par;
    pt_vec3 v_m;
    double z_c;
    int k;

    if (w < 1 || h < 1 || W < 1 || H < 1) return -1;
    for (k = 0; k < PT_NSTAGES_ALL; k++) sinks[k] = k < PT_NSTAGES ? &sink : 0;
    for (k = 0; k < PT_NSTAGES; k++) {
        pt_vrec none = {0};
        recs[k] = none;
    }
    par.translate.x = x_t; par.translate.y = y_t; par.translate.z = z_t;
    par.perspective = perspective != 0;
    par.w = w; par.h = h; par.x_ul = x_ul; par.y_ul = y_ul; par.W = W; par.H = H;
    v_m.x = x_m; v_m.y = y_m; v_m.z = z_m;
    pt_classic_journey(&par, v_m, sinks, &z_c);
    return 0;
}

static const pt_vrec *rec(int st)
{
    static const pt_vrec none = {0};
    return st >= 0 && st < PT_NSTAGES ? &recs[st] : &none;
}

EXPORT("pt_wasm_real") double pt_wasm_real(int st, int k);
double pt_wasm_real(int st, int k)
{
    return k == 0 ? rec(st)->x : k == 1 ? rec(st)->y : rec(st)->z;
}

EXPORT("pt_wasm_int") int64_t pt_wasm_int(int st, int k);
int64_t pt_wasm_int(int st, int k)
{
    if (st == PT_STAGE_INDEX) return rec(st)->i;
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

/* strcmp for stages/pt_stage.c's pt_stage_by_name() (stages/wasm/string.h). */
int strcmp(const char *a, const char *b)
{
    while (*a && *a == *b) { a++; b++; }
    return (unsigned char)*a - (unsigned char)*b;
}
