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
** takes it.  tests/kraft.sh ties the two: the pixels of the log are the
** pixels pt_run() draws, for every reference scene.
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/jnum.h"
#include "io/trace_kraft.h"

/* The colour the course's renderer gives every vertex of m, as floats 0..1
** (java.awt.Color.getRGBComponents: c / 255f). */
static void color_floats(const pt_model *m, float rgb[3])
{
    int k;
    for (k = 0; k < 3; k++) rgb[k] = (float)m->color[k] / 255.0f;
}

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

/* "(NAME) = (%9.4f, %9.4f)" for the viewport pixel of the rounded endpoint
** (x, y), from the viewport stage (pt_pixel2viewport): the course prints
** x_vp = x - 1 and y_vp = h - y as doubles.  x and y are whole numbers within
** the int range (seg_check), so the stage gives a pixel and its doubles are
** exact. */
static void put_vp_pair(FILE *f, const pt_scene *s, const char *name, double x, double y)
{
    pt_pix vp = pt_pixel2viewport((pt_vec2){x, y}, s->vp_w, s->vp_h, NULL);

    put_pair(f, name, (double)vp.x, (double)vp.y);
}

/* One step's line.  xs, ys: the point as the course prints it ("%4d" for the
** stepped coordinate, "%9.4f" for the other); rgb the colour written. */
static void put_pixel(FILE *f, const pt_scene *s, const char *xs, const char *ys,
                      pt_pix vp, const double rgb[3])
{
    char r[PT_JNUM_LEN], g[PT_JNUM_LEN], b[PT_JNUM_LEN];
    int in = vp.ok && pt_inside(vp.x, vp.y, s->vp_w, s->vp_h);

    pt_jnum_f(r, rgb[0], 0, 4, 0);
    pt_jnum_f(g, rgb[1], 0, 4, 0);
    pt_jnum_f(b, rgb[2], 0, 4, 0);
    fprintf(f, "%sfb_[w=%d,h=%d] vp_[x=%4d, y=%4d, w=%d,h=%d]  (x_pp=%s, y_pp=%s)  "
            "(x_vp=%4lld, y_vp=%4lld)  r=%s g=%s b=%s\n", in ? "      " : "Clip: ",
            s->fb_w, s->fb_h, s->vp_x, s->vp_y, s->vp_w, s->vp_h, xs, ys,
            (long long)vp.x, (long long)vp.y, r, g, b);
}

/* The course's gamma (2.2) on a colour channel, in its float arithmetic. */
static double gamma_of(float c)
{
    return (double)(float)pow((double)c, 0.45454545454545453);
}

/* Check that the course's renderer can log segment k of model m, from
** pixel-plane point a to b: its endpoints round to ints (r[4]: x0 y0 x1 y1)
** and it has at most PT_KRAFT_MAX_STEPS steps.  Returns 0, or -1 with a
** message. */
static int seg_check(const pt_scene *s, const pt_model *m, size_t k, pt_vec2 a,
                     pt_vec2 b, int64_t r[4], char *err, size_t errlen)
{
    int64_t dx, dy;

    if (!pt_pix_round(a.x, &r[0]) || !pt_pix_round(a.y, &r[1]) ||
        !pt_pix_round(b.x, &r[2]) || !pt_pix_round(b.y, &r[3]) ||
        llabs(r[0]) > INT32_MAX || llabs(r[1]) > INT32_MAX ||
        llabs(r[2]) > INT32_MAX || llabs(r[3]) > INT32_MAX) {
        snprintf(err, errlen, "%s: error: model '%s', segment %zu: an endpoint is beyond "
                 "the int pixel range of the course's renderer (its log would not end)",
                 s->path, m->name, k + 1);
        return -1;
    }
    dx = llabs(r[2] - r[0]);
    dy = llabs(r[3] - r[1]);
    if ((dx > dy ? dx : dy) >= PT_KRAFT_MAX_STEPS) {
        snprintf(err, errlen, "%s: error: model '%s', segment %zu: %lld steps, more than "
                 "the %ld lines a segment's pixel log may have", s->path, m->name, k + 1,
                 (long long)(dx > dy ? dx : dy) + 1, PT_KRAFT_MAX_STEPS);
        return -1;
    }
    return 0;
}

