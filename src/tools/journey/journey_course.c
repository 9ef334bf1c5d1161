/*
** src/tools/journey/journey_course.c -- renderers 7 and 9: one vertex's journey drawn (SVG)
** See LICENSE for copyright and license.
**
** One render of the scene (pt_course_render) is heard for the position of
** the model drawn: of its model after each stage what the panels draw (the
** first PT_JOURNEY_MAXSEG primitives, the reach of the used vertices, a bit
** a vertex), the first cuts both clip stages make, the first pixels the
** rasterizer writes with their anti-aliasing weight (stages/pt_color.h's
** pt_aa_weight); the rest streams past without being kept.
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
#include "tools/journey/journey.h"
#include "tools/journey/journey_wasm.h"
#include "io/explain_course.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

#define GAP     16               /* between panels, SVG units */
#define HEAD    70               /* the document's title lines */
#define COLS    4
#define BIG     1e6              /* coordinates beyond this never widen a panel */
#define REACH   4.0              /* a plane panel shows at most REACH times its square */
#define MAXPX   200000           /* pixels kept for the viewport panel */
#define LABEL_Y 306.0
#define NOTE_Y  326.0

/* ===== listening to the render ===== */

/* What a panel needs of the position's model after one stage, gathered as
** the render passes it: its counts, which vertices a primitive uses (a bit
** each), the reach of those vertices in each view, and the first
** PT_JOURNEY_MAXSEG primitives with their ends (the wireframe drawn).  The
** model stage keeps its whole model only for the page (its sliders run the
** model again). */
typedef struct snap {
    int have;
    size_t nv, np;
    unsigned char *used;         /* bit k: vertex k is an end of a primitive */
    double box[3][4];            /* per view_kind: min x, min y, max x, max y of
                                 ** the used vertices grow() takes */
    double big;                  /* largest |coordinate| <= BIG of a used vertex */
    double zf;                   /* least 1.1 z_v of a used vertex, z_v <= BIG */
    pt_rv_prim *p;  size_t nkeep;/* the first primitives, at most PT_JOURNEY_MAXSEG */
    pt_vec4 *e;                  /* their ends: 2 a primitive */
    unsigned char *ok;           /* 1: both ends are vertices of the model */
    pt_rv_model whole;           /* the model stage's model (kept: have_whole) */
    int have_whole;
} snap;

typedef struct jpx {             /* a pixel written, viewport coordinates */
    int x, y;
    float w;                     /* its weight: 1, or AA's 1 - f or f */
} jpx;

