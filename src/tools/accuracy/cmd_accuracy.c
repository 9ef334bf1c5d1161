/*
** src/tools/accuracy/cmd_accuracy.c -- pipetrace accuracy: each stage's error against its run time
** See LICENSE for copyright and license.
**
**   pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]
**
** Runs the scene's whole pipeline in float, double and double-double (the
** reference; src/tools/accuracy/accuracy.h says what it computes) and prints: the errors of
** each stage and of the rasterizer against the reference; per arithmetic its
** bits, headline errors and run time per vertex and per pixel; each stage's
** time alone; and two algorithm choices, 2.001 against 2.0 and the DDA's
** y += m against y = y0 + m*(x - x0).  --svg draws the error of every stage
** against the time of that stage, log-log, one panel per unit of error.
** Either camera: the rows are the scene's camera's stages (the layout
** below); the matrix camera has no 2.001, so that choice is only said not to
** apply.
**
** A block at a time: the scene goes by in blocks (pt_acc_block:
** PT_ACC_BLOCK used vertices, then segments, model by model); the
** reference makes each block once, and every run makes the same block beside
** it, is compared with it, timed and freed before the next run's; a run that
** differs from another only in the DDA (y recomputed) draws that run's block
** again.  The errors add up in the order a whole-scene run adds them, so the
** output is byte for byte what pt_acc_compare() of whole runs gives.
**
** Timing, per stage: a pass runs one stage's function (the one the error
** runs' journeys call) on the block's used vertices' inputs, prepared from
** the block run's journeys (pt_acc_work; matrix camera, ndc .. index: the
** vertices inside the view volume); the rasterizer's pass draws the block's
** segments (matrix camera: clipping included).  Passes are batched so that
** one clock reading spans at least the block's share of BATCH_SECONDS, and
** batches repeat until they took its share of MIN_SECONDS; the seconds and
** the items are summed over the blocks, which is one measurement, and the
** median of --repeat of them is shown.  Without --no-time the time columns
** and the time table vary from run to run, everything else never.
**
** Memory: the reference's block and one run's at a time; the used flags (a
** byte a vertex); the runs' images in one table (pt_acc_image): each pixel
** lit by any run once (overdraw costs nothing), with each run's colour; at
** most PT_ACC_MAXPIX pixels a run.  The environment variable
** PIPETRACE_ACC_MAXPIX (1 .. PT_ACC_MAXPIX) lowers that cap, so that a test
** reaches it with a small scene (docs/limits.md).
*/
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "tools/accuracy/accuracy.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "io/outfile.h"
#include "io/sbuf.h"
#include "core/pipetrace.h"


#define MIN_SECONDS   0.03       /* one measurement lasts at least this long */
#define BATCH_SECONDS 0.003      /* one clock reading spans at least this long */
#define MAX_REPEAT    100

static const char usage[] =
"usage: pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]\n"
"Run SCENE's whole pipeline (every stage of its camera, classic or matrix, and\n"
"the rasterizer) in float, double and double-double (the reference, 106 bits)\n"
"and print each stage's error against the reference, each stage's run time\n"
"alone (ns per vertex; the rasterizer: per pixel), and two algorithm choices:\n"
"2.001 or 2.0 in the pixel stage (classic camera), and the DDA's y += m or\n"
"y = y0 + m*(x - x0).\n"
"SCENE defaults to the built-in scene.\n"
"\n"
"  --repeat N    time each stage N times (1-100, default 3), show the median\n"
"  --no-time     leave out the times (and do not time): the output is then the\n"
"                same on every run\n"
"  --svg FILE    also draw each stage's error against its time, log-log, one\n"
"                panel per unit of error, as SVG into FILE\n"
"Docs: docs/accuracy.md\n";

/* ===== the runs ===== */

/* The runs compared, the reference first. */
enum { RUN_DD, RUN_FLOAT, RUN_DOUBLE, RUN_TWO, RUN_FLOAT_RE, RUN_DOUBLE_RE, NRUNS };

/* Every run draws into its own place of one image (pt_acc_image). */
typedef char runs_fit_image[NRUNS <= PT_ACC_MAXIMG ? 1 : -1];

static const struct { pt_arith arith; unsigned choices; } run_of[NRUNS] = {
    { PT_ARITH_DD, 0 }, { PT_ARITH_FLOAT, 0 }, { PT_ARITH_DOUBLE, 0 },
    { PT_ARITH_DOUBLE, PT_ACC_TWO }, { PT_ARITH_FLOAT, PT_ACC_RECOMPUTE },
    { PT_ARITH_DOUBLE, PT_ACC_RECOMPUTE }
};

/* Nanoseconds per vertex of each stage (row), per pixel of the rasterizer;
** NAN: not measured. */
typedef struct timing { double row[PT_ACC_MAXROWS]; } timing;

/* The rows of the scene's pipeline (pt_acc_scene_rows), and the rows the
** tables single out, found in them. */
typedef struct layout {
    const pt_acc_rows *t;        /* the pipeline's rows */
    int nrows;                   /* its stages, then the rasterizer */
    int last_real;               /* the last real stage: pixel, or screen */
    int viewport, raster;
    int two;                     /* the first row PT_ACC_TWO changes, or -1 */
} layout;

static void layout_of(layout *L, const pt_scene *s)
{
    L->t = pt_acc_scene_rows(s);
    L->nrows = L->t->nrows;
    L->last_real = pt_acc_last_real(L->t);
    L->viewport = pt_acc_row_of(L->t, PT_STAGE_VIEWPORT);
    L->raster = L->nrows - 1;
    L->two = pt_acc_row_varied(L->t, PT_ACC_TWO);
}

/* 1 when run k's choices change a row of L (the plain runs: always). */
static int run_applies(const layout *L, int k)
{
    return !run_of[k].choices || pt_acc_row_varied(L->t, run_of[k].choices) >= 0;
}

typedef struct study {
    const pt_scene *s;
    layout rows;                 /* the scene's pipeline's */
    pt_acc_run run[NRUNS];       /* each run's summary: its counts (used
                                 ** vertices, points made, segments culled,
                                 ** pixels lit and written), no journeys and no
                                 ** image; no RUN_TWO where no row has 2.001 */
    pt_acc_err err[NRUNS][PT_ACC_MAXROWS];
    timing t[NRUNS];             /* RUN_TWO: pixel and viewport; _RE runs: raster */
    int timed;
} study;

