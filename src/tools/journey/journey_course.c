/*
** src/tools/journey/journey_course.c -- renderers 7 and 9: one vertex's journey drawn (SVG)
** See LICENSE for copyright and license.
**
** One render of the scene (pt_course_render) is heard for the position of
** the model drawn: its model after each stage (kept whole: the wireframe of
** every panel), the cuts both clip stages make, the pixels the rasterizer
** writes with their anti-aliasing weight (stages/pt_color.h's pt_aa_weight).
** The vertex's numbers are pt_cx_run()'s (io/explain_course.h).  Nothing
** here computes a stage: each panel only places what the run reported.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/journey/journey_course.h"
#include "tools/journey/jdraw.h"
#include "tools/journey/jmodel.h"
#include "io/explain_course.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

#define GAP     16               /* between panels, SVG units */
#define HEAD    70               /* the document's title lines */
#define COLS    4
#define BIG     1e6              /* coordinates beyond this never widen a panel */
#define REACH   4.0              /* a plane panel shows at most REACH times its square */
#define MAXPX   200000           /* pixels kept for the viewport panel */
#define MAXSEG  4000             /* segments drawn per panel */
#define LABEL_Y 306.0
#define NOTE_Y  326.0

/* ===== listening to the render ===== */

typedef struct snap {            /* the position's model after one stage */
    int have;
    pt_vec4 *v;  size_t nv;
    pt_rv_prim *p;  size_t np;
} snap;

typedef struct jpx {             /* a pixel written, viewport coordinates */
    int x, y;
    float w;                     /* its weight: 1, or AA's 1 - f or f */
} jpx;

typedef struct crun {
    size_t mi;                   /* the position heard */
    size_t cur;                  /* the position the clip stages work on */
    int drawing;                 /* 1: the rasterizer draws position mi */
    snap st[PT_NCST];
    pt_rv_cut *cut;  size_t ncut, capcut;
    jpx *px;  size_t npx, cappx;
    int morepx;                  /* pixels past MAXPX not kept */
    int failed;
} crun;

static void on_mark(void *ud, pt_course_mark k, const pt_course_cam *cam,
                    const pt_course_pos *pos)
{
    crun *c = ud;

    (void)cam;
    if (k == PT_CMK_POSITION || k == PT_CMK_STEP) c->cur = pos->index;
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    crun *c = ud;
    snap *s = &c->st[st];

    if (pos->index != c->mi || c->failed) return;
    free(s->v);
    free(s->p);
    s->v = malloc((m->nv ? m->nv : 1) * sizeof *s->v);
    s->p = malloc((m->np ? m->np : 1) * sizeof *s->p);
    if (!s->v || !s->p) { c->failed = 1; return; }
    if (m->nv) memcpy(s->v, m->v, m->nv * sizeof *s->v);
    if (m->np) memcpy(s->p, m->p, m->np * sizeof *s->p);
    s->nv = m->nv;
    s->np = m->np;
    s->have = 1;
}

static void on_cut(void *ud, const pt_rv_cut *cut)
{
    crun *c = ud;

    if (c->cur != c->mi || c->failed) return;
    if (c->ncut == c->capcut) {
        size_t cap = c->capcut ? 2 * c->capcut : 16;
        pt_rv_cut *n = realloc(c->cut, cap * sizeof *n);
        if (!n) { c->failed = 1; return; }
        c->cut = n;
        c->capcut = cap;
    }
    c->cut[c->ncut++] = *cut;
}

static void on_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    crun *c = ud;

    (void)m; (void)p;
    c->drawing = pos->index == c->mi;
}

static void add_px(crun *c, int x, int y, float w)
{
    if (c->failed) return;
    if (c->npx == MAXPX) { c->morepx = 1; return; }
    if (c->npx == c->cappx) {
        size_t cap = c->cappx ? 2 * c->cappx : 256;
        jpx *n = realloc(c->px, cap * sizeof *n);
        if (!n) { c->failed = 1; return; }
        c->px = n;
        c->cappx = cap;
    }
    c->px[c->npx].x = x;
    c->px[c->npx].y = y;
    c->px[c->npx].w = w;
    c->npx++;
}

