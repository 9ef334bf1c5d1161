/*
** src/cmd_why.c -- pipetrace why: which segments lit a pixel, or why none did
** See LICENSE for copyright and license.
**
**   pipetrace why [SCENE] X_FB Y_FB
**
** Every segment of the scene is rasterized exactly as the renderer does it
** (pt_raster_segment, with callbacks of our own), so "lit" means "the renderer
** writes this pixel".  A pixel that nothing lit gets the segments that come
** nearest, measured from the pixel's centre to the segment between its two
** pixel-plane endpoints (before rounding), mapped to framebuffer coordinates:
** the logical pixel (x_pp, y_pp) is the point (x_ul + x_pp - 1, y_ul + h - y_pp)
** of the framebuffer, whose pixel centres sit at integer coordinates.  For each
** of them, the stage where the pixel was lost; the first that applies wins (the
** table below).  Whether a clipped step landed on the pixel comes from the
** rasterizer's clip runs, which give only a run's first and last step: it is
** exact when the run pins the step down (one row or column, or one diagonal, or
** the pixel off the run's range), and otherwise decided by the segment between
** the rounded endpoints (the line the DDA steps along) passing within half a
** pixel of the pixel's centre.
**
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
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "commands.h"
#include "cli.h"
#include "explain.h"
#include "numfmt.h"
#include "raster.h"
#include "scene.h"

#define EXIT_USAGE 1
#define EXIT_INPUT 2
#define NEAREST    3             /* segments listed for a pixel nothing lit */

static const char usage[] =
"usage: pipetrace why [SCENE] X_FB Y_FB\n"
"Say which segments lit the framebuffer pixel (X_FB, Y_FB) of SCENE (default:\n"
"the built-in scene), with their vertices' pixel-plane and viewport coordinates.\n"
"When none did, list the nearest segments and the stage where each lost it:\n"
"outside the viewport, clipped, skipped, behind the camera, degenerate, or\n"
"endpoints rounded elsewhere.\n";

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

/* The pixel asked about, in viewport coordinates, and what one segment did. */
typedef struct look {
    int64_t tx, ty;              /* target (x_vp, y_vp) */
    seg_eval *e;
} look;

static uint64_t cheb(int64_t dx, int64_t dy)
{
    uint64_t ax = (uint64_t)(dx < 0 ? -dx : dx), ay = (uint64_t)(dy < 0 ? -dy : dy);
    return ax > ay ? ax : ay;
}

