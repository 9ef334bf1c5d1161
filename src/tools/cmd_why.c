/*
** src/tools/cmd_why.c -- pipetrace why: which segments lit a pixel, or why none did
** See LICENSE for copyright and license.
**
**   pipetrace why [SCENE] X_FB Y_FB [--model NAME]
**
** One pt_run() of the scene, every model traced, gives each vertex's journey
** and then each segment's pixel, clip and skip records, in file order: "lit"
** means "the renderer writes this pixel", because these are the pixels it
** writes.  Nothing walks a line again, and nothing keeps the pixels: per
** segment, only the few numbers printed below (pixels and steps counted, the
** pixel drawn nearest, whether a clipped step landed on the pixel), and a
** degenerate segment is the one whose records add up to a single step.  Each
** segment that lit it is shown with its two vertices' journeys, model to
** index.  Memory grows with what is shown, not with the scene's journeys:
** of every vertex the run keeps only what measuring a segment needs (its
** pixel-plane point and viewport pixel, 32 bytes), and the whole journeys of
** the few vertices the report shows come from a second run that keeps those
** alone (vertices only, nothing drawn).  A pixel that nothing lit gets the segments that come nearest,
** measured from the pixel's centre to the segment between its two
** pixel-plane endpoints (before rounding), mapped to
** framebuffer coordinates: the logical pixel (x_pp, y_pp) is the point
** (x_ul + x_pp - 1, y_ul + h - y_pp) of the framebuffer, whose pixel centres
** sit at integer coordinates.  For each of them, the stage where the pixel was
** lost; the first that applies wins (the table below).  Whether a clipped step
** landed on the pixel comes from the run's clip records, which give only a
** run's first and last step: it is exact when the run pins the step down (one
** row or column, or one diagonal, or the pixel off the run's range), and
** otherwise decided by the segment between the rounded endpoints (the line the
** DDA steps along) passing within half a pixel of the pixel's centre.
**
**   model     its model left out    --model chose another model: the render
**                                   command still draws it into the image but
**                                   traces none of its records (pipeline.c), so
**                                   only NAME's segments count as lighting the
**                                   pixel; the others are judged as in the image
**   viewport  clipped               the pixel lies outside the viewport and a
**                                   clipped step of the segment lands on it
**             outside the viewport  the pixel lies outside the viewport: nothing
**                                   is ever drawn there
**             skipped               an endpoint has no integer pixel
**   image     behind the camera     an endpoint has z_c > 0 (perspective): it is
**                                   projected mirrored, the line drawn is another
**   raster    degenerate            both endpoints round to one pixel, drawn
**                                   elsewhere (viewport: clipped, if outside)
**   viewport  clipped               every step of the segment lies outside the
**                                   viewport
**   raster    rounded elsewhere     the segment passes through the pixel, but the
**                                   DDA steps from the rounded endpoints and its
**                                   nearest step lit a neighbouring pixel
**             passes by             it simply does not come here (not lost)
**
** A model without segments has no segment to be near: it is listed apart, as
** left out of the drawing, with the vertex of it that lands nearest.
**
** A viewport that sticks out of the framebuffer: the course's framebuffer
** writes a viewport pixel where the core's index rule (pt_raster_fb_pixel)
** puts it, rows wrapping, so several viewport pixels can land on the pixel
** asked about (pt_whyc_sources finds them).  Each is explained as a pixel of
** its own, at its framebuffer stage's pixel (before the row wraps: the
** coordinates the run's records use); then one more run, every model drawn,
** finds the last write on the pixel's index, from the pixel records' index,
** which sets the colour (none: the viewport's clearing, which comes first).
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "tools/why_course.h"
#include "io/explain.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

#define NEAREST    3             /* segments listed for a pixel nothing lit */

/* Where the report goes: standard output, wrapped to the terminal's width
** (src/tools/cli.h).  File-static because every printing function here writes
** to it and one command runs per process. */
static pt_cli_out term = {NULL, 0, NULL, 0};

static const char usage[] =
"usage: pipetrace why [SCENE] X_FB Y_FB [--model NAME]\n"
"Say which segments lit the framebuffer pixel (X_FB, Y_FB) of SCENE (default:\n"
"the built-in scene), with their vertices' journeys from model to index.\n"
"When none did, list the nearest segments and the stage where each lost it:\n"
"its model left out, outside the viewport, clipped, skipped, behind the\n"
"camera, degenerate, or endpoints rounded elsewhere; and the models without\n"
"segments, which are never drawn.  On a scene of the course's renderer 7 or\n"
"9: the primitives that wrote the pixel, each write's coverage and colour\n"
"bytes, and what the near clip and the clip did to the others.  When the\n"
"viewport sticks out of the framebuffer: every viewport pixel whose write\n"
"lands on the pixel's index (rows wrap), each explained, then the last write.\n"
"\n"
"  --model NAME   ask about the trace of 'pipetrace SCENE --model NAME': only\n"
"                 NAME's segments count; the others are drawn into the image\n"
"                 but left out of the trace\n"
"Docs: docs/step-why-quiz.md\n";

/* What rasterizing one segment did, seen from the pixel asked about. */
typedef struct seg_eval {
    size_t mi, si;               /* model index, segment index (0-based) */
    int result;                  /* PT_RASTER_* */
    int lit;                     /* 1: it wrote the pixel */
    uint64_t npix, nclip;        /* pixels written, steps clipped */
    int have_near;               /* 1: near_x/near_y hold a pixel it wrote */
    int64_t near_x, near_y;      /* the written pixel nearest the target (vp) */
    int64_t clip_x, clip_y;      /* degenerate and clipped: its one step (vp) */
    int clip_hit;                /* a clipped step on the target: 1 yes, 0 no,
                                 ** -1 the clip runs cannot tell */
    double dist;                 /* pixel centre to segment, framebuffer pixels */
    double dist_drawn;           /* ... to the segment between rounded endpoints */
} seg_eval;

/* What measuring a segment needs of one of its ends, from the vertex's
** journey: kept for every vertex, instead of the journey's 1.5 KB. */
typedef struct vend {
    double x_pp, y_pp;           /* the pixel stage's point */
    int64_t x_vp, y_vp;          /* the viewport stage's pixel (as its record
                                 ** holds it, whatever its flags) */
} vend;

/* The whole journeys of the vertices the report shows: key[i] (model, 0-based
** vertex), sorted and each once after shown_sort(), its journey j[i]. */
typedef struct vkey { size_t mi, v; } vkey;
typedef struct shown {
    vkey *key;                   /* owned */
    pt_journey *j;               /* owned; filled by shown_fetch() */
    size_t n, cap;
    int failed;                  /* 1: out of memory */
} shown;