/* ===== timing ===== */

static volatile double keep;     /* checksums land here, so no pass is skipped */

static double now(void)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* One timed job: a stage of a run (w, row) or its rasterizer (w NULL). */
typedef struct job {
    pt_acc_work *w;
    int row;
    const pt_acc_run *r;
} job;

/* n passes of the job; their seconds. */
static double batch(const job *jb, uint64_t n)
{
    double t0 = now(), sum = 0.0;
    uint64_t k, px;

    for (k = 0; k < n; k++)
        sum += jb->w ? pt_acc_stage_pass(jb->w, jb->row) : pt_acc_raster_pass(jb->r, &px);
    keep = sum;
    return now() - t0;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, by_value);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* Measurements summed over the blocks: per repeat, seconds and items. */
typedef struct clocked {
    double sec[MAX_REPEAT], items[MAX_REPEAT];
} clocked;

/* Add frac (the block's share of the scene) of `repeat` measurements of the
** job (items per pass) to *c: each of at least frac * MIN_SECONDS, each
** clock reading spanning at least frac * BATCH_SECONDS.  Nothing when a pass
** has no items. */
static void measure(const job *jb, double items, int repeat, double frac, clocked *c)
{
    uint64_t n = 1;
    int k;

    if (!(items > 0)) return;
    while (batch(jb, n) < BATCH_SECONDS * frac && n < ((uint64_t)1 << 40)) n *= 2;
    for (k = 0; k < repeat; k++) {
        double sec = 0.0;
        uint64_t passes = 0;

        do {
            sec += batch(jb, n);
            passes += n;
        } while (sec < MIN_SECONDS * frac);
        c->sec[k] += sec;
        c->items[k] += (double)passes * items;
    }
}

/* Nanoseconds per item of c: the median over the repeats; NAN when none was
** measured. */
static double clocked_ns(const clocked *c, int repeat)
{
    double v[MAX_REPEAT];
    int k;

    if (!(c->items[0] > 0)) return (double)NAN;
    for (k = 0; k < repeat; k++) v[k] = c->sec[k] * 1e9 / c->items[k];
    return median(v, repeat);
}

/* 1 when row of L is computed on a block of segments (the rasterizer, the
** clips of renderers 7 and 9 and their ends), 0: of vertices. */
static int row_on_segments(const layout *L, int row)
{
    pt_acc_fn fn = L->t->row[row].fn;

    return row == L->raster || fn == PT_ACC_FN_RVNEAR || fn == PT_ACC_FN_RVCLIP
           || fn == PT_ACC_FN_RVEND;
}

/* Time the rows of block run r whose bit is set in rows and which a block of
** its kind computes, adding to c[row]: each stage alone over its inputs
** (pt_acc_work), the rasterizer by its pass. */
static void time_block(const study *st, const pt_acc_run *r, int segs, unsigned rows,
                       int repeat, double frac, clocked *c)
{
    int row;

    for (row = 0; row <= st->rows.raster; row++) {
        job jb = { NULL, row, r };
        uint64_t px = 0;

        if (!(rows & 1u << row) || row_on_segments(&st->rows, row) != segs) continue;
        if (row == st->rows.raster) {
            pt_acc_raster_pass(r, &px);
            measure(&jb, (double)px, repeat, frac, &c[row]);
            continue;
        }
        jb.w = pt_acc_work_make(r, row);
        if (jb.w) measure(&jb, (double)pt_acc_work_size(jb.w), repeat, frac, &c[row]);
        pt_acc_work_free(jb.w);
    }
}

/* The rows run k is timed on: those its choices change. */
static unsigned timed_rows(const study *st, int k)
{
    const layout *L = &st->rows;
    unsigned rows = 0;
    int row;

    for (row = 0; row < L->nrows; row++)
        if (!run_of[k].choices || L->t->row[row].variants & run_of[k].choices)
            rows |= 1u << row;
    return rows;
}

/* The run whose journeys run k shares: one of the same arithmetic whose
** choices differ only in the DDA's (PT_ACC_RECOMPUTE), drawn again with
** k's; or k itself. */
static int base_of(int k)
{
    int j;

    for (j = 0; j < k; j++)
        if (run_of[j].arith == run_of[k].arith && !(run_of[j].choices & PT_ACC_RECOMPUTE)
            && (run_of[j].choices | PT_ACC_RECOMPUTE) == (run_of[k].choices | PT_ACC_RECOMPUTE))
            return j;
    return k;
}

/* Add block run r's counts to run w's summary. */
static void account(pt_acc_run *w, const pt_acc_run *r, unsigned segs)
{
    if (segs) {
        w->made += r->made;
        w->culled += r->culled;
    } else w->nused += r->nused;
}

