/*
** src/io/trace_course.c -- the course's debug log of renderers 7 and 9 (--format kraft)
** See LICENSE for copyright and license.
**
** A listener of the driver (core/course.h): each callback prints the lines
** the course's Java prints at that point, gated as PipelineLogger gates them
** (debugScene || debugPosition, the latter set per position and kept after
** the loop).  The labels are the course's, padded as it pads them.  The
** lines go into a trace's block as renderer 4's traces do (io/trace_int.h):
** a list's line written in place, its numbers by pt_jnum_f (a vertex's from
** the spellings kept in vnum), printf only for the seldom lines (say()).
*/
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/trace_course.h"
#include "io/trace.h"
#include "io/trace_int.h"
#include "io/trace_kraft.h"
#include "io/jnum.h"
#include "io/rv_log_raster.h"
#include "io/tlanes.h"

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

/* The spellings of the doubles a vertex shows ("% 10.5f") that the log
** keeps, by their bits' hash as the trace keeps its (trace_int.h: num_slot):
** a model's vertices come again in every stage's list and in each
** primitive's lines. */
#define VNUM_BITS 8
#define VNUM_LEN 23              /* longer spellings are not kept */

typedef struct clog {
    pt_course_lane ln;           /* its lane (first: pt_course_lane_ls) */
    pt_trace *t;                 /* the output block (trace_int.h) */
    int failed;                  /* out of memory */
    const pt_scene *s;
    unsigned dbg;
    int drv;                     /* 0 r7, 1 r9 Pipeline, 2 r9 Pipeline2 */
    int debug_position;          /* PipelineLogger.debugPosition */
    pt_rv_raster_ls rls;         /* the rasterizer's lines (rv_log_raster.h) */
    const char *nc_lab, *clip_lab;   /* "3. Near_Clipp", "5. Clipp" (+ ing/ed) */
    struct vnum {                /* the kept spellings: a slot holds the */
        uint64_t bits;           /*   spelling of the bits it holds */
        unsigned char len;
        char s[VNUM_LEN];
    } vnum[1 << VNUM_BITS];
} clog;

/* The room a line of the log asks for before it writes by pointer: its
** label and integers, and four numbers as Java spells them. */
#define LINE_ROOM (512 + 4 * PT_JNUM_LEN)

/* Are the debug lines on (and the piece going on this log's)? */
static int on(clog *w)
{
    return w->ln.taken && ((w->dbg & PT_KDBG_SCENE) || w->debug_position);
}

/* ===== numbers and objects as Java prints them ===== */