/* A pixel line as the pixels it writes: an anti-aliased step is two, the
** lower weighted 1 - f, the upper f. */
static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    crun *c = ud;

    if (!c->drawing) return;
    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
        add_px(c, px->x_vp, px->y_vp, 1.0f);
        break;
    case PT_RV_PX_POINT:
        if (!px->clipped) add_px(c, px->x_vp, px->y_vp, 1.0f);
        break;
    case PT_RV_PX_AA: {
        double a = px->transposed ? px->x_pp : px->y_pp;
        float f = pt_aa_weight(a, floor(a));
        if (px->transposed) {
            add_px(c, px->lo, px->y_vp, 1.0f - f);
            add_px(c, px->hi, px->y_vp, f);
        } else {
            add_px(c, px->x_vp, px->lo, 1.0f - f);
            add_px(c, px->x_vp, px->hi, f);
        }
        break;
    }
    }
}

static void crun_free(crun *c)
{
    int i;

    for (i = 0; i < PT_NCST; i++) {
        free(c->st[i].v);
        free(c->st[i].p);
    }
    free(c->cut);
    free(c->px);
}

/* Render s once, hearing position mi.  Returns 0, or -1 when out of memory. */
static int crun_run(crun *c, const pt_scene *s, size_t mi)
{
    pt_rv_raster_ls rls;
    pt_course_ls ls;
    pt_fb fb;
    int rc;

    memset(c, 0, sizeof *c);
    c->mi = mi;
    c->cur = (size_t)-1;
    memset(&rls, 0, sizeof rls);
    rls.pixel = on_pixel;
    rls.ud = c;
    memset(&ls, 0, sizeof ls);
    ls.mark = on_mark;
    ls.stage = on_stage;
    ls.raster = on_raster;
    ls.nearclip.cut = ls.clip.cut = on_cut;
    ls.nearclip.ud = ls.clip.ud = c;
    ls.raster_ls = &rls;
    ls.ud = c;
    if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) return -1;
    rc = pt_course_render(s, &fb, &ls);
    pt_fb_free(&fb);
    return rc != 0 || c->failed ? -1 : 0;
}

/* ===== the panels ===== */

/* What a panel shows of a stage's model: its points in panel data
** coordinates. */
typedef enum view_kind { VK_SPACE, VK_SIDE, VK_PLANE } view_kind;

typedef struct cpanel {
    const char *key;             /* data-stage */
    const char *title, *coords;  /* "view volume", "(x_v, y_v, z_v)" */
    const char *formula;
    pt_course_stage st;          /* the model drawn and the vertex's value shown */
    view_kind kind;
} cpanel;

typedef struct cdoc {
    const pt_scene *s;
    const pt_cx_journey *j;
    const crun *c;
    pt_rv_camera cam;
} cdoc;

static void xy_of(view_kind k, pt_vec4 p, double *x, double *y)
{
    if (k == VK_SPACE) pt_jproj(PT_STAGE_MODEL, p.x, p.y, p.z, x, y);
    else if (k == VK_SIDE) { *x = p.z; *y = p.y; }
    else { *x = p.x; *y = p.y; }
}

static void grow(double b[4], double x, double y)
{
    if (!(fabs(x) <= BIG && fabs(y) <= BIG)) return;
    if (x < b[0]) b[0] = x;
    if (y < b[1]) b[1] = y;
    if (x > b[2]) b[2] = x;
    if (y > b[3]) b[3] = y;
}

/* 1 when vertex k of the stage's model is an end of one of its primitives. */
static int used(const snap *sn, size_t k)
{
    size_t i;

    for (i = 0; i < sn->np; i++)
        if (sn->p[i].v[0] == k || (sn->p[i].kind == PT_RV_LINE && sn->p[i].v[1] == k)) return 1;
    return 0;
}

