/*
** src/tools/diff/dfit.c -- pipetrace diff: hypotheses tested on every vertex, and the verdict
** See LICENSE for copyright and license.
**
** A mistake is named only when it explains all the evidence.  Each
** hypothesis says how one stage went wrong: a known mistake of the catalogue
** (src/tools/catalogue.c), a constant offset read off the first vertex that
** differs at a stage, or float arithmetic.  It is tested on every vertex both
** traces hold (dexplain.c): where the traces differ it must reproduce ACTUAL
** (and the vertex must differ first at its stage), where they agree it must
** leave the vertex as it is.  Its fit is the two counts.  One that fits all is
** the verdict; otherwise the partial ones are listed as what they are, and the
** hypotheses are tried once more with EXPECTED and ACTUAL swapped (diff's
** arguments given in the wrong order).
*/
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/diff/diff.h"
#include "tools/diff/dseparate.h"

/* The vertices' first differing stages (pt_diff_first_stage), once. */
typedef struct fitset {
    signed char *first;          /* per table entry; owned */
    size_t differ, agree, onesided;
} fitset;

/* Test hy on every vertex with side ref as the reference; fill its counts. */
static void test_hyp(const dctx *c, const fitset *fs, dhyp *hy, int ref)
{
    size_t k;
    pt_cat_val in, got;
    int from;

    hy->repro = hy->kept = 0;
    for (k = 0; k < c->vt.n; k++) {
        int f = fs->first[k], r;
        if (f == -2) continue;
        if (f >= 0 && f != hy->stage) continue;     /* differs elsewhere first */
        r = pt_diff_hyp_vertex(c, hy, &c->vt.e[k], ref, &in, &from, &got);
        if (f == -1) hy->kept += r != 0;
        else hy->repro += r == 1;
    }
    /* an offset read off one vertex is shown by the others only: with no
    ** other differing vertex it is no evidence, and is not even listed */
    if (hy->kind == PT_DIFF_H_OFFSET && hy->repro < 2) hy->repro = 0;
    hy->full = fs->differ > 0 && hy->repro == fs->differ && hy->kept == fs->agree &&
               fs->onesided == 0;
}

/* 1 when a stage of either side did not report for some model. */
static int any_silent(const dctx *c)
{
    size_t k;
    int s;

    for (s = 0; s < 2; s++)
        for (k = 0; k < (c->nm.n ? c->nm.n : 1); k++)
            if (c->silent[s] && c->silent[s][k]) return 1;
    return 0;
}

/* Name a constant offset hypothesis from its numbers. */
static void name_offset(dhyp *hy, const pt_thdr *hd)
{
    int st = hy->stage, n = pt_stage_nvalues((pt_stage)st), k, nz = 0, which = 0;
    char b[PT_NUMLEN];
    pbuf v;

    memset(&v, 0, sizeof v);
    for (k = 0; k < n; k++) {
        int z = pt_diff_is_real(st) ? hy->off[k] == 0 : hy->ioff[k] == 0;
        if (!z) { nz++; which = k; }
        if (pt_diff_is_real(st)) pt_diff_add(&v, "%s%s", k ? ", " : "", pt_diff_num(hy->off[k], b));
        else pt_diff_add(&v, "%s%+" PRId64, k ? ", " : "", hy->ioff[k]);
    }
    if (!pt_diff_is_real(st) && nz == 1 && (hy->ioff[which] == 1 || hy->ioff[which] == -1))
        snprintf(hy->name, sizeof hy->name, "an extra %+" PRId64 " in %s", hy->ioff[which],
                 pt_diff_coord_name(st, which));
    else if (st == PT_STAGE_INDEX && hd->fb_w > 0 && hy->ioff[0] % hd->fb_w == 0)
        snprintf(hy->name, sizeof hy->name, "idx off by %+" PRId64 " rows (%+" PRId64 " = %+" PRId64
                 " W)", hy->ioff[0] / hd->fb_w, hy->ioff[0], hy->ioff[0] / hd->fb_w);
    else
        snprintf(hy->name, sizeof hy->name, "a constant offset (%.60s)", v.b);
    snprintf(hy->how, sizeof hy->how, "every %s value is the right one plus (%.100s): a constant "
             "added to or left out of the formula (y_vp = h - 1 - round(y_pp) adds -1 to "
             "every y_vp)", pt_stage_infos[st].name, v.b);
}

