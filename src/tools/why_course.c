/*
** src/tools/why_course.c -- pipetrace why on a scene of the course's renderer 7 or 9
** See LICENSE for copyright and license.
**
** The clip stages renumber the primitives they keep, so each position keeps
** the map from a stage's list back to its model's primitives: the near
** clip's input is the model's list, the clip's is what the near clip kept (or
** the model's, with `nearclip off`), the rasterizer's what the clip kept.
** Which stage's callbacks are heard follows from the stage reported last:
** after the camera the near clip runs, after the image plane the clip.
**
** A viewport that sticks out of the framebuffer: a write lands on the pixel
** asked about when the core's index rule (pt_raster_fb_pixel, rows wrapping)
** puts it at the pixel's index, so each write keeps its viewport pixel, and
** the report goes viewport pixel by viewport pixel (pt_whyc_sources).
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/why_course.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

#define MAXCUT 4                 /* rectangle cuts kept per primitive */
#define MAXWRITE 4               /* writes on the pixel kept per primitive */

/* One primitive of a position, followed through the stages. */
typedef struct cprim {
    pt_rv_prim p;                /* as the model gives it */
    int near;                    /* 0 not run, 1 kept, 2 cut, 3 dropped */
    pt_rv_cut ncut;
    int clip;                    /* 0 not reached, 1 kept, 2 cut, 3 dropped */
    int ncuts;                   /* cuts made (the first MAXCUT kept) */
    pt_rv_cut cuts[MAXCUT];
    uint64_t clip_no;            /* 1-based in the clip's list (the trace's) */
    uint64_t raster_no;          /* 1-based in the rasterizer's list; 0 not drawn */
    uint64_t npix;               /* pixels it wrote */
    int nlit;                    /* pixel writes on the pixel asked about */
    uint64_t lit_order;          /* the last of them, in the render's order, */
    int last_x_vp, last_y_vp;    /*   from this viewport pixel */
    struct write {               /* the first MAXWRITE of them: */
        pt_rv_px_kind kind;      /*   the pixel line's kind, */
        int x_vp, y_vp;          /*   the viewport pixel written, */
        float coverage;          /*   the coverage, */
        unsigned char b[3];      /*   the bytes written */
    } w[MAXWRITE];
} cprim;

typedef struct cpos {
    size_t np;
    cprim *p;
    size_t *near_out, nnear;     /* the primitives the near clip kept, in order */
    size_t *clip_out, nclip;     /* ... the clip kept */
    pt_course_stage last;        /* the stage reported last */
    int reported;                /* 1: last is set */
    uint64_t seen;               /* primitives begun in the running clip stage */
    size_t cur;                  /* the one being clipped (model index) */
    uint64_t raster_seen;
} cpos;

typedef struct whyc {
    const pt_scene *s;
    int X, Y;
    int64_t idx;                 /* the pixel's index */
    int wrap;                    /* 1: the viewport sticks out of the framebuffer */
    cpos *pos;
    size_t cur;                  /* the position being worked on */
    size_t r_prim;               /* the primitive being drawn (model index) */
    int drawing;                 /* 1: r_prim of position cur is being drawn */
    uint64_t order;              /* pixel writes on the pixel so far */
    double n;                    /* the near plane's z */
    int failed;
} whyc;

/* The position being worked on: the one a POSITION (Pipeline) or STEP
** (Pipeline2) mark names. */
static void on_mark(void *ud, pt_course_mark k, const pt_course_cam *cam,
                    const pt_course_pos *pos)
{
    whyc *w = ud;

    if (k == PT_CMK_BEGIN) w->n = cam->cam.n;
    if (k == PT_CMK_POSITION || k == PT_CMK_STEP) w->cur = pos->index;
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    whyc *w = ud;
    cpos *c = &w->pos[pos->index];
    size_t k;

    c->last = st;
    c->reported = 1;
    c->seen = 0;
    if (st != PT_CST_MODEL) return;
    c->p = calloc(m->np ? m->np : 1, sizeof *c->p);
    c->near_out = calloc(m->np ? m->np : 1, sizeof *c->near_out);
    c->clip_out = calloc(m->np ? m->np : 1, sizeof *c->clip_out);
    if (!c->p || !c->near_out || !c->clip_out) { w->failed = 1; return; }
    c->np = m->np;
    for (k = 0; k < m->np; k++) c->p[k].p = m->p[k];
}

/* The running clip stage: 1 the near clip, 2 the clip. */
static int clip_stage(const cpos *c)
{
    return c->last == PT_CST_CAMERA ? 1 : 2;
}