/* The shortest decimal of x that reads back to it. */
static void num(pt_sbuf *sb, double x)
{
    char b[PT_NUMLEN];

    pt_fmt_shortest(b, x);
    pt_sbuf_add(sb, b);
}

/* The model's segments (and points) in view v, faint or in the segments'
** blue; the ones at vertex k (0-based) wider. */
static void wire(pt_sbuf *sb, const pt_jview *v, const snap *sn, view_kind kind, size_t k,
                 int faint)
{
    size_t i, n = sn->np < MAXSEG ? sn->np : MAXSEG;

    for (i = 0; i < n; i++) {
        const pt_rv_prim *p = &sn->p[i];
        double ax, ay, bx, by;
        int at;
        if (p->v[0] >= sn->nv || (p->kind == PT_RV_LINE && p->v[1] >= sn->nv)) continue;
        at = p->v[0] == k || (p->kind == PT_RV_LINE && p->v[1] == k);
        xy_of(kind, sn->v[p->v[0]], &ax, &ay);
        if (p->kind == PT_RV_POINT) {
            if (pt_jview_in(v, ax, ay))
                pt_jcircle(sb, pt_jview_x(v, ax), pt_jview_y(v, ay), 2.5,
                           faint ? PT_JC_FAINT : PT_JC_SEG, "");
            continue;
        }
        xy_of(kind, sn->v[p->v[1]], &bx, &by);
        pt_jview_line(sb, v, ax, ay, bx, by, faint ? PT_JC_FAINT : PT_JC_SEG,
                      faint ? 1 : at ? 2.5 : 1.4, "");
    }
}

/* The window of a panel: the points of the model drawn, and the frame's. */
static void fit(pt_jview *v, double b[4], int ydown)
{
    double p = fmax(fmax(b[2] - b[0], b[3] - b[1]) * 0.08, 1e-9);

    b[0] -= p; b[1] -= p; b[2] += p; b[3] += p;
    pt_jview_fit(v, b, ydown, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H);
}

static void grow_snap(double b[4], const snap *sn, view_kind kind)
{
    size_t k;
    double x, y;

    for (k = 0; k < sn->nv; k++)
        if (used(sn, k)) {
            xy_of(kind, sn->v[k], &x, &y);
            grow(b, x, y);
        }
}

/* The side view's frame: the camera at the origin, the volume's edges (y =
** -z*t, y = -z*b; the box y = b, y = t orthographic) to depth zf, the
** near plane z = n, and the image plane z = -1 (perspective). */
static void side_frame(pt_sbuf *sb, const pt_jview *v, int persp, double b, double t, double n,
                       double zf, int nearclip)
{
    char lab[64], nb[PT_NUMLEN];

    pt_jview_line(sb, v, -BIG, 0, BIG, 0, PT_JC_AXIS, 0.8, "stroke-dasharray=\"3 3\"");
    pt_jview_line(sb, v, 0, -BIG, 0, BIG, PT_JC_AXIS, 0.8, "stroke-dasharray=\"3 3\"");
    pt_jview_label(sb, v, zf, 0, 0, -4, "start", "z");
    if (persp) {
        pt_jview_line(sb, v, 0, 0, zf, -zf * t, PT_JC_EDGE, 1.2, "");
        pt_jview_line(sb, v, 0, 0, zf, -zf * b, PT_JC_EDGE, 1.2, "");
        pt_jview_line(sb, v, -1, t, -1, b, PT_JC_EDGE, 1, "stroke-dasharray=\"2 2\"");
        pt_jview_label(sb, v, -1, t, 0, -6, "middle", "z = -1");
        if (nearclip) pt_jview_line(sb, v, n, -n * t, n, -n * b, PT_JC_VTX, 1.4, "");
    } else {
        pt_jview_line(sb, v, 0, t, zf, t, PT_JC_EDGE, 1.2, "");
        pt_jview_line(sb, v, 0, b, zf, b, PT_JC_EDGE, 1.2, "");
        if (nearclip) pt_jview_line(sb, v, n, t, n, b, PT_JC_VTX, 1.4, "");
    }
    if (nearclip) {
        pt_fmt_shortest(nb, n);
        snprintf(lab, sizeof lab, "z = n = %s", nb);
        pt_jview_label(sb, v, n, persp ? -n * b : b, 0, 12, "middle", lab);
    }
    pt_jcircle(sb, pt_jview_x(v, 0), pt_jview_y(v, 0), 3, PT_JC_TEXT, "");
}

