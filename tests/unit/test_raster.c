/*
** tests/unit/test_raster.c -- the DDA: pictures, symmetry, clipping, fast-forward
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "core/raster.h"
#include "core/pipeline.h"
#include "stages/s4_pixel2viewport.h"

/* ===== a collecting raster sink ===== */

#define MAXW 64
typedef struct canvas {
    int w, h;
    char cell[MAXW * MAXW];      /* '*' lit, '.' not */
    uint64_t pixels, clipped, runs;
    pt_pix first_clip, last_clip;
} canvas;

static void c_pixel(void *ud, int64_t x, int64_t y)
{
    canvas *c = ud;
    c->cell[y * c->w + x] = '*';
    c->pixels++;
}

static void c_clip(void *ud, uint64_t n, pt_pix first, pt_pix last)
{
    canvas *c = ud;
    if (c->runs == 0) c->first_clip = first;
    c->last_clip = last;
    c->clipped += n;
    c->runs++;
}

static void clear(canvas *c, int w, int h)
{
    memset(c, 0, sizeof *c);
    c->w = w; c->h = h;
    memset(c->cell, '.', sizeof c->cell);
}

static int draw(canvas *c, double x0, double y0, double x1, double y1)
{
    pt_raster_out out = {c_pixel, c_clip, NULL};
    out.ud = c;
    return pt_raster_segment((pt_vec2){x0, y0}, (pt_vec2){x1, y1}, c->w, c->h, pt_pixel2viewport, &out);
}

/* Compare the canvas with rows of '*' and '.', top row first. */
static int looks_like(const canvas *c, const char *rows)
{
    int x, y;
    for (y = 0; y < c->h; y++) {
        for (x = 0; x < c->w; x++)
            if (*rows++ != c->cell[y * c->w + x]) return 0;
        if (*rows++ != '\n') return 0;
    }
    return *rows == '\0';
}

/* ===== pictures ===== */

static void test_pictures(void)
{
    canvas c;

    /* An "F" in a 6x5 viewport; logical pixel (m, n) is cell (m-1, 5-n). */
    clear(&c, 6, 5);
    draw(&c, 2, 1, 2, 5);                   /* the stem */
    draw(&c, 2, 5, 5, 5);                   /* the top bar */
    draw(&c, 2, 3, 4, 3);                   /* the middle bar */
    PT_CHECK("raster-1.1 an F in a 6x5 viewport",
             looks_like(&c, ".****.\n"
                            ".*....\n"
                            ".***..\n"
                            ".*....\n"
                            ".*....\n"));
    clear(&c, 6, 5);
    draw(&c, 1.2, 1.4, 6.3, 3.6);           /* rounds to (1,1)-(6,4): slope 3/5 */
    PT_CHECK("raster-1.2 shallow line: y += 0.6 each step, rounded",
             looks_like(&c, "......\n"
                            ".....*\n"
                            "...**.\n"
                            ".**...\n"
                            "*.....\n"));
    clear(&c, 6, 5);
    draw(&c, 2, 1, 4, 5);                   /* steep: x += 0.5 per row, ties up */
    PT_CHECK("raster-1.3 steep line steps y, x ties at k+0.5 round up",
             looks_like(&c, "...*..\n"
                            "...*..\n"
                            "..*...\n"
                            "..*...\n"
                            ".*....\n"));
    PT_CHECK("raster-1.4 steep line lights one pixel per row", c.pixels == 5);
    clear(&c, 6, 5);
    PT_CHECK("raster-1.5 a segment that rounds to one point is one pixel",
             draw(&c, 3.4, 2.6, 2.6, 3.4) == PT_RASTER_DEGENERATE && c.pixels == 1 &&
             c.cell[2 * 6 + 2] == '*');
    clear(&c, 6, 5);
    PT_CHECK("raster-1.6 a degenerate segment outside is one clipped step",
             draw(&c, 9, 9, 9.2, 9.1) == PT_RASTER_DEGENERATE && c.pixels == 0 &&
             c.clipped == 1 && c.runs == 1);
}

/* ===== symmetry and clipping ===== */

static double rnd(double lo, double hi)
{
    return lo + (hi - lo) * (rand() / (RAND_MAX + 1.0));
}

