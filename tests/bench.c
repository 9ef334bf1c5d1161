/*
** tests/bench.c -- how fast pipetrace parses, runs, rasterizes and writes
** See LICENSE for copyright and license.
**
** `make bench` runs this.  It builds scenes in memory (a grid of vertices
** joined by segments; long lines in a large framebuffer), then times each
** phase as the program runs it: parsing the text, the stages, the rasterizer,
** and writing the trace (JSON Lines and text, to /dev/null).  Each figure is
** the median of 5 runs.  Figures depend on the machine: they are printed,
** never asserted (the tests check results, not speed).
*/
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include "core/pipeline.h"
#include "io/trace.h"

#define RUNS 5

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *t)
{
    qsort(t, RUNS, sizeof *t, by_value);
    return t[RUNS / 2];
}

/* A scene of n x n vertices in a perspective grid, joined along rows and
** columns, in a 1600 x 1200 framebuffer. */
static char *grid_scene(int n, size_t *len)
{
    size_t cap = (size_t)n * n * 80 + 4096, at = 0;
    char *s = malloc(cap);
    int i, j;

    at += (size_t)snprintf(s + at, cap - at,
                           "framebuffer 1600 1200\nviewport 100 50 1400 1100\nmodel grid\n"
                           "translate 0 0 -3\n");
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
            at += (size_t)snprintf(s + at, cap - at, "v %.6f %.6f %.6f\n",
                                   -1.2 + 2.4 * i / (n - 1), -1.2 + 2.4 * j / (n - 1),
                                   0.3 * ((i + j) % 7) / 7.0);
    for (i = 0; i < n; i++)
        for (j = 0; j + 1 < n; j++) {
            at += (size_t)snprintf(s + at, cap - at, "l %d %d\n", i * n + j + 1, i * n + j + 2);
            at += (size_t)snprintf(s + at, cap - at, "l %d %d\n", j * n + i + 1, (j + 1) * n + i + 1);
        }
    *len = at;
    return s;
}

typedef struct result {
    double parse, stages, raster, jsonl, text;
    uint64_t vertices, pixels, records;
} result;

static void count_rec(void *ud, const pt_vrec *r) { (void)r; ++*(uint64_t *)ud; }

static void bench(const char *name, const char *text, size_t len)
{
    double tp[RUNS], ts[RUNS], tr[RUNS], tj[RUNS], tt[RUNS];
    result res = {0, 0, 0, 0, 0, 0, 0, 0};
    char err[PT_ERRLEN];
    int k;
    static pt_trace tr_out;
    FILE *devnull = fopen("/dev/null", "w");

    for (k = 0; k < RUNS; k++) {
        pt_scene s;
        pt_options o;
        pt_plan p;
        pt_listener l;
        pt_summary sum;
        uint64_t nrec = 0;
        double t0;

        t0 = now();
        if (pt_scene_parse(&s, name, text, len, err, sizeof err) != 0) {
            fprintf(stderr, "bench: %s\n", err);
            exit(1);
        }
        tp[k] = now() - t0;
        pt_options_default(&o);
        pt_plan_make(&p, &s, &o);

        memset(&l, 0, sizeof l);                /* the stages alone */
        l.sink.vertex = count_rec;
        l.sink.ud = &nrec;
        o.rasterize = 0;
        t0 = now();
        pt_run(&s, &p, &o, &l, NULL, &sum);
        ts[k] = now() - t0;
        res.vertices = sum.vertices_traced;

        memset(&l, 0, sizeof l);                /* stages and rasterizer */
        o.rasterize = 1;
        t0 = now();
        pt_run(&s, &p, &o, &l, NULL, &sum);
        tr[k] = now() - t0 - ts[k];
        res.pixels = sum.pixels;

        pt_trace_init(&tr_out, devnull, PT_FORMAT_JSONL, 6);   /* JSON Lines */
        pt_trace_listener(&tr_out, &l);
        t0 = now();
        pt_run(&s, &p, &o, &l, NULL, &sum);
        pt_trace_finish(&tr_out);
        tj[k] = now() - t0;

        pt_trace_init(&tr_out, devnull, PT_FORMAT_TEXT, 6);    /* text */
        pt_trace_listener(&tr_out, &l);
        t0 = now();
        pt_run(&s, &p, &o, &l, NULL, &sum);
        pt_trace_finish(&tr_out);
        tt[k] = now() - t0;
        res.records = nrec + sum.pixels + sum.clip_runs + 2;

        pt_plan_free(&p);
        pt_scene_free(&s);
    }
    fclose(devnull);
    res.parse = median(tp); res.stages = median(ts); res.raster = median(tr);
    res.jsonl = median(tj); res.text = median(tt);
    printf("%-22s %9llu vertices %10llu pixels %10llu records\n", name,
           (unsigned long long)res.vertices, (unsigned long long)res.pixels,
           (unsigned long long)res.records);
    printf("  parse      %8.2f MB/s   (%.4f s)\n", (double)len / res.parse / 1e6, res.parse);
    printf("  stages     %8.2f M vertices/s\n", (double)res.vertices / res.stages / 1e6);
    printf("  rasterize  %8.2f M pixels/s\n", (double)res.pixels / res.raster / 1e6);
    printf("  jsonl      %8.2f M records/s   (%.4f s, whole run)\n",
           (double)res.records / res.jsonl / 1e6, res.jsonl);
    printf("  text       %8.2f M records/s   (%.4f s, whole run)\n",
           (double)res.records / res.text / 1e6, res.text);
}

int main(void)
{
    static const char far[] =
        "framebuffer 16384 16384\ncamera orthographic\nmodel far\n"
        "v -1e12 -0.9 0\nv 1e12 0.9 0\nv -0.9 -1e12 0\nv 0.9 1e12 0\nl 1 2\nl 3 4\n";
    size_t len;
    char *g;
    struct rusage ru;

    printf("pipetrace bench: median of %d runs; figures depend on the machine\n\n", RUNS);
    g = grid_scene(300, &len);
    bench("grid 300x300", g, len);
    free(g);
    g = grid_scene(600, &len);
    bench("grid 600x600", g, len);
    free(g);
    bench("2 lines of 1e12 px", far, sizeof far - 1);
    getrusage(RUSAGE_SELF, &ru);
    printf("\npeak resident memory: %ld MiB\n", ru.ru_maxrss / 1024);
    return 0;
}