/* An offset hypothesis at stage st from the first vertex that differs first
** there: the values of side !ref minus those of side ref, the reference.
** Returns 0 when there is none. */
static int make_offset(const dctx *c, const fitset *fs, int st, int ref, dhyp *hy)
{
    size_t k;
    int j;

    memset(hy, 0, sizeof *hy);
    hy->stage = st;
    hy->kind = PT_DIFF_H_OFFSET;
    for (k = 0; k < c->vt.n; k++) {
        const vent *e = &c->vt.e[k];
        const pt_tvrec *a, *b;
        if (fs->first[k] != st) continue;
        if (e->rec[0][st] == PT_DIFF_NONE || e->rec[1][st] == PT_DIFF_NONE) return 0;
        a = &c->t[ref].vx[e->rec[ref][st]];
        b = &c->t[!ref].vx[e->rec[!ref][st]];
        for (j = 0; j < pt_stage_nvalues((pt_stage)st); j++) {
            if (pt_diff_is_real(st)) {
                hy->off[j] = b->u.d[j] - a->u.d[j];
                if (!isfinite(hy->off[j])) return 0;
            } else {
                if ((a->flags | b->flags) & PT_REC_NULL) return 0;
                if (!pt_diff_small(a->u.n[j]) || !pt_diff_small(b->u.n[j])) return 0;
                hy->ioff[j] = b->u.n[j] - a->u.n[j];
            }
        }
        name_offset(hy, &c->t[0].hdr);
        return 1;
    }
    return 0;
}

/* The float hypothesis at real stage st. */
static void make_float(int st, dhyp *hy)
{
    memset(hy, 0, sizeof *hy);
    hy->stage = st;
    hy->kind = PT_DIFF_H_FLOAT;
    snprintf(hy->name, sizeof hy->name, "float arithmetic in the %s stage", pt_stage_infos[st].name);
    snprintf(hy->how, sizeof hy->how, "the stage computes in float (24 bits, about 7 digits) "
             "instead of double: every value ACTUAL has is a float, within a few float "
             "roundings of EXPECTED's");
}

/* The catalogue's mistakes that can show in a trace with header hd. */
static size_t add_catalogue(dctx *c, const pt_thdr *hd)
{
    size_t k, n = 0;

    for (k = 0; k < PT_NMISTAKES && c->nhy < PT_DIFF_MAXHYP; k++) {
        const pt_mistake *mk = &pt_mistakes[k];
        dhyp *hy = &c->hy[c->nhy];
        if (mk->stage == PT_STAGE_IMAGE && !hd->perspective) continue;
        if (mk->odd_only && hd->vp_w % 2 == 0 && hd->vp_h % 2 == 0) continue;
        memset(hy, 0, sizeof *hy);
        hy->stage = mk->stage;
        hy->kind = PT_DIFF_H_MISTAKE;
        hy->mk = mk;
        snprintf(hy->name, sizeof hy->name, "%s", mk->name);
        snprintf(hy->how, sizeof hy->how, "%s", mk->how);
        c->nhy++;
        n++;
    }
    return n;
}

/* 1 when a hypothesis at stage st that is not an offset explains everything. */
static int stage_explained(const dctx *c, int st)
{
    size_t k;

    for (k = 0; k < c->nhy; k++)
        if (c->hy[k].stage == st && c->hy[k].full) return 1;
    return 0;
}