static void test_symmetry(void)
{
    canvas a, b;
    int k, same = 1, counted = 1;

    srand(7);
    for (k = 0; k < 2000; k++) {
        double x0 = rnd(-20, 60), y0 = rnd(-20, 60), x1 = rnd(-20, 60), y1 = rnd(-20, 60);
        clear(&a, 40, 30);
        clear(&b, 40, 30);
        draw(&a, x0, y0, x1, y1);
        draw(&b, x1, y1, x0, y0);
        if (memcmp(a.cell, b.cell, sizeof a.cell) != 0) same = 0;
        {
            double dx = fabs(pt_java_round(x1) - pt_java_round(x0));
            double dy = fabs(pt_java_round(y1) - pt_java_round(y0));
            if (a.pixels + a.clipped != (uint64_t)(dx > dy ? dx : dy) + 1) counted = 0;
        }
    }
    PT_CHECK("raster-2.1 (a,b) and (b,a) light the same pixels (2000 random)", same);
    PT_CHECK("raster-2.2 pixels + clipped steps = max(|dx|,|dy|) + 1", counted);

    clear(&a, 10, 10);
    draw(&a, -4, 5, 14, 5);                 /* x = -4..14, inside for x = 1..10 */
    PT_CHECK("raster-2.3 horizontal line through: 10 pixels, 9 clipped in 2 runs",
             a.pixels == 10 && a.clipped == 9 && a.runs == 2);
    PT_CHECK("raster-2.4 clip runs report viewport coordinates",
             a.first_clip.x == -5 && a.first_clip.y == 5 && a.last_clip.x == 13);
    clear(&a, 10, 10);
    PT_CHECK("raster-2.5 a non-finite endpoint is skipped, nothing reported",
             draw(&a, (double)NAN, 1, 3, 3) == PT_RASTER_SKIPPED && a.pixels == 0 && a.runs == 0);
    PT_CHECK("raster-2.6 an endpoint at 1e300 is skipped",
             draw(&a, 1, 1, 1e300, 3) == PT_RASTER_SKIPPED);
}

/* ===== exact fast-forward ===== */

static double naive_advance(double y, double m, uint64_t k)
{
    while (k--) y += m;
    return y;
}

static void test_advance(void)
{
    static const double ms[] = {0.6, -0.6, 1.0 / 3, -2.0 / 7, 0.5, 1.5, 1e-9, 3e-17,
                                0.999999999, -1.0, 0.0, 0.1, 2.5, -0.75};
    static const double ys[] = {0, 1, -1, 0.5, 1234.5, -99.25, 4503599627370496.0,
                                9007199254740992.0, -9007199254740990.0, 1e15, 3.3};
    size_t i, j;
    int ok = 1;

    for (i = 0; i < sizeof ms / sizeof ms[0]; i++)
        for (j = 0; j < sizeof ys / sizeof ys[0]; j++) {
            uint64_t k;
            for (k = 0; k < 300000; k = k * 3 + 1) {
                double a = pt_raster_advance(ys[j], ms[i], k), b = naive_advance(ys[j], ms[i], k);
                if (a != b) {
                    if (ok) printf("  advance(%.17g, %.17g, %llu): %.17g != %.17g\n",
                                   ys[j], ms[i], (unsigned long long)k, a, b);
                    ok = 0;
                }
            }
        }
    PT_CHECK("raster-3.1 fast-forward equals k additions, ties and binade edges included", ok);

    ok = 1;
    srand(11);
    for (i = 0; i < 300; i++) {
        double y = rnd(-1e6, 1e6), m = rnd(-3, 3);
        uint64_t k = (uint64_t)rnd(0, 200000);
        if (i % 3 == 0) m = ldexp(floor(rnd(-64, 64)) + 0.5, -(int)rnd(0, 40));
        if (pt_raster_advance(y, m, k) != naive_advance(y, m, k)) ok = 0;
    }
    PT_CHECK("raster-3.2 fast-forward equals k additions (300 random, some ties)", ok);

    /* 2026-11-22: m = 0 at y = 0 (a vertical line along the viewport's edge)
    ** stepped one at a time: 10^13 steps hung (found with a scene like
    ** tests/extreme/edge-line-1e13.scene). */
    PT_CHECK("raster-3.3 m = 0: 10^15 steps at once; -0 becomes +0",
             pt_raster_advance(0.0, 0.0, 1000000000000000ULL) == 0 &&
             !signbit(pt_raster_advance(-0.0, 0.0, 5)) && signbit(pt_raster_advance(-0.0, 0.0, 0)));
    PT_CHECK("raster-3.4 subnormal steps from 0 jump too (10^12 steps of 1e-310 would overflow into normals)",
             pt_raster_advance(0.0, 4.9e-324, 1000000000000ULL) == 1000000000000.0 * 4.9e-324);
    ok = 1;
    {
        static const double tiny[] = {4.9e-324, 1e-310, -3e-315, 2.2250738585072014e-308, 1e-300};
        size_t a;
        for (a = 0; a < sizeof tiny / sizeof tiny[0]; a++) {
            uint64_t kk;
            for (kk = 0; kk < 200000; kk = kk * 3 + 1)
                if (pt_raster_advance(0.0, tiny[a], kk) != naive_advance(0.0, tiny[a], kk) ||
                    pt_raster_advance(-1e-305, tiny[a], kk) != naive_advance(-1e-305, tiny[a], kk))
                    ok = 0;
        }
    }
    PT_CHECK("raster-3.5 near zero and among subnormals: equals k additions", ok);

    /* 2026-11-28: a jump that lands on the binade's lower edge exactly (y
    ** moving inward, |m| a little above |d|): the next real step rounds on
    ** the finer grid below it.  The jump's margin keeps it short of the edge;
    ** without one (make mutate, tests/mutate/) the sum ends an ulp off. */
    {
        double m = -(0x1p-10 + 3 * 0x1p-55);
        uint64_t kk;
        ok = 1;
        for (kk = 508; kk < 520; kk++)
            if (pt_raster_advance(1.5, m, kk) != naive_advance(1.5, m, kk)) ok = 0;
        PT_CHECK("raster-3.6 a jump onto the binade's lower edge: equals k additions", ok);
    }
}

