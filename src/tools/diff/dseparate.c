/*
** src/tools/diff/dseparate.c -- pipetrace diff: a scene that tells apart the mistakes diff could not
** See LICENSE for copyright and license.
**
** Each candidate piece of a scene is run through the right stages and through
** every known mistake of the catalogue (the mistake's own function, as diff
** tests a hypothesis); what a trace of the piece would hold is its signature:
** renderer 4, each vertex's values at every stage and, for a segment, the
** rasterizer's pixels and clip records replayed as the raster check replays
** them; renderers 7 and 9, a position's world vertices, a segment's camera
** vertices, or the model a clip stage leaves.  Two mistakes are
** told apart by a piece whose signatures differ by more than a trace's
** printed digits hide.  Greedily, the piece that tells the most pairs apart
** is kept, until every pair with a listed mistake in it is; then each kept
** piece that others make redundant is dropped again.
*/
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/outfile.h"
#include "io/tread79.h"
#include "tools/diff/diff.h"
#include "tools/diff/dseparate.h"

#define MAXH 24                  /* hypotheses, the right stages (0) included */
#define MAXC 24                  /* candidate pieces */
#define MAXV 48                  /* values in a signature (a position's: 33) */

/* What a trace of one piece holds under one hypothesis. */
typedef struct sig {
    double val[MAXV];            /* values, in a fixed order */
    unsigned char isint[MAXV];   /* 1: compared exactly */
    size_t n;
    uint64_t px, cl;             /* renderer 4's replayed pixels and clip records */
    int has_px, has_cl;
    int fragile;                 /* 1: a colour a trace's printed digits leave
                                 ** between two bytes (renderers 7 and 9) */
} sig;

static void sig_real(sig *s, double x, int isint)
{
    if (s->n < MAXV) {
        s->isint[s->n] = (unsigned char)isint;
        s->val[s->n++] = x;
    }
}

/* 1 when a trace tells a from b: an integer that differs, a double that differs
** by more than a text trace's six decimals hide, pixels that differ. */
static int sig_differ(const sig *a, const sig *b)
{
    size_t k;

    if (a->n != b->n) return 1;
    for (k = 0; k < a->n; k++) {
        double x = a->val[k], y = b->val[k];
        if (isnan(x) || isnan(y)) { if (isnan(x) != isnan(y)) return 1; continue; }
        if (x == y) continue;
        if (a->isint[k] || isinf(x) || isinf(y)) return 1;
        if (fabs(x - y) > 1e-5 + 1e-6 * fmax(fabs(x), fabs(y))) return 1;
    }
    if (a->has_px && b->has_px && a->px != b->px) return 1;
    if (a->has_cl && b->has_cl && a->cl != b->cl) return 1;
    return 0;
}

/* ===== the search, the same for every renderer ===== */

typedef struct search {
    sig s[MAXC][MAXH];           /* s[piece][hypothesis] */
    size_t nc, nh;
    unsigned char listed[MAXH];  /* 1: must be told from every other */
    unsigned char keep[MAXC];    /* the pieces kept */
    size_t bad[2];               /* a pair no piece tells apart */
} search;

/* Pairs (i < j) that pieces keep[] (or piece c alone, c < nc) tell apart,
** among those with a listed member, into need (1: not told apart yet);
** returns how many are left. */
static size_t left_pairs(const search *q, const unsigned char *keep, unsigned char need[MAXH][MAXH])
{
    size_t i, j, c, left = 0;

    for (i = 0; i < q->nh; i++)
        for (j = i + 1; j < q->nh; j++) {
            need[i][j] = (unsigned char)(q->listed[i] || q->listed[j]);
            for (c = 0; need[i][j] && c < q->nc; c++)
                if (keep[c] && sig_differ(&q->s[c][i], &q->s[c][j])) need[i][j] = 0;
            left += need[i][j];
        }
    return left;
}

/* Keep the fewest pieces the greedy way finds.  Returns 0, or -1 with a pair
** no piece tells apart in q->bad. */
static int cover(search *q)
{
    unsigned char need[MAXH][MAXH], none[MAXC];
    size_t i, j, c;

    memset(q->keep, 0, sizeof q->keep);
    memset(none, 0, sizeof none);
    while (left_pairs(q, q->keep, need)) {
        size_t best = q->nc, bestn = 0;
        for (c = 0; c < q->nc; c++) {
            size_t n = 0;
            if (q->keep[c]) continue;
            for (i = 0; i < q->nh; i++)
                for (j = i + 1; j < q->nh; j++)
                    n += need[i][j] && sig_differ(&q->s[c][i], &q->s[c][j]);
            if (n > bestn) { bestn = n; best = c; }
        }
        if (!bestn) {
            for (i = 0; i < q->nh; i++)
                for (j = i + 1; j < q->nh; j++)
                    if (need[i][j]) { q->bad[0] = i; q->bad[1] = j; return -1; }
        }
        q->keep[best] = 1;
    }
    for (c = 0; c < q->nc; c++) {              /* drop what the others cover */
        if (!q->keep[c]) continue;
        q->keep[c] = 0;
        if (left_pairs(q, q->keep, need)) q->keep[c] = 1;
    }
    return 0;
}

/* ===== text ===== */

