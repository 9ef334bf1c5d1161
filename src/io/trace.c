/*
** src/io/trace.c -- the trace writer as a listener: the point being traced, the format's writers
** See LICENSE for copyright and license.
**
** The writer is in files of one concern each: the block it writes to, the
** numbers, strings and record openings every format makes its records of
** (trace_buf.c, trace_int.h), what the text and JSON Lines headers and
** summaries share (trace_head.c), and a file a format: trace_text.c,
** trace_jsonl.c, trace_csv.c, each a table of its record writers
** (pt_trace_writer).  This file keeps what all formats follow the same way:
** which point the records are of, and its journey for --explain.
*/
#include <stdint.h>
#include <string.h>
#include "io/trace.h"
#include "io/trace_int.h"

/* The record writers of t's format (PT_FORMAT_KRAFT is written by
** pt_kraft_write(), not by this listener: as before, CSV's writers). */
static const pt_trace_writer *writer_of(const pt_trace *t)
{
    if (t->fmt == PT_FORMAT_JSONL) return &pt_trace_jsonl;
    if (t->fmt == PT_FORMAT_TEXT) return &pt_trace_text;
    return &pt_trace_csv;
}

static void on_header(void *ud, const pt_scene *s, const pt_plan *p)
{
    pt_trace *t = ud;

    t->scene = s;
    t->plan = p;
    writer_of(t)->header(t, s, p);
}

/* ===== the point being traced ===== */

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

/* ===== public ===== */

void pt_trace_listener(pt_trace *t, pt_listener *l)
{
    const pt_trace_writer *w = writer_of(t);

    memset(l, 0, sizeof *l);                /* what a trace does not hear: NULL */
    l->header = on_header;
    l->vertex_begin = on_vertex_begin;
    l->sink.vertex = w->vertex;
    l->clipvertex_begin = on_clipvertex_begin;
    l->sink.ud = t;
    l->pixels = w->pixels;                  /* CSV: no raster rows, no summary: */
    l->clip = w->clip;                      /*   nobody listens to the rasterizer */
    l->point_pixels = w->point_pixels;
    l->journey = t->explain ? on_journey : NULL;   /* no cost without --explain */
    l->skip = w->skip;
    l->note = w->note;
    l->summary = w->summary;
    l->piece = NULL;
    l->ud = t;
}
