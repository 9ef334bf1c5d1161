/*
** src/tools/diff/cmd_diff.c -- pipetrace diff: compare two traces or two images, name the mistake
** See LICENSE for copyright and license.
**
** Two traces of one scene are compared vertex by vertex.  Records are matched
** by (model, vertex, stage): one hash table keyed by (model, v) holds, for each
** side and stage, the index of that record.  Only the FIRST stage where a
** vertex differs is explained, since every later stage computes from it: its
** differences are consequences, and are only counted.
**
** A mistake is named only when it is shown for this vertex: the diverging
** stage is recomputed from EXPECTED's value of the stage before, with the
** mistake, and must reproduce ACTUAL's value within the tolerance (from a text
** trace, for some input within its printed digits; see reproduces()).  The
** formulas, right and wrong, are the catalogue's (src/tools/catalogue.h),
** which knows the reference even in a student build.  Stage 5 has no known
** mistake listed.  Only the
** classic camera's mistakes are known; matrix-camera traces are compared
** without naming any.
**
** A stage that one side lacks for a model, though that side's header does not
** leave it out (identity, --stage) and the other side has it, did not report:
** a student stage that never called pt_emit().  That is said first, and a
** later stage's difference is not blamed on the later stage alone.
**
** When every vertex agrees and the lit pixels differ, the rasterizer's
** rounding is checked the same way: the rasterizer (pt_raster_segment) is run
** again on each differing segment from its rounded endpoints (its first and
** last steps in EXPECTED), first with the right viewport stage, which must give
** EXPECTED's pixels, then with the catalogue's viewport stage that rounds
** wrongly, which must give ACTUAL's.
*/
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "io/numfmt.h"
#include "io/outfile.h"
#include "core/pipetrace.h"
#include "io/tread.h"
#include "tools/catalogue.h"


#define NONE UINT32_MAX          /* no record */

static const char diff_usage[] =
"usage: pipetrace diff EXPECTED ACTUAL [--tol ABS] [--rel REL] [--show N]\n"
"       pipetrace diff EXPECTED.ppm ACTUAL.ppm [--image-out FILE] [--show N]\n"
"Compare two traces (JSON Lines or text, in any mix) vertex by vertex: for\n"
"each vertex the first stage where they differ, both values, and the known\n"
"mistake that reproduces ACTUAL from EXPECTED's previous stage, if one does;\n"
"then the lit pixels.  Or compare two images pixel by pixel: binary (P6) or\n"
"plain (P3) PPM, or PNG as pipetrace writes it (uncompressed).\n"
"\n"
"  --tol ABS         doubles agree when |a - b| <= max(ABS, REL * max(|a|, |b|))\n"
"  --rel REL         (defaults 0 and 1e-9; integers must be equal); a text trace\n"
"                    adds half a unit in its last printed digit\n"
"  --show N          list at most N vertices and N pixels of each kind\n"
"                    (default 10)\n"
"  --image-out FILE  images: write FILE (P6 PPM) with the differing pixels red and\n"
"                    the others EXPECTED's, dimmed to gray\n"
"\n"
"Exit status: 0 same, 1 different (or a usage error), 2 unreadable input.\n"
"Docs: docs/teaching.md\n";

typedef struct dopts {
    const char *path[2];         /* EXPECTED, ACTUAL */
    double tol, rel;             /* tolerance for doubles */
    const char *image_out;       /* --image-out, or NULL */
    size_t show;                 /* vertices and pixels listed */
} dopts;

static const char *const side_name[2] = {"EXPECTED", "ACTUAL"};

/* ===== options ===== */

static int usage_error(const char *fmt, const char *arg)
{
    return pt_cli_usage("diff", fmt, arg);
}

/* A finite number >= 0 from s, or -1. */
static double parse_nonneg(const char *s)
{
    char *end;
    double x;

    if (!*s || *s == '-' || *s == '+' || *s == ' ') return -1;
    errno = 0;
    x = strtod(s, &end);
    if (errno || *end || !isfinite(x) || x < 0) return -1;
    return x;
}

/* Fill *o from argv.  Returns -1 to go on, else the exit status. */
static int parse_args(dopts *o, int argc, char **argv)
{
    int k, npath = 0;

    memset(o, 0, sizeof *o);
    o->rel = 1e-9;
    o->show = 10;
    for (k = 1; k < argc; k++) {
        const char *a = argv[k];
        const char *val = k + 1 < argc ? argv[k + 1] : NULL;
        int takes = !strcmp(a, "--tol") || !strcmp(a, "--rel") ||
                    !strcmp(a, "--image-out") || !strcmp(a, "--show");

        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(diff_usage, stdout); return 0; }
        if (takes && !val) return usage_error("option '%s' needs a value", a);
        if (takes) k++;
        if (!strcmp(a, "--tol") || !strcmp(a, "--rel")) {
            double x = parse_nonneg(val);
            if (x < 0) return usage_error("%s takes a number >= 0", a);
            if (a[2] == 't') o->tol = x; else o->rel = x;
        } else if (!strcmp(a, "--show")) {
            double x = parse_nonneg(val);
            if (x < 0 || x != floor(x) || x > 1e9)
                return usage_error("--show takes a count, not '%s'", val);
            o->show = (size_t)x;
        } else if (!strcmp(a, "--image-out")) {
            o->image_out = val;
        } else if (a[0] == '-' && a[1] != '\0') {
            return usage_error("unknown option '%s'", a);
        } else if (npath == 2) {
            return usage_error("more than two files given ('%s')", a);
        } else {
            o->path[npath++] = a;
        }
    }
    if (npath < 2) return usage_error("%s", "needs two files: EXPECTED and ACTUAL");
    return -1;
}

/* ===== printing ===== */

/* A double as the shortest decimal that reads back to it. */
static const char *num(double x, char buf[PT_NUMLEN])
{
    pt_fmt_shortest(buf, x);
    return buf;
}

/* Print text as one paragraph wrapped at 78 columns, each line after `lead`. */
static void para(const char *lead, const char *text)
{
    size_t col = 0, lead_n = strlen(lead);
    const char *p = text;

    while (*p) {
        const char *w = p;
        size_t n;
        while (*p && *p != ' ') p++;
        n = (size_t)(p - w);
        if (col && col + 1 + n > 78) { putchar('\n'); col = 0; }
        if (!col) { fputs(lead, stdout); col = lead_n; }
        else { putchar(' '); col++; }
        fwrite(w, 1, n, stdout);
        col += n;
        while (*p == ' ') p++;
    }
    if (col) putchar('\n');
}

/* A growing string for paragraphs. */
typedef struct pbuf {
    char b[2048];
    size_t n;
} pbuf;

/* Append to s what printf would print; text past its room is dropped. */
static void pb_add(pbuf *s, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);
static void pb_add(pbuf *s, const char *fmt, ...)
{
    va_list ap;
    int k;

    if (s->n >= sizeof s->b - 1) return;
    va_start(ap, fmt);
    k = vsnprintf(s->b + s->n, sizeof s->b - s->n, fmt, ap);
    va_end(ap);
    if (k > 0) s->n += (size_t)k;
    if (s->n > sizeof s->b - 1) s->n = sizeof s->b - 1;
}

/* ===== images ===== */

/* The color of (x, y) in img, or NULL outside it. */
static const unsigned char *rgb_at(const pt_ppm *img, int x, int y)
{
    if (x >= img->w || y >= img->h) return NULL;
    return img->rgb + 3 * ((size_t)y * (size_t)img->w + (size_t)x);
}

static void print_rgb(const unsigned char *c)
{
    if (c) printf("%3d %3d %3d", c[0], c[1], c[2]);
    else printf("(outside)  ");
}

/* Write the highlight: differing pixels red, the others a's, dimmed to gray. */
static int write_highlight(const char *path, const pt_ppm *a, const pt_ppm *b, int w, int h)
{
    pt_outfile out = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];
    unsigned char *row = malloc(3 * (size_t)w);
    int x, y;

    if (!row) { fputs("pipetrace: out of memory\n", stderr); return -1; }
    if (pt_outfile_open(&out, path, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace: %s\n", err);
        free(row);
        return -1;
    }
    fprintf(out.f, "P6\n%d %d\n255\n", w, h);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const unsigned char *ca = rgb_at(a, x, y), *cb = rgb_at(b, x, y);
            unsigned char *p = row + 3 * (size_t)x;
            if (!ca || !cb || memcmp(ca, cb, 3) != 0) { p[0] = 255; p[1] = 0; p[2] = 0; }
            else {                          /* luma / 3: the picture stays readable */
                int g = (299 * ca[0] + 587 * ca[1] + 114 * ca[2]) / 3000;
                p[0] = p[1] = p[2] = (unsigned char)g;
            }
        }
        if (fwrite(row, 1, 3 * (size_t)w, out.f) != 3 * (size_t)w) break;
    }
    free(row);
    if (y < h || ferror(out.f)) {
        fprintf(stderr, "pipetrace: cannot write '%s'\n", path);
        pt_outfile_abort(&out);
        return -1;
    }
    if (pt_outfile_commit(&out, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace: %s\n", err);
        return -1;
    }
    return 0;
}