/* Every run a block at a time (pt_acc_block), all beside the reference's
** block, computed once for them: each compared into st->err[k] and timed
** (unless no_time) as it comes, then freed; a run that differs from another
** only in the DDA draws that one's block again (pt_acc_draw_again), its
** other rows the same.  The images are kept across blocks in one table
** (pt_acc_image), and st->run[k] gets each run's counts.  Returns 0, or what
** pt_acc_run_block() returns. */
static int sweep(study *st, unsigned char *const *used, size_t maxpix, int repeat,
                 int no_time)
{
    const pt_scene *s = st->s;
    pt_acc_block b;
    pt_acc_image *img = pt_acc_image_make(s, maxpix, NRUNS);
    clocked *c = calloc((size_t)NRUNS * PT_ACC_MAXROWS, sizeof *c);
    unsigned rows[NRUNS];
    int on[NRUNS], rc = 0, k, j, row, cut = st->rows.t->mcam || st->rows.t->rv;

    for (k = 0; k < NRUNS; k++) {
        on[k] = run_applies(&st->rows, k);       /* no 2.001 to replace */
        rows[k] = no_time || !on[k] ? 0 : timed_rows(st, k);
        memset(&st->run[k], 0, sizeof st->run[k]);
        st->run[k].s = s;
        st->run[k].arith = run_of[k].arith;
        st->run[k].choices = run_of[k].choices;
        pt_acc_compare_start(s, st->err[k]);
    }
    if (!img || !c || pt_acc_block_init(&b, s, used) != 0) {
        pt_acc_image_free(img);
        free(c);
        return -1;
    }
    while (rc == 0 && pt_acc_block_next(&b)) {
        double frac = b.segs ? (double)b.m.nseg / (double)b.nseg
                             : (double)b.m.nv / (double)b.nused;
        unsigned parts = b.segs ? PT_ACC_SEGMENTS : PT_ACC_VERTICES;
        pt_acc_run ref, blk;

        if ((rc = pt_acc_run_block(&ref, &b, PT_ARITH_DD, 0, img, RUN_DD)) != 0) break;
        for (k = 0; k < NRUNS && rc == 0; k++) {
            const pt_acc_run *r = &ref;

            if (!on[k] || base_of(k) != k) continue;
            if (k != RUN_DD) {
                rc = pt_acc_run_block(&blk, &b, run_of[k].arith, run_of[k].choices, img, k);
                if (rc != 0) break;
                r = &blk;
            }
            if (k == RUN_DD || !b.segs || cut)   /* classic segments: nothing to compare */
                pt_acc_compare_part(&ref, r, parts, st->err[k]);
            account(&st->run[k], r, b.segs);
            if (rows[k]) time_block(st, r, (int)b.segs, rows[k], repeat, frac, &c[k * PT_ACC_MAXROWS]);
            for (j = k + 1; j < NRUNS && rc == 0; j++) {    /* the runs drawing it again */
                pt_acc_run again = *r;

                if (!on[j] || base_of(j) != k) continue;
                if (b.segs) rc = pt_acc_draw_again(r, run_of[j].choices, img, j);
                account(&st->run[j], r, b.segs);
                again.choices = run_of[j].choices;
                if (rc == 0 && rows[j])
                    time_block(st, &again, (int)b.segs, rows[j], repeat, frac, &c[j * PT_ACC_MAXROWS]);
            }
            if (k != RUN_DD) pt_acc_run_free(&blk);
        }
        pt_acc_run_free(&ref);
    }
    for (k = 0; rc == 0 && k < NRUNS; k++) {
        if (!on[k]) continue;
        if (base_of(k) != k)                     /* the same journeys, the same errors */
            memcpy(st->err[k], st->err[base_of(k)], sizeof st->err[k]);
        pt_acc_image_count(img, k, &st->run[k]);
        pt_acc_image_end(img, RUN_DD, k, &st->err[k][st->rows.raster]);
        if (!rows[k]) continue;
        for (row = 0; row < st->rows.nrows; row++)
            if (rows[k] & 1u << row) st->t[k].row[row] = clocked_ns(&c[k * PT_ACC_MAXROWS + row], repeat);
        st->timed = 1;
    }
    pt_acc_block_free(&b);
    pt_acc_image_free(img);
    free(c);
    return rc;
}

/* A run's time per vertex through every stage: the sum of its stages' (NAN
** when none was measured). */
static double journey_time(const study *st, int run)
{
    double sum = (double)NAN;
    int row;

    for (row = 0; row < st->rows.raster; row++)
        if (!isnan(st->t[run].row[row])) sum = (isnan(sum) ? 0.0 : sum) + st->t[run].row[row];
    return sum;
}

/* ===== the table ===== */

/* An error or a time as text: "0", "inf", "-" (nothing to show), or %.3g. */
static const char *num(char *b, size_t n, double v)
{
    if (isnan(v)) return "-";
    if (v == 0) return "0";
    if (isinf(v)) return "inf";
    snprintf(b, n, "%.3g", v);
    return b;
}

static const char *ratio(char *b, size_t n, uint64_t part, uint64_t whole)
{
    snprintf(b, n, "%llu/%llu", (unsigned long long)part, (unsigned long long)whole);
    return b;
}

/* Bits to which the reference holds a/b, measured: the residual a - b*q is
** computed with fma from q = hi + lo, rounded once.  Returns k with
** |q - a/b| / |a/b| < 2^-k. */
static int dd_bits_of(double a, double b)
{
    pt_dd q = pt_dd_div(pt_dd_from(a), pt_dd_from(b));
    double r = fma(-b, q.lo, fma(-b, q.hi, a));    /* a - b*hi exact, then - b*lo */

    if (r == 0.0) return 999;
    return -(ilogb(fabs(r / a)) + 1);
}

/* Bits to which the reference's q holds sqrt(a), measured: a - q*q with fma
** (a - hi*hi exact, then - 2*hi*lo rounded once); |q - sqrt(a)| / sqrt(a) is
** about |a - q*q| / (2a).  Returns k with that below 2^-k. */
static int dd_sqrt_bits(pt_dd q, double a)
{
    double r = fma(-2.0 * q.hi, q.lo, fma(-q.hi, q.hi, a));

    if (r == 0.0) return 999;
    return -(ilogb(fabs(r / (2.0 * a))) + 1);
}

static void print_matrix_header(const study *st)
{
    const pt_scene *s = st->s;

    printf("            viewport %d x %d, matrix camera: look-at, perspective fov %.6g,\n"
           "            aspect %.6g, near %.6g, far %.6g; the reference's clipping made\n"
           "            %llu points and culled %llu segments\n", s->vp_w, s->vp_h, s->fov,
           s->aspect, s->znear, s->zfar, (unsigned long long)st->run[RUN_DD].made,
           (unsigned long long)st->run[RUN_DD].culled);
    printf("reference   double-double, %d significant bits; measured: 1/3 within 2^-%d,\n"
           "            sqrt(2) within 2^-%d, cot(30 degrees) within 2^-%d of sqrt(3)\n"
           "            (relative)\n", PT_DD_BITS, dd_bits_of(1.0, 3.0),
           dd_sqrt_bits(pt_dd_sqrt(pt_dd_from(2.0)), 2.0),
           dd_sqrt_bits(pt_dd_cot_deg(30.0), 3.0));
    printf("matrices    each arithmetic builds View, Projection and World itself: float\n"
           "            from the scene's numbers rounded to float, double as the\n"
           "            pipeline does, the reference in double-double (sqrt, division,\n"
           "            cot(fov/2)); the world lines' product is the parser's double\n"
           "            matrix, taken as exact by the reference\n");
    printf("errors      against the reference rounded to double; float rounds the\n"
           "            scene's numbers to float first, and that is its error too;\n"
           "            ndc..index: the vertices inside the view volume and the\n"
           "            points clipping made, in either run; cvv: outcodes that differ\n");
}

