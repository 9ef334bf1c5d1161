/*
** src/io/trace_int.h -- the trace writers' shared machinery: block, numbers, openings
** See LICENSE for copyright and license.
**
** For the files of the trace writer only (trace.c, trace_buf.c, trace_head.c
** and one file a format: trace_text.c, trace_jsonl.c, trace_csv.c), and the
** writers of renderers 7 and 9's traces and log, which write into a
** pt_trace's block the same way (trace_course_rec.c, trace_course.c,
** rv_log_raster.c); the rest of the program knows io/trace.h.  The small pieces every record is made of
** (put a string, make room, a number's digits) are static inline here, so
** that each format's records are written as fast as when the writer was one
** file: the compiler sees them where a record is written.  What is called
** seldom (a full block, a number not yet spelled, a record opening not yet
** kept) is in trace_buf.c.
**
** Writing to the block.  put() and its kin copy into t->buf at t->len and
** flush a full block first.  The writers of a whole record ask room() for
** all the bytes it may take, write by pointer (the *_at functions: each
** writes at o and returns the end) and then move t->len past what they
** wrote.
*/
#ifndef PT_TRACE_INT_H
#define PT_TRACE_INT_H

#include <assert.h>
#include <stdint.h>
#include <string.h>
#include "core/pipetrace.h"
#include "io/numfmt.h"

/* The files that include this one include io/trace.h first (its pt_trace is
** what everything here works on), and this header stays below it: it does
** not include it, so that trace.c's module does not come back to itself. */
#ifndef PT_TRACE_H
#error "include io/trace.h before io/trace_int.h"
#endif

/* ===== a format's writers ===== */

/* A format's record writers, as pt_listener takes them (ud: the pt_trace);
** pt_trace_listener() (trace.c) puts the format's in the listener.  pixels,
** clip, point_pixels, skip, note and summary are NULL for a format without those records (CSV):
** nobody listens to the rasterizer then. */
typedef struct pt_trace_writer {
    void (*header)(pt_trace *t, const pt_scene *s, const pt_plan *p);  /* t->scene
                                 ** and t->plan are set before it is called */
    void (*vertex)(void *ud, const pt_vrec *r);
    void (*pixels)(void *ud, const pt_model *m, uint64_t seg, const pt_fb_pixel *px,
                   size_t n);
    void (*clip)(void *ud, const pt_model *m, uint64_t seg, uint64_t count,
                 pt_pix first, pt_pix last);
    void (*point_pixels)(void *ud, const pt_model *m, uint64_t pt, const pt_fb_pixel *px,
                         size_t n);
    void (*skip)(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *why);
    void (*note)(void *ud, const pt_model *m, uint64_t seg, uint64_t v, const char *what);
    void (*summary)(void *ud, const pt_summary *sum);
} pt_trace_writer;

extern const pt_trace_writer pt_trace_text;     /* trace_text.c */
extern const pt_trace_writer pt_trace_jsonl;    /* trace_jsonl.c */
extern const pt_trace_writer pt_trace_csv;      /* trace_csv.c */

/* ===== the output block (trace_buf.c) ===== */

/* Hand the block's t->len bytes on: to t->out when set (it gives the writer
** a block to go on with), else to t->f; t->len is 0 after.  A write error
** is kept in t->failed (the first one's errno value, EIO when none was
** set).  This function can't fail otherwise. */
void pt_trace_flush(pt_trace *t);

