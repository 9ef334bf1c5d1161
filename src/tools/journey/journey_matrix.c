/*
** src/tools/journey/journey_matrix.c -- the matrix camera's panels of a journey (SVG)
** See LICENSE for copyright and license.
**
** The panels of the stages the classic camera does not have, drawn with
** journey.c's pieces (journey.h):
**
**   world   3-D: world axes, the model placed by its World matrix, the eye
**           with its direction and up vectors
**   view    3-D: the eye at the origin looking down +z_v, the frustum from
**           the near plane on (its side planes from the Projection matrix)
**   clip    two plots against w_k: x_k with the planes x_k = -w_k, w_k
**           (left, right), y_k with y_k = -w_k, w_k (bottom, top)
**   cvv     z_k against w_k with z_k = 0 (near) and z_k = w_k (far), and the
**           outcode: the six planes, each distance, each bit
**   ndc     3-D: the cube [-1, 1] x [-1, 1] x [0, 1]
**   screen  the w x h screen rectangle, y down
**
** Every number drawn is a record pt_run() reported: the vertices' journeys
** (pt_run_journeys()) and, for a segment that leaves the view volume, the
** journey of the point clipping made where it cut the segment, which pt_run()
** hands to a listener's journey callback after clipvertex_begin.  After the
** cvv a segment is drawn from those points; in clip space the cut is marked.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/journey/journey_matrix.h"
#include "tools/journey/journey_classic.h"
#include "tools/journey/jpanel.h"
#include "io/explain.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

#define LABEL   "fill=\"" PT_JC_NOTE "\""
#define BIGV    1e150            /* coordinates beyond this never widen a panel */

/* ===== the points clipping made ===== */

typedef struct cutter {
    pt_jmodel *jm;
    uint64_t seg;                /* the segment of the point announced, 1-based */
    size_t cap;                  /* room in jm->cut */
    int failed;
} cutter;

static void on_clipvertex(void *ud, const pt_model *m, uint64_t seg, uint64_t from,
                          uint64_t to, double t, pt_vec4 q)
{
    cutter *c = ud;

    (void)from; (void)to; (void)t; (void)q;
    c->seg = m == c->jm->m ? seg : 0;
}

/* A journey: a vertex's (ignored: pt_jmodel_init's run had them) or a
** clipping point's, kept when its segment is drawn. */
static void on_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    cutter *c = ud;
    pt_jmodel *jm = c->jm;
    size_t s, e;

    if (m != jm->m || v != 0 || c->seg == 0 || c->failed) return;
    s = (size_t)(c->seg - 1);
    /* pt_run() cuts the first end first, and only an end outside the volume */
    e = jm->cutix[2 * s] == 0 && jm->code[m->seg[s].a] != 0 ? 2 * s : 2 * s + 1;
    c->seg = 0;
    if (!pt_jseg_drawn(jm, s)) { jm->cutix[e] = PT_JOURNEY_UNKEPT; return; }
    if (jm->ncut == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 16;
        pt_journey *n = realloc(jm->cut, cap * sizeof *n);
        if (!n) { c->failed = 1; return; }
        jm->cut = n;
        c->cap = cap;
    }
    jm->cut[jm->ncut++] = *j;
    jm->cutix[e] = jm->ncut;
}

/* Grow bbox b to take in (x, y) when both are finite and not huge. */
static void grow(double b[4], double x, double y)
{
    if (!(fabs(x) <= BIGV && fabs(y) <= BIGV)) return;
    if (x < b[0]) b[0] = x;
    if (y < b[1]) b[1] = y;
    if (x > b[2]) b[2] = x;
    if (y > b[3]) b[3] = y;
}

static void grow3(double b[4], pt_stage st, double x, double y, double z)
{
    double px, py;

    pt_jproj(st, x, y, z, &px, &py);
    grow(b, px, py);
}

static void bbox_start(double b[4])
{
    b[0] = b[1] = 0;
    b[2] = b[3] = 0;
}