/* The cut points of one clip stage (near: 1, rectangle: 0) in view v, each
** with its t. */
static void cuts(pt_sbuf *sb, const pt_jview *v, const crun *c, int nearc, view_kind kind)
{
    size_t i;
    char lab[48], nb[PT_NUMLEN];

    for (i = 0; i < c->ncut; i++) {
        const pt_rv_cut *cu = &c->cut[i];
        double x, y;
        if ((cu->edge == PT_RV_NEAR) != nearc) continue;
        xy_of(kind, cu->p[2], &x, &y);
        if (!pt_jview_in(v, x, y)) continue;
        pt_jcircle(sb, pt_jview_x(v, x), pt_jview_y(v, y), 3.5, "none",
                   "class=\"cut\" stroke=\"#e08a00\" stroke-width=\"1.6\"");
        pt_fmt_shortest(nb, cu->t);
        snprintf(lab, sizeof lab, "v%lu t=%.5s", (unsigned long)cu->v_new + 1, nb);
        pt_jview_label(sb, v, x, y, 5, -5, "start", lab);
    }
}

/* The panel's frame, title and formula. */
static void frame(pt_sbuf *sb, int no, const cpanel *p)
{
    char t[160];

    pt_jrect(sb, 0.5, 0.5, PT_JOURNEY_PW - 1, PT_JOURNEY_PH - 1, "#fff", PT_JC_FRAME, "rx=\"6\"");
    snprintf(t, sizeof t, "%d  %s  %s", no, p->title, p->coords);
    pt_jtext(sb, 12, 21, 15, "start", "font-weight=\"bold\" fill=\"" PT_JC_TEXT "\"", t, 376);
    pt_jtext(sb, 12, 36, 10.5, "start", "font-family=\"" PT_JMONO "\" fill=\"" PT_JC_NOTE "\"",
             p->formula, 376);
    pt_jrect(sb, PT_JBOX_X, PT_JBOX_Y, PT_JBOX_W, PT_JBOX_H, "#fbfcfe", "#e3e6eb", "");
}

/* The vertex's coordinates label and the note under it. */
static void caption(pt_sbuf *sb, const cdoc *d, const cpanel *p, pt_course_stage st)
{
    const pt_cx_journey *j = d->j;
    pt_sbuf t;

    pt_sbuf_init(&t);
    pt_sbuf_add(&t, p->coords);
    if (j->have[st]) {
        pt_vec4 a = j->at[st];
        pt_sbuf_add(&t, " = (");
        num(&t, a.x); pt_sbuf_add(&t, ", ");
        num(&t, a.y); pt_sbuf_add(&t, ", ");
        num(&t, a.z); pt_sbuf_add(&t, ")");
    } else {
        pt_sbuf_add(&t, ": not yet, the vertex is made by ");
        pt_sbuf_add(&t, j->born == PT_CST_NEARCLIP ? "the near clip" : "the clip");
    }
    pt_jtext(sb, 12, LABEL_Y, 12, "start", "class=\"coords\" font-family=\"" PT_JMONO
             "\" fill=\"" PT_JC_TEXT "\"", t.s ? t.s : "", 376);
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
}

