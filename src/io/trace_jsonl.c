/*
** src/io/trace_jsonl.c -- the trace as JSON Lines, a record an object a line
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include <string.h>
#include "io/trace.h"
#include "io/trace_int.h"

/* ===== header ===== */

static void header_json(pt_trace *t, const pt_scene *s, const pt_plan *p)
{
    size_t k;
    int st, i;

    puts_(t, "{\"type\":\"header\",\"version\":1,");
    if (t->student && *t->student) {        /* a student build: which stage files */
        puts_(t, "\"student\":"); put_json_str(t, t->student); put(t, ",", 1);
    }
    puts_(t, "\"scene\":");
    put_json_str(t, s->path);
    puts_(t, ",\"framebuffer\":{\"w\":"); put_i64(t, s->fb_w);
    puts_(t, ",\"h\":"); put_i64(t, s->fb_h);
    puts_(t, "},\"background\":["); pt_trace_rgb(t, s->background, ",");
    puts_(t, "],\"viewport\":{\"x\":"); put_i64(t, s->vp_x);
    puts_(t, ",\"y\":"); put_i64(t, s->vp_y);
    puts_(t, ",\"w\":"); put_i64(t, s->vp_w);
    puts_(t, ",\"h\":"); put_i64(t, s->vp_h);
    puts_(t, "},\"camera\":\""); puts_(t, pt_trace_camera_name(s)); put(t, "\"", 1);
    if (p->pipe->matrices) pt_trace_camera(t, s, p, 1);
    if (s->from_obj) { puts_(t, ",\"obj_translate\":"); pt_trace_vec3_json(t, s->obj_translate); }
    puts_(t, ",\"models\":[");
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        const pt_model_plan *mp = &p->models[k];
        int first = 1;

        if (k) put(t, ",", 1);
        puts_(t, "{\"name\":"); put_json_str(t, m->name);
        puts_(t, ",\"vertices\":"); put_u64(t, m->nv);
        puts_(t, ",\"used\":"); put_u64(t, mp->nused);
        puts_(t, ",\"segments\":"); put_u64(t, m->nseg);
        puts_(t, ",\"translate\":"); pt_trace_vec3_json(t, m->translate);
        puts_(t, ",\"color\":["); pt_trace_rgb(t, m->color, ",");
        puts_(t, "],\"traced\":");
        puts_(t, mp->selected && !mp->hidden ? "true" : "false");
        if (p->pipe->matrices) { puts_(t, ",\"world\":"); pt_trace_mat(t, &mp->world, 1); }
        puts_(t, ",\"stages\":[");
        for (i = 0; i < p->norder; i++) {
            st = p->order[i];
            if (mp->why[st] != PT_WHY_TRACED) continue;
            if (!first) put(t, ",", 1);
            first = 0;
            put_json_str(t, pt_stage_infos[st].name);
        }
        puts_(t, "],\"left_out\":[");
        first = 1;
        for (i = 0; i < p->norder; i++) {
            st = p->order[i];
            if (mp->why[st] == PT_WHY_TRACED) continue;
            if (!first) put(t, ",", 1);
            first = 0;
            puts_(t, "{\"stage\":"); put_json_str(t, pt_stage_infos[st].name);
            puts_(t, ",\"why\":"); put_json_str(t, mp->why_text[st]); put(t, "}", 1);
        }
        puts_(t, "]}");
    }
    puts_(t, "]}\n");
}

/* ===== vertex records ===== */

/* '{"type":"vertex","model":"m1","v":': how the vertex records of model m
** begin (pt_trace_vertex_prefix). */
static void vertex_opening(pt_trace *t, const pt_model *m)
{
    puts_(t, "{\"type\":\"vertex\",\"model\":"); put_json_str(t, m->name);
    puts_(t, ",\"v\":");
}

/* --explain: r's formula with this vertex's numbers, from the journey pt_run()
** handed over before the records, so a stage left out still feeds the next
** one its real value: an "explain" field (trace_text.c: an indented line). */
static void put_explain(pt_trace *t, const pt_vrec *r)
{
    char b[PT_EXPLAINLEN];

    if (!t->journey_made) return;
    pt_explain_stage(b, sizeof b, &t->journey, r->stage, "; ");
    puts_(t, ",\"explain\":");
    put_json_str(t, b);
}

/* JSON: ["a","b"] at o, the names whose bits are set in bits. */
static char *names_json_at(char *o, unsigned bits, const char *const *names, int n)
{
    int k, first = 1;

    *o++ = '[';
    for (k = 0; k < n; k++) {
        if (!(bits & (1u << k))) continue;
        if (!first) *o++ = ',';
        first = 0;
        *o++ = '"';
        o = str_at(o, names[k]);
        *o++ = '"';
    }
    *o++ = ']';
    return o;
}