static void pad_fit(pt_jview *v, double b[4], int ydown, double bx, double by, double bw,
                    double bh)
{
    double p = fmax(b[2] - b[0], b[3] - b[1]) * 0.08;

    b[0] -= p; b[1] -= p; b[2] += p; b[3] += p;
    pt_jview_fit(v, b, ydown, bx, by, bw, bh);
}

/* The value of clip-space component c (0 x, 1 y, 2 z) of record r. */
static double comp(const pt_vrec *r, int c)
{
    return c == 0 ? r->x : c == 1 ? r->y : r->z;
}

void pt_jmatrix_absorb(pt_jmodel *jm, const pt_journey *j, size_t k)
{
    pt_jspan *sp = &jm->span;
    const pt_vrec *r = &j->rec[PT_STAGE_WORLD], *q = &j->rec[PT_STAGE_CLIP];
    double c = fmax(fabs(r->x), fmax(fabs(r->y), fabs(r->z))), z = j->rec[PT_STAGE_VIEW].z;
    double x, y;
    int i;

    pt_jclassic_absorb(jm, j, k);            /* the panels it shares */
    jm->code[k] = (unsigned char)j->rec[PT_STAGE_CVV].code;
    if (c <= BIGV && c > sp->wbig) sp->wbig = c;
    if (z <= BIGV && 1.1 * z > sp->depth) sp->depth = 1.1 * z;
    if (pt_jstage_xy(j, PT_STAGE_WORLD, &x, &y)) grow(sp->world, x, y);
    for (i = 0; i < 3; i++) grow(sp->clip[i], q->w, comp(q, i));
}

/* The length of the world panel's axes: the used vertices and the eye. */
static double world_axis(const pt_jmodel *jm)
{
    const pt_scene *s = jm->s;
    double big = fmax(fabs(s->eye.x), fmax(fabs(s->eye.y), fabs(s->eye.z)));

    if (jm->span.wbig > big) big = jm->span.wbig;
    return big > 0 ? 1.25 * big : 1;
}

/* The depth the view panel draws the frustum to: past the farthest used
** vertex, at most the far plane. */
static double view_depth(const pt_jmodel *jm)
{
    double d = 2 * jm->s->znear;

    if (jm->span.depth > d) d = jm->span.depth;
    return fmin(d, jm->s->zfar);
}

/* Corner c (0..3) of the frustum's cross-section at depth z: where x_k = +-w_k
** and y_k = +-w_k, with w_k = z_v (Projection's diagonal, m3_view2clip.h). */
static void frustum_corner(const pt_jmodel *jm, int c, double z, double p[3])
{
    const pt_mat4 *P = &pt_jmodel_journey(jm, 0)->proj;

    p[0] = (c == 0 || c == 3 ? -z : z) / P->m[0][0];
    p[1] = (c < 2 ? -z : z) / P->m[1][1];
    p[2] = z;
}

