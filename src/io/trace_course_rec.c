/*
** src/io/trace_course_rec.c -- pipetrace's trace of a renderer 7 or 9 scene (text, jsonl, csv)
** See LICENSE for copyright and license.
**
** One walker listens to the driver (core/course.h) and fills a record per
** event: a vertex at a stage (the clip stages: only the vertices they make,
** with the primitive and t they came from), a primitive drawn.  Three small
** formatters spell a record: JSON Lines, text, CSV.  docs/trace-format.md
** lists the fields.
*/
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/trace_course.h"
#include "io/trace.h"
#include "io/explain_course.h"
#include "io/numfmt.h"
#include "io/sbuf.h"

static const char *const stage_names[PT_NCST] = {
    "model", "world", "view", "camera", "nearclip", "image", "clip"};

typedef enum rkind { R_VERTEX, R_PRIM, R_WARN, R_PIXEL } rkind;

/* One record. */
typedef struct rec {
    rkind kind;
    const char *model, *position;
    const char *stage;
    uint64_t v;                  /* vertex: 1-based; prim: its number in the list */
    pt_vec4 p;                   /* vertex: x y z (w with renderer 9) */
    int has_color;
    pt_rgb color;                /* vertex: the colour of its number; a clip
                                 ** stage's vertex: the colour it made */
    const char *from;            /* a clip stage's new vertex: the stage, */
    uint64_t from_prim;          /*   the segment's number in its list (1-based), */
    double t;                    /*   t, */
    const char *edge;            /*   the edge: "z=n", "x=+1", ... */
    const pt_rv_prim *prim;      /* prim: the primitive (0-based indices) */
    uint64_t pixels;             /* prim: pixels written */
    const char *warning;         /* warn: what the course warns of */
    int64_t x_fb, y_fb;          /* pixel: the framebuffer pixel written, */
    unsigned char rgb[3];        /*   the colour written there, */
    float coverage;              /*   the share of it the primitive covers */
    const char *explain;         /* vertex, --explain: its formula with its numbers */
} rec;

typedef struct walker {
    FILE *f;
    const pt_scene *s;
    int fmt, precision, w4;
    pt_sbuf sb;
    uint64_t prim_no;            /* the primitive a clip stage is on */
    uint64_t raster_no;          /* the primitive the rasterizer is on */
    const char *clip_stage;
    /* the clip stages' new vertices: where each came from, by number */
    struct origin { uint32_t v, c; uint64_t prim; double t; pt_rv_edge edge; pt_rv_cut cut; } *org;
    size_t norg, cap_org;
    uint64_t nvrec, nprims, npixels;
    const pt_course_pos *pos;    /* the position the rasterizer draws */
    pt_sbuf names;               /* JSON: ,"model":M,"position":P for the
                                 ** names below (made once: every record of a
                                 ** position has it) */
    const char *names_model, *names_position;
    int explain;                 /* --explain: each vertex record's formula */
    pt_course_cam cam;           /*   the camera, */
    struct prev { pt_vec4 *v; size_t n; } *prev;  /* each position's vertices
                                 ** after the stage reported last */
    char xbuf[8192];             /*   and the text of one record */
} walker;

/* ===== numbers ===== */

static void num_json(pt_sbuf *sb, double x)
{
    char b[PT_NUMLEN];
    if (isnan(x)) { pt_sbuf_add(sb, "\"nan\""); return; }
    if (isinf(x)) { pt_sbuf_add(sb, x > 0 ? "\"inf\"" : "\"-inf\""); return; }
    if (x == 0.0 && signbit(x)) { pt_sbuf_add(sb, "-0.0"); return; }
    pt_fmt_shortest(b, x);
    pt_sbuf_add(sb, b);
}

static void num_csv(pt_sbuf *sb, double x)
{
    char b[PT_NUMLEN];
    if (x == 0.0 && signbit(x)) { pt_sbuf_add(sb, "-0"); return; }
    pt_fmt_shortest(b, x);
    pt_sbuf_add(sb, b);
}

