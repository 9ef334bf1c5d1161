/*
** tests/bench/baseline.c -- the plain-C yardstick of `make bench`: the same formulas, no trace
** See LICENSE for copyright and license.
**
** Usage: baseline SCENE [OUT.ppm].  What a programmer would write in an
** afternoon: fgets and strtod for the scene (framebuffer, viewport, camera
** perspective|orthographic, model, translate, color, v, l, f; nothing
** checked), the classic camera's formulas in a loop, floor(x + 0.5) for
** rounding, the DDA of src/core/raster.c without its fast-forward, and a
** uint32 framebuffer.  It prints "parse S render S pixels N": the least of 5
** parses, the least of 15 renders (the first touches the framebuffer's pages
** for the first time: the least is a warm one, as tests/bench/bench.c's are), and
** the pixels of one render; with OUT it
** writes the image too (binary PPM), so that the whole process can be timed.
** tests/bench/bench.c compares pipetrace with it.
*/
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct model {
    double tx, ty, tz;           /* translate */
    uint32_t color;              /* 0xRRGGBB */
    double *v;                   /* x y z per vertex */
    size_t nv, capv;
    uint32_t *seg;               /* a b per segment, 0-based */
    size_t nseg, capseg;
} model;

static model *models;
static size_t nmodels, capmodels;
static int W = 800, H = 600, vx, vy, vw = -1, vh = -1, perspective = 1;
static uint32_t *fb;
static double *pp;               /* pixel-plane points of the current model */

static double now(void)                 /* CPU time, as tests/bench/bench.c measures */
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void *grow(void *p, size_t *cap, size_t size)
{
    *cap = *cap ? 2 * *cap : 1024;
    p = realloc(p, *cap * size);
    if (!p) { fprintf(stderr, "baseline: out of memory\n"); exit(1); }
    return p;
}

static void add_seg(model *m, long a, long b)
{
    if (m->nseg == m->capseg) m->seg = grow(m->seg, &m->capseg, 2 * sizeof *m->seg);
    m->seg[2 * m->nseg] = (uint32_t)a;
    m->seg[2 * m->nseg + 1] = (uint32_t)b;
    m->nseg++;
}

/* l I J ... or f I J K ...: indices from 1, or negative from the end. */
static void polyline(model *m, char *p, int closed)
{
    long first = -1, prev = -1, k;
    char *e;

    for (;;) {
        k = strtol(p, &e, 10);
        if (e == p) break;
        p = e;
        k = k > 0 ? k - 1 : (long)m->nv + k;
        if (first < 0) first = k; else add_seg(m, prev, k);
        prev = k;
    }
    if (closed && first >= 0) add_seg(m, prev, first);
}

/* Forget the scene read so far. */
static void clear(void)
{
    size_t k;

    for (k = 0; k < nmodels; k++) { free(models[k].v); free(models[k].seg); }
    nmodels = 0;
    W = 800; H = 600; vx = vy = 0; vw = vh = -1; perspective = 1;
}

static void parse(FILE *f)
{
    char line[4096], *p, *e;
    model *m = NULL;

    while (fgets(line, sizeof line, f)) {
        if (line[0] == 'v' && line[1] == ' ') {
            if (m->nv == m->capv) m->v = grow(m->v, &m->capv, 3 * sizeof *m->v);
            p = line + 2;
            m->v[3 * m->nv] = strtod(p, &e);
            m->v[3 * m->nv + 1] = strtod(e, &e);
            m->v[3 * m->nv + 2] = strtod(e, &e);
            m->nv++;
        } else if ((line[0] == 'f' || line[0] == 'l') && line[1] == ' ') {
            polyline(m, line + 2, line[0] == 'f');
        } else if (strncmp(line, "model ", 6) == 0) {
            if (nmodels == capmodels) models = grow(models, &capmodels, sizeof *models);
            m = &models[nmodels++];
            memset(m, 0, sizeof *m);
            m->color = 0xffffff;
        } else if (strncmp(line, "translate ", 10) == 0) {
            m->tx = strtod(line + 10, &e);
            m->ty = strtod(e, &e);
            m->tz = strtod(e, &e);
        } else if (strncmp(line, "color ", 6) == 0) {
            long r = strtol(line + 6, &e, 10), g = strtol(e, &e, 10), b = strtol(e, &e, 10);
            m->color = (uint32_t)(r << 16 | g << 8 | b);
        } else if (strncmp(line, "framebuffer ", 12) == 0) {
            W = (int)strtol(line + 12, &e, 10);
            H = (int)strtol(e, &e, 10);
        } else if (strncmp(line, "viewport ", 9) == 0) {
            vx = (int)strtol(line + 9, &e, 10);
            vy = (int)strtol(e, &e, 10);
            vw = (int)strtol(e, &e, 10);
            vh = (int)strtol(e, &e, 10);
        } else if (strncmp(line, "camera orthographic", 19) == 0) {
            perspective = 0;
        }
    }
    if (vw < 0) { vx = vy = 0; vw = W; vh = H; }
}

