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
** A viewport that sticks out of the framebuffer adds the framebuffer's own
** line "FrameBuffer: Bad pixel coordinate (x_fb, y_fb) [w=W, h=H]" for each
** pixel written whose index y_fb*W + x_fb lies outside the pixel array
** (pt_raster_fb_pixel), whatever the debug switches: first those of the
** viewport's clearing, then each after its pixel's line (or where it would
** be: after its primitive's "4. Rasterize" lines).
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/jnum.h"
#include "io/trace_kraft.h"
#include "io/rv_log_raster.h"

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

/* "java.awt.Color[r=R,g=G,b=B]": Color.toString of colour ci of model m,
** the bytes java.awt.Color keeps of its floats. */
static void put_color(FILE *f, const pt_model *m, uint32_t ci)
{
    fprintf(f, "java.awt.Color[r=%d,g=%d,b=%d]\n", pt_color_byte(pt_model_color(m, ci, 0)),
            pt_color_byte(pt_model_color(m, ci, 1)), pt_color_byte(pt_model_color(m, ci, 2)));
}

static void put_segment(FILE *f, const char *title, const pt_segment *sg)
{
    fprintf(f, "%s: LineSegment: ([%lu, %lu], [%lu, %lu])\n", title, (unsigned long)sg->a,
            (unsigned long)sg->b, (unsigned long)sg->ca, (unsigned long)sg->cb);
}

static void put_point(FILE *f, const char *title, const pt_point *pt)
{
    fprintf(f, "%s: Point: ([%lu], [%lu]) radius = %d\n", title, (unsigned long)pt->v,
            (unsigned long)pt->c, pt->radius);
}

/* The length of model m's colour list as the course has it before it adds
** its default: `vcolor` lines, or one `color` a vertex, or none. */
static size_t ncolors_given(const pt_model *m)
{
    if (m->ncolors) return m->ncolors;
    return m->colors_given ? m->nv : 0;
}

/* The warnings the course prints whatever its debug switches
** (CheckModel.check, then the default colours), with Model.toString when a
** check fails. */
static void put_warnings(FILE *f, const pt_model *m, const pt_journey *js)
{
    size_t nprim = m->nseg + m->npts, ncol = ncolors_given(m), i, k, q;
    int error = 0;

    if (m->nv == 0 && nprim > 0) {
        fputs("***WARNING: This model does not have any vertices.\n", f);
        error = 1;
    }
    if (m->nv > 0 && nprim == 0) {
        fputs("***WARNING: This model does not have any geometric primitives.\n", f);
        error = 1;
    }
    if (m->nv > 0 && ncol == 0) fputs("***WARNING: This model does not have any colors.\n", f);
    if (error) {
        fprintf(f, "Model: %s\nThis Model's visibility is: true\nModel has %zu vertices.\n"
                "Model has %zu colors.\nModel has %zu primitives.\n", m->name, m->nv, ncol,
                nprim);
        for (i = 0; i < m->nv; i++) {
            fprintf(f, "%zu: ", i);
            put_xyz(f, js[i].rec[PT_STAGE_MODEL].x, js[i].rec[PT_STAGE_MODEL].y,
                    js[i].rec[PT_STAGE_MODEL].z);
            fputc('\n', f);
        }
        for (i = 0; i < ncol; i++) {
            fprintf(f, "%zu: ", i);
            put_color(f, m, (uint32_t)i);
        }
        for (i = 0, k = 0, q = 0; k < m->nseg || q < m->npts; i++) {
            char num[32];
            snprintf(num, sizeof num, "%zu", i);
            if (q < m->npts && m->pts[q].after <= k) put_point(f, num, &m->pts[q++]);
            else put_segment(f, num, &m->seg[k++]);
        }
        fputc('\n', f);
    }
    if (m->nv > 0 && ncol == 0)
        fprintf(f, "***WARNING: Added default color to model: %s.\n", m->name);
}

/* ===== the rasterizer's lines ===== */

/* The start of a pixel line: "Clip: " or six blanks, the framebuffer and
** viewport, the point (xs, ys as the course prints them: "%4d" for a whole
** coordinate, "%9.4f" for the other). */
static void put_where(FILE *f, const pt_scene *s, int inside, const char *xs,
                      const char *ys)
{
    fprintf(f, "%sfb_[w=%d,h=%d] vp_[x=%4d, y=%4d, w=%d,h=%d]  (x_pp=%s, y_pp=%s)  ",
            inside ? "      " : "Clip: ", s->fb_w, s->fb_h, s->vp_x, s->vp_y, s->vp_w,
            s->vp_h, xs, ys);
}

static void put_rgb(FILE *f, const float c[3])
{
    pt_klog_rgb(f, c[0], c[1], c[2]);
}

/* One step's line (logPixel), or with anti-aliasing its pair's
** (logPixelsAA: "Clip: " unless both are inside). */
static void put_step(FILE *f, const pt_scene *s, const char *xs, const char *ys,
                     int ymajor, const pt_raster_step *st)
{
    if (!st->aa) {
        put_where(f, s, st->inside, xs, ys);
        fprintf(f, "(x_vp=%4lld, y_vp=%4lld)  ", (long long)st->vp.x, (long long)st->vp.y);
        put_rgb(f, st->color);
        fputc('\n', f);
        return;
    }
    put_where(f, s, st->inside && st->inside_hi, xs, ys);
    if (!ymajor)
        fprintf(f, "x_vp=%4lld {y_low=%4lld ", (long long)st->vp.x, (long long)st->vp.y);
    else
        fprintf(f, "y_vp=%4lld {x_low=%4lld ", (long long)st->vp.y, (long long)st->vp.x);
    put_rgb(f, st->color);
    fprintf(f, "} {%s =%4lld ", ymajor ? "x_hi" : "y_hi",
            (long long)(ymajor ? st->vp_hi.x : st->vp_hi.y));
    put_rgb(f, st->color_hi);
    fputs("}\n", f);
}

/* The rasterizer's lines before the steps: the rounded endpoints and, unless
** the segment is one pixel, the slopes of position and colour and the ends'
** viewport pixels. */
static void put_setup(FILE *f, const pt_raster_setup *su)
{
    pt_klog_pair(f, "x0_pp, y0_pp", (double)su->x0, (double)su->y0);
    pt_klog_pair(f, "x1_pp, y1_pp", (double)su->x1, (double)su->y1);
    if (su->kind != PT_RASTER_DRAWN) return;
    pt_klog_slopes(f, su->m, su->ymajor ? "so" : NULL, su->dc, (double)su->vp0.x,
                   (double)su->vp0.y, (double)su->vp1.x, (double)su->vp1.y);
}

/* ===== the log ===== */

/* The log of every model from one pt_run(), model by model
** (pt_options.model_by_model): the journeys of a model's vertices, then, with
** pixels, the DDA's records of its segments; a model's closing lines when the
** next model's records begin, or at the end.  Its points are logged here
** (pt_raster_point), each before the segment that follows it in the file. */
typedef struct kraft_run {
    FILE *f;
    const pt_scene *s;
    int lines;                   /* 1: the log's lines (scene or position
                                 ** debug); 0: the warnings and Bad pixel
                                 ** lines alone */
    int pixels;                  /* 1: the rasterizer's lines too */
    int wrap;                    /* 1: the viewport sticks out of the
                                 ** framebuffer: Bad pixel lines can come */
    size_t k;                    /* the model being logged */
    pt_journey *js;              /* js[v - 1]: its vertex v's journey */
    size_t cap;                  /* room in js */
    int head;                    /* 1: put_model_head() wrote its lines */
    size_t next_pt;              /* its points logged so far */
    size_t next_seg;             /* its segments whose "4. Rasterize" lines
                                 ** are written */
    int ymajor, degenerate;      /* of the segment being stepped */
    int failed;                  /* out of memory */
} kraft_run;

/* The Position's name of model m (`model NAME POSITION`). */
static const char *position_of(const pt_model *m)
{
    return m->position ? m->position : m->name;
}

/* The lines of model m up to its segments' own: the position and its
** translation, the model, the course's warnings, every vertex stage by
** stage (journeys js), the primitives in file order and the colours.  A
** hidden model: its position's lines and the hidden line. */
static void put_model_head(FILE *f, const pt_model *m, const pt_journey *js, int lines)
{
    static const pt_stage logged[4] = {PT_STAGE_MODEL, PT_STAGE_CAMERA, PT_STAGE_IMAGE,
                                       PT_STAGE_PIXEL};
    const char *pixel_title = pt_stage_course[PT_STAGE_PIXEL];
    double x, y, z;
    size_t v, k, q, nc;
    int i;

    if (!lines) {                       /* the warnings alone */
        if (!m->hidden_model) put_warnings(f, m, js);
        return;
    }
    fprintf(f, "==== Render position: %s ====\n", position_of(m));
    fputs("---- Translation vector = [x,y,z] = [", f);
    put_3(f, m->translate.x, m->translate.y, m->translate.z);
    fputs("]\n", f);
    if (m->hidden_model) {
        fprintf(f, "====== Hidden model: %s ======\n", m->name);
        return;
    }
    fprintf(f, "====== Render model: %s ======\n", m->name);
    put_warnings(f, m, js);
    for (i = 0; i < 4; i++)
        for (v = 0; v < m->nv; v++) {
            stage_xyz(&js[v], logged[i], &x, &y, &z);
            fprintf(f, "%-14s: vIndex = %3zu, ", pt_stage_course[logged[i]], v);
            put_xyz(f, x, y, z);
            fputc('\n', f);
        }
    if (m->nseg == 0 && m->npts == 0) fprintf(f, "%s: []\n", pixel_title);
    for (k = 0, q = 0; k < m->nseg || q < m->npts; )
        if (q < m->npts && m->pts[q].after <= k) put_point(f, pixel_title, &m->pts[q++]);
        else put_segment(f, pixel_title, &m->seg[k++]);
    nc = m->ncolors ? m->ncolors : m->nv;           /* the default: one a vertex */
    for (v = 0; v < nc; v++) {
        fprintf(f, "%s: cIndex = %3zu, ", pixel_title, v);
        put_color(f, m, (uint32_t)v);
    }
}

/* The "   vIndex = ..." line of vertex v in the pixel plane (journeys js) and
** the "   cIndex = ..." line of colour c. */
static void put_end(FILE *f, const pt_journey *js, uint32_t v)
{
    double x, y, z;

    stage_xyz(&js[v], PT_STAGE_PIXEL, &x, &y, &z);
    fprintf(f, "   vIndex = %3lu, ", (unsigned long)v);
    put_xyz(f, x, y, z);
    fputc('\n', f);
}

static void put_cend(FILE *f, const pt_model *m, uint32_t c)
{
    fprintf(f, "   cIndex = %3lu, ", (unsigned long)c);
    put_color(f, m, c);
}

/* "4. Rasterize" and the two ends of segment k of model m (journeys js). */
static void put_seg_head(FILE *f, const pt_model *m, const pt_journey *js, size_t k)
{
    const pt_segment *sg = &m->seg[k];

    put_segment(f, "4. Rasterize", sg);
    put_end(f, js, sg->a);
    put_end(f, js, sg->b);
    put_cend(f, m, sg->ca);
    put_cend(f, m, sg->cb);
}

/* A pixel line of a point (logPixel with the rounded centre). */
typedef struct dot_log {
    FILE *f;
    const pt_scene *s;
    int pixels;                  /* 1: its pixel lines (else the Bad pixel
                                 ** lines alone) */
    int wrap;                    /* 1: the viewport sticks out (kraft_run) */
    float c[3];                  /* its colour, gamma-encoded when on */
} dot_log;

/* After the line of a pixel written at viewport pixel (x_vp, y_vp): the
** framebuffer's Bad pixel line when the course's index of it lies outside
** the pixel array. */
static void put_bad(FILE *f, const pt_scene *s, int64_t x_vp, int64_t y_vp)
{
    pt_fb_pixel px;

    if (pt_raster_fb_pixel(x_vp, y_vp, s->vp_x, s->vp_y, s->fb_w, s->fb_h, 1, &px) < 0)
        pt_klog_bad(f, (long long)px.x_fb, (long long)px.y_fb, s->fb_w, s->fb_h);
}

static void on_dot(void *ud, const pt_raster_dot *dt)
{
    dot_log *dl = ud;
    char one[PT_JNUM_LEN], two[PT_JNUM_LEN];

    if (dl->pixels) {
        pt_jnum_f(one, (double)dt->cx, 9, 4, 0);
        pt_jnum_f(two, (double)dt->cy, 9, 4, 0);
        put_where(dl->f, dl->s, dt->inside, one, two);
        fprintf(dl->f, "(x_vp=%4lld, y_vp=%4lld)  ", (long long)dt->vp.x,
                (long long)dt->vp.y);
        put_rgb(dl->f, dl->c);
        fputc('\n', dl->f);
    }
    if (dl->wrap && dt->inside) put_bad(dl->f, dl->s, dt->vp.x, dt->vp.y);
}

/* "4. Rasterize" of point q of model m, and with pixels its rasterizer's
** lines: the twice-mapped centre, then every pixel (NOTES.md 11.3). */
static void put_point_log(const kraft_run *kr, const pt_model *m, size_t q)
{
    const pt_point *pt = &m->pts[q];
    const pt_scene *s = kr->s;
    pt_raster_dot dt;
    dot_log dl;
    pt_vec2 pp;
    int i;

    if (kr->lines) {
        put_point(kr->f, "4. Rasterize", pt);
        put_end(kr->f, kr->js, pt->v);
        put_cend(kr->f, m, pt->c);
    }
    if (!kr->pixels && !kr->wrap) return;
    dl.f = kr->f;
    dl.s = s;
    dl.pixels = kr->pixels;
    dl.wrap = kr->wrap;
    for (i = 0; i < 3; i++) {
        float c = pt_model_color(m, pt->c, i);
        dl.c[i] = s->gamma ? pt_gamma(c) : c;
    }
    pp.x = kr->js[pt->v].rec[PT_STAGE_PIXEL].x;
    pp.y = kr->js[pt->v].rec[PT_STAGE_PIXEL].y;
    if (!kr->pixels) {                  /* the Bad pixel lines of those inside */
        pt_raster_point(pp, pt->radius, s->vp_w, s->vp_h, 0, 0, &dt, on_dot, &dl);
        return;
    }
    if (pt_raster_point(pp, -1, s->vp_w, s->vp_h, 1, 0, &dt, on_dot, &dl) < 0) return;
    pt_klog_pair(kr->f, "x_pp, y_pp", dt.x_pp, dt.y_pp);
    pt_raster_point(pp, pt->radius, s->vp_w, s->vp_h, 1, PT_KRAFT_MAX_STEPS, &dt, on_dot,
                    &dl);
}

/* Log the points of model kr->k up to those after the first upto segments. */
static void points_upto(kraft_run *kr, size_t upto)
{
    const pt_model *m = &kr->s->models[kr->k];

    for (; kr->next_pt < m->npts && m->pts[kr->next_pt].after <= upto; kr->next_pt++)
        put_point_log(kr, m, kr->next_pt);
}

/* Without the rasterizer's lines: the "4. Rasterize" lines of model kr->k's
** segments up to the first n, each after the points before it. */
static void seg_heads_upto(kraft_run *kr, size_t n)
{
    const pt_model *m = &kr->s->models[kr->k];

    for (; kr->next_seg < n; kr->next_seg++) {
        points_upto(kr, kr->next_seg);
        if (kr->lines) put_seg_head(kr->f, m, kr->js, kr->next_seg);
    }
}

/* Close model kr->k: its head if no segment wrote it, the primitives not yet
** logged, its last lines; a hidden position's one line. */
static void model_end(kraft_run *kr)
{
    const pt_model *m = &kr->s->models[kr->k];

    if (m->hidden_position) {
        if (kr->lines) fprintf(kr->f, "==== Hidden position: %s ====\n", position_of(m));
        return;
    }
    if (!kr->head) put_model_head(kr->f, m, kr->js, kr->lines);   /* no segment drawn */
    if (!m->hidden_model) {
        if (!kr->pixels) seg_heads_upto(kr, m->nseg);
        points_upto(kr, m->nseg);
        if (kr->lines) fprintf(kr->f, "====== End model: %s ======\n", m->name);
    }
    if (kr->lines) fprintf(kr->f, "==== End position: %s ====\n", position_of(m));
}

/* Begin model k: close those before it, make room for its journeys. */
static void model_begin(kraft_run *kr, size_t k)
{
    const pt_model *m = &kr->s->models[k];
    size_t need = m->nv ? m->nv : 1;

    model_end(kr);
    kr->k = k;
    kr->head = 0;
    kr->next_pt = 0;
    kr->next_seg = 0;
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
    if (!kr->head) put_model_head(kr->f, m, kr->js, 1);   /* every journey came first */
    kr->head = 1;
    points_upto(kr, seg - 1);
    put_seg_head(kr->f, m, kr->js, seg - 1);
    kr->next_seg = seg;
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
    put_step(kr->f, kr->s, one, two, kr->ymajor, st);
}

/* The pixels of segment seg drawn (the viewport sticks out): a Bad pixel
** line for each whose index lies outside the pixel array, after its step's
** line, or without the rasterizer's lines after the segment's "4. Rasterize"
** lines (those before it written first). */
static void on_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                      size_t n)
{
    kraft_run *kr = ud;
    size_t i;

    if (!kraft_at(kr, m)) return;
    if (!kr->pixels) {
        if (!kr->head) put_model_head(kr->f, m, kr->js, kr->lines);
        kr->head = 1;
        seg_heads_upto(kr, (size_t)seg);
    }
    for (i = 0; i < n; i++)
        if (px[i].idx < 0)
            pt_klog_bad(kr->f, (long long)px[i].x_fb, (long long)px[i].y_fb, kr->s->fb_w,
                        kr->s->fb_h);
}

