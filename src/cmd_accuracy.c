/*
** src/cmd_accuracy.c -- pipetrace accuracy: error against run time, per arithmetic
** See LICENSE for copyright and license.
**
**   pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]
**
** Runs the scene's whole pipeline in float, double and double-double (the
** reference; src/accuracy.h says what it computes) and prints: the errors of
** each stage and of the rasterizer against the reference; per arithmetic its
** bits, headline errors and run time per vertex and per pixel; and two
** algorithm choices, 2.001 against 2.0 and the DDA's y += m against
** y = y0 + m*(x - x0).  --svg draws the error of every stage against run
** time, log-log.
**
** Timing: a pass computes every used vertex's journey (or rasterizes every
** segment).  Passes are batched so that one clock reading spans at least
** 10 ms, and batches repeat until both passes together took 0.2 s; that is
** one measurement, and the median of --repeat of them is shown.  Without
** --no-time the time columns vary from run to run, everything else never.
*/
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "accuracy.h"
#include "builtin.h"
#include "commands.h"
#include "outfile.h"
#include "scene.h"

#define EXIT_USAGE 1
#define EXIT_INPUT 2

#define MIN_SECONDS   0.2        /* one measurement lasts at least this long */
#define BATCH_SECONDS 0.01       /* one clock reading spans at least this long */
#define MAX_REPEAT    100

static const char usage[] =
"usage: pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]\n"
"Run SCENE's whole pipeline (every stage and the rasterizer) in float, double\n"
"and double-double (the reference, 106 bits) and print each stage's error\n"
"against the reference, each arithmetic's run time per vertex and per pixel,\n"
"and two algorithm choices: 2.001 or 2.0 in the pixel stage, and the DDA's\n"
"y += m or y = y0 + m*(x - x0).  SCENE defaults to the built-in scene.\n"
"\n"
"  --repeat N    time each arithmetic N times (1-100, default 3), show the median\n"
"  --no-time     leave out the time columns (and do not time): the output is\n"
"                then the same on every run\n"
"  --svg FILE    also draw error against time, log-log, as SVG into FILE\n"
"Docs: docs/accuracy.md\n";

static int usage_error(const char *msg, const char *arg)
{
    fprintf(stderr, "pipetrace accuracy: %s%s\nTry 'pipetrace accuracy --help'.\n",
            msg, arg);
    return EXIT_USAGE;
}

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

typedef struct study {
    const pt_scene *s;
    pt_acc_run run[NRUNS];
    pt_acc_err err[NRUNS][PT_ACC_NROWS];
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
    st->t[RUN_TWO] = measure(&r[RUN_TWO], &r[RUN_DOUBLE_RE], repeat);
    st->t[RUN_DOUBLE_RE].pixel = st->t[RUN_TWO].pixel;
    st->t[RUN_TWO].pixel = (double)NAN;
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
    for (row = 0; row < PT_ACC_NROWS; row++)
        for (k = 0; k < 2; k++) {
            const pt_acc_err *e = &st->err[runs[k]][row];
            double mean = e->n ? e->sum_abs / (double)e->n : (double)NAN;

            printf("%-12s %-10s %12s %13s %10s  %s %s\n", pt_acc_row_names[row],
                   pt_arith_names[run_of[runs[k]].arith],
                   num(b1, sizeof b1, e->n ? e->max_abs : (double)NAN),
                   num(b2, sizeof b2, mean),
                   num(b3, sizeof b3, e->n && e->real ? e->max_ulp : (double)NAN),
                   ratio(b4, sizeof b4, e->differ, e->of),
                   row == PT_ACC_RASTER ? "pixels" : "vertices");
        }
}