typedef struct crun {
    size_t mi;                   /* the position heard */
    size_t cur;                  /* the position the clip stages work on */
    int drawing;                 /* 1: the rasterizer draws position mi */
    int whole;                   /* 1: keep the model stage's whole model */
    snap st[PT_NCST];
    pt_rv_cut *cut;  size_t ncut, capcut;
    int morecut;                 /* cuts past PT_JOURNEY_MAXSEG not kept */
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

typedef enum view_kind { VK_SPACE, VK_SIDE, VK_PLANE } view_kind;

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

static int bit(const unsigned char *b, size_t k)
{
    return (b[k / 8] >> (k % 8)) & 1;
}

static void snap_free(snap *s)
{
    free(s->used);
    free(s->p);
    free(s->e);
    free(s->ok);
    free(s->whole.v);
    free(s->whole.c);
    free(s->whole.p);
    memset(s, 0, sizeof *s);
}

/* Keep a copy of m whole in s (the model stage, for the page).  Returns 0,
** or -1 when out of memory. */
static int keep_whole(snap *s, const pt_rv_model *m)
{
    pt_rv_model *w = &s->whole;

    w->v = malloc((m->nv ? m->nv : 1) * sizeof *w->v);
    w->c = malloc((m->nc ? m->nc : 1) * sizeof *w->c);
    w->p = malloc((m->np ? m->np : 1) * sizeof *w->p);
    if (!w->v || !w->c || !w->p) return -1;
    if (m->nv) memcpy(w->v, m->v, m->nv * sizeof *w->v);
    if (m->nc) memcpy(w->c, m->c, m->nc * sizeof *w->c);
    if (m->np) memcpy(w->p, m->p, m->np * sizeof *w->p);
    w->nv = m->nv;
    w->nc = m->nc;
    w->np = m->np;
    s->have_whole = 1;
    return 0;
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    crun *c = ud;
    snap *s = &c->st[st];
    size_t i, k, n = m->np < PT_JOURNEY_MAXSEG ? m->np : PT_JOURNEY_MAXSEG;
    int kind;

    if (pos->index != c->mi || c->failed) return;
    snap_free(s);
    s->used = calloc(m->nv / 8 + 1, 1);
    s->p = malloc((n ? n : 1) * sizeof *s->p);
    s->e = malloc((n ? 2 * n : 1) * sizeof *s->e);
    s->ok = malloc(n ? n : 1);
    if (!s->used || !s->p || !s->e || !s->ok ||
        (st == PT_CST_MODEL && c->whole && keep_whole(s, m) != 0)) { c->failed = 1; return; }
    for (i = 0; i < m->np; i++) {
        const pt_rv_prim *p = &m->p[i];
        if (p->v[0] < m->nv) s->used[p->v[0] / 8] |= (unsigned char)(1u << (p->v[0] % 8));
        if (p->kind == PT_RV_LINE && p->v[1] < m->nv)
            s->used[p->v[1] / 8] |= (unsigned char)(1u << (p->v[1] % 8));
        if (i >= n) continue;
        s->p[i] = *p;
        s->ok[i] = p->v[0] < m->nv && (p->kind != PT_RV_LINE || p->v[1] < m->nv);
        if (!s->ok[i]) continue;
        s->e[2 * i] = m->v[p->v[0]];
        if (p->kind == PT_RV_LINE) s->e[2 * i + 1] = m->v[p->v[1]];
    }
    for (kind = 0; kind < 3; kind++) {
        s->box[kind][0] = s->box[kind][1] = HUGE_VAL;
        s->box[kind][2] = s->box[kind][3] = -HUGE_VAL;
    }
    s->big = 0;
    s->zf = HUGE_VAL;
    for (k = 0; k < m->nv; k++) {
        pt_vec4 q = m->v[k];
        double x, y, a;
        if (!bit(s->used, k)) continue;
        for (kind = 0; kind < 3; kind++) {
            xy_of((view_kind)kind, q, &x, &y);
            grow(s->box[kind], x, y);
        }
        a = fmax(fabs(q.x), fmax(fabs(q.y), fabs(q.z)));
        if (a <= BIG && a > s->big) s->big = a;
        if (q.z <= BIG && 1.1 * q.z < s->zf) s->zf = 1.1 * q.z;
    }
    s->nv = m->nv;
    s->np = m->np;
    s->nkeep = n;
    s->have = 1;
}

static void on_cut(void *ud, const pt_rv_cut *cut)
{
    crun *c = ud;

    if (c->cur != c->mi || c->failed) return;
    if (c->ncut == PT_JOURNEY_MAXSEG) { c->morecut = 1; return; }
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

    for (i = 0; i < PT_NCST; i++) snap_free(&c->st[i]);
    free(c->cut);
    free(c->px);
}

/* Render s once, hearing position mi (whole: keeping its model stage's
** model whole).  Returns 0, or -1 when out of memory. */
static int crun_run(crun *c, const pt_scene *s, size_t mi, int whole)
{
    pt_rv_raster_ls rls;
    pt_course_ls ls;
    pt_fb fb;
    int rc;

    memset(c, 0, sizeof *c);
    c->mi = mi;
    c->whole = whole;
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

/* 1 when vertex k of the stage's model is an end of one of its primitives. */
static int used(const snap *sn, size_t k)
{
    return k < sn->nv && bit(sn->used, k);
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
    size_t i;

    for (i = 0; i < sn->nkeep; i++) {
        const pt_rv_prim *p = &sn->p[i];
        double ax, ay, bx, by;
        int at;
        if (!sn->ok[i]) continue;
        at = p->v[0] == k || (p->kind == PT_RV_LINE && p->v[1] == k);
        xy_of(kind, sn->e[2 * i], &ax, &ay);
        if (p->kind == PT_RV_POINT) {
            if (pt_jview_in(v, ax, ay))
                pt_jcircle(sb, pt_jview_x(v, ax), pt_jview_y(v, ay), 2.5,
                           faint ? PT_JC_FAINT : PT_JC_SEG, "");
            continue;
        }
        xy_of(kind, sn->e[2 * i + 1], &bx, &by);
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

/* Grow b by the used vertices of the stage's model in view kind (their
** box, gathered by on_stage: the same as growing by each in turn). */
static void grow_snap(double b[4], const snap *sn, view_kind kind)
{
    if (!sn->have) return;
    grow(b, sn->box[kind][0], sn->box[kind][1]);
    grow(b, sn->box[kind][2], sn->box[kind][3]);
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

const char *pt_jcourse_text(int k)
{
    static const char *const texts[3] = {
        ": not yet, the vertex is made by the near clip",
        ": not yet, the vertex is made by the clip",
        "(x_vp, y_vp): none, outside the view square after the clip"
    };
    return texts[k >= 0 && k < 3 ? k : 2];
}

/* The text of the vertex's coordinates label at stage st: the panel's
** coordinates and their values, or why there are none yet. */
static void caption_text(pt_sbuf *t, const pt_cx_journey *j, const cpanel *p,
                         pt_course_stage st)
{
    pt_sbuf_add(t, p->coords);
    if (j->have[st]) {
        pt_vec4 a = j->at[st];
        pt_sbuf_add(t, " = (");
        num(t, a.x); pt_sbuf_add(t, ", ");
        num(t, a.y); pt_sbuf_add(t, ", ");
        num(t, a.z); pt_sbuf_add(t, ")");
    } else pt_sbuf_add(t, pt_jcourse_text(j->born == PT_CST_NEARCLIP ? 0 : 1));
}

/* The viewport panel's label: the vertex's pixel, or why it has none. */
static void viewport_text(char *t, size_t len, const pt_cx_journey *j)
{
    if (j->mapped)
        snprintf(t, len, "(x_vp, y_vp) = (%lld, %lld)", (long long)j->px_x, (long long)j->px_y);
    else snprintf(t, len, "%s", pt_jcourse_text(2));
}

/* The vertex's coordinates label. */
static void caption(pt_sbuf *sb, const cdoc *d, const cpanel *p, pt_course_stage st)
{
    pt_sbuf t;

    pt_sbuf_init(&t);
    caption_text(&t, d->j, p, st);
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
    if (d->c->st[st].np > d->c->st[st].nkeep)      /* PT_JOURNEY_MAXSEG */
        pt_sbuf_addf(&t, "the first %llu of %llu primitives drawn; ",
                     (unsigned long long)d->c->st[st].nkeep,
                     (unsigned long long)d->c->st[st].np);
    if (d->c->morecut && (st == PT_CST_NEARCLIP || st == PT_CST_CLIP))
        pt_sbuf_addf(&t, "the first %d cuts shown; ", PT_JOURNEY_MAXSEG);
    pt_sbuf_add(&t, more);
    pt_jtext(sb, 12, NOTE_Y, 11, "start", "class=\"note\" fill=\"" PT_JC_NOTE "\"",
             t.s ? t.s : "", 376);
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
}

/* The vertex's marker at its value after stage st, in view v (an arrow at
** the edge when it lies off the panel); none before a clip stage made it. */
static void marker(pt_sbuf *sb, const pt_jview *v, const cdoc *d, pt_course_stage st,
                   view_kind kind)
{
    double x, y;

    if (!d->j->have[st]) return;            /* not made yet: nothing to mark */
    xy_of(kind, d->j->at[st], &x, &y);
    pt_jmarker(sb, v, 1, x, y, d->j->v, 0, NULL, NULL);
}

/* A 3-D panel (model, world, view): the model's wireframe and its axes. */
static void panel_space(pt_sbuf *sb, const cdoc *d, const cpanel *p)
{
    const snap *sn = &d->c->st[p->st];
    double b[4] = {0, 0, 0, 0};
    pt_jview v;
    double big = sn->have ? sn->big : 0;

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

    if (sn->have && sn->zf < zf) zf = sn->zf;
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
    viewport_text(t, sizeof t, j);
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

static void panel_drawn(pt_sbuf *sb, const cdoc *d, const cpanel *p, int no)
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

/* Panel p (number no) drawn, its movable labels placed clear of each other
** and of its lines and texts (jplace.h), as the other cameras' panels are. */
static void panel(pt_sbuf *sb, const cdoc *d, const cpanel *p, int no)
{
    static const double area[4] = {PT_JBOX_X, PT_JBOX_Y, PT_JBOX_X + PT_JBOX_W,
                                   PT_JBOX_Y + PT_JBOX_H};
    pt_jplace pl;

    pt_jplace_init(&pl, area);
    pt_jdraw_to(&pl);
    panel_drawn(sb, d, p, no);
    pt_jdraw_to(NULL);
    pt_jdraw_labels(sb, &pl);
    if (pl.failed) sb->failed = 1;
    pt_jplace_free(&pl);
}

/* ===== one render, one vertex: the documents ===== */

struct pt_jcourse {
    const pt_scene *s;
    size_t mi;
    crun c;
    cdoc d;
    pt_cx_journey j;             /* the chosen vertex's */
};

int pt_jcourse_open(pt_jcourse **out, const pt_scene *s, size_t mi, int whole)
{
    pt_jcourse *jc = calloc(1, sizeof *jc);
    pt_course_cam cc;

    *out = NULL;
    if (!jc) return -1;
    if (crun_run(&jc->c, s, mi, whole) != 0) {
        crun_free(&jc->c);
        free(jc);
        return -1;
    }
    pt_course_camera(s, &cc);
    jc->s = s;
    jc->mi = mi;
    jc->d.s = s; jc->d.j = &jc->j; jc->d.c = &jc->c; jc->d.cam = cc.cam;
    *out = jc;
    return 0;
}

int pt_jcourse_vertex(pt_jcourse *jc, uint64_t v)
{
    return pt_cx_run(&jc->j, jc->s, jc->mi, v);
}

uint64_t pt_jcourse_count(const pt_jcourse *jc)
{
    const snap *sn = &jc->c.st[PT_CST_CLIP];
    return sn->have ? sn->nv : 0;
}

const pt_cx_journey *pt_jcourse_journey(const pt_jcourse *jc)
{
    return &jc->j;
}

const pt_rv_model *pt_jcourse_model(const pt_jcourse *jc, pt_rv_model *view)
{
    const snap *sn = &jc->c.st[PT_CST_MODEL];

    if (!sn->have || !sn->have_whole) return NULL;
    *view = sn->whole;
    return view;
}

/* Panel k of this renderer's (renderer 7 has no world). */
static const cpanel *nth(const pt_jcourse *jc, int k)
{
    size_t i;

    for (i = 0; i < NPANELS; i++) {
        if (panels[i].st == PT_CST_WORLD && jc->s->renderer != 9) continue;
        if (k-- == 0) return &panels[i];
    }
    return &panels[0];
}

const char *pt_jcourse_label(int st)
{
    size_t i;

    if (st == PT_CST_CLIP) st = PT_CST_IMAGE;   /* the clip works on the image plane */
    for (i = 0; i < NPANELS; i++)
        if ((int)panels[i].st == st) return panels[i].coords;
    return panels[0].coords;
}

int pt_jcourse_npanels(const pt_jcourse *jc)
{
    return jc->s->renderer == 9 ? (int)NPANELS : (int)NPANELS - 1;
}

/* The step of `step` that a panel's page texts come from (the volume's:
** the view's; the image plane's: the projection and the clip). */
static pt_cx_step step_of(const cpanel *p)
{
    if (!strcmp(p->key, "viewport")) return PT_CXS_VIEWPORT;
    return pt_cx_step_of(p->st);
}

void pt_jcourse_stage_of(const pt_jcourse *jc, int k, pt_jcourse_stage *out)
{
    const cpanel *p = nth(jc, k);
    const pt_cx_row *row = pt_cx_row_of(step_of(p));

    out->key = p->key;
    out->title = p->title;
    out->from = row->from;
    out->to = row->to;
    out->what = row->what;
    out->formula = pt_cx_formula(jc->s->renderer, step_of(p));
    if (!strcmp(p->key, "volume")) {
        out->from = out->to = "view";
        out->what = "the view volume, seen from the side: the camera at the origin looking "
                    "down -z, the rectangle l..r, b..t at z = -1 (orthographic: a box), the "
                    "near plane z = n";
        out->formula = "l, r, b, t: the camera's rectangle; n = -near";
    }
}

void pt_jcourse_panel(pt_sbuf *sb, const pt_jcourse *jc, int k)
{
    panel(sb, &jc->d, nth(jc, k), k + 1);
}

void pt_jcourse_coords(pt_sbuf *sb, const pt_jcourse *jc, int k)
{
    const cpanel *p = nth(jc, k);
    char t[160];

    if (!strcmp(p->key, "viewport")) {
        viewport_text(t, sizeof t, &jc->j);
        pt_sbuf_add(sb, t);
    } else if (p->st == PT_CST_IMAGE)
        caption_text(sb, &jc->j, p, jc->j.have[PT_CST_IMAGE] ? PT_CST_IMAGE : PT_CST_CLIP);
    else caption_text(sb, &jc->j, p, p->st);
}

/* Append step st's text when the vertex has that step. */
static void add_step(pt_sbuf *sb, const pt_cx_journey *j, pt_cx_step st, const char *before)
{
    static char b[16384];
    int i;

    for (i = 0; i < j->nsteps; i++)
        if (j->steps[i] == st) {
            pt_cx_stage(b, sizeof b, j, st, "\n");
            pt_sbuf_add(sb, before);
            pt_sbuf_add(sb, b);
            return;
        }
}

void pt_jcourse_here(pt_sbuf *sb, const pt_jcourse *jc, int k)
{
    const cpanel *p = nth(jc, k);
    const pt_cx_journey *j = &jc->j;
    const pt_rv_camera *c = &jc->d.cam;
    size_t len = sb->len;

    if (!strcmp(p->key, "volume")) {
        pt_sbuf_add(sb, "l = "); num(sb, c->l);
        pt_sbuf_add(sb, ", r = "); num(sb, c->r);
        pt_sbuf_add(sb, ", b = "); num(sb, c->b);
        pt_sbuf_add(sb, ", t = "); num(sb, c->t);
        pt_sbuf_add(sb, ", n = "); num(sb, c->n);
        pt_sbuf_add(sb, c->perspective ? " (perspective)" : " (orthographic)");
        return;
    }
    if (!strcmp(p->key, "viewport")) {
        add_step(sb, j, PT_CXS_PIXEL, "");
        add_step(sb, j, PT_CXS_VIEWPORT, "\n");
    } else if (p->st == PT_CST_IMAGE) {
        add_step(sb, j, PT_CXS_IMAGE, "");
        add_step(sb, j, PT_CXS_CLIP, sb->len > len ? "\n" : "");
    } else add_step(sb, j, pt_cx_step_of(p->st), "");
    if (sb->len == len) pt_jcourse_coords(sb, jc, k);      /* not yet */
}

void pt_jcourse_close(pt_jcourse *jc)
{
    if (!jc) return;
    crun_free(&jc->c);
    free(jc);
}

int pt_journey_course_svg(pt_sbuf *sb, const pt_scene *s, size_t mi, uint64_t v)
{
    pt_jcourse *jc;
    int rc, n, k, docw = COLS * PT_JOURNEY_PW + (COLS + 1) * GAP, doch;
    pt_sbuf t;

    if (pt_jcourse_open(&jc, s, mi, 0) != 0) return -1;
    if ((rc = pt_jcourse_vertex(jc, v)) != 0) { pt_jcourse_close(jc); return rc; }
    n = pt_jcourse_npanels(jc);
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
    for (k = 0; k < n; k++) {
        int col = k % COLS, row = k / COLS;
        int px = GAP + col * (PT_JOURNEY_PW + GAP), py = HEAD + row * (PT_JOURNEY_PH + GAP);
        pt_sbuf_addf(sb, "<g class=\"panel\" data-stage=\"%s\" transform=\"translate(%d %d)\">\n",
                     nth(jc, k)->key, px, py);
        pt_jcourse_panel(sb, jc, k);
        pt_sbuf_add(sb, "</g>\n");
        if (col < COLS - 1 && k + 1 < n)
            pt_jarrow(sb, px + PT_JOURNEY_PW + 1, py + PT_JOURNEY_PH / 2.0,
                      px + PT_JOURNEY_PW + GAP - 2, py + PT_JOURNEY_PH / 2.0, 12, "#8a919b");
    }
    pt_sbuf_add(sb, "</svg>\n");
    pt_jcourse_close(jc);
    return sb->failed ? -1 : 0;
}

int pt_journey_course_image(pt_fb *fb, const pt_scene *s, size_t mi, uint64_t v, int *has,
                            int64_t *x, int64_t *y)
{
    static pt_cx_journey j;      /* large: not on the stack */
    int rc;

    if ((rc = pt_cx_run(&j, s, mi, v)) != 0) return rc;
    if (pt_fb_init(fb, s->fb_w, s->fb_h, s->background) != 0) return -1;
    if (pt_course_render(s, fb, NULL) != 0) { pt_fb_free(fb); return -1; }
    *has = j.mapped;
    *x = (int64_t)j.par.x_ul + j.px_x;      /* x_fb = x_ul + x_vp */
    *y = (int64_t)j.par.y_ul + j.px_y;
    return 0;
}

/* ===== the page ===== */

/* Append ["..", ..] of one text per panel of the chosen vertex: kind 0 its
** coordinates, 1 the formula with its numbers, 2 the panel drawn, 3 what
** the next panel does. */
static void page_texts(pt_sbuf *sb, const pt_jcourse *jc, int kind)
{
    int k, n = pt_jcourse_npanels(jc);
    pt_sbuf t;

    pt_sbuf_init(&t);
    pt_sbuf_add(sb, "[");
    for (k = 0; k < n; k++) {
        pt_jcourse_stage in;
        t.len = 0;
        pt_sbuf_add(&t, "");
        if (kind == 0) pt_jcourse_coords(&t, jc, k);
        else if (kind == 1) pt_jcourse_here(&t, jc, k);
        else if (kind == 2) pt_jcourse_panel(&t, jc, k);
        else if (k + 1 < n) {
            pt_jcourse_stage_of(jc, k + 1, &in);
            pt_sbuf_addf(&t, "%s: ", in.title);
            pt_sbuf_add(&t, in.what);
        } else pt_sbuf_add(&t, "the rasterizer draws the primitives through this pixel");
        pt_sbuf_add(sb, k ? (kind == 2 ? ",\n" : ",") : "");
        pt_sbuf_add_json(sb, t.s ? t.s : "");
    }
    pt_sbuf_add(sb, "]");
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
}

int pt_journey_course_html(pt_sbuf *sb, const pt_scene *s, size_t mi, uint64_t v,
                           const unsigned char *pick, uint64_t npick)
{
    pt_jcourse *jc;
    uint64_t x, count, total = 0, start = 0, n = 0;
    int k, rc, np;
    pt_sbuf t;

    if (pt_jcourse_open(&jc, s, mi, 1) != 0) return -1;
    if ((rc = pt_jcourse_vertex(jc, v)) != 0) { pt_jcourse_close(jc); return rc; }
    count = pt_jcourse_count(jc);
    if (pick && npick > count) { pt_jcourse_close(jc); return 2; }
    np = pt_jcourse_npanels(jc);
    pt_journey_page_head(sb, s->models[mi].name, v);
    pt_sbuf_add(sb, "<script type=\"application/json\" id=\"data\">\n{\"where\":");
    pt_sbuf_init(&t);
    pt_sbuf_add(&t, "scene ");
    pt_sbuf_add(&t, s->path);
    pt_sbuf_addf(&t, "; the course's renderer %d, camera %s; viewport %d x %d at (x_ul, y_ul) "
                 "= (%d, %d); framebuffer %d x %d", s->renderer,
                 s->perspective ? "perspective" : "orthographic", s->vp_w, s->vp_h, s->vp_x,
                 s->vp_y, s->fb_w, s->fb_h);
    pt_sbuf_add_json(sb, t.s ? t.s : "");
    if (t.failed) sb->failed = 1;
    pt_sbuf_free(&t);
    for (x = 1; x <= count; x++) {
        int want = pick ? x <= npick && pick[x - 1] : 1;
        if (!want && x != v) continue;
        if (want) total++;
        if (x == v) start = n;
        if (n < PT_JCOURSE_MAXV || x == v) n++;
    }
    pt_sbuf_addf(sb, ",\n\"panel\":[%d,%d],\"font\":", PT_JOURNEY_PW, PT_JOURNEY_PH);
    pt_sbuf_add_json(sb, PT_JFONT);
    pt_sbuf_addf(sb, ",\"capped\":%s,\"total\":%llu,\"start\":%llu,\n\"stages\":[\n",
                 total > n ? "true" : "false", (unsigned long long)total,
                 (unsigned long long)start);
    for (k = 0; k < np; k++) {
        pt_jcourse_stage in;
        pt_jcourse_stage_of(jc, k, &in);
        pt_journey_page_stage(sb, k, in.key, in.title, in.from, in.to, in.formula, in.what);
    }
    pt_sbuf_add(sb, "],\n\"models\":[{\"name\":");
    pt_sbuf_add_json(sb, s->models[mi].name);
    pt_sbuf_add(sb, ",\"bg\":[");
    for (k = 0; k < np; k++) pt_sbuf_add(sb, k ? ",\"\"" : "\"\"");
    pt_sbuf_add(sb, "]}],\n\"vertices\":[\n");
    for (x = 1, n = 0; x <= count && !sb->failed; x++) {
        int want = pick ? x <= npick && pick[x - 1] : 1;
        if (!want && x != v) continue;
        if (n >= PT_JCOURSE_MAXV && x != v) continue;
        if ((rc = pt_jcourse_vertex(jc, x)) < 0) break;
        if (rc) continue;                   /* never there: a hidden position */
        pt_sbuf_addf(sb, "%s{\"m\":0,\"v\":%llu,\"used\":true,\"coords\":", n ? ",\n" : "",
                     (unsigned long long)x);
        page_texts(sb, jc, 0);
        pt_sbuf_add(sb, ",\n\"here\":");
        page_texts(sb, jc, 1);
        pt_sbuf_add(sb, ",\n\"next\":");
        page_texts(sb, jc, 3);
        pt_sbuf_add(sb, ",\n\"fg\":");
        page_texts(sb, jc, 2);
        pt_sbuf_add(sb, "}");
        n++;
    }
    pt_sbuf_add(sb, "]}\n</script>\n");
    pt_journey_page_script(sb);
    if (rc >= 0) {                          /* the sliders (journey_wasm.c) */
        pt_jwasm_course cw;
        pt_rv_model view;
        cw.j = &jc->j;
        cw.m = pt_jcourse_model(jc, &view);
        cw.ops = s->models[mi].ops;
        cw.nops = s->models[mi].nops;
        for (k = 0; k < PT_NCST; k++) cw.label[k] = pt_jcourse_label(k);
        for (k = 0; k < 3; k++) cw.text[k] = pt_jcourse_text(k);
        pt_journey_wasm_course(sb, s, &cw);
    }
    pt_sbuf_add(sb, "</body>\n</html>\n");
    pt_jcourse_close(jc);
    return rc < 0 || sb->failed ? -1 : 0;
}