static uint64_t cheb(int64_t dx, int64_t dy)
{
    uint64_t ax = (uint64_t)(dx < 0 ? -dx : dx), ay = (uint64_t)(dy < 0 ? -dy : dy);
    return ax > ay ? ax : ay;
}

/* ===== the stages' formulas, asked of the stages ===== */

/* Viewport pixel (x_vp, y_vp) of s in framebuffer coordinates: the
** framebuffer stage (pt_viewport2fb). */
static pt_pix vp_to_fb(const pt_scene *s, int64_t x_vp, int64_t y_vp)
{
    pt_pix vp = {x_vp, y_vp, 1};

    return pt_viewport2fb(vp, s->vp_x, s->vp_y, NULL);
}

/* Framebuffer pixel (x_fb, y_fb) of s in viewport coordinates: the way back
** through the framebuffer stage, which offsets every pixel by the framebuffer
** pixel of viewport pixel (0, 0). */
static pt_pix fb_to_vp(const pt_scene *s, int64_t x_fb, int64_t y_fb)
{
    pt_pix ul = vp_to_fb(s, 0, 0), vp = {x_fb - ul.x, y_fb - ul.y, 1};

    return vp;
}

/* Pixel-plane point (x_pp, y_pp) of s as a point of the framebuffer, whose pixel
** centres sit at integer coordinates: the viewport and framebuffer stages
** without the viewport stage's rounding, stated again on purpose (the stages
** give whole pixels only):
**   x = x_ul + x_pp - 1        (x_vp = round(x_pp) - 1,  x_fb = x_ul + x_vp)
**   y = y_ul + h - y_pp        (y_vp = h - round(y_pp),  y_fb = y_ul + y_vp)
** tests/teach/teach.sh (teach-5.29) ties it to the stages: in a viewport off the
** framebuffer's corner, a point's distance to the centre of its own
** framebuffer pixel (the trace's record) is its rounding's,
** hypot(x_pp - round(x_pp), y_pp - round(y_pp)). */
static void pp_in_fb(const pt_scene *s, double x_pp, double y_pp, double *x, double *y)
{
    *x = s->vp_x + x_pp - 1;                        /* x_ul + x_pp - 1 */
    *y = s->vp_y + s->vp_h - y_pp;                  /* y_ul + h - y_pp */
}

/* ===== what the run drew of a segment ===== */

/* Pixels written: is it the target, is it the nearest so far? */
static void on_pixel(seg_eval *e, int64_t tx, int64_t ty, int64_t x_vp, int64_t y_vp)
{
    int64_t dx = x_vp - tx, dy = y_vp - ty;

    e->npix++;
    if (dx == 0 && dy == 0) e->lit = 1;
    if (!e->have_near) {
        e->have_near = 1;
        e->near_x = x_vp; e->near_y = y_vp;
    } else {
        int64_t ex = e->near_x - tx, ey = e->near_y - ty;
        uint64_t c = cheb(dx, dy), ce = cheb(ex, ey);
        if (c < ce || (c == ce && dx * dx + dy * dy < ex * ex + ey * ey)) {
            e->near_x = x_vp; e->near_y = y_vp;
        }
    }
}

/* Does a run of count clipped steps from f to l (viewport coordinates) hold the
** step (tx, ty)?  Steps go one by one along x (x_vp = s - 1) or, for steep
** segments, along -y (y_vp = h - s); the other coordinate is monotone (the
** DDA's sum only grows or only shrinks).  1 yes, 0 no, -1 cannot tell. */
static int run_holds(uint64_t count, pt_pix f, pt_pix l, int64_t tx, int64_t ty)
{
    int64_t n = (int64_t)count - 1, along, other, f_o, l_o, k;

    if ((f.x == tx && f.y == ty) || (l.x == tx && l.y == ty)) return 1;
    if (count <= 2) return 0;
    if (l.x - f.x == n) { along = tx - f.x; other = ty; f_o = f.y; l_o = l.y; }
    else if (f.y - l.y == n) { along = f.y - ty; other = tx; f_o = f.x; l_o = l.x; }
    else return -1;
    if (along < 0 || along > n) return 0;                   /* off the run */
    if (other < (f_o < l_o ? f_o : l_o) || other > (f_o > l_o ? f_o : l_o)) return 0;
    if (f_o == l_o) return other == f_o;                    /* one row or column */
    k = l_o > f_o ? along : -along;
    if (l_o - f_o == n || f_o - l_o == n) return other == f_o + k;   /* a diagonal */
    return -1;
}

static void on_clip(seg_eval *e, int64_t tx, int64_t ty, uint64_t count, pt_pix first,
                    pt_pix last)
{
    int h = run_holds(count, first, last, tx, ty);

    e->nclip += count;
    e->clip_x = first.x;
    e->clip_y = first.y;
    if (h == 1 || (h == -1 && e->clip_hit == 0)) e->clip_hit = h;
}

/* Distance from (px, py) to the segment a-b; +inf when not finite. */
static double seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy, t = 0, d;

    if (l2 > 0) {
        t = ((px - ax) * dx + (py - ay) * dy) / l2;
        if (t < 0) t = 0;
        if (t > 1) t = 1;
    }
    d = hypot(px - (ax + t * dx), py - (ay + t * dy));
    return isfinite(d) ? d : HUGE_VAL;
}

/* ===== the journeys shown ===== */

/* Ask for the journey of model mi's 0-based vertex v.  On allocation failure
** sh->failed is set. */
static void shown_add(shown *sh, size_t mi, size_t v)
{
    if (sh->n == sh->cap) {
        size_t cap = sh->cap ? 2 * sh->cap : 16;
        vkey *k = realloc(sh->key, cap * sizeof *k);
        if (!k) { sh->failed = 1; return; }
        sh->key = k;
        sh->cap = cap;
    }
    sh->key[sh->n].mi = mi;
    sh->key[sh->n].v = v;
    sh->n++;
}

static int vkey_cmp(const void *pa, const void *pb)
{
    const vkey *a = pa, *b = pb;

    if (a->mi != b->mi) return a->mi < b->mi ? -1 : 1;
    return a->v < b->v ? -1 : a->v > b->v;
}

/* The journey asked for of model mi's 0-based vertex v, or NULL. */
static pt_journey *shown_get(const shown *sh, size_t mi, size_t v)
{
    vkey k = {mi, v};
    const vkey *f = sh->n ? bsearch(&k, sh->key, sh->n, sizeof k, vkey_cmp) : NULL;

    return f ? &sh->j[f - sh->key] : NULL;
}

/* What shown_fetch()'s run hands over: the model's index by its address. */
typedef struct fetcher {
    const pt_scene *s;
    shown *sh;
} fetcher;

static void fetch_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    fetcher *f = ud;
    pt_journey *to = v >= 1 ? shown_get(f->sh, (size_t)(m - f->s->models), v - 1) : NULL;

    if (to) *to = *j;
}