static void num_text(pt_sbuf *sb, double x, int prec)
{
    char b[PT_NUMLEN];
    pt_fmt_fixed(b, x, prec);
    pt_sbuf_addf(sb, "%13s", b);
}

static const char *edge_name(pt_rv_edge e)
{
    switch (e) {
    case PT_RV_NEAR: return "z=n";
    case PT_RV_XPOS: return "x=+1";
    case PT_RV_XNEG: return "x=-1";
    case PT_RV_YPOS: return "y=+1";
    case PT_RV_YNEG: return "y=-1";
    }
    return "";
}

/* ===== the three formatters ===== */

/* t at q (no NUL); returns the end. */
static char *put_str(char *q, const char *t)
{
    size_t n = strlen(t);
    memcpy(q, t, n);
    return q + n;
}

/* x in decimal at q (no NUL), as %lld; returns the end. */
static char *put_i64(char *q, int64_t x)
{
    if (x < 0) *q++ = '-';
    return q + pt_fmt_u64(q, x < 0 ? 0u - (uint64_t)x : (uint64_t)x);
}

/* Make w->names say r's model and position, unless it does.  0 when out of
** memory (then the record is not written: the trace's buffer says so). */
static int names(walker *w, const rec *r)
{
    if (!w->names.s || r->model != w->names_model || r->position != w->names_position) {
        w->names.len = 0;
        pt_sbuf_add(&w->names, ",\"model\":");
        pt_sbuf_add_json(&w->names, r->model);
        pt_sbuf_add(&w->names, ",\"position\":");
        pt_sbuf_add_json(&w->names, r->position);
        w->names_model = r->model;
        w->names_position = r->position;
    }
    if (w->names.failed) w->sb.failed = 1;
    return !w->names.failed;
}

static void fmt_json(walker *w, const rec *r)
{
    pt_sbuf *sb = &w->sb;

    if (!names(w, r)) return;
    if (r->kind == R_PIXEL) {                   /* one a pixel: spelt in place */
        char b[160], *q = b;
        pt_sbuf_add(sb, "{\"type\":\"pixel\"");
        pt_sbuf_addn(sb, w->names.s, w->names.len);
        q = put_i64(put_str(q, ",\"primitive\":"), (int64_t)r->v);
        q = put_i64(put_str(q, ",\"x\":"), r->x_fb);
        q = put_i64(put_str(q, ",\"y\":"), r->y_fb);
        q = put_i64(put_str(q, ",\"rgb\":["), r->rgb[0]);
        q = put_i64(put_str(q, ","), r->rgb[1]);
        q = put_i64(put_str(q, ","), r->rgb[2]);
        q = put_str(q, "],\"coverage\":");
        pt_sbuf_addn(sb, b, (size_t)(q - b));
        num_json(sb, (double)r->coverage);
        pt_sbuf_add(sb, "}\n");
        return;
    }
    if (r->kind == R_WARN) {
        pt_sbuf_add(sb, "{\"type\":\"warning\"");
        pt_sbuf_addn(sb, w->names.s, w->names.len);
        pt_sbuf_addf(sb, ",\"warning\":\"%s\"}\n", r->warning);
        return;
    }
    pt_sbuf_add(sb, r->kind == R_VERTEX ? "{\"type\":\"vertex\"" : "{\"type\":\"primitive\"");
    pt_sbuf_addn(sb, w->names.s, w->names.len);
    if (r->kind == R_PRIM) {
        const pt_rv_prim *p = r->prim;
        pt_sbuf_addf(sb, ",\"primitive\":%llu,\"kind\":\"%s\"", (unsigned long long)r->v,
                     p->kind == PT_RV_POINT ? "point" : "line");
        if (p->kind == PT_RV_POINT)
            pt_sbuf_addf(sb, ",\"v\":[%lu],\"c\":[%lu],\"radius\":%d",
                         (unsigned long)p->v[0] + 1, (unsigned long)p->c[0] + 1, p->radius);
        else
            pt_sbuf_addf(sb, ",\"v\":[%lu,%lu],\"c\":[%lu,%lu]", (unsigned long)p->v[0] + 1,
                         (unsigned long)p->v[1] + 1, (unsigned long)p->c[0] + 1,
                         (unsigned long)p->c[1] + 1);
        pt_sbuf_addf(sb, ",\"pixels\":%llu}\n", (unsigned long long)r->pixels);
        return;
    }
    {
        char b[64], *q = put_i64(b, (int64_t)r->v);
        pt_sbuf_add(sb, ",\"v\":");
        pt_sbuf_addn(sb, b, (size_t)(q - b));
        pt_sbuf_add(sb, ",\"stage\":\"");
        pt_sbuf_add(sb, r->stage);
        pt_sbuf_add(sb, "\",\"x\":");
    }
    num_json(sb, r->p.x);
    pt_sbuf_add(sb, ",\"y\":");
    num_json(sb, r->p.y);
    pt_sbuf_add(sb, ",\"z\":");
    num_json(sb, r->p.z);
    if (w->w4) { pt_sbuf_add(sb, ",\"w\":"); num_json(sb, r->p.w); }
    if (r->has_color) {
        pt_sbuf_add(sb, ",\"color\":[");
        num_json(sb, (double)r->color.r); pt_sbuf_add(sb, ",");
        num_json(sb, (double)r->color.g); pt_sbuf_add(sb, ",");
        num_json(sb, (double)r->color.b); pt_sbuf_add(sb, "]");
    }
    if (r->from) {
        pt_sbuf_addf(sb, ",\"from\":{\"stage\":\"%s\",\"segment\":%llu,\"edge\":\"%s\",\"t\":",
                     r->from, (unsigned long long)r->from_prim, r->edge);
        num_json(sb, r->t);
        pt_sbuf_add(sb, "}");
    }
    if (r->explain) {
        pt_sbuf_add(sb, ",\"explain\":");
        pt_sbuf_add_json(sb, r->explain);
    }
    pt_sbuf_add(sb, "}\n");
}

