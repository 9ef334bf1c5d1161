/*
** src/io/trace.c -- write the trace: JSON Lines, aligned text, or CSV
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>
#include "io/sbuf.h"
#include "io/trace.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"

/* ===== the output block ===== */

/* A write failed: keep the first reason (errno) for the message. */
static void write_failed(pt_trace *t)
{
    if (!t->failed) t->failed = errno ? errno : EIO;
}

static void flush(pt_trace *t)
{
    if (t->out) {                           /* it takes the block (tlanes.c) */
        t->out(t->out_ud, t);
        return;
    }
    if (t->len && fwrite(t->buf, 1, t->len, t->f) != t->len) write_failed(t);
    t->len = 0;
}

static void put(pt_trace *t, const char *s, size_t n)
{
    if (t->len + n > PT_TRACE_BLOCK) {
        flush(t);
        for (; n > PT_TRACE_BLOCK; s += PT_TRACE_BLOCK, n -= PT_TRACE_BLOCK) {
            memcpy(t->buf, s, PT_TRACE_BLOCK);  /* longer than a block: */
            t->len = PT_TRACE_BLOCK;            /*   a block at a time */
            flush(t);
        }
    }
    if (n <= 8) {                           /* most pieces: a comma, a key, a digit */
        char *o = t->buf + t->len;
        size_t k;
        for (k = 0; k < n; k++) o[k] = s[k];
    } else {
        memcpy(t->buf + t->len, s, n);
    }
    t->len += n;
}

static void puts_(pt_trace *t, const char *s) { put(t, s, strlen(s)); }

static char *room(pt_trace *t, size_t n);

/* Integers by hand (pt_fmt_u64): snprintf costs more than the rest of a
** pixel record. */
static void put_u64(pt_trace *t, uint64_t x)
{
    char *o = room(t, 20);
    t->len += pt_fmt_u64(o, x);
}

/* hi * 2^64 + lo in decimal: long division by 10 on 32-bit limbs. */
static void put_u128(pt_trace *t, uint64_t hi, uint64_t lo)
{
    uint32_t limb[4] = {(uint32_t)(hi >> 32), (uint32_t)hi, (uint32_t)(lo >> 32), (uint32_t)lo};
    char b[40], *o = b + sizeof b;
    int k, nonzero;

    if (hi == 0) { put_u64(t, lo); return; }
    do {
        uint64_t rem = 0;
        nonzero = 0;
        for (k = 0; k < 4; k++) {           /* limb[] /= 10, most significant first */
            uint64_t cur = (rem << 32) | limb[k];
            limb[k] = (uint32_t)(cur / 10);
            rem = cur % 10;
            nonzero |= limb[k] != 0;
        }
        *--o = (char)('0' + rem);
    } while (nonzero);
    put(t, o, (size_t)(b + sizeof b - o));
}

static void put_i64(pt_trace *t, int64_t x)
{
    if (x < 0) { put(t, "-", 1); put_u64(t, 0u - (uint64_t)x); }
    else put_u64(t, (uint64_t)x);
}

/* x as pt_fmt_shortest() spells it, at o (PT_NUMLEN bytes); returns the end.
** A trace spells the same doubles again and again (a model's z in each of
** its vertices, the camera's x and y where the translation's are 0, the
** image plane's z), so the spellings of recent ones are kept in t->nums,
** one slot for each hash of the bits; a slot holds the spelling of the
** bits it holds (pt_trace_init() fills each with +0's), so a hit is always
** right.  The copy is of a fixed PT_SHORTLEN bytes, no library call.  A hit
** (most of them) is inlined where a record is written; a miss spells x into
** slot e by the call below. */
static char *short_miss(struct pt_trace_num *e, char *o, double x, uint64_t bits)
{
    e->bits = bits;
    e->len = (unsigned char)pt_fmt_shortest(o, x);
    memcpy(e->s, o, PT_SHORTLEN);
    return o + e->len;
}

/* The slot of a double's bits: the top PT_TRACE_NUMBITS bits of their
** product with 2^64 / golden ratio (Knuth's multiplicative hash). */
static inline struct pt_trace_num *num_slot(pt_trace *t, uint64_t bits)
{
    return &t->nums[(bits * UINT64_C(0x9e3779b97f4a7c15)) >> (64 - PT_TRACE_NUMBITS)];
}

static inline char *short_at(pt_trace *t, char *o, double x)
{
    struct pt_trace_num *e;
    uint64_t bits;

    memcpy(&bits, &x, sizeof bits);
    e = num_slot(t, bits);
    if (e->bits != bits) return short_miss(e, o, x, bits);
    memcpy(o, e->s, PT_SHORTLEN);
    return o + e->len;
}

/* A double in JSON: shortest round-trip, non-finite as a string, negative
** zero as -0.0 (JSON readers take "-0" for the integer 0 and lose the sign).
** The slots are looked at first: in a JSON Lines trace only this function
** fills them (short_at() is CSV's), and only with finite doubles other than
** -0, so a hit needs no more tests. */
static inline char *json_num_at(pt_trace *t, char *o, double x)   /* PT_NUMLEN + 2 bytes */
{
    struct pt_trace_num *e;
    uint64_t bits;

    memcpy(&bits, &x, sizeof bits);
    e = num_slot(t, bits);
    if (e->bits == bits) {
        memcpy(o, e->s, PT_SHORTLEN);
        return o + e->len;
    }
    if ((bits >> 52 & 0x7ff) != 0x7ff && bits != UINT64_C(1) << 63)   /* finite, not -0 */
        return short_miss(e, o, x, bits);
    if (x == 0) { memcpy(o, "-0.0", 4); return o + 4; }
    *o++ = '"';
    o += pt_fmt_shortest(o, x);
    *o++ = '"';
    return o;
}