static void put(pt_sep *o, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

static void put(pt_sep *o, const char *fmt, ...)
{
    va_list ap;
    int n;

    if (o->full) return;
    va_start(ap, fmt);
    n = vsnprintf(o->text + o->n, sizeof o->text - o->n, fmt, ap);
    va_end(ap);
    if (n > 0) o->n += (size_t)n;
    if (o->n >= sizeof o->text) {               /* cut: never half a scene */
        o->ok = 0;
        o->full = 1;
        o->n = (size_t)snprintf(o->text, sizeof o->text, "the scene would be too long.");
    }
}

/* A comment of the scene: "# " lines of at most 78 columns, words kept whole. */
static void comment(pt_sep *o, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

static void comment(pt_sep *o, const char *fmt, ...)
{
    char b[2048];
    const char *p = b;
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(b, sizeof b, fmt, ap);
    va_end(ap);
    while (*p) {
        size_t n = strlen(p), cut = n, k;
        if (n > 76) {
            for (cut = 76; cut > 0 && p[cut] != ' '; cut--) {}
            if (!cut) for (cut = 76; p[cut] && p[cut] != ' '; cut++) {}
        }
        put(o, "# %.*s\n", (int)cut, p);
        for (k = cut; p[k] == ' '; k++) {}
        p += k;
    }
}

/* A sentence instead of a scene. */
static void none(pt_sep *o, const char *what, const char *a, const char *b)
{
    o->ok = 0;
    o->n = 0;
    put(o, what, a, b);
}

/* "A; B; C" of the listed names, into b (len bytes). */
static const char *list_names(char *b, size_t len, const char *const *names, size_t n)
{
    size_t k, m = 0;

    b[0] = '\0';
    for (k = 0; k < n && m < len; k++)
        m += (size_t)snprintf(b + m, len - m, "%s%s", k ? "; " : "", names[k]);
    return b;
}

/* ===== renderer 4 ===== */

/* A hypothesis of renderer 4: a stage's mistake, the rasterizer's of the same
** name, or both (NULL, NULL: the right stages). */
typedef struct hyp4 {
    const char *name;
    const pt_mistake *mk;
    const pt_raster_mistake *rk;
} hyp4;

/* A candidate piece: one vertex, or a segment. */
typedef struct piece4 {
    double t[3];                 /* its model's translation */
    double v[2][3];              /* model coordinates */
    int nv;                      /* 1 or 2 */
    const char *what;            /* what it is for */
} piece4;

/* The scene's numbers. */
typedef struct par4 {
    pt_stage_params p;           /* translation 0 */
    int pixels_only;
} par4;

/* Append stage st's values of v to s. */
static void sig_val(sig *s, int st, const pt_cat_val *v)
{
    int k, n = pt_stage_nvalues((pt_stage)st);

    if (pt_diff_is_real(st)) {
        for (k = 0; k < n; k++) sig_real(s, v->d[k], 0);
        return;
    }
    sig_real(s, (double)(v->flags & (PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y)), 1);
    for (k = 0; k < n; k++) sig_real(s, pt_cat_has(v, k) ? (double)v->n[k] : 0.0, 1);
}

/* Vertex m of a model translated by t, through the classic stages, mk's stage
** with the mistake; its values into s (unless NULL), its pixel-plane values
** into *pp. */
static void run4(const par4 *pr, const double t[3], const pt_mistake *mk, const double m[3],
                 sig *s, pt_cat_val *pp)
{
    pt_stage_params par = pr->p;
    pt_cat_val in, out;
    size_t k;

    par.translate.x = t[0]; par.translate.y = t[1]; par.translate.z = t[2];
    memset(&in, 0, sizeof in);
    in.d[0] = m[0]; in.d[1] = m[1]; in.d[2] = m[2];
    for (k = 1; k < PT_CLASSIC_NORDER; k++) {
        int st = (int)pt_classic_order[k];
        if (mk && mk->stage == st) {
            memset(&out, 0, sizeof out);
            mk->apply(&par, &in, &out);
        } else {
            pt_cat_right(st, &par, &in, &out);
        }
        if (s) sig_val(s, st, &out);
        if (st == PT_STAGE_PIXEL) *pp = out;
        in = out;
    }
}

/* Piece c of the search under hypothesis hy. */
static void sig4(const par4 *pr, const piece4 *pc, const hyp4 *hy, sig *s)
{
    pt_cat_val pp[2];
    int k;

    memset(s, 0, sizeof *s);
    for (k = 0; k < pc->nv; k++)
        run4(pr, pc->t, hy->mk, pc->v[k], pr->pixels_only ? NULL : s, &pp[k]);
    if (pc->nv == 2) {
        const pt_raster_mistake *rk = hy->rk;
        int64_t ends[4];
        uint64_t h[2];
        for (k = 0; k < 4; k++) {
            double e = pt_raster_java_round(pp[k / 2].d[k % 2]);
            if (!(fabs(e) < 1e15)) return;      /* no pixel: nothing replayed */
            ends[k] = (int64_t)e;
        }
        if (pt_diff_replay_sig(ends, pr->p.w, pr->p.h, rk ? rk->to_vp : NULL,
                               rk ? rk->steps : 0, h) != 0) return;
        if (rk && rk->no_offset && (pr->p.x_ul || pr->p.y_ul)) h[0] = ~h[0];   /* moved */
        s->px = h[0];
        s->cl = h[1];
        s->has_px = 1;
        s->has_cl = !rk || !rk->steps;
    }
}

/* Model coordinate whose pixel-plane value (axis 0: x_pp, 1: y_pp) is
** target, or the nearest found, for a vertex at z_c = -1 (perspective) or
** z_c = 0: there x_ip = x_c = x_m exactly.  The pixel stage's formula turned
** around gives only the first guess; each step asks the stage itself. */
static double aim(const par4 *pr, int axis, double target)
{
    int size = axis ? pr->p.h : pr->p.w, k;
    double x = (target - 0.5) * PT_PIXEL_DIVISOR / size - 1, best = x, bd = HUGE_VAL;
    pt_cat_val in, out;

    for (k = 0; k < 256; k++) {
        double d;
        memset(&in, 0, sizeof in);
        in.d[0] = in.d[1] = x;
        in.d[2] = pr->p.perspective ? -1 : 0;
        pt_cat_right(PT_STAGE_PIXEL, &pr->p, &in, &out);
        d = fabs(out.d[axis] - target);
        if (d < bd) { bd = d; best = x; }
        if (d == 0 || !isfinite(d)) break;
        x = nextafter(x, out.d[axis] < target ? HUGE_VAL : -HUGE_VAL);
    }
    return best;
}

/* A piece at pixel-plane targets (x0, y0) and, when two, (x1, y1). */
static void at(const par4 *pr, piece4 *pc, int two, double x0, double y0, double x1, double y1,
               const char *what)
{
    memset(pc, 0, sizeof *pc);
    pc->t[2] = pr->p.perspective ? -1 : 0;
    pc->nv = two ? 2 : 1;
    pc->v[0][0] = aim(pr, 0, x0);
    pc->v[0][1] = aim(pr, 1, y0);
    pc->v[1][0] = aim(pr, 0, x1);
    pc->v[1][1] = aim(pr, 1, y1);
    pc->what = what;
}

/* The candidate pieces for pr. */
static size_t pieces4(const par4 *pr, piece4 *pc)
{
    double w = pr->p.w, h = pr->p.h, xm = floor((w + 1) / 2) + 0.2, ym = floor((h + 1) / 2) + 0.2;
    size_t n = 0;

    at(pr, &pc[n++], 0, -1.5, 3.5, 0, 0, "x_pp and y_pp on ties, negative and positive");
    at(pr, &pc[n++], 0, -3.5, -4.5, 0, 0, "negative ties");
    at(pr, &pc[n++], 0, 2.5, -7.7, 0, 0, "a positive tie, a negative value");
    at(pr, &pc[n++], 0, -4.3, 0.37 * h + 0.21, 0, 0, "a negative x_pp, no tie");
    at(pr, &pc[n++], 0, 3.5, 1.5, 0, 0, "positive ties");
    at(pr, &pc[n++], 0, 0.37 * w + 0.21, 0.61 * h + 0.13, 0, 0, "inside, off the middle");
    at(pr, &pc[n++], 0, pr->p.W - pr->p.x_ul + 1, ym, 0, 0, "one pixel right of the framebuffer");
    at(pr, &pc[n++], 0, xm, h - (pr->p.H - pr->p.y_ul), 0, 0, "one pixel below the framebuffer");
    at(pr, &pc[n++], 0, -pr->p.x_ul, ym, 0, 0, "one pixel left of the framebuffer");
    at(pr, &pc[n++], 0, xm, h + 1 + pr->p.y_ul, 0, 0, "one pixel above the framebuffer");
    memset(&pc[n], 0, sizeof pc[n]);
    pc[n].t[0] = 0.25; pc[n].t[1] = -0.5; pc[n].t[2] = pr->p.perspective ? -3 : 0;
    pc[n].v[0][0] = -1; pc[n].v[0][1] = -1;
    pc[n].nv = 1;
    pc[n++].what = "a model translated in x, y and z";
    if (pr->p.perspective) {
        memset(&pc[n], 0, sizeof pc[n]);
        pc[n].t[2] = -1;
        pc[n].v[0][0] = 0.3; pc[n].v[0][1] = 0.2; pc[n].v[0][2] = 3;
        pc[n].nv = 1;
        pc[n++].what = "a vertex behind the camera";
    }
    if (w >= 14 && h >= 2)
        at(pr, &pc[n++], 1, 1, 0, 13, 1, "logical pixels (1, 0) to (13, 1): the DDA's y reaches "
           "0.49999999999999994 at x = 7");
    if (w >= 10 && h >= 2)
        at(pr, &pc[n++], 1, -3, 0, 9, 1, "logical pixels (-3, 0) to (9, 1): steps left of the "
           "viewport, and y = 0.49999999999999994 at x = 3");
    at(pr, &pc[n++], 1, 0.25 * w + 0.3, ym, 0.75 * w + 0.3, ym, "a row inside the viewport");
    at(pr, &pc[n++], 1, xm, 0.2 * h + 0.3, xm + 0.4, 0.8 * h + 0.3, "a column inside the viewport");
    at(pr, &pc[n++], 1, 0, ym, 5, ym, "a row from the viewport's left edge");
    return n;
}

/* The hypotheses of renderer 4 for pr, names[] marked as listed; those not
** in the catalogue into *missing (a name, or NULL).  Returns their number. */
static size_t hyps4(const par4 *pr, const char *const *names, size_t n, hyp4 *hy,
                    unsigned char *listed, const char **missing)
{
    size_t nh = 1, k, j;

    memset(hy, 0, sizeof *hy);
    hy[0].name = "the right stages";
    if (pr->pixels_only) {
        for (k = 0; k < PT_NRASTER_MISTAKES && nh < MAXH; k++) {
            hy[nh].name = pt_raster_mistakes[k].name;
            hy[nh].mk = NULL;
            hy[nh++].rk = &pt_raster_mistakes[k];
        }
    } else {
        for (k = 0; k < PT_NMISTAKES && nh < MAXH; k++) {
            const pt_mistake *mk = &pt_mistakes[k];
            int dup = 0;
            if (mk->stage == PT_STAGE_IMAGE && !pr->p.perspective) continue;
            if (mk->odd_only && pr->p.w % 2 == 0 && pr->p.h % 2 == 0) continue;
            for (j = 1; j < nh; j++) dup |= !strcmp(hy[j].name, mk->name);
            if (dup) continue;
            hy[nh].name = mk->name;
            hy[nh].mk = mk;
            hy[nh].rk = NULL;
            for (j = 0; j < PT_NRASTER_MISTAKES; j++)
                if (!strcmp(pt_raster_mistakes[j].name, mk->name)) {
                    hy[nh].rk = &pt_raster_mistakes[j];
                    break;
                }
            nh++;
        }
    }
    memset(listed, 0, MAXH);
    *missing = NULL;
    for (k = 0; k < n; k++) {
        int found = 0;
        for (j = 1; j < nh; j++)
            if (!strcmp(hy[j].name, names[k])) listed[j] = 1, found = 1;
        if (!found && !*missing) *missing = names[k];
    }
    return nh;
}

/* Search with the numbers pr; 0, or -1 (q->bad the pair left). */
static int search4(const par4 *pr, const char *const *names, size_t n, search *q, piece4 *pc,
                   hyp4 *hy, const char **missing)
{
    size_t c, i;

    q->nh = hyps4(pr, names, n, hy, q->listed, missing);
    q->nc = pieces4(pr, pc);
    for (c = 0; c < q->nc; c++)
        for (i = 0; i < q->nh; i++) sig4(pr, &pc[c], &hy[i], &q->s[c][i]);
    return cover(q);
}

/* The lines of the kept pieces: vertices grouped by translation into models
** joined by a polyline (a vertex no segment uses is not traced), each
** segment a model of its own. */
static void write4(const par4 *pr, const search *q, const piece4 *pc, pt_sep *o)
{
    size_t c, d, nm = 0;
    unsigned char done[MAXC];
    char b[3][PT_NUMLEN];

    put(o, "framebuffer %d %d\nviewport %d %d %d %d\ncamera %s\n", pr->p.W, pr->p.H,
        pr->p.x_ul, pr->p.y_ul, pr->p.w, pr->p.h, pr->p.perspective ? "perspective" : "orthographic");
    memset(done, 0, sizeof done);
    for (c = 0; c < q->nc; c++) {
        size_t nv = 0, k;
        if (!q->keep[c] || done[c]) continue;
        put(o, "\nmodel p%zu\ntranslate %s %s %s\n", ++nm, pt_diff_num(pc[c].t[0], b[0]),
            pt_diff_num(pc[c].t[1], b[1]), pt_diff_num(pc[c].t[2], b[2]));
        for (d = c; d < q->nc; d++) {
            if (!q->keep[d] || done[d] || memcmp(pc[d].t, pc[c].t, sizeof pc[c].t) ||
                (pc[d].nv == 2) != (pc[c].nv == 2) || (pc[c].nv == 2 && d != c)) continue;
            done[d] = 1;
            comment(o, "%s", pc[d].what);
            for (k = 0; k < (size_t)pc[d].nv; k++) {
                pt_cat_val pp;
                char x[PT_NUMLEN], y[PT_NUMLEN];
                memset(&pp, 0, sizeof pp);   /* run4 sets it: the pixel stage always runs */
                run4(pr, pc[d].t, NULL, pc[d].v[k], NULL, &pp);
                put(o, "v %s %s %s    # x_pp = %s, y_pp = %s\n", pt_diff_num(pc[d].v[k][0], b[0]),
                    pt_diff_num(pc[d].v[k][1], b[1]), pt_diff_num(pc[d].v[k][2], b[2]),
                    pt_diff_num(pp.d[0], x), pt_diff_num(pp.d[1], y));
                nv++;
            }
        }
        if (nv == 1) put(o, "l 1 1\n");
        else {
            put(o, "l");
            for (k = 1; k <= nv; k++) put(o, " %zu", k);
            put(o, "\n");
        }
    }
}

void pt_sep_classic(const pt_sep_r4 *sp, const char *const *names, size_t n, pt_sep *out)
{
    search *q = malloc(sizeof *q);
    piece4 pc[MAXC];
    hyp4 hy[MAXH];
    par4 pr[2];
    const char *missing = NULL;
    char nb[1024];
    int k, got = -1, ok = -1;

    memset(out, 0, sizeof *out);
    if (!q) { none(out, "%s%s", "out of memory", "."); return; }
    memset(pr, 0, sizeof pr);
    for (k = 0; k < 2; k++) {                   /* EXPECTED's numbers, else the self-check's */
        pr[k].pixels_only = sp->pixels_only;
        pr[k].p.perspective = sp->perspective;
        pr[k].p.w = 25; pr[k].p.h = 19; pr[k].p.x_ul = 7; pr[k].p.y_ul = 5;
        pr[k].p.W = 41; pr[k].p.H = 33;
    }
    if (sp->have && sp->w >= 1 && sp->h >= 1 && sp->W >= sp->x_ul + sp->w &&
        sp->H >= sp->y_ul + sp->h && sp->x_ul >= 0 && sp->y_ul >= 0 && sp->W <= 4096 && sp->H <= 4096) {
        pr[0].p.w = sp->w; pr[0].p.h = sp->h; pr[0].p.x_ul = sp->x_ul; pr[0].p.y_ul = sp->y_ul;
        pr[0].p.W = sp->W; pr[0].p.H = sp->H;
        ok = search4(&pr[0], names, n, q, pc, hy, &missing);
        got = 0;
    }
    if (ok != 0) {
        const char *bad[2];
        int tried = got == 0;
        bad[0] = tried ? hy[q->bad[0]].name : "";
        bad[1] = tried ? hy[q->bad[1]].name : "";
        ok = search4(&pr[1], names, n, q, pc, hy, &missing);
        if (ok != 0) {
            none(out, "no scene of the candidates pipetrace diff tries tells %s from %s.",
                 hy[q->bad[0]].name, hy[q->bad[1]].name);
            free(q);
            return;
        }
        got = 1;
        out->ok = 1;
        comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for "
                "the purpose: on it each gives a trace of its own, and none gives the right "
                "one's.", list_names(nb, sizeof nb, names, n));
        if (tried)
            comment(out, "EXPECTED's viewport (%d x %d at (%d, %d) in %d x %d) cannot tell %s "
                    "from %s: these sizes are the self-check scene's (odd, off the corner).",
                    sp->w, sp->h, sp->x_ul, sp->y_ul, sp->W, sp->H, bad[0], bad[1]);
        else
            comment(out, "EXPECTED has no viewport or framebuffer to keep: these sizes are the "
                    "self-check scene's (odd, off the corner).");
    } else {
        out->ok = 1;
        comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for "
                "the purpose: on it each gives a trace of its own, and none gives the right "
                "one's. Viewport, framebuffer and camera: EXPECTED's.",
                list_names(nb, sizeof nb, names, n));
    }
    if (missing)
        comment(out, "(%s is no mistake of the catalogue: it is not told apart here.)", missing);
    if (sp->pixels_only)
        comment(out, "Render it with both renderers as the course's log with its pixels "
                "(pipetrace SCENE --format kraft-pixels), and diff the two logs.");
    else
        put(out, "# Render it with both builds, as JSON Lines, and diff the two traces:\n"
            "#   build/pipetrace SCENE --format jsonl --trace expected.jsonl\n"
            "#   build-student/pipetrace SCENE --format jsonl --trace mine.jsonl\n"
            "#   build/pipetrace diff expected.jsonl mine.jsonl\n");
    write4(&pr[got], q, pc, out);
    free(q);
}