/* A student's viewport stage that moves each pixel 30 to the left: a
** viewport 40 x 10 gets the steps 31 .. 70. */
static pt_pix shift30(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    pt_pix p = pt_pixel2viewport(pp, w, h, sink);
    p.x -= 30;
    return p;
}

/* The band of steps the viewport stage is asked about reaches max(w, h)
** beyond the viewport on each side (docs/teaching.md): a stage that moves
** pixels by less still has all its pixels drawn, as the plain walk does. */
static void test_band(void)
{
    pt_raster_out out = {c_pixel, c_clip, NULL};
    canvas *c = malloc(sizeof *c);

    if (!c) return;
    clear(c, 40, 10);
    out.ud = c;
    pt_raster_segment((pt_vec2){1.0, 5.0}, (pt_vec2){70.0, 5.0}, 40, 10, shift30, &out);
    PT_CHECK("raster-6.1 a stage moving pixels by 30 (between min and max of 40 x 10): "
             "the 40 pixels of steps 31 .. 70 drawn", c->pixels == 40 && c->clipped == 30);
    clear(c, 10, 40);
    out.ud = c;
    pt_raster_segment((pt_vec2){1.0, 5.0}, (pt_vec2){70.0, 5.0}, 10, 40, shift30, &out);
    PT_CHECK("raster-6.2 ... in a viewport 10 x 40: steps 31 .. 40, 10 pixels",
             c->pixels == 10 && c->clipped == 60);
    free(c);
}

/* A long segment drawn both ways: the rasterizer (which skips) and a plain
** step-by-step loop written here from the rule in raster.h. */
static void test_long_segment(void)
{
    canvas a, b;
    double x0 = -30000000.3, y0 = -11100009.25, x1 = 70000000.2, y1 = 25900010.75;
    double rx0 = pt_java_round(x0), ry0 = pt_java_round(y0);
    double rx1 = pt_java_round(x1), ry1 = pt_java_round(y1);
    double m = (ry1 - ry0) / (rx1 - rx0), y = ry0;
    int64_t x;

    clear(&a, 50, 40);
    draw(&a, x0, y0, x1, y1);
    clear(&b, 50, 40);
    for (x = (int64_t)rx0; x <= (int64_t)rx1; x++, y += m) {
        int64_t x_vp = x - 1, y_vp = 40 - (int64_t)pt_java_round(y);
        if (x_vp >= 0 && x_vp < 50 && y_vp >= 0 && y_vp < 40) c_pixel(&b, x_vp, y_vp);
        else b.clipped++;
    }
    PT_CHECK("raster-4.1 10^8-step segment: same pixels as the plain loop",
             memcmp(a.cell, b.cell, sizeof a.cell) == 0 && a.pixels == b.pixels);
    PT_CHECK("raster-4.2 10^8-step segment: same clipped count", a.clipped == b.clipped);
    PT_CHECK("raster-4.3 the segment does cross the viewport", a.pixels > 0);
}

/* ===== whole scenes: drawn in turn or after every vertex ===== */

static void no_record(void *ud, const pt_vrec *r) { (void)ud; (void)r; }
static void no_summary(void *ud, const pt_summary *sum) { (void)ud; (void)sum; }
static void no_pixel(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                     size_t n)
{
    (void)ud; (void)m; (void)seg; (void)px; (void)n;
}

/* Run scene s with listener l into a fresh framebuffer; 0 when it ran. */
static int run_into(const pt_scene *s, const pt_listener *l, pt_fb *fb, pt_summary *sum)
{
    pt_options o;
    pt_plan p;
    int rc;

    pt_options_default(&o);
    if (pt_plan_make(&p, s, &o) != 0) return -1;
    if (pt_fb_init(fb, s->fb_w, s->fb_h, s->background) != 0) { pt_plan_free(&p); return -1; }
    rc = pt_run(s, &p, &o, l, fb, sum);
    pt_plan_free(&p);
    return rc;
}