static void print_rv_header(const study *st)
{
    const pt_scene *s = st->s;

    printf("            viewport %d x %d, renderer %d, %s, view rectangle %.6g..%.6g x\n"
           "            %.6g..%.6g, near plane z = %.6g (near clip %s); the reference's\n"
           "            clips made %llu points and dropped %llu segments\n",
           s->vp_w, s->vp_h, s->renderer, s->perspective ? "perspective" : "orthographic",
           s->cam_l, s->cam_r, s->cam_b, s->cam_t, s->cam_n, s->nearclip ? "on" : "off",
           (unsigned long long)st->run[RUN_DD].made, (unsigned long long)st->run[RUN_DD].culled);
    printf("reference   double-double, %d significant bits; measured: 1/3 within 2^-%d,\n"
           "            2.001 within 2^-%d of 2001/1000 (relative)\n", PT_DD_BITS,
           dd_bits_of(1.0, 3.0), dd_bits_of(2001.0, 1000.0));
    printf("errors      against the reference rounded to double; float rounds the\n"
           "            scene's numbers to float first (renderer 9: its position\n"
           "            matrices too, which every arithmetic takes from the double\n"
           "            stage); nearclip, clip: t and the new point of segments cut\n"
           "            alike, a cut on one side only is inf; image: the vertices and\n"
           "            the near clip's points; pixel..index: the ends drawn, either run\n");
}

static void print_header(const study *st)
{
    const pt_scene *s = st->s;
    uint64_t nseg = 0;
    size_t k;

    for (k = 0; k < s->nmodels; k++) nseg += s->models[k].nseg;
    printf("pipetrace accuracy: %s\n", s->path);
    printf("scene       %zu models, %llu vertices used, %llu segments, %zu pixels in the "
           "reference image\n", s->nmodels, (unsigned long long)st->run[RUN_DD].nused,
           (unsigned long long)nseg, st->run[RUN_DD].nimg);
    if (st->rows.t->mcam) { print_matrix_header(st); return; }
    if (st->rows.t->rv) { print_rv_header(st); return; }
    printf("            viewport %d x %d, %s camera\n", s->vp_w, s->vp_h,
           s->perspective ? "perspective" : "orthographic");
    printf("reference   double-double, %d significant bits; measured: 1/3 within 2^-%d,\n"
           "            2.001 within 2^-%d of 2001/1000 (relative)\n", PT_DD_BITS,
           dd_bits_of(1.0, 3.0), dd_bits_of(2001.0, 1000.0));
    printf("errors      against the reference rounded to double; float rounds the\n"
           "            scene's numbers to float first, and that is its error too\n");
}

/* Renderers 7 and 9: the segments each clip decided otherwise than the
** reference (cut or not, which end, which edge, kept or dropped). */
static void print_decided(const study *st)
{
    const pt_acc_rows *t = st->rows.t;
    char b1[48], b2[48];
    int row;

    if (!t->rv) return;
    printf("\nclips decided otherwise than the reference, segments\n"
           "stage             float      double\n");
    for (row = 0; row < st->rows.nrows; row++)
        if (t->row[row].fn == PT_ACC_FN_RVNEAR || t->row[row].fn == PT_ACC_FN_RVCLIP)
            printf("%-12s %10s  %10s\n", t->row[row].name,
                   ratio(b1, sizeof b1, st->err[RUN_FLOAT][row].decided, st->err[RUN_FLOAT][row].of),
                   ratio(b2, sizeof b2, st->err[RUN_DOUBLE][row].decided,
                         st->err[RUN_DOUBLE][row].of));
}

static void print_errors(const study *st)
{
    static const int runs[] = { RUN_FLOAT, RUN_DOUBLE };
    char b1[32], b2[32], b3[32], b4[48];
    int row, k;

    printf("\nstage        arithmetic  max abs err  mean abs err    max ulp  differ\n");
    for (row = 0; row < st->rows.nrows; row++)
        for (k = 0; k < 2; k++) {
            const pt_acc_err *e = &st->err[runs[k]][row];
            double mean = e->n ? e->sum_abs / (double)e->n : (double)NAN;

            printf("%-12s %-10s %12s %13s %10s  %s %s\n", st->rows.t->row[row].name,
                   pt_arith_names[run_of[runs[k]].arith],
                   num(b1, sizeof b1, e->n ? e->max_abs : (double)NAN),
                   num(b2, sizeof b2, mean),
                   num(b3, sizeof b3, e->n && e->real ? e->max_ulp : (double)NAN),
                   ratio(b4, sizeof b4, e->differ, e->of),
                   row == st->rows.raster ? "pixels"
                   : st->rows.t->row[row].of ? st->rows.t->row[row].of : "vertices");
        }
    print_decided(st);
}

static void print_arithmetics(const study *st)
{
    static const int runs[] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    const layout *L = &st->rows;
    char b1[32], b2[48], b3[48], b4[32], b5[32];
    int k;

    snprintf(b1, sizeof b1, "%s max err", L->t->row[L->last_real].name);
    printf("\narithmetic     bits %14s  viewport differ  pixels differ%s\n", b1,
           st->timed ? "  ns/vertex  ns/pixel" : "");
    for (k = 0; k < 3; k++) {
        const pt_acc_err *e = st->err[runs[k]];
        int ref = runs[k] == RUN_DD;

        printf("%-14s %4d %14s %16s %14s", pt_arith_names[run_of[runs[k]].arith],
               pt_arith_bits[run_of[runs[k]].arith],
               ref ? "reference" : num(b1, sizeof b1, e[L->last_real].n
                                       ? e[L->last_real].max_abs : (double)NAN),
               ref ? "-" : ratio(b2, sizeof b2, e[L->viewport].differ, e[L->viewport].of),
               ref ? "-" : ratio(b3, sizeof b3, e[L->raster].differ, e[L->raster].of));
        if (st->timed)
            printf(" %10s %9s", num(b4, sizeof b4, journey_time(st, runs[k])),
                   num(b5, sizeof b5, st->t[runs[k]].row[L->raster]));
        putchar('\n');
    }
}