/* Sort the keys asked for (each once), then one pt_run() of s, every vertex
** traced and nothing drawn, keeping the journeys of those alone: the numbers
** of the first run, which computed them the same way.  Returns 0, or -1 when
** out of memory. */
static int shown_fetch(shown *sh, const pt_scene *s)
{
    pt_options o;
    pt_listener l;
    fetcher f = {s, sh};
    size_t i, n = 0;

    if (sh->failed) return -1;
    if (sh->n) qsort(sh->key, sh->n, sizeof *sh->key, vkey_cmp);
    for (i = 0; i < sh->n; i++)
        if (!n || vkey_cmp(&sh->key[i], &sh->key[n - 1])) sh->key[n++] = sh->key[i];
    sh->n = n;
    if (!(sh->j = calloc(n ? n : 1, sizeof *sh->j))) return -1;
    pt_options_default(&o);
    o.trace_raster = 0;
    o.rasterize = 0;
    o.every_vertex = 1;
    memset(&l, 0, sizeof l);
    l.journey = fetch_journey;
    l.ud = &f;
    return pt_run_plain(s, &o, &l);
}

static void shown_free(shown *sh)
{
    free(sh->key);
    free(sh->j);
}

/* Ask for the journeys of the two ends of segment si of model mi. */
static void shown_add_seg(shown *sh, const pt_scene *s, size_t mi, size_t si)
{
    shown_add(sh, mi, s->models[mi].seg[si].a);
    shown_add(sh, mi, s->models[mi].seg[si].b);
}

/* The journeys of segment si of model mi's two endpoints, fetched by
** shown_fetch(). */
static void seg_journeys(const pt_scene *s, const shown *sh, size_t mi, size_t si,
                         pt_journey *a, pt_journey *b)
{
    const pt_model *m = &s->models[mi];

    *a = *shown_get(sh, mi, m->seg[si].a);
    *b = *shown_get(sh, mi, m->seg[si].b);
}

/* Segment e (e->mi, e->si), whose pixel, clip and skip records the run gave
** (e->npix, e->nclip, e->result == PT_RASTER_SKIPPED), measured against
** (X, Y): what the DDA made of it and how far the segment passes.  Every step
** of a segment drawn is a pixel or a clipped step, so one step in all is the
** one step of a degenerate segment (two ends rounded apart make two steps or
** more). */
static void measure(const pt_scene *s, vend *const *at, int64_t X, int64_t Y, seg_eval *e)
{
    const pt_model *m = &s->models[e->mi];
    const vend *a = &at[e->mi][m->seg[e->si].a], *b = &at[e->mi][m->seg[e->si].b];
    pt_pix t = fb_to_vp(s, X, Y);
    double ax, ay, bx, by;

    if (e->result != PT_RASTER_SKIPPED)
        e->result = e->npix + e->nclip == 1 ? PT_RASTER_DEGENERATE : PT_RASTER_DRAWN;
    pp_in_fb(s, a->x_pp, a->y_pp, &ax, &ay);
    pp_in_fb(s, b->x_pp, b->y_pp, &bx, &by);
    e->dist = seg_dist((double)X, (double)Y, ax, ay, bx, by);
    e->dist_drawn = HUGE_VAL;
    if (e->result != PT_RASTER_SKIPPED)                     /* rounded: viewport pixels */
        e->dist_drawn = seg_dist((double)t.x, (double)t.y, (double)a->x_vp, (double)a->y_vp,
                                 (double)b->x_vp, (double)b->y_vp);
}

/* One endpoint's journey, three lines:
**     v3  model (..) -> camera (..) -> image (..)
**         -> pixel (..) -> viewport (..) -> framebuffer (..) -> index N
** each stage's numbers as pt_explain_tuple writes them, with the notes a reader
** needs on the way (behind the camera, outside the viewport). */
static void show_vertex(uint64_t v, const pt_journey *j)
{
    static const char *const lead[PT_CLASSIC_NORDER] = {   /* the classic order's */
        "model ", " -> camera ", " -> image ", "\n        -> pixel ", " -> viewport ",
        "\n        -> framebuffer ", " -> index ",
    };
    char b[PT_EXPLAINLEN];
    int i;

    fprintf(term.f, "    v%llu  ", (unsigned long long)v);
    for (i = 0; i < PT_CLASSIC_NORDER; i++) {
        pt_stage st = pt_classic_order[i];
        const pt_vrec *r = &j->rec[st];
        pt_explain_tuple(b, sizeof b, j, st);
        fprintf(term.f, "%s%s", lead[i], b);
        if (st == PT_STAGE_IMAGE && (r->flags & PT_REC_BEHIND)) fprintf(term.f, " behind the camera");
        if (st == PT_STAGE_VIEWPORT && !(r->flags & (PT_REC_INSIDE | PT_REC_NULL)))
            fprintf(term.f, " outside");
    }
    fputc('\n', term.f);
}

/* "  tri s2 (v2 -> v3)" plus both endpoints' journeys. */
static void show_segment(const pt_scene *s, const shown *sh, const seg_eval *e,
                         const char *tail, pt_journey *a, pt_journey *b)
{
    const pt_model *m = &s->models[e->mi];
    uint64_t va = m->seg[e->si].a + 1ull, vb = m->seg[e->si].b + 1ull;

    seg_journeys(s, sh, e->mi, e->si, a, b);
    fprintf(term.f, "  %s s%llu (v%llu -> v%llu)%s\n", m->name, (unsigned long long)e->si + 1,
           (unsigned long long)va, (unsigned long long)vb, tail);
    show_vertex(va, a);
    show_vertex(vb, b);
}

