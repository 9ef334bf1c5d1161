/*
** src/tools/diff/cmd_diff.c -- pipetrace diff: compare two traces or two images, name the mistake
** See LICENSE for copyright and license.
**
** The command: its options, reading both files, and the trace diff's order of
** business.  Two images go to dimage.c.  Two traces of one scene: the intro
** and the headers (dsummary.c), then vertex by vertex (dvertex.c) with the
** first difference of each explained by the catalogue's known mistakes
** (dexplain.c), the vertices and stages one side lacks (dsummary.c), the lit
** pixels and the rasterizer (dpixels.c), and the summary (dsummary.c).
** diff.h lists the files and what they share.
*/
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/outfile.h"
#include "tools/commands.h"
#include "io/tread79.h"
#include "tools/diff/diff.h"

static const char diff_usage[] =
"usage: pipetrace diff EXPECTED ACTUAL [--tol ABS] [--rel REL] [--show N] [--verdict]\n"
"                      [--scene SCENE] [--separating-scene FILE]\n"
"       pipetrace diff EXPECTED.ppm ACTUAL.ppm [--image-out FILE] [--show N]\n"
"                      [--scene SCENE]\n"
"       pipetrace diff LOG IMAGE --scene SCENE\n"
"Compare two traces (JSON Lines or text, in any mix) vertex by vertex: for\n"
"each vertex the first stage where they differ and both values; then the\n"
"known mistake that explains every vertex (recomputed from EXPECTED's previous\n"
"stage, it gives ACTUAL's values where they differ and leaves the others as\n"
"they are), if one does, else the partial candidates; then the lit pixels.\n"
"Or compare two images pixel by pixel: binary (P6) or plain (P3) PPM, or PNG\n"
"as pipetrace writes it (uncompressed).\n"
"Or a student's own log (or trace) with pixel lines and the image the same\n"
"program wrote: is the image what the log drew?  Its pixels lit at their\n"
"viewport coordinates (x_vp, y_vp) instead names the corner forgotten in\n"
"setPixelVP, behind whatever else the log shows.\n"
"A scene of the course's renderer 7 or 9: its traces (JSON Lines, text, CSV)\n"
"and the course's logs of it (its jar's, or pipetrace's in that format) are\n"
"compared stage by stage (the clip stages' new vertices too) and pixel by\n"
"pixel, and the first stage that differs tested against those renderers'\n"
"known mistakes.\n"
"\n"
"  --tol ABS         doubles agree when |a - b| <= max(ABS, REL * max(|a|, |b|))\n"
"  --rel REL         (defaults 0 and 1e-9; integers must be equal); a text trace\n"
"                    adds half a unit in its last printed digit\n"
"  --show N          list at most N vertices and N pixels of each kind\n"
"                    (default 10)\n"
"  --verdict         end with a verdict: pass, or the stage that goes wrong\n"
"                    first, the evidence and the mistake that explains it all\n"
"                    (make check-stage uses it)\n"
"  --image-out FILE  images: write FILE (PNG when it ends in .png, else P6 PPM)\n"
"                    with the differing pixels red, the others EXPECTED's dimmed\n"
"  --scene SCENE     the scene both were made from: a trace without a header\n"
"                    (the course's log, its jar's or pipetrace's) gets the\n"
"                    framebuffer, viewport, camera and translations from it,\n"
"                    so that the known mistakes can be tested; two images: its\n"
"                    viewport's corner (x_ul, y_ul), and ACTUAL moved by exactly\n"
"                    (-x_ul, -y_ul) names the corner forgotten in setPixelVP\n"
"  --separating-scene FILE  when several known mistakes explain everything\n"
"                    (ambiguous), the scene printed that tells them apart is\n"
"                    written to FILE too (never over an input of the run)\n"
"\n"
"Exit status, as diff(1): 0 same, 1 different, 2 trouble (unreadable input\n"
"or a usage error); with --verdict, 3 when nothing differs but not every\n"
"stage, or not the pixels, could be compared (the verdict says which): no\n"
"PASS without the evidence for it.\n"
"Docs: docs/teaching.md\n";