static void fmt_text(walker *w, const rec *r)
{
    pt_sbuf *sb = &w->sb;

    pt_sbuf_add_term(sb, r->model, strlen(r->model));
    if (r->kind == R_PIXEL) {
        pt_sbuf_addf(sb, " p%-6llu pixel        x_fb = %lld  y_fb = %lld  rgb = %d %d %d  "
                     "coverage %.4f\n", (unsigned long long)r->v, (long long)r->x_fb,
                     (long long)r->y_fb, r->rgb[0], r->rgb[1], r->rgb[2], (double)r->coverage);
        return;
    }
    if (r->kind == R_WARN) {
        pt_sbuf_addf(sb, " warning: %s\n", r->warning);
        return;
    }
    if (r->kind == R_PRIM) {
        const pt_rv_prim *p = r->prim;
        if (p->kind == PT_RV_POINT)
            pt_sbuf_addf(sb, " p%-6llu drawn        point v%lu c%lu radius %d: %llu pixels\n",
                         (unsigned long long)r->v, (unsigned long)p->v[0] + 1,
                         (unsigned long)p->c[0] + 1, p->radius, (unsigned long long)r->pixels);
        else
            pt_sbuf_addf(sb, " p%-6llu drawn        line v%lu v%lu c%lu c%lu: %llu pixels\n",
                         (unsigned long long)r->v, (unsigned long)p->v[0] + 1,
                         (unsigned long)p->v[1] + 1, (unsigned long)p->c[0] + 1,
                         (unsigned long)p->c[1] + 1, (unsigned long long)r->pixels);
        return;
    }
    pt_sbuf_addf(sb, " v%-6llu %-12s x =", (unsigned long long)r->v, r->stage);
    num_text(sb, r->p.x, w->precision);
    pt_sbuf_add(sb, "  y =");
    num_text(sb, r->p.y, w->precision);
    pt_sbuf_add(sb, "  z =");
    num_text(sb, r->p.z, w->precision);
    if (w->w4) { pt_sbuf_add(sb, "  w ="); num_text(sb, r->p.w, w->precision); }
    if (r->has_color)
        pt_sbuf_addf(sb, "  rgb = %.6f %.6f %.6f", (double)r->color.r, (double)r->color.g,
                     (double)r->color.b);
    if (r->from) {
        char b[PT_NUMLEN];
        pt_fmt_shortest(b, r->t);
        pt_sbuf_addf(sb, "  from %s of segment %llu at %s, t = %s", r->from,
                     (unsigned long long)r->from_prim, r->edge, b);
    }
    pt_sbuf_add(sb, "\n");
    if (r->explain) {                       /* under the record, as renderer 4's */
        pt_sbuf_add(sb, "              ");
        pt_sbuf_add(sb, r->explain);
        pt_sbuf_add(sb, "\n");
    }
}

