/*
** src/io/trace_course.c -- the course's debug log of renderers 7 and 9 (--format kraft)
** See LICENSE for copyright and license.
**
** A listener of the driver (core/course.h): each callback prints the lines
** the course's Java prints at that point, gated as PipelineLogger gates them
** (debugScene || debugPosition, the latter set per position and kept after
** the loop).  The labels are the course's, padded as it pads them.
*/
#include <stdio.h>
#include <string.h>
#include "io/trace_course.h"
#include "io/trace_kraft.h"
#include "io/jnum.h"
#include "io/rv_log_raster.h"

/* A stage's labels per driver: r7, r9 Pipeline, r9 Pipeline2; and which
** lists it prints (V vertices, C colours, P primitives). */
#define LV 1
#define LC 2
#define LP 4
#define PI 3.141592653589793         /* Math.PI */
static const struct {
    const char *lab[3];
    int lists;
} stage_labs[PT_NCST] = {
    {{"0. Model       ", "0. Model        ", "0. Model    "}, LV},
    {{"", "1. World        ", "1. World     "}, LV},
    {{"1. View        ", "2. View         ", "2. View   "}, LV},
    {{"2. Camera      ", "3. Camera       ", "3. Camera   "}, LV | LC | LP},
    {{"3. Near_Clipped", "4. Near_Clipped", "4.  Near_Clipped  "}, LV | LC | LP},
    {{"4. Projected   ", "5. Projected   ", "5. Projected"}, LV},
    {{"5. Clipped     ", "6. Clipped     ", "6. Clipped  "}, LV | LC | LP},
};

/* Pipeline2's phases: what each does, and its per-model line's verb. */
static const char *const phase_what[8] = {
    "", "model-to-world transformation", "world-to-view transformation",
    "view-to-camera transformation", "near-plane clipping", "projection transformation",
    "clipping", "rasterization"};
static const char *const phase_verb[8] = {
    "", "", "Transform model", "Transform model", "Near_Clip model", "Project model",
    "Clip model", "Rasterize model"};

typedef struct clog {
    FILE *f;
    const pt_scene *s;
    unsigned dbg;
    int drv;                     /* 0 r7, 1 r9 Pipeline, 2 r9 Pipeline2 */
    int debug_position;          /* PipelineLogger.debugPosition */
    const char *nc_lab, *clip_lab;   /* "3. Near_Clipp", "5. Clipp" (+ ing/ed) */
} clog;

static int on(const clog *w)
{
    return (w->dbg & PT_KDBG_SCENE) || w->debug_position;
}

/* ===== numbers and objects as Java prints them ===== */

static void jf(const clog *w, double x, int width, int prec, unsigned flags)
{
    char b[PT_JNUM_LEN];
    pt_jnum_f(b, x, width, prec, flags);
    fputs(b, w->f);
}

static void jd(const clog *w, double x)
{
    char b[PT_JNUM_LEN];
    pt_jnum_dtoa(b, x);
    fputs(b, w->f);
}

