/*
** src/trace.c -- write the trace: JSON Lines, aligned text, or CSV
** See LICENSE for copyright and license.
*/
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "trace.h"
#include "numfmt.h"

/* ===== the output block ===== */

static void flush(pt_trace *t)
{
    if (t->len && fwrite(t->buf, 1, t->len, t->f) != t->len) t->failed = 1;
    t->len = 0;
}

static void put(pt_trace *t, const char *s, size_t n)
{
    if (t->len + n > sizeof t->buf) flush(t);
    if (n > sizeof t->buf) {                /* longer than a block: write as is */
        if (fwrite(s, 1, n, t->f) != n) t->failed = 1;
        return;
    }
    memcpy(t->buf + t->len, s, n);
    t->len += n;
}

static void puts_(pt_trace *t, const char *s) { put(t, s, strlen(s)); }

static void put_i64(pt_trace *t, int64_t x)
{
    char b[24];
    put(t, b, (size_t)snprintf(b, sizeof b, "%" PRId64, x));
}

static void put_u64(pt_trace *t, uint64_t x)
{
    char b[24];
    put(t, b, (size_t)snprintf(b, sizeof b, "%" PRIu64, x));
}

/* A double in JSON: shortest round-trip, non-finite as a string. */
static void put_json_num(pt_trace *t, double x)
{
    char b[PT_NUMLEN];
    size_t n = pt_fmt_shortest(b, x);

    if (isfinite(x)) { put(t, b, n); return; }
    put(t, "\"", 1); put(t, b, n); put(t, "\"", 1);
}

static void put_short(pt_trace *t, double x)
{
    char b[PT_NUMLEN];
    put(t, b, pt_fmt_shortest(b, x));
}

/* A string in JSON quotes, escaping what JSON requires. */
static void put_json_str(pt_trace *t, const char *s)
{
    put(t, "\"", 1);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') { char e[2] = {'\\', (char)c}; put(t, e, 2); }
        else if (c < 0x20) { char e[8]; put(t, e, (size_t)snprintf(e, sizeof e, "\\u%04x", c)); }
        else put(t, (const char *)&c, 1);
    }
    put(t, "\"", 1);
}

/* Text: a fixed-width right-aligned column. */
static void put_col(pt_trace *t, const char *s, size_t n, size_t width)
{
    static const char spaces[] = "                                ";
    if (n < width) put(t, spaces, width - n < 32 ? width - n : 32);
    put(t, s, n);
}

static void put_fixed_col(pt_trace *t, double x, int prec)
{
    char b[PT_NUMLEN];
    put_col(t, b, pt_fmt_fixed(b, x, prec), 12);
}

static void put_int_col(pt_trace *t, int64_t x)
{
    char b[24];
    put_col(t, b, (size_t)snprintf(b, sizeof b, "%" PRId64, x), 12);
}

/* Text: "name v12", padded so that the stage names line up. */
static void put_who(pt_trace *t, const char *name, const char *kind, uint64_t n)
{
    char b[32];
    size_t len = strlen(name) + 1 + (size_t)snprintf(b, sizeof b, "%s%" PRIu64, kind, n);
    puts_(t, name);
    put(t, " ", 1);
    puts_(t, b);
    put_col(t, "", 0, len < 14 ? 14 - len : 1);
}

/* ===== header ===== */

static const char *camera_name(const pt_scene *s)
{
    return s->perspective ? "perspective" : "orthographic";
}