static void clip_begin(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    whyc *w = ud;
    cpos *c = &w->pos[w->cur];
    uint64_t i = c->seen++;

    (void)m; (void)p;
    if (!c->np) return;
    if (clip_stage(c) == 1) c->cur = (size_t)i;
    else c->cur = w->s->nearclip ? c->near_out[i] : (size_t)i;
    if (clip_stage(c) == 2) c->p[c->cur].clip_no = i + 1;
}

static void clip_cut(void *ud, const pt_rv_cut *cut)
{
    whyc *w = ud;
    cpos *c = &w->pos[w->cur];
    cprim *p = &c->p[c->cur];

    if (!c->np) return;
    if (cut->edge == PT_RV_NEAR) { p->ncut = *cut; p->near = 2; return; }
    if (p->ncuts < MAXCUT) p->cuts[p->ncuts] = *cut;
    p->ncuts++;
}

static void clip_end(void *ud, const pt_rv_model *m, const pt_rv_prim *q, int accepted)
{
    whyc *w = ud;
    cpos *c = &w->pos[w->cur];
    cprim *p = &c->p[c->cur];

    (void)m; (void)q;
    if (!c->np) return;
    if (clip_stage(c) == 1) {
        if (p->near != 2 || !accepted) p->near = accepted ? 1 : 3;
        if (accepted) c->near_out[c->nnear++] = c->cur;
    } else {
        p->clip = !accepted ? 3 : p->ncuts ? 2 : 1;
        if (accepted) c->clip_out[c->nclip++] = c->cur;
    }
}

static void on_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    whyc *w = ud;
    cpos *c = &w->pos[pos->index];
    uint64_t i = c->raster_seen++;

    (void)m; (void)p;
    w->drawing = i < c->nclip;
    if (!w->drawing) return;
    w->r_prim = c->clip_out[i];
    c->p[w->r_prim].raster_no = i + 1;
}

static void on_drawn(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                     const pt_rv_prim *p, uint64_t n)
{
    whyc *w = ud;

    (void)m; (void)p;
    if (w->drawing) w->pos[pos->index].p[w->r_prim].npix = n;
    w->drawing = 0;
}

/* One write of colour col at viewport pixel (x_vp, y_vp) with coverage f. */
static void hit(whyc *w, const pt_rv_pixel *px, int x_vp, int y_vp, pt_rgb col, float f)
{
    const pt_rv_raster_par *par = px->par;
    pt_fb_pixel at;
    cprim *p;

    if (pt_raster_fb_pixel(x_vp, y_vp, par->x_ul, par->y_ul, par->W, par->H, w->wrap, &at)
        != w->idx) return;
    p = &w->pos[w->cur].p[w->r_prim];
    p->lit_order = ++w->order;
    p->last_x_vp = x_vp;
    p->last_y_vp = y_vp;
    if (p->nlit < MAXWRITE) {
        struct write *o = &p->w[p->nlit];
        o->kind = px->kind;
        o->x_vp = x_vp;
        o->y_vp = y_vp;
        o->coverage = f;
        o->b[0] = pt_color_byte(col.r);
        o->b[1] = pt_color_byte(col.g);
        o->b[2] = pt_color_byte(col.b);
    }
    p->nlit++;
}

static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    whyc *w = ud;

    if (!w->drawing) return;
    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
        hit(w, px, px->x_vp, px->y_vp, px->c[0], 1.0f);
        break;
    case PT_RV_PX_POINT:
        if (!px->clipped) hit(w, px, px->x_vp, px->y_vp, px->c[0], 1.0f);
        break;
    case PT_RV_PX_AA: {
        double a = px->transposed ? px->x_pp : px->y_pp;
        float f = pt_aa_weight(a, floor(a));
        if (px->transposed) {
            hit(w, px, px->lo, px->y_vp, px->c[0], 1.0f - f);
            hit(w, px, px->hi, px->y_vp, px->c[1], f);
        } else {
            hit(w, px, px->x_vp, px->lo, px->c[0], 1.0f - f);
            hit(w, px, px->x_vp, px->hi, px->c[1], f);
        }
        break;
    }
    }
}

/* ===== the report ===== */

static void num(FILE *f, double x)
{
    char b[PT_NUMLEN];

    pt_fmt_shortest(b, x);
    fputs(b, f);
}

