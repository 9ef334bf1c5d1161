/*
** src/tools/journey/cmd_journey.c -- pipetrace journey: draw one vertex's way through the stages
** See LICENSE for copyright and license.
**
**   pipetrace journey [SCENE] --vertex N|LIST [--model NAME] [--svg FILE] [--html FILE]
**                     [--image FILE]
**
** --svg writes one SVG picture with a panel per coordinate system; --html a
** self-contained page that shows one stage at a time with its formula and
** numbers, Prev/Next buttons and a choice of vertex (src/tools/journey/journey.h and
** src/tools/journey/journey_html.c draw them); --image the rendered framebuffer with the
** vertex's pixel marked, PNG or PPM as the render command writes it.  Files
** are written whole or not at all (src/io/outfile.h); "-" is standard output.
** Both cameras are drawn: the matrix camera's panels follow its ten stages
** (src/tools/journey/journey_matrix.c).  A scene of the course's renderer 7
** or 9 gets its own panels, page and image (src/tools/journey/journey_course.c).
*/
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/cli.h"
#include "tools/commands.h"
#include "io/explain.h"
#include "core/pipetrace.h"
#include "tools/journey/journey.h"
#include "tools/journey/journey_course.h"
#include "io/explain_course.h"
#include "io/outfile.h"
#include "io/png.h"


static const char usage[] =
"usage: pipetrace journey [SCENE] --vertex N|LIST [--model NAME] [--svg FILE]\n"
"                         [--html FILE] [--image FILE]\n"
"Draw vertex N (1-based) of model NAME (default: the first model that has a\n"
"vertex N) on its way from model coordinates to its element of the pixel\n"
"array, one panel per coordinate system.  SCENE defaults to the built-in scene.\n"
"\n"
"  --svg FILE     one SVG picture with all seven panels ('-': standard output)\n"
"  --html FILE    a self-contained page: one stage at a time with its formula\n"
"                 and numbers, Prev/Next buttons, every used vertex to choose\n"
"                 (at most 2000); it needs no network and no other file\n"
"  --image FILE   the rendered framebuffer with the vertex's pixel ringed in red:\n"
"                 PNG when FILE ends in .png (any case), else binary PPM (P6)\n"
"  --vertex LIST  with --html only: several vertices of the model, N and A-B\n"
"                 joined by commas (1,4-6) or 'all'; the page lists just those\n"
"\n"
"At least one of --svg, --html and --image.  Either camera: the classic camera's\n"
"seven panels, or the matrix camera's ten (camera lookat: world, view, clip, cvv,\n"
"ndc and screen between model and viewport; a vertex outside the view volume\n"
"stops at the cvv, and its segments go on from where clipping cut them).\n"
"A scene of the course's renderer 7 or 9: the panels model, [world,] view,\n"
"view volume, normalized, near clip, image plane, viewport; a vertex past the\n"
"model's own is one a clip stage made.  The page lists every vertex of the\n"
"position (at most 64) or the --vertex list, its sliders move l, r, b, t, n,\n"
"the translation (7) or view vector and matrix angles (9) and the viewport;\n"
"--image rings the"
" vertex's pixel in the course's render.\n"
"Exit status: 0 success, 1 usage error, 2 bad input or output error.\n"
"Docs: docs/journey.md\n";

/* Write the text in sb (or, sb NULL, the image fb) to path, whole or not at
** all.  Returns 0 or -1. */
static int write_file(const char *path, const pt_sbuf *sb, const pt_fb *fb)
{
    pt_outfile o = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];
    int bad;

    if (pt_outfile_open(&o, path, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace journey: %s\n", err);
        return -1;
    }
    if (sb) bad = fwrite(sb->s, 1, sb->len, o.f) != sb->len;
    else bad = (pt_path_is_png(path) ? pt_fb_write_png(fb, o.f) : pt_fb_write_ppm(fb, o.f)) != 0;
    return pt_outfile_finish(&o, bad, "pipetrace journey");
}