int pt_diff_fit(dctx *c)
{
    const pt_thdr *hd = &c->t[0].hdr;
    fitset fs;
    size_t k, nbase;
    int st, silent = any_silent(c);

    c->nhy = 0;
    c->verdict = c->swapped = -1;
    c->nfull = 0;
    memset(&fs, 0, sizeof fs);
    fs.first = malloc(c->vt.n ? c->vt.n : 1);
    if (!fs.first) return -1;
    for (k = 0; k < c->vt.n; k++) {
        int f = pt_diff_first_stage(c, &c->vt.e[k]);
        fs.first[k] = (signed char)f;
        if (f == -2) fs.onesided++;
        else if (f == -1) fs.agree++;
        else fs.differ++;
    }
    c->fit_differ = fs.differ;
    c->fit_agree = fs.agree;
    if (silent) fs.onesided++;              /* nothing explains a stage that did not report */
    if (!hd->have || hd->pipe != PT_PIPE_CLASSIC || hd->vp_w < 1 || hd->vp_h < 1 || !fs.differ) {
        free(fs.first);
        return 0;
    }
    add_catalogue(c, hd);
    if (c->t[1].prec < 0)
        for (st = PT_STAGE_CAMERA; st <= PT_STAGE_PIXEL; st++)
            if (st != PT_STAGE_IMAGE || hd->perspective) make_float(st, &c->hy[c->nhy++]);
    nbase = c->nhy;
    for (k = 0; k < nbase; k++) test_hyp(c, &fs, &c->hy[k], 0);
    for (st = PT_STAGE_CAMERA; st <= PT_STAGE_INDEX; st++)
        if (!stage_explained(c, st) && c->nhy < PT_DIFF_MAXHYP && make_offset(c, &fs, st, 0, &c->hy[c->nhy]))
            test_hyp(c, &fs, &c->hy[c->nhy++], 0);
    for (k = 0; k < c->nhy; k++) {
        if (!c->hy[k].full) continue;
        if (c->verdict < 0) c->verdict = (int)k;
        if (k == (size_t)c->verdict || strcmp(c->hy[k].name, c->hy[c->verdict].name)) c->nfull++;
    }
    /* diff's arguments in the wrong order: the hypotheses with ACTUAL as the
    ** reference (which must then be right, see pt_diff_hyp_vertex: so a
    ** mistake does not fit both ways round) */
    for (k = 0; c->verdict < 0 && c->swapped < 0 && k < nbase + PT_CLASSIC_NORDER; k++) {
        dhyp h = k < nbase ? c->hy[k] : c->hy[0];
        pt_stage off = k < nbase ? PT_STAGE_MODEL : pt_classic_order[k - nbase];
        if (k >= nbase && (off == PT_STAGE_MODEL ||
                           !make_offset(c, &fs, (int)off, 1, &h))) continue;
        if (h.kind == PT_DIFF_H_FLOAT && c->t[0].prec >= 0) continue;
        test_hyp(c, &fs, &h, 1);
        if (h.full) { c->swap_hy = h; c->swapped = (int)k; }
    }
    free(fs.first);
    return 0;
}

/* "reproduces all 4 differing vertices and leaves the 11 agreeing ones as
** they are", or for a partial fit how far it goes. */
static void fit_str(pbuf *s, const dhyp *hy, size_t nd, size_t na)
{
    if (hy->full) {
        if (nd == 1) pt_diff_add(s, "reproduces the 1 differing vertex");
        else pt_diff_add(s, "reproduces all %zu differing vertices", nd);
        if (na == 1) pt_diff_add(s, " and leaves the 1 agreeing one as it is");
        else if (na) pt_diff_add(s, " and leaves the %zu agreeing ones as they are", na);
        return;
    }
    pt_diff_add(s, "reproduces %zu of the %zu differing vertices", hy->repro, nd);
    if (hy->kept < na) pt_diff_add(s, " and would change %zu of the %zu agreeing ones", na - hy->kept, na);
    else if (na) pt_diff_add(s, " and leaves the %zu agreeing ones as they are", na);
}