static void header_json(pt_trace *t, const pt_scene *s, const pt_plan *p)
{
    size_t k;
    int st;

    puts_(t, "{\"type\":\"header\",\"version\":1,\"scene\":");
    put_json_str(t, s->path);
    puts_(t, ",\"framebuffer\":{\"w\":"); put_i64(t, s->fb_w);
    puts_(t, ",\"h\":"); put_i64(t, s->fb_h);
    puts_(t, "},\"background\":["); put_i64(t, s->background[0]);
    put(t, ",", 1); put_i64(t, s->background[1]);
    put(t, ",", 1); put_i64(t, s->background[2]);
    puts_(t, "],\"viewport\":{\"x\":"); put_i64(t, s->vp_x);
    puts_(t, ",\"y\":"); put_i64(t, s->vp_y);
    puts_(t, ",\"w\":"); put_i64(t, s->vp_w);
    puts_(t, ",\"h\":"); put_i64(t, s->vp_h);
    puts_(t, "},\"camera\":\""); puts_(t, camera_name(s)); put(t, "\"", 1);
    if (s->from_obj) {
        puts_(t, ",\"obj_translate\":["); put_json_num(t, s->obj_translate.x);
        put(t, ",", 1); put_json_num(t, s->obj_translate.y);
        put(t, ",", 1); put_json_num(t, s->obj_translate.z); put(t, "]", 1);
    }
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
        puts_(t, ",\"translate\":["); put_json_num(t, m->translate.x);
        put(t, ",", 1); put_json_num(t, m->translate.y);
        put(t, ",", 1); put_json_num(t, m->translate.z);
        puts_(t, "],\"color\":["); put_i64(t, m->color[0]);
        put(t, ",", 1); put_i64(t, m->color[1]);
        put(t, ",", 1); put_i64(t, m->color[2]);
        puts_(t, "],\"traced\":");
        puts_(t, mp->selected ? "true" : "false");
        puts_(t, ",\"stages\":[");
        for (st = 0; st < PT_NSTAGES; st++) {
            if (mp->why[st] != PT_WHY_TRACED) continue;
            if (!first) put(t, ",", 1);
            first = 0;
            put_json_str(t, pt_stage_infos[st].name);
        }
        puts_(t, "],\"left_out\":[");
        first = 1;
        for (st = 0; st < PT_NSTAGES; st++) {
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

static void header_text(pt_trace *t, const pt_scene *s, const pt_plan *p)
{
    size_t k;
    int st;

    puts_(t, "# pipetrace trace, format version 1\nscene        ");
    puts_(t, s->path);
    puts_(t, "\nframebuffer  "); put_i64(t, s->fb_w); puts_(t, " x "); put_i64(t, s->fb_h);
    puts_(t, ", background "); put_i64(t, s->background[0]);
    put(t, " ", 1); put_i64(t, s->background[1]);
    put(t, " ", 1); put_i64(t, s->background[2]);
    puts_(t, "\nviewport     "); put_i64(t, s->vp_w); puts_(t, " x "); put_i64(t, s->vp_h);
    puts_(t, " at (x_ul, y_ul) = ("); put_i64(t, s->vp_x); puts_(t, ", ");
    put_i64(t, s->vp_y); puts_(t, ")\ncamera       "); puts_(t, camera_name(s));
    if (s->from_obj) {
        puts_(t, "\nobj placed   translate "); put_short(t, s->obj_translate.x);
        put(t, " ", 1); put_short(t, s->obj_translate.y);
        put(t, " ", 1); put_short(t, s->obj_translate.z);
    }
    put(t, "\n", 1);
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        const pt_model_plan *mp = &p->models[k];

        puts_(t, "model        "); puts_(t, m->name);
        puts_(t, ": "); put_u64(t, m->nv); puts_(t, " vertices (");
        put_u64(t, mp->nused); puts_(t, " used), "); put_u64(t, m->nseg);
        puts_(t, " segments, translate "); put_short(t, m->translate.x);
        put(t, " ", 1); put_short(t, m->translate.y);
        put(t, " ", 1); put_short(t, m->translate.z);
        puts_(t, ", color "); put_i64(t, m->color[0]);
        put(t, " ", 1); put_i64(t, m->color[1]);
        put(t, " ", 1); put_i64(t, m->color[2]);
        if (!mp->selected) puts_(t, ", not traced (--model)");
        put(t, "\n", 1);
        for (st = 0; st < PT_NSTAGES; st++) {
            if (mp->why[st] == PT_WHY_TRACED) continue;
            puts_(t, "  left out   "); puts_(t, pt_stage_infos[st].name);
            puts_(t, ": "); puts_(t, mp->why_text[st]); put(t, "\n", 1);
        }
    }
    put(t, "\n", 1);
}

static void on_header(void *ud, const pt_scene *s, const pt_plan *p)
{
    pt_trace *t = ud;

    if (t->fmt == PT_FORMAT_JSONL) header_json(t, s, p);
    else if (t->fmt == PT_FORMAT_TEXT) header_text(t, s, p);
    else puts_(t, "model,v,stage,x,y,z,inside,behind,i,warning\n");
}

/* ===== vertex records ===== */

static void on_vertex_begin(void *ud, const pt_model *m, uint64_t v)
{
    pt_trace *t = ud;
    t->model = m;
    t->v = v;
}

/* Names of a stage's coordinates in the text format. */
static const char *const coord_names[PT_NSTAGES][3] = {
    {"x_m  = ", "y_m  = ", "z_m  = "}, {"x_c  = ", "y_c  = ", "z_c  = "},
    {"x_ip = ", "y_ip = ", "z_ip = "}, {"x_pp = ", "y_pp = ", ""},
    {"x_vp = ", "y_vp = ", ""},        {"x_fb = ", "y_fb = ", ""},
    {"idx  = ", "", ""},
};

static int has_z(pt_stage st) { return st <= PT_STAGE_IMAGE; }
static int is_real(pt_stage st) { return st <= PT_STAGE_PIXEL; }

/* Text: "  ! cancellation (9 digits lost)". */
static void put_warnings_text(pt_trace *t, const pt_vrec *r)
{
    int k;

    puts_(t, "  !");
    for (k = 0; k < PT_NWARN; k++) {
        if (!(r->warn & (1u << k))) continue;
        put(t, " ", 1);
        puts_(t, pt_warn_names[k]);
        if ((1u << k) & (PT_WARN_CANCEL | PT_WARN_ILLCOND)) {
            puts_(t, " ("); put_i64(t, r->digits_lost); puts_(t, " digits lost)");
        }
    }
}

/* JSON: ,"warning":["cancellation"],"digits_lost":9 */
static void put_warnings_json(pt_trace *t, const pt_vrec *r)
{
    int k, first = 1;

    puts_(t, ",\"warning\":[");
    for (k = 0; k < PT_NWARN; k++) {
        if (!(r->warn & (1u << k))) continue;
        if (!first) put(t, ",", 1);
        first = 0;
        put(t, "\"", 1); puts_(t, pt_warn_names[k]); put(t, "\"", 1);
    }
    put(t, "]", 1);
    if (r->warn & (PT_WARN_CANCEL | PT_WARN_ILLCOND)) {
        puts_(t, ",\"digits_lost\":"); put_i64(t, r->digits_lost);
    }
}

static void vertex_text(pt_trace *t, const pt_vrec *r)
{
    const char *const *cn = coord_names[r->stage];
    char b[16];

    put_who(t, t->model->name, "v", t->v);
    snprintf(b, sizeof b, "%-13s", pt_stage_infos[r->stage].name);
    put(t, b, 13);
    if (r->stage == PT_STAGE_INDEX) {
        puts_(t, cn[0]);
        if (r->flags & PT_REC_NULL) put_col(t, "none", 4, 12);
        else put_int_col(t, r->i);
    } else if (is_real(r->stage)) {
        puts_(t, cn[0]); put_fixed_col(t, r->x, t->precision);
        puts_(t, "  "); puts_(t, cn[1]); put_fixed_col(t, r->y, t->precision);
        if (has_z(r->stage)) {
            puts_(t, "  "); puts_(t, cn[2]); put_fixed_col(t, r->z, t->precision);
        }
    } else if (r->flags & PT_REC_NULL) {
        puts_(t, cn[0]); put_col(t, "none", 4, 12);
        puts_(t, "  "); puts_(t, cn[1]); put_col(t, "none", 4, 12);
    } else {
        puts_(t, cn[0]); put_int_col(t, r->ix);
        puts_(t, "  "); puts_(t, cn[1]); put_int_col(t, r->iy);
    }
    if (r->flags & PT_REC_BEHIND) puts_(t, "  behind the camera");
    if (r->stage == PT_STAGE_VIEWPORT)
        puts_(t, r->flags & PT_REC_INSIDE ? "  inside" : "  outside");
    if (r->warn) put_warnings_text(t, r);
    put(t, "\n", 1);
}

static void vertex_json(pt_trace *t, const pt_vrec *r)
{
    puts_(t, "{\"type\":\"vertex\",\"model\":"); put_json_str(t, t->model->name);
    puts_(t, ",\"v\":"); put_u64(t, t->v);
    puts_(t, ",\"stage\":\""); puts_(t, pt_stage_infos[r->stage].name); put(t, "\"", 1);
    if (r->stage == PT_STAGE_INDEX) {
        puts_(t, ",\"i\":");
        if (r->flags & PT_REC_NULL) puts_(t, "null"); else put_i64(t, r->i);
    } else if (is_real(r->stage)) {
        puts_(t, ",\"x\":"); put_json_num(t, r->x);
        puts_(t, ",\"y\":"); put_json_num(t, r->y);
        if (has_z(r->stage)) { puts_(t, ",\"z\":"); put_json_num(t, r->z); }
    } else if (r->flags & PT_REC_NULL) {
        puts_(t, ",\"x\":null,\"y\":null");
    } else {
        puts_(t, ",\"x\":"); put_i64(t, r->ix);
        puts_(t, ",\"y\":"); put_i64(t, r->iy);
    }
    if (r->stage == PT_STAGE_IMAGE && (r->flags & PT_REC_BEHIND))
        puts_(t, ",\"behind\":true");
    if (r->stage == PT_STAGE_VIEWPORT)
        puts_(t, r->flags & PT_REC_INSIDE ? ",\"inside\":true" : ",\"inside\":false");
    if (r->warn) put_warnings_json(t, r);
    puts_(t, "}\n");
}

/* CSV: model,v,stage,x,y,z,inside,behind,i,warning; empty where a field does not
** apply; warning names joined by '|'. */
static void vertex_csv(pt_trace *t, const pt_vrec *r)
{
    puts_(t, t->model->name); put(t, ",", 1); put_u64(t, t->v); put(t, ",", 1);
    puts_(t, pt_stage_infos[r->stage].name); put(t, ",", 1);
    if (is_real(r->stage)) {
        put_short(t, r->x); put(t, ",", 1); put_short(t, r->y); put(t, ",", 1);
        if (has_z(r->stage)) put_short(t, r->z);
    } else if (r->stage != PT_STAGE_INDEX && !(r->flags & PT_REC_NULL)) {
        put_i64(t, r->ix); put(t, ",", 1); put_i64(t, r->iy); put(t, ",", 1);
    } else {
        put(t, ",,", 2);
    }
    put(t, ",", 1);
    if (r->stage == PT_STAGE_VIEWPORT) puts_(t, r->flags & PT_REC_INSIDE ? "1" : "0");
    put(t, ",", 1);
    if (r->stage == PT_STAGE_IMAGE) puts_(t, r->flags & PT_REC_BEHIND ? "1" : "0");
    put(t, ",", 1);
    if (r->stage == PT_STAGE_INDEX && !(r->flags & PT_REC_NULL)) put_i64(t, r->i);
    put(t, ",", 1);
    {
        int k, first = 1;
        for (k = 0; k < PT_NWARN; k++) {
            if (!(r->warn & (1u << k))) continue;
            if (!first) put(t, "|", 1);
            first = 0;
            puts_(t, pt_warn_names[k]);
        }
    }
    put(t, "\n", 1);
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    pt_trace *t = ud;

    if (t->fmt == PT_FORMAT_JSONL) vertex_json(t, r);
    else if (t->fmt == PT_FORMAT_TEXT) vertex_text(t, r);
    else vertex_csv(t, r);
}

/* ===== raster records ===== */

static void on_pixel(void *ud, const pt_model *m, uint64_t seg,
                     int64_t x_fb, int64_t y_fb, int64_t idx)
{
    pt_trace *t = ud;

    if (t->fmt == PT_FORMAT_JSONL) {
        puts_(t, "{\"type\":\"pixel\",\"model\":"); put_json_str(t, m->name);
        puts_(t, ",\"segment\":"); put_u64(t, seg);
        puts_(t, ",\"x\":"); put_i64(t, x_fb);
        puts_(t, ",\"y\":"); put_i64(t, y_fb);
        puts_(t, ",\"i\":"); put_i64(t, idx);
        puts_(t, "}\n");
    } else if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, "s", seg);
        puts_(t, "pixel        x_fb = "); put_int_col(t, x_fb);
        puts_(t, "  y_fb = "); put_int_col(t, y_fb);
        puts_(t, "  idx = "); put_i64(t, idx);
        put(t, "\n", 1);
    }
}