/* The stage where segment e lost pixel (X, Y), in words, after the caller's
** indentation. */
static void show_reason(const pt_scene *s, const seg_eval *e, const pt_journey *a,
                        const pt_journey *b, long long X, long long Y, int target_inside)
{
    const pt_model *m = &s->models[e->mi];
    const pt_journey *behind = NULL;
    pt_pix t = fb_to_vp(s, X, Y), near = vp_to_fb(s, e->near_x, e->near_y);
    uint64_t vnull = a->rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL ? m->seg[e->si].a + 1ull
                                                                  : m->seg[e->si].b + 1ull;
    char num[PT_NUMLEN];

    if (a->rec[PT_STAGE_IMAGE].flags & PT_REC_BEHIND) behind = a;     /* the image stage says */
    else if (b->rec[PT_STAGE_IMAGE].flags & PT_REC_BEHIND) behind = b;

    if (!target_inside && e->clip_hit == 1)
        fprintf(term.f, "lost at viewport: clipped by the viewport: one of its steps lands on "
               "this pixel, (x_vp, y_vp) = (%lld, %lld), but the pixel lies outside the "
               "viewport and steps there are not drawn\n",
               (long long)t.x, (long long)t.y);
    else if (!target_inside && e->clip_hit == -1 && e->dist_drawn <= 0.5)
        fprintf(term.f, "lost at viewport: clipped by the viewport: it runs through this pixel "
               "(the line between its rounded endpoints passes within half a pixel of the "
               "centre), but the pixel lies outside the viewport and steps there are not "
               "drawn\n");
    else if (!target_inside)
        fprintf(term.f, "lost at viewport: outside the viewport: the pixel lies outside the "
               "viewport, nothing is ever drawn there\n");
    else if (e->result == PT_RASTER_SKIPPED)
        fprintf(term.f, "lost at viewport: skipped: v%llu has no integer pixel (not finite, or "
               "beyond 2^62), so the segment is not drawn\n", (unsigned long long)vnull);
    else if (behind) {
        pt_fmt_shortest(num, behind->rec[PT_STAGE_CAMERA].z);
        fprintf(term.f, "lost at image: behind the camera: v%llu has z_c = %s > 0 and is "
               "projected mirrored through the origin, so the line drawn is not the one "
               "in front of the camera\n", behind == a ? m->seg[e->si].a + 1ull
                                                      : m->seg[e->si].b + 1ull, num);
    } else if (e->result == PT_RASTER_DEGENERATE && e->npix)
        fprintf(term.f, "lost at raster: degenerate: both endpoints round to one pixel, and it "
               "drew that one pixel elsewhere, at (x_fb, y_fb) = (%lld, %lld)\n",
               (long long)near.x, (long long)near.y);
    else if (e->result == PT_RASTER_DEGENERATE)
        fprintf(term.f, "lost at viewport: degenerate and clipped: both endpoints round to one "
               "pixel, (x_vp, y_vp) = (%lld, %lld), outside the viewport\n",
               (long long)e->clip_x, (long long)e->clip_y);
    else if (e->npix == 0)
        fprintf(term.f, "lost at viewport: clipped by the viewport: all %llu of its steps lie "
               "outside the viewport\n", (unsigned long long)e->nclip);
    else if (e->dist <= 0.5)
        fprintf(term.f, "lost at raster: endpoints rounded elsewhere: the segment passes through "
               "this pixel, but the DDA steps from the rounded endpoints and its nearest "
               "step lit the neighbouring pixel (x_fb, y_fb) = (%lld, %lld)\n",
               (long long)near.x, (long long)near.y);
    else
        fprintf(term.f, "not lost: it passes by; the nearest pixel it lit is (x_fb, y_fb) = "
               "(%lld, %lld)\n",
               (long long)near.x, (long long)near.y);
}

/* A whole number from s into *v; 0 on success. */
static int parse_int(const char *s, long long *v)
{
    char *end;

    errno = 0;
    *v = strtoll(s, &end, 10);
    return (*s == '\0' || *end || errno) ? -1 : 0;
}

/* 1 when a sorts before b: nearer, and in file order among equals. */
static int nearer(const seg_eval *a, const seg_eval *b)
{
    return a->dist < b->dist;
}

/* Put e into the list best[0..*n) kept sorted by nearer(), at most NEAREST. */
static void keep_nearest(seg_eval best[NEAREST], int *n, const seg_eval *e)
{
    int k;

    for (k = *n; k > 0 && nearer(e, &best[k - 1]); k--)
        if (k < NEAREST) best[k] = best[k - 1];
    if (k < NEAREST) {
        best[k] = *e;
        if (*n < NEAREST) ++*n;
    }
}

/* A write on the pixel that the report lists as lighting it, in drawing
** order: segment (mi, k) of a counted model, or point k + 1 of model mi
** (renderer 4) in colour rgb. */
typedef struct lit_ev {
    int point;                   /* 1: a point, 0: a segment */
    size_t mi, k;
    unsigned char rgb[3];
} lit_ev;

/* What the loop over the segments found. */
typedef struct why_ctx {
    const pt_scene *s;
    vend **at;                   /* at[mi][v]: what measure() needs of model mi's
                                 ** vertex v + 1, from the run; owned */
    shown sh;                    /* the journeys of the vertices shown; owned */
    lit_ev *lit;                 /* the writes listed as lighting the pixel, */
    size_t nev, capev;           /*   in drawing order; owned */
    int failed;                  /* 1: out of memory during the run */
    seg_eval nob[NEAREST];       /* models without segments, nearest first: */
    int nnob;                    /*   mi the model, si its nearest vertex */
    const pt_model *sel;         /* --model's model, or NULL: every model counts */
    long long X, Y;              /* the pixel (x_fb, y_fb) */
    int inside;                  /* 1: it lies inside the viewport */
    int wrapped;                 /* 1: one of the viewport pixels that land on a
                                 ** pixel of a viewport sticking out */
    uint64_t nlit;               /* segments of counted models that lit it */
    uint64_t nleft;              /* segments of left-out models that lit it, */
    size_t left_mi[10], left_si[10];    /*   the first ten of them */
    int drawn;                   /* 1: some segment, of any model, drew it; */
    size_t last_mi, last_si;     /*   the last one drawn sets its color */
    int pt_drawn;                /* 1: some point (renderer 4) drew it after that
                                 ** segment (or with none): the last one, */
    size_t pt_mi, pt_k;          /*   model and point (0-based), sets its color */
    unsigned char pt_rgb[3];     /*   to this */
    seg_eval best[NEAREST];      /* the nearest segments not counted as lit */
    int nbest;
    seg_eval best_sel;           /* --model: the nearest of its own segments */
    int have_sel;
    seg_eval e;                  /* the segment whose records the run gives now */
    int64_t tx, ty;              /* the pixel (x_vp, y_vp) */
    pt_pix ul;                   /* the framebuffer pixel of viewport pixel (0, 0) */
} why_ctx;

/* "lost at model: its model left out" for a segment of a model --model left
** out, then what the renderer does with it in the image. */
static void show_left_out(const why_ctx *w, const seg_eval *e, const pt_journey *a,
                          const pt_journey *b)
{
    const char *name = w->s->models[e->mi].name;

    fprintf(term.f, "    lost at model: its model left out: --model %s traces the records of "
           "model %s only; model %s is drawn into the image but not traced\n",
           w->sel->name, w->sel->name, name);
    if (e->lit) fprintf(term.f, "    in the image, it lights this pixel\n");
    else {
        fprintf(term.f, "    in the image, ");
        show_reason(w->s, e, a, b, w->X, w->Y, w->inside);
    }
}

