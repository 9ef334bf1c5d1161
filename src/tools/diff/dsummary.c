/*
** src/tools/diff/dsummary.c -- pipetrace diff: the intro, the headers, silent stages, the summary
** See LICENSE for copyright and license.
**
** What is said around the vertex-by-vertex list: the two files and the
** tolerance, how the headers differ, the vertices and stages only one side
** has, a stage that did not report (a student stage that never called
** pt_emit(): said first, and a later stage's difference is not blamed on the
** later stage alone), and the closing paragraph with the likely mistake.
*/
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/diff/diff.h"

/* Print how the headers differ; returns 1 when they do. */
int pt_diff_compare_headers(const dctx *c)
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
    if (strcmp(pt_camera_word(pt_pipelines[a->pipe], a->perspective),
               pt_camera_word(pt_pipelines[b->pipe], b->perspective)) != 0) {
        printf("header: camera %s in EXPECTED, %s in ACTUAL\n",
               pt_camera_word(pt_pipelines[a->pipe], a->perspective),
               pt_camera_word(pt_pipelines[b->pipe], b->perspective));
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
        } else if (!pt_diff_same_real(c, ma->t[0], mb->t[0]) || !pt_diff_same_real(c, ma->t[1], mb->t[1]) ||
                           !pt_diff_same_real(c, ma->t[2], mb->t[2])) {
            char b1[PT_NUMLEN], b2[PT_NUMLEN], b3[PT_NUMLEN];
            printf("header: model %s is translated by %s %s %s in EXPECTED", pt_names_get(&c->nm,
                   ma->name), pt_diff_num(ma->t[0], b1), pt_diff_num(ma->t[1], b2), pt_diff_num(ma->t[2], b3));
            printf(", by %s %s %s in ACTUAL\n", pt_diff_num(mb->t[0], b1), pt_diff_num(mb->t[1], b2),
                           pt_diff_num(mb->t[2], b3));
            differ = 1;
        }
    }
    if (differ) printf("The headers differ: these may be traces of different scenes.\n\n");
    return differ;
}

static const char *format_name(const pt_tread *t)
{
    if (t->kind == PT_TK_KRAFT) return "the course's debug log";
    return t->kind == PT_TK_JSONL ? "JSON Lines" : "text";
}

void pt_diff_print_intro(const dctx *c)
{
    char b1[PT_NUMLEN], b2[PT_NUMLEN];
    pbuf sb;
    int s;

    for (s = 0; s < 2; s++) {
        const pt_tread *t = &c->t[s];
        printf("%-9s %s  (%s", pt_diff_side[s], c->o->path[s], format_name(t));
        if (t->prec >= 0) printf(", %d decimals", t->prec);
        printf(": %zu vertex, %zu pixel records)\n", t->nvx, t->npx);
    }
    for (s = 0; s < 2; s++)
        if (c->t[s].unread)
            printf("Note: %" PRIu64 " line%s of %s (the first: line %" PRIu64 ") %s not a kind "
                   "of line diff reads (a program's own output): "
                   "passed over, not compared.\n", c->t[s].unread, c->t[s].unread == 1 ? "" : "s",
                   pt_diff_side[s], c->t[s].unread_line, c->t[s].unread == 1 ? "is" : "are");
    memset(&sb, 0, sizeof sb);
    printf("Integers must be equal; doubles a and b agree when\n"
           "  |a - b| <= max(%s, %s * max(|a|, |b|))\n", pt_diff_num(c->o->tol, b1), pt_diff_num(c->o->rel, b2));
    if (c->t[0].prec >= 0 || c->t[1].prec >= 0) {
        pt_diff_add(&sb, "plus half a unit in the last printed digit of a text trace (");
        for (s = 0; s < 2; s++) {
            if (c->t[s].prec < 0) continue;
            pt_diff_add(&sb, "%s%s: %s", s && c->t[0].prec >= 0 ? ", " : "", pt_diff_side[s],
                        pt_diff_num(0.5 * pow(10.0, -c->t[s].prec), b1));
        }
        pt_diff_add(&sb, "): the text format prints only --precision decimals.");
        pt_diff_para("", sb.b);
    }
    printf("\n");
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
    if (st == PT_STAGE_VIEWPORT && pt_pipelines[c->t[0].hdr.pipe]->matrices)
        return "stages/m7_screen2viewport.c";       /* the matrix camera floors */
    return file[st];
}