/* The note: what the stage did to the vertex (made it, cut it off). */
static void note(pt_sbuf *sb, const cdoc *d, pt_course_stage st, const char *more)
{
    const pt_cx_journey *j = d->j;
    pt_sbuf t;
    size_t i;
    int off = 0;

    pt_sbuf_init(&t);
    if (j->born == st && st != PT_CST_MODEL) {
        pt_sbuf_addf(&t, "made by this stage: segment %llu cut at t = ",
                     (unsigned long long)j->cut_prim);
        num(&t, j->cut.t);
        pt_sbuf_add(&t, "; ");
    }
    for (i = 0; i < j->noff; i++)
        if (j->off[i].stage == st) off++;
    if (off) pt_sbuf_addf(&t, "cut off %d segment%s here; ", off, off > 1 ? "s" : "");
    if (j->have[st] && d->c->st[st].have && !used(&d->c->st[st], (size_t)(j->v - 1)))
        pt_sbuf_add(&t, "no primitive uses it after this stage; ");
    pt_sbuf_add(&t, more);
    pt_jtext(sb, 12, NOTE_Y, 11, "start", "class=\"note\" fill=\"" PT_JC_NOTE "\"",
             t.s ? t.s : "", 376);
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
}

/* The vertex's marker at its value after stage st, in view v. */
static void marker(pt_sbuf *sb, const pt_jview *v, const cdoc *d, pt_course_stage st,
                   view_kind kind)
{
    double x = 0, y = 0;

    if (d->j->have[st]) xy_of(kind, d->j->at[st], &x, &y);
    pt_jmarker(sb, v, d->j->have[st], x, y, d->j->v, 0, NULL, NULL);
}

/* A 3-D panel (model, world, view): the model's wireframe and its axes. */
static void panel_space(pt_sbuf *sb, const cdoc *d, const cpanel *p)
{
    const snap *sn = &d->c->st[p->st];
    double b[4] = {0, 0, 0, 0};
    pt_jview v;
    size_t k;
    double big = 0;

    for (k = 0; k < sn->nv; k++)
        if (used(sn, k)) {
            double m = fmax(fabs(sn->v[k].x), fmax(fabs(sn->v[k].y), fabs(sn->v[k].z)));
            if (m <= BIG && m > big) big = m;
        }
    big = big > 0 ? 1.2 * big : 1;
    {
        double ax[3][3] = {{big, 0, 0}, {0, big, 0}, {0, 0, big}}, x, y;
        int i;
        for (i = 0; i < 3; i++) {
            pt_jproj(PT_STAGE_MODEL, ax[i][0], ax[i][1], ax[i][2], &x, &y); grow(b, x, y);
            pt_jproj(PT_STAGE_MODEL, -ax[i][0], -ax[i][1], -ax[i][2], &x, &y); grow(b, x, y);
        }
    }
    grow_snap(b, sn, VK_SPACE);
    fit(&v, b, 0);
    pt_jaxis3(sb, &v, PT_STAGE_MODEL, big, 0, 0, "x");
    pt_jaxis3(sb, &v, PT_STAGE_MODEL, 0, big, 0, "y");
    pt_jaxis3(sb, &v, PT_STAGE_MODEL, 0, 0, big, "z");
    wire(sb, &v, sn, VK_SPACE, (size_t)(d->j->v - 1), 0);
    marker(sb, &v, d, p->st, VK_SPACE);
}