/* The DDA: x from x0 to x1, y += m; transposed when |slope| > 1. */
static uint64_t segment(double x0, double y0, double x1, double y1, uint32_t color)
{
    uint64_t n = 0;
    int tr;
    double m, y, t;
    long s, s1;

    x0 = floor(x0 + 0.5); y0 = floor(y0 + 0.5);
    x1 = floor(x1 + 0.5); y1 = floor(y1 + 0.5);
    tr = fabs(y1 - y0) > fabs(x1 - x0);
    if (tr) { t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; }
    m = x1 == x0 ? 0 : (y1 - y0) / (x1 - x0);
    y = y0;
    for (s = (long)x0, s1 = (long)x1; s <= s1; s++, y += m) {
        long px = tr ? (long)floor(y + 0.5) : s, py = tr ? s : (long)floor(y + 0.5);
        long x_vp = px - 1, y_vp = vh - py;             /* the viewport stage */
        if (x_vp < 0 || x_vp >= vw || y_vp < 0 || y_vp >= vh) continue;
        fb[(long)(vy + y_vp) * W + (vx + x_vp)] = color;  /* framebuffer, index */
        n++;
    }
    return n;
}

static uint64_t render(void)
{
    uint64_t n = 0;
    size_t k, j;

    for (k = 0; k < nmodels; k++) {
        model *m = &models[k];
        pp = realloc(pp, (m->nv ? m->nv : 1) * 2 * sizeof *pp);
        for (j = 0; j < m->nv; j++) {
            double xc = m->v[3 * j] + m->tx, yc = m->v[3 * j + 1] + m->ty;
            double zc = m->v[3 * j + 2] + m->tz;
            double xip = perspective ? xc / -zc : xc, yip = perspective ? yc / -zc : yc;
            pp[2 * j] = 0.5 + vw / 2.001 * (xip + 1);
            pp[2 * j + 1] = 0.5 + vh / 2.001 * (yip + 1);
        }
        for (j = 0; j < m->nseg; j++) {
            uint32_t a = m->seg[2 * j], b = m->seg[2 * j + 1];
            n += segment(pp[2 * a], pp[2 * a + 1], pp[2 * b], pp[2 * b + 1], m->color);
        }
    }
    return n;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    double t0, tparse[5], t[15];
    uint64_t pixels = 0;
    FILE *f;
    int k, runs = argc > 2 ? 1 : 5;     /* with OUT: once, as a user would */
    int renders = argc > 2 ? 1 : 15;    /* as many as tests/bench/bench.c's RENDERS */

    for (k = 0; k < runs; k++) {
        if (argc < 2 || !(f = fopen(argv[1], "r"))) {
            fprintf(stderr, "usage: baseline SCENE [OUT.ppm]\n");
            return 1;
        }
        clear();
        t0 = now();
        parse(f);
        tparse[k] = now() - t0;
        fclose(f);
    }
    fb = calloc((size_t)W * H, sizeof *fb);
    for (k = 0; k < renders; k++) {
        t0 = now();
        pixels = render();
        t[k] = now() - t0;
    }
    if (argc > 2) {              /* the image: RGB bytes */
        unsigned char *rgb = malloc((size_t)W * H * 3);
        size_t i;
        f = fopen(argv[2], "wb");
        for (i = 0; i < (size_t)W * H; i++) {
            rgb[3 * i] = (unsigned char)(fb[i] >> 16);
            rgb[3 * i + 1] = (unsigned char)(fb[i] >> 8);
            rgb[3 * i + 2] = (unsigned char)fb[i];
        }
        if (!f || fprintf(f, "P6\n%d %d\n255\n", W, H) < 0
            || fwrite(rgb, 3, (size_t)W * H, f) != (size_t)W * H || fclose(f) != 0) {
            fprintf(stderr, "baseline: cannot write %s\n", argv[2]);
            return 1;
        }
        free(rgb);
        printf("parse %.6f render %.6f pixels %llu\n", tparse[0], t[0],
               (unsigned long long)pixels);
        return 0;
    }
    qsort(t, (size_t)renders, sizeof *t, by_value);
    qsort(tparse, 5, sizeof *tparse, by_value);
    printf("parse %.6f render %.6f pixels %llu\n", tparse[0], t[0], (unsigned long long)pixels);
    return 0;
}
