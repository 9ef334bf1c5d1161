/*
** src/tools/diff/dseparate.c -- pipetrace diff: a scene that tells apart the mistakes diff could not
** See LICENSE for copyright and license.
**
** Each candidate piece of a scene is run through the right stages and through
** every known mistake of the catalogue (the mistake's own function, as diff
** tests a hypothesis); what a trace of the piece would hold is its signature.
** Here renderer 4's: each vertex's values at every stage and, for a segment,
** the rasterizer's pixels and clip records replayed as the raster check
** replays them; and the scene printed or written.  Renderers 7 and 9's
** candidates are dseparate79.c's, the search that keeps the fewest pieces
** dsearch.c's.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/outfile.h"
#include "tools/diff/diff.h"
#include "tools/diff/dseparate.h"

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
static void sig_val(pt_sep_sig *s, int st, const pt_cat_val *v)
{
    int k, n = pt_stage_nvalues((pt_stage)st);

    if (pt_diff_is_real(st)) {
        for (k = 0; k < n; k++) pt_sep_real(s, v->d[k], 0);
        return;
    }
    pt_sep_real(s, (double)(v->flags & (PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y)), 1);
    for (k = 0; k < n; k++) pt_sep_real(s, pt_cat_has(v, k) ? (double)v->n[k] : 0.0, 1);
}

/* Vertex m of a model translated by t, through the classic stages, mk's stage
** with the mistake; its values into s (unless NULL), its pixel-plane values
** into *pp. */
static void run4(const par4 *pr, const double t[3], const pt_mistake *mk, const double m[3],
                 pt_sep_sig *s, pt_cat_val *pp)
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
static void sig4(const par4 *pr, const piece4 *pc, const hyp4 *hy, pt_sep_sig *s)
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
        for (k = 0; k < PT_NRASTER_MISTAKES && nh < PT_SEP_MAXH; k++) {
            hy[nh].name = pt_raster_mistakes[k].name;
            hy[nh].mk = NULL;
            hy[nh++].rk = &pt_raster_mistakes[k];
        }
    } else {
        for (k = 0; k < PT_NMISTAKES && nh < PT_SEP_MAXH; k++) {
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
    memset(listed, 0, PT_SEP_MAXH);
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
static int search4(const par4 *pr, const char *const *names, size_t n, pt_sep_search *q, piece4 *pc,
                   hyp4 *hy, const char **missing)
{
    size_t c, i;

    q->nh = hyps4(pr, names, n, hy, q->listed, missing);
    q->nc = pieces4(pr, pc);
    for (c = 0; c < q->nc; c++)
        for (i = 0; i < q->nh; i++) sig4(pr, &pc[c], &hy[i], &q->s[c][i]);
    return pt_sep_cover(q);
}

/* The lines of the kept pieces: vertices grouped by translation into models
** joined by a polyline (a vertex no segment uses is not traced), each
** segment a model of its own. */
static void write4(const par4 *pr, const pt_sep_search *q, const piece4 *pc, pt_sep *o)
{
    size_t c, d, nm = 0;
    unsigned char done[PT_SEP_MAXC];
    char b[3][PT_NUMLEN];

    pt_sep_put(o, "framebuffer %d %d\nviewport %d %d %d %d\ncamera %s\n", pr->p.W, pr->p.H,
        pr->p.x_ul, pr->p.y_ul, pr->p.w, pr->p.h, pr->p.perspective ? "perspective" : "orthographic");
    memset(done, 0, sizeof done);
    for (c = 0; c < q->nc; c++) {
        size_t nv = 0, k;
        if (!q->keep[c] || done[c]) continue;
        pt_sep_put(o, "\nmodel p%zu\ntranslate %s %s %s\n", ++nm, pt_diff_num(pc[c].t[0], b[0]),
            pt_diff_num(pc[c].t[1], b[1]), pt_diff_num(pc[c].t[2], b[2]));
        for (d = c; d < q->nc; d++) {
            if (!q->keep[d] || done[d] || memcmp(pc[d].t, pc[c].t, sizeof pc[c].t) ||
                (pc[d].nv == 2) != (pc[c].nv == 2) || (pc[c].nv == 2 && d != c)) continue;
            done[d] = 1;
            pt_sep_comment(o, "%s", pc[d].what);
            for (k = 0; k < (size_t)pc[d].nv; k++) {
                pt_cat_val pp;
                char x[PT_NUMLEN], y[PT_NUMLEN];
                memset(&pp, 0, sizeof pp);   /* run4 sets it: the pixel stage always runs */
                run4(pr, pc[d].t, NULL, pc[d].v[k], NULL, &pp);
                pt_sep_put(o, "v %s %s %s    # x_pp = %s, y_pp = %s\n", pt_diff_num(pc[d].v[k][0], b[0]),
                    pt_diff_num(pc[d].v[k][1], b[1]), pt_diff_num(pc[d].v[k][2], b[2]),
                    pt_diff_num(pp.d[0], x), pt_diff_num(pp.d[1], y));
                nv++;
            }
        }
        if (nv == 1) pt_sep_put(o, "l 1 1\n");
        else {
            pt_sep_put(o, "l");
            for (k = 1; k <= nv; k++) pt_sep_put(o, " %zu", k);
            pt_sep_put(o, "\n");
        }
    }
}

void pt_sep_classic(const pt_sep_r4 *sp, const char *const *names, size_t n, pt_sep *out)
{
    pt_sep_search *q = malloc(sizeof *q);
    piece4 pc[PT_SEP_MAXC];
    hyp4 hy[PT_SEP_MAXH];
    par4 pr[2];
    const char *missing = NULL;
    char nb[1024];
    int k, got = -1, ok = -1;

    memset(out, 0, sizeof *out);
    if (!q) { pt_sep_none(out, "%s%s", "out of memory", "."); return; }
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
            pt_sep_none(out, "no scene of the candidates pipetrace diff tries tells %s from %s.",
                 hy[q->bad[0]].name, hy[q->bad[1]].name);
            free(q);
            return;
        }
        got = 1;
        out->ok = 1;
        pt_sep_comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for "
                "the purpose: on it each gives a trace of its own, and none gives the right "
                "one's.", pt_sep_names(nb, sizeof nb, names, n));
        if (tried)
            pt_sep_comment(out, "EXPECTED's viewport (%d x %d at (%d, %d) in %d x %d) cannot tell %s "
                    "from %s: these sizes are the self-check scene's (odd, off the corner).",
                    sp->w, sp->h, sp->x_ul, sp->y_ul, sp->W, sp->H, bad[0], bad[1]);
        else
            pt_sep_comment(out, "EXPECTED has no viewport or framebuffer to keep: these sizes are the "
                    "self-check scene's (odd, off the corner).");
    } else {
        out->ok = 1;
        pt_sep_comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for "
                "the purpose: on it each gives a trace of its own, and none gives the right "
                "one's. Viewport, framebuffer and camera: EXPECTED's.",
                pt_sep_names(nb, sizeof nb, names, n));
    }
    if (missing)
        pt_sep_comment(out, "(%s is no mistake of the catalogue: it is not told apart here.)", missing);
    if (sp->pixels_only)
        pt_sep_comment(out, "Render it with both renderers as the course's log with its pixels "
                "(pipetrace SCENE --format kraft-pixels), and diff the two logs.");
    else
        pt_sep_put(out, "# Render it with both builds, as JSON Lines, and diff the two traces:\n"
            "#   build/pipetrace SCENE --format jsonl --trace expected.jsonl\n"
            "#   build-student/pipetrace SCENE --format jsonl --trace mine.jsonl\n"
            "#   build/pipetrace diff expected.jsonl mine.jsonl\n");
    write4(&pr[got], q, pc, out);
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