/* Ring framebuffer pixel (x, y) of fb (scene s's) in the panels' red: the
** pixel itself and the square 3 pixels around it, inside the framebuffer. */
static void ring(pt_fb *fb, const pt_scene *s, int64_t x, int64_t y)
{
    static const unsigned char red[3] = PT_JOURNEY_RED_RGB;
    pt_pix px = {0, 0, 1};
    int64_t dx, dy;

    for (dy = -3; dy <= 3; dy++)
        for (dx = -3; dx <= 3; dx++) {
            int ring = dx == -3 || dx == 3 || dy == -3 || dy == 3;
            if (!(ring || (dx == 0 && dy == 0))) continue;
            if (x + dx < 0 || x + dx >= s->fb_w || y + dy < 0 || y + dy >= s->fb_h) continue;
            px.x = x + dx;
            px.y = y + dy;
            pt_fb_set(fb, pt_fb2index(px, s->fb_w, s->fb_h, NULL), red);   /* the index stage */
        }
}

/* The scene rendered into fb (initialised here), with the framebuffer pixel of
** vertex v of model m ringed (ring()) when it has one.  Returns 0, or -1 when
** out of memory (fb is then freed). */
static int render_marked(pt_fb *fb, const pt_scene *s, const pt_model *m, uint64_t v)
{
    pt_journey j;

    if (pt_journey_render(fb, s) != 0) return -1;
    if (pt_run_journey(&j, s, m, v, 0) != 0) { pt_fb_free(fb); return -1; }
    if ((j.rec[PT_STAGE_FRAMEBUFFER].flags & PT_REC_NULL) ||          /* no pixel, or */
        !(j.reported & 1u << PT_STAGE_FRAMEBUFFER)) return 0;        /* stopped at the cvv */
    ring(fb, s, j.rec[PT_STAGE_FRAMEBUFFER].ix, j.rec[PT_STAGE_FRAMEBUFFER].iy);
    return 0;
}

/* --vertex LIST: "all", or items N or A-B (1 <= A <= B) joined by commas. */
#define VLIST_MAX 64
typedef struct vlist {
    int all;                     /* "all": every vertex of the model */
    int n;                       /* items; the first item's A is shown first */
    uint64_t a[VLIST_MAX], b[VLIST_MAX];
    uint64_t max;                /* the largest B */
} vlist;

/* Parse t into *l.  Returns 0, or -1 when t is no such list. */
static int vlist_parse(vlist *l, const char *t)
{
    memset(l, 0, sizeof *l);
    if (!strcmp(t, "all")) { l->all = 1; l->max = 1; return 0; }
    for (;;) {
        unsigned long long x[2] = {0, 0};
        int k, nd;
        for (k = 0; k < 2; k++) {
            for (nd = 0; *t >= '0' && *t <= '9'; t++, nd++) {
                if (x[k] > (4294967295ull - (unsigned)(*t - '0')) / 10) return -1;
                x[k] = x[k] * 10 + (unsigned)(*t - '0');
            }
            if (nd == 0 || x[k] == 0) return -1;
            if (k == 0 && *t == '-') { t++; continue; }
            if (k == 0) x[1] = x[0];
            break;
        }
        if (x[0] > x[1] || l->n == VLIST_MAX) return -1;
        l->a[l->n] = x[0]; l->b[l->n] = x[1]; l->n++;
        if (x[1] > l->max) l->max = x[1];
        if (*t == '\0') return 0;
        if (*t++ != ',') return -1;
    }
}