/* The models without segments: the renderer transforms and draws nothing of
** them.  The NEAREST nearest (by their nearest vertex, measured as the
** segments' endpoints are) into w->nob, after the run; their nearest
** vertices' journeys asked for. */
static void find_no_segments(why_ctx *w)
{
    const pt_scene *s = w->s;
    seg_eval e;                             /* here mi: the model, si: its nearest vertex */
    size_t mi, v;
    int k;

    for (mi = 0; mi < s->nmodels; mi++) {
        const pt_model *m = &s->models[mi];
        double dmin = HUGE_VAL, x, y;
        size_t vmin = 0;

        if (m->nseg) continue;
        for (v = 0; v < m->nv; v++) {
            double dv;
            pp_in_fb(s, w->at[mi][v].x_pp, w->at[mi][v].y_pp, &x, &y);
            dv = seg_dist((double)w->X, (double)w->Y, x, y, x, y);  /* a point */
            if (v == 0 || dv < dmin) { dmin = dv; vmin = v; }
        }
        memset(&e, 0, sizeof e);
        e.mi = mi;
        e.si = vmin;
        e.dist = dmin;
        keep_nearest(w->nob, &w->nnob, &e);
    }
    for (k = 0; k < w->nnob; k++)
        if (s->models[w->nob[k].mi].nv) shown_add(&w->sh, w->nob[k].mi, w->nob[k].si);
}

/* ... and where each one's nearest vertex would land. */
static void show_no_segments(const why_ctx *w)
{
    const pt_scene *s = w->s;
    const seg_eval *best = w->nob;
    int n = w->nnob, k;
    char d[PT_NUMLEN], fb[PT_EXPLAINLEN];

    if (!n) return;
    fprintf(term.f, "models without segments (left out: the renderer draws nothing of a model "
           "without segments):\n");
    for (k = 0; k < n; k++) {
        const pt_model *m = &s->models[best[k].mi];

        if (!m->nv) { fprintf(term.f, "  %s: no vertices either\n", m->name); continue; }
        pt_explain_tuple(fb, sizeof fb, shown_get(&w->sh, best[k].mi, best[k].si),
                         PT_STAGE_FRAMEBUFFER);
        if (best[k].dist == HUGE_VAL) snprintf(d, sizeof d, "an unknown distance");
        else pt_fmt_fixed(d, best[k].dist, 2);
        fprintf(term.f, "  %s: %zu %s; the nearest, v%zu, would be %s%s away, at "
               "(x_fb, y_fb) = %s\n", m->name, m->nv, m->nv == 1 ? "vertex" : "vertices",
               best[k].si + 1, d, best[k].dist == HUGE_VAL ? "" : " pixels", fb);
    }
}

/* Add a write on the pixel to the list the report prints as "lit by" (a
** point's in colour rgb); its segment's ends' journeys asked for. */
static void lit_add(why_ctx *w, int point, size_t mi, size_t k, const unsigned char *rgb)
{
    lit_ev *ev;

    if (w->nev == w->capev) {
        size_t cap = w->capev ? 2 * w->capev : 16;
        lit_ev *n = realloc(w->lit, cap * sizeof *n);
        if (!n) { w->failed = 1; return; }
        w->lit = n;
        w->capev = cap;
    }
    ev = &w->lit[w->nev++];
    memset(ev, 0, sizeof *ev);
    ev->point = point;
    ev->mi = mi;
    ev->k = k;
    if (rgb) memcpy(ev->rgb, rgb, sizeof ev->rgb);
    if (!point) shown_add_seg(&w->sh, w->s, mi, k);
    w->nlit++;
}

/* Segment w->e, its records all heard: list it when it lit the pixel (of
** a counted model), else keep it if it is among the nearest. */
static void seg_done(why_ctx *w)
{
    const pt_scene *s = w->s;
    seg_eval *e = &w->e;
    size_t mi = e->mi, si = e->si;
    int left_out = w->sel && &s->models[mi] != w->sel;

    measure(s, w->at, w->X, w->Y, e);
    if (e->lit) {                           /* drawing order: the last one sets the color */
        w->drawn = 1;
        w->last_mi = mi;
        w->last_si = si;
        w->pt_drawn = 0;                    /* drawn over the points before it */
    }
    if (e->lit && !left_out) {
        lit_add(w, 0, mi, si, NULL);
        return;
    }
    if (e->lit && w->nleft < 10) {
        w->left_mi[w->nleft] = mi;
        w->left_si[w->nleft] = si;
    }
    if (e->lit) w->nleft++;
    keep_nearest(w->best, &w->nbest, e);
    if (w->sel && !left_out && (!w->have_sel || nearer(e, &w->best_sel))) {
        w->best_sel = *e;
        w->have_sel = 1;
    }
}

/* Make w->e segment (mi, si), or the first segment after it in file order
** ((s->nmodels, 0): none is left), with no record heard yet. */
static void seg_start(why_ctx *w, size_t mi, size_t si)
{
    const pt_scene *s = w->s;

    while (mi < s->nmodels && si >= s->models[mi].nseg) { mi++; si = 0; }
    memset(&w->e, 0, sizeof w->e);
    w->e.mi = mi;
    w->e.si = si;
}

/* The run's records come segment by segment in file order: those of segment
** seg (1-based) of model m come now, so every segment before it is done
** (models_end: all are). */
static void seg_reach(why_ctx *w, size_t mi, uint64_t seg)
{
    while (w->e.mi < mi || (w->e.mi == mi && w->e.si + 1 < seg)) {
        seg_done(w);
        seg_start(w, w->e.mi, w->e.si + 1);
    }
}

static size_t model_index(const why_ctx *w, const pt_model *m)
{
    return (size_t)(m - w->s->models);
}

static void why_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    why_ctx *w = ud;

    if (v >= 1 && v <= m->nv) {
        vend *e = &w->at[model_index(w, m)][v - 1];
        e->x_pp = j->rec[PT_STAGE_PIXEL].x;
        e->y_pp = j->rec[PT_STAGE_PIXEL].y;
        e->x_vp = j->rec[PT_STAGE_VIEWPORT].ix;
        e->y_vp = j->rec[PT_STAGE_VIEWPORT].iy;
    }
}

static void why_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                       size_t n)
{
    why_ctx *w = ud;
    size_t k;

    seg_reach(w, model_index(w, m), seg);
    for (k = 0; k < n; k++)                 /* back to viewport pixels */
        on_pixel(&w->e, w->tx, w->ty, px[k].x_fb - w->ul.x, px[k].y_fb - w->ul.y);
}

/* The pixels of point pt (1-based) of model m, which the course's renderer 4
** draws after its `after` segments: the segments before it are done first,
** so that the lines come in drawing order. */
static void why_point_pixels(void *ud, const pt_model *m, uint64_t pt, const pt_fb_pixel *px,
                             size_t n)
{
    why_ctx *w = ud;
    const pt_point *p = &m->pts[pt - 1];
    size_t k;

    seg_reach(w, model_index(w, m), p->after + 1);
    for (k = 0; k < n; k++) {
        if (px[k].x_fb != w->X || px[k].y_fb != w->Y) continue;
        w->pt_drawn = 1;
        w->pt_mi = model_index(w, m);
        w->pt_k = pt - 1;
        memcpy(w->pt_rgb, px[k].paint.rgb, sizeof w->pt_rgb);
        if (w->sel && m != w->sel) continue;
        lit_add(w, 1, w->pt_mi, w->pt_k, px[k].paint.rgb);
    }
}