/* A side view (view volume, normalized, near clip). */
static void panel_side(pt_sbuf *sb, const cdoc *d, const cpanel *p)
{
    const snap *sn = &d->c->st[p->st];
    const pt_rv_camera *cam = &d->cam;
    int norm = p->st != PT_CST_VIEW, persp = cam->perspective;
    double bb = norm ? -1 : cam->b, tt = norm ? 1 : cam->t, n = cam->n;
    double b[4], zf = -1.2;
    pt_jview v;
    size_t k;

    for (k = 0; k < sn->nv; k++)
        if (used(sn, k) && sn->v[k].z <= BIG && 1.1 * sn->v[k].z < zf) zf = 1.1 * sn->v[k].z;
    if (n < 0 && 1.2 * n < zf) zf = 1.2 * n;
    b[0] = zf; b[2] = 0.1;
    b[1] = persp ? fmin(0, fmin(-zf * bb, -zf * tt)) : fmin(bb, 0);
    b[3] = persp ? fmax(0, fmax(-zf * bb, -zf * tt)) : fmax(tt, 0);
    if (p->st == PT_CST_NEARCLIP) grow_snap(b, &d->c->st[PT_CST_CAMERA], VK_SIDE);
    grow_snap(b, sn, VK_SIDE);
    fit(&v, b, 0);
    side_frame(sb, &v, persp, bb, tt, n, zf, d->s->nearclip);
    if (p->st == PT_CST_NEARCLIP) wire(sb, &v, &d->c->st[PT_CST_CAMERA], VK_SIDE, (size_t)-1, 1);
    wire(sb, &v, sn, VK_SIDE, (size_t)(d->j->v - 1), 0);
    if (p->st == PT_CST_NEARCLIP) cuts(sb, &v, d->c, 1, VK_SIDE);
    marker(sb, &v, d, p->st, VK_SIDE);
}

/* The image plane: the view square, the projected model (faint), the
** clip's segments and its cut points. */
static void panel_image(pt_sbuf *sb, const cdoc *d, const cpanel *p)
{
    static const double sq[4] = {-1, -1, 1, 1};
    const snap *im = &d->c->st[PT_CST_IMAGE], *cl = &d->c->st[PT_CST_CLIP];
    double b[4] = {-1, -1, 1, 1};
    pt_jview v;
    pt_course_stage st = d->j->have[PT_CST_IMAGE] ? PT_CST_IMAGE : PT_CST_CLIP;

    (void)p;
    grow_snap(b, im, VK_PLANE);
    b[0] = fmax(b[0], -REACH); b[1] = fmax(b[1], -REACH);
    b[2] = fmin(b[2], REACH); b[3] = fmin(b[3], REACH);
    fit(&v, b, 0);
    pt_jrect(sb, pt_jview_x(&v, -1), pt_jview_y(&v, 1), 2 * v.s, 2 * v.s, PT_JC_AREA, "", "");
    pt_joutline(sb, &v, sq, PT_JC_EDGE, 1.2);
    pt_jview_line(sb, &v, -BIG, 0, BIG, 0, PT_JC_AXIS, 0.8, "stroke-dasharray=\"3 3\"");
    pt_jview_line(sb, &v, 0, -BIG, 0, BIG, PT_JC_AXIS, 0.8, "stroke-dasharray=\"3 3\"");
    pt_jview_label(sb, &v, 1, 1, 3, -4, "start", "(1, 1)");
    pt_jview_label(sb, &v, -1, -1, -3, 12, "end", "(-1, -1)");
    wire(sb, &v, im, VK_PLANE, (size_t)-1, 1);
    wire(sb, &v, cl, VK_PLANE, (size_t)(d->j->v - 1), 0);
    cuts(sb, &v, d->c, 0, VK_PLANE);
    marker(sb, &v, d, st, VK_PLANE);
}