/* pt_run draws each model right after its vertices when nobody listens to
** the vertices (in turn), else after all of them: the same image and summary,
** drawn by pt_raster_draw with and without a pixel listener (the classic
** camera) or pt_raster_segment (the matrix camera). */
static void test_in_turn(void)
{
    static const char *const scenes[] = {
        "docs/examples/builtin.scene", "docs/examples/two-models.scene",
        "docs/examples/clip.scene", "docs/examples/behind.scene",
        "docs/examples/lookat-cube.scene", "docs/examples/lookat-near.scene",
        "docs/examples/lookat-world.scene", "docs/examples/ortho.scene",
        "docs/examples/selfcheck.scene", "docs/examples/compare-matrix.scene"};
    int k, loaded = 1, same_image = 1, same_sum = 1, drew = 1;

    for (k = 0; k < (int)(sizeof scenes / sizeof *scenes); k++) {
        pt_listener l[3];
        pt_summary sum[3];
        pt_fb fb[3];
        pt_scene s;
        char err[PT_ERRLEN];
        int i;

        if (pt_scene_load(&s, scenes[k], err, sizeof err) != 0) { loaded = 0; continue; }
        memset(l, 0, sizeof l);
        for (i = 0; i < 3; i++) l[i].summary = no_summary;  /* warnings counted */
        l[1].sink.vertex = no_record;                        /* vertices first */
        l[2].sink.vertex = no_record;
        l[2].pixels = no_pixel;                              /* a pixel listener */
        for (i = 0; i < 3; i++) {
            if (run_into(&s, &l[i], &fb[i], &sum[i]) != 0) { loaded = 0; break; }
            if (i == 0) continue;
            if (memcmp(fb[0].rgb, fb[i].rgb, 3 * (size_t)s.fb_w * s.fb_h) != 0)
                same_image = 0;
            if (memcmp(&sum[0], &sum[i], sizeof sum[0]) != 0) same_sum = 0;
        }
        if (i == 3 && sum[0].pixels == 0) drew = 0;
        while (i-- > 0) pt_fb_free(&fb[i]);
        pt_scene_free(&s);
    }
    PT_CHECK("raster-5.1 the example scenes load and run", loaded);
    PT_CHECK("raster-5.2 each draws pixels", drew);
    PT_CHECK("raster-5.3 drawn in turn or after every vertex: the same image", same_image);
    PT_CHECK("raster-5.4 ... and the same summary", same_sum);
}

/* ===== pixel records carry the colour written and the coverage ===== */

/* What a pixel listener saw against the image: every record's colour is the
** framebuffer's at its index (the last segment to write a pixel wins, and the
** records come in drawing order), with coverage 1. */
typedef struct px_check {
    const pt_fb *fb;             /* the image drawn so far, filled after */
    unsigned char *seen;         /* 3 bytes a pixel: the last record's colour */
    uint64_t n, full;            /* records, and those with coverage 1 */
} px_check;

static void px_record(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                      size_t n)
{
    px_check *c = ud;
    size_t k;

    (void)seg;
    for (k = 0; k < n; k++) {
        c->n++;
        c->full += px[k].paint.coverage == 1.0f;
        if (memcmp(px[k].paint.rgb, m->color, 3) != 0) c->full = 0;   /* not its model's */
        if (px[k].idx >= 0 && px[k].idx < (int64_t)c->fb->w * c->fb->h)
            memcpy(c->seen + 3 * px[k].idx, px[k].paint.rgb, 3);
    }
}

static void test_pixel_colours(void)
{
    static const char *const scenes[] = {
        "docs/examples/two-models.scene", "docs/examples/lookat-cube.scene"};
    int k, ok = 1, all_full = 1, same = 1;

    for (k = 0; k < 2; k++) {
        pt_listener l;
        pt_summary sum;
        pt_fb fb;
        pt_scene s;
        px_check c;
        char err[PT_ERRLEN];
        size_t i, npix;

        if (pt_scene_load(&s, scenes[k], err, sizeof err) != 0) { ok = 0; continue; }
        npix = (size_t)s.fb_w * s.fb_h;
        memset(&l, 0, sizeof l);
        memset(&c, 0, sizeof c);
        c.fb = &fb;
        c.seen = malloc(3 * npix);
        l.pixels = px_record;
        l.ud = &c;
        if (!c.seen) { ok = 0; pt_scene_free(&s); continue; }
        fb.w = s.fb_w; fb.h = s.fb_h;
        for (i = 0; i < npix; i++) memcpy(c.seen + 3 * i, s.background, 3);
        if (run_into(&s, &l, &fb, &sum) != 0) ok = 0;
        else {
            if (c.n == 0 || c.full != c.n) all_full = 0;
            if (memcmp(c.seen, fb.rgb, 3 * npix) != 0) same = 0;
            pt_fb_free(&fb);
        }
        free(c.seen);
        pt_scene_free(&s);
    }
    PT_CHECK("raster-6.1 the scenes run with a pixel listener", ok);
    PT_CHECK("raster-6.2 every pixel record has its model's colour and coverage 1", all_full);
    PT_CHECK("raster-6.3 the records' colours, written in order, are the image", same);
}