/* Each stage's time alone, per arithmetic (only when timed). */
static void print_stage_times(const study *st, int repeat)
{
    static const int runs[] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    char b[3][32];
    int row, k;

    if (!st->timed) return;
    printf("\ntime per stage alone, ns per vertex (raster: ns per pixel), median of %d\n"
           "stage             float     double  double-double\n", repeat);
    for (row = 0; row < st->rows.nrows; row++) {
        for (k = 0; k < 3; k++) num(b[k], sizeof b[k], st->t[runs[k]].row[row]);
        printf("%-12s %10s %10s %14s\n", st->rows.t->row[row].name,
               isnan(st->t[runs[0]].row[row]) ? "-" : b[0],
               isnan(st->t[runs[1]].row[row]) ? "-" : b[1],
               isnan(st->t[runs[2]].row[row]) ? "-" : b[2]);
    }
}

/* The classic camera's choice: 2.001 or 2.0 in the pixel stage. */
static void print_two(const study *st)
{
    static const int two[] = { RUN_DOUBLE, RUN_TWO };
    const layout *L = &st->rows;
    char b1[32], b2[48], b3[48], b4[32];
    int k;

    printf("\nchoice: 2.001 or 2.0 in x_pp = 0.5 + w/2.001 * (x_ip + 1), in double\n");
    printf("constant  pixel max err  viewport differ  left viewport  pixels differ%s\n",
           st->timed ? "  pixel ns/vertex" : "");
    for (k = 0; k < 2; k++) {
        const pt_acc_err *e = st->err[two[k]];

        printf("%-8s %14s %16s %14llu %14s", k ? "2.0" : "2.001",
               num(b1, sizeof b1, e[L->two].n ? e[L->two].max_abs : (double)NAN),
               ratio(b2, sizeof b2, e[L->viewport].differ, e[L->viewport].of),
               (unsigned long long)e[L->viewport].left,
               ratio(b3, sizeof b3, e[L->raster].differ, e[L->raster].of));
        if (st->timed) printf(" %16s", num(b4, sizeof b4, st->t[two[k]].row[L->two]));
        putchar('\n');
    }
}

static void print_choices(const study *st)
{
    static const int dda[] = { RUN_FLOAT, RUN_FLOAT_RE, RUN_DOUBLE, RUN_DOUBLE_RE };
    char b1[32], b2[48], b3[48], b4[32];
    int k;

    if (st->rows.two < 0) printf("\n%s", st->rows.t->no_two);
    else print_two(st);

    printf("\nchoice: the DDA's y += m or y = y0 + m*(x - x0), against the exact line\n");
    printf("arithmetic  DDA        max abs err  mean abs err  pixels differ%s\n",
           st->timed ? "  ns/pixel" : "");
    for (k = 0; k < 4; k++) {
        const pt_acc_err *e = &st->err[dda[k]][st->rows.raster];

        printf("%-11s %-10s %11s %13s %14s", pt_arith_names[run_of[dda[k]].arith],
               k % 2 ? "recompute" : "y += m",
               num(b1, sizeof b1, e->n ? e->max_abs : (double)NAN),
               num(b2, sizeof b2, e->n ? e->sum_abs / (double)e->n : (double)NAN),
               ratio(b3, sizeof b3, e->differ, e->of));
        if (st->timed) printf(" %9s", num(b4, sizeof b4, st->t[dda[k]].row[st->rows.raster]));
        putchar('\n');
    }
}

/* ===== the plot ===== */

/*
** Four panels, one per unit of error, each with its own log-log axes: the
** coordinates (model .. image, or the matrix camera's model .. ndc), pixels
** (the pixel plane or screen, viewport, framebuffer), array places (index),
** and the rasterizer (the DDA's y, in pixels, against ns per pixel).  Every
** stage is a point at its own time.  Labels are placed by boxes: a label's
** box is its text's width at LABEL_EM of the font size a character, and it
** goes at the first place beside its point where its box meets no other
** label, no point and stays inside the plot (tests/cli/accuracy.sh checks the
** boxes of every text of the SVG).
*/

#define SVG_W    1000
#define SVG_H    800
#define PANEL_W  500            /* panels in a 2 x 2 grid below the header */
#define PANEL_H  345
#define PANELS_T 100
#define MARGIN_L 80             /* plot area inside a panel */
#define MARGIN_R 20
#define MARGIN_T 30
#define MARGIN_B 55
#define LABEL_FS 10             /* font sizes */
#define TEXT_FS  11
#define LABEL_EM 0.6            /* a character's width, of the font size */
#define MAXPTS   48
#define MAXBOX   96

static const char *const panel_unit[PT_ACC_NPANELS] = {
    "coordinates", "pixels", "array places", "raster"
};
static const char *const panel_title[PT_ACC_NPANELS] = {
    "coordinates", "pixels", "array index", "rasterizer"
};
static const char *const panel_ylabel[PT_ACC_NPANELS] = {
    "max abs error (coordinates), log", "max abs error (pixels), log",
    "max abs error (array places), log", "max abs error of y (pixels), log"
};
static const char *const panel_xlabel[PT_ACC_NPANELS] = {
    "ns per vertex, each stage alone, log", "ns per vertex, each stage alone, log",
    "ns per vertex, each stage alone, log", "ns per pixel, the DDA's pass, log"
};

static const char *const series_color[3] = { "#d95f02", "#1b61b8", "#1b9e77" };

/* The panel of a row: -1 for none (the cvv: outcodes, no error). */
static int panel_of(const study *st, int row)
{
    return st->rows.t->row[row].panel;
}

/* One point: a stage of one run at its own time. */
typedef struct point {
    double t, err;               /* ns, max abs error (0 and inf allowed) */
    int series;                  /* 0 float, 1 double, 2 double-double */
    int panel;
    char label[40];              /* "camera", "2.0: pixel" */
    double px, py;               /* the point */
    double lx, ly;               /* its label's anchor and baseline */
    int anchor_end;              /* 1: text-anchor end (left of the point) */
} point;

/* A text's box. */
typedef struct box { double x0, y0, x1, y1; } box;