void pt_diff_report_fit(const dctx *c)
{
    pbuf s;
    size_t k;
    int any = 0;

    for (k = 0; k < c->nhy; k++) {
        const dhyp *hy = &c->hy[k];
        if (!hy->repro) continue;
        if (!any++)
            printf("Known mistakes tested on every vertex (%zu differ, %zu agree):\n",
                   c->fit_differ, c->fit_agree);
        memset(&s, 0, sizeof s);
        pt_diff_add(&s, "%s: %s (%s stage), which ", hy->full ? "explains all" : "partial",
                    hy->name, pt_stage_infos[hy->stage].name);
        fit_str(&s, hy, c->fit_differ, c->fit_agree);
        pt_diff_add(&s, hy->full ? "." : ": it does NOT explain the trace.");
        pt_diff_para("  ", s.b);
        if (hy->full) pt_diff_para("      ", hy->how);
    }
    if (c->swapped >= 0) {
        memset(&s, 0, sizeof s);
        pt_diff_add(&s, "with EXPECTED and ACTUAL swapped: %s (%s stage) ", c->swap_hy.name,
                    pt_stage_infos[c->swap_hy.stage].name);
        fit_str(&s, &c->swap_hy, c->fit_differ, c->fit_agree);
        pt_diff_add(&s, ".");
        if (!any++) printf("Known mistakes tested on every vertex (%zu differ, %zu agree):\n",
                           c->fit_differ, c->fit_agree);
        pt_diff_para("  ", s.b);
    }
    if (any) printf("\n");
    if (c->verdict >= 0 && c->nfull > 1) {
        const char *names[PT_DIFF_MAXHYP];
        size_t n = 0, j;
        for (k = 0; k < c->nhy; k++) {
            int seen = 0;
            if (!c->hy[k].full) continue;
            for (j = 0; j < n; j++) seen |= !strcmp(names[j], c->hy[k].name);
            if (!seen) names[n++] = c->hy[k].name;
        }
        pt_diff_separate(c, names, n, 0);
        printf("\n");
    }
}

void pt_diff_separate(const dctx *c, const char *const *names, size_t n, int pixels_only)
{
    const pt_thdr *hd = &c->t[0].hdr;
    pt_sep_r4 sp;
    pt_sep *sep = malloc(sizeof *sep);

    if (!sep) return;
    memset(&sp, 0, sizeof sp);
    sp.have = hd->have;
    sp.w = hd->vp_w; sp.h = hd->vp_h; sp.x_ul = hd->vp_x; sp.y_ul = hd->vp_y;
    sp.W = hd->fb_w; sp.H = hd->fb_h;
    sp.perspective = hd->perspective;
    sp.pixels_only = pixels_only;
    pt_sep_classic(&sp, names, n, sep);
    if (pt_sep_emit(sep, sep->ok ? c->o->sep_out : NULL) != 0) c->o->out->sep = -1;
    else if (sep->ok) c->o->out->sep = 1;
    free(sep);
}

void pt_diff_verdict(const dctx *c, pbuf *s)
{
    size_t k, shown = 0;

    if (c->verdict >= 0 && c->nfull == 1) {
        const dhyp *hy = &c->hy[c->verdict];
        pt_diff_add(s, " Likely mistake there: %s, which ", hy->name);
        fit_str(s, hy, c->fit_differ, c->fit_agree);
        pt_diff_add(s, ".");
    } else if (c->verdict >= 0) {
        pt_diff_add(s, " These known mistakes each explain every vertex, and this scene "
                    "cannot tell them apart:");
        for (k = 0; k < c->nhy; k++)
            if (c->hy[k].full) pt_diff_add(s, "%s %s", shown++ ? ";" : "", c->hy[k].name);
        pt_diff_add(s, ".%s", c->o->out->sep ? " The separating scene printed above tells them "
                    "apart." : "");
    } else if (c->nhy) {
        pt_diff_add(s, " No single known mistake explains every vertex.");
        for (k = 0; k < c->nhy && shown < 3; k++) {
            const dhyp *hy = &c->hy[k];
            if (!hy->repro) continue;
            pt_diff_add(s, "%s %s (%s stage), which ", shown++ ? ";" : " Partial candidates, "
                        "which do NOT explain the trace:", hy->name, pt_stage_infos[hy->stage].name);
            fit_str(s, hy, c->fit_differ, c->fit_agree);
        }
        if (shown) pt_diff_add(s, ".");
    }
    if (c->swapped >= 0)
        pt_diff_add(s, " With EXPECTED and ACTUAL swapped, %s explains every vertex: are the "
                    "arguments in the wrong order? (pipetrace diff REFERENCE STUDENT)",
                    c->swap_hy.name);
}

void pt_diff_outcome_stage(pt_diff_outcome *out, const char *st)
{
    snprintf(out->stage, sizeof out->stage, "%s", st);
}

void pt_diff_outcome_named(pt_diff_outcome *out, const char *name)
{
    int k;

    for (k = 0; k < out->nnamed && k < PT_DIFF_MAXNAMED; k++)
        if (!strcmp(out->named[k], name)) return;
    if (out->nnamed < PT_DIFF_MAXNAMED)
        snprintf(out->named[out->nnamed], sizeof out->named[0], "%s", name);
    out->nnamed++;
}