static int image_diff(const dopts *o, const pt_ppm img[2])
{
    const pt_ppm *a = &img[0], *b = &img[1];
    int w = a->w > b->w ? a->w : b->w, h = a->h > b->h ? a->h : b->h;
    int x, y, x0 = w, y0 = h, x1 = -1, y1 = -1, k;
    size_t ndiff = 0, shown = 0;
    int differ = a->w != b->w || a->h != b->h || a->maxval != b->maxval;

    for (k = 0; k < 2; k++)
        printf("%-9s %s  (%s, %d x %d, maxval %d)\n", side_name[k], o->path[k],
               img[k].format, img[k].w, img[k].h, img[k].maxval);
    if (a->w != b->w || a->h != b->h)
        printf("The sizes differ; pixels inside one image only count as different.\n");
    if (a->maxval != b->maxval)
        printf("The maxvals differ; the color bytes are compared as they are.\n");
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const unsigned char *ca = rgb_at(a, x, y), *cb = rgb_at(b, x, y);
            if (ca && cb && memcmp(ca, cb, 3) == 0) continue;
            if (ndiff++ == 0) printf("\n");
            if (x < x0) x0 = x;
            if (x > x1) x1 = x;
            if (y < y0) y0 = y;
            if (y > y1) y1 = y;
            if (shown < o->show) {
                printf("  (%d, %d)  expected ", x, y);
                print_rgb(ca);
                printf("  actual ");
                print_rgb(cb);
                printf("\n");
                shown++;
            }
        }
    }
    if (ndiff > shown) printf("  ... and %zu more\n", ndiff - shown);
    printf("\n");
    if (ndiff)
        printf("%zu of %zu pixels differ, all within the box (x, y) = (%d, %d) .. (%d, %d).\n",
               ndiff, (size_t)w * (size_t)h, x0, y0, x1, y1);
    else
        printf("The images are the same: %d x %d pixels.\n", w, h);
    if (o->image_out) {
        if (write_highlight(o->image_out, a, b, w, h) != 0) return PT_EXIT_INPUT;
        printf("Highlight written to %s: differing pixels red, the others EXPECTED's in "
               "dimmed gray.\n", o->image_out);
    }
    return ndiff || differ ? PT_EXIT_DIFFER : PT_EXIT_OK;
}

/* ===== the vertex table ===== */

/* One vertex of either trace: where each side's record of each stage is. */
typedef struct vent {
    uint64_t v;                  /* 1-based vertex number */
    uint32_t model;              /* name id */
    uint32_t rec[2][PT_NSTAGES_ALL];   /* index into side's vx[], or NONE */
} vent;

/* Open addressing over entries in order of first sight (EXPECTED's first). */
typedef struct vtab {
    vent *e;                     /* entries; owned */
    size_t n, cap;
    uint32_t *slot;              /* entry index + 1, or 0; owned */
    size_t nslot;                /* power of two > 2 n */
} vtab;

static size_t vhash(uint32_t model, uint64_t v)
{
    uint64_t h = v * 0x9E3779B97F4A7C15u ^ ((uint64_t)model * 0xC2B2AE3D27D4EB4Fu);
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9u;
    h ^= h >> 32;
    return (size_t)h;
}

static int vt_rehash(vtab *t, size_t nslot)
{
    uint32_t *slot = calloc(nslot, sizeof *slot);
    size_t k;

    if (!slot) return -1;
    for (k = 0; k < t->n; k++) {
        size_t s = vhash(t->e[k].model, t->e[k].v) & (nslot - 1);
        while (slot[s]) s = (s + 1) & (nslot - 1);
        slot[s] = (uint32_t)k + 1;
    }
    free(t->slot);
    t->slot = slot;
    t->nslot = nslot;
    return 0;
}

/* The entry of (model, v), added when new; NULL when out of memory. */
static vent *vt_get(vtab *t, uint32_t model, uint64_t v)
{
    size_t s;
    vent *e;
    int side, st;

    if (2 * (t->n + 1) >= t->nslot && vt_rehash(t, t->nslot ? 2 * t->nslot : 1024) != 0)
        return NULL;
    s = vhash(model, v) & (t->nslot - 1);
    for (; t->slot[s]; s = (s + 1) & (t->nslot - 1)) {
        e = &t->e[t->slot[s] - 1];
        if (e->model == model && e->v == v) return e;
    }
    if (t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 1024;
        vent *ne = cap < UINT32_MAX ? realloc(t->e, cap * sizeof *ne) : NULL;
        if (!ne) return NULL;
        t->e = ne;
        t->cap = cap;
    }
    e = &t->e[t->n];
    e->v = v;
    e->model = model;
    for (side = 0; side < 2; side++)
        for (st = 0; st < PT_NSTAGES_ALL; st++) e->rec[side][st] = NONE;
    t->slot[s] = (uint32_t)++t->n;
    return e;
}

/* ===== the comparison ===== */

/* Everything one trace diff needs. */
typedef struct dctx {
    const dopts *o;
    pt_names nm;                 /* model names of both traces */
    pt_tread t[2];               /* EXPECTED, ACTUAL */
    vtab vt;
    double (*tr)[3];             /* tr[model id]: translation from EXPECTED's header */
    unsigned char *has_tr;       /* has_tr[model id]: 1 when tr is known */
    /* counts */
    size_t agree, differ, only[2];
    size_t first_at[PT_NSTAGES_ALL];    /* vertices that first differ at each stage */
    size_t stage_only[2][PT_NSTAGES_ALL];   /* records without a partner */
    size_t shown;                /* vertices listed */
    size_t *mk_hits;             /* per mistake: vertices it reproduces */
    size_t agree_clip, differ_clip;     /* of agree and differ: matrix clip points */
    unsigned *silent[2];         /* silent[s][model id]: bit st when side s has no
                                 ** record of stage st for that model though its
                                 ** header does not leave st out and the other side
                                 ** has them: the stage did not report; owned */
    size_t silent_recs[2][PT_NSTAGES_ALL];  /* the other side's records it lacks */
} dctx;

/* Slack of the number x read from side s: for a text trace, half a unit in
** its last printed digit ("%.Nf"; "%.Ne" from 1e15 up), plus strtod's half ulp.
** For JSON Lines 0: its numbers are the doubles themselves. */
static double slack(const dctx *c, int s, double x)
{
    int prec = c->t[s].prec;
    double half, ax = fabs(x);

    if (prec < 0 || !isfinite(x)) return 0.0;
    half = 0.5 * pow(10.0, -prec);
    if (ax >= 1e15) half = 0.5 * pow(10.0, floor(log10(ax)) - prec);
    return half * (1 + 1e-9) + ax * 0x1p-52;
}

/* 1 when x and y agree within the tolerance plus `extra`.  Non-finite values
** agree only with themselves (nan with nan). */
static int near(const dctx *c, double x, double y, double extra)
{
    double allow;

    if (isnan(x) || isnan(y)) return isnan(x) && isnan(y);
    if (isinf(x) || isinf(y)) return x == y;
    allow = fmax(c->o->tol, c->o->rel * fmax(fabs(x), fabs(y)));
    return fabs(y - x) <= allow + extra;
}

/* 1 when a (EXPECTED) and b (ACTUAL) agree. */
static int same_real(const dctx *c, double a, double b)
{
    return near(c, a, b, slack(c, 0, a) + slack(c, 1, b));
}

/* 1 when stage st holds doubles, 0 when integers. */
static int is_real(int st) { return pt_stage_infos[st].nreal > 0; }

/* Number of values of stage st: 1 to 4. */
static int ncoord(int st) { return pt_stage_infos[st].nreal + pt_stage_infos[st].nint; }

/* Name of value k of stage st, as the text trace writes it: "x_pp". */
static const char *coord_name(int st, int k) { return pt_stage_infos[st].coord[k]; }

/* "box v3", or for a point where the matrix camera clipped a segment
** "box s2 (clipped end 1)", into buf. */
static const char *who(const dctx *c, uint32_t model, uint64_t v, char *buf, size_t len)
{
    if (v & PT_TCLIPV)
        snprintf(buf, len, "%s s%" PRIu64 " (clipped end %d)", pt_names_get(&c->nm, model),
                 (v & ~PT_TCLIPV) >> 1, (int)(v & 1) + 1);
    else
        snprintf(buf, len, "%s v%" PRIu64, pt_names_get(&c->nm, model), v);
    return buf;
}

/* 1 when |x| < 2^62: sums and differences of two such numbers, or one and a
** size, cannot overflow.  pipetrace's own integers always are (PT_PIX_LIMIT);
** a trace from elsewhere may hold anything. */
static int small(int64_t x)
{
    return x > -(INT64_C(1) << 62) && x < (INT64_C(1) << 62);
}

#define D_NULL 0x20u             /* stage_diff: one side has no value (bits 0-3: values) */
#define D_FLAG 0x40u             /* stage_diff: inside or behind differs */