static int overlap(const box *a, const box *b)
{
    return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

/* The box of text of n characters at font size fs, anchored at (x, y):
** anchor -1 start, 0 middle, 1 end. */
static box text_box(double x, double y, size_t n, double fs, int anchor)
{
    double w = LABEL_EM * fs * (double)n;
    box b;

    b.x0 = anchor < 0 ? x : anchor == 0 ? x - w / 2 : x - w;
    b.x1 = b.x0 + w;
    b.y0 = y - 0.8 * fs;
    b.y1 = y + 0.25 * fs;
    return b;
}

/* s made safe for XML text and attributes by pt_sbuf_add_xml(): the scene's
** path may hold any byte.  Should its few bytes not be allocated, each byte
** but [A-Za-z0-9 ./_-] is written as '?': less, but still well-formed. */
static void xml_text(FILE *f, const char *s)
{
    pt_sbuf b;

    pt_sbuf_init(&b);
    pt_sbuf_add_xml(&b, s);
    if (!b.failed) fputs(b.s ? b.s : "", f);
    else
        for (; *s; s++)
            fputc(strchr(" ./_-", *s) || (*s >= '0' && *s <= '9') || (*s >= 'a' && *s <= 'z')
                  || (*s >= 'A' && *s <= 'Z') ? *s : '?', f);
    pt_sbuf_free(&b);
}

static int add_point(point *p, int n, int series, const char *choice, const char *name,
                     double t, double err, int panel)
{
    if (isnan(t) || isnan(err) || panel < 0 || n == MAXPTS) return n;
    memset(&p[n], 0, sizeof p[n]);
    p[n].t = t; p[n].err = err; p[n].series = series; p[n].panel = panel;
    snprintf(p[n].label, sizeof p[n].label, "%s%s", choice ? choice : "", name);
    return n + 1;
}

/* Every point of the plot. */
static int collect_points(const study *st, point *p)
{
    static const int arith_runs[3] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    const layout *L = &st->rows;
    int n = 0, k, row;

    for (k = 0; k < 3; k++)
        for (row = 0; row < L->nrows; row++) {
            const pt_acc_err *e = &st->err[arith_runs[k]][row];

            n = add_point(p, n, k, NULL, L->t->row[row].name, st->t[arith_runs[k]].row[row],
                          arith_runs[k] == RUN_DD ? 0.0 : e->n ? e->max_abs : (double)NAN,
                          panel_of(st, row));
        }
    for (row = 0; row < L->nrows; row++) {           /* 2.0 for 2.001 */
        const pt_acc_err *e = &st->err[RUN_TWO][row];

        if (!(L->t->row[row].variants & PT_ACC_TWO)) continue;
        n = add_point(p, n, 1, "2.0: ", L->t->row[row].name, st->t[RUN_TWO].row[row],
                      e->n ? e->max_abs : (double)NAN, panel_of(st, row));
    }
    n = add_point(p, n, 0, "recompute y: ", "raster", st->t[RUN_FLOAT_RE].row[L->raster],
                  st->err[RUN_FLOAT_RE][L->raster].max_abs, PT_ACC_PANEL_RASTER);
    n = add_point(p, n, 1, "recompute y: ", "raster", st->t[RUN_DOUBLE_RE].row[L->raster],
                  st->err[RUN_DOUBLE_RE][L->raster].max_abs, PT_ACC_PANEL_RASTER);
    return n;
}

/* Position of decade exponent e on an axis from lo to hi drawn from a to b. */
static double axis_pos(double e, double lo, double hi, double a, double b)
{
    return a + (b - a) * (e - lo) / (hi - lo);
}

/* A decade's tick label: 0.01 .. 10000 written out, else 1eN. */
static void decade(char *b, size_t n, int e)
{
    if (e >= -2 && e <= 4) snprintf(b, n, "%g", pow(10.0, e));
    else snprintf(b, n, "1e%d", e);
}

/* One panel's frame: its plot area and decades. */
typedef struct frame {
    double l, r, t, b;           /* the plot area */
    double x0, x1, y0, y1;       /* decades of time and error */
    double bottom, top;          /* the y axis's ends: room for 0 and inf */
    int zeros, infs;
    int decades;                 /* 0: no finite error but 0, no decade to name */
} frame;

static void frame_of(frame *fr, int panel, point *p, int n)
{
    double tmin = HUGE_VAL, tmax = 0, emin = HUGE_VAL, emax = 0;
    double ox = (panel % 2) * PANEL_W, oy = PANELS_T + (panel / 2) * PANEL_H;
    int k;

    memset(fr, 0, sizeof *fr);
    fr->l = ox + MARGIN_L; fr->r = ox + PANEL_W - MARGIN_R;
    fr->t = oy + MARGIN_T; fr->b = oy + PANEL_H - MARGIN_B;
    for (k = 0; k < n; k++) {
        if (p[k].panel != panel) continue;
        if (p[k].t < tmin) tmin = p[k].t;
        if (p[k].t > tmax) tmax = p[k].t;
        if (p[k].err == 0) fr->zeros = 1;
        else if (isinf(p[k].err)) fr->infs = 1;
        else {
            if (p[k].err < emin) emin = p[k].err;
            if (p[k].err > emax) emax = p[k].err;
        }
    }
    if (tmax == 0) { tmin = 1; tmax = 10; }
    fr->decades = emax > 0;
    if (emax == 0) { emin = 0.1; emax = 1; }
    fr->x0 = floor(log10(tmin));
    fr->x1 = ceil(log10(tmax));
    if (fr->x1 <= fr->x0) fr->x1 = fr->x0 + 1;
    fr->y0 = floor(log10(emin));
    fr->y1 = ceil(log10(emax));
    if (fr->y1 <= fr->y0) fr->y1 = fr->y0 + 1;
    fr->bottom = fr->zeros ? fr->y0 - 1.6 : fr->y0;     /* the 0 line at y0 - 1 */
    fr->top = fr->infs ? fr->y1 + 1.6 : fr->y1;         /* the inf line at y1 + 1 */
    for (k = 0; k < n; k++) {
        double e;

        if (p[k].panel != panel) continue;
        e = p[k].err == 0 ? fr->y0 - 1 : isinf(p[k].err) ? fr->y1 + 1 : log10(p[k].err);
        p[k].px = axis_pos(log10(p[k].t), fr->x0, fr->x1, fr->l, fr->r);
        p[k].py = axis_pos(e, fr->bottom, fr->top, fr->b, fr->t);
    }
}

/* Place the labels of one panel: for each point, the first place beside it
** (right, then left, then rows further up and down) whose box stays inside the
** plot and meets no placed label and no point. */
static void place_labels(point *p, int n, int panel, const frame *fr)
{
    box placed[MAXBOX], dot;
    int np = 0, k, i, tries;

    for (k = 0; k < n; k++) {
        if (p[k].panel != panel) continue;
        for (tries = 0; tries < 40; tries++) {
            int side = tries % 2, step = (tries / 2 + 1) / 2;
            double dy = (tries / 2) % 2 ? -12.0 * step : 12.0 * step;
            double x = p[k].px + (side ? -7 : 7), y = p[k].py + 3.5 + dy;
            box b = text_box(x, y, strlen(p[k].label), LABEL_FS, side ? 1 : -1);
            int ok = b.x0 >= fr->l + 2 && b.x1 <= fr->r - 2 && b.y0 >= fr->t + 2
                     && b.y1 <= fr->b - 2;

            for (i = 0; ok && i < np; i++) ok = !overlap(&b, &placed[i]);
            for (i = 0; ok && i < n; i++) {
                if (p[i].panel != panel) continue;
                dot.x0 = p[i].px - 5; dot.x1 = p[i].px + 5;
                dot.y0 = p[i].py - 5; dot.y1 = p[i].py + 5;
                ok = !overlap(&b, &dot);
            }
            if (ok || tries == 39) {
                p[k].lx = x; p[k].ly = y; p[k].anchor_end = side;
                if (np < MAXBOX) placed[np++] = b;
                break;
            }
        }
    }
}

/* A text at (x, y), anchor -1 start, 0 middle, 1 end; cls names its role. */
static void text_at(FILE *f, double x, double y, int fs, int anchor, const char *fill,
                    const char *cls, const char *s)
{
    fprintf(f, "<text class=\"%s\" x=\"%.1f\" y=\"%.1f\" font-size=\"%d\"%s%s%s%s%s>", cls,
            x, y, fs, strcmp(cls, "label") ? "" : " stroke=\"white\" stroke-width=\"3\" "
            "paint-order=\"stroke\"",
            anchor < 0 ? "" : anchor == 0 ? " text-anchor=\"middle\"" : " text-anchor=\"end\"",
            fill ? " fill=\"" : "", fill ? fill : "", fill ? "\"" : "");
    xml_text(f, s);
    fputs("</text>\n", f);
}

static void write_panel(FILE *f, const study *st, int panel, point *p, int n)
{
    frame fr;
    char b[64];
    int k, step;

    frame_of(&fr, panel, p, n);
    place_labels(p, n, panel, &fr);
    fprintf(f, "<g class=\"panel\" data-unit=\"%s\">\n", panel_unit[panel]);
    snprintf(b, sizeof b, "%s%s", panel_title[panel], st->rows.t->panel_sub[panel]);
    text_at(f, fr.l, fr.t - 10, 12, -1, NULL, "panel-title", b);
    for (k = (int)fr.x0; k <= (int)fr.x1; k++) {    /* x: every decade */
        double x = axis_pos(k, fr.x0, fr.x1, fr.l, fr.r);

        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
                x, fr.t, x, fr.b);
        decade(b, sizeof b, k);
        text_at(f, x, fr.b + 14, 10, 0, NULL, "tick", b);
    }
    for (step = 1; (fr.y1 - fr.y0) / step > 6; step++) {}
    for (k = (int)fr.y0; fr.decades && k <= (int)fr.y1; k++) {  /* y: 7 decades at most */
        double y = axis_pos(k, fr.bottom, fr.top, fr.b, fr.t);

        if ((k - (int)fr.y1) % step) continue;
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
                fr.l, y, fr.r, y);
        decade(b, sizeof b, k);
        text_at(f, fr.l - 5, y + 3.5, 10, 1, NULL, "tick", b);
    }
    for (k = 0; k < 2; k++) {                       /* the lines of 0 and of inf */
        double y;

        if (!(k ? fr.infs : fr.zeros)) continue;
        y = axis_pos(k ? fr.y1 + 1 : fr.y0 - 1, fr.bottom, fr.top, fr.b, fr.t);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#888\" "
                   "stroke-dasharray=\"5 4\"/>\n", fr.l, y, fr.r, y);
        text_at(f, fr.l - 5, y + 3.5, 10, 1, NULL, "tick", k ? "inf" : "0");
    }
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
               "stroke=\"#333\"/>\n", fr.l, fr.t, fr.r - fr.l, fr.b - fr.t);
    text_at(f, (fr.l + fr.r) / 2, fr.b + 32, TEXT_FS, 0, NULL, "axis x", panel_xlabel[panel]);
    fprintf(f, "<text class=\"axis y\" x=\"%.1f\" y=\"%.1f\" font-size=\"%d\" "
               "text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">",
            fr.l - 48, (fr.t + fr.b) / 2, TEXT_FS, fr.l - 48, (fr.t + fr.b) / 2);
    xml_text(f, panel_ylabel[panel]);
    fputs("</text>\n", f);

    for (k = 0; k < n; k++) {                       /* points, leaders, labels */
        const char *c = series_color[p[k].series];

        if (p[k].panel != panel) continue;
        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\" stroke=\"%s\" "
                   "stroke-width=\"1.5\"/>\n", p[k].px, p[k].py,
                strchr(p[k].label, ':') ? "white" : c, c);
        if (fabs(p[k].ly - 3.5 - p[k].py) > 1)      /* moved away: a leader */
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                       "stroke-width=\"0.6\"/>\n", p[k].px, p[k].py,
                    p[k].lx + (p[k].anchor_end ? 1 : -1), p[k].ly - 3.5, c);
        text_at(f, p[k].lx, p[k].ly, LABEL_FS, p[k].anchor_end ? 1 : -1, c, "label",
                p[k].label);
    }
    fputs("</g>\n", f);
}