static void put_pair_json(pt_trace *t, pt_pix p)
{
    put(t, "[", 1); put_i64(t, p.x); put(t, ",", 1); put_i64(t, p.y); put(t, "]", 1);
}

static void put_pair_text(pt_trace *t, pt_pix p)
{
    put(t, "(", 1); put_i64(t, p.x); puts_(t, ", "); put_i64(t, p.y); put(t, ")", 1);
}

static void on_clip(void *ud, const pt_model *m, uint64_t seg, uint64_t count,
                    pt_pix first, pt_pix last)
{
    pt_trace *t = ud;

    if (t->fmt == PT_FORMAT_JSONL) {
        puts_(t, "{\"type\":\"clip\",\"model\":"); put_json_str(t, m->name);
        puts_(t, ",\"segment\":"); put_u64(t, seg);
        puts_(t, ",\"count\":"); put_u64(t, count);
        puts_(t, ",\"first\":"); put_pair_json(t, first);
        puts_(t, ",\"last\":"); put_pair_json(t, last);
        puts_(t, "}\n");
    } else if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, "s", seg);
        puts_(t, "clipped      "); put_u64(t, count);
        puts_(t, count == 1 ? " step at (x_vp, y_vp) = " : " steps, (x_vp, y_vp) from ");
        put_pair_text(t, first);
        if (count > 1) { puts_(t, " to "); put_pair_text(t, last); }
        put(t, "\n", 1);
    }
}