void pt_diff_print_verdict(const dctx *c, int differ, int top, int px_differ, const rstat *rs)
{
    pt_diff_outcome *out = c->o->out;
    pbuf s;
    size_t k;
    int side, st;

    memset(&s, 0, sizeof s);
    if (!differ) {
        pt_diff_para("", "Verdict: PASS. ACTUAL agrees with EXPECTED at every stage of every "
                     "vertex, and lights the same pixels.");
        return;
    }
    for (side = 0; side < 2; side++)
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (c->silent_recs[side][st]) {
                pt_diff_add(&s, "Verdict: FAIL at the %s stage: %s has no %s records. The stage "
                            "computes, but does not report what it computed: it must call "
                            "pt_emit(sink, &r) as stages/ does.", pt_stage_infos[st].name,
                            pt_diff_side[side], pt_stage_infos[st].name);
                pt_diff_outcome_stage(out, pt_stage_infos[st].name);
                out->silent = 1;
                pt_diff_para("", s.b);
                return;
            }
    if (top >= 0) {
        const vent *e = c->first_ex[top] ? &c->vt.e[c->first_ex[top] - 1] : NULL;
        char who[128];
        pt_diff_add(&s, "Verdict: FAIL at the %s stage, where %zu of the %zu differing "
                    "vertices go wrong first", pt_stage_infos[top].name, c->first_at[top], c->differ);
        if (e) {
            pt_diff_add(&s, "; the first is %s: ", pt_diff_who(c, e->model, e->v, who, sizeof who));
            pt_diff_evidence(c, e, top, &s);
        }
        pt_diff_add(&s, ".");
        pt_diff_outcome_stage(out, pt_stage_infos[top].name);
        if (c->verdict >= 0)
            for (k = 0; k < c->nhy; k++)
                if (c->hy[k].full) pt_diff_outcome_named(out, c->hy[k].name);
        if (c->verdict >= 0 && c->nfull == 1 && c->hy[c->verdict].stage == top) {
            const dhyp *hy = &c->hy[c->verdict];
            pt_diff_add(&s, " Likely mistake: %s: %s. It explains all the evidence: it ",
                        hy->name, hy->how);
            fit_str(&s, hy, c->fit_differ, c->fit_agree);
            pt_diff_add(&s, ".");
        } else if (c->verdict >= 0) {
            pt_diff_add(&s, " More than one known mistake explains it (see above).");
        } else {
            pt_diff_add(&s, " No known mistake explains it: compare your %s stage with its "
                        "formula, %s, on that vertex (pipetrace step --vertex N shows each "
                        "stage's numbers).", pt_stage_infos[top].name, pt_stage_infos[top].formula);
        }
        if (c->swapped >= 0)
            pt_diff_add(&s, " With EXPECTED and ACTUAL swapped, %s explains it: the reference "
                        "goes first.", c->swap_hy.name);
    } else if (px_differ) {
        pt_diff_add(&s, "Verdict: FAIL in the pixels: every vertex agrees, but the lit pixels "
                    "differ");
        pt_diff_outcome_stage(out, "pixels");
        size_t named[PT_NRASTER_MISTAKES], nn = pt_diff_raster_named(rs, named);
        for (k = 0; k < nn; k++) pt_diff_outcome_named(out, pt_raster_mistakes[named[k]].name);
        if (nn == 1)
            pt_diff_add(&s, ". Likely mistake: %s: %s. It reproduces %s.",
                        pt_raster_mistakes[named[0]].name, pt_raster_mistakes[named[0]].how,
                        rs->segs_differ == 1 ? "the one segment that differs"
                        : "every segment that differs");
        else if (nn > 1) {
            pt_diff_add(&s, "; more than one known mistake of the rasterizer reproduces every "
                        "segment that differs: ");
            for (k = 0; k < nn; k++)
                pt_diff_add(&s, "%s%s", k ? " or " : "", pt_raster_mistakes[named[k]].name);
            pt_diff_add(&s, ".");
        } else
            pt_diff_add(&s, "; no known mistake of the rasterizer explains them.");
    } else {
        pt_diff_add(&s, "Verdict: FAIL: the traces differ (see above).");
    }
    pt_diff_para("", s.b);
}