static void put_json_num(pt_trace *t, double x)
{
    t->len = (size_t)(json_num_at(t, room(t, PT_NUMLEN + 2), x) - t->buf);
}

static void put_short(pt_trace *t, double x)
{
    char *o = room(t, PT_NUMLEN);
    t->len += pt_fmt_shortest(o, x);
}

/* A string's characters as JSON writes them inside quotes: " and \ after a
** backslash, control characters as \u00XX, a byte that is no UTF-8 as
** \ufffd.  The text header writes the scene path so too: one line, nothing
** for a terminal to act on, and tread_text.c reads it back. */
static void put_json_chars(pt_trace *t, const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    int n;

    while (*p) {
        unsigned char c = *p;
        if (c == '"' || c == '\\') { char e[2] = {'\\', (char)c}; put(t, e, 2); p++; }
        else if (c < 0x20) { char e[8]; put(t, e, (size_t)snprintf(e, sizeof e, "\\u%04x", c)); p++; }
        else if ((n = pt_sbuf_utf8_len(p)) == 0) { puts_(t, "\\ufffd"); p++; }  /* a path's bad byte */
        else { put(t, (const char *)p, (size_t)n); p += n; }
    }
}

/* A string in JSON quotes, escaping what JSON requires. */
static void put_json_str(pt_trace *t, const char *s)
{
    put(t, "\"", 1);
    put_json_chars(t, s);
    put(t, "\"", 1);
}

/* Text: a fixed-width right-aligned column. */
static void put_col(pt_trace *t, const char *s, size_t n, size_t width)
{
    static const char spaces[] = "                                ";
    if (n < width) put(t, spaces, width - n < 32 ? width - n : 32);
    put(t, s, n);
}

/* The most a vertex record writes after the model's name (and before
** --explain's text): v or a segment (20 bytes), the stage's name and keys,
** five numbers of PT_NUMLEN + 2, integers, the plane and warning names
** (pt_trace_init() checks that each list fits in 160 bytes), punctuation. */
#define PT_ROW_REST (5 * (PT_NUMLEN + 2) + 8 * 24 + 2 * 160 + 256)

/* Room for n bytes (at most a block; a vertex record asks for PT_ROW_REST,
** a run of pixel records for PT_RASTER_RUN of theirs) at the end of the
** block, for the writers below that write there by pointer and then move
** t->len past what they wrote: one check for a whole record, or a whole
** run, instead of one per piece. */
static char *room(pt_trace *t, size_t n)
{
    assert(n <= PT_TRACE_BLOCK);
    if (t->len + n > PT_TRACE_BLOCK) flush(t);
    return t->buf + t->len;
}

/* Text: x as "%12.*f" (pt_fmt_fixed: "%.*e" from 1e15 on), right-aligned.
** The number goes over in one fixed-size copy of all of b, the bytes past
** its end included: they land in room that the next piece overwrites. */
static void put_fixed_col(pt_trace *t, double x, int prec)
{
    char b[PT_NUMLEN], *o = room(t, PT_NUMLEN + 12);
    size_t n = pt_fmt_fixed(b, x, prec), pad = n < 12 ? 12 - n : 0;

    memcpy(o, "            ", 12);
    memcpy(o + pad, b, PT_NUMLEN);
    t->len += pad + n;
}

/* u's digits at o (20 bytes); below 10^8 (the pixels, the indexes) from the
** trace's digit table, else by pt_fmt_u64(). */
static char *digits_at(const pt_trace *t, char *o, uint64_t u)
{
    if (u < 100000000) return o + pt_fmt_u32_tab(&t->digits, o, (uint32_t)u);
    return o + pt_fmt_u64(o, u);
}

/* "%*" PRId64 at o (at most 20 bytes plus padding); returns the end.  Digits
** by hand (snprintf costs more than the rest of a record). */
static char *int_at(const pt_trace *t, char *o, int64_t x, size_t width)
{
    uint64_t u = x < 0 ? 0u - (uint64_t)x : (uint64_t)x;

    if (width) {
        size_t n = pt_fmt_ulen(u) + (x < 0);
        for (; width > n; width--) *o++ = ' ';
    }
    if (x < 0) *o++ = '-';
    return digits_at(t, o, u);
}

static char *u64_at(const pt_trace *t, char *o, uint64_t x)   /* x's digits at o */
{
    return digits_at(t, o, x);
}

static char *str_at(char *o, const char *s)         /* s at o; returns the end */
{
    size_t n = strlen(s);
    memcpy(o, s, n);
    return o + n;
}

static void put_int_col(pt_trace *t, int64_t x)
{
    t->len = (size_t)(int_at(t, room(t, 32), x, 12) - t->buf);
}

/* Text: "name v12", padded so that the stage names line up: to 14 columns, or
** by one space when longer. */
static void put_who(pt_trace *t, const char *name, char kind, uint64_t n)
{
    size_t nlen = strlen(name), len = nlen + 2 + pt_fmt_ulen(n);
    size_t pad = len < 14 ? 14 - len : 1;
    char *o;

    put(t, name, nlen);
    o = room(t, 40);                                /* 2 + 20 + 13 bytes */
    o[0] = ' ';
    o[1] = kind;
    o += 2 + pt_fmt_u64(o + 2, n);
    memcpy(o, "             ", 13);                 /* pad <= 13 of them */
    t->len = (size_t)(o + pad - t->buf);
}

/* Text: a stage name left-aligned in 13 columns ("%-13s", cut to 13). */
static void put_stage_col(pt_trace *t, const char *name)
{
    size_t n = strlen(name);
    char *o = room(t, 13);

    if (n > 13) n = 13;
    memcpy(o, name, n);
    memset(o + n, ' ', 13 - n);
    t->len += 13;
}

/* ===== header ===== */