static void fmt_csv(walker *w, const rec *r)
{
    pt_sbuf *sb = &w->sb;

    if (r->kind != R_VERTEX) return;             /* CSV: vertex rows only */
    pt_sbuf_add_csv(sb, r->model);
    pt_sbuf_add(sb, ",");
    pt_sbuf_add_csv(sb, r->position);
    pt_sbuf_addf(sb, ",%llu,%s,", (unsigned long long)r->v, r->stage);
    num_csv(sb, r->p.x); pt_sbuf_add(sb, ",");
    num_csv(sb, r->p.y); pt_sbuf_add(sb, ",");
    num_csv(sb, r->p.z); pt_sbuf_add(sb, ",");
    if (w->w4) num_csv(sb, r->p.w);
    pt_sbuf_add(sb, ",");
    if (r->has_color) {
        num_csv(sb, (double)r->color.r); pt_sbuf_add(sb, ",");
        num_csv(sb, (double)r->color.g); pt_sbuf_add(sb, ",");
        num_csv(sb, (double)r->color.b);
    } else pt_sbuf_add(sb, ",,");
    if (r->from) {
        pt_sbuf_addf(sb, ",%s,%llu,%s,", r->from, (unsigned long long)r->from_prim, r->edge);
        num_csv(sb, r->t);
    } else pt_sbuf_add(sb, ",,,,");
    pt_sbuf_add(sb, "\n");
}

static void emit(walker *w, const rec *r)
{
    switch (w->fmt) {
    case PT_FORMAT_JSONL: fmt_json(w, r); break;
    case PT_FORMAT_CSV: fmt_csv(w, r); break;
    default: fmt_text(w, r); break;
    }
    if (w->sb.len && !w->sb.failed) fwrite(w->sb.s, 1, w->sb.len, w->f);
    w->sb.len = 0;
}

/* ===== the walker ===== */

/* Start a record of kind k about position pos. */
static void rec_init(rec *r, rkind k, const pt_course_pos *pos)
{
    memset(r, 0, sizeof *r);
    r->kind = k;
    r->model = pos->sm->name;
    r->position = pos->pos_name;
}

static const struct origin *origin_of(const walker *w, uint32_t v)
{
    size_t k;
    for (k = w->norg; k-- > 0;)
        if (w->org[k].v == v) return &w->org[k];
    return NULL;
}

/* --explain: record r's formula with its numbers (pt_cx_explain_rec), from
** the position's vertices after the stage before; o: where a clip stage's
** new vertex came from. */
static void explain(walker *w, rec *r, pt_course_stage st, const pt_course_pos *pos, size_t k,
                    const struct origin *o)
{
    const struct prev *pv = &w->prev[pos->index];
    pt_cx_rec x;

    memset(&x, 0, sizeof x);
    x.st = st;
    x.pos = pos;
    x.cur = r->p;
    if (k < pv->n) x.prev = pv->v[k];
    x.color = r->has_color ? &r->color : NULL;
    if (o) { x.cut = &o->cut; x.cut_prim = o->prim; }
    pt_cx_explain_rec(w->xbuf, sizeof w->xbuf, w->s, &w->cam, &x, "; ");
    r->explain = w->xbuf;
}