/* The DDA's lines for the segment from pixel-plane point a to b, colours
** ca and cb; r: its endpoints rounded (seg_check).  This function can't fail. */
static void kraft_segment(FILE *f, const pt_scene *s, const int64_t r[4],
                          const float ca[3], const float cb[3])
{
    double x0, y0, x1, y1, sl, acc, rgb[3], dc[3];
    float c0[3], c1[3];
    int steep, i;
    int64_t st, s0, s1;
    char one[PT_JNUM_LEN], two[PT_JNUM_LEN];
    static const char *const chan[3] = {"mRed", "mGrn", "mBlu"};

    x0 = (double)r[0]; y0 = (double)r[1];            /* Math.round, kept as doubles */
    x1 = (double)r[2]; y1 = (double)r[3];
    put_pair(f, "x0_pp, y0_pp", x0, y0);
    put_pair(f, "x1_pp, y1_pp", x1, y1);
    memcpy(c0, ca, sizeof c0);
    memcpy(c1, cb, sizeof c1);
    if (x0 == x1 && y0 == y1) {                      /* one pixel, no gamma */
        pt_pix vp = pt_pixel2viewport((pt_vec2){x0, y0}, s->vp_w, s->vp_h, NULL);
        for (i = 0; i < 3; i++) rgb[i] = (double)c0[i];
        pt_jnum_f(one, x0, 9, 4, 0);
        pt_jnum_f(two, y0, 9, 4, 0);
        put_pixel(f, s, one, two, vp, rgb);
        return;
    }
    steep = fabs(y1 - y0) > fabs(x1 - x0);
    if (steep ? y1 < y0 : x1 < x0) {                 /* step toward increasing s */
        double t;
        t = x0; x0 = x1; x1 = t;
        t = y0; y0 = y1; y1 = t;
        memcpy(c0, cb, sizeof c0);
        memcpy(c1, ca, sizeof c1);
    }
    if (!steep) { s0 = (int64_t)x0; s1 = (int64_t)x1; }
    else        { s0 = (int64_t)y0; s1 = (int64_t)y1; }
    if (!steep) {
        sl = (y1 - y0) / (x1 - x0);                  /* m = dy / dx */
        pt_jnum_dtoa(one, sl);
        fprintf(f, "Slope m    = %s\n", one);
    } else {
        sl = (x1 - x0) / (y1 - y0);                  /* m = dx / dy */
        pt_jnum_dtoa(one, sl);
        pt_jnum_dtoa(two, 1 / sl);
        fprintf(f, "Slope m    = %s (so 1/m = %s)\n", one, two);
    }
    for (i = 0; i < 3; i++) {                        /* colour slopes */
        dc[i] = (double)(c1[i] - c0[i]) / (steep ? y1 - y0 : x1 - x0);
        pt_jnum_dtoa(one, dc[i]);
        fprintf(f, "Slope %s = %s\n", chan[i], one);
    }
    put_vp_pair(f, s, "x0_vp, y0_vp", x0, y0);
    put_vp_pair(f, s, "x1_vp, y1_vp", x1, y1);
    acc = steep ? x0 : y0;
    for (st = s0; st <= s1; st++) {
        pt_vec2 p;
        pt_pix vp;
        double from = steep ? y0 : x0;

        for (i = 0; i < 3; i++) {                    /* colour, then gamma */
            float c = (float)fabs((double)c0[i] + dc[i] * ((double)st - from));
            rgb[i] = gamma_of(c);
        }
        if (!steep) { p.x = (double)st; p.y = acc; }
        else        { p.x = acc; p.y = (double)st; }
        vp = pt_pixel2viewport(p, s->vp_w, s->vp_h, NULL);
        if (!steep) {
            snprintf(one, sizeof one, "%4lld", (long long)st);
            pt_jnum_f(two, acc, 9, 4, 0);
        } else {
            pt_jnum_f(one, acc, 9, 4, 0);
            snprintf(two, sizeof two, "%4lld", (long long)st);
        }
        put_pixel(f, s, one, two, vp, rgb);
        acc += sl;                                   /* y += m (x += m) */
    }
}