/* A usage error: the message, and diff's exit status for trouble (2, as
** diff(1): 1 means "different"). */
static int usage_error(const char *fmt, const char *arg)
{
    pt_cli_usage("diff", fmt, arg);
    return PT_EXIT_TROUBLE;
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
                    !strcmp(a, "--image-out") || !strcmp(a, "--show") || !strcmp(a, "--scene") ||
                    !strcmp(a, "--separating-scene");

        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(diff_usage, stdout); return 0; }
        if (!strcmp(a, "--verdict")) { o->verdict = 1; continue; }
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
        } else if (!strcmp(a, "--scene")) {
            o->scene = val;
        } else if (!strcmp(a, "--separating-scene")) {
            o->sep_out = val;
        } else if (a[0] == '-' && a[1] != '\0') {
            pt_cli_unknown("diff", diff_usage, a);
            return PT_EXIT_TROUBLE;             /* diff's usage errors: 2 */
        } else if (npath == 2) {
            return usage_error("more than two files given ('%s')", a);
        } else {
            o->path[npath++] = a;
        }
    }
    if (npath < 2) return usage_error("%s", "needs two files: EXPECTED and ACTUAL");
    return -1;
}

static int trace_diff(dctx *c)
{
    size_t k, nmiss = 0, nextra = 0, nlit[2] = {0, 0};
    int rc, hdr_differ, pixels_compared;
    rstat rs;

    memset(&rs, 0, sizeof rs);
    rc = pt_diff_fill_table(c);
    if (rc) return rc;
    if (pt_diff_fill_translations(c) != 0 || pt_diff_find_silent(c) != 0) return -1;
    if (pt_diff_fit(c) != 0) return -1;

    pt_diff_print_intro(c);
    hdr_differ = pt_diff_compare_headers(c);
    for (k = 0; k < c->vt.n; k++) {
        const vent *e = &c->vt.e[k];
        int st, both[2] = {0, 0};
        for (st = 0; st < PT_NSTAGES_ALL; st++) {
            both[0] |= e->rec[0][st] != PT_DIFF_NONE;
            both[1] |= e->rec[1][st] != PT_DIFF_NONE;
        }
        if (both[0] && both[1]) pt_diff_compare_vertex(c, e);
    }
    if (c->differ > c->shown) printf("... and %zu more vertices differ\n", c->differ - c->shown);
    if (c->differ) printf("\n");
    pt_diff_report_one_sided(c);
    pt_diff_report_silent(c);
    pt_diff_report_stage_only(c);
    pt_diff_report_fit(c);

    /* pixels: compared when both traces were rasterized with raster records */
    pixels_compared = (c->t[0].npx || c->t[0].ncl) && (c->t[1].npx || c->t[1].ncl);
    if (pixels_compared) {
        if (pt_diff_compare_pixels(c, &nmiss, &nextra, nlit) != 0) return -1;
        if ((nmiss || nextra) && c->t[0].hdr.have) {
            if (pt_diff_check_raster(c, &rs) != 0) return -1;
            if (!c->differ && !c->only[0] && !c->only[1] && !pt_diff_silent_any(c))
                pt_diff_report_raster(c, &rs);
        }
        if (nmiss || nextra) printf("\n");
        c->o->out->px_compared = 1;
        c->o->out->px_missing = nmiss;
        c->o->out->px_extra = nextra;
    } else if (c->t[0].npx + c->t[0].ncl + c->t[1].npx + c->t[1].ncl) {
        printf("Not compared: lit pixels (only %s has raster records).\n\n",
               c->t[0].npx + c->t[0].ncl ? "EXPECTED" : "ACTUAL");
    }
    c->o->out->vertices = c->agree + c->differ;
    c->o->out->differ = c->differ;
    c->o->out->only = c->only[0] + c->only[1];
    return pt_diff_summarize(c, hdr_differ, nmiss, nextra, nlit, pixels_compared, &rs);
}