static const char *camera_name(const pt_scene *s)
{
    return s->matrix ? "lookat" : s->perspective ? "perspective" : "orthographic";
}

static void put_vec3_json(pt_trace *t, pt_vec3 v)
{
    put(t, "[", 1); put_json_num(t, v.x); put(t, ",", 1); put_json_num(t, v.y);
    put(t, ",", 1); put_json_num(t, v.z); put(t, "]", 1);
}

static void put_vec3_text(pt_trace *t, pt_vec3 v)
{
    put(t, "(", 1); put_short(t, v.x); puts_(t, ", "); put_short(t, v.y);
    puts_(t, ", "); put_short(t, v.z); put(t, ")", 1);
}

/* A matrix as four rows: JSON [[m00,m01,m02,m03],...], text "[m00 m01 m02
** m03] [m10 ...] ...". */
static void put_mat(pt_trace *t, const pt_mat4 *m, int json)
{
    const char *sep = json ? "," : " ";
    int i, j;

    if (json) put(t, "[", 1);
    for (i = 0; i < 4; i++) {
        if (i) put(t, sep, 1);
        put(t, "[", 1);
        for (j = 0; j < 4; j++) {
            if (j) put(t, sep, 1);
            if (json) put_json_num(t, m->m[i][j]);
            else put_short(t, m->m[i][j]);
        }
        put(t, "]", 1);
    }
    if (json) put(t, "]", 1);
}

/* Three small integers (a colour) separated by sep. */
static void put_rgb(pt_trace *t, const unsigned char c[3], const char *sep)
{
    put_i64(t, c[0]); puts_(t, sep); put_i64(t, c[1]); puts_(t, sep); put_i64(t, c[2]);
}

/* A point as the text header writes it: "x y z". */
static void put_xyz_text(pt_trace *t, pt_vec3 v)
{
    put_short(t, v.x); put(t, " ", 1); put_short(t, v.y); put(t, " ", 1); put_short(t, v.z);
}

/* The matrix camera's parameters and matrices, JSON (json 1) or text lines
** (json 0): the same values in the same order, each after its label. */
static void camera_put(pt_trace *t, const pt_scene *s, const pt_plan *p, int json)
{
    static const char *const vec_label[2][3] = {
        {" eye ", " direction ", " up "},
        {",\"lookat\":{\"eye\":", ",\"direction\":", ",\"up\":"}};
    static const char *const num_label[2][4] = {
        {"\nprojection   perspective fov ", " aspect ", " near ", " far "},
        {"},\"projection\":{\"fov\":", ",\"aspect\":", ",\"near\":", ",\"far\":"}};
    static const char *const mat_label[2][2] = {
        {"\nview         ", "\nprojection   "},
        {"},\"view\":", ",\"projection_matrix\":"}};
    const pt_vec3 vec[3] = {s->eye, s->dir, s->up};
    const double num[4] = {s->fov, s->aspect, s->znear, s->zfar};
    const pt_mat4 *mat[2] = {&p->view, &p->proj};
    void (*put_vec)(pt_trace *, pt_vec3) = json ? put_vec3_json : put_vec3_text;
    void (*put_num)(pt_trace *, double) = json ? put_json_num : put_short;
    int k;

    for (k = 0; k < 3; k++) { puts_(t, vec_label[json][k]); put_vec(t, vec[k]); }
    if (json) {
        puts_(t, ",\"up_perpendicular\":"); puts_(t, p->up_skewed ? "false" : "true");
        puts_(t, ",\"up_adjusted\":"); puts_(t, p->up_adjusted ? "true" : "false");
    } else if (p->up_adjusted) {
        puts_(t, "\n  warning    up is not perpendicular to direction: re-derived"
                 " (--raw-lookat keeps it)");
    } else if (p->up_skewed) {
        puts_(t, "\n  warning    up is not perpendicular to direction: kept as given"
                 " (--raw-lookat), so View is not orthonormal");
    }
    for (k = 0; k < 4; k++) { puts_(t, num_label[json][k]); put_num(t, num[k]); }
    for (k = 0; k < 2; k++) { puts_(t, mat_label[json][k]); put_mat(t, mat[k], json); }
}

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
    puts_(t, "},\"background\":["); put_rgb(t, s->background, ",");
    puts_(t, "],\"viewport\":{\"x\":"); put_i64(t, s->vp_x);
    puts_(t, ",\"y\":"); put_i64(t, s->vp_y);
    puts_(t, ",\"w\":"); put_i64(t, s->vp_w);
    puts_(t, ",\"h\":"); put_i64(t, s->vp_h);
    puts_(t, "},\"camera\":\""); puts_(t, camera_name(s)); put(t, "\"", 1);
    if (s->matrix) camera_put(t, s, p, 1);
    if (s->from_obj) { puts_(t, ",\"obj_translate\":"); put_vec3_json(t, s->obj_translate); }
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
        puts_(t, ",\"translate\":"); put_vec3_json(t, m->translate);
        puts_(t, ",\"color\":["); put_rgb(t, m->color, ",");
        puts_(t, "],\"traced\":");
        puts_(t, mp->selected ? "true" : "false");
        if (s->matrix) { puts_(t, ",\"world\":"); put_mat(t, &mp->world, 1); }
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