/* --explain: keep the position's vertices after stage st for the next. */
static void keep_prev(walker *w, const pt_course_pos *pos, const pt_rv_model *m)
{
    struct prev *pv = &w->prev[pos->index];
    pt_vec4 *v = realloc(pv->v, (m->nv ? m->nv : 1) * sizeof *v);

    if (!v) { w->sb.failed = 1; return; }
    if (m->nv) memcpy(v, m->v, m->nv * sizeof *v);
    pv->v = v;
    pv->n = m->nv;
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    walker *w = ud;
    size_t k, from = 0;
    const struct origin *o;
    rec r;

    if (st == PT_CST_NEARCLIP || st == PT_CST_CLIP) {   /* only the vertices it made */
        from = m->nv;
        for (k = 0; k < w->norg; k++)
            if (w->org[k].v < from) from = w->org[k].v;
    }
    for (k = from; k < m->nv; k++) {
        rec_init(&r, R_VERTEX, pos);
        r.stage = stage_names[st];
        r.v = (uint64_t)k + 1;
        r.p = m->v[k];
        if (k < m->nc) { r.has_color = 1; r.color = m->c[k]; }
        o = NULL;
        if (st == PT_CST_NEARCLIP || st == PT_CST_CLIP) {
            o = origin_of(w, (uint32_t)k);
            if (o) {
                r.from = stage_names[st];
                r.from_prim = o->prim;
                r.t = o->t;
                r.edge = edge_name(o->edge);
                r.has_color = o->c < m->nc;
                if (r.has_color) r.color = m->c[o->c];
            }
        }
        if (w->explain) explain(w, &r, st, pos, k, o);
        emit(w, &r);
        w->nvrec++;
    }
    if (w->explain) keep_prev(w, pos, m);
    w->prim_no = 0;
    w->norg = 0;
    w->raster_no = 0;
}

static void clip_begin(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    walker *w = ud;
    (void)m; (void)p;
    w->prim_no++;
}

static void clip_cut(void *ud, const pt_rv_cut *c)
{
    walker *w = ud;

    if (w->norg == w->cap_org) {
        size_t cap = w->cap_org ? 2 * w->cap_org : 16;
        struct origin *o = realloc(w->org, cap * sizeof *o);
        if (!o) { w->sb.failed = 1; return; }
        w->org = o;
        w->cap_org = cap;
    }
    w->org[w->norg].v = c->v_new;
    w->org[w->norg].c = c->c_new;
    w->org[w->norg].prim = w->prim_no;
    w->org[w->norg].t = c->t;
    w->org[w->norg].edge = c->edge;
    w->org[w->norg].cut = *c;
    w->norg++;
}

static void on_warn(void *ud, pt_course_warn k, const pt_course_pos *pos,
                    const pt_rv_model *m)
{
    walker *w = ud;
    rec r;

    (void)m;
    rec_init(&r, R_WARN, pos);
    switch (k) {
    case PT_CWN_NO_VERTICES: r.warning = "no_vertices"; break;
    case PT_CWN_NO_PRIMITIVES: r.warning = "no_primitives"; break;
    case PT_CWN_NO_COLORS: r.warning = "no_colors"; break;
    case PT_CWN_DUMP: return;
    case PT_CWN_DEFAULT_COLOR: r.warning = "default_color"; break;
    }
    emit(w, &r);
}

/* One pixel record: (x_vp, y_vp) in the viewport, colour c, coverage f. */
static void pixel_rec(walker *w, const pt_rv_raster_par *par, int x_vp, int y_vp, pt_rgb c,
                      float f)
{
    rec r;

    rec_init(&r, R_PIXEL, w->pos);
    r.v = w->raster_no + 1;
    r.x_fb = (int64_t)par->x_ul + x_vp;
    r.y_fb = (int64_t)par->y_ul + y_vp;
    r.rgb[0] = pt_color_byte(c.r);
    r.rgb[1] = pt_color_byte(c.g);
    r.rgb[2] = pt_color_byte(c.b);
    r.coverage = f;
    emit(w, &r);
}