/* journey on a scene of the course's renderer 7 or 9: the SVG, the page
** (vertices from l, a list, or every vertex of the position) and the image.
** Returns the exit status. */
static int course_journey(const pt_scene *s, const char *model, uint64_t v, const char *svg,
                          const char *html, const char *image, const vlist *l)
{
    size_t mi = 0;
    pt_sbuf a, b;
    pt_fb fb;
    unsigned char *pick = NULL;
    uint64_t npick = 0, x;
    int rc, have_fb = 0, has = 0, i;
    int64_t px = 0, py = 0;

    if (model) {
        const pt_model *m = pt_cli_model(s, "journey", model);
        if (!m) return PT_EXIT_INPUT;
        mi = (size_t)(m - s->models);
        rc = 0;
    } else rc = pt_cx_find(s, v, &mi);
    if (!l->all && (l->n > 1 || l->a[0] != l->b[0])) {   /* the vertices the page lists */
        npick = l->max;
        if (!(pick = calloc(npick, 1))) rc = -1;
        for (i = 0; pick && i < l->n; i++)
            for (x = l->a[i]; x <= l->b[i]; x++) pick[x - 1] = 1;
    }
    pt_sbuf_init(&a);
    pt_sbuf_init(&b);
    if (rc == 0 && svg) rc = pt_journey_course_svg(&a, s, mi, v);
    if (rc == 0 && html) rc = pt_journey_course_html(&b, s, mi, v, pick, npick);
    if (rc == 0 && image && (rc = pt_journey_course_image(&fb, s, mi, v, &has, &px, &py)) == 0) {
        have_fb = 1;
        if (has) ring(&fb, s, px, py);
    }
    if (rc == 2)
        fprintf(stderr, "pipetrace journey: --vertex: the position of model %s of %s has no "
                "vertex %llu, not even after the clips\n", s->models[mi].name, s->path,
                (unsigned long long)npick);
    else if (rc == 1 && model)
        fprintf(stderr, "pipetrace journey: --vertex %llu: the position of model %s of %s has "
                "no vertex %llu, not even after the clips\n", (unsigned long long)v, model,
                s->path, (unsigned long long)v);
    else if (rc == 1)
        fprintf(stderr, "pipetrace journey: --vertex %llu: no position of %s has a vertex %llu, "
                "not even after the clips\n", (unsigned long long)v, s->path,
                (unsigned long long)v);
    else if (rc) fprintf(stderr, "pipetrace journey: %s: out of memory\n", s->path);
    /* every output is complete before any file is touched */
    if (!rc && svg && write_file(svg, &a, NULL) != 0) rc = -1;
    if (!rc && html && write_file(html, &b, NULL) != 0) rc = -1;
    if (!rc && image && write_file(image, NULL, &fb) != 0) rc = -1;
    if (have_fb) pt_fb_free(&fb);
    pt_sbuf_free(&a);
    pt_sbuf_free(&b);
    free(pick);
    return rc ? PT_EXIT_INPUT : 0;
}