static void header_text(pt_trace *t, const pt_scene *s, const pt_plan *p)
{
    size_t k;
    int st, i;

    puts_(t, "# pipetrace trace, format version 1\nscene        ");
    put_json_chars(t, s->path);
    puts_(t, "\nframebuffer  "); put_i64(t, s->fb_w); puts_(t, " x "); put_i64(t, s->fb_h);
    puts_(t, ", background "); put_rgb(t, s->background, " ");
    puts_(t, "\nviewport     "); put_i64(t, s->vp_w); puts_(t, " x "); put_i64(t, s->vp_h);
    puts_(t, " at (x_ul, y_ul) = ("); put_i64(t, s->vp_x); puts_(t, ", ");
    put_i64(t, s->vp_y); puts_(t, ")\ncamera       "); puts_(t, camera_name(s));
    if (s->matrix) camera_put(t, s, p, 0);
    if (s->from_obj) { puts_(t, "\nobj placed   translate "); put_xyz_text(t, s->obj_translate); }
    if (t->student && *t->student) {        /* a student build: which stage files */
        puts_(t, "\nstudent      "); puts_(t, t->student);
    }
    put(t, "\n", 1);
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        const pt_model_plan *mp = &p->models[k];

        puts_(t, "model        "); puts_(t, m->name);
        puts_(t, ": "); put_u64(t, m->nv); puts_(t, " vertices (");
        put_u64(t, mp->nused); puts_(t, " used), "); put_u64(t, m->nseg);
        puts_(t, " segments, translate "); put_xyz_text(t, m->translate);
        puts_(t, ", color "); put_rgb(t, m->color, " ");
        if (!mp->selected) puts_(t, ", not traced (--model)");
        put(t, "\n", 1);
        if (s->matrix) {
            puts_(t, "  world      "); put_mat(t, &mp->world, 0); put(t, "\n", 1);
        }
        for (i = 0; i < p->norder; i++) {
            st = p->order[i];
            if (mp->why[st] == PT_WHY_TRACED) continue;
            puts_(t, "  left out   "); puts_(t, pt_stage_infos[st].name);
            puts_(t, ": "); puts_(t, mp->why_text[st]); put(t, "\n", 1);
        }
    }
    put(t, "\n", 1);
}

/* The CSV header rows; see vertex_csv(). */
static const char csv_classic[] =
    "model,v,stage,x,y,z,inside,behind,i,warning,digits_lost\n";
static const char csv_matrix[] =
    "model,v,stage,x,y,z,w,code,planes,inside,i,segment,t,warning,digits_lost\n";

static void on_header(void *ud, const pt_scene *s, const pt_plan *p)
{
    pt_trace *t = ud;

    t->scene = s;
    t->plan = p;
    if (t->fmt == PT_FORMAT_JSONL) header_json(t, s, p);
    else if (t->fmt == PT_FORMAT_TEXT) header_text(t, s, p);
    else {
        if (t->student && *t->student) {    /* a student build: which stage files */
            puts_(t, "# student "); puts_(t, t->student); put(t, "\n", 1);
        }
        puts_(t, s->matrix ? csv_matrix : csv_classic);
    }
}

/* ===== vertex records ===== */

static void on_clipvertex_begin(void *ud, const pt_model *m, uint64_t seg,
                               uint64_t from, uint64_t to, double tc, pt_vec4 q)
{
    pt_trace *t = ud;

    t->model = m;
    t->clipv = 1;
    t->seg = seg;
    t->from = from;
    t->to = to;
    t->t_clip = tc;
    t->q_clip = q;
    t->journey_made = 0;
}

static void on_vertex_begin(void *ud, const pt_model *m, uint64_t v)
{
    pt_trace *t = ud;

    t->clipv = 0;
    t->model = m;
    t->v = v;
    t->journey_made = 0;
}

/* --explain: the point's journey, which comes before its records. */
static void on_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    pt_trace *t = ud;

    (void)m; (void)v;
    t->journey = *j;
    t->journey_made = 1;
}

/* "x_pp = ": the name of value k of stage st (stages/pt_stage.h), padded to
** four characters so that the columns line up. */
static void put_lhs(pt_trace *t, pt_stage st, int k)
{
    const char *name = pt_stage_infos[st].coord[k];
    size_t n = strlen(name);

    put(t, name, n);
    for (; n < 4; n++) put(t, " ", 1);
    put(t, " = ", 3);
}

/* --explain: r's formula with this vertex's numbers, from the journey pt_run()
** handed over before the records, so a stage left out still feeds the next
** one its real value.  Text: an indented line; JSON: an "explain" field. */
static void put_explain(pt_trace *t, const pt_vrec *r)
{
    char b[PT_EXPLAINLEN];
    size_t n;

    if (!t->journey_made) return;
    n = pt_explain_stage(b, sizeof b, &t->journey, r->stage, "; ");
    if (n >= sizeof b) n = sizeof b - 1;
    if (t->fmt == PT_FORMAT_JSONL) { puts_(t, ",\"explain\":"); put_json_str(t, b); return; }
    put_col(t, "", 0, 14);
    put(t, b, n);
    put(t, "\n", 1);
}

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

/* Text: the rest of "(0b000101: outside near left)", or ": inside ...)". */
static void put_planes_text(pt_trace *t, unsigned code)
{
    int k;

    if (!code) { puts_(t, ": inside the view volume)"); return; }
    puts_(t, ": outside");
    for (k = 0; k < PT_CVV_NPLANES; k++)
        if (code & (1u << k)) { put(t, " ", 1); puts_(t, pt_cvv_names[k]); }
    put(t, ")", 1);
}