static void print_arithmetics(const study *st)
{
    static const int runs[] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    char b1[32], b2[48], b3[48], b4[32], b5[32];
    int k;

    printf("\narithmetic     bits  pixel max err  viewport differ  pixels differ%s\n",
           st->timed ? "  ns/vertex  ns/pixel" : "");
    for (k = 0; k < 3; k++) {
        const pt_acc_err *e = st->err[runs[k]];
        int ref = runs[k] == RUN_DD;

        printf("%-14s %4d %14s %16s %14s", pt_arith_names[run_of[runs[k]].arith],
               pt_arith_bits[run_of[runs[k]].arith],
               ref ? "reference" : num(b1, sizeof b1, e[PT_ACC_PIXEL].n
                                       ? e[PT_ACC_PIXEL].max_abs : (double)NAN),
               ref ? "-" : ratio(b2, sizeof b2, e[PT_ACC_VIEWPORT].differ, e[PT_ACC_VIEWPORT].of),
               ref ? "-" : ratio(b3, sizeof b3, e[PT_ACC_RASTER].differ, e[PT_ACC_RASTER].of));
        if (st->timed)
            printf(" %10s %9s", num(b4, sizeof b4, st->t[runs[k]].vertex),
                   num(b5, sizeof b5, st->t[runs[k]].pixel));
        putchar('\n');
    }
}