/* ===== the log ===== */

/* The pixel-plane points of segment sg's two ends, from the journeys js. */
static void seg_ends(const pt_journey *js, const pt_segment *sg, pt_vec2 pp[2])
{
    pp[0].x = js[sg->a].rec[PT_STAGE_PIXEL].x;
    pp[0].y = js[sg->a].rec[PT_STAGE_PIXEL].y;
    pp[1].x = js[sg->b].rec[PT_STAGE_PIXEL].x;
    pp[1].y = js[sg->b].rec[PT_STAGE_PIXEL].y;
}

/* Check every segment of m as seg_check() does.  Returns 0, or -1 with a
** message. */
static int model_check(const pt_scene *s, const pt_model *m, char *err, size_t errlen)
{
    pt_journey *js = pt_run_journeys(s, m, 0);
    size_t k;
    int rc = 0;

    if (!js) { snprintf(err, errlen, "pipetrace: out of memory"); return -1; }
    for (k = 0; k < m->nseg && rc == 0; k++) {
        pt_vec2 pp[2];
        int64_t r[4];

        seg_ends(js, &m->seg[k], pp);
        rc = seg_check(s, m, k, pp[0], pp[1], r, err, errlen);
    }
    free(js);
    return rc;
}

static int kraft_model(FILE *f, const pt_scene *s, const pt_model *m, int pixels,
                       char *err, size_t errlen)
{
    static const pt_stage logged[4] = {PT_STAGE_MODEL, PT_STAGE_CAMERA, PT_STAGE_IMAGE,
                                       PT_STAGE_PIXEL};
    const char *pixel_title = pt_stage_course[PT_STAGE_PIXEL];
    pt_journey *js = pt_run_journeys(s, m, 0);
    double x, y, z;
    float rgb[3];
    size_t v, k;
    int q;

    if (!js) { snprintf(err, errlen, "pipetrace: out of memory"); return -1; }
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
    color_floats(m, rgb);
    for (k = 0; k < m->nseg; k++) {
        const pt_segment *sg = &m->seg[k];
        uint32_t ends[2];
        pt_vec2 pp[2];
        int64_t r[4];
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
        seg_ends(js, sg, pp);
        if (pixels && seg_check(s, m, k, pp[0], pp[1], r, err, errlen) == 0)
            kraft_segment(f, s, r, rgb, rgb);
        else if (pixels) {                /* model_check() saw it first */
            free(js);
            return -1;
        }
    }
    fprintf(f, "====== End model: %s ======\n", m->name);
    fprintf(f, "==== End position: %s ====\n", m->name);
    free(js);
    return 0;
}

int pt_kraft_write(FILE *f, const pt_scene *s, int pixels, char *err, size_t errlen)
{
    size_t k;

    if (pt_scene_pipeline(s) != &pt_pipe_classic) {
        snprintf(err, errlen, "%s: error: the course's renderer has no %s "
                 "('camera %s'), so there is no log of it to write: use --format "
                 "text, jsonl or csv", s->path, pt_scene_pipeline(s)->title,
                 pt_scene_camera_word(s));
        return -1;
    }
    for (k = 0; pixels && k < s->nmodels; k++)   /* nothing written on error */
        if (model_check(s, &s->models[k], err, errlen) != 0) return -1;
    fputs("\n== Begin Rendering of Scene:  ==\n-- Current Camera:\nCamera: \n", f);
    fprintf(f, "perspective = %s\n", s->perspective ? "true" : "false");
    for (k = 0; k < s->nmodels; k++)
        if (kraft_model(f, s, &s->models[k], pixels, err, errlen) != 0) return -1;
    fputs("== End Rendering of Scene ==\n", f);
    return 0;
}