int pt_cmd_journey(int argc, char **argv)
{
    const char *path = NULL, *model = NULL, *svg = NULL, *html = NULL, *image = NULL;
    unsigned long long v = 0;
    const pt_model *m = NULL;
    pt_scene s;
    pt_sbuf a, b;
    pt_fb fb;
    int k, rc, have_fb = 0;
    pt_cli_args ca = {"journey", usage, 1, NULL, NULL, 0};
    vlist vl;
    unsigned char *pick = NULL;
    int listed = 0;

    for (k = 1; k < argc; k++) {
        const char *o = argv[k];

        const char *val;
        int u;

        if (!strcmp(o, "--svg") || !strcmp(o, "--html") || !strcmp(o, "--image")) {
            if ((u = pt_cli_value("journey", argc, argv, &k, &val)) >= 0) return u;
            if (!strcmp(o, "--svg")) svg = val;
            else if (!strcmp(o, "--html")) html = val;
            else image = val;
        } else if (!strcmp(o, "--vertex")) {
            if ((u = pt_cli_value("journey", argc, argv, &k, &val)) >= 0) return u;
            if (vlist_parse(&vl, val) != 0) {
                uint64_t one;                   /* a number out of range: say its range */
                if (*val && !val[strspn(val, "0123456789")])
                    return pt_cli_vertex("journey", val, &one);
                return pt_cli_usage("journey", "--vertex takes a vertex number >= 1, a list "
                                    "such as 1,4-6 or 'all', not %s", val);
            }
            listed = 1;
        } else if ((u = pt_cli_arg(&ca, argc, argv, &k)) >= 0) return u;  /* SCENE, --vertex, ... */
    }
    path = ca.path;
    model = ca.model;
    if (!listed) return pt_cli_usage("journey", "--vertex N is required");
    v = vl.all ? 1 : vl.a[0];
    if ((vl.all || vl.n > 1 || vl.a[0] != vl.b[0]) && (svg || image))
        return pt_cli_usage("journey", "--svg and --image draw one vertex; a list of vertices "
                            "is for --html");
    if (!svg && !html && !image)
        return pt_cli_usage("journey", "nothing to write: give --svg FILE, --html FILE or --image FILE");
    if ((svg && html && !strcmp(svg, html)) || (svg && image && !strcmp(svg, image)) ||
        (html && image && !strcmp(html, image)))
        return pt_cli_usage("journey", "two outputs name the same file: %s",
                            svg && html && !strcmp(svg, html) ? svg : image);
    {
        const char *out[3] = {svg, html, image}, *opt[3] = {"--svg", "--html", "--image"};
        if (pt_cli_outputs(path, out, opt, 3) != 0) return PT_EXIT_INPUT;   /* over the scene */
    }

    if (pt_cli_load(&s, path) != 0) return PT_EXIT_INPUT;
    {
        const char *out[3] = {svg, html, image}, *opt[3] = {"--svg", "--html", "--image"};
        /* every camera and renderer keeps only what it draws (journey.h,
        ** journey_course.c): no cap on the scene */
        if (pt_cli_outputs_objs(&s, out, opt, 3) != 0) {
            pt_scene_free(&s);
            return PT_EXIT_INPUT;
        }
    }
    if (s.renderer == 7 || s.renderer == 9) {
        rc = course_journey(&s, model, v, svg, html, image, &vl);
        pt_scene_free(&s);
        return rc;
    }
    if (!(m = pt_cli_vertex_model(&s, "journey", model, vl.max))) {
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (vl.all || vl.n > 1 || vl.a[0] != vl.b[0]) {   /* the vertices the page lists */
        int i;
        if (!(pick = calloc(m->nv, 1))) {
            fputs("pipetrace journey: out of memory\n", stderr);
            pt_scene_free(&s);
            return PT_EXIT_INPUT;
        }
        for (i = 0; i < (vl.all ? 1 : vl.n); i++) {
            uint64_t x, lo = vl.all ? 1 : vl.a[i], hi = vl.all ? m->nv : vl.b[i];
            for (x = lo; x <= hi; x++) pick[x - 1] = 1;
        }
    }

    pt_sbuf_init(&a);
    pt_sbuf_init(&b);
    rc = 0;
    if (svg) rc = pt_journey_svg(&a, &s, m, v);
    if (!rc && html) rc = pt_journey_html(&b, &s, m, v, pick);
    if (!rc && image && render_marked(&fb, &s, m, v) != 0) rc = -1;
    have_fb = !rc && image;
    if (rc == -2)
        fprintf(stderr, "pipetrace journey: the segments of the vertices shown of %s draw "
                "more than %d pixels; journey keeps them in memory and takes at most that "
                "many (docs/limits.md)\n", s.path, PT_JOURNEY_MAXPIX);
    else if (rc) fputs("pipetrace journey: out of memory\n", stderr);
    /* every output is complete before any file is touched */
    if (!rc && svg && write_file(svg, &a, NULL) != 0) rc = -1;
    if (!rc && html && write_file(html, &b, NULL) != 0) rc = -1;
    if (!rc && image && write_file(image, NULL, &fb) != 0) rc = -1;
    if (have_fb) pt_fb_free(&fb);
    pt_sbuf_free(&a);
    pt_sbuf_free(&b);
    free(pick);
    pt_scene_free(&s);
    return rc ? PT_EXIT_INPUT : 0;
}