/* Which parts of stage st differ between a and b: bit k for value k, D_NULL,
** D_FLAG.  0 when they agree. */
static unsigned stage_diff(const dctx *c, int st, const pt_tvrec *a, const pt_tvrec *b)
{
    unsigned m = 0;
    int k;

    if (is_real(st)) {
        for (k = 0; k < ncoord(st); k++)
            if (!same_real(c, a->u.d[k], b->u.d[k])) m |= 1u << k;
    } else if ((a->flags ^ b->flags) & PT_REC_NULL) {
        m |= D_NULL;
    } else if (!(a->flags & PT_REC_NULL)) {
        for (k = 0; k < ncoord(st); k++)
            if (a->u.n[k] != b->u.n[k]) m |= 1u << k;
    }
    if ((a->flags ^ b->flags) & (PT_REC_INSIDE | PT_REC_BEHIND)) m |= D_FLAG;
    return m;
}

/* Print the differing parts of stage st. */
static void print_stage_diff(int st, const pt_tvrec *a, const pt_tvrec *b, unsigned m)
{
    char b1[PT_NUMLEN], b2[PT_NUMLEN], b3[PT_NUMLEN];
    int k;

    for (k = 0; k < ncoord(st); k++) {
        if (!(m & (D_NULL | 1u << k))) continue;
        printf("    %-5s expected ", coord_name(st, k));
        if (is_real(st)) {
            printf("%s, actual %s", num(a->u.d[k], b1), num(b->u.d[k], b2));
            if (isfinite(a->u.d[k]) && isfinite(b->u.d[k]))
                printf(", difference %s", num(b->u.d[k] - a->u.d[k], b3));
        } else if (a->flags & PT_REC_NULL) {
            printf("none, actual %" PRId64, b->u.n[k]);
        } else if (b->flags & PT_REC_NULL) {
            printf("%" PRId64 ", actual none", a->u.n[k]);
        } else {
            printf("%" PRId64 ", actual %" PRId64, a->u.n[k], b->u.n[k]);
            if (small(a->u.n[k]) && small(b->u.n[k]))
                printf(", difference %+" PRId64, b->u.n[k] - a->u.n[k]);
        }
        printf("\n");
    }
    if ((a->flags ^ b->flags) & PT_REC_INSIDE)
        printf("    inside the viewport: expected %s, actual %s\n",
               a->flags & PT_REC_INSIDE ? "yes" : "no", b->flags & PT_REC_INSIDE ? "yes" : "no");
    if ((a->flags ^ b->flags) & PT_REC_BEHIND)
        printf("    behind the camera: expected %s, actual %s\n",
               a->flags & PT_REC_BEHIND ? "yes" : "no", b->flags & PT_REC_BEHIND ? "yes" : "no");
}

/* ===== known mistakes ===== */

/* What the formulas need from EXPECTED's header, for one vertex. */
typedef struct hctx {
    pt_stage_params par;         /* w, h, W, H, x_ul, y_ul, perspective, translation */
    int has_t;                   /* 1: the translation is known */
} hctx;

/* Range of one recomputed value over the inputs tried. */
typedef struct vrange {
    int any_finite, nan, pinf, ninf;    /* kinds of double seen */
    double lo, hi;               /* finite doubles */
    int any_null, any_value;     /* integer stages */
    int64_t ilo, ihi;
} vrange;

static void range_add(vrange *r, int real, const pt_cat_val *o, int k)
{
    if (real) {
        double x = o->d[k];
        if (isnan(x)) r->nan = 1;
        else if (isinf(x)) { if (x > 0) r->pinf = 1; else r->ninf = 1; }
        else if (!r->any_finite++) r->lo = r->hi = x;
        else { r->lo = fmin(r->lo, x); r->hi = fmax(r->hi, x); }
    } else if (o->null) {
        r->any_null = 1;
    } else {
        int64_t x = o->n[k];
        if (!r->any_value++) r->ilo = r->ihi = x;
        else { if (x < r->ilo) r->ilo = x; if (x > r->ihi) r->ihi = x; }
    }
}

/* Where to try an input x known to within +-s: x itself, both ends, and each
** tie k + 0.5 in between with its neighbouring doubles, where roundings change
** their minds (floor(x + 0.5) at 0.49999999999999994).  Returns the count. */
static int samples(double x, double s, double out[16])
{
    double t;
    int n = 0;

    out[n++] = x;
    if (!(s > 0) || !isfinite(x)) return n;
    out[n++] = x - s;
    out[n++] = x + s;
    for (t = floor(x - s) + 0.5; t <= x + s && n + 3 <= 16; t += 1) {
        if (t < x - s) continue;
        out[n++] = t;
        out[n++] = nextafter(t, -HUGE_VAL);
        out[n++] = nextafter(t, HUGE_VAL);
    }
    return n;
}

/* 1 when the ranges r[] of the mistake's results hold ACTUAL's record arec. */
static int in_ranges(const dctx *c, const vrange r[4], int st, const pt_tvrec *arec)
{
    int k;

    for (k = 0; k < ncoord(st); k++) {
        if (is_real(st)) {
            double a = arec->u.d[k], allow;
            if (isnan(a)) { if (!r[k].nan) return 0; continue; }
            if (isinf(a)) { if (!(a > 0 ? r[k].pinf : r[k].ninf)) return 0; continue; }
            if (!r[k].any_finite) return 0;
            allow = fmax(c->o->tol, c->o->rel * fmax(fabs(a), fmax(fabs(r[k].lo), fabs(r[k].hi))));
            allow += slack(c, 1, a);
            if (a < r[k].lo - allow || a > r[k].hi + allow) return 0;
        } else if (arec->flags & PT_REC_NULL) {
            if (!r[k].any_null) return 0;
        } else if (!r[k].any_value || arec->u.n[k] < r[k].ilo || arec->u.n[k] > r[k].ihi) {
            return 0;
        }
    }
    return 1;
}

/* 1 when mistake mk reproduces ACTUAL's record arec of stage st from the input
** in: EXPECTED's previous stage; *at_in gets the mistake's result for in, to
** show.  When in came from a text trace, each real input may be anywhere
** within in_slack[k] of its value, and the mistake's results over that box
** must hold arec:
**   - a real-valued stage: the box's corners and mid-points bound them (each
**     formula is monotone in each input, the sign of z_c aside);
**   - the viewport stage, whose x and y each depend on x_pp or y_pp alone:
**     the samples() of each, keeping only inputs that the right formula takes
**     to EXPECTED's own record erec (a tie printed "-2.500000" stays a tie).
** An integer input (framebuffer -> index) is exact. */
static int reproduces(const dctx *c, const pt_mistake *mk, const hctx *h, const pt_cat_val *in,
                      const double in_slack[3], int in_real, int st,
                      const pt_tvrec *erec, const pt_tvrec *arec, pt_cat_val *at_in)
{
    vrange r[4];
    pt_cat_val x, out, right;
    int k, p;

    memset(r, 0, sizeof r);
    memset(at_in, 0, sizeof *at_in);
    mk->apply(&h->par, in, at_in);
    if (!in_real) {
        for (k = 0; k < ncoord(st); k++) range_add(&r[k], is_real(st), at_in, k);
    } else if (is_real(st)) {
        int vary[3], nvary = 0, npts = 1;
        for (k = 0; k < 3; k++)
            if (in_slack[k] > 0) { vary[nvary++] = k; npts *= 3; }
        for (p = 0; p < npts; p++) {        /* offsets -1, 0, +1 of each input */
            int q = p, j;
            x = *in;
            for (j = 0; j < nvary; j++, q /= 3)
                x.d[vary[j]] += (q % 3 - 1) * in_slack[vary[j]];
            memset(&out, 0, sizeof out);
            mk->apply(&h->par, &x, &out);
            for (k = 0; k < ncoord(st); k++) range_add(&r[k], 1, &out, k);
        }
    } else {
        for (k = 0; k < ncoord(st); k++) {
            double v[16];
            int n = samples(in->d[k], in_slack[k], v);
            for (p = 0; p < n; p++) {
                x = *in;
                x.d[k] = v[p];
                memset(&right, 0, sizeof right);
                pt_cat_right(st, &h->par, &x, &right);
                if (right.null != ((erec->flags & PT_REC_NULL) != 0) ||
                    (!right.null && right.n[k] != erec->u.n[k])) continue;
                memset(&out, 0, sizeof out);
                mk->apply(&h->par, &x, &out);
                range_add(&r[k], 0, &out, k);
            }
        }
    }
    return in_ranges(c, r, st, arec);
}

/* Fill *h from EXPECTED's header for a vertex of model `model`; 0 when there is
** no header. */
static int hctx_of(const dctx *c, uint32_t model, hctx *h)
{
    const pt_thdr *hd = &c->t[0].hdr;

    if (!hd->have || hd->perspective < 0 || hd->vp_w < 1 || hd->vp_h < 1) return 0;
    h->par.w = hd->vp_w; h->par.h = hd->vp_h;
    h->par.W = hd->fb_w; h->par.H = hd->fb_h;
    h->par.x_ul = hd->vp_x; h->par.y_ul = hd->vp_y;
    h->par.perspective = hd->perspective;
    h->has_t = model < c->nm.n && c->has_tr[model];
    if (h->has_t) {
        h->par.translate.x = c->tr[model][0];
        h->par.translate.y = c->tr[model][1];
        h->par.translate.z = c->tr[model][2];
    }
    return 1;
}