/* Vertex.toString(): r7 "(x,y,z) = (...)", r9 "(x,y,z,w)=(...)". */
static void vertex(const clog *w, pt_vec4 v)
{
    if (w->drv == 0) {
        fputs("(x,y,z) = (", w->f);
        jf(w, v.x, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
        jf(w, v.y, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
        jf(w, v.z, 10, 5, PT_JNUM_SPACE); fputs(")", w->f);
        return;
    }
    fputs("(x,y,z,w)=(", w->f);
    jf(w, v.x, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
    jf(w, v.y, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
    jf(w, v.z, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
    jf(w, v.w, 10, 5, PT_JNUM_SPACE); fputs(")", w->f);
}

static void color(const clog *w, pt_rgb c)
{
    fprintf(w->f, "java.awt.Color[r=%d,g=%d,b=%d]", pt_color_byte(c.r), pt_color_byte(c.g), pt_color_byte(c.b));
}

static void prim(const clog *w, const pt_rv_prim *p)
{
    if (p->kind == PT_RV_POINT)
        fprintf(w->f, "Point: ([%lu], [%lu]) radius = %d", (unsigned long)p->v[0],
                (unsigned long)p->c[0], p->radius);
    else
        fprintf(w->f, "LineSegment: ([%lu, %lu], [%lu, %lu])", (unsigned long)p->v[0],
                (unsigned long)p->v[1], (unsigned long)p->c[0], (unsigned long)p->c[1]);
}

/* Matrix.toString(): four rows of "% 9.5f", no newline after the last. */
static void matrix(const clog *w, const pt_jmat *m)
{
    static const char *const open[4] = {"[[", " [", " [", " ["};
    int i, j;

    for (i = 0; i < 4; i++) {
        fputs(open[i], w->f);
        for (j = 0; j < 4; j++) {
            const pt_vec4 *c = &m->col[j];
            double x = i == 0 ? c->x : i == 1 ? c->y : i == 2 ? c->z : c->w;
            if (j) fputs("  ", w->f);
            jf(w, x, 9, 5, PT_JNUM_SPACE);
        }
        fputs(i < 3 ? " ]\n" : " ]]", w->f);
    }
}

/* PipelineLogger.logPrimitive: the primitive, its vertices, its colours. */
static void log_prim(const clog *w, const char *lab, const char *suffix,
                     const pt_rv_model *m, const pt_rv_prim *p)
{
    int k, n = p->kind == PT_RV_POINT ? 1 : 2;

    if (!on(w)) return;
    fprintf(w->f, "%s%s: ", lab, suffix);
    prim(w, p);
    fputc('\n', w->f);
    for (k = 0; k < n; k++) {
        fprintf(w->f, "   vIndex = %3lu, ", (unsigned long)p->v[k]);
        vertex(w, m->v[p->v[k]]);
        fputc('\n', w->f);
    }
    for (k = 0; k < n; k++) {
        fprintf(w->f, "   cIndex = %3lu, ", (unsigned long)p->c[k]);
        color(w, m->c[p->c[k]]);
        fputc('\n', w->f);
    }
}

/* logVertexList, logColorList, logPrimitiveList. */
static void lists(const clog *w, const char *lab, int which, const pt_rv_model *m)
{
    size_t k;

    if (!on(w)) return;
    if (which & LV) {
        if (m->nv == 0) fprintf(w->f, "%s: empty vertex list\n", lab);
        for (k = 0; k < m->nv; k++) {
            fprintf(w->f, "%s: vIndex = %3lu, ", lab, (unsigned long)k);
            vertex(w, m->v[k]);
            fputc('\n', w->f);
        }
    }
    if (which & LC) {
        if (m->nc == 0) fprintf(w->f, "%s: empty color list\n", lab);
        for (k = 0; k < m->nc; k++) {
            fprintf(w->f, "%s: cIndex = %3lu, ", lab, (unsigned long)k);
            color(w, m->c[k]);
            fputc('\n', w->f);
        }
    }
    if (which & LP) {
        if (m->np == 0) fprintf(w->f, "%s: empty primitive list\n", lab);
        for (k = 0; k < m->np; k++) {
            fprintf(w->f, "%s: ", lab);
            prim(w, &m->p[k]);
            fputc('\n', w->f);
        }
    }
}

/* ===== the driver's events ===== */

/* Camera.toString(). */
static void camera(const clog *w, const pt_course_cam *c)
{
    const pt_rv_camera *k = &c->cam;
    double fovy = (180. / PI) * pt_jmath_atan(k->t) + (180. / PI) * pt_jmath_atan(-k->b);

    fputs("Camera: \n  perspective = ", w->f);
    fputs(k->perspective ? "true" : "false", w->f);
    fputs("\n  left = ", w->f); jd(w, k->l);
    fputs(",   right = ", w->f); jd(w, k->r);
    fputs("\n  bottom = ", w->f); jd(w, k->b);
    fputs(",   top = ", w->f); jd(w, k->t);
    fputs("\n  near = ", w->f); jd(w, -k->n);
    fputs("\n  (fovy = ", w->f); jd(w, fovy);
    fputs(", aspect ratio = ", w->f); jf(w, (k->r - k->l) / (k->t - k->b), 0, 2, 0);
    fputs(")\n", w->f);
    if (w->drv == 0) return;
    fputs("Normalization Matrix\n", w->f);
    matrix(w, &c->norm);
    fputs("\nTranslation Vector\n  [x,y,z,w] = [", w->f);
    jf(w, k->view.x, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
    jf(w, k->view.y, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
    jf(w, k->view.z, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
    jf(w, 0.0, 10, 5, PT_JNUM_SPACE); fputs("]\n", w->f);
}

/* The position's placement line(s). */
static void placement(const clog *w, const pt_course_pos *p)
{
    if (w->drv == 0) {
        fputs("---- Translation vector = [x,y,z] = [", w->f);
        jf(w, p->translate.x, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
        jf(w, p->translate.y, 10, 5, PT_JNUM_SPACE); fputs("  ", w->f);
        jf(w, p->translate.z, 10, 5, PT_JNUM_SPACE); fputs("]\n", w->f);
        return;
    }
    fputs(w->drv == 2 ? "---- Transformation matrix:\n" : "---- Transformation matrix = ", w->f);
    matrix(w, &p->matrix);
    fputc('\n', w->f);
}

static void on_mark(void *ud, pt_course_mark k, const pt_course_cam *cam,
                    const pt_course_pos *p)
{
    clog *w = ud;
    const char *name = p && p->sm ? p->sm->name : "";
    const char *pos = p && p->sm ? p->pos_name : "";
    const char *sname = w->s->scene_name ? w->s->scene_name : "";
    int p2 = w->drv == 2;

    if (p && p->sm && (k == PT_CMK_POSITION || k == PT_CMK_POSITION_HIDDEN))
        w->debug_position = (w->dbg & PT_KDBG_POSITION) != 0;
    if (!on(w)) return;
    switch (k) {
    case PT_CMK_BEGIN:
        if (w->drv == 0) fprintf(w->f, "\n== Begin Rendering of Scene: %s ==\n", sname);
        else if (!p2) fprintf(w->f, "\n== Begin Rendering of Scene (Pipeline 1): %s ==\n", sname);
        else fprintf(w->f, "\n= Begin Rendering of Scene (Pipeline 2): %s =\n", sname);
        fputs(p2 ? "- Current Camera:\n" : "-- Current Camera:\n", w->f);
        camera(w, cam);
        break;
    case PT_CMK_POSITION:
        fprintf(w->f, p2 ? "==== 1. Render position: %s ====\n" : "==== Render position: %s ====\n",
                pos);
        placement(w, p);
        break;
    case PT_CMK_MODEL:
        fprintf(w->f, p2 ? "==== 1. Model-to-world transform of: %s ====\n"
                         : "====== Render model: %s ======\n", name);
        break;
    case PT_CMK_MODEL_END:
        if (p2) fprintf(w->f, "==== 1. End Model: %s::%s ====\n", pos, name);
        else fprintf(w->f, "====== End model: %s ======\n", name);
        break;
    case PT_CMK_MODEL_HIDDEN:
        fprintf(w->f, p2 ? "==== 1. Hidden model: %s ====\n" : "====== Hidden model: %s ======\n",
                name);
        break;
    case PT_CMK_POSITION_END:
        fprintf(w->f, p2 ? "==== 1. End position: %s ====\n" : "==== End position: %s ====\n",
                pos);
        break;
    case PT_CMK_POSITION_HIDDEN:
        fprintf(w->f, p2 ? "==== 1. Hidden position: %s ====\n"
                         : "==== Hidden position: %s ====\n", pos);
        break;
    case PT_CMK_END:
        fputs(p2 ? "= End Rendering of Scene (Pipeline 2) =\n" : "== End Rendering of Scene ==\n",
              w->f);
        break;
    case PT_CMK_PHASE:
        fprintf(w->f, "== %d. Begin %s of Scene ====\n", p->phase, phase_what[p->phase & 7]);
        break;
    case PT_CMK_STEP:
        fprintf(w->f, "==== %d. %s: %s::%s ====\n", p->phase, phase_verb[p->phase & 7], pos, name);
        break;
    case PT_CMK_STEP_END:
        fprintf(w->f, "==== %d. End Model: %s::%s ====\n", p->phase, pos, name);
        break;
    case PT_CMK_PHASE_END:                       /* stage 2's line says view-to-camera */
        fprintf(w->f, "== %d. End %s of Scene ====\n", p->phase,
                phase_what[p->phase == 2 ? 3 : p->phase & 7]);
        break;
    }
}

/* Model.toString(), then println's newline. */
static void dump(const clog *w, const pt_course_pos *p, const pt_rv_model *m)
{
    size_t k;

    fprintf(w->f, "Model: %s\nThis Model's visibility is: true\n", p->sm->name);
    fprintf(w->f, "Model has %lu vertices.\nModel has %lu colors.\nModel has %lu primitives.\n",
            (unsigned long)m->nv, (unsigned long)m->nc, (unsigned long)m->np);
    for (k = 0; k < m->nv; k++) {
        fprintf(w->f, "%lu: ", (unsigned long)k);
        vertex(w, m->v[k]);
        fputc('\n', w->f);
    }
    for (k = 0; k < m->nc; k++) {
        fprintf(w->f, "%lu: ", (unsigned long)k);
        color(w, m->c[k]);
        fputc('\n', w->f);
    }
    for (k = 0; k < m->np; k++) {
        fprintf(w->f, "%lu: ", (unsigned long)k);
        prim(w, &m->p[k]);
        fputc('\n', w->f);
    }
    fputc('\n', w->f);
}

static void on_warn(void *ud, pt_course_warn k, const pt_course_pos *p, const pt_rv_model *m)
{
    clog *w = ud;

    switch (k) {
    case PT_CWN_NO_VERTICES:
        fputs("***WARNING: This model does not have any vertices.\n", w->f);
        break;
    case PT_CWN_NO_PRIMITIVES:
        fputs("***WARNING: This model does not have any geometric primitives.\n", w->f);
        break;
    case PT_CWN_NO_COLORS:
        fputs("***WARNING: This model does not have any colors.\n", w->f);
        break;
    case PT_CWN_DUMP:
        dump(w, p, m);
        break;
    case PT_CWN_DEFAULT_COLOR:
        fprintf(w->f, "***WARNING: Added default color to model: %s.\n", p->sm->name);
        break;
    }
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *p, const pt_rv_model *m)
{
    clog *w = ud;
    (void)p;
    lists(w, stage_labs[st].lab[w->drv], stage_labs[st].lists, m);
}

static void on_raster(void *ud, const pt_course_pos *p, const pt_rv_model *m,
                      const pt_rv_prim *pr)
{
    clog *w = ud;
    (void)p;
    log_prim(w, w->drv == 0 ? "6. Rasterize" : "7. Rasterize", "", m, pr);
}

/* ===== the clip stages' lines ===== */

static void nc_begin(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    clog *w = ud;
    log_prim(w, w->nc_lab, "ing", m, p);
}

static void nc_end(void *ud, const pt_rv_model *m, const pt_rv_prim *p, int accepted)
{
    clog *w = ud;
    log_prim(w, w->nc_lab, accepted ? "ed (accept)" : "ed (reject)", m, p);
}

static void clip_begin(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    clog *w = ud;
    log_prim(w, w->clip_lab, "ing", m, p);
}

static void clip_end(void *ud, const pt_rv_model *m, const pt_rv_prim *p, int accepted)
{
    clog *w = ud;
    log_prim(w, w->clip_lab, accepted ? "ed (accept)" : "ed (reject)", m, p);
}

static int clip_on(const clog *w)
{
    return on(w) && (w->dbg & PT_KDBG_CLIP);
}

static void nc_trivial(void *ud, int accept)
{
    clog *w = ud;
    if (clip_on(w))
        fputs(accept ? "-- Near_Clip: Trivial accept.\n" : "-- Near_Clip: Trivial delete.\n", w->f);
}

static void clip_trivial(void *ud, int accept)
{
    clog *w = ud;
    if (clip_on(w)) fputs(accept ? "-- Trivial accept.\n" : "-- Trivial delete.\n", w->f);
}

/* "<% .Pf, % .Pf, % .Pf" (sep between them) of a point's first n coordinates. */
static void coords(const clog *w, const char *head, pt_vec4 v, int n, int prec,
                   unsigned flags, const char *sep, const char *tail)
{
    fputs(head, w->f);
    jf(w, v.x, 0, prec, flags); fputs(sep, w->f);
    jf(w, v.y, 0, prec, flags);
    if (n == 3) { fputs(sep, w->f); jf(w, v.z, 0, prec, flags); }
    fputs(tail, w->f);
}

static pt_vec4 rgb4(pt_rgb c)
{
    pt_vec4 v = {(double)c.r, (double)c.g, (double)c.b, 0.0};
    return v;
}

static void nc_cut(void *ud, const pt_rv_cut *c)
{
    clog *w = ud;

    if (!clip_on(w)) return;
    fprintf(w->f, "-- Clip off v%d at z=", c->off);
    jf(w, c->plane, 0, 3, 0);
    fputs("\n-- t = ", w->f);
    jf(w, c->t, 0, 25, 0);
    fputc('\n', w->f);
    coords(w, "-- <x0, y0, z0> = <", c->p[0], 3, 8, PT_JNUM_SPACE, ", ", "\n");
    coords(w, "-- <x1, y1, z1> = <", c->p[1], 3, 8, PT_JNUM_SPACE, ", ", "\n");
    coords(w, "-- <x,  y,  z>  = <", c->p[2], 3, 8, PT_JNUM_SPACE, ", ", "\n");
    coords(w, "-- <r0, g0, b0> = <", rgb4(c->c[0]), 3, 8, 0, ", ", ">\n");
    coords(w, "-- <r1, g1, b1> = <", rgb4(c->c[1]), 3, 8, 0, ", ", ">\n");
    coords(w, "-- <r,  g,  b>  = <", rgb4(c->c[2]), 3, 8, 0, ", ", ">\n");
}

static void clip_cut(void *ud, const pt_rv_cut *c)
{
    clog *w = ud;
    const char *eq = "";

    if (!clip_on(w)) return;
    switch (c->edge) {
    case PT_RV_NEAR: eq = "z = n"; break;            /* not the rectangle's */
    case PT_RV_XPOS: eq = "x = +1"; break;
    case PT_RV_XNEG: eq = "x = -1"; break;
    case PT_RV_YPOS: eq = "y = +1"; break;
    case PT_RV_YNEG: eq = "y = -1"; break;
    }
    fprintf(w->f, "-- Clip off v%d at %s\n-- t = ", c->off, eq);
    jf(w, c->t, 0, 25, PT_JNUM_SPACE);
    fputc('\n', w->f);
    coords(w, "-- <x_i, y_i> = <", c->p[0], 2, 24, PT_JNUM_SPACE, ", ", ">\n");
    coords(w, "-- <x_o, y_o> = <", c->p[1], 2, 24, PT_JNUM_SPACE, ", ", ">\n");
    coords(w, "-- <x_c, y_c> = <", c->p[2], 2, 24, PT_JNUM_SPACE, ", ", ">\n");
    coords(w, "-- <r_i, g_i, b_i> = <", rgb4(c->c[0]), 3, 15, PT_JNUM_SPACE, ",  ", ">\n");
    coords(w, "-- <r_o, g_o, b_o> = <", rgb4(c->c[1]), 3, 15, PT_JNUM_SPACE, ",  ", ">\n");
    coords(w, "-- <r_c, g_c, b_c> = <", rgb4(c->c[2]), 3, 15, PT_JNUM_SPACE, ",  ", ">\n");
}

/* ===== the log ===== */

/* The first point too large for the pixel log (pt_kraft_point_check), from
** a run that draws nothing (pt_course_ls.measure). */
typedef struct cap_check {
    const pt_scene *s;
    char *err;
    size_t errlen;
    int rc;
} cap_check;

static void cap_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                       const pt_rv_prim *p)
{
    cap_check *cc = ud;

    (void)m;
    if (cc->rc == 0 && p->kind == PT_RV_POINT)
        cc->rc = pt_kraft_point_check(cc->s, pos->sm->name, p->radius, cc->err, cc->errlen);
}

/* 0 when the course's log of s can print every pixel line, else -1 with a
** message in err. */
static int log_check(const pt_scene *s, pt_fb *fb, char *err, size_t errlen)
{
    pt_course_ls ls;
    cap_check cc;

    cc.s = s; cc.err = err; cc.errlen = errlen; cc.rc = 0;
    memset(&ls, 0, sizeof ls);
    ls.raster = cap_raster;
    ls.measure = 1;
    ls.ud = &cc;
    if (pt_course_render(s, fb, &ls) != 0) {
        snprintf(err, errlen, "pipetrace: out of memory");
        return -1;
    }
    return cc.rc;
}

int pt_course_log(FILE *f, const pt_scene *s, unsigned dbg, pt_fb *fb,
                  char *err, size_t errlen)
{
    clog w;
    pt_course_ls ls;
    pt_rv_raster_ls rls;
    int pixels = (dbg & PT_KDBG_RASTERIZE) && (dbg & (PT_KDBG_SCENE | PT_KDBG_POSITION));

    if (pixels && log_check(s, fb, err, errlen) != 0) return -1;   /* nothing written */
    memset(&w, 0, sizeof w);
    w.f = f;
    w.s = s;
    w.dbg = dbg;
    w.drv = s->renderer == 9 ? (s->pipeline2 ? 2 : 1) : 0;
    w.nc_lab = w.drv ? "4. Near_Clipp" : "3. Near_Clipp";
    w.clip_lab = w.drv ? "6. Clipp" : "5. Clipp";
    memset(&ls, 0, sizeof ls);
    ls.mark = on_mark;
    ls.warn = on_warn;
    ls.stage = on_stage;
    ls.raster = on_raster;
    ls.nearclip.begin = nc_begin;
    ls.nearclip.trivial = nc_trivial;
    ls.nearclip.cut = nc_cut;
    ls.nearclip.end = nc_end;
    ls.nearclip.ud = &w;
    ls.clip.begin = clip_begin;
    ls.clip.trivial = clip_trivial;
    ls.clip.cut = clip_cut;
    ls.clip.end = clip_end;
    ls.clip.ud = &w;
    /* the rasterizer's lines: Rasterize.debug under the scene's or the
    ** positions' debug (the same for every position); Bad pixel lines always */
    pt_rv_log_raster_ls(&rls, f, pixels);
    ls.raster_ls = &rls;
    ls.ud = &w;
    if (pt_course_render(s, fb, &ls) != 0) {
        snprintf(err, errlen, "pipetrace: out of memory");
        return -1;
    }
    return 0;
}