/* Find the silent stages: for each model, a stage that side s lacks entirely
** while it has records of other stages of that model, the other side has
** records of it, and s's header does not leave it out.  A stage left out on
** purpose (an identity, --stage) is in the header; a student stage that forgot
** to call pt_emit() is not.  Returns 0, or -1 when out of memory. */
int pt_diff_find_silent(dctx *c)
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
void pt_diff_report_silent(const dctx *c)
{
    int s, st;
    pbuf sb;

    for (s = 0; s < 2; s++)
        for (st = 0; st < PT_NSTAGES_ALL; st++) {
            if (!c->silent_recs[s][st]) continue;
            memset(&sb, 0, sizeof sb);
            pt_diff_no_records(&sb, s, st);
            pt_diff_add(&sb, " %s's header does not leave the %s stage out, and %s has %zu of "
                        "them. A stage reports its record through the trace interface, "
                        "pt_emit(sink, &r), as %s does (docs/teaching.md); its values were not "
                        "compared, and a difference in a later stage may start there.",
                        pt_diff_side[s], pt_stage_infos[st].name, pt_diff_side[!s],
                        c->silent_recs[s][st], stage_file(c, st));
            pt_diff_para("", sb.b);
            printf("\n");
        }
}

/* The side-only vertices: count them and list a few. */
void pt_diff_report_one_sided(dctx *c)
{
    int s, st;
    size_t k;

    for (s = 0; s < 2; s++) {
        size_t listed = 0;
        for (k = 0; k < c->vt.n; k++) {
            const vent *e = &c->vt.e[k];
            int here = 0, there = 0;
            for (st = 0; st < PT_NSTAGES_ALL; st++) {
                here |= e->rec[s][st] != PT_DIFF_NONE;
                there |= e->rec[!s][st] != PT_DIFF_NONE;
            }
            if (!here || there) continue;
            if (c->only[s]++ == 0) printf("only in %s:", pt_diff_side[s]);
            if (listed < c->o->show) {
                char name[128];
                printf("%s %s", listed ? "," : "", pt_diff_who(c, e->model, e->v, name, sizeof name));
                listed++;
            }
        }
        if (c->only[s] > listed) printf(", ... (%zu in all)", c->only[s]);
        if (c->only[s]) printf("\n\n");
    }
}

/* A note on stages only one trace holds: they are not compared. */
void pt_diff_report_stage_only(const dctx *c)
{
    int s, st, any = 0;

    for (s = 0; s < 2; s++)
        for (st = 0; st < PT_NSTAGES_ALL; st++) {
            if (!c->stage_only[s][st]) continue;
            printf("%s %s records are only in %s (%zu)", any ? ";" : "Not compared:",
                   pt_stage_infos[st].name, pt_diff_side[s], c->stage_only[s][st]);
            any = 1;
        }
    if (any) printf(".\n\n");
}

/* 1 when a stage of either side did not report (find_silent). */
int pt_diff_silent_any(const dctx *c)
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

    if (!nclip) { pt_diff_add(s, "vertices"); return; }
    if (parts)
        pt_diff_add(s, "points (%zu of %zu vertices, %zu of %zu clip points)",
                    c->agree - c->agree_clip, nv, c->agree_clip, nclip);
    else
        pt_diff_add(s, "points (%zu vertices, %zu clip points)", nv, nclip);
}

/* What the agreement does not cover, as "the framebuffer stage (in neither
** trace), the lit pixels (...)": each stage of EXPECTED's pipeline that no
** vertex of both traces holds, and the pixels unless both have raster
** records.  Returns how many gaps. */
static int gaps(const dctx *c, int pixels_compared, pbuf *s)
{
    const pt_pipeline *pl = pt_pipelines[c->t[0].hdr.pipe];
    int i, n = 0;
    size_t k;

    for (i = 0; i < pl->norder; i++) {
        pt_stage st = pl->order[i];
        int held[2] = {0, 0}, both = 0;
        for (k = 0; k < c->vt.n && !both; k++) {
            const vent *e = &c->vt.e[k];
            held[0] |= e->rec[0][st] != PT_DIFF_NONE;
            held[1] |= e->rec[1][st] != PT_DIFF_NONE;
            both = e->rec[0][st] != PT_DIFF_NONE && e->rec[1][st] != PT_DIFF_NONE;
        }
        if (both && st == PT_STAGE_FRAMEBUFFER && c->t[0].hdr.have && c->t[0].hdr.vp_x == 0
            && c->t[0].hdr.vp_y == 0) {     /* compared, but x_ul + x_vp = x_vp */
            pt_diff_add(s, "%sthe framebuffer stage's offset (the viewport's corner is (0, 0) "
                        "here, so a stage that leaves it out agrees)", n++ ? ", " : "");
            continue;
        }
        if (both) continue;
        pt_diff_add(s, "%sthe %s stage (%s)", n++ ? ", " : "", pt_stage_infos[st].name,
                    held[0] ? "only in EXPECTED" : held[1] ? "only in ACTUAL" : "in neither trace");
    }
    if (!pixels_compared) {
        int r0 = c->t[0].npx || c->t[0].ncl, r1 = c->t[1].npx || c->t[1].ncl;
        pt_diff_add(s, "%sthe lit pixels (%s)", n++ ? ", " : "",
                    r0 ? "only EXPECTED has raster records" : r1 ? "only ACTUAL has raster "
                    "records" : "neither trace has raster records");
    }
    return n;
}