/* EXPECTED's value of the stage before st for vertex e, into *in with the slack
** of each real value; *from gets the stage it came from.  A stage left out as
** the identity is replaced by the one before it (camera = model when the
** translation is 0 0 0; framebuffer = viewport when the viewport is at 0,0).
** Returns 0 when there is no such record. */
static int prev_value(const dctx *c, const vent *e, int st, const hctx *h,
                      pt_cat_val *in, double in_slack[3], int *from)
{
    int p = st - 1, k;
    uint32_t i;
    const pt_tvrec *r;

    if (p < 0) return 0;
    i = e->rec[0][p];
    if (i == NONE && p == PT_STAGE_CAMERA && h->has_t && h->par.translate.x == 0 &&
        h->par.translate.y == 0 && h->par.translate.z == 0)
        i = e->rec[0][p = PT_STAGE_MODEL];
    if (i == NONE && p == PT_STAGE_FRAMEBUFFER && h->par.x_ul == 0 && h->par.y_ul == 0)
        i = e->rec[0][p = PT_STAGE_VIEWPORT];
    if (i == NONE) return 0;
    r = &c->t[0].vx[i];
    memset(in, 0, sizeof *in);
    in_slack[0] = in_slack[1] = in_slack[2] = 0;
    if (is_real(p)) {
        for (k = 0; k < ncoord(p); k++) {
            in->d[k] = r->u.d[k];
            in_slack[k] = slack(c, 0, r->u.d[k]);
        }
    } else {
        in->null = (r->flags & PT_REC_NULL) != 0;
        for (k = 0; k < ncoord(p); k++) in->n[k] = r->u.n[k];
    }
    *from = p;
    return 1;
}

/* Append the values of stage st in *v to sb: "x_pp = 1.5, y_pp = 2". */
static void pt_cat_val_str(pbuf *sb, int st, const pt_cat_val *v)
{
    char b[PT_NUMLEN];
    int k;

    for (k = 0; k < ncoord(st); k++) {
        pb_add(sb, "%s%s = ", k ? ", " : "", coord_name(st, k));
        if (is_real(st)) pb_add(sb, "%s", num(v->d[k], b));
        else if (v->null) pb_add(sb, "none");
        else pb_add(sb, "%" PRId64, v->n[k]);
    }
}

/* Find the mistakes that reproduce the first difference of e at stage st,
** count them, and print them when `print`. */
static void explain(dctx *c, const vent *e, int st, int print)
{
    hctx h;
    pt_cat_val in, out;
    double in_slack[3];
    int from, found = 0;
    size_t k;
    const pt_tvrec *erec = &c->t[0].vx[e->rec[0][st]];
    const pt_tvrec *arec = &c->t[1].vx[e->rec[1][st]];
    const char *last = NULL;
    pbuf sb;

    memset(&h, 0, sizeof h);
    if (!hctx_of(c, e->model, &h)) {
        if (print) printf("    (no known mistake checked: %s)\n", c->t[0].hdr.have ?
                          "those known are the classic camera's" : "EXPECTED has no header");
        return;
    }
    if (st == PT_STAGE_MODEL) {
        if (print) printf("    (the model stage holds the scene's own numbers: are these "
                          "traces of one scene?)\n");
        return;
    }
    if (!prev_value(c, e, st, &h, &in, in_slack, &from)) {
        if (print) printf("    (no known mistake checked: EXPECTED has no %s record to "
                          "recompute from)\n", pt_stage_infos[st - 1].name);
        return;
    }
    for (k = 0; k < PT_NMISTAKES; k++) {
        const pt_mistake *mk = &pt_mistakes[k];
        if (mk->stage != st) continue;
        if (st == PT_STAGE_CAMERA && !h.has_t) continue;
        if (st == PT_STAGE_IMAGE && !h.par.perspective) continue;
        if (mk->odd_only && h.par.w % 2 == 0 && h.par.h % 2 == 0) continue;
        if (!reproduces(c, mk, &h, &in, in_slack, is_real(from), st, erec, arec, &out)) continue;
        if (last && !strcmp(last, mk->name)) continue;   /* a second form of the same */
        last = mk->name;
        found++;
        c->mk_hits[k]++;
        if (!print) continue;
        printf("    likely mistake: %s\n", mk->name);
        para("      ", mk->how);
        memset(&sb, 0, sizeof sb);
        pb_add(&sb, "check: the %s stage recomputed with it from EXPECTED's %s record (",
               pt_stage_infos[st].name, pt_stage_infos[from].name);
        pt_cat_val_str(&sb, from, &in);
        pb_add(&sb, ") gives ");
        pt_cat_val_str(&sb, st, &out);
        pb_add(&sb, ", as ACTUAL has%s.", c->t[0].prec >= 0 || c->t[1].prec >= 0 ?
               " (within the printed digits)" : "");
        para("      ", sb.b);
    }
    if (!found) {
        if (print) printf("    no known mistake reproduces this from EXPECTED's %s record\n",
                          pt_stage_infos[from].name);
    }
}

/* Compare one vertex present on both sides, stage by stage in pipeline order. */
static void compare_vertex(dctx *c, const vent *e)
{
    int k, st, first = -1, nlater = 0;
    unsigned m = 0, later = 0;
    const pt_tvrec *a = NULL, *b = NULL;
    char name[128];

    for (k = 0; k < PT_NSTAGES_ALL; k++) {
        uint32_t i, j;
        unsigned d;
        st = pt_trace_order[k];
        i = e->rec[0][st];
        j = e->rec[1][st];
        if (i == NONE || j == NONE) {       /* a silent stage, or one left out */
            int lacking = i == NONE ? 0 : 1;    /* the side without it */
            if (i == NONE && j == NONE) continue;
            if (c->silent[lacking][e->model] & 1u << st) c->silent_recs[lacking][st]++;
            else c->stage_only[!lacking][st]++;
            continue;
        }
        d = stage_diff(c, st, &c->t[0].vx[i], &c->t[1].vx[j]);
        if (!d) continue;
        if (first < 0) {
            first = st;
            m = d;
            a = &c->t[0].vx[i];
            b = &c->t[1].vx[j];
        } else {
            later |= 1u << st;
        }
    }
    if (first < 0) {
        c->agree++;
        c->agree_clip += (e->v & PT_TCLIPV) != 0;
        return;
    }
    c->differ++;
    c->differ_clip += (e->v & PT_TCLIPV) != 0;
    c->first_at[first]++;
    if (c->shown >= c->o->show) { explain(c, e, first, 0); return; }
    c->shown++;
    printf("%s: differs first at %s", who(c, e->model, e->v, name, sizeof name),
           pt_stage_infos[first].name);
    for (k = 0; k < PT_NSTAGES_ALL; k++)
        if (later & 1u << pt_trace_order[k])
            printf("%s%s", nlater++ ? ", " : ", later at ", pt_stage_infos[pt_trace_order[k]].name);
    printf("\n");
    print_stage_diff(first, a, b, m);
    for (k = 0; k < PT_NSTAGES_ALL && (int)pt_trace_order[k] != first; k++) {
        int sd;
        for (sd = 0; sd < 2; sd++)
            if (c->silent[sd][e->model] & 1u << pt_trace_order[k])
                printf("    but %s has no %s record: that stage did not report, and the "
                       "difference may start there\n", side_name[sd],
                       pt_stage_infos[pt_trace_order[k]].name);
    }
    explain(c, e, first, 1);
}

/* ===== pixels ===== */

/* A pixel record's place, for sorting by position. */
typedef struct pkey {
    int64_t y, x, i;             /* sort keys */
    size_t k;                    /* index into px[] */
} pkey;

static int pkey_cmp(const void *pa, const void *pb)
{
    const pkey *a = pa, *b = pb;

    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->i != b->i) return a->i < b->i ? -1 : 1;
    return a->k < b->k ? -1 : a->k > b->k;
}

/* A raster record (pixel or clip) in its segment, for sorting by segment. */
typedef struct skey {
    uint64_t seg;                /* 1-based segment */
    uint32_t model;              /* name id */
    int clip;                    /* 1: cl[k], 0: px[k] */
    size_t order;                /* place in the file: 2 npix (clip), 2 k + 1 (pixel) */
    size_t k;                    /* index */
} skey;

/* Order of the segments of a and b: model id, then segment number. */
static int seg_cmp(const skey *a, const skey *b)
{
    if (a->model != b->model) return a->model < b->model ? -1 : 1;
    if (a->seg != b->seg) return a->seg < b->seg ? -1 : 1;
    return 0;
}

static int skey_cmp(const void *pa, const void *pb)
{
    const skey *a = pa, *b = pb;
    int c = seg_cmp(a, b);

    if (c) return c;
    return a->order < b->order ? -1 : a->order > b->order;
}

static size_t pix_hash(int64_t x, int64_t y, int64_t i)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15u ^ (uint64_t)y * 0xC2B2AE3D27D4EB4Fu ^
                 (uint64_t)i * 0x165667B19E3779F9u;
    h ^= h >> 31;
    return (size_t)h;
}