/* "cube segment 3 (v1 v2)" */
static void prim_name(FILE *f, const pt_scene *s, size_t mi, size_t k, const cprim *p)
{
    fprintf(f, "%s %s %zu (v%u", s->models[mi].name,
            p->p.kind == PT_RV_POINT ? "point" : "segment", k + 1, p->p.v[0] + 1);
    if (p->p.kind == PT_RV_LINE) fprintf(f, " v%u", p->p.v[1] + 1);
    fputc(')', f);
}

static const char *edge_name(pt_rv_edge e)
{
    switch (e) {
    case PT_RV_NEAR: return "the near plane z = n";
    case PT_RV_XPOS: return "the edge x = +1";
    case PT_RV_XNEG: return "the edge x = -1";
    case PT_RV_YPOS: return "the edge y = +1";
    case PT_RV_YNEG: return "the edge y = -1";
    }
    return "";
}

static void show_cut(FILE *f, const pt_rv_cut *c)
{
    fprintf(f, "; cut at %s, t = ", edge_name(c->edge));
    num(f, c->t);
    fprintf(f, ", new vertex %u", c->v_new + 1);
}

/* What the clips did to p, as "; ..." clauses. */
static void show_clips(FILE *f, const whyc *w, const cprim *p)
{
    int k;

    if (p->near == 2) show_cut(f, &p->ncut);
    if (p->near == 3) {
        fprintf(f, "; dropped by the near clip: %s beyond the near plane z = n = ",
                p->p.kind == PT_RV_POINT ? "it lies" : "both ends lie");
        num(f, w->n);
    }
    for (k = 0; k < p->ncuts && k < MAXCUT; k++) show_cut(f, &p->cuts[k]);
    if (p->clip == 3)
        fprintf(f, "; dropped by the clip: %s outside the view rectangle -1..1",
                p->p.kind == PT_RV_POINT ? "it lies" : "both ends lie beyond one edge");
}

/* The writes of p on the pixel, in order: kind, coverage, bytes; with vp,
** only those from viewport pixel vp. */
static void show_writes(FILE *f, const pt_scene *s, const cprim *p, const pt_pix *vp)
{
    int k, shown = 0;

    for (k = 0; k < p->nlit && k < MAXWRITE; k++) {
        const struct write *o = &p->w[k];
        if (vp && (o->x_vp != vp->x || o->y_vp != vp->y)) continue;
        if (shown++) fputs("; then ", f);
        fputs(o->kind == PT_RV_PX_END ? "its last pixel (the end's colour as it is, no gamma)"
              : o->kind == PT_RV_PX_AA ? "an anti-aliased step"
              : o->kind == PT_RV_PX_POINT ? "a pixel of the point" : "a step", f);
        fputs(", coverage ", f);
        num(f, (double)o->coverage);
        fprintf(f, ", bytes %d %d %d%s", o->b[0], o->b[1], o->b[2],
                o->kind != PT_RV_PX_END && s->gamma ? " (gamma-encoded)" : "");
    }
    if (p->nlit > MAXWRITE) fprintf(f, "; %d writes here in all", p->nlit);
}


/* 1 when p wrote the pixel from viewport pixel vp (a write it kept), or at
** all (vp NULL). */
static int wrote_from(const cprim *p, const pt_pix *vp)
{
    int k;

    if (!vp) return p->nlit > 0;
    for (k = 0; k < p->nlit && k < MAXWRITE; k++)
        if (p->w[k].x_vp == vp->x && p->w[k].y_vp == vp->y) return 1;
    return 0;
}

/* The primitives of the models counted (sel, or all) that wrote the pixel
** (from viewport pixel vp, or from any: NULL), in drawing order, each with
** its writes and clips; returns how many. */
static size_t show_lit(FILE *f, const whyc *w, const pt_model *sel, const pt_pix *vp)
{
    const pt_scene *s = w->s;
    size_t mi, k, n = 0;

    for (mi = 0; mi < s->nmodels; mi++)
        for (k = 0; k < w->pos[mi].np; k++) {
            const cprim *p = &w->pos[mi].p[k];
            if ((sel && &s->models[mi] != sel) || !wrote_from(p, vp)) continue;
            if (!n++) fputs("lit by, in drawing order (the last write wins):\n", f);
            fputs("  ", f);
            prim_name(f, s, mi, k, p);
            fprintf(f, ", drawn as primitive %llu: ", (unsigned long long)p->raster_no);
            show_writes(f, s, p, vp);
            show_clips(f, w, p);
            fputc('\n', f);
        }
    return n;
}