int pt_jmatrix_layout(pt_jmodel *jm)
{
    const pt_model *m = jm->m;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    cutter c;
    double b[4], A, D, pt[3];
    size_t k;
    int rc, i;

    if (pt_jclassic_layout(jm) != 0) return -1;  /* model, viewport, framebuffer */
    jm->cutix = calloc(m->nseg ? 2 * m->nseg : 1, sizeof *jm->cutix);
    if (!jm->cutix) return -1;
    memset(&c, 0, sizeof c);
    c.jm = jm;
    memset(&l, 0, sizeof l);
    l.clipvertex_begin = on_clipvertex;
    l.journey = on_journey;
    l.ud = &c;
    pt_options_default(&o);
    o.model = m->name;
    o.trace_raster = 0;
    o.rasterize = 1;                         /* clipping happens with the segments */
    if (pt_plan_make(&p, jm->s, &o) != 0) return -1;
    rc = pt_run(jm->s, &p, &o, &l, NULL, &sum);
    pt_plan_free(&p);
    if (rc != 0 || c.failed) return -1;
    for (k = 0; k < m->nseg; k++) {          /* an end outside and not cut: culled */
        unsigned ca = jm->code[m->seg[k].a], cb = jm->code[m->seg[k].b];
        if ((ca && !jm->cutix[2 * k]) || (cb && !jm->cutix[2 * k + 1]))
            jm->cutix[2 * k] = jm->cutix[2 * k + 1] = PT_JOURNEY_CULLED;
    }

    /* world: origin, axes, the eye, the used vertices */
    A = world_axis(jm);
    bbox_start(b);
    grow3(b, PT_STAGE_WORLD, A, 0, 0);
    grow3(b, PT_STAGE_WORLD, 0, A, 0);
    grow3(b, PT_STAGE_WORLD, 0, 0, A);
    grow3(b, PT_STAGE_WORLD, jm->s->eye.x, jm->s->eye.y, jm->s->eye.z);
    pt_jspan_merge(b, jm->span.world);       /* the used vertices */
    pad_fit(&jm->view[PT_STAGE_WORLD], b, 0, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H);
    /* view: the eye, the frustum, the used vertices; ndc: the cube */
    D = view_depth(jm);
    bbox_start(b);
    for (i = 0; i < 4; i++) {
        frustum_corner(jm, i, jm->s->znear, pt); grow3(b, PT_STAGE_VIEW, pt[0], pt[1], pt[2]);
        frustum_corner(jm, i, D, pt); grow3(b, PT_STAGE_VIEW, pt[0], pt[1], pt[2]);
    }
    pad_fit(&jm->view[PT_STAGE_VIEW], b, 0, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H);
    bbox_start(b);
    for (i = 0; i < 8; i++)
        grow3(b, PT_STAGE_NDC, i & 1 ? 1.2 : -1.2, i & 2 ? 1.2 : -1.2, i & 4 ? 1.2 : 0);
    pad_fit(&jm->view[PT_STAGE_NDC], b, 0, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H);
    /* screen: the rectangle, y down */
    b[0] = 0; b[1] = 0; b[2] = jm->par.w; b[3] = jm->par.h;
    pad_fit(&jm->view[PT_STAGE_SCREEN], b, 1, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H);
    /* clip space: (w_k, x_k), (w_k, y_k), (w_k, z_k), each from w_k = 0 on */
    for (i = 0; i < 3; i++) {
        pt_jview *v = i == 0 ? &jm->view[PT_STAGE_CLIP] : i == 1 ? &jm->clip_y : &jm->clip_z;
        b[0] = 0; b[1] = i == 2 ? 0 : -1; b[2] = 1; b[3] = 1;
        pt_jspan_merge(b, jm->span.clip[i]);     /* the used vertices */
        if (i < 2) { b[1] = fmin(b[1], -b[2]); b[3] = fmax(b[3], b[2]); }  /* the wedge */
        pad_fit(v, b, 0, i == 1 ? PT_JBOX_X + PT_JBOX_W / 2 + 4 : PT_JBOX_X, PT_JBOX_Y + 16, PT_JBOX_W / 2 - 4, PT_JBOX_H - 16);
    }
    return 0;
}

int pt_jmatrix_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb)
{
    const size_t *cx = &jm->cutix[2 * s];
    int after = st == PT_STAGE_NDC || st == PT_STAGE_SCREEN || st == PT_STAGE_VIEWPORT ||
                st == PT_STAGE_FRAMEBUFFER || st == PT_STAGE_INDEX;

    *ja = *pt_jmodel_journey(jm, jm->m->seg[s].a);
    *jb = *pt_jmodel_journey(jm, jm->m->seg[s].b);
    if (!after) return 1;
    if (cx[0] == PT_JOURNEY_CULLED) return 0;
    if (cx[0]) *ja = jm->cut[cx[0] - 1];
    if (cx[1]) *jb = jm->cut[cx[1] - 1];
    return 1;
}