static void test_blend(void)
{
    static const unsigned char bg[3] = {10, 20, 200}, red[3] = {255, 0, 0};
    pt_fb fb;
    int ok = pt_fb_init(&fb, 2, 1, bg) == 0;

    if (!ok) { PT_CHECK("raster-7.0 a 2x1 framebuffer", 0); return; }
    pt_fb_blend(&fb, 0, red, 1.0f);
    PT_CHECK("raster-7.1 blend with coverage 1 writes the colour",
             fb.rgb[0] == 255 && fb.rgb[1] == 0 && fb.rgb[2] == 0);
    pt_fb_blend(&fb, 1, red, 0.0f);
    PT_CHECK("raster-7.2 ... with coverage 0 leaves the pixel",
             fb.rgb[3] == 10 && fb.rgb[4] == 20 && fb.rgb[5] == 200);
    pt_fb_blend(&fb, 1, red, 0.25f);
    /* 0.25 * 255 + 0.75 * 10 = 71.25 -> 71; 0.75 * 20 = 15; 0.75 * 200 = 150 */
    PT_CHECK("raster-7.3 ... with coverage 0.25, a quarter of the way, rounded",
             fb.rgb[3] == 71 && fb.rgb[4] == 15 && fb.rgb[5] == 150);
    pt_fb_free(&fb);
}

/* ===== the DDA's records (pt_raster_walk) ===== */

/* A canvas that also collects the step records. */
typedef struct stepped {
    canvas c;                    /* the pixels and clip records */
    pt_raster_setup su;          /* the last setup */
    int setups;
    uint64_t steps, inside, outside;
    int in_order;                /* 1: every step's s is the one before's + 1 */
    int pixels_match;            /* 1: every inside step's pixel is lit after it */
    int64_t last_s;
    double last_a;
    int sane;                    /* 1: accumulated a = a0 + m + ... as stepped */
    pt_pix px[4096];             /* the inside steps' pixels, in order */
    float color[3];              /* the last step's colour */
} stepped;

/* 1: the first n of a and b are the same pixels (field by field: a pt_pix
** has padding, which memcmp would compare too). */
static int same_pixels(const pt_pix *a, const pt_pix *b, uint64_t n)
{
    uint64_t i;
    for (i = 0; i < n && i < 4096; i++)
        if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].ok != b[i].ok) return 0;
    return 1;
}

static void s_setup(void *ud, const pt_raster_setup *su)
{
    stepped *t = ud;
    t->su = *su;
    t->setups++;
    t->last_s = su->s0 - 1;
    t->last_a = su->a0 - su->m;
}

static void s_step(void *ud, const pt_raster_step *st)
{
    stepped *t = ud;
    if (st->s != t->last_s + 1) t->in_order = 0;
    if (t->steps > 0 && st->a != t->last_a + t->su.m) t->sane = 0;
    if (t->steps == 0 && st->a != t->su.a0) t->sane = 0;
    t->last_s = st->s;
    t->last_a = st->a;
    if (st->inside) {
        if (t->inside < 4096) t->px[t->inside] = st->vp;
        t->inside++;
    } else {
        t->outside++;
    }
    memcpy(t->color, st->color, sizeof t->color);
    t->steps++;
}

static int walk_into(stepped *t, int w, int h, double x0, double y0, double x1, double y1,
                     const float c0[3], const float c1[3])
{
    pt_raster_out out = {c_pixel, c_clip, NULL};
    pt_raster_steps ls;
    int i;

    memset(t, 0, sizeof *t);
    clear(&t->c, w, h);
    t->in_order = t->sane = 1;
    out.ud = &t->c;
    ls.setup = s_setup;
    ls.step = s_step;
    ls.ud = t;
    memset(&ls.col, 0, sizeof ls.col);
    ls.paint = NULL;
    ls.col.gamma = 1;
    for (i = 0; i < 3; i++) { ls.col.c0[i] = c0[i]; ls.col.c1[i] = c1[i]; }
    return pt_raster_walk((pt_vec2){x0, y0}, (pt_vec2){x1, y1}, w, h, pt_pixel2viewport,
                          &out, &ls);
}