/* Log every model of s into f, from one run.  Returns 0, or -1 with a
** message. */
static int kraft_models(FILE *f, const pt_scene *s, int lines, int pixels, char *err,
                        size_t errlen)
{
    kraft_run kr;
    pt_options o;
    pt_listener l;
    int rc;

    if (s->nmodels == 0) return 0;
    memset(&kr, 0, sizeof kr);
    kr.f = f; kr.s = s; kr.lines = lines; kr.pixels = pixels;
    kr.wrap = !pt_scene_vp_inside(s);
    kr.cap = s->models[0].nv ? s->models[0].nv : 1;
    kr.js = calloc(kr.cap, sizeof *kr.js);
    pt_options_default(&o);
    o.every_vertex = 1;
    o.rasterize = pixels || kr.wrap;
    o.trace_raster = pixels || kr.wrap;
    o.model_by_model = 1;
    memset(&l, 0, sizeof l);
    l.journey = on_journey;
    if (pixels) { l.setup = on_setup; l.step = on_step; }
    if (kr.wrap) l.pixels = on_pixels;
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

/* The course's unconditional lines alone (its debug switches scene and
** position off): each shown model's warnings. */
static int kraft_warnings(FILE *f, const pt_scene *s, char *err, size_t errlen)
{
    size_t k;

    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        pt_journey *js;

        if (m->hidden_position || m->hidden_model) continue;
        js = pt_run_journeys(s, m, 0);
        if (!js) {
            snprintf(err, errlen, "pipetrace: out of memory");
            return -1;
        }
        put_warnings(f, m, js);
        free(js);
    }
    return 0;
}

