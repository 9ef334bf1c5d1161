/*
** src/tools/diff/dexplain.c -- pipetrace diff: one hypothesis on one vertex, and a vertex's difference explained
** See LICENSE for copyright and license.
**
** A hypothesis (dfit.c) says how a stage went wrong.  On one vertex it is
** tested by recomputing that stage the wrong way from the reference's value
** of the stage before; the result must be the other side's value within the
** tolerance (from a text trace, for some input within its printed digits; see
** reproduces()).  Float arithmetic is tested on the values themselves: the
** other side's are floats, within float error of the reference's.  Only the
** classic camera's mistakes are known.
*/
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/diff/diff.h"

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
    } else if (!pt_cat_has(o, k)) {
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
static int in_ranges(const dctx *c, const vrange r[4], int st, int aside, const pt_tvrec *arec)
{
    int k;

    for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
        if (pt_diff_is_real(st)) {
            double a = arec->u.d[k], allow;
            if (isnan(a)) { if (!r[k].nan) return 0; continue; }
            if (isinf(a)) { if (!(a > 0 ? r[k].pinf : r[k].ninf)) return 0; continue; }
            if (!r[k].any_finite) return 0;
            allow = fmax(c->o->tol, c->o->rel * fmax(fabs(a), fmax(fabs(r[k].lo), fabs(r[k].hi))));
            allow += pt_diff_slack(c, aside, a);
            if (a < r[k].lo - allow || a > r[k].hi + allow) return 0;
        } else if (!pt_flags_have(arec->flags, k)) {
            if (!r[k].any_null) return 0;
        } else if (!r[k].any_value || arec->u.n[k] < r[k].ilo || arec->u.n[k] > r[k].ihi) {
            return 0;
        }
    }
    return 1;
}

/* Hypothesis h's stage applied to in, as pt_cat_right. */
static void happly(const dhyp *h, const pt_stage_params *par, const pt_cat_val *in, pt_cat_val *out)
{
    int k;

    memset(out, 0, sizeof *out);
    if (h->kind == PT_DIFF_H_MISTAKE) { h->mk->apply(par, in, out); return; }
    pt_cat_right(h->stage, par, in, out);
    if (pt_diff_is_real(h->stage)) {
        for (k = 0; k < 3; k++) out->d[k] += h->off[k];
    } else {
        for (k = 0; k < 2; k++) if (pt_cat_has(out, k)) out->n[k] += h->ioff[k];
    }
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
static int reproduces(const dctx *c, const dhyp *mk, int ref, const hctx *h, const pt_cat_val *in,
                      const double in_slack[3], int in_real, int st,
                      const pt_tvrec *erec, const pt_tvrec *arec, pt_cat_val *at_in)
{
    vrange r[4];
    pt_cat_val x, out, right;
    int k, p;

    memset(r, 0, sizeof r);
    memset(at_in, 0, sizeof *at_in);
    happly(mk, &h->par, in, at_in);
    if (!in_real) {
        for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) range_add(&r[k], pt_diff_is_real(st), at_in, k);
    } else if (pt_diff_is_real(st)) {
        int vary[3], nvary = 0, npts = 1;
        for (k = 0; k < 3; k++)
            if (in_slack[k] > 0) { vary[nvary++] = k; npts *= 3; }
        for (p = 0; p < npts; p++) {        /* offsets -1, 0, +1 of each input */
            int q = p, j;
            x = *in;
            for (j = 0; j < nvary; j++, q /= 3)
                x.d[vary[j]] += (q % 3 - 1) * in_slack[vary[j]];
            happly(mk, &h->par, &x, &out);
            for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) range_add(&r[k], 1, &out, k);
        }
    } else {
        for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
            double v[16];
            int n = samples(in->d[k], in_slack[k], v);
            for (p = 0; p < n; p++) {
                x = *in;
                x.d[k] = v[p];
                memset(&right, 0, sizeof right);
                pt_cat_right(st, &h->par, &x, &right);
                if (pt_cat_has(&right, k) != pt_flags_have(erec->flags, k) ||
                    (pt_cat_has(&right, k) && right.n[k] != erec->u.n[k])) continue;
                happly(mk, &h->par, &x, &out);
                range_add(&r[k], 0, &out, k);
            }
        }
    }
    return in_ranges(c, r, st, !ref, arec);
}