static void test_steps(void)
{
    static const float black[3] = {0, 0, 0}, white[3] = {1, 1, 1};
    static const float grey[3] = {0.5f, 0.5f, 0.5f};
    stepped *t = malloc(sizeof *t), *u = malloc(sizeof *u);
    canvas c;
    int r, k, same;

    if (!t || !u) { PT_CHECK("steps-0 memory", 0); free(t); free(u); return; }
    /* a segment inside: every step lit, the same pixels as pt_raster_segment */
    r = walk_into(t, 8, 6, 1.2, 1.4, 7.6, 4.4, black, black);
    clear(&c, 8, 6);
    draw(&c, 1.2, 1.4, 7.6, 4.4);
    PT_CHECK("steps-1.1 drawn, one setup", r == PT_RASTER_DRAWN && t->setups == 1);
    PT_CHECK("steps-1.2 setup: rounded ends, x-major, not swapped",
             t->su.x0 == 1 && t->su.y0 == 1 && t->su.x1 == 8 && t->su.y1 == 4 &&
             !t->su.ymajor && !t->su.swapped && t->su.s0 == 1 && t->su.s1 == 8);
    PT_CHECK("steps-1.3 slope m = 3/7", t->su.m == 3.0 / 7.0);
    PT_CHECK("steps-1.4 a step for each s, in order, a accumulated",
             t->steps == 8 && t->in_order && t->sane);
    PT_CHECK("steps-1.5 the steps' pixels are the pixels drawn",
             t->inside == t->c.pixels && memcmp(t->c.cell, c.cell, sizeof c.cell) == 0);
    same = 1;
    for (k = 0; k < (int)t->inside && k < 4096; k++)
        if (t->c.cell[t->px[k].y * 8 + t->px[k].x] != '*') same = 0;
    PT_CHECK("steps-1.6 ... each inside step's pixel is lit", same);

    /* far outside: the plain walk, every clipped step told, counted as the
    ** clip records count them */
    r = walk_into(t, 5, 5, -300.2, 2.0, 400.4, 3.0, black, black);
    PT_CHECK("steps-2.1 a long segment: every step told",
             r == PT_RASTER_DRAWN && t->steps == 701 && t->in_order && t->sane);
    PT_CHECK("steps-2.2 clipped steps = clip records' count", t->outside == t->c.clipped);
    PT_CHECK("steps-2.3 inside steps = pixels", t->inside == t->c.pixels && t->inside == 5);
    clear(&c, 5, 5);
    draw(&c, -300.2, 2.0, 400.4, 3.0);
    PT_CHECK("steps-2.4 the same pixels and clip records as the fast-forward",
             memcmp(c.cell, t->c.cell, sizeof c.cell) == 0 && c.clipped == t->c.clipped &&
             c.runs == t->c.runs);

    /* endpoint symmetry: (a, b) and (b, a) step alike, swapped once */
    walk_into(t, 9, 9, 2.0, 8.4, 5.2, 1.1, black, white);
    walk_into(u, 9, 9, 5.2, 1.1, 2.0, 8.4, white, black);
    PT_CHECK("steps-3.1 y-major, one of the two swapped",
             t->su.ymajor && u->su.ymajor && t->su.swapped != u->su.swapped);
    PT_CHECK("steps-3.2 the same steps, pixels and colours",
             t->steps == u->steps && t->inside == u->inside &&
             same_pixels(t->px, u->px, t->inside) &&
             memcmp(t->c.cell, u->c.cell, sizeof t->c.cell) == 0 &&
             memcmp(t->color, u->color, sizeof t->color) == 0);
    PT_CHECK("steps-3.3 colours in stepping order, slope over the steps",
             t->su.c0[0] == 1.0f && t->su.c1[0] == 0.0f && t->su.dc[0] == -1.0 / 7.0);
    PT_CHECK("steps-3.4 the last step's colour: c1, gamma-encoded (0^(1/2.2) = 0)",
             t->color[0] == 0.0f);

    /* one pixel: degenerate, its colour c0 without gamma */
    r = walk_into(t, 4, 4, 2.3, 2.2, 1.7, 1.9, grey, white);
    PT_CHECK("steps-4.1 degenerate: one setup, one step",
             r == PT_RASTER_DEGENERATE && t->setups == 1 &&
             t->su.kind == PT_RASTER_DEGENERATE && t->steps == 1 && t->inside == 1);
    PT_CHECK("steps-4.2 ... in c0, raw", t->color[0] == 0.5f);
    r = walk_into(t, 4, 4, 2.0, 1.0, 3.0, 1.0, grey, grey);
    PT_CHECK("steps-4.3 two steps, each gamma-encoded: (float)pow(0.5, 1/2.2)",
             r == PT_RASTER_DRAWN && t->steps == 2 &&
             t->color[0] == (float)pow(0.5, 1 / 2.2));

    /* skipped: a setup that says so, no step */
    r = walk_into(t, 4, 4, (double)NAN, 1.0, 3.0, 1.0, grey, grey);
    PT_CHECK("steps-5.1 skipped: one setup, kind skipped, no step",
             r == PT_RASTER_SKIPPED && t->setups == 1 && t->su.kind == PT_RASTER_SKIPPED &&
             t->steps == 0);
    free(t);
    free(u);
}

/* ===== the course's colours (renderer 4): bytes, and one image either way ===== */

/* An image the walked DDA paints (pt_raster_walk with a paint callback). */
typedef struct painted {
    pt_fb fb;
    uint64_t n;
} painted;