static void vertex_json(pt_trace *t, const pt_vrec *r)
{
    /* the stage's columns are read once, before any byte is stored (each
    ** may alias them) */
    const pt_stage_info *in = &pt_stage_infos[r->stage];
    const pt_value_kind kind = in->kind;
    const unsigned sflags = in->flags;
    const int nval = in->nreal + in->nint;
    char *o;

    if (t->clipv) {
        puts_(t, "{\"type\":\"clipvertex\",\"model\":"); put_json_str(t, t->model->name);
        o = room(t, PT_ROW_REST);
        o = str_at(o, ",\"segment\":"); o = u64_at(t, o, t->seg);
        o = str_at(o, ",\"from\":"); o = u64_at(t, o, t->from);
        o = str_at(o, ",\"to\":"); o = u64_at(t, o, t->to);
        o = str_at(o, ",\"t\":"); o = json_num_at(t, o, t->t_clip);
    } else {
        if (!(o = vertex_opening_at(t, 1, vertex_opening))) {
            puts_(t, "{\"type\":\"vertex\",\"model\":"); put_json_str(t, t->model->name);
            o = room(t, PT_ROW_REST);
            o = u64_at(t, str_at(o, ",\"v\":"), t->v);
        }
    }
    o = frag_at(t, o, r->stage, 0);         /* ,"stage":"camera","x": */
    switch (kind) {
    case PT_VAL_OUTCODE:                    /* ,"stage":"cvv","code": */
        o = int_at(t, o, r->code, 0);
        o = str_at(o, ",\"planes\":");
        o = names_json_at(o, r->code, pt_cvv_names, PT_CVV_NPLANES);
        break;
    case PT_VAL_REAL: {
        /* the first value's key came with the stage's name */
        const double v[4] = {r->x, r->y, r->z, r->w};
        int k;
        o = json_num_at(t, o, v[0]);
        for (k = 1; k < nval; k++)
            o = json_num_at(t, key_at(t, o, r->stage, k), v[k]);
        break;
    }
    case PT_VAL_PIXEL:
    case PT_VAL_INDEX: {                    /* viewport, framebuffer, index */
        const int64_t n[2] = {kind == PT_VAL_INDEX ? r->i : r->ix, r->iy};
        int k;
        for (k = 0; k < nval; k++) {
            if (k) o = key_at(t, o, r->stage, k);
            o = pt_rec_has(r, k) ? int_at(t, o, n[k], 0) : str_at(o, "null");
        }
        break;
    }
    }
    if (sflags & r->flags & PT_REC_BEHIND)
        o = str_at(o, ",\"behind\":true");
    if (sflags & PT_REC_INSIDE)             /* a stage that says inside or not */
        o = str_at(o, r->flags & PT_REC_INSIDE ? ",\"inside\":true" : ",\"inside\":false");
    if (r->warn) {                          /* ,"warning":["cancellation"],"digits_lost":9 */
        o = str_at(o, ",\"warning\":");
        o = names_json_at(o, r->warn, pt_warn_names, PT_NWARN);
        if (r->warn & (PT_WARN_CANCEL | PT_WARN_ILLCOND)) {
            o = str_at(o, ",\"digits_lost\":"); o = int_at(t, o, r->digits_lost, 0);
        }
    }
    if (!t->explain) {                      /* the usual case: close it in place */
        *o++ = '}';
        *o++ = '\n';
        t->len = (size_t)(o - t->buf);
        return;
    }
    t->len = (size_t)(o - t->buf);
    put_explain(t, r);
    puts_(t, "}\n");
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    vertex_json(ud, r);
}

/* ===== raster records ===== */

/* '{"type":"KIND","model":NAME,"segment":SEG': how a raster record opens. */
/* '{"type":"KIND","model":M,"KEY":N' */
static void put_rec_json(pt_trace *t, const char *kind, const pt_model *m, const char *key,
                         uint64_t n)
{
    puts_(t, "{\"type\":\""); puts_(t, kind); puts_(t, "\",\"model\":");
    put_json_str(t, m->name);
    puts_(t, ",\""); puts_(t, key); puts_(t, "\":"); put_u64(t, n);
}

static void put_seg_json(pt_trace *t, const char *kind, const pt_model *m, uint64_t seg)
{
    put_rec_json(t, kind, m, "segment", seg);
}

/* '{"type":"pixel","model":"m1","segment":7,"x":': how the pixel records of
** segment seg of m begin (pt_trace_pixel_prefix); returns the length of
** what the model's other segments share, up to the segment's number. */
static size_t pixel_opening(pt_trace *t, const pt_model *m, uint64_t seg)
{
    size_t start = t->len, mlen;

    put_seg_json(t, "pixel", m, seg);
    mlen = t->len - start - pt_fmt_ulen(seg);   /* up to the segment's number */
    puts_(t, ",\"x\":");
    return mlen;
}

static void pixel_prefix(pt_trace *t, const pt_model *m, uint64_t seg)
{
    if (m == t->pix_model && t->pix_len && t->pix_mlen + 32 <= sizeof t->pix) {
        /* the next segment of the same model: only the number changes */
        char *o = u64_at(t, t->pix + t->pix_mlen, seg);
        memcpy(o, ",\"x\":", 5);
        t->pix_seg = seg;
        t->pix_len = (size_t)(o + 5 - t->pix);
        return;
    }
    pt_trace_pixel_prefix(t, m, seg, pixel_opening);
}