/* The distinct pixels (x, y, i) of t sorted by position, each with its first
** record's index.  A hash set drops the repeats first (a pixel lit by many
** segments), so only distinct pixels are sorted: at most the framebuffer's
** worth however long the trace. */
static pkey *sorted_pixels(const pt_tread *t, size_t *n)
{
    size_t nslot = 1024, m = 0, cap = 256, k, j;
    uint32_t *slot = calloc(nslot, sizeof *slot);
    pkey *p = malloc(cap * sizeof *p);

    if (!slot || !p || t->npx >= UINT32_MAX) goto fail;
    for (k = 0; k < t->npx; k++) {
        const pt_tpix *x = &t->px[k];
        size_t h = pix_hash(x->x, x->y, x->i) & (nslot - 1);
        for (; slot[h]; h = (h + 1) & (nslot - 1)) {
            const pkey *q = &p[slot[h] - 1];
            if (q->x == x->x && q->y == x->y && q->i == x->i) break;
        }
        if (slot[h]) continue;              /* seen */
        if (m == cap) {
            pkey *np = realloc(p, 2 * cap * sizeof *np);
            if (!np) goto fail;
            p = np;
            cap *= 2;
        }
        p[m].x = x->x; p[m].y = x->y; p[m].i = x->i; p[m].k = k;
        slot[h] = (uint32_t)++m;
        if (2 * m >= nslot) {               /* grow and rehash */
            uint32_t *ns = calloc(2 * nslot, sizeof *ns);
            if (!ns) goto fail;
            nslot *= 2;
            for (j = 0; j < m; j++) {
                h = pix_hash(p[j].x, p[j].y, p[j].i) & (nslot - 1);
                while (ns[h]) h = (h + 1) & (nslot - 1);
                ns[h] = (uint32_t)j + 1;
            }
            free(slot);
            slot = ns;
        }
    }
    free(slot);
    qsort(p, m, sizeof *p, pkey_cmp);
    *n = m;
    return p;
fail:
    free(slot);
    free(p);
    return NULL;
}

/* The raster records of t sorted by segment, in step order within each. */
static skey *sorted_steps(const pt_tread *t, size_t *n)
{
    size_t k, m = 0;
    skey *s = malloc((t->npx + t->ncl ? t->npx + t->ncl : 1) * sizeof *s);

    if (!s) return NULL;
    for (k = 0; k < t->npx; k++, m++) {
        s[m].seg = t->px[k].seg; s[m].model = t->px[k].model;
        s[m].clip = 0; s[m].order = 2 * k + 1; s[m].k = k;
    }
    for (k = 0; k < t->ncl; k++, m++) {
        s[m].seg = t->cl[k].seg; s[m].model = t->cl[k].model;
        s[m].clip = 1; s[m].order = 2 * t->cl[k].npix; s[m].k = k;
    }
    qsort(s, m, sizeof *s, skey_cmp);
    *n = m;
    return s;
}

/* The pixels of one segment in viewport coordinates, step order. */
typedef struct plist {
    int64_t (*p)[2];             /* owned */
    size_t n, cap;
    int oom;                     /* 1: plist_add failed while replaying */
} plist;

static int plist_add(plist *l, int64_t x, int64_t y)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        int64_t (*np)[2] = realloc(l->p, cap * sizeof *np);
        if (!np) return -1;
        l->p = np;
        l->cap = cap;
    }
    l->p[l->n][0] = x;
    l->p[l->n][1] = y;
    l->n++;
    return 0;
}

static void replay_pixel(void *ud, int64_t x, int64_t y)
{
    plist *l = ud;
    if (plist_add(l, x, y) != 0) l->oom = 1;
}

static void replay_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    (void)ud; (void)count; (void)first; (void)last;
}

/* Run the rasterizer again, each step's pixel found by to_vp, for the segment
** whose rounded endpoints are ends[] = X0 Y0 X1 Y1 (logical pixels), in a w x h
** viewport; the pixels it writes go to *out in step order.  Returns 0, or -1
** when out of memory. */
static int replay(const int64_t ends[4], int w, int h, pt_raster_vp to_vp, plist *out)
{
    pt_vec2 p0, p1;
    pt_raster_out ro;

    p0.x = (double)ends[0]; p0.y = (double)ends[1];
    p1.x = (double)ends[2]; p1.y = (double)ends[3];
    ro.pixel = replay_pixel;
    ro.clip = replay_clip;
    ro.ud = out;
    out->n = 0;
    out->oom = 0;
    pt_raster_segment(p0, p1, w, h, to_vp, &ro);
    return out->oom ? -1 : 0;
}

static int plist_eq(const plist *a, const plist *b)
{
    return a->n == b->n && (a->n == 0 || memcmp(a->p, b->p, a->n * sizeof *a->p) == 0);
}

/* What the raster check found. */
typedef struct rstat {
    size_t segs_differ;          /* segments whose pixels differ */
    size_t hits[PT_NRASTER_MISTAKES];        /* ... that each rounding mistake reproduces */
    int first_set;               /* 1: first_* below are set */
    uint32_t first_model;        /* the first differing segment */
    uint64_t first_seg;
    int64_t ends[4];             /* its rounded endpoints X0 Y0 X1 Y1 */
    int ends_ok;                 /* 1: ends verified by replaying EXPECTED */
} rstat;

/* Segment by segment: which differ, and which rounding mistake of the
** rasterizer reproduces ACTUAL's pixels from EXPECTED's endpoints. */
static int check_raster(dctx *c, rstat *rs)
{
    const pt_thdr *hd = &c->t[0].hdr;
    size_t n[2], k[2] = {0, 0}, j;
    skey *s[2];
    plist pl[2] = {{NULL, 0, 0, 0}, {NULL, 0, 0, 0}}, re = {NULL, 0, 0, 0};
    int side, rc = 0;

    memset(rs, 0, sizeof *rs);
    s[0] = sorted_steps(&c->t[0], &n[0]);
    s[1] = sorted_steps(&c->t[1], &n[1]);
    if (!s[0] || !s[1]) rc = -1;
    while (rc == 0 && (k[0] < n[0] || k[1] < n[1])) {
        uint32_t model;
        uint64_t seg;
        size_t beg[2], end[2];
        int64_t ends[4];
        int have_ends = 0, ok = 0, sane = 1;    /* sane: every coordinate small() */

        /* the next segment of either list: the smaller (model, seg) */
        side = k[1] >= n[1] ? 0 : k[0] >= n[0] ? 1 : seg_cmp(&s[0][k[0]], &s[1][k[1]]) <= 0 ? 0 : 1;
        model = s[side][k[side]].model;
        seg = s[side][k[side]].seg;
        for (side = 0; side < 2; side++) {
            beg[side] = k[side];
            pl[side].n = 0;
            while (k[side] < n[side] && s[side][k[side]].model == model &&
                   s[side][k[side]].seg == seg) {
                const skey *q = &s[side][k[side]++];
                if (!q->clip) {
                    const pt_tpix *p = &c->t[side].px[q->k];
                    if (!small(p->x) || !small(p->y)) sane = 0;
                    else if (plist_add(&pl[side], p->x - hd->vp_x, p->y - hd->vp_y) != 0)
                        rc = -1;
                } else if (!small(c->t[side].cl[q->k].first[0]) ||
                           !small(c->t[side].cl[q->k].first[1]) ||
                           !small(c->t[side].cl[q->k].last[0]) ||
                           !small(c->t[side].cl[q->k].last[1])) {
                    sane = 0;
                }
            }
            end[side] = k[side];
        }
        if (rc != 0 || plist_eq(&pl[0], &pl[1])) continue;
        /* rounded endpoints: EXPECTED's first and last steps, as logical pixels;
        ** a viewport beyond PT_MAX_SIZE is no trace of pipetrace's: not replayed */
        if (end[0] > beg[0] && sane && hd->vp_w >= 1 && hd->vp_h >= 1 &&
            hd->vp_w <= PT_MAX_SIZE && hd->vp_h <= PT_MAX_SIZE) {
            const skey *f = &s[0][beg[0]], *l = &s[0][end[0] - 1];
            int64_t fx, fy, lx, ly;
            if (f->clip) { fx = c->t[0].cl[f->k].first[0]; fy = c->t[0].cl[f->k].first[1]; }
            else { fx = c->t[0].px[f->k].x - hd->vp_x; fy = c->t[0].px[f->k].y - hd->vp_y; }
            if (l->clip) { lx = c->t[0].cl[l->k].last[0]; ly = c->t[0].cl[l->k].last[1]; }
            else { lx = c->t[0].px[l->k].x - hd->vp_x; ly = c->t[0].px[l->k].y - hd->vp_y; }
            ends[0] = fx + 1; ends[1] = hd->vp_h - fy;
            ends[2] = lx + 1; ends[3] = hd->vp_h - ly;
            have_ends = 1;
            if (replay(ends, hd->vp_w, hd->vp_h, pt_pixel2viewport, &re))
                rc = -1;
            ok = rc == 0 && plist_eq(&re, &pl[0]);
        }
        if (!rs->first_set) {
            rs->first_set = 1;
            rs->first_model = model;
            rs->first_seg = seg;
            if (have_ends) memcpy(rs->ends, ends, sizeof ends);
            rs->ends_ok = ok;
        }
        rs->segs_differ++;
        for (j = 0; ok && rc == 0 && j < PT_NRASTER_MISTAKES; j++) {
            if (replay(ends, hd->vp_w, hd->vp_h, pt_raster_mistakes[j].to_vp, &re)) rc = -1;
            else if (plist_eq(&re, &pl[1])) rs->hits[j]++;
        }
    }
    free(s[0]);
    free(s[1]);
    free(pl[0].p);
    free(pl[1].p);
    free(re.p);
    return rc;
}