/* ===== renderers 7 and 9: the world, the camera, the near clip, the clip ===== */

/* A segment of the candidates, in view coordinates, with its two colours. */
typedef struct piece79 {
    double v[2][3];
    int rgb[2][3];
} piece79;

/* cam's numbers as the stages take them. */
static pt_rv_camera rv_camera(const pt_c79cam *cam)
{
    pt_rv_camera k;

    memset(&k, 0, sizeof k);
    k.perspective = cam->persp;
    k.l = cam->l; k.r = cam->r; k.b = cam->b; k.t = cam->t; k.n = cam->n;
    return k;
}

/* v (view coordinates) in camera coordinates, by cam's renderer's stage. */
static pt_vec4 camera79(const pt_c79cam *cam, const double v[3])
{
    pt_rv_camera k = rv_camera(cam);
    pt_vec4 p = {v[0], v[1], v[2], 1.0};

    if (cam->renderer == 9) {
        pt_jmat m = pt_r9_normalize_matrix(&k);
        return pt_r9_view2camera(p, &m);
    }
    return pt_r7_view2camera(p, &k);
}

/* The camera stage's (x, y, z, w) of pc's vertices, mk's (or the right
** stage's when NULL): the catalogue's own function, given the view values
** and the right ones, as diff tests the hypothesis. */
static void sig_camera(const pt_c79cam *cam, const piece79 *pc, const pt_mistake79 *mk, sig *s)
{
    int e, k;

    for (e = 0; e < 2; e++) {
        pt_vec4 r = camera79(cam, pc->v[e]);
        double prev[4] = {pc->v[e][0], pc->v[e][1], pc->v[e][2], 1.0};
        double right[4] = {r.x, r.y, r.z, r.w}, o[4];
        if (mk) mk->vertex(cam, prev, right, o);
        else memcpy(o, right, sizeof o);
        for (k = 0; k < 4; k++) sig_real(s, o[k], 0);
    }
}