int pt_jmatrix_pixelplane(const pt_jmodel *jm, const pt_journey *j, pt_vec2 *pp)
{
    const pt_vrec *r = &j->rec[PT_STAGE_VIEWPORT];
    pt_pix vp;

    if (!(j->reported & 1u << PT_STAGE_VIEWPORT) || (r->flags & PT_REC_NULL)) return -1;
    vp.x = r->ix; vp.y = r->iy; vp.ok = 1;
    *pp = pt_viewport2pixelplane(vp, jm->par.h);
    return 0;
}

/* ===== backgrounds ===== */

static void axes3(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st, double A, const char *sfx)
{
    char t[16];

    snprintf(t, sizeof t, "x_%s", sfx); pt_jaxis3(sb, &jm->view[st], st, A, 0, 0, t);
    snprintf(t, sizeof t, "y_%s", sfx); pt_jaxis3(sb, &jm->view[st], st, 0, A, 0, t);
    snprintf(t, sizeof t, "z_%s", sfx); pt_jaxis3(sb, &jm->view[st], st, 0, 0, A, t);
}

/* A labelled point of a 3-D panel. */
static void point3(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st, const double *p,
                   const char *label)
{
    const pt_jview *v = &jm->view[st];
    double x, y;

    pt_jproj(st, p[0], p[1], p[2], &x, &y);
    if (!pt_jview_in(v, x, y)) return;
    pt_jcircle(sb, pt_jview_x(v, x), pt_jview_y(v, y), 4, "#333", "");
    pt_jlabel_at(sb, pt_jview_x(v, x) - 7, pt_jview_y(v, y) - 8, 11, "end", "fill=\"#333\"", label, 0, PT_JLAB_OTHER);
}

static void bg_world(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_scene *s = jm->s;
    double A = world_axis(jm), e[3], d[3], u[3], nd, nu;

    (void)st;
    axes3(sb, jm, PT_STAGE_WORLD, A, "w");
    pt_jwireframe(sb, jm, PT_STAGE_WORLD);
    e[0] = s->eye.x; e[1] = s->eye.y; e[2] = s->eye.z;
    nd = sqrt(s->dir.x * s->dir.x + s->dir.y * s->dir.y + s->dir.z * s->dir.z);
    nu = sqrt(s->up.x * s->up.x + s->up.y * s->up.y + s->up.z * s->up.z);
    d[0] = e[0] + 0.4 * A * s->dir.x / nd; d[1] = e[1] + 0.4 * A * s->dir.y / nd;
    d[2] = e[2] + 0.4 * A * s->dir.z / nd;
    u[0] = e[0] + 0.25 * A * s->up.x / nu; u[1] = e[1] + 0.25 * A * s->up.y / nu;
    u[2] = e[2] + 0.25 * A * s->up.z / nu;
    pt_jline3(sb, &jm->view[PT_STAGE_WORLD], PT_STAGE_WORLD, e, d, PT_JC_EDGE, 2, "");
    pt_jline3(sb, &jm->view[PT_STAGE_WORLD], PT_STAGE_WORLD, e, u, PT_JC_EDGE, 1.5, "stroke-dasharray=\"4 2\"");
    point3(sb, jm, PT_STAGE_WORLD, d, "direction");
    point3(sb, jm, PT_STAGE_WORLD, u, "up");
    point3(sb, jm, PT_STAGE_WORLD, e, "eye");
}