/* Write the plot: every stage's max abs error against its own time. */
static void write_svg(FILE *f, const study *st)
{
    point p[MAXPTS];
    char b[200];
    int n = collect_points(st, p), k;
    double x;

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"%d\">\n",
            SVG_W, SVG_H, SVG_W, SVG_H, TEXT_FS);
    fprintf(f, "<title>pipetrace accuracy: ");
    xml_text(f, st->s->path);
    fprintf(f, "</title>\n<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", SVG_W, SVG_H);
    snprintf(b, sizeof b, "Error against the cost of each stage: %s", st->s->path);
    text_at(f, 20, 24, 14, -1, NULL, "title", b);
    text_at(f, 20, 42, TEXT_FS, -1, "#555", "note",
            "max abs error of each stage against the double-double reference, "
            "one panel per unit; each stage timed alone");
    for (k = 0, x = 26; k < 4; k++) {               /* the legend, in a row */
        fprintf(f, "<circle cx=\"%.1f\" cy=\"60\" r=\"4\" fill=\"%s\" stroke=\"%s\" "
                   "stroke-width=\"1.5\"/>\n", x, k < 3 ? series_color[k] : "white",
                k < 3 ? series_color[k] : "#333");
        if (k < 3)
            snprintf(b, sizeof b, "%s, %d bits%s", pt_arith_names[k], pt_arith_bits[k],
                     k == 2 ? " (reference)" : "");
        else snprintf(b, sizeof b, "hollow: an algorithm choice");
        text_at(f, x + 10, 64, TEXT_FS, -1, NULL, "legend", b);
        x += 10 + LABEL_EM * TEXT_FS * (double)strlen(b) + 30;
    }
    snprintf(b, sizeof b, "0 (the reference's own errors, and exact results) lies on the "
             "dashed line marked 0, inf on the one marked inf%s.", st->rows.t->no_plot);
    text_at(f, 20, 84, TEXT_FS, -1, "#555", "note", b);
    for (k = 0; k < PT_ACC_NPANELS; k++) write_panel(f, st, k, p, n);
    fprintf(f, "</svg>\n");
}