/* Compare the sets of lit pixels: count the missing and extra ones into
** *nmiss and *nextra, and list a few of each.  nlit[s]: distinct pixels of
** side s. */
static int compare_pixels(dctx *c, size_t *nmiss, size_t *nextra, size_t nlit[2])
{
    pkey *p[2];
    size_t n[2], count[2] = {0, 0};
    int pass;

    p[0] = sorted_pixels(&c->t[0], &n[0]);
    p[1] = sorted_pixels(&c->t[1], &n[1]);
    if (!p[0] || !p[1]) { free(p[0]); free(p[1]); return -1; }
    nlit[0] = n[0];
    nlit[1] = n[1];
    /* pass 0 counts; pass 1 lists the missing, pass 2 the extra ones */
    for (pass = 0; pass < 3; pass++) {
        size_t a = 0, b = 0, shown = 0;
        int want = pass - 1;                /* the side listed: 0 missing, 1 extra */
        if (pass == 1 && (count[0] || count[1]))
            printf("Lit pixels: %zu in EXPECTED, %zu in ACTUAL.\n", n[0], n[1]);
        if (pass && !count[want]) continue;
        if (pass) printf("  %s in ACTUAL: %zu\n", want ? "extra" : "missing", count[want]);
        while ((a < n[0] || b < n[1]) && (pass == 0 || shown < c->o->show)) {
            int side, cmp = a >= n[0] ? 1 : b >= n[1] ? -1 : 0;
            const pkey *q;
            if (!cmp) {
                pkey x = p[0][a], y = p[1][b];
                x.k = y.k = 0;
                cmp = pkey_cmp(&x, &y);
            }
            if (!cmp) { a++; b++; continue; }
            side = cmp < 0 ? 0 : 1;
            q = side ? &p[1][b++] : &p[0][a++];
            if (pass == 0) { count[side]++; continue; }
            if (side == want) {
                const pt_tpix *x = &c->t[side].px[q->k];
                printf("    (x_fb, y_fb) = (%" PRId64 ", %" PRId64 "), idx %" PRId64
                       ", from %s s%" PRIu64 "\n", x->x, x->y, x->i,
                       pt_names_get(&c->nm, x->model), x->seg);
                shown++;
            }
        }
        if (pass && count[want] > shown) printf("    ... and %zu more\n", count[want] - shown);
    }
    *nmiss = count[0];
    *nextra = count[1];
    free(p[0]);
    free(p[1]);
    return 0;
}

/* ===== headers ===== */

/* Print how the headers differ; returns 1 when they do. */
static int compare_headers(const dctx *c)
{
    const pt_thdr *a = &c->t[0].hdr, *b = &c->t[1].hdr;
    int differ = 0;
    size_t k;

    if (!a->have || !b->have) return 0;
    if (a->fb_w != b->fb_w || a->fb_h != b->fb_h) {
        printf("header: framebuffer %d x %d in EXPECTED, %d x %d in ACTUAL\n",
               a->fb_w, a->fb_h, b->fb_w, b->fb_h);
        differ = 1;
    }
    if (a->vp_x != b->vp_x || a->vp_y != b->vp_y || a->vp_w != b->vp_w || a->vp_h != b->vp_h) {
        printf("header: viewport %d x %d at (%d, %d) in EXPECTED, %d x %d at (%d, %d) in ACTUAL\n",
               a->vp_w, a->vp_h, a->vp_x, a->vp_y, b->vp_w, b->vp_h, b->vp_x, b->vp_y);
        differ = 1;
    }
    if (a->perspective != b->perspective) {
        static const char *const cam[3] = {"lookat", "orthographic", "perspective"};
        printf("header: camera %s in EXPECTED, %s in ACTUAL\n", cam[a->perspective + 1],
               cam[b->perspective + 1]);
        differ = 1;
    }
    for (k = 0; k < a->nmodels || k < b->nmodels; k++) {
        const pt_tmodel *ma = k < a->nmodels ? &a->models[k] : NULL;
        const pt_tmodel *mb = k < b->nmodels ? &b->models[k] : NULL;
        if (!ma || !mb || ma->name != mb->name) {
            printf("header: model %zu is %s in EXPECTED, %s in ACTUAL\n", k + 1,
                   ma ? pt_names_get(&c->nm, ma->name) : "missing",
                   mb ? pt_names_get(&c->nm, mb->name) : "missing");
            differ = 1;
        } else if (!same_real(c, ma->t[0], mb->t[0]) || !same_real(c, ma->t[1], mb->t[1]) ||
                   !same_real(c, ma->t[2], mb->t[2])) {
            char b1[PT_NUMLEN], b2[PT_NUMLEN], b3[PT_NUMLEN];
            printf("header: model %s is translated by %s %s %s in EXPECTED", pt_names_get(&c->nm,
                   ma->name), num(ma->t[0], b1), num(ma->t[1], b2), num(ma->t[2], b3));
            printf(", by %s %s %s in ACTUAL\n", num(mb->t[0], b1), num(mb->t[1], b2),
                   num(mb->t[2], b3));
            differ = 1;
        }
    }
    if (differ) printf("The headers differ: these may be traces of different scenes.\n\n");
    return differ;
}

/* ===== the trace diff ===== */

static const char *format_name(const pt_tread *t)
{
    return t->kind == PT_TK_JSONL ? "JSON Lines" : "text";
}

static void print_intro(const dctx *c)
{
    char b1[PT_NUMLEN], b2[PT_NUMLEN];
    pbuf sb;
    int s;

    for (s = 0; s < 2; s++) {
        const pt_tread *t = &c->t[s];
        printf("%-9s %s  (%s", side_name[s], c->o->path[s], format_name(t));
        if (t->prec >= 0) printf(", %d decimals", t->prec);
        printf(": %zu vertex, %zu pixel records)\n", t->nvx, t->npx);
    }
    memset(&sb, 0, sizeof sb);
    printf("Integers must be equal; doubles a and b agree when\n"
           "  |a - b| <= max(%s, %s * max(|a|, |b|))\n", num(c->o->tol, b1), num(c->o->rel, b2));
    if (c->t[0].prec >= 0 || c->t[1].prec >= 0) {
        pb_add(&sb, "plus half a unit in the last printed digit of a text trace (");
        for (s = 0; s < 2; s++) {
            if (c->t[s].prec < 0) continue;
            pb_add(&sb, "%s%s: %s", s && c->t[0].prec >= 0 ? ", " : "", side_name[s],
                   num(0.5 * pow(10.0, -c->t[s].prec), b1));
        }
        pb_add(&sb, "): the text format prints only --precision decimals.");
        para("", sb.b);
    }
    printf("\n");
}

/* Fill the vertex table from both sides.  Returns 0, 2 on a duplicate record
** (message printed), -1 when out of memory. */
static int fill_table(dctx *c)
{
    int s;
    size_t k;

    for (s = 0; s < 2; s++) {
        for (k = 0; k < c->t[s].nvx; k++) {
            const pt_tvrec *r = &c->t[s].vx[k];
            vent *e;
            if (k >= NONE) return -1;
            if (!(e = vt_get(&c->vt, r->model, r->v))) return -1;
            if (e->rec[s][r->stage] != NONE) {
                char name[128];
                fprintf(stderr, "%s:%" PRIu32 ":1: error: a second %s record for %s (the "
                        "first is on line %" PRIu32 ")\n", c->o->path[s], r->line,
                        pt_stage_infos[r->stage].name, who(c, r->model, r->v, name, sizeof name),
                        c->t[s].vx[e->rec[s][r->stage]].line);
                return PT_EXIT_INPUT;
            }
            e->rec[s][r->stage] = (uint32_t)k;
        }
    }
    return 0;
}

/* EXPECTED's translations by model id. */
static int fill_translations(dctx *c)
{
    const pt_thdr *hd = &c->t[0].hdr;
    size_t k, n = c->nm.n ? c->nm.n : 1;

    c->tr = calloc(n, sizeof *c->tr);
    c->has_tr = calloc(n, 1);
    if (!c->tr || !c->has_tr) return -1;
    for (k = 0; k < hd->nmodels; k++) {
        memcpy(c->tr[hd->models[k].name], hd->models[k].t, sizeof *c->tr);
        c->has_tr[hd->models[k].name] = 1;
    }
    return 0;
}

/* The stage files a student replaces, for the message on a silent stage. */
static const char *stage_file(const dctx *c, int st)
{
    static const char *const file[PT_NSTAGES_ALL] = {
        "stages/pt_classic.c", "stages/s1_model2camera.c", "stages/s2_camera2image.c",
        "stages/s3_image2pixel.c", "stages/s4_pixel2viewport.c", "stages/s5_viewport2fb.c",
        "stages/s6_fb2index.c", "stages/m1_model2world.c", "stages/m2_world2view.c",
        "stages/m3_view2clip.c", "stages/m4_clip2cvv.c", "stages/m5_clip2ndc.c",
        "stages/m6_ndc2screen.c",
    };
    if (st == PT_STAGE_VIEWPORT && c->t[0].hdr.perspective < 0)
        return "stages/m7_screen2viewport.c";       /* the matrix camera floors */
    return file[st];
}

