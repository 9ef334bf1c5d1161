/*
** tests/test_reference.c -- every case rendered by the Java teaching renderer
** See LICENSE for copyright and license.
**
** For each NAME.scene in the directory given (default tests/reference, a copy of
** the project's shared reference cases), run the classic pipeline with every
** stage traced and compare with NAME.expect: each vertex value bit for bit (as
** doubles: -0.0 differs from 0.0), each integer exactly, and the set of lit
** pixels exactly.  Format of .expect: tests/reference/README.md.
*/
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "refcases.h"
#include "core/pipeline.h"

/* What the pipeline produced for one case. */
typedef struct got {
    const pt_scene *s;
    pt_vrec *rec;                /* rec[(k-th vertex overall)*PT_NSTAGES_ALL + stage] */
    unsigned char *have;         /* same index: 1 when reported */
    size_t *base;                /* base[m]: index of model m's first vertex */
    size_t cur;                  /* vertex being traced */
    unsigned char *lit;          /* fb_w*fb_h: 1 when a pixel was written */
} got;

static void on_begin(void *ud, const pt_model *m, uint64_t v)
{
    got *g = ud;
    g->cur = g->base[m - g->s->models] + (size_t)(v - 1);
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    got *g = ud;
    g->rec[g->cur * PT_NSTAGES_ALL + r->stage] = *r;
    g->have[g->cur * PT_NSTAGES_ALL + r->stage] = 1;
}

static void on_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                      size_t n)
{
    got *g = ud;
    size_t k;
    (void)m; (void)seg;
    for (k = 0; k < n; k++) g->lit[px[k].idx] = 1;
}

static int same_double(double a, double b)
{
    return a == b ? signbit(a) == signbit(b) : (isnan(a) && isnan(b));
}

static size_t model_index(const pt_scene *s, const char *name)
{
    size_t k;
    for (k = 0; k < s->nmodels; k++)
        if (strcmp(s->models[k].name, name) == 0) return k;
    return (size_t)-1;
}

/* Compare one "vertex ..." line; returns NULL or what differs. */
static const char *check_vertex_line(got *g, char *line, size_t *nlines)
{
    char model[256], stage[32];
    unsigned long v;
    int used, st;
    size_t mk, at;
    const pt_vrec *r;
    char *p;

    if (sscanf(line, "vertex %255s %lu %31s %n", model, &v, stage, &used) != 3)
        return "unreadable vertex line";
    p = line + used;
    mk = model_index(g->s, model);
    st = pt_stage_by_name(stage);
    if (mk == (size_t)-1 || st < 0 || v < 1 || v > g->s->models[mk].nv)
        return "unknown model, vertex or stage";
    at = (g->base[mk] + v - 1) * PT_NSTAGES_ALL + (size_t)st;
    if (!g->have[at]) return "vertex not traced";
    g->have[at] = 2;                        /* matched by a line */
    (*nlines)++;
    r = &g->rec[at];
    if (st <= PT_STAGE_PIXEL) {
        double x = strtod(p, &p), y = strtod(p, &p);
        double z = st < PT_STAGE_PIXEL ? strtod(p, &p) : 0;
        if (!same_double(x, r->x) || !same_double(y, r->y) ||
            (st < PT_STAGE_PIXEL && !same_double(z, r->z)))
            return "real value differs";
    } else if (st == PT_STAGE_INDEX) {
        if (strncmp(p, "null", 4) == 0) return (r->flags & PT_REC_NULL) ? NULL : "index should be null";
        if ((r->flags & PT_REC_NULL) || strtoll(p, NULL, 10) != r->i) return "index differs";
    } else {
        long long x = strtoll(p, &p, 10), y = strtoll(p, &p, 10);
        if ((r->flags & PT_REC_NULL) || x != r->ix || y != r->iy) return "pixel differs";
    }
    return NULL;
}

/* The cases tests/reference/ holds (its README.md): every one must run, so
** that a lost or unreadable case fails instead of shrinking the test. */
#define REF_NCASES 39
static int ncases_run;

static void run_case(const char *dir, const char *name)
{
    char path[4096], line[4096], descr[PT_ERRLEN + 600];
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    got g;
    size_t k, nv = 0, nlines = 0, nhave = 0, npix = 0, nlit = 0;
    const char *bad = NULL;
    unsigned char *want;
    FILE *f;

    if (pt_ref_load(&s, dir, name, "ref") != 0) return;
    ncases_run++;
    pt_options_default(&o);
    o.all_stages = 1;
    pt_plan_make(&p, &s, &o);
    memset(&g, 0, sizeof g);
    g.s = &s;
    g.base = calloc(s.nmodels + 1, sizeof *g.base);
    for (k = 0; k < s.nmodels; k++) { g.base[k] = nv; nv += s.models[k].nv; }
    g.rec = calloc(nv * PT_NSTAGES_ALL + 1, sizeof *g.rec);
    g.have = calloc(nv * PT_NSTAGES_ALL + 1, 1);
    g.lit = calloc((size_t)s.fb_w * s.fb_h, 1);
    want = calloc((size_t)s.fb_w * s.fb_h, 1);
    memset(&l, 0, sizeof l);
    l.vertex_begin = on_begin;
    l.sink.vertex = on_vertex;
    l.sink.ud = &g;
    l.pixels = on_pixels;
    l.ud = &g;
    pt_run(&s, &p, &o, &l, NULL, &sum);

    snprintf(path, sizeof path, "%s/%s.expect", dir, name);
    f = fopen(path, "r");
    while (f && !bad && fgets(line, sizeof line, f)) {
        if (strncmp(line, "vertex ", 7) == 0) {
            bad = check_vertex_line(&g, line, &nlines);
        } else if (strncmp(line, "pixel ", 6) == 0) {
            long x, y;
            if (sscanf(line, "pixel %ld %ld", &x, &y) != 2 || x < 0 || y < 0 ||
                x >= s.fb_w || y >= s.fb_h) bad = "bad pixel line";
            else if (!want[(size_t)y * s.fb_w + x]) { want[(size_t)y * s.fb_w + x] = 1; npix++; }
        }
    }
    if (!f) bad = "no .expect file";
    else fclose(f);
    for (k = 0; k < nv * PT_NSTAGES_ALL; k++) nhave += g.have[k] != 0;
    for (k = 0; !bad && k < (size_t)s.fb_w * s.fb_h; k++) {
        nlit += g.lit[k];
        if (g.lit[k] != want[k]) bad = "lit pixels differ";
    }
    if (!bad && nhave != nlines) bad = "traced vertices differ from the expected ones";
    snprintf(descr, sizeof descr, "ref %s: %zu vertex records, %zu pixels match (%s)",
             name, nlines, npix, bad ? bad : "ok");
    PT_CHECK(descr, bad == NULL && nlit == npix);
    free(g.base); free(g.rec); free(g.have); free(g.lit); free(want);
    pt_plan_free(&p);
    pt_scene_free(&s);
}

int main(int argc, char **argv)
{
    pt_ref_run(argc, argv, "test_reference", run_case);
    {
        char d[80];
        snprintf(d, sizeof d, "ref-0 all %d reference cases ran (%d did)", REF_NCASES, ncases_run);
        PT_CHECK(d, ncases_run == REF_NCASES);
    }
    return pt_test_report();
}