static void vertex_text(pt_trace *t, const pt_vrec *r)
{

    if (t->clipv) put_who(t, t->model->name, 's', t->seg);
    else put_who(t, t->model->name, 'v', t->v);
    put_stage_col(t, pt_stage_infos[r->stage].name);
    if (r->stage == PT_STAGE_CVV) {             /* "code = 61 = 0b111101" */
        char bits[PT_CVV_NPLANES + 1];
        int k;
        for (k = 0; k < PT_CVV_NPLANES; k++)
            bits[k] = r->code & (1u << (PT_CVV_NPLANES - 1 - k)) ? '1' : '0';
        bits[PT_CVV_NPLANES] = '\0';
        put_lhs(t, r->stage, 0); put_i64(t, r->code); puts_(t, "  (0b"); puts_(t, bits);
        put_planes_text(t, r->code);
    } else if (r->stage == PT_STAGE_INDEX) {
        put_lhs(t, r->stage, 0);
        if (r->flags & PT_REC_NULL) put_col(t, "none", 4, 12);
        else put_int_col(t, r->i);
    } else if (pt_stage_infos[r->stage].nreal) {
        const double v[4] = {r->x, r->y, r->z, r->w};
        int k;
        for (k = 0; k < pt_stage_infos[r->stage].nreal; k++) {
            if (k) puts_(t, "  ");
            put_lhs(t, r->stage, k); put_fixed_col(t, v[k], t->precision);
        }
    } else {                                /* viewport, framebuffer: null per value */
        put_lhs(t, r->stage, 0);
        if (pt_rec_has(r, 0)) put_int_col(t, r->ix); else put_col(t, "none", 4, 12);
        puts_(t, "  "); put_lhs(t, r->stage, 1);
        if (pt_rec_has(r, 1)) put_int_col(t, r->iy); else put_col(t, "none", 4, 12);
    }
    if (r->flags & PT_REC_BEHIND) puts_(t, "  behind the camera");
    if (r->stage == PT_STAGE_VIEWPORT)
        puts_(t, r->flags & PT_REC_INSIDE ? "  inside" : "  outside");
    if (t->clipv && r->stage == PT_STAGE_NDC) {
        puts_(t, "  (clipped v"); put_u64(t, t->from); puts_(t, "-v"); put_u64(t, t->to);
        puts_(t, " at t = "); put_short(t, t->t_clip); put(t, ")", 1);
    }
    if (r->warn) put_warnings_text(t, r);
    put(t, "\n", 1);
    if (t->explain) put_explain(t, r);
}

/* Piece k of stage st at o; returns the end.  One copy of the whole slot,
** 32 bytes with its length byte (two 16-byte moves, where s alone would be
** five): the bytes past the end are written over next. */
static char *frag_at(const pt_trace *t, char *o, pt_stage st, int k)
{
    memcpy(o, &t->frag[st][k], sizeof t->frag[st][k]);
    return o + t->frag[st][k].len;
}

/* ',"y":' at o: the JSON key of value k >= 1 of stage st (stages/pt_stage.h);
** the first comes with the stage's name. */
static char *key_at(const pt_trace *t, char *o, pt_stage st, int k)
{
    return frag_at(t, o, st, k);
}

/* The pieces of each stage's records: JSON Lines ',"stage":"NAME","KEY":'
** (the first value's key; every stage has one) and the keys ',"KEY":' of the
** others; CSV its name.  From pt_stage_infos; a piece that would not fit
** (none does) is left empty and asserted. */
static void frags_init(pt_trace *t)
{
    int st, k;

    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        const pt_stage_info *in = &pt_stage_infos[st];
        for (k = 0; k < 5; k++) {
            struct pt_trace_frag *f = &t->frag[st][k];
            int n = 0;
            memset(f->s, 0, sizeof f->s);
            if (k == 0 && t->fmt == PT_FORMAT_CSV)
                n = snprintf(f->s, sizeof f->s, "%s", in->name);
            else if (k == 0)
                n = snprintf(f->s, sizeof f->s, ",\"stage\":\"%s\",\"%s\":",
                             in->name, in->key[0]);
            else if (k < 4 && in->key[k] && t->fmt != PT_FORMAT_CSV)
                n = snprintf(f->s, sizeof f->s, ",\"%s\":", in->key[k]);
            assert(n >= 0 && (size_t)n < sizeof f->s);
            f->len = (unsigned char)n;
        }
    }
}

/* Where a record opening for model m will start in the block, with room
** made for it, or SIZE_MAX when m's name is too long to keep one: a name of
** up to 40 bytes, each escaped to 6 at most, keeps the whole opening below
** the room made, so no flush can come between its start and its end. */
static size_t opening_start(pt_trace *t, const pt_model *m)
{
    if (strlen(m->name) > 40) return SIZE_MAX;
    room(t, 512);
    return t->len;
}

/* What was written to the block since start, taken back out of it into
** dst (cap bytes): its length, or 0 (and nothing kept) when it does not fit.
** The record openings kept below are written so, by the code that writes
** the records the long way, then copied for each record. */
static size_t take_back(pt_trace *t, size_t start, char *dst, size_t cap)
{
    size_t n;

    assert(t->len >= start);
    n = t->len - start;
    t->len = start;
    if (n > cap) return 0;
    memcpy(dst, t->buf + start, n);
    return n;
}

/* How the vertex records of model m begin, up to v's digits:
** '{"type":"vertex","model":"m1","v":' (JSON Lines) or 'm1,' (CSV), written
** by the code that writes them otherwise (then taken back out of the block)
** and kept in t->vx; t->vx_mlen is 0 when it does not fit with 20 bytes to
** spare for v's digits (as pixel_prefix). */
static void vertex_prefix(pt_trace *t, const pt_model *m)
{
    size_t start;

    t->vx_model = m;
    t->vx_mlen = 0;
    t->vx_len = 0;
    if ((start = opening_start(t, m)) == SIZE_MAX) return;
    if (t->fmt == PT_FORMAT_CSV) {
        puts_(t, m->name); put(t, ",", 1);
    } else {
        puts_(t, "{\"type\":\"vertex\",\"model\":"); put_json_str(t, m->name);
        puts_(t, ",\"v\":");
    }
    t->vx_mlen = take_back(t, start, t->vx, sizeof t->vx - 20);
}