/* The writes on the pixel listed as lighting it, in drawing order, each
** segment with its ends' journeys. */
static void show_lit(const why_ctx *w)
{
    size_t i;
    pt_journey ja, jb;

    for (i = 0; i < w->nev; i++) {
        const lit_ev *ev = &w->lit[i];
        const pt_model *m = &w->s->models[ev->mi];

        if (i == 0) fprintf(term.f, "lit by:\n");
        if (!ev->point) {
            seg_eval e;
            memset(&e, 0, sizeof e);
            e.mi = ev->mi;
            e.si = ev->k;
            show_segment(w->s, &w->sh, &e, "", &ja, &jb);
            continue;
        }
        fprintf(term.f, "  %s p%llu (point %llu: v%llu, radius %d): a pixel of its square, "
                "in color %d %d %d (the course's renderer 4 draws points)\n", m->name,
                (unsigned long long)ev->k + 1, (unsigned long long)ev->k + 1,
                (unsigned long long)m->pts[ev->k].v + 1, m->pts[ev->k].radius, ev->rgb[0],
                ev->rgb[1], ev->rgb[2]);
    }
}

static void why_clip(void *ud, const pt_model *m, uint64_t seg, uint64_t count, pt_pix first,
                     pt_pix last)
{
    why_ctx *w = ud;

    seg_reach(w, model_index(w, m), seg);
    on_clip(&w->e, w->tx, w->ty, count, first, last);
}

static void why_skip(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *why)
{
    why_ctx *w = ud;

    (void)v; (void)why;
    seg_reach(w, model_index(w, m), seg);
    w->e.result = PT_RASTER_SKIPPED;
}

/* One pt_run() of the scene, every model traced and every vertex (a model
** without segments too: where its vertices would land): keep what measuring
** needs of each vertex's journey, then measure each segment against the pixel
** from its pixel, clip and skip records, listing those that lit it (of the
** counted models) and keeping the nearest of the others; then a second run
** for the journeys of the vertices the report shows.  Returns 0, or -1 when
** out of memory. */
static int scan(why_ctx *w)
{
    pt_options o;
    pt_listener l;
    pt_pix t = fb_to_vp(w->s, w->X, w->Y);

    w->tx = t.x;
    w->ty = t.y;
    w->ul = vp_to_fb(w->s, 0, 0);
    seg_start(w, 0, 0);
    pt_options_default(&o);
    o.every_vertex = 1;
    memset(&l, 0, sizeof l);
    l.journey = why_journey;
    l.pixels = why_pixels;
    l.point_pixels = why_point_pixels;
    l.clip = why_clip;
    l.skip = why_skip;
    l.ud = w;
    if (pt_run_plain(w->s, &o, &l) != 0 || w->failed) return -1;
    seg_reach(w, w->s->nmodels, 0);         /* the last segment's records are in */
    if (w->failed) return -1;
    if (!w->nlit) {                         /* the report shows the nearest */
        int k;
        for (k = 0; k < w->nbest; k++) shown_add_seg(&w->sh, w->s, w->best[k].mi, w->best[k].si);
        if (w->have_sel) shown_add_seg(&w->sh, w->s, w->best_sel.mi, w->best_sel.si);
        find_no_segments(w);
    }
    return shown_fetch(&w->sh, w->s);
}

/* Segments of left-out models that lit the pixel, as scan() found them:
** "also lit ... : a s1, b s3". */
static void show_also_lit(const why_ctx *w)
{
    uint64_t k;

    fprintf(term.f, "also lit in the image by segments that --model %s leaves out of the trace:",
           w->sel->name);
    for (k = 0; k < w->nleft && k < 10; k++)
        fprintf(term.f, "%s %s s%zu", k ? "," : "", w->s->models[w->left_mi[k]].name, w->left_si[k] + 1);
    if (w->nleft > 10) fprintf(term.f, ", ... (%llu in all)", (unsigned long long)w->nleft);
    fputc('\n', term.f);
}

/* The nearest segments, each with the stage where it lost the pixel. */
static void show_nearest(const why_ctx *w)
{
    seg_eval list[NEAREST + 1];
    int n = w->nbest, k, has_sel = 0;
    pt_journey ja, jb;

    memset(list, 0, sizeof list);           /* list[NEAREST] too (gcc -O3 asks) */
    memcpy(list, w->best, sizeof w->best);
    for (k = 0; k < n; k++) has_sel |= &w->s->models[list[k].mi] == w->sel;
    if (w->have_sel && !has_sel) list[n++] = w->best_sel;  /* --model's own, always */
    if (n)
        fprintf(term.f, "nearest segments (distance from the pixel's centre to the segment "
               "between its pixel-plane endpoints, in framebuffer pixels):\n");
    for (k = 0; k < n; k++) {
        const seg_eval *e = &list[k];
        char tail[64], d[PT_NUMLEN];

        if (e->dist == HUGE_VAL) snprintf(tail, sizeof tail, ": distance unknown");
        else {
            pt_fmt_fixed(d, e->dist, 2);
            snprintf(tail, sizeof tail, ": %s pixels away", d);
        }
        show_segment(w->s, &w->sh, e, tail, &ja, &jb);
        if (w->sel && &w->s->models[e->mi] != w->sel) show_left_out(w, e, &ja, &jb);
        else {
            fprintf(term.f, "    ");
            show_reason(w->s, e, &ja, &jb, w->X, w->Y, w->inside);
        }
    }
}

/* Free what w owns (a zeroed w too). */
static void why_free(why_ctx *w)
{
    size_t mi;

    if (w->at)
        for (mi = 0; mi < w->s->nmodels; mi++) free(w->at[mi]);
    free(w->at);
    shown_free(&w->sh);
    free(w->lit);
}

/* Room for what measuring needs of every vertex, at[mi][v], which scan()
** fills.  NULL when out of memory. */
static vend **ends_room(const pt_scene *s)
{
    vend **at = calloc(s->nmodels ? s->nmodels : 1, sizeof *at);
    size_t mi;

    if (!at) return NULL;
    for (mi = 0; mi < s->nmodels; mi++)
        if (!(at[mi] = calloc(s->models[mi].nv ? s->models[mi].nv : 1, sizeof *at[mi]))) {
            while (mi > 0) free(at[--mi]);
            free(at);
            return NULL;
        }
    return at;
}