/* Fill *h from side ref's header (translations: EXPECTED's) for a vertex of model `model`; 0 when there is
** no header. */
static int hctx_of(const dctx *c, int ref, uint32_t model, hctx *h)
{
    const pt_thdr *hd = &c->t[ref].hdr;

    if (!hd->have || hd->pipe != PT_PIPE_CLASSIC || hd->vp_w < 1 || hd->vp_h < 1) return 0;
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

/* Side ref's value of the stage before st for vertex e, into *in with the slack
** of each real value; *from gets the stage it came from.  A stage left out as
** the identity is replaced by the one before it (camera = model when the
** translation is 0 0 0; framebuffer = viewport when the viewport is at 0,0).
** Returns 0 when there is no such record. */
static int prev_value(const dctx *c, int ref, const vent *e, int st, const hctx *h,
                      pt_cat_val *in, double in_slack[3], int *from)
{
    int p = st - 1, k;
    uint32_t i;
    const pt_tvrec *r;

    if (p < 0) return 0;
    i = e->rec[ref][p];
    if (i == PT_DIFF_NONE && p == PT_STAGE_CAMERA && h->has_t && h->par.translate.x == 0 &&
        h->par.translate.y == 0 && h->par.translate.z == 0)
        i = e->rec[ref][p = PT_STAGE_MODEL];
    if (i == PT_DIFF_NONE && p == PT_STAGE_FRAMEBUFFER && h->par.x_ul == 0 && h->par.y_ul == 0)
        i = e->rec[ref][p = PT_STAGE_VIEWPORT];
    if (i == PT_DIFF_NONE) return 0;
    r = &c->t[ref].vx[i];
    memset(in, 0, sizeof *in);
    in_slack[0] = in_slack[1] = in_slack[2] = 0;
    if (pt_diff_is_real(p)) {
        for (k = 0; k < pt_stage_nvalues((pt_stage)p); k++) {
            in->d[k] = r->u.d[k];
            in_slack[k] = pt_diff_slack(c, ref, r->u.d[k]);
        }
    } else {
        in->flags = r->flags & (PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y);
        for (k = 0; k < pt_stage_nvalues((pt_stage)p); k++) in->n[k] = r->u.n[k];
    }
    *from = p;
    return 1;
}

/* Append the values of stage st in *v to sb: "x_pp = 1.5, y_pp = 2". */
void pt_diff_val_str(pbuf *sb, int st, const pt_cat_val *v)
{
    char b[PT_NUMLEN];
    int k;

    for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
        pt_diff_add(sb, "%s%s = ", k ? ", " : "", pt_diff_coord_name(st, k));
        if (pt_diff_is_real(st)) pt_diff_add(sb, "%s", pt_diff_num(v->d[k], b));
        else if (!pt_cat_has(v, k)) pt_diff_add(sb, "none");
        else pt_diff_add(sb, "%" PRId64, v->n[k]);
    }
}

/* 1 when x is a float: (double)(float)x == x. */
static int is_float(double x)
{
    return !isfinite(x) || (fabs(x) <= 0x1.fffffep127 && (double)(float)x == x);
}

/* The float hypothesis on one vertex: every value of the other side is a
** float within float error of the reference's, the error bounded by 16
** float roundings of the numbers the formula adds (its inputs, the
** translation, w or h). */
static int float_fits(const dctx *c, const dhyp *hy, const hctx *h, int ref, const pt_cat_val *in,
                      const pt_tvrec *erec, const pt_tvrec *arec)
{
    int k, st = hy->stage;
    const double t[3] = {h->par.translate.x, h->par.translate.y, h->par.translate.z};

    (void)c;
    for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
        double e = erec->u.d[k], a = arec->u.d[k], scale;
        if (!is_float(a)) return 0;
        if (!isfinite(e) || !isfinite(a)) { if (!(e == a || (isnan(e) && isnan(a)))) return 0; continue; }
        scale = fabs(e) + fabs(in->d[k]) + 1;
        if (st == PT_STAGE_CAMERA) scale += fabs(t[k]);
        if (st == PT_STAGE_IMAGE) scale += fabs(in->d[k] / in->d[2]);
        if (st == PT_STAGE_PIXEL) scale += k ? h->par.h : h->par.w;
        if (!(fabs(a - e) <= 16 * 0x1p-24 * scale)) return 0;
    }
    (void)ref;
    return 1;
}