/* A vertex record of t->model begun at the end of the block from its kept
** opening (one fixed-size copy), with room made for the rest: where it goes
** on, or NULL when no opening is kept (a long name: the caller writes it).
** With with_v the opening goes on with t->v's digits: a vertex's records
** come in a row, so the digits are kept with the opening, written once for
** all of them. */
static inline char *vertex_opening_at(pt_trace *t, int with_v)
{
    char *o;

    if (t->model != t->vx_model) vertex_prefix(t, t->model);
    if (!t->vx_mlen) return NULL;
    if (with_v && (!t->vx_len || t->vx_v != t->v)) {
        t->vx_len = (size_t)(u64_at(t, t->vx + t->vx_mlen, t->v) - t->vx);
        t->vx_v = t->v;
    }
    o = room(t, sizeof t->vx + PT_ROW_REST);
    memcpy(o, t->vx, sizeof t->vx);
    return o + (with_v ? t->vx_len : t->vx_mlen);
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
    char *o;

    if (t->clipv) {
        puts_(t, "{\"type\":\"clipvertex\",\"model\":"); put_json_str(t, t->model->name);
        o = room(t, PT_ROW_REST);
        o = str_at(o, ",\"segment\":"); o = u64_at(t, o, t->seg);
        o = str_at(o, ",\"from\":"); o = u64_at(t, o, t->from);
        o = str_at(o, ",\"to\":"); o = u64_at(t, o, t->to);
        o = str_at(o, ",\"t\":"); o = json_num_at(t, o, t->t_clip);
    } else {
        if (!(o = vertex_opening_at(t, 1))) {
            puts_(t, "{\"type\":\"vertex\",\"model\":"); put_json_str(t, t->model->name);
            o = room(t, PT_ROW_REST);
            o = u64_at(t, str_at(o, ",\"v\":"), t->v);
        }
    }
    o = frag_at(t, o, r->stage, 0);         /* ,"stage":"camera","x": */
    if (r->stage == PT_STAGE_CVV) {         /* ,"stage":"cvv","code": */
        o = int_at(t, o, r->code, 0);
        o = str_at(o, ",\"planes\":");
        o = names_json_at(o, r->code, pt_cvv_names, PT_CVV_NPLANES);
    } else if (pt_stage_infos[r->stage].nreal) {
        /* nreal is read once (each byte stored may alias it); the first
        ** value's key came with the stage's name */
        const double v[4] = {r->x, r->y, r->z, r->w};
        int k, nreal = pt_stage_infos[r->stage].nreal;
        o = json_num_at(t, o, v[0]);
        for (k = 1; k < nreal; k++)
            o = json_num_at(t, key_at(t, o, r->stage, k), v[k]);
    } else {                                /* viewport, framebuffer, index */
        const int64_t n[2] = {r->stage == PT_STAGE_INDEX ? r->i : r->ix, r->iy};
        int k, nint = pt_stage_infos[r->stage].nint;      /* read once, as nreal */
        for (k = 0; k < nint; k++) {
            if (k) o = key_at(t, o, r->stage, k);
            o = pt_rec_has(r, k) ? int_at(t, o, n[k], 0) : str_at(o, "null");
        }
    }
    if (r->stage == PT_STAGE_IMAGE && (r->flags & PT_REC_BEHIND))
        o = str_at(o, ",\"behind\":true");
    if (r->stage == PT_STAGE_VIEWPORT)
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

/* CSV rows, empty where a field does not apply, warning names joined by '|':
**   classic camera: model,v,stage,x,y,z,inside,behind,i,warning,digits_lost
**   matrix camera:  model,v,stage,x,y,z,w,code,planes,inside,i,segment,t,warning,
**                   digits_lost
** (planes joined by '|'; a point clipping made has no v, but its segment and t). */

/* Names whose bits are set in bits, joined by sep, at o; returns the end. */
static char *names_at(char *o, unsigned bits, const char *const *names, int n, char sep)
{
    int k, first = 1;

    for (k = 0; k < n; k++) {
        if (!(bits & (1u << k))) continue;
        if (!first) *o++ = sep;
        first = 0;
        o = str_at(o, names[k]);
    }
    return o;
}

static void vertex_csv(pt_trace *t, const pt_vrec *r)
{
    int matrix = t->scene && t->scene->matrix, k, dims = pt_stage_infos[r->stage].nreal;
    const double v[4] = {r->x, r->y, r->z, r->w};
    char *o;

    if (!(o = vertex_opening_at(t, !t->clipv))) {   /* 'm1,12' ('m1,' clipped) */
        puts_(t, t->model->name);
        o = room(t, PT_ROW_REST);
        *o++ = ',';
        if (!t->clipv) o = u64_at(t, o, t->v);
    }
    *o++ = ',';
    o = frag_at(t, o, r->stage, 0);         /* the stage's name */
    for (k = 0; k < (matrix ? 4 : 3); k++) {            /* x,y,z[,w] */
        *o++ = ',';
        if (k < dims) o = short_at(t, o, v[k]);
        else if (k < 2 && !dims && r->stage != PT_STAGE_INDEX && r->stage != PT_STAGE_CVV
                 && pt_rec_has(r, k))
            o = int_at(t, o, k ? r->iy : r->ix, 0);
    }
    *o++ = ',';
    if (matrix) {                                       /* code,planes */
        if (r->stage == PT_STAGE_CVV) {
            o = int_at(t, o, r->code, 0);
            *o++ = ',';
            o = names_at(o, r->code, pt_cvv_names, PT_CVV_NPLANES, '|');
        } else {
            *o++ = ',';
        }
        *o++ = ',';
    }
    if (r->stage == PT_STAGE_VIEWPORT) *o++ = r->flags & PT_REC_INSIDE ? '1' : '0';
    *o++ = ',';
    if (!matrix) {                                      /* behind */
        if (r->stage == PT_STAGE_IMAGE) *o++ = r->flags & PT_REC_BEHIND ? '1' : '0';
        *o++ = ',';
    }
    if (r->stage == PT_STAGE_INDEX && !(r->flags & PT_REC_NULL)) o = int_at(t, o, r->i, 0);
    *o++ = ',';
    if (matrix) {                                       /* segment,t */
        if (t->clipv) { o = u64_at(t, o, t->seg); *o++ = ','; o = short_at(t, o, t->t_clip); }
        else *o++ = ',';
        *o++ = ',';
    }
    o = names_at(o, r->warn, pt_warn_names, PT_NWARN, '|');
    *o++ = ',';
    if (r->warn & (PT_WARN_CANCEL | PT_WARN_ILLCOND)) o = int_at(t, o, r->digits_lost, 0);
    *o++ = '\n';
    t->len = (size_t)(o - t->buf);
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    pt_trace *t = ud;

    if (t->fmt == PT_FORMAT_JSONL) vertex_json(t, r);
    else if (t->fmt == PT_FORMAT_TEXT) vertex_text(t, r);
    else vertex_csv(t, r);
}

/* ===== raster records ===== */

/* '{"type":"KIND","model":NAME,"segment":SEG': how a raster record opens. */
static void put_seg_json(pt_trace *t, const char *kind, const pt_model *m, uint64_t seg)
{
    puts_(t, "{\"type\":\""); puts_(t, kind); puts_(t, "\",\"model\":");
    put_json_str(t, m->name);
    puts_(t, ",\"segment\":"); put_u64(t, seg);
}

/* How the pixel records of segment seg of m begin, up to the first number:
** '{"type":"pixel","model":"m1","segment":7,"x":' (JSON Lines) or
** "m1 s7          pixel        x_fb = " (text), written by the code that
** writes every other record (then taken back out of the block) and kept in
** t->pix for the pixels of the segment, which come in a row; t->pix_len is
** 0 when it does not fit (opening_start). */
static void pixel_prefix(pt_trace *t, const pt_model *m, uint64_t seg)
{
    size_t start, mlen = 0;

    if (t->fmt == PT_FORMAT_JSONL && m == t->pix_model && t->pix_len &&
        t->pix_mlen + 32 <= sizeof t->pix) {
        /* the next segment of the same model: only the number changes */
        char *o = u64_at(t, t->pix + t->pix_mlen, seg);
        memcpy(o, ",\"x\":", 5);
        t->pix_seg = seg;
        t->pix_len = (size_t)(o + 5 - t->pix);
        return;
    }
    t->pix_model = m;
    t->pix_seg = seg;
    t->pix_len = 0;
    if ((start = opening_start(t, m)) == SIZE_MAX) return;
    if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, 's', seg);
        puts_(t, "pixel        x_fb = ");
    } else {
        put_seg_json(t, "pixel", m, seg);
        mlen = t->len - start - pt_fmt_ulen(seg);   /* up to the segment's number */
        puts_(t, ",\"x\":");
    }
    t->pix_len = take_back(t, start, t->pix, sizeof t->pix);
    t->pix_mlen = mlen;
}