static void p_paint(void *ud, int64_t x, int64_t y, const pt_fb_paint *pa)
{
    painted *pt = ud;
    pt_fb_set(&pt->fb, y * pt->fb.w + x, pa->rgb);
    pt->n++;
}

static void p_pixel(void *ud, int64_t x, int64_t y)
{
    (void)ud; (void)x; (void)y;
}

static void p_clip(void *ud, uint64_t n, pt_pix first, pt_pix last)
{
    (void)ud; (void)n; (void)first; (void)last;
}

static void test_course_colors(void)
{
    static const unsigned char black[3] = {0, 0, 0};
    int b, ok = 1, k, same = 1, pairs = 1;
    unsigned seed = 12345;

    for (b = 0; b < 256; b++) ok &= pt_color_byte(pt_color_float((unsigned char)b)) == b;
    PT_CHECK("course-1.1 an int colour's byte comes back through c / 255f", ok);
    /* NOTES.md 9.4: the midpoint of 128 and 129 rounds up only in float */
    PT_CHECK("course-1.2 0.50392157f is 129 (widened first: 128)", pt_color_byte(0.50392157f) == 129);
    PT_CHECK("course-1.3 NaN is 0, as Java's (int)", pt_color_byte(nanf("")) == 0);
    PT_CHECK("course-1.4 1.0f is 255", pt_color_byte(1.0f) == 255);
    {
        float lo, hi;
        pt_aa_blend(0.5f, 1.0f, 0.25f, &lo, &hi);
        PT_CHECK("course-1.5 anti-aliasing shares: low (1-w)c + w bg, hi w c + (1-w) bg",
                 lo == 0.75f * 0.5f + 0.25f && hi == 0.25f * 0.5f + 0.75f);
        PT_CHECK("course-1.6 the weight is the fraction, in float",
                 pt_aa_weight(3.25, 3.0) == 0.25f);
    }
    /* The inlined DDA (pt_raster_draw) and the walked one (pt_raster_walk)
    ** paint the same image, for segments of one colour and of two, with and
    ** without gamma and anti-aliasing, inside the viewport and across it. */
    for (k = 0; k < 400; k++) {
        pt_fb a, bb;
        pt_raster_image im;
        pt_raster_steps ls;
        pt_raster_out out = {p_pixel, p_clip, NULL};
        painted pt;
        pt_vec2 p0, p1;
        int i;

        pt_fb_init(&a, 30, 20, black);
        pt_fb_init(&bb, 30, 20, black);
        memset(&im, 0, sizeof im);
        memset(&ls, 0, sizeof ls);
        im.fb = &a; im.W = 30; im.H = 20; im.x_ul = 0; im.y_ul = 0;
        im.col.gamma = k & 1;
        im.col.aa = (k >> 1) & 1;
        for (i = 0; i < 3; i++) {
            seed = seed * 1103515245u + 12345u;
            im.col.c0[i] = pt_color_float((unsigned char)(seed >> 16));
            im.col.c1[i] = (k >> 2) & 1 ? im.col.c0[i] : pt_color_float((unsigned char)(seed >> 8));
            im.col.bg[i] = pt_color_float((unsigned char)(40 * i));
        }
        seed = seed * 1103515245u + 12345u;
        p0.x = (double)(seed >> 16 & 63) - 16.0; p0.y = (double)(seed >> 8 & 31) - 6.0;
        seed = seed * 1103515245u + 12345u;
        p1.x = (double)(seed >> 16 & 63) - 16.0 + 0.3; p1.y = (double)(seed >> 8 & 31) - 6.0;
        pt_raster_draw(p0, p1, 30, 20, &im, &out);
        ls.col = im.col;
        ls.paint = p_paint;
        pt.fb = bb; pt.n = 0;
        ls.ud = &pt;
        pt_raster_walk(p0, p1, 30, 20, pt_pixel2viewport, &out, &ls);
        same &= memcmp(a.rgb, bb.rgb, 3 * 30 * 20) == 0;
        pairs &= pt.n == im.pixels;
        pt_fb_free(&a);
        pt_fb_free(&bb);
    }
    PT_CHECK("course-2.1 pt_raster_draw and pt_raster_walk paint the same images", same);
    PT_CHECK("course-2.2 ... the same number of pixels", pairs);
}

/* ===== a viewport that sticks out of the framebuffer ===== */

/* The course's FrameBuffer.setPixelFB(x, y): pixel_buffer[y*W + x], kept
** when that index lies in the array (written out here, in Java's terms, to
** tie pt_raster_fb_pixel's wrapping and pt_fb_fill to it). */
static int64_t java_index(int64_t x, int64_t y, int W, int H)
{
    int64_t i = y * W + x;
    return i >= 0 && i < (int64_t)W * H ? i : -1;
}