/* The viewport: its pixel grid, the position's pixels, the vertex's. */
static void panel_viewport(pt_sbuf *sb, const cdoc *d)
{
    const pt_cx_journey *j = d->j;
    double r[4], b[4];
    pt_jview v;
    size_t i;
    char t[160];

    r[0] = 0; r[1] = 0; r[2] = j->par.w; r[3] = j->par.h;
    memcpy(b, r, sizeof b);
    fit(&v, b, 1);
    pt_jgrid(sb, &v, r, 0, 6);
    for (i = 0; i < d->c->npx; i++) {
        const jpx *q = &d->c->px[i];
        char op[64], wb[PT_NUMLEN];
        if (q->w <= 0) continue;
        pt_fmt_fixed(wb, (double)q->w, 3);
        snprintf(op, sizeof op, "fill-opacity=\"%s\"", wb);
        pt_jview_rect(sb, &v, q->x, q->y, 1, 1, PT_JC_SEG, "", op, 0.6);
    }
    pt_joutline(sb, &v, r, PT_JC_EDGE, 1.2);
    if (j->mapped)
        pt_jmarker(sb, &v, 1, (double)j->px_x + 0.5, (double)j->px_y + 0.5, j->v, 1, NULL, NULL);
    if (j->mapped)
        snprintf(t, sizeof t, "(x_vp, y_vp) = (%lld, %lld)", (long long)j->px_x,
                 (long long)j->px_y);
    else
        snprintf(t, sizeof t, "(x_vp, y_vp): none, outside the view square after the clip");
    pt_jtext(sb, 12, LABEL_Y, 12, "start", "class=\"coords\" font-family=\"" PT_JMONO
             "\" fill=\"" PT_JC_TEXT "\"", t, 376);
    snprintf(t, sizeof t, "%dx%d viewport at (%d, %d); %s%s", j->par.w, j->par.h, j->par.x_ul,
             j->par.y_ul, j->par.antialias ? "anti-aliased pixels shaded by their weight"
                                           : "every pixel drawn",
             d->c->morepx ? "; not every pixel shown" : "");
    pt_jtext(sb, 12, NOTE_Y, 11, "start", "class=\"note\" fill=\"" PT_JC_NOTE "\"", t, 376);
}

static const cpanel panels[] = {
    { "model", "model", "(x_m, y_m, z_m)", "the scene's vertices", PT_CST_MODEL, VK_SPACE },
    { "world", "world", "(x_w, y_w, z_w)", "v_w = M v_m (the position's matrix)",
      PT_CST_WORLD, VK_SPACE },
    { "view", "view", "(x_v, y_v, z_v)", NULL, PT_CST_VIEW, VK_SPACE },
    { "volume", "view volume", "(x_v, y_v, z_v)", NULL, PT_CST_VIEW, VK_SIDE },
    { "camera", "normalized", "(x_c, y_c, z_c)", "l..r, b..t become -1..1; z_c = z_v",
      PT_CST_CAMERA, VK_SIDE },
    { "nearclip", "near clip", "(x_c, y_c, z_c)", "cut at z = n: t = (n - z1)/(z0 - z1)",
      PT_CST_NEARCLIP, VK_SIDE },
    { "image", "image plane", "(x_p, y_p, z_p)", NULL, PT_CST_IMAGE, VK_PLANE },
    { "viewport", "viewport", "(x_vp, y_vp)", "x_vp = Math.round(x_pp) - 1, "
      "y_vp = h - Math.round(y_pp)", PT_CST_CLIP, VK_PLANE },
};
#define NPANELS (sizeof panels / sizeof panels[0])

static void panel(pt_sbuf *sb, const cdoc *d, const cpanel *p, int no)
{
    cpanel q = *p;
    char more[160];

    more[0] = '\0';
    if (!strcmp(p->key, "view"))
        q.formula = d->j->renderer == 9 ? "v_v = v_w - view vector" : "v_v = v_m + t";
    if (!strcmp(p->key, "volume"))
        q.formula = d->cam.perspective ? "camera at 0 looking down -z; l..r, b..t at z = -1"
                                       : "the box l..r x b..t along -z";
    if (!strcmp(p->key, "image"))
        q.formula = d->cam.perspective ? "x_p = x_c / -z_c, y_p = y_c / -z_c; clip to -1..1"
                                       : "x_p = x_c, y_p = y_c; clip to -1..1";
    frame(sb, no, &q);
    switch (p->kind) {
    case VK_SPACE: panel_space(sb, d, p); break;
    case VK_SIDE: panel_side(sb, d, p); break;
    case VK_PLANE:
        if (p->st == PT_CST_IMAGE) panel_image(sb, d, p);
        else { panel_viewport(sb, d); return; }
        break;
    }
    if (p->st == PT_CST_IMAGE) {
        caption(sb, d, &q, d->j->have[PT_CST_IMAGE] ? PT_CST_IMAGE : PT_CST_CLIP);
        note(sb, d, PT_CST_CLIP, "orange rings: the clip's cut points");
        return;
    }
    caption(sb, d, &q, p->st);
    if (p->st == PT_CST_NEARCLIP)
        snprintf(more, sizeof more, "%s", d->s->nearclip ? "orange rings: the cut points"
                                                           : "the near clip is off");
    if (!strcmp(p->key, "volume"))
        snprintf(more, sizeof more, "side view: z_v across, y_v up; x from l to r likewise");
    note(sb, d, p->st, more);
}