/* One pixel record, the long way: for a model whose name is too long to
** keep its opening (pixel_prefix). */
static void pixel_long(pt_trace *t, const pt_model *m, uint64_t seg, const pt_fb_pixel *p)
{
    if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, 's', seg);
        puts_(t, "pixel        x_fb = "); put_int_col(t, p->x_fb);
        puts_(t, "  y_fb = "); put_int_col(t, p->y_fb);
        puts_(t, "  idx = "); put_i64(t, p->idx);
        put(t, "\n", 1);
        return;
    }
    put_seg_json(t, "pixel", m, seg);
    puts_(t, ",\"x\":"); put_i64(t, p->x_fb);
    puts_(t, ",\"y\":"); put_i64(t, p->y_fb);
    puts_(t, ",\"i\":"); put_i64(t, p->idx);
    puts_(t, "}\n");
}

/* x at o as int_at(t, o, x, 0) writes it: a pixel of the array (0 to
** 10^8 - 1) straight from the digit table, without the sign's test. */
static inline char *pixel_int_at(const pt_trace *t, char *o, int64_t x)
{
    if ((uint64_t)x < 100000000) return o + pt_fmt_u32_tab(&t->digits, o, (uint32_t)x);
    return int_at(t, o, x, 0);
}

/* The rest of a JSON Lines pixel record after its kept opening, at o:
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

/* The same for the text format: '  X  y_fb = Y  idx = I\n'. */
static char *pixel_text_at(const pt_trace *t, char *o, const pt_fb_pixel *p)
{
    o = int_at(t, o, p->x_fb, 12);
    o = int_at(t, str_at(o, "  y_fb = "), p->y_fb, 12);
    o = int_at(t, str_at(o, "  idx = "), p->idx, 0);
    *o++ = '\n';
    return o;
}

/* The longest pixel record after its opening: three integers of 20 bytes,
** padding to 12 columns, the keys between them, the line's end. */
#define PT_PIXEL_REST 100