static void test_sticking_out(void)
{
    static const unsigned char bg[3] = {0, 0, 0}, red[3] = {200, 10, 20};
    int W, H, x_ul, y_ul, ok_wrap = 1, ok_plain = 1, ok_fill = 1, ok_draw = 1, n = 0;
    unsigned seed = 7;

    for (W = 1; W <= 6; W++)
        for (H = 1; H <= 5; H++)
            for (x_ul = -9; x_ul <= 9; x_ul += 3)
                for (y_ul = -7; y_ul <= 7; y_ul += 2) {
                    int64_t x_vp, y_vp;
                    for (y_vp = -2; y_vp < 10; y_vp++)
                        for (x_vp = -2; x_vp < 14; x_vp++) {
                            pt_fb_pixel px;
                            int64_t x = x_ul + x_vp, y = y_ul + y_vp;
                            int64_t i = pt_raster_fb_pixel(x_vp, y_vp, x_ul, y_ul, W, H, 1, &px);
                            ok_wrap &= i == java_index(x, y, W, H) && px.idx == i &&
                                       px.x_fb == x && px.y_fb == y;
                            i = pt_raster_fb_pixel(x_vp, y_vp, x_ul, y_ul, W, H, 0, &px);
                            ok_plain &= i == (x >= 0 && x < W && y >= 0 && y < H ? y * W + x : -1);
                            n++;
                        }
                    {   /* clearVP of a w x h viewport: pixel by pixel, Java's way */
                        int w = 1 + (int)((seed = seed * 1103515245u + 12345u) >> 16) % 9;
                        int h = 1 + (int)((seed = seed * 1103515245u + 12345u) >> 16) % 7;
                        unsigned char want[3 * 30];
                        pt_fb fb;
                        int64_t i, j, k;
                        if (pt_fb_init(&fb, W, H, bg) != 0) { ok_fill = 0; continue; }
                        memset(want, 0, sizeof want);
                        for (j = 0; j < h; j++)
                            for (i = 0; i < w; i++)
                                if ((k = java_index(x_ul + i, y_ul + j, W, H)) >= 0)
                                    memcpy(want + 3 * k, red, 3);
                        pt_fb_fill(&fb, x_ul, y_ul, w, h, red);
                        ok_fill &= memcmp(fb.rgb, want, 3 * (size_t)W * H) == 0;
                        pt_fb_free(&fb);
                    }
                }
    PT_CHECK("raster-8.1 a viewport sticking out: each pixel at the course's index "
             "y_fb*W + x_fb (rows wrap), -1 outside the array", ok_wrap && n > 10000);
    PT_CHECK("raster-8.2 ... not wrapped for a viewport inside: -1 outside the framebuffer",
             ok_plain);
    PT_CHECK("raster-8.3 the viewport's clearing writes what clearVP writes", ok_fill);

    /* the inlined DDA with wrap draws where the index puts each pixel */
    for (W = 3; W <= 9; W += 3) {
        pt_fb fb;
        pt_raster_image im;
        pt_raster_out out = {c_pixel, c_clip, NULL};
        canvas cv;
        unsigned char want[3 * 81];
        pt_vec2 a = {0.6, 0.6}, b = {12.4, 7.2};        /* a 12 x 8 viewport, corner to corner */
        int64_t s;
        if (pt_fb_init(&fb, W, W, bg) != 0) { ok_draw = 0; continue; }
        memset(&im, 0, sizeof im);
        memset(&cv, 0, sizeof cv);
        cv.w = 12; cv.h = 8;
        out.ud = &cv;
        pt_raster_segment(a, b, 12, 8, pt_pixel2viewport, &out);   /* the viewport pixels */
        im.fb = &fb; im.W = W; im.H = W; im.x_ul = -2; im.y_ul = -1; im.wrap = 1;
        im.col.c0[0] = im.col.c1[0] = 200.0f / 255.0f;
        im.col.c0[1] = im.col.c1[1] = 10.0f / 255.0f;
        im.col.c0[2] = im.col.c1[2] = 20.0f / 255.0f;
        pt_raster_colors_prepare(&im.col);
        pt_raster_draw(a, b, 12, 8, &im, &out);
        memset(want, 0, sizeof want);
        for (s = 0; s < 12 * 8; s++) {
            int64_t k;
            if (cv.cell[s] != '*') continue;
            if ((k = java_index(-2 + s % 12, -1 + s / 12, W, W)) >= 0)
                memcpy(want + 3 * k, im.col.rgb, 3);
        }
        ok_draw &= memcmp(fb.rgb, want, 3 * (size_t)W * W) == 0 && im.pixels > 0;
        pt_fb_free(&fb);
    }
    PT_CHECK("raster-8.4 pt_raster_draw with wrap: the pixels where the course's index puts them",
             ok_draw);
}

int main(void)
{
    test_pictures();
    test_symmetry();
    test_advance();
    test_band();
    test_long_segment();
    test_in_turn();
    test_pixel_colours();
    test_blend();
    test_steps();
    test_course_colors();
    test_sticking_out();
    return pt_test_report();
}