int pt_journey_course_svg(pt_sbuf *sb, const pt_scene *s, size_t mi, uint64_t v)
{
    static pt_cx_journey j;      /* large: not on the stack */
    pt_course_cam cc;
    crun c;
    cdoc d;
    size_t i;
    int rc, n = 0, no = 0, docw = COLS * PT_JOURNEY_PW + (COLS + 1) * GAP, doch;
    pt_sbuf t;

    if ((rc = pt_cx_run(&j, s, mi, v)) != 0) return rc;
    if (crun_run(&c, s, mi) != 0) { crun_free(&c); return -1; }
    pt_course_camera(s, &cc);
    d.s = s; d.j = &j; d.c = &c; d.cam = cc.cam;
    for (i = 0; i < NPANELS; i++)
        if (panels[i].st != PT_CST_WORLD || s->renderer == 9) n++;
    doch = HEAD + ((n + COLS - 1) / COLS) * (PT_JOURNEY_PH + GAP);
    pt_sbuf_add(sb, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    pt_sbuf_addf(sb, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %d %d\" "
                 "width=\"100%%\" font-family=\"%s\">\n", docw, doch, PT_JFONT);
    pt_sbuf_init(&t);
    pt_sbuf_addf(&t, "pipetrace journey: vertex %llu of model ", (unsigned long long)v);
    pt_sbuf_add(&t, s->models[mi].name);
    pt_sbuf_addf(&t, ", renderer %d", s->renderer);
    pt_sbuf_add(sb, "<title>");
    pt_sbuf_add_xml(sb, t.s ? t.s : "");
    pt_sbuf_add(sb, "</title>\n");
    pt_sbuf_addf(sb, "<rect width=\"%d\" height=\"%d\" fill=\"#f3f4f6\"/>\n", docw, doch);
    pt_jtext(sb, GAP, 30, 22, "start", "font-weight=\"bold\" fill=\"" PT_JC_TEXT "\"",
             t.s ? t.s : "", docw - 2 * GAP);
    t.len = 0;
    pt_sbuf_add(&t, "scene ");
    pt_sbuf_add(&t, s->path);
    pt_sbuf_add(&t, ": the course's stages, one panel each; every number is the render's");
    pt_jtext(sb, GAP, 50, 13, "start", "fill=\"" PT_JC_NOTE "\"", t.s ? t.s : "", docw - 2 * GAP);
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
    for (i = 0; i < NPANELS; i++) {
        int col, row, px, py;
        if (panels[i].st == PT_CST_WORLD && s->renderer != 9) continue;
        col = no % COLS; row = no / COLS;
        px = GAP + col * (PT_JOURNEY_PW + GAP);
        py = HEAD + row * (PT_JOURNEY_PH + GAP);
        no++;
        pt_sbuf_addf(sb, "<g class=\"panel\" data-stage=\"%s\" transform=\"translate(%d %d)\">\n",
                     panels[i].key, px, py);
        panel(sb, &d, &panels[i], no);
        pt_sbuf_add(sb, "</g>\n");
        if (col < COLS - 1 && no < n)
            pt_jarrow(sb, px + PT_JOURNEY_PW + 1, py + PT_JOURNEY_PH / 2.0,
                      px + PT_JOURNEY_PW + GAP - 2, py + PT_JOURNEY_PH / 2.0, 12, "#8a919b");
    }
    pt_sbuf_add(sb, "</svg>\n");
    crun_free(&c);
    return sb->failed ? -1 : 0;
}