/* The primitives of the models counted that did not write the pixel: where
** they were drawn, or what the clips did to them; then the hidden models. */
static void show_not_lit(FILE *f, const whyc *w, const pt_model *sel, size_t nlit)
{
    const pt_scene *s = w->s;
    size_t mi, k, nother = 0;

    for (mi = 0; mi < s->nmodels; mi++)
        for (k = 0; k < w->pos[mi].np; k++)
            nother += (!sel || &s->models[mi] == sel) && !w->pos[mi].p[k].nlit;
    if (nother) fprintf(f, "not lit by%s:\n", nlit ? " the others" : "");
    for (mi = 0; mi < s->nmodels; mi++)
        for (k = 0; k < w->pos[mi].np; k++) {
            const cprim *p = &w->pos[mi].p[k];
            if ((sel && &s->models[mi] != sel) || p->nlit) continue;
            fputs("  ", f);
            prim_name(f, s, mi, k, p);
            if (p->raster_no)
                fprintf(f, ": drawn as primitive %llu, %llu pixels elsewhere",
                        (unsigned long long)p->raster_no, (unsigned long long)p->npix);
            else
                fputs(": not drawn", f);
            show_clips(f, w, p);
            fputc('\n', f);
        }
    for (mi = 0; mi < s->nmodels; mi++)
        if ((!sel || &s->models[mi] == sel) && (s->models[mi].hidden_model ||
                                               s->models[mi].hidden_position))
            fprintf(f, "  model %s: hidden, nothing of it is drawn\n", s->models[mi].name);
}

/* The last write on the pixel of the models counted (sel, or all): 1 and
** its model and primitive, or 0 for none. */
static int last_write(const whyc *w, const pt_model *sel, size_t *last_mi, size_t *last_k)
{
    const pt_scene *s = w->s;
    size_t mi, k;
    uint64_t last = 0;

    for (mi = 0; mi < s->nmodels; mi++)
        for (k = 0; k < w->pos[mi].np; k++) {
            const cprim *p = &w->pos[mi].p[k];
            if ((sel && &s->models[mi] != sel) || p->lit_order <= last) continue;
            last = p->lit_order;
            *last_mi = mi;
            *last_k = k;
        }
    return last > 0;
}

/* The report on a scene whose viewport lies inside the framebuffer. */
static void report_inside(FILE *f, const whyc *w, const pt_model *sel, const unsigned char *o)
{
    const pt_scene *s = w->s;
    int x_vp = w->X - s->vp_x, y_vp = w->Y - s->vp_y;
    int inside = x_vp >= 0 && x_vp < s->vp_w && y_vp >= 0 && y_vp < s->vp_h;
    size_t nlit, last_mi = 0, last_k = 0;

    if (inside) fprintf(f, "inside the viewport at (x_vp, y_vp) = (%d, %d)\n", x_vp, y_vp);
    else fprintf(f, "outside the viewport: the rasterizer draws only into the viewport\n");
    fprintf(f, "antialias %s, gamma %s, nearclip %s\n", s->antialias ? "on" : "off",
            s->gamma ? "on" : "off", s->nearclip ? "on" : "off");
    nlit = show_lit(f, w, sel, NULL);
    if (!last_write(w, sel, &last_mi, &last_k)) {
        fprintf(f, "not lit: no primitive%s writes it; it keeps the %s %d %d %d\n",
                sel ? " of the chosen model" : "",
                inside ? "viewport's background" : "background", o[0], o[1], o[2]);
    } else {
        fprintf(f, "color %d %d %d: the last write, by ", o[0], o[1], o[2]);
        prim_name(f, s, last_mi, last_k, &w->pos[last_mi].p[last_k]);
        fputc('\n', f);
    }
    show_not_lit(f, w, sel, nlit);
}