/* What the report says of pixel (w->X, w->Y) after its first lines: the
** segments and points that lit it, or the nearest segments and where each
** lost it.  Returns 0, or -1 when out of memory. */
static int explain(why_ctx *w)
{
    const pt_scene *s = w->s;

    if (scan(w) != 0) return -1;
    show_lit(w);
    if (w->nleft && w->nlit) show_also_lit(w);
    if (!w->nlit) {
        if (w->wrapped && !w->drawn)
            fprintf(term.f, "not lit from there: no segment writes this viewport pixel\n");
        else if (!w->drawn)
            fprintf(term.f, "not lit: no segment writes it, so it keeps the background color "
                   "%d %d %d\n", s->background[0], s->background[1], s->background[2]);
        else
            fprintf(term.f, "not lit in the trace of --model %s: none of its segments writes this "
                   "pixel; segments of models it leaves out do (below)\n", w->sel->name);
        if (w->sel && !w->sel->nseg)
            fprintf(term.f, "model %s has no segments: the renderer draws nothing of it (below)\n",
                   w->sel->name);
        show_nearest(w);
        if (!w->nbest) fprintf(term.f, "the scene has no segments\n");
        show_no_segments(w);
    }
    return 0;
}

/* ===== a viewport that sticks out of the framebuffer ===== */

/* The last write on one index of the pixel array, in drawing order, of any
** model: what the image shows there (the viewport's clearing comes first). */
typedef struct last_write {
    const pt_scene *s;
    int64_t idx;                 /* the index asked about */
    int any;                     /* 1: a segment or point wrote it: */
    int point;                   /*   1 a point, 0 a segment, */
    const pt_model *m;           /*   of this model, */
    uint64_t k;                  /*   1-based, */
    int64_t x_fb, y_fb;          /*   at this pixel of the framebuffer stage, */
    unsigned char rgb[3];        /*   in this colour */
} last_write;

static void lw_note(last_write *lw, const pt_model *m, int point, uint64_t k,
                    const pt_fb_pixel *px, size_t n)
{
    size_t i;

    for (i = 0; i < n; i++) {
        if (px[i].idx != lw->idx) continue;
        lw->any = 1;
        lw->point = point;
        lw->m = m;
        lw->k = k;
        lw->x_fb = px[i].x_fb;
        lw->y_fb = px[i].y_fb;
        memcpy(lw->rgb, px[i].paint.rgb, sizeof lw->rgb);
    }
}

static void lw_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px, size_t n)
{
    lw_note(ud, m, 0, seg, px, n);
}

static void lw_point_pixels(void *ud, const pt_model *m, uint64_t pt, const pt_fb_pixel *px,
                            size_t n)
{
    lw_note(ud, m, 1, pt, px, n);
}

/* One pt_run() of s, every model drawn, keeping the last write on lw->idx:
** the pixel records give each write's index (pt_raster_fb_pixel's). */
static int find_last_write(last_write *lw)
{
    pt_options o;
    pt_listener l;

    pt_options_default(&o);
    memset(&l, 0, sizeof l);
    l.pixels = lw_pixels;
    l.point_pixels = lw_point_pixels;
    l.ud = lw;
    return pt_run_plain(lw->s, &o, &l);
}

/* The pixel's colour and the segment or point that set it, when one did: a
** segment's colour is the one its write left (lw, the rasterizer's pixel
** record: per-vertex colours, anti-aliasing and gamma change it), its model's
** colour when lw heard no write of a segment. */
static void show_color(const why_ctx *w, const last_write *lw)
{
    const pt_scene *s = w->s;

    if (w->pt_drawn) {
        const pt_model *m = &s->models[w->pt_mi];
        fprintf(term.f, "color %d %d %d%s: %s p%zu is the last point drawn there\n",
                w->pt_rgb[0], w->pt_rgb[1], w->pt_rgb[2], w->sel ? " in the image" : "", m->name,
                w->pt_k + 1);
    } else if (w->drawn) {
        const pt_model *m = &s->models[w->last_mi];
        const unsigned char *rgb = lw->any && !lw->point ? lw->rgb : m->color;
        fprintf(term.f, "color %d %d %d%s: %s s%zu is the last segment drawn there\n", rgb[0],
               rgb[1], rgb[2], w->sel ? " in the image" : "", m->name, w->last_si + 1);
    }
}

/* The report on pixel (w->X, w->Y) of a scene whose viewport sticks out,
** which nsrc >= 1 viewport pixels land on: each of them explained as a pixel
** of its own (at its framebuffer stage's pixel, before the row wraps), then
** the last write.  Returns 0, or -1 when out of memory. */
static int why_wrapped(const why_ctx *w0, size_t nsrc)
{
    const pt_scene *s = w0->s;
    pt_pix *src = calloc(nsrc, sizeof *src), fb = {w0->X, w0->Y, 1}, ul = vp_to_fb(s, 0, 0);
    last_write lw;
    size_t i;

    if (!src) return -1;
    pt_whyc_sources(s, w0->X, w0->Y, src, nsrc);
    memset(&lw, 0, sizeof lw);
    lw.s = s;
    lw.idx = pt_fb2index(fb, s->fb_w, s->fb_h, NULL);
    if (find_last_write(&lw) != 0) { free(src); return -1; }
    fprintf(term.f, "pixel (x_fb, y_fb) = (%lld, %lld) of %s: idx = %lld\n", w0->X, w0->Y,
            s->path, (long long)lw.idx);
    pt_whyc_wrap_head(term.f, s, w0->X, w0->Y, nsrc);
    if (w0->sel)
        fprintf(term.f, "--model %s: the trace of this model alone; the image still shows every "
               "model\n", w0->sel->name);
    for (i = 0; i < nsrc; i++) {
        pt_pix f = vp_to_fb(s, src[i].x, src[i].y);
        why_ctx w;
        int rc;

        pt_whyc_source(term.f, s, w0->X, w0->Y, src[i]);
        if (i >= PT_WHYC_EXPLAINED) continue;
        memset(&w, 0, sizeof w);
        w.s = s;
        w.sel = w0->sel;
        w.X = f.x;
        w.Y = f.y;
        w.inside = 1;
        w.wrapped = 1;
        if (!(w.at = ends_room(s))) { free(src); return -1; }
        rc = explain(&w);
        why_free(&w);
        if (rc != 0) { free(src); return -1; }
    }
    if (nsrc > PT_WHYC_EXPLAINED)
        fprintf(term.f, "(the %zu viewport pixels after the first %d are listed, not "
                "explained)\n", nsrc - PT_WHYC_EXPLAINED, PT_WHYC_EXPLAINED);
    fputc('\n', term.f);
    if (lw.any)
        fprintf(term.f, "color %d %d %d%s: the last write, by %s %c%llu, from viewport pixel "
                "(x_vp, y_vp) = (%lld, %lld)\n", lw.rgb[0], lw.rgb[1], lw.rgb[2],
                w0->sel ? " in the image" : "", lw.m->name, lw.point ? 'p' : 's',
                (unsigned long long)lw.k, (long long)(lw.x_fb - ul.x),
                (long long)(lw.y_fb - ul.y));
    else
        fprintf(term.f, "color %d %d %d%s: no segment or point writes it; the last write is the "
                "viewport's clearing, of viewport pixel (x_vp, y_vp) = (%lld, %lld), to the "
                "viewport background\n", s->vp_background[0], s->vp_background[1],
                s->vp_background[2], w0->sel ? " in the image" : "",
                (long long)src[nsrc - 1].x, (long long)src[nsrc - 1].y);
    free(src);
    return 0;
}