/* Give side s of c, a trace without a header, the header scene sc would
** have written: what the catalogue's formulas need besides the vertices.
** Returns 0, or -1 out of memory. */
static int header_of_scene(dctx *c, int s, const pt_scene *sc)
{
    pt_thdr *h = &c->t[s].hdr;
    size_t k;

    h->fb_w = sc->fb_w;
    h->fb_h = sc->fb_h;
    h->vp_x = sc->vp_x;
    h->vp_y = sc->vp_y;
    h->vp_w = sc->vp_w;
    h->vp_h = sc->vp_h;
    h->pipe = sc->pipe;
    h->perspective = sc->pipe == PT_PIPE_MATRIX ? 1 : sc->perspective;
    if (sc->nmodels > h->cap) {
        pt_tmodel *m = realloc(h->models, sc->nmodels * sizeof *m);
        if (!m) return -1;
        h->models = m;
        h->cap = sc->nmodels;
    }
    h->nmodels = 0;
    for (k = 0; k < sc->nmodels; k++) {
        pt_tmodel *m = &h->models[h->nmodels];
        memset(m, 0, sizeof *m);
        if (pt_names_intern(&c->nm, sc->models[k].name, strlen(sc->models[k].name),
                            &m->name) != 0) return -1;
        m->t[0] = sc->models[k].translate.x;
        m->t[1] = sc->models[k].translate.y;
        m->t[2] = sc->models[k].translate.z;
        h->nmodels++;
    }
    h->have = 1;
    return 0;
}

/* --scene: the header of each side that has none.  Returns 0, or the exit
** status after the message. */
static int headers_from_scene(dctx *c)
{
    pt_scene sc;
    int s, rc;

    if ((rc = pt_cli_load(&sc, c->o->scene)) != 0) return PT_EXIT_TROUBLE;
    if (sc.renderer != 4) {
        fprintf(stderr, "pipetrace diff: %s: error: --scene is for the classic camera's and "
                "the matrix camera's traces; a scene of renderer %d is compared without "
                "it\n", c->o->scene, sc.renderer);
        pt_scene_free(&sc);
        return PT_EXIT_TROUBLE;
    }
    for (s = 0, rc = 0; s < 2 && rc == 0; s++)
        if (!c->t[s].hdr.have && header_of_scene(c, s, &sc) != 0) rc = -1;
    pt_scene_free(&sc);
    return rc;
}

/* 1 for the kinds of file that are images. */
static int is_image(pt_tkind k)
{
    return k == PT_TK_PPM || k == PT_TK_P3 || k == PT_TK_PNG;
}

