/*
** tests/unit/test_lanes79.c -- renderers 7 and 9: a trace on two threads is the trace on one
** See LICENSE for copyright and license.
**
** Usage: test_lanes79 [--both N] SCENE...  Each scene of renderer 7 or 9 is
** traced by pt_course_trace() and logged by pt_course_log() on one thread and
** on two (io/tlanes.h), in every format (JSON Lines and text with and
** without the formulas, CSV, the course's log at its default switches and
** with every one), with the driver's pieces of its default size and with
** tiny ones (a cut before every model's step and every primitive, or every
** few), so that the lanes take turns often and, each piece's text in a
** block of its own, run out of free blocks and wait for each other.  Trace,
** image and result must be the same.  With --both N, the first N scenes'
** pieces must go to both threads (the JSON Lines trace at the default size;
** tried a few times, since which thread gets there first is the
** scheduler's to say).  The second thread runs the rasterizer on the
** primitives of its own pieces only (the first on all of them, for the
** image), as the driver's tally says.  And on every scene each primitive's
** pixel lines, which the cuts count without drawing (pt_rv_raster_steps)
** or as they draw (pt_rv_raster_prim_steps), are the lines the rasterizer
** tells as it draws it.
*/
#define _POSIX_C_SOURCE 200809L       /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "core/scene.h"
#include "core/fb.h"
#include "io/trace.h"
#include "io/trace_course.h"
#include "io/trace_kraft.h"
#include "core/course.h"
#include "stages/rv_raster.h"

typedef struct result {
    char *text;                  /* the trace */
    size_t len;
    pt_fb fb;                    /* the image */
    int rc;
    uint64_t taken[2];           /* the pieces each thread wrote (two threads) */
    pt_course_tally tally[2];    /* the primitives each thread took and drew */
} result;

static uint64_t steps_prims;     /* the primitives check_steps saw, all scenes */

/* The ways of writing: a format of pt_course_trace, or the log (kraft). */
typedef struct way {
    const char *name;
    int fmt;                     /* PT_FORMAT_*; PT_FORMAT_KRAFT: pt_course_log */
    int explain;
    unsigned dbg;                /* the log's switches */
} way;

static const way ways[] = {
    {"jsonl", PT_FORMAT_JSONL, 0, 0}, {"jsonl --explain", PT_FORMAT_JSONL, 1, 0},
    {"text", PT_FORMAT_TEXT, 0, 0}, {"text --explain", PT_FORMAT_TEXT, 1, 0},
    {"csv", PT_FORMAT_CSV, 0, 0}, {"kraft", PT_FORMAT_KRAFT, 0, PT_KDBG_SCENE},
    {"kraft all", PT_FORMAT_KRAFT, 0, PT_KDBG_ALL},
};

/* The sizes of the pieces tried (vertices, primitives, pixels): the
** driver's own, a cut everywhere, a few. */
static const uint64_t sizes[][3] = {{0, 0, 0}, {1, 1, 1}, {3, 2, 40}};

/* Write s the way wy into *r, on one thread (cut NULL) or two. */
static void trace(result *r, const pt_scene *s, const way *wy, const uint64_t *cut)
{
    pt_course_cuts cuts;
    char err[512];
    FILE *f;

    memset(r, 0, sizeof *r);
    r->rc = -1;
    memset(&cuts, 0, sizeof cuts);
    if (cut) {
        cuts.threads = 2;
        cuts.vertices = cut[0];
        cuts.prims = cut[1];
        cuts.pixels = cut[2];
    }
    if (pt_fb_init(&r->fb, s->fb_w, s->fb_h, s->background) != 0) return;
    if (!(f = open_memstream(&r->text, &r->len))) return;
    r->rc = wy->fmt == PT_FORMAT_KRAFT
          ? pt_course_log(f, s, wy->dbg, cut ? &cuts : NULL, &r->fb, err, sizeof err)
          : pt_course_trace(f, s, wy->fmt, 6, wy->explain, cut ? &cuts : NULL, &r->fb, err,
                            sizeof err);
    if (ferror(f)) r->rc = -2;
    fclose(f);                              /* r->text, r->len: the trace */
    r->taken[0] = cuts.taken[0];
    r->taken[1] = cuts.taken[1];
    r->tally[0] = cuts.tally[0];
    r->tally[1] = cuts.tally[1];
}

/* Two threads' r: the first drew every primitive, the second only those of
** its pieces (each primitive is in one piece). */
static int drew_alike(const result *r)
{
    const pt_course_tally *t = r->tally;
    return t[0].prims_drawn == t[0].prims_wanted + t[1].prims_wanted &&
           t[1].prims_drawn == t[1].prims_wanted;
}

/* ===== the cuts' pixel lines against the rasterizer's ===== */

typedef struct steps_check {
    pt_rv_raster_par par;        /* the viewport, as the driver's */
    unsigned char *rgb;          /* a framebuffer to draw each primitive again */
    uint64_t lines;              /* the pixel lines of the primitive being drawn */
    uint64_t prims, wrong, total;
} steps_check;

static void sc_pixel(void *ud, const pt_rv_pixel *px)
{
    (void)px;
    ((steps_check *)ud)->lines++;
}

static void sc_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    (void)pos; (void)m; (void)p;
    ((steps_check *)ud)->lines = 0;
}

static void sc_drawn(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                     const pt_rv_prim *p, uint64_t n)
{
    steps_check *sc = ud;
    uint64_t again;
    (void)pos; (void)n;
    sc->prims++;
    sc->total += sc->lines;
    if (pt_rv_raster_steps(m, p, &sc->par) != sc->lines) sc->wrong++;
    pt_rv_raster_prim_steps(m, p, &sc->par, sc->rgb, NULL, &again);   /* found drawing */
    if (again != sc->lines) sc->wrong++;
}