static void bg_view(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    double D = view_depth(jm), o[3] = {0, 0, 0}, n[4][3], f[4][3];
    char t[64 + PT_NUMLEN], a[PT_NUMLEN];
    int c;

    (void)st;
    for (c = 0; c < 4; c++) {
        frustum_corner(jm, c, jm->s->znear, n[c]);
        frustum_corner(jm, c, D, f[c]);
    }
    for (c = 0; c < 4; c++) {
        pt_jline3(sb, &jm->view[PT_STAGE_VIEW], PT_STAGE_VIEW, o, f[c], PT_JC_EDGE, 1, "stroke-dasharray=\"5 3\"");
        pt_jline3(sb, &jm->view[PT_STAGE_VIEW], PT_STAGE_VIEW, f[c], f[(c + 1) % 4], PT_JC_EDGE,
                  D < jm->s->zfar ? 1 : 2, D < jm->s->zfar ? "stroke-dasharray=\"5 3\"" : "");
        pt_jline3(sb, &jm->view[PT_STAGE_VIEW], PT_STAGE_VIEW, n[c], n[(c + 1) % 4], PT_JC_EDGE, 2, "");
    }
    axes3(sb, jm, PT_STAGE_VIEW, 0.6 * D, "v");
    pt_jwireframe(sb, jm, PT_STAGE_VIEW);
    point3(sb, jm, PT_STAGE_VIEW, o, "eye");
    pt_fmt_shortest(a, jm->s->znear);
    snprintf(t, sizeof t, "near plane z_v = %s", a);
    pt_jlabel_at(sb, PT_JBOX_X + 6, PT_JBOX_Y + PT_JBOX_H - 20, 10, "start", LABEL, "frustum: from the near plane",
                   0, PT_JLAB_OTHER);
    pt_jlabel_at(sb, PT_JBOX_X + 6, PT_JBOX_Y + PT_JBOX_H - 8, 10, "start", LABEL,
                   D < jm->s->zfar ? "the far plane lies beyond" : "to the far plane", 0, PT_JLAB_OTHER);
    pt_jlabel_at(sb, PT_JBOX_X + 6, PT_JBOX_Y + 14, 10, "start", LABEL, t, 0, PT_JLAB_OTHER);
}

/* One clip-space plot: component c against w_k, with its two planes. */
static void bg_wedge(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, int c)
{
    static const char *const names[3] = {"x_k", "y_k", "z_k"};
    static const char *const planes[3][2] = {{"right: x_k = w_k", "left: x_k = -w_k"},
                                             {"top: y_k = w_k", "bottom: y_k = -w_k"},
                                             {"far: z_k = w_k", "near: z_k = 0"}};
    const pt_model *m = jm->m;
    double W = v->x1, t;
    size_t k;
    char a[48];

    pt_jview_line(sb, v, v->x0, 0, v->x1, 0, "#6b7280", 0.8, "");
    pt_jview_line(sb, v, 0, v->y0, 0, v->y1, "#6b7280", 0.8, "");
    pt_jview_line(sb, v, 0, 0, W, W, PT_JC_EDGE, 1.8, "");
    pt_jview_line(sb, v, 0, 0, W, c == 2 ? 0 : -W, PT_JC_EDGE, 1.8, "");
    t = fmin(0.8 * W, v->y1 * 0.8);
    pt_jview_label(sb, v, t, t, -4, -4, "end", planes[c][0]);
    t = fmin(0.65 * W, -0.65 * v->y0);        /* below the line, with room under it */
    pt_jview_label(sb, v, c == 2 ? 0.8 * W : t, c == 2 ? 0 : -t, 0, 13, "end", planes[c][1]);
    pt_jview_label(sb, v, v->x1, 0, -3, -4, "end", "w_k");
    snprintf(a, sizeof a, "%s against w_k", names[c]);
    pt_jtext(sb, v->bx + 2, v->by - 4, 10.5, "start", "fill=\"#222\"", a, 0);
    for (k = 0; k < m->nseg && k < PT_JOURNEY_MAXSEG; k++) {
        const pt_vrec *ra = &pt_jmodel_journey(jm, m->seg[k].a)->rec[PT_STAGE_CLIP];
        const pt_vrec *rb = &pt_jmodel_journey(jm, m->seg[k].b)->rec[PT_STAGE_CLIP];
        pt_jview_line(sb, v, ra->w, comp(ra, c), rb->w, comp(rb, c), "#b9bfc9", 1, "");
    }
}

static void bg_cvv(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    int b;
    char t[64];

    (void)st;
    bg_wedge(sb, jm, &jm->clip_z, 2);
    pt_jtext(sb, PT_JBOX_X + PT_JBOX_W / 2 + 8, PT_JBOX_Y + 12, 10.5, "start", "fill=\"#222\"",
             "outside a plane: its bit is 1", 0);
    for (b = 0; b < PT_CVV_NPLANES; b++) {
        snprintf(t, sizeof t, "0x%02x %s", 1u << b, pt_cvv_names[b]);
        pt_jtext(sb, PT_JBOX_X + PT_JBOX_W / 2 + 8, PT_JBOX_Y + 32 + 18 * b, 10.5, "start",
                 "font-family=\"DejaVu Sans Mono, Menlo, Consolas, monospace\" " LABEL, t, 0);
    }
}