/* Read file s of o, and parse it when it is a trace (its buffer is then freed:
** only one file's text is held at a time).  Returns 0, or the exit status
** after printing the message. */
static int load(dctx *c, int s, char **buf, size_t *len, pt_tkind *kind, int *r79)
{
    char err[PT_ERRLEN];

    if (pt_tread_file(c->o->path[s], buf, len, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return PT_EXIT_INPUT;
    }
    if ((*r79 = pt_t79_renderer(*buf, *len)) == 7 || *r79 == 9) return 0;   /* d79.c reads it */
    *r79 = 0;
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
    if (s == 0 && c->t[0].hdr.student[0])  /* the reference should come first */
        fprintf(stderr, "pipetrace diff: warning: EXPECTED %s comes from a student build "
                "(student %s); the reference trace is build/pipetrace's (are the two "
                "swapped?)\n", c->o->path[0], c->t[0].hdr.student);
    free(*buf);
    *buf = NULL;
    return 0;
}

int pt_cmd_diff(int argc, char **argv)
{
    pt_diff_outcome out;
    return pt_diff_run(argc, argv, &out);
}

int pt_diff_run(int argc, char **argv, pt_diff_outcome *out)
{
    dopts o;
    char *buf[2] = {NULL, NULL};
    size_t len[2];
    pt_tkind kind[2];
    char err[PT_ERRLEN];
    dctx *c;
    int rc, s, r79[2] = {0, 0};

    memset(out, 0, sizeof *out);
    rc = parse_args(&o, argc, argv);
    o.out = out;
    if (rc >= 0) return out->status = rc;
    for (s = 0; s < 2 && o.image_out; s++)      /* --image-out over an input: no */
        if (pt_outfile_same(o.image_out, !strcmp(o.path[s], "-") ? "/dev/stdin" : o.path[s])) {
            fprintf(stderr, "%s: error: --image-out names %s, %s; writing it would destroy it\n",
                    o.image_out, s ? "ACTUAL" : "EXPECTED", o.path[s]);
            return out->status = PT_EXIT_TROUBLE;
        }
    if (o.sep_out) {                            /* the scene over an input: no */
        const char *in[3];
        size_t nin = 0, hit = 0;
        for (s = 0; s < 2; s++) in[nin++] = !strcmp(o.path[s], "-") ? "/dev/stdin" : o.path[s];
        if (o.scene) in[nin++] = o.scene;
        if (!strcmp(o.sep_out, "-") || (hit = pt_outfile_among(o.sep_out, in, nin)) < nin) {
            fprintf(stderr, "%s: error: --separating-scene names %s; writing it would destroy "
                    "it\n", o.sep_out, !strcmp(o.sep_out, "-") ? "standard output, where the "
                    "report goes" : hit == 2 ? "--scene's file" : hit ? "ACTUAL" : "EXPECTED");
            return out->status = PT_EXIT_TROUBLE;
        }
    }
    c = calloc(1, sizeof *c);
    if (!c) { fputs("pipetrace: out of memory\n", stderr); return out->status = PT_EXIT_INPUT; }
    c->o = &o;
    for (s = 0; s < 2; s++)
        if ((rc = load(c, s, &buf[s], &len[s], &kind[s], &r79[s])) != 0) goto done;
    if (r79[0] || r79[1]) {
        if (!r79[0] || !r79[1])
            rc = usage_error("%s", "cannot compare a trace or log of renderer 7 or 9 with "
                             "another kind of file");
        else if (o.image_out)
            rc = usage_error("%s", "--image-out needs two images");
        else
            rc = pt_diff79(&o, buf, len);
    } else if (!is_image(kind[0]) && is_image(kind[1]) && o.scene && !o.image_out) {
        pt_ppm img;                             /* a student's own log and image */
        memset(&img, 0, sizeof img);
        if (pt_image_parse(&img, o.path[1], buf[1], len[1], err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            rc = PT_EXIT_INPUT;
        } else {
            rc = pt_diff_own_image(&o, &c->t[0], &img);
        }
        pt_image_free(&img);
    } else if (is_image(kind[0]) != is_image(kind[1])) {
        rc = usage_error("%s", "cannot compare an image with a trace (but a trace or log "
                         "with the image the same program wrote, --scene given)");
    } else if (is_image(kind[0])) {
        pt_ppm img[2];
        memset(img, 0, sizeof img);
        for (s = 0; s < 2 && rc == 0; s++) {
            if (pt_image_parse(&img[s], o.path[s], buf[s], len[s], err, sizeof err) != 0) {
                fprintf(stderr, "%s\n", err);
                rc = PT_EXIT_INPUT;
            }
        }
        if (rc == 0) rc = pt_diff_images(&o, img);
        pt_image_free(&img[0]);
        pt_image_free(&img[1]);
    } else if (o.image_out) {
        rc = usage_error("%s", "--image-out needs two images");
    } else if (!o.scene || (rc = headers_from_scene(c)) == 0) {
        rc = trace_diff(c);
    }
    if (rc < 0) {
        fputs("pipetrace: out of memory\n", stderr);
        rc = PT_EXIT_INPUT;
    }
    if (o.sep_out && out->sep < 0 && rc != PT_EXIT_INPUT) rc = PT_EXIT_TROUBLE;
    else if (o.sep_out && out->sep == 0 && rc != PT_EXIT_INPUT && rc != PT_EXIT_TROUBLE)
        fprintf(stderr, "pipetrace diff: note: nothing ambiguous, so no separating scene: %s "
                "not written\n", o.sep_out);
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
    free(c->silent[0]);
    free(c->silent[1]);
    free(c);
    free(buf[0]);
    free(buf[1]);
    return out->status = rc;
}