static void print_choices(const study *st)
{
    static const int two[] = { RUN_DOUBLE, RUN_TWO };
    static const int dda[] = { RUN_FLOAT, RUN_FLOAT_RE, RUN_DOUBLE, RUN_DOUBLE_RE };
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

    printf("\nchoice: the DDA's y += m or y = y0 + m*(x - x0), against the exact line\n");
    printf("arithmetic  DDA        max abs err  mean abs err  pixels differ%s\n",
           st->timed ? "  ns/pixel" : "");
    for (k = 0; k < 4; k++) {
        const pt_acc_err *e = &st->err[dda[k]][PT_ACC_RASTER];

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

/* Plot area and canvas, in SVG user units. */
#define SVG_W   800
#define SVG_H   520
#define PLOT_L  80
#define PLOT_R  580
#define PLOT_T  60
#define PLOT_B  460

typedef struct point {
    double t, err;               /* ns, error (0 and inf allowed) */
    int series;                  /* 0 float, 1 double, 2 double-double */
    int hollow;                  /* an algorithm choice, not the arithmetic as written */
    char label[96];
    double px, py, ly;           /* position; label's y after spreading */
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

/* Add a point, or the stage's name to a point already there. */
static int add_point(point *p, int n, int series, int hollow, double t, double err,
                     const char *label)
{
    int k;

    if (isnan(t) || isnan(err)) return n;
    for (k = 0; k < n; k++)
        if (p[k].series == series && p[k].hollow == hollow && p[k].t == t && p[k].err == err) {
            size_t len = strlen(p[k].label);
            snprintf(p[k].label + len, sizeof p[k].label - len, ", %s", label);
            return n;
        }
    memset(&p[n], 0, sizeof p[n]);
    p[n].t = t; p[n].err = err; p[n].series = series; p[n].hollow = hollow;
    snprintf(p[n].label, sizeof p[n].label, "%s", label);
    return n + 1;
}

static int by_label_y(const void *a, const void *b)
{
    const point *x = *(const point *const *)a, *y = *(const point *const *)b;
    if (x->py != y->py) return x->py < y->py ? -1 : 1;
    return strcmp(x->label, y->label);
}

/* Spread the labels of one side (float's on the left, the others' on the
** right) so that no two are closer than 12 units. */
static void spread_labels(point *p, int n, int left)
{
    point *side[64];
    int k, m = 0;

    for (k = 0; k < n; k++)
        if ((p[k].series == 0) == left) side[m++] = &p[k];
    qsort(side, (size_t)m, sizeof *side, by_label_y);
    for (k = 0; k < m; k++) {
        side[k]->ly = side[k]->py + 4;
        if (k && side[k]->ly < side[k - 1]->ly + 12) side[k]->ly = side[k - 1]->ly + 12;
    }
}

static double log_pos(double v, double lo, double hi, double a, double b)
{
    return a + (b - a) * (log10(v) - lo) / (hi - lo);
}

/* Write the plot: every stage's max abs error against its time, log-log. */
static void write_svg(FILE *f, const study *st)
{
    static const int arith_runs[3] = { RUN_FLOAT, RUN_DOUBLE, RUN_DD };
    point p[64];
    int n = 0, k, row, e, zeros = 0, infs = 0;
    double tmin = HUGE_VAL, tmax = 0, emin = HUGE_VAL, emax = 0;
    double x_lo, x_hi, y_lo, y_hi, floor_e, ceil_e;
    char label[64];

    for (k = 0; k < 3; k++)                         /* the arithmetics as written */
        for (row = 0; row < PT_ACC_NROWS; row++) {
            const pt_acc_err *er = &st->err[arith_runs[k]][row];
            const timing *t = &st->t[arith_runs[k]];
            double err = arith_runs[k] == RUN_DD ? 0.0 : er->n ? er->max_abs : (double)NAN;

            n = add_point(p, n, k, 0, row == PT_ACC_RASTER ? t->pixel : t->vertex, err,
                          pt_acc_row_names[row]);
        }
    n = add_point(p, n, 1, 1, st->t[RUN_TWO].vertex,
                  st->err[RUN_TWO][PT_ACC_VIEWPORT].n ? st->err[RUN_TWO][PT_ACC_VIEWPORT].max_abs
                                                      : (double)NAN, "viewport with 2.0");
    n = add_point(p, n, 0, 1, st->t[RUN_FLOAT_RE].pixel,
                  st->err[RUN_FLOAT_RE][PT_ACC_RASTER].max_abs, "raster, recompute y");
    n = add_point(p, n, 1, 1, st->t[RUN_DOUBLE_RE].pixel,
                  st->err[RUN_DOUBLE_RE][PT_ACC_RASTER].max_abs, "raster, recompute y");

    for (k = 0; k < n; k++) {                       /* the axes' ranges */
        if (p[k].t < tmin) tmin = p[k].t;
        if (p[k].t > tmax) tmax = p[k].t;
        if (p[k].err == 0) zeros = 1;
        else if (isinf(p[k].err)) infs = 1;
        else {
            if (p[k].err < emin) emin = p[k].err;
            if (p[k].err > emax) emax = p[k].err;
        }
    }
    if (n == 0) { tmin = 1; tmax = 10; }
    if (emax == 0) { emin = 1e-16; emax = 1; }
    x_lo = floor(log10(tmin));
    x_hi = ceil(log10(tmax));
    if (x_hi <= x_lo) x_hi = x_lo + 1;
    y_lo = floor(log10(emin)) - (zeros ? 2 : 0);   /* room for the line of zeros */
    y_hi = ceil(log10(emax)) + (infs ? 1 : 0);
    if (y_hi <= y_lo) y_hi = y_lo + 1;
    floor_e = pow(10.0, y_lo);
    ceil_e = pow(10.0, y_hi);
    for (k = 0; k < n; k++) {
        double err = p[k].err == 0 ? floor_e : isinf(p[k].err) ? ceil_e : p[k].err;

        p[k].px = log_pos(p[k].t, x_lo, x_hi, PLOT_L, PLOT_R);
        p[k].py = log_pos(err, y_lo, y_hi, PLOT_B, PLOT_T);
    }
    spread_labels(p, n, 1);
    spread_labels(p, n, 0);

    fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"11\">\n",
            SVG_W, SVG_H, SVG_W, SVG_H);
    fprintf(f, "<title>pipetrace accuracy: ");
    xml_text(f, st->s->path);
    fprintf(f, "</title>\n<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", SVG_W, SVG_H);
    fprintf(f, "<text x=\"%d\" y=\"24\" font-size=\"14\">Error against run time: ", PLOT_L);
    xml_text(f, st->s->path);
    fprintf(f, "</text>\n");
    fprintf(f, "<text x=\"%d\" y=\"42\" fill=\"#555\">max abs error of each stage against "
               "the double-double reference; one point per stage</text>\n", PLOT_L);

    for (e = (int)x_lo; e <= (int)x_hi; e++) {     /* grid and ticks */
        double x = log_pos(pow(10.0, e), x_lo, x_hi, PLOT_L, PLOT_R);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n",
                x, PLOT_T, x, PLOT_B);
        fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">1e%d</text>\n",
                x, PLOT_B + 16, e);
    }
    for (e = (int)y_lo; e <= (int)y_hi; e++) {
        double y = log_pos(pow(10.0, e), y_lo, y_hi, PLOT_B, PLOT_T);
        int step = y_hi - y_lo > 24 ? 2 : 1;

        fprintf(f, "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
                PLOT_L, y, PLOT_R, y);
        if ((e - (int)y_lo) % step == 0 || e == (int)y_hi)
            fprintf(f, "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n",
                    PLOT_L - 6, y + 4, zeros && e == (int)y_lo ? "0"
                    : infs && e == (int)y_hi ? "inf" : (snprintf(label, sizeof label,
                                                                 "1e%d", e), label));
    }
    if (zeros)
        fprintf(f, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#999\" "
                   "stroke-dasharray=\"4 3\"/>\n", PLOT_L, PLOT_B, PLOT_R, PLOT_B);
    if (infs)
        fprintf(f, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#999\" "
                   "stroke-dasharray=\"4 3\"/>\n", PLOT_L, PLOT_T, PLOT_R, PLOT_T);
    fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" "
               "stroke=\"#333\"/>\n", PLOT_L, PLOT_T, PLOT_R - PLOT_L, PLOT_B - PLOT_T);
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">run time, ns per vertex "
               "(stages) or per pixel (raster), log scale</text>\n",
            (PLOT_L + PLOT_R) / 2, PLOT_B + 36);
    fprintf(f, "<text transform=\"translate(%d %d) rotate(-90)\" text-anchor=\"middle\">"
               "max abs error, log scale</text>\n", PLOT_L - 52, (PLOT_T + PLOT_B) / 2);

    for (k = 0; k < n; k++) {                       /* the points and their labels */
        const char *c = series_color[p[k].series];
        int left = p[k].series == 0;

        fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\" stroke=\"%s\" "
                   "stroke-width=\"1.5\"/>\n", p[k].px, p[k].py, p[k].hollow ? "white" : c, c);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\" text-anchor=\"%s\" "
                   "font-size=\"10\">", p[k].px + (left ? -7 : 7), p[k].ly, c,
                left ? "end" : "start");
        xml_text(f, p[k].label);
        fprintf(f, "</text>\n");
    }

    fprintf(f, "<g transform=\"translate(%d %d)\">\n", PLOT_R + 20, PLOT_T + 10);
    for (k = 0; k < 3; k++) {                       /* the legend */
        fprintf(f, "<circle cx=\"6\" cy=\"%d\" r=\"4\" fill=\"%s\"/>\n", k * 18,
                series_color[k]);
        fprintf(f, "<text x=\"16\" y=\"%d\">%s (%d bits)</text>\n", k * 18 + 4,
                pt_arith_names[k], pt_arith_bits[k]);
    }
    fprintf(f, "<circle cx=\"6\" cy=\"54\" r=\"4\" fill=\"white\" stroke=\"#333\" "
               "stroke-width=\"1.5\"/>\n<text x=\"16\" y=\"58\">an algorithm choice</text>\n");
    fprintf(f, "<text x=\"0\" y=\"86\" fill=\"#555\">An error of 0 is drawn on</text>\n"
               "<text x=\"0\" y=\"100\" fill=\"#555\">the bottom line, marked 0%s</text>\n"
               "<text x=\"0\" y=\"114\" fill=\"#555\">(the reference's are 0 by</text>\n"
               "<text x=\"0\" y=\"128\" fill=\"#555\">definition); inf on the top</text>\n"
               "<text x=\"0\" y=\"142\" fill=\"#555\">line, marked inf.</text>\n",
            zeros ? ":" : ".");
    if (zeros) fprintf(f, "<text x=\"0\" y=\"156\" fill=\"#555\">it stands for 1e%d.</text>\n",
                       (int)y_lo);
    fprintf(f, "<text x=\"0\" y=\"180\" fill=\"#555\">Units: model..pixel</text>\n"
               "<text x=\"0\" y=\"194\" fill=\"#555\">coordinates; viewport and</text>\n"
               "<text x=\"0\" y=\"208\" fill=\"#555\">framebuffer pixels; index</text>\n"
               "<text x=\"0\" y=\"222\" fill=\"#555\">array places; raster the</text>\n"
               "<text x=\"0\" y=\"236\" fill=\"#555\">DDA's y, in pixels.</text>\n");
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

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];

        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); return 0; }
        if (!strcmp(a, "--no-time")) no_time = 1;
        else if (!strcmp(a, "--repeat") || !strcmp(a, "--svg")) {
            if (k + 1 >= argc) return usage_error("option needs a value: ", a);
            if (!strcmp(a, "--svg")) svg = argv[++k];
            else {
                const char *val = argv[++k];
                char *end;
                long v;

                errno = 0;
                v = strtol(val, &end, 10);
                if (val[0] < '0' || val[0] > '9' || *end || errno || v < 1 || v > MAX_REPEAT)
                    return usage_error("--repeat takes 1 to 100, not ", val);
                repeat = (int)v;
            }
        } else if (a[0] == '-' && a[1] != '\0') return usage_error("unknown option ", a);
        else if (path) return usage_error("more than one scene given: ", a);
        else path = a;
    }
    if (svg && no_time) return usage_error("--svg plots run time: drop --no-time", "");

    rc = path ? pt_scene_load(&s, path, err, sizeof err)
              : pt_scene_parse(&s, "<builtin>", pt_builtin_scene,
                               strlen(pt_builtin_scene), err, sizeof err);
    if (rc != 0) { fprintf(stderr, "%s\n", err); return EXIT_INPUT; }
    if (s.matrix) {
        fprintf(stderr, "pipetrace accuracy: %s: the matrix camera is not covered; accuracy "
                "follows model -> camera -> image -> pixel -> viewport -> framebuffer -> "
                "index\n", s.path);
        pt_scene_free(&s);
        return EXIT_INPUT;
    }
    st = calloc(1, sizeof *st);
    if (!st) { fputs("pipetrace accuracy: out of memory\n", stderr); pt_scene_free(&s); return EXIT_INPUT; }
    st->s = &s;
    for (k = 0; k < NRUNS && rc == 0; k++) {
        st->t[k].vertex = st->t[k].pixel = (double)NAN;
        rc = pt_acc_run_make(&st->run[k], &s, run_of[k].arith, run_of[k].choices);
    }
    if (rc != 0) {
        fputs("pipetrace accuracy: out of memory\n", stderr);
        rc = EXIT_INPUT;
        goto done;
    }
    for (k = 0; k < NRUNS; k++) pt_acc_compare(&st->run[RUN_DD], &st->run[k], st->err[k]);
    if (!no_time) time_all(st, repeat);

    print_header(st);
    print_errors(st);
    print_arithmetics(st);
    print_choices(st);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace accuracy: cannot write to standard output\n", stderr);
        rc = EXIT_INPUT;
        goto done;
    }
    if (svg) {
        pt_outfile out;

        if (pt_outfile_open(&out, svg, err, sizeof err) != 0) rc = EXIT_INPUT;
        else {
            write_svg(out.f, st);
            if (pt_outfile_commit(&out, err, sizeof err) != 0) rc = EXIT_INPUT;
        }
        if (rc) fprintf(stderr, "pipetrace accuracy: %s\n", err);
    }
done:
    for (k = 0; k < NRUNS; k++) pt_acc_run_free(&st->run[k]);
    free(st);
    pt_scene_free(&s);
    return rc;
}
