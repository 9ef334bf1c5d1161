/*
** src/io/trace_kraft.c -- write the course renderer's own debug log (--format kraft)
** See LICENSE for copyright and license.
**
** The log's layout, model by model (trace_kraft.h says what it is):
**   ==== Render position: NAME ====         then its translation, the model,
**   TITLE: vIndex = %3d, (x,y,z) = (...)    every vertex, stage by stage
**   3. Pixel-plane: LineSegment: ([a, b], [a, b])     the segments,
**   3. Pixel-plane: cIndex = %3d, java.awt.Color[...] one colour a vertex,
**   4. Rasterize: LineSegment: ...          each segment with its two vertices
**                                           and colours, and with pixels its
**                                           rasterizer lines (kraft_segment).
** The rasterizer's lines follow the course's DDA as it prints it: the rounded
** endpoints, the slopes of position and colour, then one line per step, each
** step's pixel from the viewport stage (pt_pixel2viewport), as src/core/raster.c
** takes it.  tests/formats/kraft.sh ties the two: the pixels of the log are the
** pixels pt_run() draws, for every reference scene.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/jnum.h"
#include "io/trace_kraft.h"

/* "% 10.5f  % 10.5f  % 10.5f": the three numbers of Vertex.toString and
** Vector.toString. */
static void put_3(FILE *f, double x, double y, double z)
{
    char a[PT_JNUM_LEN], b[PT_JNUM_LEN], c[PT_JNUM_LEN];

    pt_jnum_f(a, x, 10, 5, PT_JNUM_SPACE);
    pt_jnum_f(b, y, 10, 5, PT_JNUM_SPACE);
    pt_jnum_f(c, z, 10, 5, PT_JNUM_SPACE);
    fprintf(f, "%s  %s  %s", a, b, c);
}

/* "(x,y,z) = (...)": Vertex.toString. */
static void put_xyz(FILE *f, double x, double y, double z)
{
    fputs("(x,y,z) = (", f);
    put_3(f, x, y, z);
    fputc(')', f);
}

/* The values the log shows for vertex journey j at stage st (the pixel plane
** has z = 0). */
static void stage_xyz(const pt_journey *j, pt_stage st, double *x, double *y, double *z)
{
    *x = j->rec[st].x;
    *y = j->rec[st].y;
    *z = st == PT_STAGE_PIXEL ? 0.0 : j->rec[st].z;
}

static void put_color(FILE *f, const pt_model *m)
{
    fprintf(f, "java.awt.Color[r=%d,g=%d,b=%d]\n", m->color[0], m->color[1], m->color[2]);
}

static void put_segment(FILE *f, const char *title, const pt_segment *sg)
{
    fprintf(f, "%s: LineSegment: ([%lu, %lu], [%lu, %lu])\n", title, (unsigned long)sg->a,
            (unsigned long)sg->b, (unsigned long)sg->a, (unsigned long)sg->b);
}

/* ===== the rasterizer's lines ===== */

/* "(NAME) = (%9.4f, %9.4f)" */
static void put_pair(FILE *f, const char *name, double a, double b)
{
    char s[PT_JNUM_LEN], t[PT_JNUM_LEN];

    pt_jnum_f(s, a, 9, 4, 0);
    pt_jnum_f(t, b, 9, 4, 0);
    fprintf(f, "(%s) = (%s, %s)\n", name, s, t);
}

/* One step's line.  xs, ys: the point as the course prints it ("%4d" for the
** stepped coordinate, "%9.4f" for the other). */
static void put_step(FILE *f, const pt_scene *s, const char *xs, const char *ys,
                     const pt_raster_step *st)
{
    char r[PT_JNUM_LEN], g[PT_JNUM_LEN], b[PT_JNUM_LEN];

    pt_jnum_f(r, (double)st->color[0], 0, 4, 0);
    pt_jnum_f(g, (double)st->color[1], 0, 4, 0);
    pt_jnum_f(b, (double)st->color[2], 0, 4, 0);
    fprintf(f, "%sfb_[w=%d,h=%d] vp_[x=%4d, y=%4d, w=%d,h=%d]  (x_pp=%s, y_pp=%s)  "
            "(x_vp=%4lld, y_vp=%4lld)  r=%s g=%s b=%s\n", st->inside ? "      " : "Clip: ",
            s->fb_w, s->fb_h, s->vp_x, s->vp_y, s->vp_w, s->vp_h, xs, ys,
            (long long)st->vp.x, (long long)st->vp.y, r, g, b);
}