/* why on a scene of the course's renderer 7 or 9 (tools/why_course.h); frees s. */
static int course_why(pt_scene *s, long long X, long long Y, const char *model)
{
    const pt_model *sel = NULL;
    int rc;

    if (X < 0 || X >= s->fb_w || Y < 0 || Y >= s->fb_h) {
        fprintf(stderr, "pipetrace why: X_FB Y_FB = %lld %lld: the pixel lies outside the "
                "%d x %d framebuffer of %s (x_fb 0..%d, y_fb 0..%d)\n", X, Y, s->fb_w,
                s->fb_h, s->path, s->fb_w - 1, s->fb_h - 1);
        pt_scene_free(s);
        return PT_EXIT_INPUT;
    }
    if (model && !(sel = pt_cli_model(s, "why", model))) {
        pt_scene_free(s);
        return PT_EXIT_INPUT;
    }
    pt_cli_out_open(&term);
    rc = pt_whyc_report(term.f, s, (int)X, (int)Y, sel);
    pt_scene_free(s);
    if (pt_cli_out_close(&term) != 0) {
        fputs("pipetrace why: cannot write to standard output\n", stderr);
        return PT_EXIT_INPUT;
    }
    return rc ? PT_EXIT_INPUT : 0;
}

int pt_cmd_why(int argc, char **argv)
{
    const char *pos[3], *model = NULL;
    int npos = 0, k;
    pt_scene s;
    pt_pix fb, vp;
    why_ctx w;
    last_write lw;
    size_t nsrc;
    int rc;

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); return 0; }
        if (!strcmp(a, "--model")) {
            if (k + 1 >= argc) return pt_cli_usage("why", "--model needs a model name");
            model = argv[++k];
            continue;
        }
        if (a[0] == '-' && !(a[1] >= '0' && a[1] <= '9'))
            return pt_cli_unknown("why", usage, a);
        if (npos == 3)
            return pt_cli_usage("why", "too many arguments ('%s'): expected [SCENE] X_FB Y_FB", a);
        pos[npos++] = a;
    }
    memset(&w, 0, sizeof w);
    if (npos < 2 || parse_int(pos[npos - 2], &w.X) || parse_int(pos[npos - 1], &w.Y)) {
        return pt_cli_usage("why", "needs a pixel: X_FB Y_FB (whole numbers)");
    }

    if (pt_cli_load(&s, npos == 3 ? pos[0] : NULL) != 0) return PT_EXIT_INPUT;
    if (s.renderer == 7 || s.renderer == 9) return course_why(&s, w.X, w.Y, model);
    w.s = &s;
    if (pt_scene_pipeline(&s) != &pt_pipe_classic) {
        fprintf(stderr, "pipetrace why: %s: why follows the classic camera (model -> camera "
                "-> image -> pixel -> viewport); this scene has the %s: try 'pipetrace "
                "step'\n", s.path, pt_scene_pipeline(&s)->title);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (w.X < 0 || w.X >= s.fb_w || w.Y < 0 || w.Y >= s.fb_h) {
        fprintf(stderr, "pipetrace why: X_FB Y_FB = %lld %lld: the pixel lies outside the "
                "%d x %d framebuffer of %s (x_fb 0..%d, y_fb 0..%d)\n", w.X, w.Y, s.fb_w,
                s.fb_h, s.path, s.fb_w - 1, s.fb_h - 1);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (model && !(w.sel = pt_cli_model(&s, "why", model))) {
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (!(w.at = ends_room(&s))) {
        fprintf(stderr, "pipetrace why: %s: out of memory\n", s.path);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }

    pt_cli_out_open(&term);
    nsrc = pt_scene_vp_inside(&s) ? 0 : pt_whyc_sources(&s, w.X, w.Y, NULL, 0);
    if (nsrc) rc = why_wrapped(&w, nsrc);
    else {
        fb.x = w.X; fb.y = w.Y; fb.ok = 1;
        vp = fb_to_vp(&s, w.X, w.Y);
        w.inside = pt_inside(vp.x, vp.y, s.vp_w, s.vp_h);
        fprintf(term.f, "pixel (x_fb, y_fb) = (%lld, %lld) of %s: idx = %lld, ", w.X, w.Y,
                s.path, (long long)pt_fb2index(fb, s.fb_w, s.fb_h, NULL));
        if (w.inside)
            fprintf(term.f, "inside the viewport at (x_vp, y_vp) = (%lld, %lld)\n",
                    (long long)vp.x, (long long)vp.y);
        else {
            pt_pix ul = vp_to_fb(&s, 0, 0), lr = vp_to_fb(&s, s.vp_w - 1, s.vp_h - 1);
            fprintf(term.f, "outside the viewport (x_fb %lld..%lld, y_fb %lld..%lld): nothing "
                    "is ever drawn there\n", (long long)ul.x, (long long)lr.x,
                    (long long)ul.y, (long long)lr.y);
        }
        if (!pt_scene_vp_inside(&s)) pt_whyc_wrap_head(term.f, &s, w.X, w.Y, 0);
        if (w.sel)
            fprintf(term.f, "--model %s: the trace of this model alone; the image still shows "
                    "every model\n", w.sel->name);
        rc = explain(&w);
        memset(&lw, 0, sizeof lw);
        lw.s = &s;
        lw.idx = pt_fb2index(fb, s.fb_w, s.fb_h, NULL);
        if (rc == 0 && w.drawn && !w.pt_drawn) rc = find_last_write(&lw);
        if (rc == 0) show_color(&w, &lw);
    }
    if (rc != 0) {
        fprintf(stderr, "pipetrace why: %s: out of memory\n", s.path);
        why_free(&w);
        pt_scene_free(&s);
        pt_cli_out_close(&term);
        return PT_EXIT_INPUT;
    }
    why_free(&w);
    pt_scene_free(&s);
    if (pt_cli_out_close(&term) != 0) {
        fputs("pipetrace why: cannot write to standard output\n", stderr);
        return PT_EXIT_INPUT;
    }
    return 0;
}