/* What clip stage st (mk's, or the right one when NULL) leaves of pc: the
** near clip takes the camera's vertices, the clip the image plane's. */
static void sig79(const pt_c79cam *cam, int st, const piece79 *pc, const pt_mistake79 *mk, sig *s)
{
    pt_rv_model m;
    pt_rv_prim p;
    size_t k;
    int rc, e;

    memset(s, 0, sizeof *s);
    if (st == PT_T79_CAMERA) {
        sig_camera(cam, pc, mk, s);
        return;
    }
    memset(&m, 0, sizeof m);
    memset(&p, 0, sizeof p);
    rc = 0;
    for (e = 0; e < 2; e++) {
        pt_vec4 v = camera79(cam, pc->v[e]);
        pt_rgb c;
        c.r = (float)pc->rgb[e][0] / 255.0f;
        c.g = (float)pc->rgb[e][1] / 255.0f;
        c.b = (float)pc->rgb[e][2] / 255.0f;
        if (st == PT_T79_CLIP) v = pt_rv_project(v, cam->persp);
        rc |= pt_rv_add_vertex(&m, v) | pt_rv_add_color(&m, c);
    }
    p.kind = PT_RV_LINE;
    p.v[1] = p.c[1] = 1;
    rc |= pt_rv_add_prim(&m, &p);
    if (rc == 0)
        rc = mk ? mk->clip(cam, &m) : st == PT_T79_CLIP ? pt_rv_clip(&m, NULL) < 0 ? -1 : 0
                                                        : pt_rv_nearclip(&m, cam->n, NULL);
    sig_real(s, rc, 1);
    sig_real(s, (double)m.nv, 1);
    sig_real(s, (double)m.np, 1);
    for (k = 0; rc == 0 && k < m.nv; k++) {
        sig_real(s, m.v[k].x, 0); sig_real(s, m.v[k].y, 0); sig_real(s, m.v[k].z, 0);
    }
    for (k = 0; rc == 0 && k < m.nc; k++) {     /* the log prints Color bytes */
        const float f[3] = {m.c[k].r, m.c[k].g, m.c[k].b};
        for (e = 0; e < 3; e++) {
            double x = (double)f[e] * 255;      /* 6 decimals: +-0.00013 of a byte */
            s->fragile |= fabs(x - floor(x) - 0.5) < 0.01;
            sig_real(s, pt_color_byte(f[e]), 1);
        }
    }
    for (k = 0; rc == 0 && k < m.np; k++) {
        sig_real(s, m.p[k].v[0], 1); sig_real(s, m.p[k].v[1], 1);
        sig_real(s, m.p[k].c[0], 1); sig_real(s, m.p[k].c[1], 1);
    }
    pt_rv_model_free(&m);
}