/* n bytes of s at the end of the block. */
static inline void put(pt_trace *t, const char *s, size_t n)
{
    if (t->len + n > PT_TRACE_BLOCK) {
        pt_trace_flush(t);
        for (; n > PT_TRACE_BLOCK; s += PT_TRACE_BLOCK, n -= PT_TRACE_BLOCK) {
            memcpy(t->buf, s, PT_TRACE_BLOCK);  /* longer than a block: */
            t->len = PT_TRACE_BLOCK;            /*   a block at a time */
            pt_trace_flush(t);
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

static inline void puts_(pt_trace *t, const char *s) { put(t, s, strlen(s)); }

/* The most a vertex record writes after the model's name (and before
** --explain's text): v or a segment (20 bytes), the stage's name and keys,
** five numbers of PT_NUMLEN + 2, integers, the plane and warning names
** (pt_trace_init() checks that each list fits in 160 bytes), punctuation. */
#define PT_ROW_REST (5 * (PT_NUMLEN + 2) + 8 * 24 + 2 * 160 + 256)

/* Room for n bytes (at most a block; a vertex record asks for PT_ROW_REST,
** a run of pixel records for PT_RASTER_RUN of theirs) at the end of the
** block, for the writers that write there by pointer and then move
** t->len past what they wrote: one check for a whole record, or a whole
** run, instead of one per piece. */
static inline char *room(pt_trace *t, size_t n)
{
    assert(n <= PT_TRACE_BLOCK);
    if (t->len + n > PT_TRACE_BLOCK) pt_trace_flush(t);
    return t->buf + t->len;
}

/* Integers by hand (pt_fmt_u64): snprintf costs more than the rest of a
** pixel record. */
static inline void put_u64(pt_trace *t, uint64_t x)
{
    char *o = room(t, 20);
    t->len += pt_fmt_u64(o, x);
}

static inline void put_i64(pt_trace *t, int64_t x)
{
    if (x < 0) { put(t, "-", 1); put_u64(t, 0u - (uint64_t)x); }
    else put_u64(t, (uint64_t)x);
}

/* hi * 2^64 + lo in decimal, at the end of the block (the summary's counts,
** clipped steps beyond 2^64).  This function can't fail. */
void pt_trace_put_u128(pt_trace *t, uint64_t hi, uint64_t lo);

/* ===== numbers and strings ===== */

/* x spelled by pt_fmt_shortest() at o into slot e of t->nums, which then
** holds bits (x's); returns the end.  The miss of short_at() and
** json_num_at(), below.  This function can't fail. */
char *pt_trace_short_miss(struct pt_trace_num *e, char *o, double x, uint64_t bits);

/* The slot of a double's bits: the top PT_TRACE_NUMBITS bits of their
** product with 2^64 / golden ratio (Knuth's multiplicative hash). */
static inline struct pt_trace_num *num_slot(pt_trace *t, uint64_t bits)
{
    return &t->nums[(bits * UINT64_C(0x9e3779b97f4a7c15)) >> (64 - PT_TRACE_NUMBITS)];
}

/* x as pt_fmt_shortest() spells it, at o (PT_NUMLEN bytes); returns the end.
** A trace spells the same doubles again and again (a model's z in each of
** its vertices, the camera's x and y where the translation's are 0, the
** image plane's z), so the spellings of recent ones are kept in t->nums,
** one slot for each hash of the bits; a slot holds the spelling of the
** bits it holds (pt_trace_init() fills each with +0's), so a hit is always
** right.  The copy is of a fixed PT_SHORTLEN bytes, no library call.  A hit
** (most of them) is inlined where a record is written; a miss spells x into
** the slot by pt_trace_short_miss(). */
static inline char *short_at(pt_trace *t, char *o, double x)
{
    struct pt_trace_num *e;
    uint64_t bits;

    memcpy(&bits, &x, sizeof bits);
    e = num_slot(t, bits);
    if (e->bits != bits) return pt_trace_short_miss(e, o, x, bits);
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
        return pt_trace_short_miss(e, o, x, bits);
    if (x == 0) { memcpy(o, "-0.0", 4); return o + 4; }
    *o++ = '"';
    o += pt_fmt_shortest(o, x);
    *o++ = '"';
    return o;
}

static inline void put_json_num(pt_trace *t, double x)
{
    t->len = (size_t)(json_num_at(t, room(t, PT_NUMLEN + 2), x) - t->buf);
}

static inline void put_short(pt_trace *t, double x)
{
    char *o = room(t, PT_NUMLEN);
    t->len += pt_fmt_shortest(o, x);
}

/* A string's characters as JSON writes them inside quotes: " and \ after a
** backslash, control characters as \u00XX, a byte that is no UTF-8 as
** \ufffd.  The text header writes the scene path so too: one line, nothing
** for a terminal to act on, and tread_text.c reads it back.  This function
** can't fail. */
void pt_trace_json_chars(pt_trace *t, const char *s);

/* A string in JSON quotes, escaping what JSON requires. */
static inline void put_json_str(pt_trace *t, const char *s)
{
    put(t, "\"", 1);
    pt_trace_json_chars(t, s);
    put(t, "\"", 1);
}

/* Text: a fixed-width right-aligned column. */
static inline void put_col(pt_trace *t, const char *s, size_t n, size_t width)
{
    static const char spaces[] = "                                ";
    if (n < width) put(t, spaces, width - n < 32 ? width - n : 32);
    put(t, s, n);
}

/* u's digits at o (20 bytes); below 10^8 (the pixels, the indexes) from the
** trace's digit table, else by pt_fmt_u64(). */
static inline char *digits_at(const pt_trace *t, char *o, uint64_t u)
{
    if (u < 10000) return o + pt_fmt_u4_tab(&t->digits, o, (uint32_t)u);   /* most of them */
    if (u < 100000000) return o + pt_fmt_u32_tab(&t->digits, o, (uint32_t)u);
    return o + pt_fmt_u64(o, u);
}

/* "%*" PRId64 at o (at most 20 bytes plus padding); returns the end.  Digits
** by hand (snprintf costs more than the rest of a record). */
static inline char *int_at(const pt_trace *t, char *o, int64_t x, size_t width)
{
    uint64_t u = x < 0 ? 0u - (uint64_t)x : (uint64_t)x;

    if (width) {
        size_t n = pt_fmt_ulen(u) + (x < 0);
        for (; width > n; width--) *o++ = ' ';
    }
    if (x < 0) *o++ = '-';
    return digits_at(t, o, u);
}

static inline char *u64_at(const pt_trace *t, char *o, uint64_t x)   /* x's digits at o */
{
    return digits_at(t, o, x);
}

static inline char *str_at(char *o, const char *s)         /* s at o; returns the end */
{
    size_t n = strlen(s);
    memcpy(o, s, n);
    return o + n;
}

/* ===== record openings (trace_buf.c) ===== */

/* The pieces of each stage's records, made once from pt_stage_infos by
** pt_trace_init() (trace_buf.c: frags_init): JSON Lines ',"stage":"NAME",
** "KEY":' and the keys of the other values, CSV the stage's name.
**
** Piece k of stage st at o; returns the end.  One copy of the whole slot,
** 32 bytes with its length byte (two 16-byte moves, where s alone would be
** five): the bytes past the end are written over next. */
static inline char *frag_at(const pt_trace *t, char *o, pt_stage st, int k)
{
    memcpy(o, &t->frag[st][k], sizeof t->frag[st][k]);
    return o + t->frag[st][k].len;
}

/* ',"y":' at o: the JSON key of value k >= 1 of stage st (stages/pt_stage.h);
** the first comes with the stage's name. */
static inline char *key_at(const pt_trace *t, char *o, pt_stage st, int k)
{
    return frag_at(t, o, st, k);
}

/* Keep in t->vx how the vertex records of model m begin, up to v's digits:
** opening() writes it at the end of the block, the usual way, and it is
** taken back out of the block into t->vx.  t->vx_mlen is its length, 0 when
** it does not fit with 20 bytes to spare for v's digits (a long name: the
** records are then written the long way).  This function can't fail. */
void pt_trace_vertex_prefix(pt_trace *t, const pt_model *m,
                            void (*opening)(pt_trace *t, const pt_model *m));

/* A vertex record of t->model begun at the end of the block from its kept
** opening (one fixed-size copy), with room made for the rest: where it goes
** on, or NULL when no opening is kept (a long name: the caller writes it).
** With with_v the opening goes on with t->v's digits: a vertex's records
** come in a row, so the digits are kept with the opening, written once for
** all of them.  opening: the format's, as pt_trace_vertex_prefix() takes it. */
static inline char *vertex_opening_at(pt_trace *t, int with_v,
                                      void (*opening)(pt_trace *t, const pt_model *m))
{
    char *o;

    if (t->model != t->vx_model) pt_trace_vertex_prefix(t, t->model, opening);
    if (!t->vx_mlen) return NULL;
    if (with_v && (!t->vx_len || t->vx_v != t->v)) {
        t->vx_len = (size_t)(u64_at(t, t->vx + t->vx_mlen, t->v) - t->vx);
        t->vx_v = t->v;
    }
    o = room(t, sizeof t->vx + PT_ROW_REST);
    memcpy(o, t->vx, sizeof t->vx);
    return o + (with_v ? t->vx_len : t->vx_mlen);
}

/* Keep in t->pix how the pixel records of segment seg of m begin, up to the
** first number ('{"type":"pixel","model":"m1","segment":7,"x":' in JSON
** Lines, "m1 s7          pixel        x_fb = " in text): opening() writes it
** at the end of the block, the usual way, and returns the length of what
** stays the same for the model's next segment (0: nothing); it is taken
** back out of the block into t->pix.  t->pix_len is its length, 0 when it
** does not fit (a long name).  The pixels of a segment come in a row, so
** the opening is copied for each.  This function can't fail. */
void pt_trace_pixel_prefix(pt_trace *t, const pt_model *m, uint64_t seg,
                           size_t (*opening)(pt_trace *t, const pt_model *m, uint64_t seg));

/* The longest pixel record after its opening: three integers of 20 bytes,
** padding to 12 columns, the keys between them, the line's end. */
#define PT_PIXEL_REST 100

/* A run of n pixel records of segment seg of m: after prefix() (which keeps
** the opening, see pt_trace_pixel_prefix) each is the opening, one
** fixed-size copy, and rest_at(t, o, p) writing its numbers at o; when no
** opening is kept, each is written the long way, by one().  The format's
** on_pixels calls it with its own three, so that they are inlined. */
static inline void pixels_put(pt_trace *t, const pt_model *m, uint64_t seg,
                              const pt_fb_pixel *px, size_t n,
                              void (*prefix)(pt_trace *, const pt_model *, uint64_t),
                              void (*one)(pt_trace *, const pt_model *, uint64_t,
                                          const pt_fb_pixel *),
                              char *(*rest_at)(const pt_trace *, char *, const pt_fb_pixel *))
{
    size_t k;
    char *o;

    if (m != t->pix_model || seg != t->pix_seg) prefix(t, m, seg);
    if (!t->pix_len) {
        for (k = 0; k < n; k++) one(t, m, seg, &px[k]);
        return;
    }
    assert(n <= PT_RASTER_RUN);             /* room for all n at once: */
    o = room(t, n * (sizeof t->pix + PT_PIXEL_REST));   /* 12.5 KiB at most */
    for (k = 0; k < n; k++) {               /* each: one fixed-size copy, the numbers */
        memcpy(o, t->pix, sizeof t->pix);
        o = rest_at(t, o + t->pix_len, &px[k]);
    }
    t->len = (size_t)(o - t->buf);
}

/* ===== what the text and JSON Lines headers and summaries share (trace_head.c) ===== */

/* "lookat", "perspective" or "orthographic".  This function can't fail. */
const char *pt_trace_camera_name(const pt_scene *s);

/* A point as JSON writes it: [x,y,z].  This function can't fail. */
void pt_trace_vec3_json(pt_trace *t, pt_vec3 v);

/* A matrix as four rows: JSON (json 1) [[m00,m01,m02,m03],...], text (json
** 0) "[m00 m01 m02 m03] [m10 ...] ...".  This function can't fail. */
void pt_trace_mat(pt_trace *t, const pt_mat4 *m, int json);

/* Three small integers (a colour) separated by sep.  This function can't
** fail. */
void pt_trace_rgb(pt_trace *t, const unsigned char c[3], const char *sep);

/* The matrix camera's parameters and matrices, JSON (json 1) or text lines
** (json 0): the same values in the same order, each after its label.  This
** function can't fail. */
void pt_trace_camera(pt_trace *t, const pt_scene *s, const pt_plan *p, int json);

/* The summary's counts, in the order both formats write them, each as
** hi * 2^64 + lo. */
#define PT_TRACE_NCOUNTS 12
typedef struct pt_trace_count {
    const char *name;            /* as the trace names it: "vertices_traced" */
    uint64_t hi, lo;             /* its value: hi * 2^64 + lo */
} pt_trace_count;

/* Fill c with sum's counts.  This function can't fail. */
void pt_trace_counts(const pt_summary *sum, pt_trace_count c[PT_TRACE_NCOUNTS]);

#endif