/* The report on a scene whose viewport sticks out: viewport pixel by
** viewport pixel, those that land on the pixel's index. */
static int report_wrapped(FILE *f, const whyc *w, const pt_model *sel, const unsigned char *o)
{
    const pt_scene *s = w->s;
    size_t n = pt_whyc_sources(s, w->X, w->Y, NULL, 0), i, nlit = 0, last_mi = 0, last_k = 0;
    pt_pix *src = calloc(n ? n : 1, sizeof *src);

    if (!src) return -1;
    pt_whyc_sources(s, w->X, w->Y, src, n);
    fputc('\n', f);
    fprintf(f, "antialias %s, gamma %s, nearclip %s\n", s->antialias ? "on" : "off",
            s->gamma ? "on" : "off", s->nearclip ? "on" : "off");
    pt_whyc_wrap_head(f, s, w->X, w->Y, n);
    for (i = 0; i < n; i++) {
        size_t here;
        pt_whyc_source(f, s, w->X, w->Y, src[i]);
        if (i >= PT_WHYC_EXPLAINED) continue;
        here = show_lit(f, w, sel, &src[i]);
        if (!here) fprintf(f, "not lit from there: no primitive%s writes it\n",
                           sel ? " of the chosen model" : "");
        nlit += here;
    }
    if (n > PT_WHYC_EXPLAINED)
        fprintf(f, "(the %zu viewport pixels after the first %d are listed, not explained)\n",
                n - PT_WHYC_EXPLAINED, PT_WHYC_EXPLAINED);
    fputc('\n', f);
    if (last_write(w, NULL, &last_mi, &last_k)) {
        const cprim *p = &w->pos[last_mi].p[last_k];
        fprintf(f, "color %d %d %d%s: the last write, by ", o[0], o[1], o[2],
                sel ? " in the image" : "");
        prim_name(f, s, last_mi, last_k, p);
        fprintf(f, ", drawn as primitive %llu, from viewport pixel (x_vp, y_vp) = (%d, %d)\n",
                (unsigned long long)p->raster_no, p->last_x_vp, p->last_y_vp);
    } else if (n) {
        fprintf(f, "color %d %d %d: no primitive writes it; the last write is the viewport's "
                "clearing, of viewport pixel (x_vp, y_vp) = (%lld, %lld), to the viewport "
                "background\n", o[0], o[1], o[2], (long long)src[n - 1].x,
                (long long)src[n - 1].y);
    } else {
        fprintf(f, "not lit: no viewport pixel writes it; it keeps the background %d %d %d\n",
                o[0], o[1], o[2]);
    }
    show_not_lit(f, w, sel, nlit);
    free(src);
    return 0;
}

int pt_whyc_report(FILE *f, const pt_scene *s, int X, int Y, const pt_model *sel)
{
    pt_rv_raster_ls rls;
    pt_course_ls ls;
    pt_fb fb;
    whyc w;
    pt_pix at = {X, Y, 1};
    size_t mi;
    int rc;

    memset(&w, 0, sizeof w);
    w.s = s; w.X = X; w.Y = Y;
    w.idx = pt_fb2index(at, s->fb_w, s->fb_h, NULL);
    w.wrap = !pt_scene_vp_inside(s);
    w.pos = calloc(s->nmodels ? s->nmodels : 1, sizeof *w.pos);
    if (!w.pos || pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) {
        free(w.pos);
        fprintf(stderr, "pipetrace why: %s: out of memory\n", s->path);
        return -1;
    }
    memset(&rls, 0, sizeof rls);
    rls.pixel = on_pixel;
    rls.ud = &w;
    memset(&ls, 0, sizeof ls);
    ls.mark = on_mark;
    ls.stage = on_stage;
    ls.raster = on_raster;
    ls.drawn = on_drawn;
    ls.nearclip.begin = ls.clip.begin = clip_begin;
    ls.nearclip.cut = ls.clip.cut = clip_cut;
    ls.nearclip.end = ls.clip.end = clip_end;
    ls.nearclip.ud = ls.clip.ud = &w;
    ls.raster_ls = &rls;
    ls.ud = &w;
    rc = pt_course_render(s, &fb, &ls);
    if (rc != 0 || w.failed) {
        fprintf(stderr, "pipetrace why: %s: out of memory\n", s->path);
        goto out;
    }

    fprintf(f, "pixel (x_fb, y_fb) = (%d, %d) of %s, renderer %d: idx = %lld", X, Y, s->path,
            s->renderer, (long long)w.idx);
    if (!w.wrap) {
        fputs(", ", f);
        report_inside(f, &w, sel, fb.rgb + 3 * (size_t)w.idx);
    } else if (report_wrapped(f, &w, sel, fb.rgb + 3 * (size_t)w.idx) != 0) {
        fprintf(stderr, "pipetrace why: %s: out of memory\n", s->path);
        w.failed = 1;
    }
out:
    for (mi = 0; mi < s->nmodels; mi++) {
        free(w.pos[mi].p);
        free(w.pos[mi].near_out);
        free(w.pos[mi].clip_out);
    }
    free(w.pos);
    pt_fb_free(&fb);
    return rc != 0 || w.failed ? -1 : 0;
}

