/*
** src/tools/accuracy/cmd_accuracy.c -- pipetrace accuracy: error against run time, per arithmetic
** See LICENSE for copyright and license.
**
**   pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]
**
** Runs the scene's whole pipeline in float, double and double-double (the
** reference; src/tools/accuracy/accuracy.h says what it computes) and prints: the errors of
** each stage and of the rasterizer against the reference; per arithmetic its
** bits, headline errors and run time per vertex and per pixel; and two
** algorithm choices, 2.001 against 2.0 and the DDA's y += m against
** y = y0 + m*(x - x0).  --svg draws the error of every stage against run
** time, log-log.  Either camera: the rows are the scene's camera's stages
** (the layout below); the matrix camera has no 2.001, so that choice is only
** said not to apply.
**
** Timing: a pass computes every used vertex's journey (or rasterizes every
** segment).  Passes are batched so that one clock reading spans at least
** 10 ms, and batches repeat until both passes together took 0.2 s; that is
** one measurement, and the median of --repeat of them is shown.  Without
** --no-time the time columns vary from run to run, everything else never.
** Matrix camera: the raster pass includes the clipping of every segment.
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
#include "core/pipetrace.h"


#define MIN_SECONDS   0.2        /* one measurement lasts at least this long */
#define BATCH_SECONDS 0.01       /* one clock reading spans at least this long */
#define MAX_REPEAT    100

static const char usage[] =
"usage: pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]\n"
"Run SCENE's whole pipeline (every stage of its camera, classic or matrix, and\n"
"the rasterizer) in float, double and double-double (the reference, 106 bits)\n"
"and print each stage's error against the reference, each arithmetic's run\n"
"time per vertex and per pixel, and two algorithm choices: 2.001 or 2.0 in the\n"
"pixel stage (classic camera), and the DDA's y += m or y = y0 + m*(x - x0).\n"
"SCENE defaults to the built-in scene.\n"
"\n"
"  --repeat N    time each arithmetic N times (1-100, default 3), show the median\n"
"  --no-time     leave out the time columns (and do not time): the output is\n"
"                then the same on every run\n"
"  --svg FILE    also draw error against time, log-log, as SVG into FILE\n"
"Docs: docs/accuracy.md\n";

/* ===== the runs ===== */

/* The runs compared, the reference first. */
enum { RUN_DD, RUN_FLOAT, RUN_DOUBLE, RUN_TWO, RUN_FLOAT_RE, RUN_DOUBLE_RE, NRUNS };

static const struct { pt_arith arith; unsigned choices; } run_of[NRUNS] = {
    { PT_ARITH_DD, 0 }, { PT_ARITH_FLOAT, 0 }, { PT_ARITH_DOUBLE, 0 },
    { PT_ARITH_DOUBLE, PT_ACC_TWO }, { PT_ARITH_FLOAT, PT_ACC_RECOMPUTE },
    { PT_ARITH_DOUBLE, PT_ACC_RECOMPUTE }
};

/* Nanoseconds per vertex and per pixel; NAN: not measured. */
typedef struct timing { double vertex, pixel; } timing;

/* The rows of one camera's table. */
typedef struct layout {
    int nrows;                   /* its stages, then the rasterizer */
    const char *const *names;    /* "model", ... "raster" */
    int last_real;               /* the last real stage: pixel, or screen */
    int viewport, raster;
} layout;

static const layout classic_rows = {
    PT_ACC_NROWS, pt_acc_row_names, PT_ACC_PIXEL, PT_ACC_VIEWPORT, PT_ACC_RASTER
};
static const layout matrix_rows = {
    PT_ACC_M_NROWS, pt_acc_mrow_names, PT_ACC_M_SCREEN, PT_ACC_M_VIEWPORT, PT_ACC_M_RASTER
};