/* The near clip's candidates: segments across the near plane and its mirror
** image, between them, beyond them. */
static size_t pieces_near(const pt_c79cam *cam, piece79 *pc)
{
    static const int col[6][3] = {{255, 0, 0}, {0, 0, 255}, {0, 255, 0}, {255, 255, 0},
                                  {200, 100, 50}, {90, 30, 220}};
    static const double xy[5][4] = {{-0.3, -0.2, 0.4, 0.3}, {0.2, -0.3, -0.1, 0.25},
                                    {0.1, 0.1, -0.2, 0.15}, {-0.25, 0.3, 0.3, -0.2},
                                    {0.35, -0.1, -0.3, 0.2}};
    double lo = fmin(cam->n, -cam->n), hi = fmax(cam->n, -cam->n), a = hi - lo;
    double far, mid, beyond;
    size_t c;
    int i;

    if (!(a > 0) || !isfinite(a)) a = 0.2;
    far = lo - 10 * a; mid = (lo + hi) / 2; beyond = hi + 2 * a;
    {
        const double z[5][2] = {{far, beyond}, {far, mid}, {beyond, beyond + 2 * a},
                                {mid, far}, {far, beyond + a}};
        for (c = 0; c < 5; c++)
            for (i = 0; i < 2; i++) {
                pc[c].v[i][0] = xy[c][2 * i];
                pc[c].v[i][1] = xy[c][2 * i + 1];
                pc[c].v[i][2] = z[c][i];
                memcpy(pc[c].rgb[i], col[(2 * c + i) % 6], sizeof pc[c].rgb[i]);
            }
    }
    return 5;
}