/* The course's renderer can log segment seg of model m (setup su): its
** endpoints round to ints and it has at most PT_KRAFT_MAX_STEPS steps.
** Returns 0, or -1 with a message. */
static int seg_check(const pt_scene *s, const pt_model *m, uint64_t seg,
                     const pt_raster_setup *su, char *err, size_t errlen)
{
    int64_t n = su->s1 - su->s0;                     /* steps - 1 */

    if (su->kind == PT_RASTER_SKIPPED ||
        llabs(su->x0) > INT32_MAX || llabs(su->y0) > INT32_MAX ||
        llabs(su->x1) > INT32_MAX || llabs(su->y1) > INT32_MAX) {
        snprintf(err, errlen, "%s: error: model '%s', segment %llu: an endpoint is beyond "
                 "the int pixel range of the course's renderer (its log would not end)",
                 s->path, m->name, (unsigned long long)seg);
        return -1;
    }
    if (n >= PT_KRAFT_MAX_STEPS) {
        snprintf(err, errlen, "%s: error: model '%s', segment %llu: %lld steps, more than "
                 "the %ld lines a segment's pixel log may have", s->path, m->name,
                 (unsigned long long)seg, (long long)n + 1, PT_KRAFT_MAX_STEPS);
        return -1;
    }
    return 0;
}

/* The rasterizer's lines before the steps: the rounded endpoints and, unless
** the segment is one pixel, the slopes of position and colour and the ends'
** viewport pixels. */
static void put_setup(FILE *f, const pt_raster_setup *su)
{
    char one[PT_JNUM_LEN], two[PT_JNUM_LEN];
    static const char *const chan[3] = {"mRed", "mGrn", "mBlu"};
    int i;

    put_pair(f, "x0_pp, y0_pp", (double)su->x0, (double)su->y0);
    put_pair(f, "x1_pp, y1_pp", (double)su->x1, (double)su->y1);
    if (su->kind != PT_RASTER_DRAWN) return;
    pt_jnum_dtoa(one, su->m);
    if (!su->ymajor) {
        fprintf(f, "Slope m    = %s\n", one);
    } else {
        pt_jnum_dtoa(two, 1 / su->m);
        fprintf(f, "Slope m    = %s (so 1/m = %s)\n", one, two);
    }
    for (i = 0; i < 3; i++) {
        pt_jnum_dtoa(one, su->dc[i]);
        fprintf(f, "Slope %s = %s\n", chan[i], one);
    }
    put_pair(f, "x0_vp, y0_vp", (double)su->vp0.x, (double)su->vp0.y);
    put_pair(f, "x1_vp, y1_vp", (double)su->vp1.x, (double)su->vp1.y);
}

/* ===== the log ===== */

/* The lines of model m up to its segments' own: the translation, every
** vertex stage by stage (journeys js), the segments and the colours. */
static void put_model_head(FILE *f, const pt_model *m, const pt_journey *js)
{
    static const pt_stage logged[4] = {PT_STAGE_MODEL, PT_STAGE_CAMERA, PT_STAGE_IMAGE,
                                       PT_STAGE_PIXEL};
    const char *pixel_title = pt_stage_course[PT_STAGE_PIXEL];
    double x, y, z;
    size_t v, k;
    int q;

    fprintf(f, "==== Render position: %s ====\n", m->name);
    fputs("---- Translation vector = [x,y,z] = [", f);
    put_3(f, m->translate.x, m->translate.y, m->translate.z);
    fputs("]\n", f);
    fprintf(f, "====== Render model: %s ======\n", m->name);
    for (q = 0; q < 4; q++)
        for (v = 0; v < m->nv; v++) {
            stage_xyz(&js[v], logged[q], &x, &y, &z);
            fprintf(f, "%-14s: vIndex = %3zu, ", pt_stage_course[logged[q]], v);
            put_xyz(f, x, y, z);
            fputc('\n', f);
        }
    if (m->nseg == 0) fprintf(f, "%s: []\n", pixel_title);
    for (k = 0; k < m->nseg; k++) put_segment(f, pixel_title, &m->seg[k]);
    for (v = 0; v < m->nv; v++) {
        fprintf(f, "%s: cIndex = %3zu, ", pixel_title, v);
        put_color(f, m);
    }
}