static void bg_ndc(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    double p[8][3];
    int i, d;

    (void)st;
    for (i = 0; i < 8; i++) {
        p[i][0] = i & 1 ? 1 : -1; p[i][1] = i & 2 ? 1 : -1; p[i][2] = i & 4 ? 1 : 0;
    }
    for (i = 0; i < 8; i++)                  /* each edge once: to a corner one bit up */
        for (d = 1; d < 8; d <<= 1)
            if (!(i & d)) pt_jline3(sb, &jm->view[PT_STAGE_NDC], PT_STAGE_NDC, p[i], p[i | d], PT_JC_EDGE, 1.5, "");
    axes3(sb, jm, PT_STAGE_NDC, 1.2, "n");
    pt_jwireframe(sb, jm, PT_STAGE_NDC);
    pt_jtext(sb, PT_JBOX_X + 6, PT_JBOX_Y + PT_JBOX_H - 8, 10, "start", LABEL,
             "the cube -1 <= x_n, y_n <= 1, 0 <= z_n <= 1", 0);
}

static void bg_screen(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    const pt_jview *v = &jm->view[PT_STAGE_SCREEN];
    double w = jm->par.w, h = jm->par.h, x0 = pt_jview_x(v, 0), y0 = pt_jview_y(v, 0);
    char t[64];

    (void)st;
    pt_jrect(sb, x0, y0, pt_jview_x(v, w) - x0, pt_jview_y(v, h) - y0, "#e6eefa", PT_JC_EDGE, "");
    pt_jview_label(sb, v, 0, 0, 0, -5, "start", "(0, 0)");
    snprintf(t, sizeof t, "(%d, %d)", jm->par.w, jm->par.h);
    pt_jview_label(sb, v, w, h, 0, 13, "end", t);
    pt_jview_label(sb, v, w, 0, 4, 10, "start", "x_s");
    pt_jview_label(sb, v, 0, h, -4, 0, "end", "y_s");
    pt_jwireframe(sb, jm, PT_STAGE_SCREEN);
}

static void bg_clip(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st)
{
    (void)st;
    bg_wedge(sb, jm, &jm->view[PT_STAGE_CLIP], 0);
    bg_wedge(sb, jm, &jm->clip_y, 1);
}

/* ===== foregrounds ===== */

/* Vertex k's segments in a clip-space plot, the cuts clipping made on them,
** and the vertex. */
static void fg_wedge(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, int c, size_t k)
{
    const pt_model *m = jm->m;
    const pt_vrec *r = &pt_jmodel_journey(jm, k)->rec[PT_STAGE_CLIP];
    size_t s;
    int e;

    for (s = 0; s < m->nseg; s++) {
        const pt_vrec *ra, *rb;
        if (m->seg[s].a != k && m->seg[s].b != k) continue;
        ra = &pt_jmodel_journey(jm, m->seg[s].a)->rec[PT_STAGE_CLIP];
        rb = &pt_jmodel_journey(jm, m->seg[s].b)->rec[PT_STAGE_CLIP];
        pt_jview_line(sb, v, ra->w, comp(ra, c), rb->w, comp(rb, c), PT_JC_SEG, 2,
                      "stroke-linecap=\"round\"");
        for (e = 0; e < 2; e++) {            /* where clipping cut it */
            size_t i = jm->cutix[2 * s + e];
            const pt_vrec *q;
            if (i == 0 || i == PT_JOURNEY_CULLED) continue;
            q = &jm->cut[i - 1].rec[PT_STAGE_CLIP];
            if (!pt_jview_in(v, q->w, comp(q, c))) continue;
            pt_jrect(sb, pt_jview_x(v, q->w) - 4, pt_jview_y(v, comp(q, c)) - 4, 8, 8, "#fff",
                     PT_JC_VTX, "stroke-width=\"1.5\" class=\"cut\"");
            pt_jlabel_at(sb, pt_jview_x(v, q->w) + 6, pt_jview_y(v, comp(q, c)) + 12, 10, "start",
                      "fill=\"" PT_JC_VTX "\"", "cut", 0, PT_JLAB_OTHER);
        }
    }
    pt_jmarker(sb, v, isfinite(r->w) && isfinite(comp(r, c)), r->w, comp(r, c), k + 1, 0,
               NULL, NULL);
}