/* The summary paragraph; returns the exit status. */
int pt_diff_summarize(dctx *c, int hdr_differ, size_t nmiss, size_t nextra,
                             const size_t nlit[2], int pixels_compared, const rstat *rs)
{
    pbuf s;
    size_t total = c->agree + c->differ, k;
    int st, top = -1, differ;

    memset(&s, 0, sizeof s);
    differ = hdr_differ || c->differ || c->only[0] || c->only[1] || nmiss || nextra ||
             pt_diff_silent_any(c);
    if (!differ) {
        pt_diff_add(&s, "The traces agree: %zu of %zu ", total, total);
        points(&s, c, 0);
        pt_diff_add(&s, " at every stage both hold");
        if (pixels_compared) pt_diff_add(&s, ", and the same %zu lit pixel%s.", nlit[0], nlit[0] == 1 ? "" : "s");
        else pt_diff_add(&s, ".");
        pt_diff_para("", s.b);
        if (c->o->verdict) {
            pbuf g;
            memset(&g, 0, sizeof g);
            printf("\n");
            if (gaps(c, pixels_compared, &g)) {
                memset(&s, 0, sizeof s);
                pt_diff_add(&s, "Verdict: NOT PROVEN. ACTUAL agrees with EXPECTED wherever both "
                            "were compared, but not compared were: %s. Trace both with "
                            "--all-stages --format jsonl (raster records included) on a scene "
                            "that exercises them; exit status 3.", g.b);
                pt_diff_para("", s.b);
                return PT_EXIT_UNPROVEN;
            }
            pt_diff_print_verdict(c, 0, -1, 0, rs);
        }
        return PT_EXIT_OK;
    }
    for (k = 0; k < 2; k++)
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (c->silent_recs[k][st]) {
                pt_diff_no_records(&s, (int)k, st);
                pt_diff_add(&s, " ");
            }
    if (total) {
        pt_diff_add(&s, "%zu of %zu ", c->agree, total);
        points(&s, c, 1);
        pt_diff_add(&s, " agree%s", c->agree == 1 ? "s" : "");
    } else pt_diff_add(&s, "No vertex is in both traces");
    if (c->differ) pt_diff_add(&s, ", %zu differ%s", c->differ, c->differ > 1 ? "" : "s");
    if (c->only[0])
        pt_diff_add(&s, ", %zu %s only in EXPECTED", c->only[0], c->only[0] > 1 ? "are" : "is");
    if (c->only[1]) pt_diff_add(&s, ", %zu only in ACTUAL", c->only[1]);
    pt_diff_add(&s, ".");
    for (st = 0; st < PT_NSTAGES_ALL; st++)
        if (c->first_at[st] && (top < 0 || c->first_at[st] > c->first_at[top])) top = st;
    if (top >= 0) {
        int quiet = -1;                     /* a silent stage before top */
        for (k = 0; k < PT_NSTAGES_ALL && (int)pt_trace_order[k] != top; k++)
            if (c->silent_recs[0][pt_trace_order[k]] || c->silent_recs[1][pt_trace_order[k]])
                quiet = pt_trace_order[k];
        pt_diff_add(&s, " The stage that goes wrong first most often is %s (%zu of %zu)",
                    pt_stage_infos[top].name, c->first_at[top], c->differ);
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (st != top && c->first_at[st])
                pt_diff_add(&s, "; %s first for %zu", pt_stage_infos[st].name, c->first_at[st]);
        pt_diff_add(&s, ".");
        if (quiet >= 0)
            pt_diff_add(&s, " But the %s stage before it did not report, so the mistake may be "
                        "there, not in the %s stage.", pt_stage_infos[quiet].name,
                        pt_stage_infos[top].name);
        pt_diff_verdict(c, &s);
        if (!c->nhy && c->t[0].hdr.pipe != PT_PIPE_CLASSIC)
            pt_diff_add(&s, " The known mistakes are the classic camera's: none was checked.");
    }
    if (hdr_differ) pt_diff_add(&s, " The headers differ.");
    if (pixels_compared && (nmiss || nextra)) {
        int vertices_differ = c->differ || c->only[0] || c->only[1] || pt_diff_silent_any(c);
        if (c->px_shift)
            pt_diff_add(&s, " %s lit pixels differ%s: all of them moved by (%" PRId64 ", %" PRId64
                        ")", vertices_differ ? "The" : "But the", vertices_differ ? " too" : "",
                        c->px_d[0], c->px_d[1]);
        else
            pt_diff_add(&s, " %s lit pixels differ%s: %zu in EXPECTED, %zu in ACTUAL (%zu missing, "
                        "%zu extra)", vertices_differ ? "The" : "But the", vertices_differ ? " too" : "",
                        nlit[0], nlit[1], nmiss, nextra);
        if (vertices_differ && rs->own_tried && rs->own_tried == rs->segs_differ && !rs->own_bad)
            pt_diff_add(&s, ", as a consequence: from ACTUAL's own end pixels the reference "
                        "rasterizer draws ACTUAL's pixels in every segment that differs.");
        else if (vertices_differ && rs->own_bad)
            pt_diff_add(&s, ", and not only as a consequence: from ACTUAL's own end pixels the "
                        "reference rasterizer does not draw ACTUAL's pixels in %zu of the %zu "
                        "segments that differ (the first: %s segment %" PRIu64 "), so the "
                        "rasterizer (or the viewport stage it asks each step) goes wrong there "
                        "too: a second mistake.", rs->own_bad, rs->segs_differ,
                        pt_names_get(&c->nm, rs->own_model), rs->own_seg);
        else if (vertices_differ && rs->own_tried)
            pt_diff_add(&s, ", which may be a consequence: from ACTUAL's own end pixels the "
                        "reference rasterizer draws ACTUAL's pixels in the %zu segment%s it "
                        "could replay; the other %zu were not checked.",
                        rs->own_tried, rs->own_tried == 1 ? "" : "s",
                        rs->segs_differ - rs->own_tried);
        else if (vertices_differ)
            pt_diff_add(&s, "; whether only as a consequence was not checked (%s).",
                        c->t[0].hdr.have ? "ACTUAL's framebuffer stage offsets its vertices in more "
                        "than one way"
                        : "EXPECTED has no header with the viewport");
        else if (rs->segs_differ) {
            size_t best = PT_NRASTER_MISTAKES, named[PT_NRASTER_MISTAKES];
            size_t nn = pt_diff_raster_named(rs, named);
            pt_diff_add(&s, ", so the rasterizer differs, in %zu segment%s.",
                        rs->segs_differ, rs->segs_differ > 1 ? "s" : "");
            for (k = 0; k < PT_NRASTER_MISTAKES; k++)
                if (rs->hits[k] && (best == PT_NRASTER_MISTAKES || rs->hits[k] > rs->hits[best])) best = k;
            if (nn == 1) {
                pt_diff_add(&s, " Likely mistake: %s %s, which reproduces ACTUAL's pixels in every "
                            "segment that differs.", pt_raster_mistakes[named[0]].name,
                            pt_raster_mistakes[named[0]].where);
            } else if (nn > 1) {
                pt_diff_add(&s, " Likely mistake: ambiguous: ");
                for (k = 0; k < nn; k++)
                    pt_diff_add(&s, "%s%s", k ? " or " : "", pt_raster_mistakes[named[k]].name);
                pt_diff_add(&s, " (each reproduces ACTUAL's pixels in every segment that differs).");
                if (c->o->out->sep) pt_diff_add(&s, " The separating scene printed above tells "
                                                "them apart.");
            } else if (best < PT_NRASTER_MISTAKES) {
                pt_diff_add(&s, " No known mistake of the rasterizer explains every segment: %s "
                            "reproduces %zu of the %zu, so it does NOT explain them.",
                            pt_raster_mistakes[best].name, rs->hits[best], rs->segs_differ);
            } else {
                pt_diff_add(&s, " No known mistake of the rasterizer reproduces them.");
            }
        } else {
            pt_diff_add(&s, ".");
        }
        if (vertices_differ) pt_diff_raster_second(rs, &s);
    } else if (pixels_compared) {
        pt_diff_add(&s, " Both light the same %zu pixel%s.", nlit[0], nlit[0] == 1 ? "" : "s");
    }
    pt_diff_para("", s.b);
    if (c->o->verdict) {
        printf("\n");
        pt_diff_print_verdict(c, 1, top, pixels_compared && (nmiss || nextra), rs);
    }
    return PT_EXIT_DIFFER;
}