/* printf(fmt, ...) at the end of the block: the log's seldom lines (a
** render's marks, the warnings).  A failed allocation sets w->failed. */
static void say(clog *w, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static void say(clog *w, const char *fmt, ...)
{
    va_list ap;
    char b[1024], *big;
    int n;

    va_start(ap, fmt);
    n = vsnprintf(b, sizeof b, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    if ((size_t)n < sizeof b) { put(w->t, b, (size_t)n); return; }
    if (!(big = malloc((size_t)n + 1))) { w->failed = 1; return; }   /* a long name */
    va_start(ap, fmt);
    vsnprintf(big, (size_t)n + 1, fmt, ap);
    va_end(ap);
    put(w->t, big, (size_t)n);
    free(big);
}

static void out(clog *w, const char *s)
{
    puts_(w->t, s);
}

/* String.format("%W.Pf", x) (pt_jnum_f) at o; returns the end. */
static char *jf_at(char *o, double x, int width, int prec, unsigned flags)
{
    return o + pt_jnum_f(o, x, width, prec, flags);
}

static void jf(clog *w, double x, int width, int prec, unsigned flags)
{
    char *o = room(w->t, PT_JNUM_LEN);
    w->t->len = (size_t)(jf_at(o, x, width, prec, flags) - w->t->buf);
}

static void jd(clog *w, double x)
{
    char *o = room(w->t, PT_JNUM_LEN);
    w->t->len += pt_jnum_dtoa(o, x);
}

/* "% 10.5f" of x, a vertex's number, at o: from its kept spelling when it
** is x's, else by pt_jnum_f (and kept when short). */
static char *vnum_at(clog *w, char *o, double x)
{
    struct vnum *e;
    uint64_t bits;
    size_t n;

    memcpy(&bits, &x, sizeof bits);
    e = &w->vnum[(bits * UINT64_C(0x9e3779b97f4a7c15)) >> (64 - VNUM_BITS)];
    if (e->bits == bits && e->len) {
        memcpy(o, e->s, VNUM_LEN);
        return o + e->len;
    }
    n = pt_jnum_f(o, x, 10, 5, PT_JNUM_SPACE);
    if (n <= VNUM_LEN) {
        e->bits = bits;
        e->len = (unsigned char)n;
        memcpy(e->s, o, n);
    }
    return o + n;
}

/* Vertex.toString() at o: r7 "(x,y,z) = (...)", r9 "(x,y,z,w)=(...)". */
static char *vertex_at(clog *w, char *o, pt_vec4 v)
{
    o = str_at(o, w->drv == 0 ? "(x,y,z) = (" : "(x,y,z,w)=(");
    o = vnum_at(w, o, v.x);
    o = vnum_at(w, str_at(o, "  "), v.y);
    o = vnum_at(w, str_at(o, "  "), v.z);
    if (w->drv) o = vnum_at(w, str_at(o, "  "), v.w);
    return str_at(o, ")");
}

/* Color.toString(): the bytes java.awt.Color keeps of the floats. */
static char *color_at(clog *w, char *o, pt_rgb c)
{
    o = u64_at(w->t, str_at(o, "java.awt.Color[r="), (uint64_t)pt_color_byte(c.r));
    o = u64_at(w->t, str_at(o, ",g="), (uint64_t)pt_color_byte(c.g));
    o = u64_at(w->t, str_at(o, ",b="), (uint64_t)pt_color_byte(c.b));
    return str_at(o, "]");
}

/* Point.toString(), LineSegment.toString(): 0-based indices. */
static char *prim_at(clog *w, char *o, const pt_rv_prim *p)
{
    const pt_trace *t = w->t;

    if (p->kind == PT_RV_POINT) {
        o = u64_at(t, str_at(o, "Point: (["), p->v[0]);
        o = u64_at(t, str_at(o, "], ["), p->c[0]);
        return int_at(t, str_at(o, "]) radius = "), p->radius, 0);
    }
    o = u64_at(t, str_at(o, "LineSegment: (["), p->v[0]);
    o = u64_at(t, str_at(o, ", "), p->v[1]);
    o = u64_at(t, str_at(o, "], ["), p->c[0]);
    o = u64_at(t, str_at(o, ", "), p->c[1]);
    return str_at(o, "])");
}

/* A line: lab (put first: it may be long), pre, idx right-aligned in idx_w
** columns ("%3lu") and post, then what it shows, L_VERTEX, L_COLOR or
** L_PRIM: vertex, colour or primitive k of m; then the line's end. */
enum { L_VERTEX, L_COLOR, L_PRIM };
static void line(clog *w, const char *lab, const char *pre, int idx_w, size_t idx,
                 const char *post, int what, const pt_rv_model *m, size_t k)
{
    pt_trace *t = w->t;
    char *o;

    out(w, lab);
    o = str_at(room(t, LINE_ROOM), pre);
    o = str_at(int_at(t, o, (int64_t)idx, (size_t)idx_w), post);
    switch (what) {
    case L_VERTEX: o = vertex_at(w, o, m->v[k]); break;
    case L_COLOR: o = color_at(w, o, m->c[k]); break;
    case L_PRIM: o = prim_at(w, o, &m->p[k]); break;
    }
    t->len = (size_t)(str_at(o, "\n") - t->buf);
}

/* Matrix.toString(): four rows of "% 9.5f", no newline after the last. */
static void matrix(clog *w, const pt_jmat *m)
{
    static const char *const open[4] = {"[[", " [", " [", " ["};
    int i, j;

    for (i = 0; i < 4; i++) {
        out(w, open[i]);
        for (j = 0; j < 4; j++) {
            const pt_vec4 *c = &m->col[j];
            double x = i == 0 ? c->x : i == 1 ? c->y : i == 2 ? c->z : c->w;
            if (j) out(w, "  ");
            jf(w, x, 9, 5, PT_JNUM_SPACE);
        }
        out(w, i < 3 ? " ]\n" : " ]]");
    }
}

/* PipelineLogger.logPrimitive: the primitive, its vertices, its colours. */
static void log_prim(clog *w, const char *lab, const char *suffix,
                     const pt_rv_model *m, const pt_rv_prim *p)
{
    int k, n = p->kind == PT_RV_POINT ? 1 : 2;
    char *o;

    if (!on(w)) return;
    out(w, lab);
    o = prim_at(w, str_at(str_at(room(w->t, LINE_ROOM), suffix), ": "), p);
    w->t->len = (size_t)(str_at(o, "\n") - w->t->buf);
    for (k = 0; k < n; k++) line(w, "", "   vIndex = ", 3, p->v[k], ", ", L_VERTEX, m, p->v[k]);
    for (k = 0; k < n; k++) line(w, "", "   cIndex = ", 3, p->c[k], ", ", L_COLOR, m, p->c[k]);
}

/* logVertexList, logColorList, logPrimitiveList. */
static void lists(clog *w, const char *lab, int which, const pt_rv_model *m)
{
    size_t k;

    if (!on(w)) return;
    if (which & LV) {
        if (m->nv == 0) say(w, "%s: empty vertex list\n", lab);
        for (k = 0; k < m->nv; k++) line(w, lab, ": vIndex = ", 3, k, ", ", L_VERTEX, m, k);
    }
    if (which & LC) {
        if (m->nc == 0) say(w, "%s: empty color list\n", lab);
        for (k = 0; k < m->nc; k++) line(w, lab, ": cIndex = ", 3, k, ", ", L_COLOR, m, k);
    }
    if (which & LP) {
        if (m->np == 0) say(w, "%s: empty primitive list\n", lab);
        for (k = 0; k < m->np; k++) {
            char *o;
            out(w, lab);
            o = prim_at(w, str_at(room(w->t, LINE_ROOM), ": "), &m->p[k]);
            w->t->len = (size_t)(str_at(o, "\n") - w->t->buf);
        }
    }
}

/* ===== the driver's events ===== */

/* Camera.toString(). */
static void camera(clog *w, const pt_course_cam *c)
{
    const pt_rv_camera *k = &c->cam;
    double fovy = (180. / PI) * pt_jmath_atan(k->t) + (180. / PI) * pt_jmath_atan(-k->b);

    out(w, "Camera: \n  perspective = ");
    out(w, k->perspective ? "true" : "false");
    out(w, "\n  left = "); jd(w, k->l);
    out(w, ",   right = "); jd(w, k->r);
    out(w, "\n  bottom = "); jd(w, k->b);
    out(w, ",   top = "); jd(w, k->t);
    out(w, "\n  near = "); jd(w, -k->n);
    out(w, "\n  (fovy = "); jd(w, fovy);
    out(w, ", aspect ratio = "); jf(w, (k->r - k->l) / (k->t - k->b), 0, 2, 0);
    out(w, ")\n");
    if (w->drv == 0) return;
    out(w, "Normalization Matrix\n");
    matrix(w, &c->norm);
    out(w, "\nTranslation Vector\n  [x,y,z,w] = [");
    jf(w, k->view.x, 10, 5, PT_JNUM_SPACE); out(w, "  ");
    jf(w, k->view.y, 10, 5, PT_JNUM_SPACE); out(w, "  ");
    jf(w, k->view.z, 10, 5, PT_JNUM_SPACE); out(w, "  ");
    jf(w, 0.0, 10, 5, PT_JNUM_SPACE); out(w, "]\n");
}

/* The position's placement line(s). */
static void placement(clog *w, const pt_course_pos *p)
{
    if (w->drv == 0) {
        out(w, "---- Translation vector = [x,y,z] = [");
        jf(w, p->translate.x, 10, 5, PT_JNUM_SPACE); out(w, "  ");
        jf(w, p->translate.y, 10, 5, PT_JNUM_SPACE); out(w, "  ");
        jf(w, p->translate.z, 10, 5, PT_JNUM_SPACE); out(w, "]\n");
        return;
    }
    out(w, w->drv == 2 ? "---- Transformation matrix:\n" : "---- Transformation matrix = ");
    matrix(w, &p->matrix);
    out(w, "\n");
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
        if (w->drv == 0) say(w, "\n== Begin Rendering of Scene: %s ==\n", sname);
        else if (!p2) say(w, "\n== Begin Rendering of Scene (Pipeline 1): %s ==\n", sname);
        else say(w, "\n= Begin Rendering of Scene (Pipeline 2): %s =\n", sname);
        out(w, p2 ? "- Current Camera:\n" : "-- Current Camera:\n");
        camera(w, cam);
        break;
    case PT_CMK_POSITION:
        say(w, p2 ? "==== 1. Render position: %s ====\n" : "==== Render position: %s ====\n",
                pos);
        placement(w, p);
        break;
    case PT_CMK_MODEL:
        say(w, p2 ? "==== 1. Model-to-world transform of: %s ====\n"
                         : "====== Render model: %s ======\n", name);
        break;
    case PT_CMK_MODEL_END:
        if (p2) say(w, "==== 1. End Model: %s::%s ====\n", pos, name);
        else say(w, "====== End model: %s ======\n", name);
        break;
    case PT_CMK_MODEL_HIDDEN:
        say(w, p2 ? "==== 1. Hidden model: %s ====\n" : "====== Hidden model: %s ======\n",
                name);
        break;
    case PT_CMK_POSITION_END:
        say(w, p2 ? "==== 1. End position: %s ====\n" : "==== End position: %s ====\n",
                pos);
        break;
    case PT_CMK_POSITION_HIDDEN:
        say(w, p2 ? "==== 1. Hidden position: %s ====\n"
                         : "==== Hidden position: %s ====\n", pos);
        break;
    case PT_CMK_END:
        out(w, p2 ? "= End Rendering of Scene (Pipeline 2) =\n" : "== End Rendering of Scene ==\n");
        break;
    case PT_CMK_PHASE:
        say(w, "== %d. Begin %s of Scene ====\n", p->phase, phase_what[p->phase & 7]);
        break;
    case PT_CMK_STEP:
        say(w, "==== %d. %s: %s::%s ====\n", p->phase, phase_verb[p->phase & 7], pos, name);
        break;
    case PT_CMK_STEP_END:
        say(w, "==== %d. End Model: %s::%s ====\n", p->phase, pos, name);
        break;
    case PT_CMK_PHASE_END:                       /* stage 2's line says view-to-camera */
        say(w, "== %d. End %s of Scene ====\n", p->phase,
                phase_what[p->phase == 2 ? 3 : p->phase & 7]);
        break;
    }
}

/* Model.toString(), then println's newline. */
static void dump(clog *w, const pt_course_pos *p, const pt_rv_model *m)
{
    size_t k;

    say(w, "Model: %s\nThis Model's visibility is: true\n", p->sm->name);
    say(w, "Model has %lu vertices.\nModel has %lu colors.\nModel has %lu primitives.\n",
        (unsigned long)m->nv, (unsigned long)m->nc, (unsigned long)m->np);
    for (k = 0; k < m->nv; k++) line(w, "", "", 0, k, ": ", L_VERTEX, m, k);
    for (k = 0; k < m->nc; k++) line(w, "", "", 0, k, ": ", L_COLOR, m, k);
    for (k = 0; k < m->np; k++) line(w, "", "", 0, k, ": ", L_PRIM, m, k);
    out(w, "\n");
}

static void on_warn(void *ud, pt_course_warn k, const pt_course_pos *p, const pt_rv_model *m)
{
    clog *w = ud;

    if (!w->ln.taken) return;                /* the warnings: whatever the switches */
    switch (k) {
    case PT_CWN_NO_VERTICES:
        out(w, "***WARNING: This model does not have any vertices.\n");
        break;
    case PT_CWN_NO_PRIMITIVES:
        out(w, "***WARNING: This model does not have any geometric primitives.\n");
        break;
    case PT_CWN_NO_COLORS:
        out(w, "***WARNING: This model does not have any colors.\n");
        break;
    case PT_CWN_DUMP:
        dump(w, p, m);
        break;
    case PT_CWN_DEFAULT_COLOR:
        say(w, "***WARNING: Added default color to model: %s.\n", p->sm->name);
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

static int clip_on(clog *w)
{
    return on(w) && (w->dbg & PT_KDBG_CLIP);
}

static void nc_trivial(void *ud, int accept)
{
    clog *w = ud;
    if (clip_on(w))
        out(w, accept ? "-- Near_Clip: Trivial accept.\n" : "-- Near_Clip: Trivial delete.\n");
}

static void clip_trivial(void *ud, int accept)
{
    clog *w = ud;
    if (clip_on(w)) out(w, accept ? "-- Trivial accept.\n" : "-- Trivial delete.\n");
}

/* "<% .Pf, % .Pf, % .Pf" (sep between them) of a point's first n coordinates. */
static void coords(clog *w, const char *head, pt_vec4 v, int n, int prec,
                   unsigned flags, const char *sep, const char *tail)
{
    out(w, head);
    jf(w, v.x, 0, prec, flags); out(w, sep);
    jf(w, v.y, 0, prec, flags);
    if (n == 3) { out(w, sep); jf(w, v.z, 0, prec, flags); }
    out(w, tail);
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
    say(w, "-- Clip off v%d at z=", c->off);
    jf(w, c->plane, 0, 3, 0);
    out(w, "\n-- t = ");
    jf(w, c->t, 0, 25, 0);
    out(w, "\n");
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
    say(w, "-- Clip off v%d at %s\n-- t = ", c->off, eq);
    jf(w, c->t, 0, 25, PT_JNUM_SPACE);
    out(w, "\n");
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

/* pt_course_ls.piece: is the piece the lane's (tlanes.h)?  ud: a writer's
** state, which begins with its lane. */
static int on_piece(void *ud, uint64_t n, int last)
{
    pt_course_lane *ln = ud;
    ln->taken = pt_tlanes_piece(ln->t, n, last);
    ln->pieces += (uint64_t)ln->taken;
    return ln->taken;
}

void pt_course_lane_ls(pt_course_ls *ls, pt_course_lane *ln)
{
    if (!ln->cuts) return;
    ls->piece = on_piece;
    ls->piece_vertices = ln->cuts->vertices;
    ls->piece_prims = ln->cuts->prims;
    ls->piece_pixels = ln->cuts->pixels;
    ls->skip_unwanted = ln->skips;
    ls->tally = &ln->tally;
}

/* Set w up to write s's log with the course's flags dbg to f.  0, or -1
** when out of memory (then free(w->t) still). */
static int clog_init(clog *w, FILE *f, const pt_scene *s, unsigned dbg)
{
    memset(w, 0, sizeof *w);
    if (!(w->t = malloc(sizeof *w->t))) return -1;
    pt_trace_init(w->t, f, PT_FORMAT_KRAFT, 0);
    w->ln.t = w->t;
    w->s = s;
    w->dbg = dbg;
    w->ln.taken = 1;
    w->drv = s->renderer == 9 ? (s->pipeline2 ? 2 : 1) : 0;
    w->nc_lab = w->drv ? "4. Near_Clipp" : "3. Near_Clipp";
    w->clip_lab = w->drv ? "6. Clipp" : "5. Clipp";
    /* the rasterizer's lines: Rasterize.debug under the scene's or the
    ** positions' debug (the same for every position); Bad pixel lines always */
    pt_rv_log_raster_ls(&w->rls, w->t,
                        (dbg & PT_KDBG_RASTERIZE) && (dbg & (PT_KDBG_SCENE | PT_KDBG_POSITION)));
    return 0;
}

/* Render w's scene into fb with w listening (cut into pieces for tlanes.h
** when its lane says).  0, or -1 when out of memory. */
static int clog_walk(void *ud, pt_fb *fb)
{
    clog *w = ud;
    pt_course_ls ls;
    int rc;

    memset(&ls, 0, sizeof ls);
    ls.mark = on_mark;
    ls.warn = on_warn;
    ls.stage = on_stage;
    ls.raster = on_raster;
    ls.nearclip.begin = nc_begin;
    ls.nearclip.trivial = nc_trivial;
    ls.nearclip.cut = nc_cut;
    ls.nearclip.end = nc_end;
    ls.nearclip.ud = w;
    ls.clip.begin = clip_begin;
    ls.clip.trivial = clip_trivial;
    ls.clip.cut = clip_cut;
    ls.clip.end = clip_end;
    ls.clip.ud = w;
    ls.raster_ls = &w->rls;
    pt_course_lane_ls(&ls, &w->ln);
    ls.ud = w;
    rc = pt_course_render(w->s, fb, &ls) != 0 || w->failed ? -1 : 0;
    pt_trace_flush(w->t);                    /* write errors: in ferror(f) */
    return rc;
}

/* Two lanes' walks, each into its framebuffer. */
typedef struct lanes {
    int (*walk)(void *w, pt_fb *fb);
    void *w[2];
    pt_fb fb[2];
} lanes;

static int lane_walk(void *ud, int k)
{
    lanes *ln = ud;
    return ln->walk(ln->w[k], &ln->fb[k]);
}

int pt_course_lanes(const pt_scene *s, pt_fb *fb, pt_course_cuts *cuts,
                    int (*walk)(void *w, pt_fb *fb), void *const w[2])
{
    pt_course_lane *l0 = w[0], *l1 = w[1];
    pt_trace *t[2];
    lanes ln;
    int rc;

    memset(&ln, 0, sizeof ln);
    ln.walk = walk;
    ln.w[0] = w[0];
    ln.w[1] = w[1];
    ln.fb[0] = *fb;
    ln.fb[1].w = s->fb_w;                    /* lane 1's: no pixels (lane 0 */
    ln.fb[1].h = s->fb_h;                    /*   draws the image) */
    ln.fb[1].rgb = NULL;
    l0->cuts = l1->cuts = cuts;
    l1->taken = 0;                           /* piece 0 is lane 0's */
    l1->skips = 1;                           /* lane 0 draws the image */
    memset(&l0->tally, 0, sizeof l0->tally);
    memset(&l1->tally, 0, sizeof l1->tally);
    t[0] = l0->t;
    t[1] = l1->t;
    rc = pt_tlanes(t, lane_walk, &ln);
    cuts->taken[0] = l0->pieces;
    cuts->taken[1] = l1->pieces;
    cuts->tally[0] = l0->tally;
    cuts->tally[1] = l1->tally;
    l0->cuts = l1->cuts = NULL;
    l0->taken = l1->taken = 1;
    l1->skips = 0;
    return rc;
}

/* The log on two threads: 0, -1 (out of memory), or 1 when no second
** thread is to be had (nothing has run). */
static int clog_lanes(FILE *f, const pt_scene *s, unsigned dbg, pt_course_cuts *cuts,
                      pt_fb *fb)
{
    clog *w = calloc(2, sizeof *w);
    int rc = 1;

    if (!w) return 1;
    if (clog_init(&w[0], f, s, dbg) == 0 && clog_init(&w[1], f, s, dbg) == 0) {
        void *ws[2];
        ws[0] = &w[0];
        ws[1] = &w[1];
        rc = pt_course_lanes(s, fb, cuts, clog_walk, ws);
    }
    if (rc != 1 && w[0].t) cuts->failed = w[0].t->failed;
    free(w[0].t);
    free(w[1].t);
    free(w);
    return rc;
}

int pt_course_log(FILE *f, const pt_scene *s, unsigned dbg, pt_course_cuts *cuts,
                  pt_fb *fb, char *err, size_t errlen)
{
    clog w;
    int rc, pixels = (dbg & PT_KDBG_RASTERIZE) && (dbg & (PT_KDBG_SCENE | PT_KDBG_POSITION));

    if (pixels && log_check(s, fb, err, errlen) != 0) return -1;   /* nothing written */
    rc = cuts && cuts->threads == 2 ? clog_lanes(f, s, dbg, cuts, fb) : 1;
    if (rc == 1) {                           /* one thread */
        rc = clog_init(&w, f, s, dbg) == 0 ? clog_walk(&w, fb) : -1;
        if (cuts && w.t) cuts->failed = w.t->failed;
        free(w.t);
    }
    if (rc) snprintf(err, errlen, "pipetrace: out of memory");
    return rc;
}