static void cuts(pt_sbuf *sb, const pt_jmodel *jm, size_t k, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    const pt_model *m = jm->m;
    size_t s;
    int e;

    for (s = 0; s < m->nseg; s++) {
        if (m->seg[s].a != k && m->seg[s].b != k) continue;
        for (e = 0; e < 2; e++) {
            size_t i = jm->cutix[2 * s + e];
            double x, y;
            if (i == 0 || i == PT_JOURNEY_CULLED) continue;
            if (!pt_jstage_xy(&jm->cut[i - 1], st, &x, &y) || !pt_jview_in(v, x, y)) continue;
            pt_jrect(sb, pt_jview_x(v, x) - 4, pt_jview_y(v, y) - 4, 8, 8, "#fff", PT_JC_VTX,
                     "stroke-width=\"1.5\" class=\"cut\"");
        }
    }
}

/* The outcode: each plane's distance (inside >= 0) and bit. */
static void fg_code(pt_sbuf *sb, const pt_vrec *r)
{
    pt_vec4 q;
    double d[PT_CVV_NPLANES];
    char t[96], a[PT_NUMLEN];
    int b;

    q.x = r->x; q.y = r->y; q.z = r->z; q.w = r->w;
    pt_cvv_distances(q, d);
    for (b = 0; b < PT_CVV_NPLANES; b++) {
        int out = (r->code >> b) & 1;
        pt_fmt_shortest(a, d[b]);
        snprintf(t, sizeof t, "%d  d = %s", out, a);
        pt_jtext(sb, PT_JBOX_X + PT_JBOX_W / 2 + 84, PT_JBOX_Y + 32 + 18 * (double)b, 10.5, "start",
                 out ? "font-weight=\"bold\" fill=\"" PT_JC_VTX "\"" : LABEL, t, PT_JBOX_W / 2 - 88);
    }
    snprintf(t, sizeof t, "code = %u", r->code);
    pt_jtext(sb, PT_JBOX_X + PT_JBOX_W / 2 + 8, PT_JBOX_Y + 32 + 18 * PT_CVV_NPLANES + 6, 13, "start",
             "font-weight=\"bold\" fill=\"" PT_JC_VTX "\"", t, 0);
    pt_jtext(sb, PT_JBOX_X + PT_JBOX_W / 2 + 8, PT_JBOX_Y + 32 + 18 * PT_CVV_NPLANES + 24, 10, "start", LABEL,
             "d: the signed distance, inside >= 0", 0);
}

void pt_jmatrix_stopped_fg(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k,
                          pt_stage st)
{
    char t[160];

    (void)j;
    if (st != PT_STAGE_INDEX) pt_jsegments(sb, jm, &jm->view[st], st, k, 2);
    if (st == PT_STAGE_NDC || st == PT_STAGE_SCREEN) cuts(sb, jm, k, st);
    snprintf(t, sizeof t, "v%llu stops at the cvv", (unsigned long long)(k + 1));
    pt_jlabel_at(sb, PT_JBOX_X + PT_JBOX_W / 2, PT_JBOX_Y + PT_JBOX_H / 2, 12, "middle",
                 "fill=\"" PT_JC_VTX "\" " PT_JHALO, t, PT_JBOX_W - 10, PT_JLAB_OTHER);
    pt_jlabel_at(sb, PT_JBOX_X + PT_JBOX_W / 2, PT_JBOX_Y + PT_JBOX_H / 2 + 17, 10.5, "middle",
                 LABEL " " PT_JHALO, "its segments: from the cuts", PT_JBOX_W - 10, PT_JLAB_OTHER);
}

