/*
** src/io/tread_int.h -- what the trace readers share (src/io/tread*.c only)
** See LICENSE for copyright and license.
**
** pt_tread_parse() (tread.c) reads the buffer one line at a time and hands
** each line to the reader of its format: pt_tr_json_line() (tread_jsonl.c)
** or pt_tr_text_line() (tread_text.c).  Both fill the same pt_tread through
** the same pt_treader, with the record and number helpers below
** (tread_util.c).
** The images (tread_image.c) share only the list of formats for messages.
** Nothing here is part of the public API: that is io/tread.h.
*/
#ifndef PT_TREAD_INT_H
#define PT_TREAD_INT_H

#include <stddef.h>
#include <stdint.h>

/* The types of io/tread.h, by name only: the files that include this one
** include io/tread.h first, and this header stays below it (no module cycle). */
struct pt_names;
struct pt_tread;
struct pt_tvrec;
struct pt_tpix;
struct pt_tclip;
struct pt_tmodel;

#if defined(__GNUC__) || defined(__clang__)
#define PT_TR_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PT_TR_PRINTF_LIKE(f, a)
#endif

/* The images pt_image_parse() reads, for messages. */
#define PT_TR_IMG_FORMATS "binary PPM (P6), plain PPM (P3), or PNG as pipetrace writes it"

/* ===== the reader ===== */

/* The reading position and where errors go; one per pt_tread_parse() call,
** zeroed at its start. */
typedef struct pt_treader {
    const char *path;            /* file name for messages */
    const char *line;            /* start of the current line */
    const char *eol;             /* its end (before "\r\n" or "\n") */
    size_t lineno;               /* its number, 1-based */
    char *err;                   /* message buffer */
    size_t errlen;               /* its size */
    struct pt_names *nm;         /* names go here */
    struct pt_tread *t;          /* records go here */
    char *sbuf;                  /* a decoded JSON string; owned */
    size_t scap;                 /* room in sbuf */
    int cv_have;                 /* 1: a clip-vertex record was read: */
    uint32_t cv_model;           /*   its model, */
    uint64_t cv_seg;             /*   segment, */
    int cv_pos, cv_end;          /*   stage's place in pt_trace_order, and end */
    int state;                   /* text: which part of the trace the line is in
                                 ** (tread_text.c); 0 at the start */
} pt_treader;

/* Write "FILE:LINE:COL: error: ..." for the byte `at` of the current line
** (NULL: column 1).  Control bytes become '?' so that the message stays one
** line.  Returns -1. */
int pt_tr_fail(pt_treader *r, const char *at, const char *fmt, ...) PT_TR_PRINTF_LIKE(3, 4);

/* pt_tr_fail() with "out of memory".  Returns -1. */
int pt_tr_oom(pt_treader *r);

/* Make room for one more element in *arr, an array of n `size`-byte
** elements with room for *cap.  Returns 0, or -1 (out of memory, reported). */
int pt_tr_grow(pt_treader *r, void **arr, size_t n, size_t *cap, size_t size);

/* The current line number as a record keeps it, at most UINT32_MAX.  This
** function can't fail. */
uint32_t pt_tr_line32(const pt_treader *r);

/* The flags of an integer record whose values k with bit k set in nulls are
** null, for a stage whose records may carry sflags (pt_stage_info.flags): 0,
** or PT_REC_NULL with PT_REC_HAS_X/Y, where the stage has them, for the
** coordinates that still have one (a pixel's null is per value, an index's
** whole).  This function can't fail. */
unsigned pt_tr_null_flags(unsigned nulls, unsigned sflags);

/* A new vertex record at the end of r->t->vx: vertex v of model at stage st
** on the current line, no flags, no values yet.  Returns it, or NULL (out of
** memory, reported). */
struct pt_tvrec *pt_tr_new_vrec(pt_treader *r, uint32_t model, uint64_t v, int st);

/* Append *px to r->t->px, *c to r->t->cl.  Return 0, or -1 (out of memory,
** reported). */
int pt_tr_add_pixel(pt_treader *r, const struct pt_tpix *px);
int pt_tr_add_clip(pt_treader *r, const struct pt_tclip *c);

/* A new model at the end of r->t->hdr.models, zeroed.  Returns it, or NULL
** (out of memory, reported). */
struct pt_tmodel *pt_tr_new_model(pt_treader *r);

/* The vertex number of a clip vertex of segment seg at stage st: the records
** of its first end, then of its second, each in stage order, so a stage that
** does not come after the previous one starts the second end.  `at` is where
** an error points.  Returns 0, or -1 (reported). */
int pt_tr_clipv_number(pt_treader *r, uint32_t model, uint64_t seg, int st, const char *at,
                       uint64_t *v);

/* The pt_stage named p[0..n), or -1.  This function can't fail. */
int pt_tr_stage_named(const char *p, size_t n);

/* ===== numbers and words ===== */

/* The length of the number at p (before e): -?D+(.D+)?([eE][+-]?D+)?, or 0.
** *decimals gets the count of digits after the point (at most 99).  JSON
** forbids leading zeros; the text format never writes them, so both are held
** to that.  This function can't fail. */
size_t pt_tr_num_len(const char *p, const char *e, int *decimals);

/* 1 when p[0..n) is an integer token: no point, no exponent. */
int pt_tr_is_int_token(const char *p, size_t n);

/* The integer at p (already checked by pt_tr_num_len()) into *out.  Returns
** 0, or -1 when out of range. */
int pt_tr_to_i64(const char *p, int64_t *out);

/* 1 when p[0..n) spells s. */
int pt_tr_is(const char *p, size_t n, const char *s);

/* The header's camera word p[0..n) into h->pipe and h->perspective:
** "perspective" and "orthographic" name the classic camera, a pipeline's own
** word (pt_pipeline.camera: "lookat") that pipeline.  Returns 0, or -1 for
** another word. */
int pt_tr_camera(pt_thdr *h, const char *p, size_t n);

/* A non-finite value as the traces spell it: nan, inf, -inf.  1 with *x when
** p[0..n) is one, else 0. */
int pt_tr_nonfinite(const char *p, size_t n, double *x);

/* ===== the formats ===== */

/* Read the current line of a JSON Lines trace (tread_jsonl.c).  Returns 0, or
** -1 (reported). */
int pt_tr_json_line(pt_treader *r);

/* Read the current line of a text trace (tread_text.c): the version line,
** the header, the records, the summary.  Returns 0, or -1 (reported). */
int pt_tr_text_line(pt_treader *r);

/* After the last line of a text trace: -1 (reported) when it was cut short
** before the end of its summary, else 0.  r->lineno is one past the last
** line. */
int pt_tr_text_end(pt_treader *r);

/* Read a whole log of the course's renderer, buf[0..len) (tread_kraft.c).
** Returns 0, or -1 (reported). */
int pt_tr_kraft(pt_treader *r, const char *buf, size_t len);

#endif