typedef struct study {
    const pt_scene *s;
    const layout *rows;          /* the scene's camera's */
    pt_acc_run run[NRUNS];       /* matrix camera: no RUN_TWO (all zero) */
    pt_acc_err err[NRUNS][PT_ACC_MAXROWS];
    timing t[NRUNS];             /* vertex of RUN_TWO, pixel of the _RE runs */
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

/* n vertex passes of rv, then n raster passes of rr (either may be NULL);
** their seconds in *tv and *tr. */
static void batch(pt_acc_run *rv, const pt_acc_run *rr, uint64_t n, double *tv, double *tr)
{
    double t0, t1, sum = 0.0;
    uint64_t k, px;

    t0 = now();
    for (k = 0; rv && k < n; k++) sum += pt_acc_vertex_pass(rv);
    t1 = now();
    *tv = t1 - t0;
    for (k = 0; rr && k < n; k++) sum += pt_acc_raster_pass(rr, &px);
    *tr = now() - t1;
    keep = sum;
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

/* Time the vertex passes of rv and the raster passes of rr: the median over
** `repeat` measurements of at least MIN_SECONDS each. */
static timing measure(pt_acc_run *rv, const pt_acc_run *rr, int repeat)
{
    double v[MAX_REPEAT], p[MAX_REPEAT], tv, tr;
    uint64_t n = 1, px = 0;
    timing t = { (double)NAN, (double)NAN };
    int k;

    if (rv && rv->nused == 0) rv = NULL;
    if (rr) pt_acc_raster_pass(rr, &px);
    if (rr && px == 0) rr = NULL;
    if (!rv && !rr) return t;
    for (;;) {                                      /* passes per clock reading */
        batch(rv, rr, n, &tv, &tr);
        if (tv + tr >= BATCH_SECONDS || n >= ((uint64_t)1 << 40)) break;
        n *= 2;
    }
    for (k = 0; k < repeat; k++) {
        double sv = 0.0, sr = 0.0;
        uint64_t passes = 0;

        do {
            batch(rv, rr, n, &tv, &tr);
            sv += tv; sr += tr; passes += n;
        } while (sv + sr < MIN_SECONDS);
        v[k] = rv ? sv * 1e9 / ((double)passes * (double)rv->nused) : 0.0;
        p[k] = rr ? sr * 1e9 / ((double)passes * (double)px) : 0.0;
    }
    if (rv) t.vertex = median(v, repeat);
    if (rr) t.pixel = median(p, repeat);
    return t;
}

static void time_all(study *st, int repeat)
{
    pt_acc_run *r = st->run;

    st->t[RUN_DD] = measure(&r[RUN_DD], &r[RUN_DD], repeat);
    st->t[RUN_FLOAT] = measure(&r[RUN_FLOAT], &r[RUN_FLOAT], repeat);
    st->t[RUN_DOUBLE] = measure(&r[RUN_DOUBLE], &r[RUN_DOUBLE], repeat);
    if (st->s->matrix)                              /* no 2.001: no RUN_TWO */
        st->t[RUN_DOUBLE_RE] = measure(NULL, &r[RUN_DOUBLE_RE], repeat);
    else {
        st->t[RUN_TWO] = measure(&r[RUN_TWO], &r[RUN_DOUBLE_RE], repeat);
        st->t[RUN_DOUBLE_RE].pixel = st->t[RUN_TWO].pixel;
        st->t[RUN_TWO].pixel = (double)NAN;
    }
    st->t[RUN_FLOAT_RE] = measure(NULL, &r[RUN_FLOAT_RE], repeat);
    st->timed = 1;
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
    if (s->matrix) { print_matrix_header(st); return; }
    printf("            viewport %d x %d, %s camera\n", s->vp_w, s->vp_h,
           s->perspective ? "perspective" : "orthographic");
    printf("reference   double-double, %d significant bits; measured: 1/3 within 2^-%d,\n"
           "            2.001 within 2^-%d of 2001/1000 (relative)\n", PT_DD_BITS,
           dd_bits_of(1.0, 3.0), dd_bits_of(2001.0, 1000.0));
    printf("errors      against the reference rounded to double; float rounds the\n"
           "            scene's numbers to float first, and that is its error too\n");
}

static void print_errors(const study *st)
{
    static const int runs[] = { RUN_FLOAT, RUN_DOUBLE };
    char b1[32], b2[32], b3[32], b4[48];
    int row, k;

    printf("\nstage        arithmetic  max abs err  mean abs err    max ulp  differ\n");
    for (row = 0; row < st->rows->nrows; row++)
        for (k = 0; k < 2; k++) {
            const pt_acc_err *e = &st->err[runs[k]][row];
            double mean = e->n ? e->sum_abs / (double)e->n : (double)NAN;

            printf("%-12s %-10s %12s %13s %10s  %s %s\n", st->rows->names[row],
                   pt_arith_names[run_of[runs[k]].arith],
                   num(b1, sizeof b1, e->n ? e->max_abs : (double)NAN),
                   num(b2, sizeof b2, mean),
                   num(b3, sizeof b3, e->n && e->real ? e->max_ulp : (double)NAN),
                   ratio(b4, sizeof b4, e->differ, e->of),
                   row == st->rows->raster ? "pixels" : "vertices");
        }
}

static void print_arithmetics(const study *st)
{
    static const int runs[] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    const layout *L = st->rows;
    char b1[32], b2[48], b3[48], b4[32], b5[32];
    int k;

    printf("\narithmetic     bits %14s  viewport differ  pixels differ%s\n",
           st->s->matrix ? "screen max err" : "pixel max err",
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
            printf(" %10s %9s", num(b4, sizeof b4, st->t[runs[k]].vertex),
                   num(b5, sizeof b5, st->t[runs[k]].pixel));
        putchar('\n');
    }
}

/* The classic camera's choice: 2.001 or 2.0 in the pixel stage. */
static void print_two(const study *st)
{
    static const int two[] = { RUN_DOUBLE, RUN_TWO };
    char b1[32], b2[48], b3[48], b4[32];
    int k;

    printf("\nchoice: 2.001 or 2.0 in x_pp = 0.5 + w/2.001 * (x_ip + 1), in double\n");
    printf("constant  pixel max err  viewport differ  left viewport  pixels differ%s\n",
           st->timed ? "  ns/vertex" : "");
    for (k = 0; k < 2; k++) {
        const pt_acc_err *e = st->err[two[k]];

        printf("%-8s %14s %16s %14llu %14s", k ? "2.0" : "2.001",
               num(b1, sizeof b1, e[PT_ACC_PIXEL].n ? e[PT_ACC_PIXEL].max_abs : (double)NAN),
               ratio(b2, sizeof b2, e[PT_ACC_VIEWPORT].differ, e[PT_ACC_VIEWPORT].of),
               (unsigned long long)e[PT_ACC_VIEWPORT].left,
               ratio(b3, sizeof b3, e[PT_ACC_RASTER].differ, e[PT_ACC_RASTER].of));
        if (st->timed) printf(" %10s", num(b4, sizeof b4, st->t[two[k]].vertex));
        putchar('\n');
    }
}

static void print_choices(const study *st)
{
    static const int dda[] = { RUN_FLOAT, RUN_FLOAT_RE, RUN_DOUBLE, RUN_DOUBLE_RE };
    char b1[32], b2[48], b3[48], b4[32];
    int k;

    if (st->s->matrix)
        printf("\nchoice: 2.001 or 2.0 does not apply to the matrix camera: its screen stage,\n"
               "x_s = (x_n + 1) * w * 0.5, has no 2.001\n");
    else print_two(st);

    printf("\nchoice: the DDA's y += m or y = y0 + m*(x - x0), against the exact line\n");
    printf("arithmetic  DDA        max abs err  mean abs err  pixels differ%s\n",
           st->timed ? "  ns/pixel" : "");
    for (k = 0; k < 4; k++) {
        const pt_acc_err *e = &st->err[dda[k]][st->rows->raster];

        printf("%-11s %-10s %11s %13s %14s", pt_arith_names[run_of[dda[k]].arith],
               k % 2 ? "recompute" : "y += m",
               num(b1, sizeof b1, e->n ? e->max_abs : (double)NAN),
               num(b2, sizeof b2, e->n ? e->sum_abs / (double)e->n : (double)NAN),
               ratio(b3, sizeof b3, e->differ, e->of));
        if (st->timed) printf(" %9s", num(b4, sizeof b4, st->t[dda[k]].pixel));
        putchar('\n');
    }
}

/* ===== the plot ===== */

/* Canvas and plot area, in SVG user units. */
#define SVG_W   800
#define SVG_H   520
#define PLOT_L  80
#define PLOT_R  560
#define PLOT_T  60
#define PLOT_B  450
#define MAXPTS  48

/* One point: the stages (bits of rows) of one run that share a time and an
** error. */
typedef struct point {
    double t, err;               /* ns, max abs error (0 and inf allowed) */
    int series;                  /* 0 float, 1 double, 2 double-double */
    const char *choice;          /* an algorithm choice ("2.0: "), or NULL */
    unsigned rows;               /* bit k: row k */
    double px, py, ly;           /* the point; its label's baseline */
} point;

static const char *const series_color[3] = { "#d95f02", "#1b61b8", "#1b9e77" };

/* s with &, <, >, " escaped for XML text and attributes. */
static void xml_text(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
}

/* Add row's point, or add row to the same run's point with the same values. */
static int add_point(point *p, int n, int series, const char *choice, double t,
                     double err, int row)
{
    int k;

    if (isnan(t) || isnan(err) || n == MAXPTS) return n;
    for (k = 0; k < n; k++)
        if (p[k].series == series && p[k].choice == choice && p[k].t == t && p[k].err == err) {
            p[k].rows |= 1u << row;
            return n;
        }
    memset(&p[n], 0, sizeof p[n]);
    p[n].t = t; p[n].err = err; p[n].series = series; p[n].choice = choice;
    p[n].rows = 1u << row;
    return n + 1;
}

/* The label of a point: its stages (rows of L), three or more in a row as
** "first..last". */
static void point_label(char *b, size_t n, const point *p, const layout *L)
{
    size_t len = 0;
    int r = 0, end;

    b[0] = '\0';
    if (p->choice) len += (size_t)snprintf(b, n, "%s", p->choice);
    while (r < L->nrows && len < n) {
        if (!(p->rows & (1u << r))) { r++; continue; }
        for (end = r; end + 1 < L->nrows && (p->rows & (1u << (end + 1))); end++) {}
        if (end - r >= 2)
            len += (size_t)snprintf(b + len, n - len, "%s%s..%s", len && !p->choice ? ", " : "",
                                    L->names[r], L->names[end]);
        else
            for (; r <= end && len < n; r++)
                len += (size_t)snprintf(b + len, n - len, "%s%s",
                                        len && !(p->choice && len == strlen(p->choice))
                                        ? ", " : "", L->names[r]);
        r = end + 1;
    }
}

static int by_y(const void *a, const void *b)
{
    const point *x = *(const point *const *)a, *y = *(const point *const *)b;

    if (x->py != y->py) return x->py < y->py ? -1 : 1;
    return x->rows < y->rows ? -1 : x->rows > y->rows;
}

/* Spread the labels of one series at least 12 units apart, top to bottom
** (not those of errors of 0: they go under the line of zeros). */
static void spread_labels(point *p, int n, int series)
{
    point *col[MAXPTS];
    int k, m = 0;

    for (k = 0; k < n; k++)
        if (p[k].series == series && p[k].err != 0) col[m++] = &p[k];
    qsort(col, (size_t)m, sizeof *col, by_y);
    for (k = 0; k < m; k++) {
        col[k]->ly = col[k]->py + 4;
        if (k && col[k]->ly < col[k - 1]->ly + 12) col[k]->ly = col[k - 1]->ly + 12;
    }
}

/* Labels of errors of 0: centered under their points, below the line, each
** in the first row where it overlaps no label before it (widths estimated
** at 5.6 units a character). */
static void place_zero_labels(point *p, int n, const layout *L)
{
    double lo[MAXPTS], hi[MAXPTS];
    int row[MAXPTS], k, j, r, m = 0;
    char b[160];

    for (k = 0; k < n; k++) {
        if (p[k].err != 0) continue;
        point_label(b, sizeof b, &p[k], L);
        lo[m] = p[k].px - 2.8 * (double)strlen(b) - 4;
        hi[m] = p[k].px + 2.8 * (double)strlen(b) + 4;
        for (r = 0;; r++) {
            for (j = 0; j < m; j++)
                if (row[j] == r && lo[m] < hi[j] && lo[j] < hi[m]) break;
            if (j == m) break;
        }
        row[m++] = r;
        p[k].ly = p[k].py + 16 + 12 * r;
    }
}

/* Position of decade exponent e on an axis from lo to hi drawn from a to b. */
static double axis_pos(double e, double lo, double hi, double a, double b)
{
    return a + (b - a) * (e - lo) / (hi - lo);
}

/* Write the plot: every stage's max abs error against its run's time, log-log. */
static void write_svg(FILE *f, const study *st)
{
    static const int arith_runs[3] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    static const char *const classic_notes[] = {
        "An error of 0 lies on the dashed",
        "line marked 0, which stands for",
        NULL,                                       /* "1e-17; the reference's ..." */
        "are 0 by definition.",
        "",                                         /* infs: where inf lies */
        "Units of error: model..pixel",
        "in their coordinates; viewport",
        "and framebuffer in pixels; index",
        "in array places; raster: the",
        "DDA's y against the exact line,",
        "in pixels.  Time: ns per vertex",
        "(stages), ns per pixel (raster)."
    };
    static const char *const matrix_notes[] = {
        "An error of 0 lies on the dashed",
        "line marked 0, which stands for",
        NULL,
        "are 0 by definition.",
        "",
        "Units of error: model..screen",
        "in their coordinates; viewport",
        "and framebuffer in pixels; index",
        "in array places; raster: the",
        "DDA's y against the exact line,",
        "in pixels; cvv (outcodes) has",
        "no point.  Time: ns per vertex",
        "(stages), ns per pixel (raster",
        "with clipping)."
    };
    const layout *L = st->rows;
    const char *const *notes = st->s->matrix ? matrix_notes : classic_notes;
    int nnotes = st->s->matrix ? (int)(sizeof matrix_notes / sizeof matrix_notes[0])
                               : (int)(sizeof classic_notes / sizeof classic_notes[0]);
    point p[MAXPTS];
    static const int tick_steps[] = { 1, 2, 5, 10, 20, 50, 100 };
    int n = 0, k, row, step, zeros = 0, infs = 0;
    double tmin = HUGE_VAL, tmax = 0, emin = HUGE_VAL, emax = 0;
    double x0, x1, y0, y1, bottom, top;
    char b[160];

    for (k = 0; k < 3; k++)                         /* the arithmetics as written */
        for (row = 0; row < L->nrows; row++) {
            const pt_acc_err *e = &st->err[arith_runs[k]][row];
            const timing *t = &st->t[arith_runs[k]];

            n = add_point(p, n, k, NULL, row == L->raster ? t->pixel : t->vertex,
                          arith_runs[k] == RUN_DD ? 0.0 : e->n ? e->max_abs : (double)NAN, row);
        }
    if (!st->s->matrix) {                           /* the choices: 2.001 or 2.0 */
        n = add_point(p, n, 1, "2.0: ", st->t[RUN_TWO].vertex,
                      st->err[RUN_TWO][PT_ACC_PIXEL].n ? st->err[RUN_TWO][PT_ACC_PIXEL].max_abs
                                                       : (double)NAN, PT_ACC_PIXEL);
        n = add_point(p, n, 1, "2.0: ", st->t[RUN_TWO].vertex,
                      st->err[RUN_TWO][PT_ACC_VIEWPORT].n
                      ? st->err[RUN_TWO][PT_ACC_VIEWPORT].max_abs : (double)NAN, PT_ACC_VIEWPORT);
    }
    n = add_point(p, n, 0, "recompute y: ", st->t[RUN_FLOAT_RE].pixel,   /* the DDA's */
                  st->err[RUN_FLOAT_RE][L->raster].max_abs, L->raster);
    n = add_point(p, n, 1, "recompute y: ", st->t[RUN_DOUBLE_RE].pixel,
                  st->err[RUN_DOUBLE_RE][L->raster].max_abs, L->raster);

    for (k = 0; k < n; k++) {                       /* the axes: whole decades */
        if (p[k].t < tmin) tmin = p[k].t;
        if (p[k].t > tmax) tmax = p[k].t;
        if (p[k].err == 0) zeros = 1;
        else if (isinf(p[k].err)) infs = 1;
        else {
            if (p[k].err < emin) emin = p[k].err;
            if (p[k].err > emax) emax = p[k].err;
        }
    }
    if (tmax == 0) { tmin = 1; tmax = 10; }
    if (emax == 0) { emin = 1e-16; emax = 1; }
    x0 = floor(log10(tmin));
    x1 = ceil(log10(tmax));
    if (x1 <= x0) x1 = x0 + 1;
    y0 = floor(log10(emin));
    y1 = ceil(log10(emax));
    if (y1 <= y0) y1 = y0 + 1;
    bottom = zeros ? y0 - 3 : y0;                   /* the 0 line at y0 - 1 */
    top = infs ? y1 + 1.5 : y1;                     /* the inf line at y1 + 1 */
    for (k = 0; k < n; k++) {
        double e = p[k].err == 0 ? y0 - 1 : isinf(p[k].err) ? y1 + 1 : log10(p[k].err);

        p[k].px = axis_pos(log10(p[k].t), x0, x1, PLOT_L, PLOT_R);
        p[k].py = axis_pos(e, bottom, top, PLOT_B, PLOT_T);
    }
    for (k = 0; k < 3; k++) spread_labels(p, n, k);
    place_zero_labels(p, n, L);

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"11\">\n",
            SVG_W, SVG_H, SVG_W, SVG_H);
    fprintf(f, "<title>pipetrace accuracy: ");
    xml_text(f, st->s->path);
    fprintf(f, "</title>\n<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", SVG_W, SVG_H);
    fprintf(f, "<text x=\"%d\" y=\"24\" font-size=\"14\">Error against run time: ", PLOT_L);
    xml_text(f, st->s->path);
    fprintf(f, "</text>\n<text x=\"%d\" y=\"42\" fill=\"#555\">max abs error of each stage "
               "against the double-double reference, one point per stage</text>\n", PLOT_L);

    for (k = (int)x0; k <= (int)x1; k++) {          /* grid, ticks, axes */
        double x = axis_pos(k, x0, x1, PLOT_L, PLOT_R);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n"
                   "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">1e%d</text>\n",
                x, PLOT_T, x, PLOT_B, x, PLOT_B + 16, k);
    }
    for (step = 0; step < 6 && (y1 - y0) / tick_steps[step] > 20; step++) {}
    step = tick_steps[step];
    for (k = (int)y0; k <= (int)y1; k++) {          /* every decade, at most ~20 */
        double y = axis_pos(k, bottom, top, PLOT_B, PLOT_T);
        if (k % step) continue;
        fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>\n"
                   "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n",
                PLOT_L, y, PLOT_R, y, PLOT_L - 6, y + 4, k);
    }
    for (k = 0; k < 2; k++) {                       /* the lines of 0 and of inf */
        double y;
        if (!(k ? infs : zeros)) continue;
        y = axis_pos(k ? y1 + 1 : y0 - 1, bottom, top, PLOT_B, PLOT_T);
        fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#888\" "
                   "stroke-dasharray=\"5 4\"/>\n<text x=\"%d\" y=\"%.1f\" "
                   "text-anchor=\"end\">%s</text>\n",
                PLOT_L, y, PLOT_R, y, PLOT_L - 6, y + 4, k ? "inf" : "0");
    }
    fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" "
               "stroke=\"#333\"/>\n", PLOT_L, PLOT_T, PLOT_R - PLOT_L, PLOT_B - PLOT_T);
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">run time: ns per vertex "
               "(stages) or per pixel (raster), log scale</text>\n",
            (PLOT_L + PLOT_R) / 2, PLOT_B + 36);
    fprintf(f, "<text transform=\"translate(%d %d) rotate(-90)\" text-anchor=\"middle\">"
               "max abs error, log scale</text>\n", PLOT_L - 50, (PLOT_T + PLOT_B) / 2);

    for (k = 0; k < n; k++) {                       /* points and labels */
        const char *c = series_color[p[k].series];
        int left = p[k].series != 1;                /* double's labels go right */

        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\" stroke=\"%s\" "
                   "stroke-width=\"1.5\"/>\n", p[k].px, p[k].py, p[k].choice ? "white" : c, c);
        point_label(b, sizeof b, &p[k], L);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\" text-anchor=\"%s\" "
                   "font-size=\"10\">", p[k].err == 0 ? p[k].px : p[k].px + (left ? -7 : 7),
                p[k].ly, c, p[k].err == 0 ? "middle" : left ? "end" : "start");
        xml_text(f, b);
        fprintf(f, "</text>\n");
    }

    fprintf(f, "<g transform=\"translate(%d %d)\">\n", PLOT_R + 20, PLOT_T + 6);
    for (k = 0; k < 3; k++)                         /* the legend */
        fprintf(f, "<circle cx=\"6\" cy=\"%d\" r=\"4\" fill=\"%s\"/>\n"
                   "<text x=\"16\" y=\"%d\">%s, %d bits%s</text>\n", k * 18,
                series_color[k], k * 18 + 4, pt_arith_names[k], pt_arith_bits[k],
                k == 2 ? " (reference)" : "");
    fprintf(f, "<circle cx=\"6\" cy=\"54\" r=\"4\" fill=\"white\" stroke=\"#333\" "
               "stroke-width=\"1.5\"/>\n<text x=\"16\" y=\"58\">an algorithm choice</text>\n");
    for (k = 0; k < nnotes; k++) {
        fprintf(f, "<text x=\"0\" y=\"%d\" fill=\"#555\">", 86 + 14 * k);
        if (!notes[k]) fprintf(f, "1e%d; the reference's errors", (int)y0 - 1);
        else if (!notes[k][0] && infs) fprintf(f, "inf lies on the top dashed line.");
        else xml_text(f, notes[k]);
        fprintf(f, "</text>\n");
    }
    fprintf(f, "</g>\n</svg>\n");
}