/* Every primitive of s: pt_rv_raster_steps() = the pixel lines drawn. */
static void check_steps(const pt_scene *s, const char *path)
{
    steps_check sc;
    pt_rv_raster_ls rls;
    pt_course_ls ls;
    pt_fb fb;
    char what[600];
    int rc = -1;

    memset(&sc, 0, sizeof sc);
    sc.par.w = s->vp_w;
    sc.par.h = s->vp_h;
    sc.par.x_ul = s->vp_x;
    sc.par.y_ul = s->vp_y;
    sc.par.W = s->fb_w;
    sc.par.H = s->fb_h;
    memset(&rls, 0, sizeof rls);
    rls.pixel = sc_pixel;
    rls.ud = &sc;
    memset(&ls, 0, sizeof ls);
    ls.raster = sc_raster;
    ls.drawn = sc_drawn;
    ls.raster_ls = &rls;
    ls.ud = &sc;
    if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) == 0) {
        sc.rgb = malloc(3 * (size_t)s->fb_w * (size_t)s->fb_h + 1);
        rc = sc.rgb ? pt_course_render(s, &fb, &ls) : -1;
        free(sc.rgb);
        pt_fb_free(&fb);
    }
    snprintf(what, sizeof what, "lanes79-7 %s: pixel lines by pt_rv_raster_steps and "
             "pt_rv_raster_prim_steps = drawn "
             "(%llu primitives, %llu lines, %llu differ)", path, (unsigned long long)sc.prims,
             (unsigned long long)sc.total, (unsigned long long)sc.wrong);
    PT_CHECK(what, rc == 0 && sc.wrong == 0);
    steps_prims += sc.prims;
}

static void result_free(result *r)
{
    free(r->text);
    pt_fb_free(&r->fb);
}

static int same(const result *a, const result *b)
{
    return a->rc == 0 && b->rc == 0 && a->text && b->text && a->len == b->len &&
           memcmp(a->text, b->text, a->len) == 0 && a->fb.w == b->fb.w && a->fb.h == b->fb.h &&
           memcmp(a->fb.rgb, b->fb.rgb, 3 * (size_t)a->fb.w * (size_t)a->fb.h) == 0;
}

/* Every way and size of scene path; with both, its pieces on both threads. */
static void check_scene(const char *path, int both)
{
    pt_scene s;
    char err[512], what[600];
    size_t k, z;

    if (pt_scene_load(&s, path, err, sizeof err) != 0) {
        printf("FAIL %s: %s\n", path, err);
        pt_test_failed++;
        return;
    }
    if (s.renderer != 7 && s.renderer != 9) {
        printf("FAIL %s: not renderer 7 or 9\n", path);
        pt_test_failed++;
        pt_scene_free(&s);
        return;
    }
    check_steps(&s, path);
    for (k = 0; k < sizeof ways / sizeof ways[0]; k++) {
        result one;
        trace(&one, &s, &ways[k], NULL);
        for (z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
            result two;
            trace(&two, &s, &ways[k], sizes[z]);
            snprintf(what, sizeof what, "lanes79-1 %s, %s, pieces %d: the trace and image of "
                     "one thread", path, ways[k].name, (int)z);
            PT_CHECK(what, same(&one, &two));
            snprintf(what, sizeof what, "lanes79-2 %s, %s, pieces %d: the first thread wrote "
                     "the first piece and the last", path, ways[k].name, (int)z);
            PT_CHECK(what, two.taken[0] >= 2);
            snprintf(what, sizeof what, "lanes79-8 %s, %s, pieces %d: the first thread drew "
                     "every primitive, the second only its pieces' (%llu of %llu)", path,
                     ways[k].name, (int)z, (unsigned long long)two.tally[1].prims_drawn,
                     (unsigned long long)two.tally[0].prims_drawn);
            PT_CHECK(what, drew_alike(&two));
            result_free(&two);
        }
        result_free(&one);
    }
    if (both) {
        result two;
        int tries;
        for (tries = 0; tries < 5; tries++) {
            trace(&two, &s, &ways[0], sizes[0]);
            if (two.taken[0] > 1 && two.taken[1] > 0 && two.tally[0].prims_wanted > 0 &&
                two.tally[1].prims_wanted > 0) break;
            result_free(&two);
            two.text = NULL;
            two.fb.rgb = NULL;
        }
        snprintf(what, sizeof what, "lanes79-3 %s: pieces on both threads (%llu and %llu)",
                 path, (unsigned long long)two.taken[0], (unsigned long long)two.taken[1]);
        PT_CHECK(what, two.taken[0] > 1 && two.taken[1] > 0);
        snprintf(what, sizeof what, "lanes79-9 %s: the second thread drew fewer primitives "
                 "than the first (%llu of %llu), its own pieces' (%llu)", path,
                 (unsigned long long)two.tally[1].prims_drawn,
                 (unsigned long long)two.tally[0].prims_drawn,
                 (unsigned long long)two.tally[1].prims_wanted);
        PT_CHECK(what, two.tally[1].prims_drawn < two.tally[0].prims_drawn &&
                       two.tally[1].prims_wanted > 0 && drew_alike(&two));
        result_free(&two);
    }
    pt_scene_free(&s);
}

int main(int argc, char **argv)
{
    int k = 1, both = 0;

    if (argc > 2 && strcmp(argv[1], "--both") == 0) {
        both = atoi(argv[2]);
        k = 3;
    }
    for (; k < argc; k++, both--) check_scene(argv[k], both > 0);
    PT_CHECK("lanes79-7.1 the scenes have primitives to draw", steps_prims > 0);
    return pt_test_report();
}
