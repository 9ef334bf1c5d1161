/*
** tests/unit/test_trace.c -- the trace writer's shortcuts give the bytes the long way gives
** See LICENSE for copyright and license.
**
** The writer keeps the spellings of recent doubles (256 slots by a hash of
** their bits) and the beginning of the pixel records of the segment being
** drawn, and how a vertex's records begin, its number too.  Here records
** are handed to it straight, as pt_run() hands them: vertex records whose
** numbers come from a pool of 1000 (so slots are hit, and shared by values
** that collide), in CSV and in JSON Lines (runs of stages, the model and v
** changing), and pixels that switch between models and segments, in JSON
** Lines and text.  Every line must be the one written here from
** pt_fmt_shortest() and printf.
*/
#define _POSIX_C_SOURCE 200809L
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "core/pipeline.h"
#include "io/numfmt.h"
#include "io/trace.h"

static uint64_t rng = 88172645463325252ULL;

static uint64_t next_random(void)           /* xorshift64 (Marsaglia 2003) */
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return rng;
}

#define NPOOL 1000
#define NREC 20000

/* A double of every kind: short decimals, long ones, integers, -0, tiny,
** any bits, and doubles next to each other (0.1's ulp is 2^-56), which
** differ only in their low bits when they share a slot. */
static double pool_value(int k)
{
    uint64_t r = next_random();
    double x;

    switch (k % 6) {
    case 5: return 0.1 + k * 0x1p-56;      /* neighbours: the same high bits */
    case 0: return (double)(int64_t)(r % 2000001 - 1000000) / 1e6;
    case 1: return ((double)(r >> 11) * 0x1p-53 - 0.5) * 3840;
    case 2: return (double)(int64_t)(r % 4001) - 2000;
    case 3: return k % 2 ? -0.0 : 1e-300 * (double)(r % 1000);
    default: memcpy(&x, &r, sizeof x); return x;     /* any bits, NaN too */
    }
}

static int g_failed_line;               /* the first line that differs, 1-based */

/* Compare the lines of got with want, one by one. */
static int same_lines(const char *got, size_t n, const char *want, size_t wn)
{
    size_t k, line = 1;

    for (k = 0; k < n && k < wn; k++) {
        if (got[k] != want[k]) break;
        if (got[k] == '\n') line++;
    }
    if (k == n && n == wn) return 1;
    g_failed_line = (int)line;
    return 0;
}

/* End the trace t written to f and the lines w wanted; compare the two. */
static int finish(pt_trace *t, FILE *f, FILE *w, char **got, size_t *n, char **want,
                  size_t *wn)
{
    int ok = pt_trace_finish(t) == 0;

    fclose(f);
    fclose(w);
    ok = ok && same_lines(*got, *n, *want, *wn);
    free(*got);
    free(*want);
    return ok;
}

/* CSV (the classic camera's columns) of NREC model records from the pool. */
static int csv_numbers(void)
{
    static pt_trace t;
    static double pool[NPOOL];
    pt_model m;
    pt_listener l;
    char *got = NULL, *want = NULL, num[3][PT_NUMLEN];
    size_t n = 0, wn = 0;
    FILE *f = open_memstream(&got, &n), *w = open_memstream(&want, &wn);
    int k;

    if (!f || !w) return 0;
    for (k = 0; k < NPOOL; k++) pool[k] = pool_value(k);
    memset(&m, 0, sizeof m);
    m.name = "m";
    pt_trace_init(&t, f, PT_FORMAT_CSV, 6);
    pt_trace_listener(&t, &l);
    for (k = 0; k < NREC; k++) {
        pt_vrec r;
        memset(&r, 0, sizeof r);
        r.stage = PT_STAGE_MODEL;
        r.x = pool[next_random() % NPOOL];
        r.y = pool[next_random() % NPOOL];
        r.z = pool[next_random() % NPOOL];
        l.vertex_begin(l.ud, &m, (uint64_t)k + 1);
        l.sink.vertex(l.sink.ud, &r);
        pt_fmt_shortest(num[0], r.x);
        pt_fmt_shortest(num[1], r.y);
        pt_fmt_shortest(num[2], r.z);
        fprintf(w, "m,%d,model,%s,%s,%s,,,,,\n", k + 1, num[0], num[1], num[2]);
    }
    return finish(&t, f, w, &got, &n, &want, &wn);
}