/* ===== a viewport that sticks out of the framebuffer (why_course.h) ===== */

/* The search below: the course's index is linear along a viewport row, so a
** viewport pixel lands on (X, Y) only at x_fb = X + k W, y_fb = Y - k, its row
** wrapped k rows (k < 0: the other way); one candidate a viewport row, each
** asked of the core's rule, pt_raster_fb_pixel, which alone says where a
** pixel lands (tests/teach/why_vpout.py ties the answer to the trace's
** pixel records). */
size_t pt_whyc_sources(const pt_scene *s, int64_t X, int64_t Y, pt_pix *out, size_t n)
{
    pt_pix fb = {X, Y, 1};
    int64_t idx = pt_fb2index(fb, s->fb_w, s->fb_h, NULL), y_vp;
    int wrap = !pt_scene_vp_inside(s);
    size_t m = 0;

    if (idx < 0) return 0;
    for (y_vp = 0; y_vp < s->vp_h; y_vp++) {             /* the clearing's order */
        int64_t k = Y - s->vp_y - y_vp;                    /* rows wrapped */
        int64_t x_vp = X + k * s->fb_w - s->vp_x;
        pt_fb_pixel q;
        if (x_vp < 0 || x_vp >= s->vp_w) continue;
        if (pt_raster_fb_pixel(x_vp, y_vp, s->vp_x, s->vp_y, s->fb_w, s->fb_h, wrap, &q) != idx)
            continue;
        if (m < n) { out[m].x = x_vp; out[m].y = y_vp; out[m].ok = 1; }
        m++;
    }
    return m;
}

void pt_whyc_wrap_head(FILE *f, const pt_scene *s, int64_t X, int64_t Y, size_t nsrc)
{
    pt_pix fb = {X, Y, 1};
    long long idx = (long long)pt_fb2index(fb, s->fb_w, s->fb_h, NULL);

    fprintf(f, "the viewport %d x %d at (x_ul, y_ul) = (%d, %d) sticks out of the %d x %d "
            "framebuffer: the course's framebuffer writes viewport pixel (x_vp, y_vp) at the "
            "index y_fb * W + x_fb of its pixel array (x_fb = x_ul + x_vp, y_fb = y_ul + y_vp) "
            "without testing x_fb against the width, so a pixel past the left or right edge "
            "lands in a neighbouring row, and one whose index lies outside the array is "
            "dropped; clearing the viewport writes each of its pixels first, row by row, in "
            "the viewport background %d %d %d\n", s->vp_w, s->vp_h, s->vp_x, s->vp_y,
            s->fb_w, s->fb_h, s->vp_background[0], s->vp_background[1], s->vp_background[2]);
    if (nsrc)
        fprintf(f, "%zu viewport pixel%s land%s on index %lld, in the clearing's order:\n", nsrc,
                nsrc == 1 ? "" : "s", nsrc == 1 ? "s" : "", idx);
    else
        fprintf(f, "no viewport pixel lands on index %lld: nothing is ever drawn there\n", idx);
}

void pt_whyc_source(FILE *f, const pt_scene *s, int64_t X, int64_t Y, pt_pix vp)
{
    pt_fb_pixel q;
    long long idx = (long long)pt_raster_fb_pixel(vp.x, vp.y, s->vp_x, s->vp_y, s->fb_w,
                                                  s->fb_h, 1, &q);
    long long rows = (long long)(q.y_fb - Y);

    fprintf(f, "\nviewport pixel (x_vp, y_vp) = (%lld, %lld) -> framebuffer (x_fb, y_fb) = "
            "(%lld, %lld) -> index y_fb * W + x_fb = %lld * %d + %s%lld%s = %lld",
            (long long)vp.x, (long long)vp.y, (long long)q.x_fb, (long long)q.y_fb,
            (long long)q.y_fb, s->fb_w, q.x_fb < 0 ? "(" : "", (long long)q.x_fb,
            q.x_fb < 0 ? ")" : "", idx);
    if (q.x_fb == X && q.y_fb == Y)
        fputs(", where it lies\n", f);
    else
        fprintf(f, " -> shown at (x_fb, y_fb) = (%lld, %lld): x_fb = %lld lies %s, so the "
                "index falls %lld row%s %s\n", (long long)X, (long long)Y, (long long)q.x_fb,
                q.x_fb < 0 ? "left of the framebuffer" : "past its width",
                rows < 0 ? -rows : rows, rows == 1 || rows == -1 ? "" : "s",
                rows > 0 ? "up" : "down");
}