/* Find the silent stages: for each model, a stage that side s lacks entirely
** while it has records of other stages of that model, the other side has
** records of it, and s's header does not leave it out.  A stage left out on
** purpose (an identity, --stage) is in the header; a student stage that forgot
** to call pt_emit() is not.  Returns 0, or -1 when out of memory. */
static int find_silent(dctx *c)
{
    size_t n = c->nm.n ? c->nm.n : 1, k, m;
    unsigned *has[2];
    int s;

    has[0] = calloc(n, sizeof *has[0]);
    has[1] = calloc(n, sizeof *has[1]);
    c->silent[0] = calloc(n, sizeof *c->silent[0]);
    c->silent[1] = calloc(n, sizeof *c->silent[1]);
    if (!has[0] || !has[1] || !c->silent[0] || !c->silent[1]) {
        free(has[0]);
        free(has[1]);
        return -1;
    }
    for (s = 0; s < 2; s++)
        for (k = 0; k < c->t[s].nvx; k++)
            has[s][c->t[s].vx[k].model] |= 1u << c->t[s].vx[k].stage;
    for (s = 0; s < 2; s++) {
        const pt_thdr *h = &c->t[s].hdr;
        for (k = 0; k < h->nmodels; k++) {
            const pt_tmodel *tm = &h->models[k];
            m = tm->name;
            if (!tm->left_known || !has[s][m]) continue;
            c->silent[s][m] = has[!s][m] & ~has[s][m] & ~tm->left_out;
        }
    }
    free(has[0]);
    free(has[1]);
    return 0;
}

/* A silent stage, said plainly: it explains every later difference. */
static void report_silent(const dctx *c)
{
    int s, st;
    pbuf sb;

    for (s = 0; s < 2; s++)
        for (st = 0; st < PT_NSTAGES_ALL; st++) {
            if (!c->silent_recs[s][st]) continue;
            memset(&sb, 0, sizeof sb);
            pb_add(&sb, "%s has no %s records: the stage did not report them. %s's header "
                   "does not leave the %s stage out, and %s has %zu of them. A stage reports "
                   "its record through the trace interface, pt_emit(sink, &r), as %s does "
                   "(docs/teaching.md); its values were not compared, and a difference in a "
                   "later stage may start there.", side_name[s], pt_stage_infos[st].name,
                   side_name[s], pt_stage_infos[st].name, side_name[!s],
                   c->silent_recs[s][st], stage_file(c, st));
            para("", sb.b);
            printf("\n");
        }
}

/* The side-only vertices: count them and list a few. */
static void report_one_sided(dctx *c)
{
    int s, st;
    size_t k;

    for (s = 0; s < 2; s++) {
        size_t listed = 0;
        for (k = 0; k < c->vt.n; k++) {
            const vent *e = &c->vt.e[k];
            int here = 0, there = 0;
            for (st = 0; st < PT_NSTAGES_ALL; st++) {
                here |= e->rec[s][st] != NONE;
                there |= e->rec[!s][st] != NONE;
            }
            if (!here || there) continue;
            if (c->only[s]++ == 0) printf("only in %s:", side_name[s]);
            if (listed < c->o->show) {
                char name[128];
                printf("%s %s", listed ? "," : "", who(c, e->model, e->v, name, sizeof name));
                listed++;
            }
        }
        if (c->only[s] > listed) printf(", ... (%zu in all)", c->only[s]);
        if (c->only[s]) printf("\n\n");
    }
}

/* A note on stages only one trace holds: they are not compared. */
static void report_stage_only(const dctx *c)
{
    int s, st, any = 0;

    for (s = 0; s < 2; s++)
        for (st = 0; st < PT_NSTAGES_ALL; st++) {
            if (!c->stage_only[s][st]) continue;
            printf("%s %s records are only in %s (%zu)", any ? ";" : "Not compared:",
                   pt_stage_infos[st].name, side_name[s], c->stage_only[s][st]);
            any = 1;
        }
    if (any) printf(".\n\n");
}

/* 1 when a stage of either side did not report (find_silent). */
static int silent_any(const dctx *c)
{
    int s, st;

    for (s = 0; s < 2; s++)
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (c->silent_recs[s][st]) return 1;
    return 0;
}

/* "vertices", or with clip points of the matrix camera among them "points
** (3 vertices, 2 clip points)"; with `parts` the parts that agree: "points
** (3 of 3 vertices, 0 of 2 clip points)". */
static void points(pbuf *s, const dctx *c, int parts)
{
    size_t nclip = c->agree_clip + c->differ_clip, nv = c->agree + c->differ - nclip;

    if (!nclip) { pb_add(s, "vertices"); return; }
    if (parts)
        pb_add(s, "points (%zu of %zu vertices, %zu of %zu clip points)",
               c->agree - c->agree_clip, nv, c->agree_clip, nclip);
    else
        pb_add(s, "points (%zu vertices, %zu clip points)", nv, nclip);
}

/* The summary paragraph; returns the exit status. */
static int summarize(dctx *c, int hdr_differ, size_t nmiss, size_t nextra,
                     const size_t nlit[2], int pixels_compared, const rstat *rs)
{
    pbuf s;
    size_t total = c->agree + c->differ, k;
    int st, top = -1, differ;

    memset(&s, 0, sizeof s);
    differ = hdr_differ || c->differ || c->only[0] || c->only[1] || nmiss || nextra ||
             silent_any(c);
    if (!differ) {
        pb_add(&s, "The traces agree: %zu of %zu ", total, total);
        points(&s, c, 0);
        pb_add(&s, " at every stage both hold");
        if (pixels_compared) pb_add(&s, ", and the same %zu lit pixel%s.", nlit[0], nlit[0] == 1 ? "" : "s");
        else pb_add(&s, ".");
        para("", s.b);
        return PT_EXIT_OK;
    }
    for (k = 0; k < 2; k++)
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (c->silent_recs[k][st])
                pb_add(&s, "%s has no %s records: the stage did not report them. ",
                       side_name[k], pt_stage_infos[st].name);
    if (total) {
        pb_add(&s, "%zu of %zu ", c->agree, total);
        points(&s, c, 1);
        pb_add(&s, " agree%s", c->agree == 1 ? "s" : "");
    } else pb_add(&s, "No vertex is in both traces");
    if (c->differ) pb_add(&s, ", %zu differ%s", c->differ, c->differ > 1 ? "" : "s");
    if (c->only[0])
        pb_add(&s, ", %zu %s only in EXPECTED", c->only[0], c->only[0] > 1 ? "are" : "is");
    if (c->only[1]) pb_add(&s, ", %zu only in ACTUAL", c->only[1]);
    pb_add(&s, ".");
    for (st = 0; st < PT_NSTAGES_ALL; st++)
        if (c->first_at[st] && (top < 0 || c->first_at[st] > c->first_at[top])) top = st;
    if (top >= 0) {
        size_t best = PT_NMISTAKES;
        int quiet = -1;                     /* a silent stage before top */
        for (k = 0; k < PT_NSTAGES_ALL && (int)pt_trace_order[k] != top; k++)
            if (c->silent_recs[0][pt_trace_order[k]] || c->silent_recs[1][pt_trace_order[k]])
                quiet = pt_trace_order[k];
        pb_add(&s, " The stage that goes wrong first most often is %s (%zu of %zu)",
               pt_stage_infos[top].name, c->first_at[top], c->differ);
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (st != top && c->first_at[st])
                pb_add(&s, "; %s first for %zu", pt_stage_infos[st].name, c->first_at[st]);
        pb_add(&s, ".");
        if (quiet >= 0)
            pb_add(&s, " But the %s stage before it did not report, so the mistake may be "
                   "there, not in the %s stage.", pt_stage_infos[quiet].name,
                   pt_stage_infos[top].name);
        for (k = 0; k < PT_NMISTAKES; k++)
            if (pt_mistakes[k].stage == top && c->mk_hits[k] &&
                (best == PT_NMISTAKES || c->mk_hits[k] > c->mk_hits[best])) best = k;
        if (best < PT_NMISTAKES) {
            size_t hits = 0;
            for (k = 0; k < PT_NMISTAKES; k++)
                if (!strcmp(pt_mistakes[k].name, pt_mistakes[best].name)) hits += c->mk_hits[k];
            pb_add(&s, " Likely mistake there: %s, which reproduces ACTUAL", pt_mistakes[best].name);
            if (hits < c->first_at[top])
                pb_add(&s, " for %zu of those %zu vertices.", hits, c->first_at[top]);
            else if (hits > 2) pb_add(&s, " for all %zu.", hits);
            else if (hits == 2) pb_add(&s, " for both.");
            else pb_add(&s, ".");
        } else if (c->t[0].hdr.perspective < 0) {
            pb_add(&s, " The known mistakes are the classic camera's: none was checked.");
        } else {
            pb_add(&s, " No known mistake reproduces ACTUAL there.");
        }
    }
    if (hdr_differ) pb_add(&s, " The headers differ.");
    if (pixels_compared && (nmiss || nextra)) {
        int vertices_differ = c->differ || c->only[0] || c->only[1] || silent_any(c);
        pb_add(&s, " %s lit pixels differ%s: %zu in EXPECTED, %zu in ACTUAL (%zu missing, "
               "%zu extra)", vertices_differ ? "The" : "But the", vertices_differ ? " too" : "",
               nlit[0], nlit[1], nmiss, nextra);
        if (vertices_differ) pb_add(&s, ", as a consequence.");
        else if (rs->segs_differ) {
            size_t best = PT_NRASTER_MISTAKES;
            pb_add(&s, ", so the rasterizer differs, in %zu segment%s.",
                   rs->segs_differ, rs->segs_differ > 1 ? "s" : "");
            for (k = 0; k < PT_NRASTER_MISTAKES; k++)
                if (rs->hits[k] && (best == PT_NRASTER_MISTAKES || rs->hits[k] > rs->hits[best])) best = k;
            if (best < PT_NRASTER_MISTAKES) {
                pb_add(&s, " Likely mistake: %s in the rasterizer's rounding (pt_pix_round in "
                       "s4), which reproduces ACTUAL's pixels", pt_raster_mistakes[best].name);
                if (rs->hits[best] < rs->segs_differ)
                    pb_add(&s, " for %zu of those segments.", rs->hits[best]);
                else pb_add(&s, ".");
            } else {
                pb_add(&s, " No known mistake of its rounding reproduces them.");
            }
        } else {
            pb_add(&s, ".");
        }
    } else if (pixels_compared) {
        pb_add(&s, " Both light the same %zu pixel%s.", nlit[0], nlit[0] == 1 ? "" : "s");
    }
    para("", s.b);
    return PT_EXIT_DIFFER;
}