/* ===== main ===== */

int pt_cmd_accuracy(int argc, char **argv)
{
    const char *path = NULL, *svg = NULL;
    int k, repeat = 3, no_time = 0, rc = 0;
    study *st;
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

    if (pt_cli_load(&s, path) != 0) return PT_EXIT_INPUT;
    st = calloc(1, sizeof *st);
    if (!st) { fputs("pipetrace accuracy: out of memory\n", stderr); pt_scene_free(&s); return PT_EXIT_INPUT; }
    st->s = &s;
    st->rows = s.matrix ? &matrix_rows : &classic_rows;
    for (k = 0; k < NRUNS && rc == 0; k++) {
        st->t[k].vertex = st->t[k].pixel = (double)NAN;
        if (s.matrix && k == RUN_TWO) continue;     /* no 2.001 to replace */
        rc = pt_acc_run_make(&st->run[k], &s, run_of[k].arith, run_of[k].choices);
    }
    if (rc != 0) {
        fputs("pipetrace accuracy: out of memory\n", stderr);
        rc = PT_EXIT_INPUT;
        goto done;
    }
    for (k = 0; k < NRUNS; k++)
        if (!(s.matrix && k == RUN_TWO)) pt_acc_compare(&st->run[RUN_DD], &st->run[k], st->err[k]);
    if (!no_time) time_all(st, repeat);

    print_header(st);
    print_errors(st);
    print_arithmetics(st);
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