/* Pixels written: is it the target, is it the nearest so far? */
static void on_pixel(void *ud, int64_t x_vp, int64_t y_vp)
{
    look *lk = ud;
    seg_eval *e = lk->e;
    int64_t dx = x_vp - lk->tx, dy = y_vp - lk->ty;

    e->npix++;
    if (dx == 0 && dy == 0) e->lit = 1;
    if (!e->have_near) {
        e->have_near = 1;
        e->near_x = x_vp; e->near_y = y_vp;
    } else {
        int64_t ex = e->near_x - lk->tx, ey = e->near_y - lk->ty;
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

static void on_clip(void *ud, uint64_t count, pt_pix first, pt_pix last)
{
    look *lk = ud;
    int h = run_holds(count, first, last, lk->tx, lk->ty);

    lk->e->nclip += count;
    lk->e->clip_x = first.x;
    lk->e->clip_y = first.y;
    if (h == 1 || (h == -1 && lk->e->clip_hit == 0)) lk->e->clip_hit = h;
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

/* The journeys of segment si of model mi's two endpoints. */
static void seg_journeys(const pt_scene *s, size_t mi, size_t si, pt_journey *a, pt_journey *b)
{
    const pt_model *m = &s->models[mi];
    pt_stage_params par;

    pt_stage_params_of(&par, s, m);
    pt_journey_compute(a, &par, m->v[m->seg[si].a]);
    pt_journey_compute(b, &par, m->v[m->seg[si].b]);
}

/* Rasterize segment si of model mi and measure it against (X, Y). */
static void evaluate(const pt_scene *s, size_t mi, size_t si, int64_t X, int64_t Y,
                     seg_eval *e)
{
    pt_journey a, b;
    const pt_vrec *pa, *pb;
    pt_vec2 p0, p1;
    pt_raster_out out;
    look lk;

    memset(e, 0, sizeof *e);
    e->mi = mi;
    e->si = si;
    seg_journeys(s, mi, si, &a, &b);
    pa = &a.rec[PT_STAGE_PIXEL];
    pb = &b.rec[PT_STAGE_PIXEL];
    p0.x = pa->x; p0.y = pa->y;
    p1.x = pb->x; p1.y = pb->y;
    lk.tx = X - s->vp_x;
    lk.ty = Y - s->vp_y;
    lk.e = e;
    out.pixel = on_pixel;
    out.clip = on_clip;
    out.ud = &lk;
    e->result = pt_raster_segment(p0, p1, s->vp_w, s->vp_h, &out);
    e->dist = seg_dist((double)X, (double)Y,                 /* (x_ul + x_pp - 1, */
                       s->vp_x + pa->x - 1, s->vp_y + s->vp_h - pa->y,   /* y_ul + h - y_pp) */
                       s->vp_x + pb->x - 1, s->vp_y + s->vp_h - pb->y);
    e->dist_drawn = HUGE_VAL;
    if (e->result != PT_RASTER_SKIPPED)                     /* rounded: viewport pixels */
        e->dist_drawn = seg_dist((double)lk.tx, (double)lk.ty,
                                 (double)a.rec[PT_STAGE_VIEWPORT].ix,
                                 (double)a.rec[PT_STAGE_VIEWPORT].iy,
                                 (double)b.rec[PT_STAGE_VIEWPORT].ix,
                                 (double)b.rec[PT_STAGE_VIEWPORT].iy);
}

/* "    v3  (x_pp, y_pp) = (..)  (x_vp, y_vp) = (..)" for one endpoint */
static void show_vertex(uint64_t v, const pt_journey *j)
{
    char pp[PT_EXPLAINLEN], vp[PT_EXPLAINLEN];

    pt_explain_values(pp, sizeof pp, j, PT_STAGE_PIXEL);
    pt_explain_values(vp, sizeof vp, j, PT_STAGE_VIEWPORT);
    printf("    v%llu  %s  %s%s%s\n", (unsigned long long)v, pp, vp,
           j->rec[PT_STAGE_VIEWPORT].flags & (PT_REC_INSIDE | PT_REC_NULL) ? "" : " outside",
           j->rec[PT_STAGE_IMAGE].flags & PT_REC_BEHIND ? ", behind the camera" : "");
}

/* "  tri s2 (v2 -> v3)" plus both endpoints. */
static void show_segment(const pt_scene *s, const seg_eval *e, const char *tail,
                         pt_journey *a, pt_journey *b)
{
    const pt_model *m = &s->models[e->mi];
    uint64_t va = m->seg[e->si].a + 1ull, vb = m->seg[e->si].b + 1ull;

    seg_journeys(s, e->mi, e->si, a, b);
    printf("  %s s%llu (v%llu -> v%llu)%s\n", m->name, (unsigned long long)e->si + 1,
           (unsigned long long)va, (unsigned long long)vb, tail);
    show_vertex(va, a);
    show_vertex(vb, b);
}

/* The stage where segment e lost pixel (X, Y), in words. */
static void show_reason(const pt_scene *s, const seg_eval *e, const pt_journey *a,
                        const pt_journey *b, long long X, long long Y, int target_inside)
{
    const pt_model *m = &s->models[e->mi];
    const pt_journey *behind = NULL;
    uint64_t vnull = a->rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL ? m->seg[e->si].a + 1ull
                                                                  : m->seg[e->si].b + 1ull;
    char num[PT_NUMLEN];

    if (s->perspective && a->rec[PT_STAGE_CAMERA].z > 0) behind = a;
    else if (s->perspective && b->rec[PT_STAGE_CAMERA].z > 0) behind = b;

    if (!target_inside && e->clip_hit == 1)
        printf("    lost at viewport: clipped by the viewport: one of its steps lands on "
               "this pixel, (x_vp, y_vp) = (%lld, %lld), but the pixel lies outside the "
               "viewport and steps there are not drawn\n",
               (long long)(X - s->vp_x), (long long)(Y - s->vp_y));
    else if (!target_inside && e->clip_hit == -1 && e->dist_drawn <= 0.5)
        printf("    lost at viewport: clipped by the viewport: it runs through this pixel "
               "(the line between its rounded endpoints passes within half a pixel of the "
               "centre), but the pixel lies outside the viewport and steps there are not "
               "drawn\n");
    else if (!target_inside)
        printf("    lost at viewport: outside the viewport: the pixel lies outside the "
               "viewport, nothing is ever drawn there\n");
    else if (e->result == PT_RASTER_SKIPPED)
        printf("    lost at viewport: skipped: v%llu has no integer pixel (not finite, or "
               "beyond 2^62), so the segment is not drawn\n", (unsigned long long)vnull);
    else if (behind) {
        pt_fmt_shortest(num, behind->rec[PT_STAGE_CAMERA].z);
        printf("    lost at image: behind the camera: v%llu has z_c = %s > 0 and is "
               "projected mirrored through the origin, so the line drawn is not the one "
               "in front of the camera\n", behind == a ? m->seg[e->si].a + 1ull
                                                      : m->seg[e->si].b + 1ull, num);
    } else if (e->result == PT_RASTER_DEGENERATE && e->npix)
        printf("    lost at raster: degenerate: both endpoints round to one pixel, and it "
               "drew that one pixel elsewhere, at (x_fb, y_fb) = (%lld, %lld)\n",
               (long long)(e->near_x + s->vp_x), (long long)(e->near_y + s->vp_y));
    else if (e->result == PT_RASTER_DEGENERATE)
        printf("    lost at viewport: degenerate and clipped: both endpoints round to one "
               "pixel, (x_vp, y_vp) = (%lld, %lld), outside the viewport\n",
               (long long)e->clip_x, (long long)e->clip_y);
    else if (e->npix == 0)
        printf("    lost at viewport: clipped by the viewport: all %llu of its steps lie "
               "outside the viewport\n", (unsigned long long)e->nclip);
    else if (e->dist <= 0.5)
        printf("    lost at raster: endpoints rounded elsewhere: the segment passes through "
               "this pixel, but the DDA steps from the rounded endpoints and its nearest "
               "step lit the neighbouring pixel (x_fb, y_fb) = (%lld, %lld)\n",
               (long long)(e->near_x + s->vp_x), (long long)(e->near_y + s->vp_y));
    else
        printf("    not lost: it passes by; the nearest pixel it lit is (x_fb, y_fb) = "
               "(%lld, %lld)\n",
               (long long)(e->near_x + s->vp_x), (long long)(e->near_y + s->vp_y));
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

int pt_cmd_why(int argc, char **argv)
{
    const char *pos[3];
    int npos = 0, k, rc, inside;
    long long X, Y;
    pt_scene s;
    seg_eval best[NEAREST], e;
    int nbest = 0;
    uint64_t nlit = 0;
    const pt_model *last = NULL;
    size_t last_seg = 0, mi, si;
    pt_journey ja, jb;

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); return 0; }
        if (a[0] == '-' && !(a[1] >= '0' && a[1] <= '9')) {
            fprintf(stderr, "pipetrace why: unknown option %s\nTry 'pipetrace why --help'.\n", a);
            return EXIT_USAGE;
        }
        if (npos == 3) {
            fputs("pipetrace why: too many arguments\nTry 'pipetrace why --help'.\n", stderr);
            return EXIT_USAGE;
        }
        pos[npos++] = a;
    }
    if (npos < 2 || parse_int(pos[npos - 2], &X) || parse_int(pos[npos - 1], &Y)) {
        fputs("pipetrace why: needs a pixel: X_FB Y_FB (whole numbers)\n"
              "Try 'pipetrace why --help'.\n", stderr);
        return EXIT_USAGE;
    }

    if (pt_cli_load(&s, npos == 3 ? pos[0] : NULL) != 0) return EXIT_INPUT;
    rc = s.matrix ? 0 : pt_journey_agrees(&s);
    if (rc != 1) {
        fprintf(stderr, "pipetrace why: %s: %s\n", s.path, rc < 0 ? "out of memory"
                : "why follows the classic camera (model -> camera -> image -> pixel -> "
                  "viewport); this scene has the matrix camera: try 'pipetrace step'");
        pt_scene_free(&s);
        return EXIT_INPUT;
    }
    if (X < 0 || X >= s.fb_w || Y < 0 || Y >= s.fb_h) {
        fprintf(stderr, "pipetrace why: pixel (%lld, %lld) lies outside the %d x %d "
                "framebuffer of %s (x_fb 0..%d, y_fb 0..%d)\n", X, Y, s.fb_w, s.fb_h,
                s.path, s.fb_w - 1, s.fb_h - 1);
        pt_scene_free(&s);
        return EXIT_INPUT;
    }

    inside = X >= s.vp_x && X < s.vp_x + s.vp_w && Y >= s.vp_y && Y < s.vp_y + s.vp_h;
    printf("pixel (x_fb, y_fb) = (%lld, %lld) of %s: idx = %lld, ", X, Y, s.path,
           Y * s.fb_w + X);
    if (inside)
        printf("inside the viewport at (x_vp, y_vp) = (%lld, %lld)\n", X - s.vp_x, Y - s.vp_y);
    else
        printf("outside the viewport (x_fb %d..%d, y_fb %d..%d): nothing is ever drawn there\n",
               s.vp_x, s.vp_x + s.vp_w - 1, s.vp_y, s.vp_y + s.vp_h - 1);

    for (mi = 0; mi < s.nmodels; mi++) {
        for (si = 0; si < s.models[mi].nseg; si++) {
            evaluate(&s, mi, si, X, Y, &e);
            if (e.lit) {
                if (nlit++ == 0) printf("lit by:\n");
                show_segment(&s, &e, "", &ja, &jb);
                last = &s.models[mi];
                last_seg = si;
                continue;
            }
            if (nlit) continue;
            for (k = nbest; k > 0 && nearer(&e, &best[k - 1]); k--)
                if (k < NEAREST) best[k] = best[k - 1];
            if (k < NEAREST) {
                best[k] = e;
                if (nbest < NEAREST) nbest++;
            }
        }
    }

    if (nlit) {
        printf("color %d %d %d: %s s%llu is the last segment drawn there\n",
               last->color[0], last->color[1], last->color[2], last->name,
               (unsigned long long)last_seg + 1);
    } else {
        printf("not lit: no segment writes it, so it keeps the background color %d %d %d\n",
               s.background[0], s.background[1], s.background[2]);
        if (nbest)
            printf("nearest segments (distance from the pixel's centre to the segment "
                   "between its pixel-plane endpoints, in framebuffer pixels):\n");
        for (k = 0; k < nbest; k++) {
            char tail[64], d[PT_NUMLEN];

            if (best[k].dist == HUGE_VAL) snprintf(tail, sizeof tail, ": distance unknown");
            else {
                pt_fmt_fixed(d, best[k].dist, 2);
                snprintf(tail, sizeof tail, ": %s pixels away", d);
            }
            show_segment(&s, &best[k], tail, &ja, &jb);
            show_reason(&s, &best[k], &ja, &jb, X, Y, inside);
        }
        if (!nbest) printf("the scene has no segments\n");
    }
    pt_scene_free(&s);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace why: cannot write to standard output\n", stderr);
        return EXIT_INPUT;
    }
    return 0;
}