/* The camera's candidates: segments in front of the camera whose ends lie
** off the lines where a skew mistake and a size mistake agree: through the
** eye, x_v = k z_v (r+l)/2 and y_v = k z_v (t+b)/2 with k = 1 (the skew
** forgotten, the width), -3 (its sign, the half-width twice), -2 (forgotten,
** twice), 3 (its sign, the width); orthographic, parallel to the z axis,
** x_v = k (r+l)/2 with k = -1, 3, 2, -3. */
static size_t pieces_camera(piece79 *pc)
{
    static const double v[3][6] = {{-0.3, -0.2, -2.1, 0.4, 0.3, -2.6},
                                   {0.35, -0.15, -3.2, -0.25, 0.45, -1.7},
                                   {0.6, 0.1, -2.4, 0.05, -0.55, -3.5}};
    static const int col[2][3] = {{255, 0, 0}, {0, 0, 255}};
    size_t c;
    int i;

    for (c = 0; c < 3; c++)
        for (i = 0; i < 2; i++) {
            memcpy(pc[c].v[i], v[c] + 3 * i, sizeof pc[c].v[i]);
            memcpy(pc[c].rgb[i], col[i], sizeof pc[c].rgb[i]);
        }
    return 3;
}

/* The view coordinates at z_v = -2 that the image plane's (x, y) comes
** from, by the camera's formula turned around: a first guess only, the
** signatures run the stages themselves. */
static void view_at(const pt_c79cam *cam, double x, double y, double v[3])
{
    double d = cam->persp ? 2 : 1;              /* x_c = x_p * -z_v (orthographic: x_p) */

    v[0] = x * d * (cam->r - cam->l) / 2 + d * (cam->r + cam->l) / 2;
    v[1] = y * d * (cam->t - cam->b) / 2 + d * (cam->t + cam->b) / 2;
    v[2] = -2;
}

/* The clip's candidates, each from an inside end to an outside one beyond
** one edge, given on the image plane (view_at()).  Two colours five bytes apart,
** cut a quarter of the way in from the outside end: the new colour
** interpolated (1.25 bytes in: a byte), in bytes (truncated: the next one)
** and not at all (the inside end's) are three bytes, and a t outside 0 .. 1
** (a mistake's) still makes a colour java.awt.Color takes; or one colour,
** which shows where each cut lands. */
static size_t pieces_clip(const pt_c79cam *cam, piece79 *pc)
{
    static const double img[6][4] = {
        {0.4, 0.15, 1.2, -0.1}, {-0.1, -0.4, 0.15, -1.2}, {0.3, 0.4, 1.6, 0.7},
        {-0.5, -0.2, -1.3, -0.6}, {0.1, 0.6, 0.4, 1.5}, {0.6, 0.7, 1.3, 1.4}};
    static const int col[6][2][3] = {
        {{125, 115, 105}, {130, 120, 110}}, {{60, 200, 90}, {65, 205, 95}},
        {{255, 0, 0}, {255, 0, 0}}, {{0, 255, 0}, {0, 255, 0}}, {{0, 0, 255}, {0, 0, 255}},
        {{255, 255, 0}, {255, 255, 0}}};
    size_t c;
    int i;

    for (c = 0; c < 6; c++)
        for (i = 0; i < 2; i++) {
            view_at(cam, img[c][2 * i], img[c][2 * i + 1], pc[c].v[i]);
            memcpy(pc[c].rgb[i], col[c][i], sizeof pc[c].rgb[i]);
        }
    return 6;
}

/* A position of the world stage's candidates: two matrix lines, a rotation
** and a translation, that do not commute, on a cube of side 1.  Composed
** backwards, rotate-then-translate is the order mistake's way 1 and
** translate-then-rotate its way 0 (catalogue79.c: [A | A^-1 t], [A | A t]). */
typedef struct pos79 {
    int rot_first;               /* 1: rotate, then translate */
    char axis;                   /* x, y or z */
    double deg, t[3];
} pos79;

static const pos79 world_pieces[3] = {
    {1, 'y', 30.0, {1.5, 0.0, -6.0}}, {0, 'z', 25.0, {-1.0, 0.5, -5.0}},
    {1, 'x', 40.0, {0.5, -1.0, -5.0}}};

/* The cube's corner k (0..7) in model coordinates. */
static void corner(int k, double v[4])
{
    v[0] = k & 4 ? 0.5 : -0.5;
    v[1] = k & 2 ? 0.5 : -0.5;
    v[2] = k & 1 ? 0.5 : -0.5;
    v[3] = 1.0;
}

/* The world stage's (x, y, z, w) of the cube at position pp: the right
** stage (mk NULL) with the matrix its lines build, or position mistake mk
** from the model's and the right world vertices, as diff tests it (the way
** the lines go, where the mistake has more than one). */
static void sig_world(const pos79 *pp, const pt_mistake79 *mk, sig *s)
{
    pt_matop op[2];
    pt_jmat m;
    double prev[8][4], right[8][4], out[8][4];
    int k, i, r = pp->rot_first ? 0 : 1;

    memset(op, 0, sizeof op);
    op[r].mul = op[1 - r].mul = PT_MATMUL_POST;
    op[r].kind = PT_MATOP_ROTATE;
    op[r].a[0] = pp->deg;
    op[r].a[1 + (pp->axis - 'x')] = 1.0;        /* rotate x|y|z DEG, as a scene gives it */
    op[1 - r].kind = PT_MATOP_TRANSLATE;
    memcpy(op[1 - r].a, pp->t, sizeof pp->t);
    m = pt_r9_position_matrix(op, 2);
    for (k = 0; k < 8; k++) {
        pt_vec4 v, o;
        corner(k, prev[k]);
        v.x = prev[k][0]; v.y = prev[k][1]; v.z = prev[k][2]; v.w = prev[k][3];
        o = pt_r9_model2world(v, &m);
        right[k][0] = o.x; right[k][1] = o.y; right[k][2] = o.z; right[k][3] = o.w;
    }
    if (!mk) memcpy(out, right, sizeof out);
    else if (mk->position(8, (const double (*)[4])prev, (const double (*)[4])right,
                          pp->rot_first, out) != 0 &&
             mk->position(8, (const double (*)[4])prev, (const double (*)[4])right, 0, out) != 0) {
        sig_real(s, -1, 1);                     /* the mistake finds no matrix */
        return;
    }
    sig_real(s, 0, 1);
    for (k = 0; k < 8; k++)
        for (i = 0; i < 4; i++) sig_real(s, out[k][i], 0);
}