static void on_skip(void *ud, const pt_model *m, uint64_t seg, uint64_t v,
                    const char *why)
{
    pt_trace *t = ud;

    if (t->fmt == PT_FORMAT_JSONL) {
        puts_(t, "{\"type\":\"skip\",\"model\":"); put_json_str(t, m->name);
        puts_(t, ",\"segment\":"); put_u64(t, seg);
        puts_(t, ",\"v\":"); put_u64(t, v);
        puts_(t, ",\"why\":"); put_json_str(t, why); puts_(t, "}\n");
    } else if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, "s", seg);
        puts_(t, "skipped      v"); put_u64(t, v); puts_(t, ": ");
        puts_(t, why); put(t, "\n", 1);
    }
}

/* ===== summary ===== */

static void on_summary(void *ud, const pt_summary *sum)
{
    pt_trace *t = ud;
    static const char *const names[] = {
        "models", "vertices", "vertices_unused", "vertices_traced", "segments",
        "segments_degenerate", "segments_skipped", "pixels", "clipped",
        "clip_runs", "behind",
    };
    const uint64_t vals[] = {
        sum->models, sum->vertices, sum->vertices_unused, sum->vertices_traced,
        sum->segments, sum->segments_degenerate, sum->segments_skipped,
        sum->pixels, sum->clipped, sum->clip_runs, sum->behind,
    };
    size_t k;

    if (t->fmt == PT_FORMAT_CSV) return;
    if (t->fmt == PT_FORMAT_JSONL) {
        puts_(t, "{\"type\":\"summary\"");
        for (k = 0; k < sizeof vals / sizeof vals[0]; k++) {
            puts_(t, ",\""); puts_(t, names[k]); puts_(t, "\":"); put_u64(t, vals[k]);
        }
        puts_(t, ",\"warnings\":{");
        for (k = 0; k < PT_NWARN; k++) {
            if (k) put(t, ",", 1);
            put(t, "\"", 1); puts_(t, pt_warn_names[k]); puts_(t, "\":");
            put_u64(t, sum->warnings[k]);
        }
        puts_(t, sum->rasterized ? "},\"rasterized\":true}\n" : "},\"rasterized\":false}\n");
        return;
    }
    puts_(t, "\nsummary");
    for (k = 0; k < sizeof vals / sizeof vals[0]; k++) {
        puts_(t, k % 4 == 0 ? "\n  " : "  ");
        puts_(t, names[k]); put(t, " ", 1); put_u64(t, vals[k]);
    }
    puts_(t, "\n  warnings");
    for (k = 0; k < PT_NWARN; k++) {
        put(t, " ", 1); puts_(t, pt_warn_names[k]); put(t, " ", 1);
        put_u64(t, sum->warnings[k]);
    }
    puts_(t, sum->rasterized ? "\n  rasterized yes\n" : "\n  rasterized no (--vertex without --image)\n");
}

/* ===== public ===== */

void pt_trace_init(pt_trace *t, FILE *f, pt_format fmt, int precision)
{
    t->f = f;
    t->fmt = fmt;
    t->precision = precision;
    t->model = NULL;
    t->v = 0;
    t->failed = 0;
    t->len = 0;
}

void pt_trace_listener(pt_trace *t, pt_listener *l)
{
    l->header = on_header;
    l->vertex_begin = on_vertex_begin;
    l->sink.vertex = on_vertex;
    l->sink.ud = t;
    l->pixel = on_pixel;
    l->clip = on_clip;
    l->skip = on_skip;
    l->summary = on_summary;
    l->ud = t;
}

int pt_trace_finish(pt_trace *t)
{
    flush(t);
    if (fflush(t->f) != 0) t->failed = 1;
    return t->failed ? -1 : 0;
}