/* One pixel record of segment or point (KEY) n, the long way. */
static void pixel_line(pt_trace *t, const pt_model *m, const char *key, uint64_t n,
                       const pt_fb_pixel *p)
{
    put_rec_json(t, "pixel", m, key, n);
    puts_(t, ",\"x\":"); put_i64(t, p->x_fb);
    puts_(t, ",\"y\":"); put_i64(t, p->y_fb);
    puts_(t, ",\"i\":"); put_i64(t, p->idx);
    puts_(t, "}\n");
}

/* A segment's pixel record, the long way: for a model whose name is too long
** to keep its opening. */
static void pixel_long(pt_trace *t, const pt_model *m, uint64_t seg, const pt_fb_pixel *p)
{
    pixel_line(t, m, "segment", seg, p);
}

/* x at o as int_at(t, o, x, 0) writes it: a pixel of the array (0 to
** 10^8 - 1) straight from the digit table, without the sign's test. */
static inline char *pixel_int_at(const pt_trace *t, char *o, int64_t x)
{
    if ((uint64_t)x < 100000000) return o + pt_fmt_u32_tab(&t->digits, o, (uint32_t)x);
    return int_at(t, o, x, 0);
}

/* The rest of a pixel record after its kept opening, at o:
** 'X,"y":Y,"i":I}\n'. */
static char *pixel_json_at(const pt_trace *t, char *o, const pt_fb_pixel *p)
{
    o = pixel_int_at(t, o, p->x_fb);
    memcpy(o, ",\"y\":", 5);
    o = pixel_int_at(t, o + 5, p->y_fb);
    memcpy(o, ",\"i\":", 5);
    o = pixel_int_at(t, o + 5, p->idx);
    memcpy(o, "}\n", 2);
    return o + 2;
}

static void on_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                      size_t n)
{
    pixels_put(ud, m, seg, px, n, pixel_prefix, pixel_long, pixel_json_at);
}

/* A point's pixels: {"type":"pixel","model":M,"point":N,"x":X,"y":Y,"i":I},
** the plain way. */
static void on_point_pixels(void *ud, const pt_model *m, uint64_t pt, const pt_fb_pixel *px,
                            size_t n)
{
    size_t k;

    for (k = 0; k < n; k++) pixel_line(ud, m, "point", pt, &px[k]);
}

static void put_pair_json(pt_trace *t, pt_pix p)
{
    put(t, "[", 1);     /* null where the step has no such value (PT_PIX_NONE) */
    if (p.x == PT_PIX_NONE) puts_(t, "null"); else put_i64(t, p.x);
    put(t, ",", 1);
    if (p.y == PT_PIX_NONE) puts_(t, "null"); else put_i64(t, p.y);
    put(t, "]", 1);
}

static void on_clip(void *ud, const pt_model *m, uint64_t seg, uint64_t count,
                    pt_pix first, pt_pix last)
{
    pt_trace *t = ud;

    put_seg_json(t, "clip", m, seg);
    puts_(t, ",\"count\":"); put_u64(t, count);
    puts_(t, ",\"first\":"); put_pair_json(t, first);
    puts_(t, ",\"last\":"); put_pair_json(t, last);
    puts_(t, "}\n");
}

/* A segment's remark of type TYPE, its text under KEY. */
static void remark(pt_trace *t, const pt_model *m, uint64_t seg, const char *type,
                   uint64_t v, const char *key, const char *text)
{
    put_seg_json(t, type, m, seg);
    if (v) { puts_(t, ",\"v\":"); put_u64(t, v); }
    puts_(t, key); put_json_str(t, text); puts_(t, "}\n");
}

static void on_skip(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *why)
{
    remark(ud, m, seg, "skip", v, ",\"why\":", why);
}

static void on_note(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *what)
{
    remark(ud, m, seg, "note", v, ",\"what\":", what);
}

/* ===== summary ===== */

static void on_summary(void *ud, const pt_summary *sum)
{
    pt_trace *t = ud;
    pt_trace_count c[PT_TRACE_NCOUNTS];
    size_t k;

    pt_trace_counts(sum, c);
    puts_(t, "{\"type\":\"summary\"");
    for (k = 0; k < PT_TRACE_NCOUNTS; k++) {
        puts_(t, ",\""); puts_(t, c[k].name); puts_(t, "\":");
        pt_trace_put_u128(t, c[k].hi, c[k].lo);
    }
    puts_(t, ",\"warnings\":{");
    for (k = 0; k < PT_NWARN; k++) {
        if (k) put(t, ",", 1);
        put(t, "\"", 1); puts_(t, pt_warn_names[k]); puts_(t, "\":");
        put_u64(t, sum->warnings[k]);
    }
    puts_(t, sum->rasterized ? "},\"rasterized\":true}\n" : "},\"rasterized\":false}\n");
}

const pt_trace_writer pt_trace_jsonl = {
    header_json, on_vertex, on_pixels, on_clip, on_point_pixels, on_skip, on_note, on_summary
};