static void on_pixels(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                      size_t n)
{
    pt_trace *t = ud;
    size_t k;
    char *o;

    if (t->fmt != PT_FORMAT_TEXT && t->fmt != PT_FORMAT_JSONL) return;  /* CSV: none */
    if (m != t->pix_model || seg != t->pix_seg) pixel_prefix(t, m, seg);
    if (!t->pix_len) {
        for (k = 0; k < n; k++) pixel_long(t, m, seg, &px[k]);
        return;
    }
    assert(n <= PT_RASTER_RUN);             /* room for all n at once: */
    o = room(t, n * (sizeof t->pix + PT_PIXEL_REST));   /* 12.5 KiB at most */
    if (t->fmt == PT_FORMAT_JSONL) {
        for (k = 0; k < n; k++) {           /* each: one fixed-size copy, the numbers */
            memcpy(o, t->pix, sizeof t->pix);
            o = pixel_json_at(t, o + t->pix_len, &px[k]);
        }
    } else {
        for (k = 0; k < n; k++) {
            memcpy(o, t->pix, sizeof t->pix);
            o = pixel_text_at(t, o + t->pix_len, &px[k]);
        }
    }
    t->len = (size_t)(o - t->buf);
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
        put_seg_json(t, "clip", m, seg);
        puts_(t, ",\"count\":"); put_u64(t, count);
        puts_(t, ",\"first\":"); put_pair_json(t, first);
        puts_(t, ",\"last\":"); put_pair_json(t, last);
        puts_(t, "}\n");
    } else if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, 's', seg);
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
        put_seg_json(t, "skip", m, seg);
        if (v) { puts_(t, ",\"v\":"); put_u64(t, v); }
        puts_(t, ",\"why\":"); put_json_str(t, why); puts_(t, "}\n");
    } else if (t->fmt == PT_FORMAT_TEXT) {
        put_who(t, m->name, 's', seg);
        puts_(t, "skipped      ");
        if (v) { put(t, "v", 1); put_u64(t, v); puts_(t, ": "); }
        puts_(t, why); put(t, "\n", 1);
    }
}

/* ===== summary ===== */

static void on_summary(void *ud, const pt_summary *sum)
{
    pt_trace *t = ud;
    const struct { const char *name; uint64_t hi, lo; } c[] = {    /* hi * 2^64 + lo */
        {"models", 0, sum->models}, {"vertices", 0, sum->vertices},
        {"vertices_unused", 0, sum->vertices_unused},
        {"vertices_traced", 0, sum->vertices_traced}, {"segments", 0, sum->segments},
        {"segments_degenerate", 0, sum->segments_degenerate},
        {"segments_skipped", 0, sum->segments_skipped},
        {"segments_culled", 0, sum->segments_culled}, {"pixels", 0, sum->pixels},
        {"clipped", sum->clipped_hi, sum->clipped}, {"clip_runs", 0, sum->clip_runs},
        {"behind", 0, sum->behind},
    };
    size_t k;

    if (t->fmt == PT_FORMAT_CSV) return;
    if (t->fmt == PT_FORMAT_JSONL) {
        puts_(t, "{\"type\":\"summary\"");
        for (k = 0; k < sizeof c / sizeof c[0]; k++) {
            puts_(t, ",\""); puts_(t, c[k].name); puts_(t, "\":");
            put_u128(t, c[k].hi, c[k].lo);
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
    for (k = 0; k < sizeof c / sizeof c[0]; k++) {
        puts_(t, k % 4 == 0 ? "\n  " : "  ");
        puts_(t, c[k].name); put(t, " ", 1);
        put_u128(t, c[k].hi, c[k].lo);
    }
    puts_(t, "\n  warnings");
    for (k = 0; k < PT_NWARN; k++) {
        put(t, " ", 1); puts_(t, pt_warn_names[k]); put(t, " ", 1);
        put_u64(t, sum->warnings[k]);
    }
    puts_(t, sum->rasterized ? "\n  rasterized yes\n" : "\n  rasterized no (--vertex without --image)\n");
}

/* ===== public ===== */

/* The bytes names[0..n) take in a record at most: each quoted, a separator. */
static size_t names_len(const char *const *names, int n)
{
    size_t len = 0;
    int k;

    for (k = 0; k < n; k++) len += strlen(names[k]) + 3;
    return len;
}

void pt_trace_init(pt_trace *t, FILE *f, pt_format fmt, int precision)
{
    char b[PT_NUMLEN];
    size_t k;

    assert(names_len(pt_warn_names, PT_NWARN) <= 160);         /* PT_ROW_REST */
    assert(names_len(pt_cvv_names, PT_CVV_NPLANES) <= 160);
    t->f = f;
    t->fmt = fmt;
    t->precision = precision;
    t->model = NULL;
    t->v = 0;
    t->explain = 0;
    t->student = NULL;
    t->journey_made = 0;
    t->clipv = 0;
    t->scene = NULL;
    t->plan = NULL;
    t->failed = 0;
    t->len = 0;
    t->buf = t->block;
    t->out = NULL;
    t->out_ud = NULL;
    t->pix_model = NULL;
    t->pix_seg = 0;
    t->pix_len = 0;
    t->pix_mlen = 0;
    t->vx_model = NULL;
    t->vx_mlen = 0;
    t->vx_v = 0;
    t->vx_len = 0;
    pt_digits4_init(&t->digits);
    frags_init(t);
    for (k = 0; k < sizeof t->nums / sizeof t->nums[0]; k++) {  /* each slot: +0 */
        t->nums[k].bits = 0;
        t->nums[k].len = (unsigned char)pt_fmt_shortest(b, 0.0);
        memcpy(t->nums[k].s, b, PT_SHORTLEN);
    }
}

void pt_trace_listener(pt_trace *t, pt_listener *l)
{
    l->header = on_header;
    l->vertex_begin = on_vertex_begin;
    l->sink.vertex = on_vertex;
    l->clipvertex_begin = on_clipvertex_begin;
    l->sink.ud = t;
    l->pixels = on_pixels;
    l->clip = on_clip;
    l->journey = t->explain ? on_journey : NULL;   /* no cost without --explain */
    l->skip = on_skip;
    l->summary = on_summary;
    l->piece = NULL;
    if (t->fmt == PT_FORMAT_CSV) {          /* no raster rows, no summary: */
        l->pixels = NULL;                   /* nobody listens to the rasterizer */
        l->clip = NULL;
        l->skip = NULL;
        l->summary = NULL;
    }
    l->ud = t;
}

int pt_trace_finish(pt_trace *t)
{
    flush(t);
    if (fflush(t->f) != 0) write_failed(t);
    return t->failed ? -1 : 0;
}