/* The Bad pixel lines of the viewport's clearing (Viewport.clearVP: every
** pixel of the viewport, row by row, through setPixelVP), which the course's
** program does before it renders. */
static void clear_bad(FILE *f, const pt_scene *s)
{
    int x, y;

    for (y = 0; y < s->vp_h; y++)
        for (x = 0; x < s->vp_w; x++) put_bad(f, s, x, y);
}

int pt_kraft_write(FILE *f, const pt_scene *s, unsigned dbg, char *err, size_t errlen)
{
    int shown = (dbg & (PT_KDBG_SCENE | PT_KDBG_POSITION)) != 0;   /* logMessage's test */
    int pixels = shown && (dbg & PT_KDBG_RASTERIZE);

    if (pt_scene_pipeline(s) != &pt_pipe_classic) {
        snprintf(err, errlen, "%s: error: the course's renderer has no %s "
                 "('camera %s'), so there is no log of it to write: use --format "
                 "text, jsonl or csv", s->path, pt_scene_pipeline(s)->title,
                 pt_scene_camera_word(s));
        return -1;
    }
    if (pixels && pt_kraft_check(s, err, errlen) != 0) return -1;   /* nothing written */
    if (!pt_scene_vp_inside(s)) {       /* vp.clearVP() before the render */
        clear_bad(f, s);
        if (!shown) return kraft_models(f, s, 0, 0, err, errlen);
    }
    if (!shown) return kraft_warnings(f, s, err, errlen);
    if (dbg & PT_KDBG_SCENE) {   /* debugPosition is still false: the scene's alone */
        fprintf(f, "\n== Begin Rendering of Scene: %s ==\n-- Current Camera:\nCamera: \n",
                s->scene_name ? s->scene_name : "");
        fprintf(f, "perspective = %s\n", s->perspective ? "true" : "false");
    }
    if (kraft_models(f, s, 1, pixels, err, errlen) != 0) return -1;
    if ((dbg & PT_KDBG_SCENE) || s->nmodels > 0)    /* the last position's flag */
        fputs("== End Rendering of Scene ==\n", f);
    return 0;
}