/* ===== main ===== */

int pt_cmd_accuracy(int argc, char **argv)
{
    const char *path = NULL, *svg = NULL, *env;
    int k, repeat = 3, no_time = 0, rc = 0;
    size_t maxpix = PT_ACC_MAXPIX;
    study *st;
    unsigned char **used;
    pt_scene s;
    char err[PT_ERRLEN];
    pt_cli_args ca = {"accuracy", usage, 0, NULL, NULL, 0};

    for (k = 1; k < argc; k++) {
        const char *a = argv[k], *val;
        int u;

        if (!strcmp(a, "--no-time")) no_time = 1;
        else if (!strcmp(a, "--repeat") || !strcmp(a, "--svg")) {
            if ((u = pt_cli_value("accuracy", argc, argv, &k, &val)) >= 0) return u;
            if (!strcmp(a, "--svg")) svg = val;
            else {
                char *end;
                long v;

                errno = 0;
                v = strtol(val, &end, 10);
                if (val[0] < '0' || val[0] > '9' || *end || errno || v < 1 || v > MAX_REPEAT)
                    return pt_cli_usage("accuracy", "--repeat takes 1 to 100, not %s", val);
                repeat = (int)v;
            }
        } else if ((u = pt_cli_arg(&ca, argc, argv, &k)) >= 0) return u;  /* SCENE, --help */
    }
    path = ca.path;
    if (svg && no_time) return pt_cli_usage("accuracy", "--svg plots run time: drop --no-time");
    if (pt_cli_outputs(path, &svg, (const char *const[]){"--svg"}, 1) != 0) return PT_EXIT_INPUT;

    if ((env = getenv("PIPETRACE_ACC_MAXPIX")) != NULL) {   /* the tests' lower cap */
        uint64_t v;
        if (pt_cli_count(env, 1, PT_ACC_MAXPIX, &v) != 0)
            return pt_cli_usage("accuracy", "PIPETRACE_ACC_MAXPIX takes 1 to %d, not %s",
                                PT_ACC_MAXPIX, env);
        maxpix = (size_t)v;
    }

    if (pt_cli_load(&s, path) != 0) return PT_EXIT_INPUT;
    if (pt_cli_outputs_objs(&s, &svg, (const char *const[]){"--svg"}, 1) != 0) {
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    st = calloc(1, sizeof *st);
    if (!st) { fputs("pipetrace accuracy: out of memory\n", stderr); pt_scene_free(&s); return PT_EXIT_INPUT; }
    st->s = &s;
    layout_of(&st->rows, &s);
    /* one run at a time beside the reference, a block at a time */
    if ((used = pt_acc_used_make(&s)) == NULL) rc = -1;
    for (k = 0; k < NRUNS; k++) {
        int row;

        for (row = 0; row < PT_ACC_MAXROWS; row++) st->t[k].row[row] = (double)NAN;
    }
    if (rc == 0) rc = sweep(st, used, maxpix, repeat, no_time);
    pt_acc_used_free(&s, used);
    if (rc == -2)
        fprintf(stderr, "pipetrace accuracy: %s lights more than %zu pixels; accuracy keeps "
                "its image in memory and takes at most that many (docs/limits.md)\n", s.path,
                maxpix);
    else if (rc != 0)
        fputs("pipetrace accuracy: out of memory\n", stderr);
    if (rc != 0) {
        rc = PT_EXIT_INPUT;
        goto done;
    }

    print_header(st);
    print_errors(st);
    print_arithmetics(st);
    print_stage_times(st, repeat);
    print_choices(st);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace accuracy: cannot write to standard output\n", stderr);
        rc = PT_EXIT_INPUT;
        goto done;
    }
    if (svg) {
        pt_outfile out;

        if (pt_outfile_open(&out, svg, err, sizeof err) != 0) rc = PT_EXIT_INPUT;
        else {
            write_svg(out.f, st);
            if (pt_outfile_commit(&out, err, sizeof err) != 0) rc = PT_EXIT_INPUT;
        }
        if (rc) fprintf(stderr, "pipetrace accuracy: %s\n", err);
    }
done:
    for (k = 0; k < NRUNS; k++) pt_acc_run_free(&st->run[k]);
    free(st);
    pt_scene_free(&s);
    return rc;
}