/* Position pp as a model of the scene: its matrix lines and the cube. */
static void write_position(const pos79 *pp, size_t k, pt_sep *out)
{
    static const int col[8][3] = {{255, 0, 0}, {255, 128, 0}, {255, 255, 0}, {0, 255, 0},
                                  {0, 255, 255}, {0, 0, 255}, {128, 0, 255}, {255, 255, 255}};
    char b[3][PT_NUMLEN];
    double v[4];
    int i, bit;

    put(out, "model p%zu\n", k);
    for (i = 0; i < 2; i++) {
        if ((i == 0) == (pp->rot_first != 0))
            put(out, "matrix rotate %c %s\n", pp->axis, pt_diff_num(pp->deg, b[0]));
        else
            put(out, "matrix translate %s %s %s\n", pt_diff_num(pp->t[0], b[0]),
                pt_diff_num(pp->t[1], b[1]), pt_diff_num(pp->t[2], b[2]));
    }
    for (i = 0; i < 8; i++) {
        corner(i, v);
        put(out, "v %s %s %s\n", pt_diff_num(v[0], b[0]), pt_diff_num(v[1], b[1]),
            pt_diff_num(v[2], b[2]));
    }
    for (i = 0; i < 8; i++) put(out, "vcolor %d %d %d\n", col[i][0], col[i][1], col[i][2]);
    for (bit = 1; bit < 8; bit <<= 1)           /* the 12 edges: corners one bit apart */
        for (i = 0; i < 8; i++)
            if (!(i & bit)) put(out, "segment %d %d\n", i + 1, (i | bit) + 1);
}

/* The stage of the catalogue's mistake name for cam's renderer, or -1. */
static int stage_of(const pt_c79cam *cam, const char *name)
{
    size_t k;

    for (k = 0; k < PT_NMISTAKES79; k++)
        if (!strcmp(pt_mistakes79[k].name, name) &&
            (!pt_mistakes79[k].renderer || pt_mistakes79[k].renderer == cam->renderer))
            return pt_mistakes79[k].stage;
    return -1;
}

/* Why there is no scene for stage st's mistakes (a sentence's end), or NULL
** when the search makes one. */
static const char *no_search(int st)
{
    switch ((pt_t79_stage)st) {
    case PT_T79_WORLD:
    case PT_T79_CAMERA:
    case PT_T79_NEARCLIP:
    case PT_T79_CLIP:
        return NULL;
    case PT_T79_MODEL:
    case PT_T79_VIEW:
    case PT_T79_IMAGE:
        return "the stage has at most one known mistake, which no other can be taken for";
    }
    return "no two of the pixels' mistakes give the same colour to a pixel strictly "
           "between 0 and 1 (gamma twice makes it lighter, no gamma darker, and the swapped "
           "weights give a pair each other's colours, which gamma would have to map to one "
           "another and back), so they both fit only where ACTUAL's pixels differ from "
           "EXPECTED's by little more than the digits printed; any segment of two colours "
           "between 0 and 255, with anti-aliasing and gamma on, tells them apart";
}

/* The comment of stage st's scene, after its first sentence. */
static void course_comment(const pt_c79cam *cam, int st, pt_sep *out, const char *names)
{
    char b[2][PT_NUMLEN];
    double sx = cam->r + cam->l, sy = cam->t + cam->b;

    if (st == PT_T79_NEARCLIP) {
        comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for "
                "the purpose: on it each gives a log of its own, and none gives the right "
                "one's. The camera's rectangle and near plane are EXPECTED's; it sits at the "
                "origin (no view vector, no matrix), so the segments are given where the near "
                "clip sees them. The framebuffer's size, antialias off and gamma on are the "
                "course's usual ones: the near clip does not depend on them. Render it with "
                "both renderers, debug on, and diff the logs.", names);
        return;
    }
    comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for the "
            "purpose: on it each gives a log of its own, and none gives the right one's. It "
            "keeps EXPECTED's camera, at the origin (no view vector)%s.", names,
            st == PT_T79_WORLD ? "" : "; no matrix either, so the segments are given in view "
            "coordinates");
    if (st == PT_T79_WORLD)
        comment(out, "Its position's two matrix lines, a rotation and a translation of a few "
                "units, do not commute: composed backwards they put the cube elsewhere, and "
                "the transposed product turns it the other way and puts t.v_m + 1, far from "
                "1, into w.");
    else if (st == PT_T79_CAMERA && (sx != 0 || sy != 0))
        comment(out, "The rectangle is asymmetric (r + l = %s, t + b = %s), so the skew moves "
                "each vertex; the ends lie off the lines %s on which a skew mistake and a size "
                "mistake give the same camera coordinates (x_v = k %s(r+l)/2, y_v = k %s(t+b)/2 "
                "for k = %s).", pt_diff_num(sx, b[0]), pt_diff_num(sy, b[1]),
                cam->persp ? "through the eye" : "parallel to the z axis",
                cam->persp ? "z_v " : "", cam->persp ? "z_v " : "",
                cam->persp ? "1, -3, -2, 3" : "-1, 3, 2, -3");
    else if (st == PT_T79_CAMERA)
        comment(out, "The rectangle is symmetric (r + l = t + b = 0), so no skew mistake "
                "changes anything; the ends lie off the camera's axis, where the size mistakes "
                "move them.");
    else
        comment(out, "Each segment runs from inside the rectangle to beyond one edge. Where it "
                "has two colours, they are five bytes apart and the edge cuts it a quarter of "
                "the way in from the outside end, so that the new colour interpolated, in "
                "bytes (truncated) and not at all (the inside end's) are three different "
                "bytes, and a t outside 0 .. 1 still makes a colour java.awt.Color takes; "
                "where it has one, it shows where the cut lands.");
    comment(out, "The framebuffer's size, antialias off and gamma on are the course's usual "
            "ones: the %s does not depend on them. Render it with both renderers, debug on, "
            "and diff the logs.", st == PT_T79_WORLD ? "world stage"
                                  : st == PT_T79_CAMERA ? "camera stage" : "clip");
}

