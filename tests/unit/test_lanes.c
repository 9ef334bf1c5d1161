/*
** tests/unit/test_lanes.c -- a trace on two threads is the trace on one, byte for byte
** See LICENSE for copyright and license.
**
** Usage: test_lanes SCENE...  Each scene is traced by pt_run() alone and by
** pt_tlanes_run() in every format (JSON Lines, text with and without the
** formulas, CSV), with an image and without, with the pieces of pt_run's
** default size and with tiny ones (a cut after every vertex and every
** segment, or every few), so that the lanes take turns often and, each
** piece's text in a block of its own, run out of free blocks and wait for
** each other; then each filter of the command line on its own.  Trace,
** image and summary must be the same (CSV has no summary record: then
** pt_run counts what the command line needs).
*/
#define _POSIX_C_SOURCE 200809L       /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "core/pipeline.h"
#include "io/trace.h"
#include "io/tlanes.h"

typedef struct result {
    char *text;                  /* the trace */
    size_t len;
    pt_fb fb;                    /* the image (pixels NULL: none) */
    pt_summary sum;
    int rc;
} result;

/* Trace s into *r in format fmt (explain: with the formulas), on two threads
** or one, with an image or not. */
static void trace(result *r, const pt_scene *s, const pt_options *o, pt_format fmt,
                  int explain, int two, int image)
{
    pt_plan p;
    pt_trace *t = malloc(sizeof *t);
    pt_listener l;
    FILE *f;

    memset(r, 0, sizeof *r);
    r->rc = -1;
    f = open_memstream(&r->text, &r->len);
    if (!t || !f || pt_plan_make(&p, s, o) != 0) { free(t); if (f) fclose(f); return; }
    if (image && pt_fb_init(&r->fb, s->fb_w, s->fb_h, s->background) != 0) r->fb.rgb = NULL;   /* no memory: compared as none */
    pt_trace_init(t, f, fmt, 6);
    t->explain = explain;
    pt_trace_listener(t, &l);
    r->rc = two ? pt_tlanes_run(t, s, &p, o, r->fb.rgb ? &r->fb : NULL, &r->sum)
                : pt_run(s, &p, o, &l, r->fb.rgb ? &r->fb : NULL, &r->sum);
    if (pt_trace_finish(t) != 0) r->rc = -2;
    fclose(f);                              /* r->text, r->len: the trace */
    free(t);
    pt_plan_free(&p);
}

static void result_free(result *r)
{
    free(r->text);
    pt_fb_free(&r->fb);
}

static int same_image(const pt_fb *a, const pt_fb *b)
{
    if (!a->rgb || !b->rgb) return !a->rgb && !b->rgb;
    return a->w == b->w && a->h == b->h &&
           memcmp(a->rgb, b->rgb, 3 * (size_t)a->w * (size_t)a->h) == 0;
}

/* The sizes of the pieces tried: pt_run's own, a cut everywhere, a few. */
static const uint64_t sizes[][3] = {
    {PT_PIECE_VERTICES, PT_PIECE_SEGMENTS, PT_PIECE_PIXELS}, {1, 1, 1}, {3, 2, 40},
};

/* The trace's filters, each on its own, in JSON Lines with tiny pieces and
** an image: --vertex 2, --model (the last model), --stage raster alone,
** --stage pixel (no raster records), --all-stages. */
#define NFILTERS 5

static void check_filtered(const pt_scene *s, const char *path, int filter)
{
    pt_options o;
    result one, two;
    char what[600];

    pt_options_default(&o);
    o.piece_vertices = 2;
    o.piece_segments = 1;
    o.piece_pixels = 16;
    switch (filter) {
    case 0: o.vertex = 2; break;
    case 1: o.model = s->nmodels ? s->models[s->nmodels - 1].name : NULL; break;
    case 2: o.stage_mask = 0; break;
    case 3: o.stage_mask = 1u << PT_STAGE_PIXEL; o.trace_raster = 0; break;
    default: o.all_stages = 1; break;
    }
    trace(&one, s, &o, PT_FORMAT_JSONL, 0, 0, 1);
    trace(&two, s, &o, PT_FORMAT_JSONL, 0, 1, 1);
    snprintf(what, sizeof what, "%s, jsonl, filter %d", path, filter);
    PT_CHECK(what, one.rc == 0 && two.rc == 0 && one.text && two.text && one.len == two.len &&
                   memcmp(one.text, two.text, one.len) == 0);
    PT_CHECK(what, same_image(&one.fb, &two.fb));
    PT_CHECK(what, memcmp(&one.sum, &two.sum, sizeof one.sum) == 0);
    result_free(&one);
    result_free(&two);
}

static void check_scene(const char *path)
{
    static const struct { pt_format fmt; int explain; const char *name; } fmts[] = {
        {PT_FORMAT_JSONL, 0, "jsonl"}, {PT_FORMAT_TEXT, 0, "text"},
        {PT_FORMAT_TEXT, 1, "text --explain"}, {PT_FORMAT_CSV, 0, "csv"},
    };
    pt_scene s;
    char err[512];
    size_t k, z;
    int image;

    if (pt_scene_load(&s, path, err, sizeof err) != 0) {
        printf("FAIL %s: %s\n", path, err);
        pt_test_failed++;
        return;
    }
    for (k = 0; k < sizeof fmts / sizeof fmts[0]; k++)
        for (z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
            for (image = 0; image < 2; image++) {
                pt_options o;
                result one, two;
                char what[600];
                pt_options_default(&o);
                o.piece_vertices = sizes[z][0];
                o.piece_segments = sizes[z][1];
                o.piece_pixels = sizes[z][2];
                trace(&one, &s, &o, fmts[k].fmt, fmts[k].explain, 0, image);
                trace(&two, &s, &o, fmts[k].fmt, fmts[k].explain, 1, image);
                snprintf(what, sizeof what, "%s, %s, pieces %d, %s", path, fmts[k].name,
                         (int)z, image ? "image" : "no image");
                PT_CHECK(what, one.rc == 0 && two.rc == 0 && one.text && two.text);
                PT_CHECK(what, one.text && two.text && one.len == two.len &&
                               memcmp(one.text, two.text, one.len) == 0);
                PT_CHECK(what, same_image(&one.fb, &two.fb));
                if (fmts[k].fmt != PT_FORMAT_CSV)
                    PT_CHECK(what, memcmp(&one.sum, &two.sum, sizeof one.sum) == 0);
                else                                /* no summary record (pt_run) */
                    PT_CHECK(what, one.sum.vertices_traced == two.sum.vertices_traced &&
                                   one.sum.behind == two.sum.behind);
                result_free(&one);
                result_free(&two);
            }
    for (k = 0; k < NFILTERS; k++) check_filtered(&s, path, (int)k);
    pt_scene_free(&s);
}

int main(int argc, char **argv)
{
    int k;

    for (k = 1; k < argc; k++) check_scene(argv[k]);
    PT_CHECK("some scene given", argc > 1);
    return pt_test_report();
}
