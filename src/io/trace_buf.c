/*
** src/io/trace_buf.c -- the trace writer's block, its numbers, its record openings
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "io/sbuf.h"
#include "io/trace.h"
#include "io/trace_int.h"

/* ===== the output block ===== */

/* A write failed: keep the first reason (errno) for the message. */
static void write_failed(pt_trace *t)
{
    if (!t->failed) t->failed = errno ? errno : EIO;
}

/* See trace_int.h. */
void pt_trace_flush(pt_trace *t)
{
    if (t->out) {                           /* it takes the block (tlanes.c) */
        t->out(t->out_ud, t);
        return;
    }
    if (t->len && fwrite(t->buf, 1, t->len, t->f) != t->len) write_failed(t);
    t->len = 0;
}

/* Long division by 10 on 32-bit limbs.  See trace_int.h. */
void pt_trace_put_u128(pt_trace *t, uint64_t hi, uint64_t lo)
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

/* ===== numbers and strings ===== */

/* See trace_int.h. */
char *pt_trace_short_miss(struct pt_trace_num *e, char *o, double x, uint64_t bits)
{
    e->bits = bits;
    e->len = (unsigned char)pt_fmt_shortest(o, x);
    memcpy(e->s, o, PT_SHORTLEN);
    return o + e->len;
}

/* See trace_int.h. */
void pt_trace_json_chars(pt_trace *t, const char *s)
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

/* ===== record openings ===== */

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

/* See trace_int.h. */
void pt_trace_vertex_prefix(pt_trace *t, const pt_model *m,
                            void (*opening)(pt_trace *t, const pt_model *m))
{
    size_t start;

    t->vx_model = m;
    t->vx_mlen = 0;
    t->vx_len = 0;
    if ((start = opening_start(t, m)) == SIZE_MAX) return;
    opening(t, m);
    t->vx_mlen = take_back(t, start, t->vx, sizeof t->vx - 20);
}

/* See trace_int.h. */
void pt_trace_pixel_prefix(pt_trace *t, const pt_model *m, uint64_t seg,
                           size_t (*opening)(pt_trace *t, const pt_model *m, uint64_t seg))
{
    size_t start, mlen;

    t->pix_model = m;
    t->pix_seg = seg;
    t->pix_len = 0;
    if ((start = opening_start(t, m)) == SIZE_MAX) return;
    mlen = opening(t, m, seg);
    t->pix_len = take_back(t, start, t->pix, sizeof t->pix);
    t->pix_mlen = mlen;
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
int pt_trace_finish(pt_trace *t)
{
    pt_trace_flush(t);
    if (fflush(t->f) != 0) write_failed(t);
    return t->failed ? -1 : 0;
}