/* Print the raster check's details for the first differing segment. */
static void report_raster(const dctx *c, const rstat *rs)
{
    pbuf sb;
    size_t k;

    if (!rs->first_set) return;
    memset(&sb, 0, sizeof sb);
    if (rs->segs_differ == 1)
        pb_add(&sb, "Every vertex agrees, so the rasterizer differs: segment %s s%" PRIu64
               " lights other pixels.", pt_names_get(&c->nm, rs->first_model), rs->first_seg);
    else
        pb_add(&sb, "Every vertex agrees, so the rasterizer differs: %zu segments light other "
               "pixels, the first %s s%" PRIu64 ".", rs->segs_differ,
               pt_names_get(&c->nm, rs->first_model), rs->first_seg);
    if (!rs->ends_ok)
        pb_add(&sb, " Its endpoints cannot be read off EXPECTED's steps, so no mistake was "
               "checked.");
    para("  ", sb.b);
    for (k = 0; rs->ends_ok && k < PT_NRASTER_MISTAKES; k++) {
        if (!rs->hits[k]) continue;
        printf("  likely mistake: %s\n", pt_raster_mistakes[k].name);
        para("    ", pt_raster_mistakes[k].how);
        memset(&sb, 0, sizeof sb);
        pb_add(&sb, "check: the DDA run again from the rounded endpoints (%" PRId64 ", %" PRId64
               ") and (%" PRId64 ", %" PRId64 ") lights EXPECTED's pixels with Math.round and "
               "ACTUAL's with it", rs->ends[0], rs->ends[1], rs->ends[2], rs->ends[3]);
        if (rs->segs_differ > 1)
            pb_add(&sb, "; so it does for %zu of the %zu segments", rs->hits[k], rs->segs_differ);
        pb_add(&sb, ".");
        para("    ", sb.b);
    }
}

static int trace_diff(dctx *c)
{
    size_t k, nmiss = 0, nextra = 0, nlit[2] = {0, 0};
    int rc, hdr_differ, pixels_compared;
    rstat rs;

    memset(&rs, 0, sizeof rs);
    rc = fill_table(c);
    if (rc) return rc;
    if (fill_translations(c) != 0 || find_silent(c) != 0) return -1;
    c->mk_hits = calloc(PT_NMISTAKES, sizeof *c->mk_hits);
    if (!c->mk_hits) return -1;

    print_intro(c);
    hdr_differ = compare_headers(c);
    for (k = 0; k < c->vt.n; k++) {
        const vent *e = &c->vt.e[k];
        int st, both[2] = {0, 0};
        for (st = 0; st < PT_NSTAGES_ALL; st++) {
            both[0] |= e->rec[0][st] != NONE;
            both[1] |= e->rec[1][st] != NONE;
        }
        if (both[0] && both[1]) compare_vertex(c, e);
    }
    if (c->differ > c->shown) printf("... and %zu more vertices differ\n", c->differ - c->shown);
    if (c->differ) printf("\n");
    report_one_sided(c);
    report_silent(c);
    report_stage_only(c);

    /* pixels: compared when both traces were rasterized with raster records */
    pixels_compared = (c->t[0].npx || c->t[0].ncl) && (c->t[1].npx || c->t[1].ncl);
    if (pixels_compared) {
        if (compare_pixels(c, &nmiss, &nextra, nlit) != 0) return -1;
        if ((nmiss || nextra) && !c->differ && !c->only[0] && !c->only[1] && !silent_any(c) &&
            c->t[0].hdr.have) {
            if (check_raster(c, &rs) != 0) return -1;
            report_raster(c, &rs);
        }
        if (nmiss || nextra) printf("\n");
    } else if (c->t[0].npx + c->t[0].ncl + c->t[1].npx + c->t[1].ncl) {
        printf("Not compared: lit pixels (only %s has raster records).\n\n",
               c->t[0].npx + c->t[0].ncl ? "EXPECTED" : "ACTUAL");
    }
    return summarize(c, hdr_differ, nmiss, nextra, nlit, pixels_compared, &rs);
}

/* ===== the command ===== */

/* 1 for the kinds of file that are images. */
static int is_image(pt_tkind k)
{
    return k == PT_TK_PPM || k == PT_TK_P3 || k == PT_TK_PNG;
}

/* Read file s of o, and parse it when it is a trace (its buffer is then freed:
** only one file's text is held at a time).  Returns 0, or the exit status
** after printing the message. */
static int load(dctx *c, int s, char **buf, size_t *len, pt_tkind *kind)
{
    char err[PT_ERRLEN];

    if (pt_tread_file(c->o->path[s], buf, len, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return PT_EXIT_INPUT;
    }
    *kind = pt_tread_kind(*buf, *len);
    if (*kind == PT_TK_CSV) {
        fprintf(stderr, "%s:1:1: error: a CSV trace has no header and no raster records; "
                "write it with --format jsonl\n", c->o->path[s]);
        return PT_EXIT_INPUT;
    }
    if (is_image(*kind)) return 0;
    if (pt_tread_parse(&c->t[s], c->o->path[s], *buf, *len, &c->nm, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return PT_EXIT_INPUT;
    }
    free(*buf);
    *buf = NULL;
    return 0;
}

int pt_cmd_diff(int argc, char **argv)
{
    dopts o;
    char *buf[2] = {NULL, NULL};
    size_t len[2];
    pt_tkind kind[2];
    char err[PT_ERRLEN];
    dctx *c;
    int rc, s;

    rc = parse_args(&o, argc, argv);
    if (rc >= 0) return rc;
    c = calloc(1, sizeof *c);
    if (!c) { fputs("pipetrace: out of memory\n", stderr); return PT_EXIT_INPUT; }
    c->o = &o;
    for (s = 0; s < 2; s++)
        if ((rc = load(c, s, &buf[s], &len[s], &kind[s])) != 0) goto done;
    if (is_image(kind[0]) != is_image(kind[1])) {
        rc = usage_error("%s", "cannot compare an image with a trace");
    } else if (is_image(kind[0])) {
        pt_ppm img[2];
        memset(img, 0, sizeof img);
        for (s = 0; s < 2 && rc == 0; s++) {
            if (pt_image_parse(&img[s], o.path[s], buf[s], len[s], err, sizeof err) != 0) {
                fprintf(stderr, "%s\n", err);
                rc = PT_EXIT_INPUT;
            }
        }
        if (rc == 0) rc = image_diff(&o, img);
        pt_image_free(&img[0]);
        pt_image_free(&img[1]);
    } else if (o.image_out) {
        rc = usage_error("%s", "--image-out needs two images");
    } else {
        rc = trace_diff(c);
    }
    if (rc < 0) {
        fputs("pipetrace: out of memory\n", stderr);
        rc = PT_EXIT_INPUT;
    }
done:
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace: cannot write to standard output\n", stderr);
        rc = PT_EXIT_INPUT;
    }
    pt_tread_free(&c->t[0]);
    pt_tread_free(&c->t[1]);
    pt_names_free(&c->nm);
    free(c->vt.e);
    free(c->vt.slot);
    free(c->tr);
    free(c->has_tr);
    free(c->mk_hits);
    free(c->silent[0]);
    free(c->silent[1]);
    free(c);
    free(buf[0]);
    free(buf[1]);
    return rc;
}