static void fg_clip(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    (void)j; (void)st;
    fg_wedge(sb, jm, &jm->view[PT_STAGE_CLIP], 0, k);
    fg_wedge(sb, jm, &jm->clip_y, 1, k);
}

static void fg_cvv(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    (void)st;
    fg_wedge(sb, jm, &jm->clip_z, 2, k);
    fg_code(sb, &j->rec[PT_STAGE_CVV]);
}

static void fg_world(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    pt_jfg_path(sb, jm, j, st);
    pt_jfg_point(sb, jm, j, k, st);
}

/* NDC and screen: the segments from the cuts, the cuts marked, the vertex. */
static void fg_cut(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st)
{
    const pt_jview *v = &jm->view[st];
    double x, y;
    int ok = pt_jstage_xy(j, st, &x, &y);

    pt_jsegments(sb, jm, v, st, k, 2);
    cuts(sb, jm, k, st);
    pt_jmarker(sb, v, ok, x, y, (uint64_t)k + 1, 0, NULL, NULL);
}

size_t pt_jmatrix_unreached(char *t, size_t n, pt_stage st)
{
    size_t len = 0;
    int k, c = pt_coord_count(st);

    t[0] = '\0';
    for (k = 0; k < c && len < n; k++)
        len += (size_t)snprintf(t + len, n - len, "%s%s", k ? ", " : c > 1 ? "(" : "",
                                pt_coord_name(st, k));
    if (len < n) len += (size_t)snprintf(t + len, n - len, "%s: not reached", c > 1 ? ")" : "");
    return len;
}

/* ===== notes ===== */

void pt_jmatrix_stopped_note(char *t, size_t n, const pt_journey *j, pt_stage st)
{
    (void)st;
    snprintf(t, n, "not reached: the vertex is outside the view volume (cvv code %u)",
             j->rec[PT_STAGE_CVV].code);
}

/* What a stage's note says whatever the vertex, or NULL (note_of() says). */
static const char *const said[PT_NSTAGES_ALL] = {
    [PT_STAGE_WORLD] = "the model placed in the world: its world lines, then translate",
    [PT_STAGE_CLIP] = "inside when -w_k <= x_k, y_k <= w_k and 0 <= z_k <= w_k",
    [PT_STAGE_NDC] = "divided by w_k: inside the cube",
    [PT_STAGE_SCREEN] = "y grows downward; pixel (i, j) covers i <= x_s < i + 1, j <= y_s < j + 1",
};

static void note_of(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                    int used)
{
    const pt_vrec *r = &j->rec[st];

    (void)jm; (void)used;
    if (said[st]) snprintf(t, n, "%s", said[st]);
    else if (st == PT_STAGE_VIEW)
        snprintf(t, n, "%s", r->z > 0 ? "in front of the eye (z_v > 0)"
                 : "not in front of the eye (z_v <= 0): the near plane clips it");
    else if (st == PT_STAGE_CVV)
        snprintf(t, n, "%s", r->code == 0 ? "inside the view volume: on to the divide by w_k"
                 : "outside: its segments are clipped before the divide");
}

/* ===== the rows (jrows.c) ===== */

const pt_jstage_row pt_jmatrix_rows[PT_NSTAGES_ALL] = {
    [PT_STAGE_WORLD]  = { bg_world, fg_world, note_of },
    [PT_STAGE_VIEW]   = { bg_view, pt_jfg_point, note_of },
    [PT_STAGE_CLIP]   = { bg_clip, fg_clip, note_of },
    [PT_STAGE_CVV]    = { bg_cvv, fg_cvv, note_of },
    [PT_STAGE_NDC]    = { bg_ndc, fg_cut, note_of },
    [PT_STAGE_SCREEN] = { bg_screen, fg_cut, note_of },
};