int pt_diff_hyp_vertex(const dctx *c, const dhyp *hy, const vent *e, int ref,
                       pt_cat_val *in, int *from, pt_cat_val *got)
{
    hctx h;
    dhyp right;                  /* the right formula: an offset of 0 */
    double in_slack[3];
    int st = hy->stage;
    uint32_t i = e->rec[ref][st], j = e->rec[!ref][st];

    memset(&h, 0, sizeof h);
    memset(got, 0, sizeof *got);
    if (i == PT_DIFF_NONE || j == PT_DIFF_NONE || !hctx_of(c, ref, e->model, &h)) return -1;
    if (st == PT_STAGE_CAMERA && !h.has_t) return -1;
    if (!prev_value(c, ref, e, st, &h, in, in_slack, from)) return -1;
    /* the reference must be right here: its value follows from its previous
    ** stage by the right formula (reproduces() with the sides as given
    ** compares with side !ref, so ref's own record is passed as side !!ref) */
    memset(&right, 0, sizeof right);
    right.stage = st;
    right.kind = PT_DIFF_H_OFFSET;
    if (!reproduces(c, &right, !ref, &h, in, in_slack, pt_diff_is_real(*from), st,
                    &c->t[ref].vx[i], &c->t[ref].vx[i], got)) return -1;
    if (hy->kind == PT_DIFF_H_FLOAT)
        return float_fits(c, hy, &h, ref, in, &c->t[ref].vx[i], &c->t[!ref].vx[j]);
    return reproduces(c, hy, ref, &h, in, in_slack, pt_diff_is_real(*from), st,
                      &c->t[ref].vx[i], &c->t[!ref].vx[j], got);
}

/* 1 when EXPECTED has the record stage st is recomputed from, for vertex e. */
static int prev_known(const dctx *c, const vent *e, int st)
{
    hctx h;
    pt_cat_val in;
    double sl[3];
    int from;

    memset(&h, 0, sizeof h);
    return hctx_of(c, 0, e->model, &h) && prev_value(c, 0, e, st, &h, &in, sl, &from);
}

/* Print what the hypotheses say of vertex e, whose first difference is at
** stage st: the check of the one that explains the trace, or which partial
** ones reproduce it, or that none does. */
void pt_diff_explain(const dctx *c, const vent *e, int st)
{
    pbuf sb;
    pt_cat_val in, got;
    int from = st, n = 0;
    size_t k;

    if (st == PT_STAGE_MODEL) {
        printf("    (the model stage holds the scene's own numbers: are these "
               "traces of one scene?)\n");
        return;
    }
    if (!c->nhy) {
        printf("    (no known mistake checked: %s)\n", !c->t[0].hdr.have ? "EXPECTED has no header"
               : "those known are the classic camera's");
        return;
    }
    if (c->verdict >= 0 && c->nfull == 1) {
        const dhyp *hy = &c->hy[c->verdict];
        if (pt_diff_hyp_vertex(c, hy, e, 0, &in, &from, &got) != 1 || hy->stage != st) return;
        printf("    likely mistake: %s\n", hy->name);
        memset(&sb, 0, sizeof sb);
        if (hy->kind == PT_DIFF_H_FLOAT) {
            pt_diff_add(&sb, "check: ACTUAL's %s values are floats, within float error of "
                        "EXPECTED's.", pt_stage_infos[st].name);
        } else {
            pt_diff_add(&sb, "check: the %s stage recomputed with it from EXPECTED's %s record (",
                        pt_stage_infos[st].name, pt_stage_infos[from].name);
            pt_diff_val_str(&sb, from, &in);
            pt_diff_add(&sb, ") gives ");
            pt_diff_val_str(&sb, st, &got);
            pt_diff_add(&sb, ", as ACTUAL has%s; it does so for every vertex (see the end).",
                        c->t[0].prec >= 0 || c->t[1].prec >= 0 ? " (within the printed digits)" : "");
        }
        pt_diff_para("      ", sb.b);
        return;
    }
    memset(&sb, 0, sizeof sb);
    for (k = 0; k < c->nhy; k++) {
        const dhyp *hy = &c->hy[k];
        if (hy->stage != st || pt_diff_hyp_vertex(c, hy, e, 0, &in, &from, &got) != 1) continue;
        pt_diff_add(&sb, "%s%s", n++ ? "; " : "", hy->name);
    }
    if (n) {
        printf("    reproduced here by (%s, see the end):\n", c->verdict >= 0 ?
               "they fit every vertex: this scene cannot tell them apart" : "each fails elsewhere");
        pt_diff_para("      ", sb.b);
    } else if (prev_known(c, e, st)) {
        printf("    no known mistake reproduces this from EXPECTED's %s record\n",
               pt_stage_infos[st - 1].name);
    } else {
        printf("    (no known mistake checked: EXPECTED has no %s record to "
               "recompute from)\n", pt_stage_infos[st - 1].name);
    }
}