/* x as a JSON Lines trace spells it: pt_fmt_shortest(), -0 as -0.0 (a JSON
** reader keeps its sign), nan and inf in quotes. */
static void json_spell(char *b, double x)
{
    char s[PT_NUMLEN];

    pt_fmt_shortest(s, x);
    if (x == 0 && signbit(x)) strcpy(b, "-0.0");
    else if (!isfinite(x)) snprintf(b, PT_NUMLEN + 2, "\"%s\"", s);
    else strcpy(b, s);
}

/* JSON Lines: NREC vertex records of two models (a short name, and one too
** long for the kept opening), each vertex with a run of stages: reals from
** the pool, integers that are null now and then, the viewport's inside.
** The model changes now and then with v kept, or v jumps back: the v
** digits kept with the opening must follow both. */
static int json_vertices(void)
{
    static pt_trace t;
    static double pool[NPOOL];
    static const char *const names[2] = {"m1", "a_name_of_more_than_forty_bytes_written_piece_by_piece"};
    static const pt_stage stages[] = {PT_STAGE_MODEL, PT_STAGE_CAMERA, PT_STAGE_IMAGE,
                                      PT_STAGE_PIXEL, PT_STAGE_VIEWPORT, PT_STAGE_INDEX};
    pt_model m[2];
    pt_listener l;
    char *got = NULL, *want = NULL, num[3][PT_NUMLEN + 2], ints[2][32];
    size_t n = 0, wn = 0;
    FILE *f = open_memstream(&got, &n), *w = open_memstream(&want, &wn);
    int k = 0, mk = 0;
    uint64_t v = 1;

    if (!f || !w) return 0;
    for (k = 0; k < NPOOL; k++) pool[k] = pool_value(k);
    memset(m, 0, sizeof m);
    m[0].name = (char *)names[0];
    m[1].name = (char *)names[1];
    pt_trace_init(&t, f, PT_FORMAT_JSONL, 6);
    pt_trace_listener(&t, &l);
    for (k = 0; k < NREC; ) {
        size_t s, first = next_random() % 6, last = first + next_random() % (6 - first);
        if (next_random() % 8 == 0) mk = !mk;
        v = next_random() % 16 == 0 ? next_random() % 100000 + 1 : v + 1;
        l.vertex_begin(l.ud, &m[mk], v);
        for (s = first; s <= last; s++, k++) {
            pt_vrec r;
            const pt_stage_info *in = &pt_stage_infos[stages[s]];
            int j;
            memset(&r, 0, sizeof r);
            r.stage = stages[s];
            fprintf(w, "{\"type\":\"vertex\",\"model\":\"%s\",\"v\":%" PRIu64
                    ",\"stage\":\"%s\"", names[mk], v, in->name);
            if (in->nreal) {
                r.x = pool[next_random() % NPOOL];
                r.y = pool[next_random() % NPOOL];
                r.z = pool[next_random() % NPOOL];
                json_spell(num[0], r.x);
                json_spell(num[1], r.y);
                json_spell(num[2], r.z);
                for (j = 0; j < in->nreal; j++) fprintf(w, ",\"%s\":%s", in->key[j], num[j]);
            } else {
                r.ix = (int64_t)(next_random() % 4000) - 1000;
                r.iy = (int64_t)(next_random() % 3000);
                r.i = (int64_t)(next_random() % 100000000);
                if (next_random() % 5 == 0)
                    r.flags = PT_REC_NULL | (next_random() % 2 ? PT_REC_HAS_X : 0u);
                snprintf(ints[0], sizeof ints[0], "%" PRId64, r.stage == PT_STAGE_INDEX ? r.i : r.ix);
                snprintf(ints[1], sizeof ints[1], "%" PRId64, r.iy);
                for (j = 0; j < in->nint; j++)
                    fprintf(w, ",\"%s\":%s", in->key[j], pt_rec_has(&r, j) ? ints[j] : "null");
                if (r.stage == PT_STAGE_VIEWPORT) {
                    if (next_random() % 2) r.flags |= PT_REC_INSIDE;
                    fprintf(w, ",\"inside\":%s", r.flags & PT_REC_INSIDE ? "true" : "false");
                }
            }
            fprintf(w, "}\n");
            l.sink.vertex(l.sink.ud, &r);
        }
    }
    return finish(&t, f, w, &got, &n, &want, &wn);
}