/* The rasterizer's pixel lines as pixel records: an anti-aliased step is
** two pixels, weighted 1 - f and f, f the fraction of the stepped y. */
static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    walker *w = ud;
    const pt_rv_raster_par *par = px->par;

    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
        pixel_rec(w, par, px->x_vp, px->y_vp, px->c[0], 1.0f);
        break;
    case PT_RV_PX_POINT:
        if (!px->clipped) pixel_rec(w, par, px->x_vp, px->y_vp, px->c[0], 1.0f);
        break;
    case PT_RV_PX_AA: {
        double y = px->transposed ? px->x_pp : px->y_pp;
        float f = (float)(y - (double)(int64_t)y);
        if (px->transposed) {
            pixel_rec(w, par, px->lo, px->y_vp, px->c[0], 1.0f - f);
            pixel_rec(w, par, px->hi, px->y_vp, px->c[1], f);
        } else {
            pixel_rec(w, par, px->x_vp, px->lo, px->c[0], 1.0f - f);
            pixel_rec(w, par, px->x_vp, px->hi, px->c[1], f);
        }
        break;
    }
    }
}

static void on_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    walker *w = ud;
    (void)m; (void)p;
    w->pos = pos;
}

static void on_drawn(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                     const pt_rv_prim *p, uint64_t n)
{
    walker *w = ud;
    rec r;

    (void)m;
    rec_init(&r, R_PRIM, pos);
    r.v = ++w->raster_no;
    r.prim = p;
    r.pixels = n;
    emit(w, &r);
    w->nprims++;
    w->npixels += n;
}

/* The header: the scene, its renderer, framebuffer, viewport and camera. */
static void header(walker *w, const pt_course_cam *c)
{
    const pt_scene *s = w->s;
    const pt_rv_camera *k = &c->cam;
    pt_sbuf *sb = &w->sb;

    if (w->fmt == PT_FORMAT_CSV) {
        pt_sbuf_add(sb, "model,position,v,stage,x,y,z,w,r,g,b,from,segment,edge,t\n");
    } else if (w->fmt == PT_FORMAT_JSONL) {
        pt_sbuf_addf(sb, "{\"type\":\"header\",\"version\":1,\"renderer\":%d,\"pipeline\":%d,"
                     "\"scene\":", s->renderer, s->pipeline2 ? 2 : 1);
        pt_sbuf_add_json(sb, s->path);
        pt_sbuf_addf(sb, ",\"framebuffer\":{\"w\":%d,\"h\":%d},\"viewport\":{\"x\":%d,\"y\":%d,"
                     "\"w\":%d,\"h\":%d},\"camera\":{\"projection\":\"%s\",\"l\":", s->fb_w,
                     s->fb_h, s->vp_x, s->vp_y, s->vp_w, s->vp_h,
                     k->perspective ? "perspective" : "orthographic");
        num_json(sb, k->l); pt_sbuf_add(sb, ",\"r\":");
        num_json(sb, k->r); pt_sbuf_add(sb, ",\"b\":");
        num_json(sb, k->b); pt_sbuf_add(sb, ",\"t\":");
        num_json(sb, k->t); pt_sbuf_add(sb, ",\"n\":");
        num_json(sb, k->n); pt_sbuf_addf(sb, "},\"nearclip\":%s,\"antialias\":%s,\"gamma\":%s}\n",
                                          s->nearclip ? "true" : "false",
                                          s->antialias ? "true" : "false",
                                          s->gamma ? "true" : "false");
    } else {
        char b[5][PT_NUMLEN];
        pt_sbuf_add(sb, "# pipetrace trace of a course renderer's scene, format version 1\nscene        ");
        pt_sbuf_add_term(sb, s->path, strlen(s->path));
        pt_fmt_shortest(b[0], k->l); pt_fmt_shortest(b[1], k->r);
        pt_fmt_shortest(b[2], k->b); pt_fmt_shortest(b[3], k->t);
        pt_fmt_shortest(b[4], k->n);
        pt_sbuf_addf(sb, "\nrenderer     %d%s\nframebuffer  %d x %d\nviewport     %d x %d at "
                     "(x_ul, y_ul) = (%d, %d)\ncamera       %s, l r b t = %s %s %s %s, n = %s\n"
                     "switches     nearclip %s, antialias %s, gamma %s\n\n", s->renderer,
                     s->pipeline2 ? " (Pipeline2)" : "", s->fb_w, s->fb_h, s->vp_w, s->vp_h,
                     s->vp_x, s->vp_y, k->perspective ? "perspective" : "orthographic",
                     b[0], b[1], b[2], b[3], b[4], s->nearclip ? "on" : "off",
                     s->antialias ? "on" : "off", s->gamma ? "on" : "off");
    }
    if (!w->sb.failed) fwrite(sb->s, 1, sb->len, w->f);
    sb->len = 0;
}