void pt_sep_course(const pt_c79cam *cam, const char *const *names, size_t n, pt_sep *out)
{
    search *q = malloc(sizeof *q);
    const pt_mistake79 *hy[MAXH];
    piece79 pc[MAXC];
    size_t k, j, c, i;
    int st = n ? stage_of(cam, names[0]) : -1;
    char b[3][PT_NUMLEN], nb[1024];
    const char *why;

    memset(out, 0, sizeof *out);
    if (!q) { none(out, "%s%s", "out of memory", "."); return; }
    for (k = 0; k < n; k++)
        if (stage_of(cam, names[k]) != st) {   /* never: diff lists one stage's */
            none(out, "%s is not of the stage %s is.", names[k], names[0]);
            free(q);
            return;
        }
    why = st < 0 ? "no mistake of the catalogue is listed" : no_search(st);
    if (why) {
        none(out, "%s%s", why, ".");
        free(q);
        return;
    }
    memset(q, 0, sizeof *q);
    hy[0] = NULL;
    q->nh = 1;
    for (k = 0; k < PT_NMISTAKES79 && q->nh < MAXH; k++) {
        const pt_mistake79 *m = &pt_mistakes79[k];
        if (m->stage != st || !(st == PT_T79_WORLD ? m->position != NULL
                                : st == PT_T79_CAMERA ? m->vertex != NULL : m->clip != NULL)) continue;
        if (m->renderer && m->renderer != cam->renderer) continue;
        hy[q->nh++] = m;
    }
    for (k = 0; k < n; k++)
        for (j = 1; j < q->nh; j++)
            if (!strcmp(hy[j]->name, names[k])) q->listed[j] = 1;
    q->nc = st == PT_T79_NEARCLIP ? pieces_near(cam, pc)
          : st == PT_T79_CAMERA ? pieces_camera(pc)
          : st == PT_T79_WORLD ? sizeof world_pieces / sizeof world_pieces[0] : pieces_clip(cam, pc);
    for (c = 0; c < q->nc; c++) {
        int usable = 1;
        for (i = 0; i < q->nh; i++) {
            if (st == PT_T79_WORLD) sig_world(&world_pieces[c], hy[i], &q->s[c][i]);
            else sig79(cam, st, &pc[c], hy[i], &q->s[c][i]);
            usable &= q->s[c][i].val[0] == 0;   /* the stage ran (a colour Java takes) */
            usable &= !q->s[c][i].fragile;      /* its bytes read back */
        }
        if (st == PT_T79_CLIP && !usable)       /* a student's renderer would throw, or
                                                ** a trace leave a byte in doubt: unused */
            for (i = 0; i < q->nh; i++) memset(&q->s[c][i], 0, sizeof q->s[c][i]);
    }
    if (cover(q) != 0) {
        none(out, "no scene of the candidates pipetrace diff tries tells %s from %s.",
             q->bad[0] ? hy[q->bad[0]]->name : "the right stage", hy[q->bad[1]]->name);
        free(q);
        return;
    }
    out->ok = 1;
    course_comment(cam, st, out, list_names(nb, sizeof nb, names, n));
    put(out, "renderer %d\nscene separate\nframebuffer 60 50\n", cam->renderer);
    put(out, "camera %s %s %s %s", cam->persp ? "perspective" : "orthographic",
        pt_diff_num(cam->l, b[0]), pt_diff_num(cam->r, b[1]), pt_diff_num(cam->b, b[2]));
    put(out, " %s\n", pt_diff_num(cam->t, b[0]));
    if (cam->persp && cam->n != -0.1) put(out, "near %s\n", pt_diff_num(-cam->n, b[0]));
    put(out, "nearclip on\nantialias off\ngamma on\n");
    if (st == PT_T79_WORLD) {
        for (c = 0; c < q->nc; c++)
            if (q->keep[c]) write_position(&world_pieces[c], c + 1, out);
        free(q);
        return;
    }
    put(out, "model separate\n");
    for (c = 0; c < q->nc; c++)
        for (i = 0; q->keep[c] && i < 2; i++)
            put(out, "v %s %s %s\n", pt_diff_num(pc[c].v[i][0], b[0]), pt_diff_num(pc[c].v[i][1], b[1]),
                pt_diff_num(pc[c].v[i][2], b[2]));
    for (c = 0; c < q->nc; c++)
        for (i = 0; q->keep[c] && i < 2; i++)
            put(out, "vcolor %d %d %d\n", pc[c].rgb[i][0], pc[c].rgb[i][1], pc[c].rgb[i][2]);
    for (c = 0, k = 0; c < q->nc; c++)
        if (q->keep[c]) { put(out, "segment %zu %zu\n", k + 1, k + 2); k += 2; }
    free(q);
}

/* ===== output ===== */

int pt_sep_emit(const pt_sep *s, const char *path)
{
    pt_outfile of;
    char err[PT_ERRLEN];
    pbuf pb;

    if (!s->ok) {
        memset(&pb, 0, sizeof pb);
        pt_diff_add(&pb, "No separating scene: %s", s->text);
        pt_diff_para("", pb.b);
        return 0;
    }
    printf("Separating scene (the lines between the markers, as a scene file%s):\n",
           path ? "; also written to --separating-scene's file" : "; --separating-scene FILE writes it");
    printf("#---- begin separating scene ----\n%.*s#---- end separating scene ----\n",
           (int)s->n, s->text);
    if (!path) return 0;
    if (pt_outfile_open(&of, path, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    return pt_outfile_finish(&of, fwrite(s->text, 1, s->n, of.f) != s->n, "pipetrace diff");
}