/* "4. Rasterize" and the two ends of segment k of model m (journeys js). */
static void put_seg_head(FILE *f, const pt_model *m, const pt_journey *js, size_t k)
{
    const pt_segment *sg = &m->seg[k];
    uint32_t ends[2];
    double x, y, z;
    int e;

    ends[0] = sg->a; ends[1] = sg->b;
    put_segment(f, "4. Rasterize", sg);
    for (e = 0; e < 2; e++) {
        stage_xyz(&js[ends[e]], PT_STAGE_PIXEL, &x, &y, &z);
        fprintf(f, "   vIndex = %3lu, ", (unsigned long)ends[e]);
        put_xyz(f, x, y, z);
        fputc('\n', f);
    }
    for (e = 0; e < 2; e++) {
        fprintf(f, "   cIndex = %3lu, ", (unsigned long)ends[e]);
        put_color(f, m);
    }
}

/* The log of every model from one pt_run(), model by model
** (pt_options.model_by_model): the journeys of a model's vertices, then, with
** pixels, the DDA's records of its segments; a model's closing lines when the
** next model's records begin, or at the end. */
typedef struct kraft_run {
    FILE *f;
    const pt_scene *s;
    int pixels;                  /* 1: the rasterizer's lines too */
    size_t k;                    /* the model being logged */
    pt_journey *js;              /* js[v - 1]: its vertex v's journey */
    size_t cap;                  /* room in js */
    int head;                    /* 1: put_model_head() wrote its lines */
    int ymajor, degenerate;      /* of the segment being stepped */
    int failed;                  /* out of memory */
} kraft_run;

/* Close model kr->k: its head if no segment wrote it, the segments without
** pixels, its last lines. */
static void model_end(kraft_run *kr)
{
    const pt_model *m = &kr->s->models[kr->k];
    size_t q;

    if (!kr->head) put_model_head(kr->f, m, kr->js);       /* no segment drawn */
    for (q = 0; !kr->pixels && q < m->nseg; q++) put_seg_head(kr->f, m, kr->js, q);
    fprintf(kr->f, "====== End model: %s ======\n", m->name);
    fprintf(kr->f, "==== End position: %s ====\n", m->name);
}

/* Begin model k: close those before it, make room for its journeys. */
static void model_begin(kraft_run *kr, size_t k)
{
    const pt_model *m = &kr->s->models[k];
    size_t need = m->nv ? m->nv : 1;

    model_end(kr);
    kr->k = k;
    kr->head = 0;
    if (need > kr->cap) {
        pt_journey *js = realloc(kr->js, need * sizeof *js);
        if (!js) { kr->failed = 1; kr->cap = 0; free(kr->js); kr->js = NULL; return; }
        kr->js = js;
        kr->cap = need;
    }
    memset(kr->js, 0, need * sizeof *kr->js);
}

/* Bring the log to model m: every model before it is closed. */
static int kraft_at(kraft_run *kr, const pt_model *m)
{
    size_t k = (size_t)(m - kr->s->models);

    while (!kr->failed && kr->k < k) model_begin(kr, kr->k + 1);
    return !kr->failed;
}

static void on_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    kraft_run *kr = ud;

    if (kraft_at(kr, m) && v >= 1 && v <= m->nv) kr->js[v - 1] = *j;
}

static void on_setup(void *ud, const pt_model *m, uint64_t seg, const pt_raster_setup *su)
{
    kraft_run *kr = ud;

    if (!kraft_at(kr, m)) return;
    if (!kr->head) put_model_head(kr->f, m, kr->js);   /* every journey came first */
    kr->head = 1;
    put_seg_head(kr->f, m, kr->js, seg - 1);
    put_setup(kr->f, su);
    kr->ymajor = su->ymajor;
    kr->degenerate = su->kind == PT_RASTER_DEGENERATE;
}