static void summary(walker *w)
{
    if (w->fmt == PT_FORMAT_CSV) return;
    if (w->fmt == PT_FORMAT_JSONL)
        fprintf(w->f, "{\"type\":\"summary\",\"models\":%lu,\"vertex_records\":%llu,"
                "\"primitives_drawn\":%llu,\"pixels\":%llu}\n", (unsigned long)w->s->nmodels,
                (unsigned long long)w->nvrec, (unsigned long long)w->nprims,
                (unsigned long long)w->npixels);
    else
        fprintf(w->f, "\nsummary\n  models %lu  vertex_records %llu  primitives_drawn %llu  "
                "pixels %llu\n", (unsigned long)w->s->nmodels, (unsigned long long)w->nvrec,
                (unsigned long long)w->nprims, (unsigned long long)w->npixels);
}

int pt_course_trace(FILE *f, const pt_scene *s, int fmt, int precision, int explain,
                    pt_fb *fb, char *err, size_t errlen)
{
    walker w;
    pt_course_ls ls;
    pt_rv_raster_ls rls;
    pt_course_cam cam;
    int rc;

    memset(&w, 0, sizeof w);
    w.f = f;
    w.s = s;
    w.fmt = fmt;
    w.precision = precision;
    w.w4 = s->renderer == 9;
    pt_sbuf_init(&w.sb);
    pt_sbuf_init(&w.names);
    memset(&rls, 0, sizeof rls);
    rls.pixel = on_pixel;
    rls.ud = &w;
    memset(&ls, 0, sizeof ls);
    ls.stage = on_stage;
    ls.drawn = on_drawn;
    ls.raster = on_raster;
    ls.raster_ls = fmt == PT_FORMAT_CSV ? NULL : &rls;   /* CSV: no pixel rows */
    ls.warn = on_warn;
    ls.nearclip.begin = clip_begin;
    ls.nearclip.cut = clip_cut;
    ls.nearclip.ud = &w;
    ls.clip = ls.nearclip;
    ls.ud = &w;
    pt_course_camera(s, &cam);
    w.cam = cam;
    w.explain = explain;
    if (explain && !(w.prev = calloc(s->nmodels ? s->nmodels : 1, sizeof *w.prev))) {
        snprintf(err, errlen, "pipetrace: out of memory");
        pt_sbuf_free(&w.sb);
        return -1;
    }
    header(&w, &cam);
    rc = pt_course_render(s, fb, &ls);
    if (rc == 0 && !w.sb.failed) summary(&w);
    if (rc != 0 || w.sb.failed) snprintf(err, errlen, "pipetrace: out of memory");
    rc = rc != 0 || w.sb.failed ? -1 : 0;
    pt_sbuf_free(&w.sb);
    pt_sbuf_free(&w.names);
    free(w.org);
    if (w.prev) {
        size_t k;
        for (k = 0; k < s->nmodels; k++) free(w.prev[k].v);
        free(w.prev);
    }
    return rc;
}