/* Pixels of two models, segments switching now and then, in fmt, handed
** over in runs of 1 to PT_RASTER_RUN as the rasterizer hands them; x_fb
** below 0 and indexes from 10^8 on now and then (a student's stages). */
static int pixels(pt_format fmt)
{
    static pt_trace t;
    static const char *const names[2] = {"m1", "a_name_of_more_than_forty_bytes_written_piece_by_piece"};
    pt_model m[2];
    pt_listener l;
    char *got = NULL, *want = NULL, who[128];
    size_t n = 0, wn = 0;
    FILE *f = open_memstream(&got, &n), *w = open_memstream(&want, &wn);
    int k, mk = 0;
    uint64_t seg = 1;

    if (!f || !w) return 0;
    memset(m, 0, sizeof m);
    m[0].name = (char *)names[0];
    m[1].name = (char *)names[1];
    pt_trace_init(&t, f, fmt, 6);
    pt_trace_listener(&t, &l);
    for (k = 0; k < NREC; ) {
        pt_fb_pixel px[PT_RASTER_RUN];
        int run = 1 + (int)(next_random() % PT_RASTER_RUN), j;
        if (run > NREC - k) run = NREC - k;
        if (next_random() % 10 == 0) mk = !mk;
        if (next_random() % 4 == 0) seg = next_random() % 100000 + 1;
        for (j = 0; j < run; j++) {
            int64_t x = (int64_t)(next_random() % 4000) - 1000, y = (int64_t)(next_random() % 3000);
            int64_t i = (int64_t)(next_random() % 100000000);
            if (next_random() % 100 == 0) i = (int64_t)(next_random() % 1000000000000);
            px[j].x_fb = x; px[j].y_fb = y; px[j].idx = i;
            if (fmt == PT_FORMAT_JSONL) {
                fprintf(w, "{\"type\":\"pixel\",\"model\":\"%s\",\"segment\":%" PRIu64
                        ",\"x\":%" PRId64 ",\"y\":%" PRId64 ",\"i\":%" PRId64 "}\n",
                        names[mk], seg, x, y, i);
            } else {
                snprintf(who, sizeof who, "%s s%" PRIu64, names[mk], seg);
                fprintf(w, "%-13s pixel        x_fb = %12" PRId64 "  y_fb = %12" PRId64
                        "  idx = %" PRId64 "\n", who, x, y, i);
            }
        }
        l.pixels(l.ud, &m[mk], seg, px, (size_t)run);
        k += run;
    }
    return finish(&t, f, w, &got, &n, &want, &wn);
}

int main(void)
{
    g_failed_line = 0;
    PT_CHECK("trace-1.1 CSV: 20000 records of numbers from a pool of 1000, as "
             "pt_fmt_shortest spells each", csv_numbers());
    if (g_failed_line) printf("  first difference in line %d\n", g_failed_line);
    g_failed_line = 0;
    PT_CHECK("trace-1.4 JSON Lines: 20000 vertex records of two models, runs of "
             "stages, v going on or jumping", json_vertices());
    if (g_failed_line) printf("  first difference in line %d\n", g_failed_line);
    g_failed_line = 0;
    PT_CHECK("trace-1.2 JSON Lines: 20000 pixels of two models and changing segments",
             pixels(PT_FORMAT_JSONL));
    if (g_failed_line) printf("  first difference in line %d\n", g_failed_line);
    g_failed_line = 0;
    PT_CHECK("trace-1.3 text: the same pixels, columns as printf aligns them",
             pixels(PT_FORMAT_TEXT));
    if (g_failed_line) printf("  first difference in line %d\n", g_failed_line);
    return pt_test_report();
}