static void on_step(void *ud, const pt_model *m, uint64_t seg, const pt_raster_step *st)
{
    kraft_run *kr = ud;
    char one[PT_JNUM_LEN], two[PT_JNUM_LEN];

    (void)seg;
    if (!kraft_at(kr, m)) return;
    if (kr->degenerate) {                            /* "%9.4f" both */
        pt_jnum_f(one, st->pp.x, 9, 4, 0);
        pt_jnum_f(two, st->pp.y, 9, 4, 0);
    } else if (!kr->ymajor) {
        snprintf(one, sizeof one, "%4lld", (long long)st->s);
        pt_jnum_f(two, st->a, 9, 4, 0);
    } else {
        pt_jnum_f(one, st->a, 9, 4, 0);
        snprintf(two, sizeof two, "%4lld", (long long)st->s);
    }
    put_step(kr->f, kr->s, one, two, st);
}

/* Log every model of s into f, from one run.  Returns 0, or -1 with a
** message. */
static int kraft_models(FILE *f, const pt_scene *s, int pixels, char *err, size_t errlen)
{
    kraft_run kr;
    pt_options o;
    pt_listener l;
    int rc;

    if (s->nmodels == 0) return 0;
    memset(&kr, 0, sizeof kr);
    kr.f = f; kr.s = s; kr.pixels = pixels;
    kr.cap = s->models[0].nv ? s->models[0].nv : 1;
    kr.js = calloc(kr.cap, sizeof *kr.js);
    pt_options_default(&o);
    o.every_vertex = 1;
    o.rasterize = pixels;
    o.trace_raster = pixels;
    o.model_by_model = 1;
    memset(&l, 0, sizeof l);
    l.journey = on_journey;
    if (pixels) { l.setup = on_setup; l.step = on_step; }
    l.ud = &kr;
    rc = kr.js ? pt_run_plain(s, &o, &l) : -1;
    if (rc == 0 && kraft_at(&kr, &s->models[s->nmodels - 1])) model_end(&kr);
    free(kr.js);
    if (rc != 0 || kr.failed) {
        snprintf(err, errlen, "pipetrace: out of memory");
        return -1;
    }
    return 0;
}

/* The first segment of the scene the course's renderer cannot log
** (seg_check), from the setup records of one pt_run(). */
typedef struct kraft_check {
    const pt_scene *s;
    char *err;
    size_t errlen;
    int rc;
} kraft_check;

static void check_setup(void *ud, const pt_model *m, uint64_t seg, const pt_raster_setup *su)
{
    kraft_check *kc = ud;

    if (kc->rc == 0) kc->rc = seg_check(kc->s, m, seg, su, kc->err, kc->errlen);
}

/* Check every segment of s as seg_check() does.  Returns 0, or -1 with a
** message. */
static int scene_check(const pt_scene *s, char *err, size_t errlen)
{
    kraft_check kc;
    pt_options o;
    pt_listener l;

    kc.s = s; kc.err = err; kc.errlen = errlen; kc.rc = 0;
    pt_options_default(&o);
    memset(&l, 0, sizeof l);
    l.setup = check_setup;       /* the setups alone: the walk skips, as ever */
    l.ud = &kc;
    if (pt_run_plain(s, &o, &l) != 0) {
        snprintf(err, errlen, "pipetrace: out of memory");
        return -1;
    }
    return kc.rc;
}

int pt_kraft_write(FILE *f, const pt_scene *s, int pixels, char *err, size_t errlen)
{
    if (pt_scene_pipeline(s) != &pt_pipe_classic) {
        snprintf(err, errlen, "%s: error: the course's renderer has no %s "
                 "('camera %s'), so there is no log of it to write: use --format "
                 "text, jsonl or csv", s->path, pt_scene_pipeline(s)->title,
                 pt_scene_camera_word(s));
        return -1;
    }
    if (pixels && scene_check(s, err, errlen) != 0) return -1;   /* nothing written */
    fputs("\n== Begin Rendering of Scene:  ==\n-- Current Camera:\nCamera: \n", f);
    fprintf(f, "perspective = %s\n", s->perspective ? "true" : "false");
    if (kraft_models(f, s, pixels, err, errlen) != 0) return -1;
    fputs("== End Rendering of Scene ==\n", f);
    return 0;
}
