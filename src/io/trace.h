/*
** src/io/trace.h -- write the trace: JSON Lines, aligned text, or CSV
** See LICENSE for copyright and license.
**
** The trace writer is a pt_listener: the pipeline hands it numbers, it formats
** them into a 256 KiB buffer and writes whole blocks.  No allocation per record.
** Record kinds and their fields (docs/trace-format.md has the full table):
**
**   kind     field     meaning
**   -------  --------  ------------------------------------------------------
**   header   version   trace format version, PT_TRACE_VERSION
**            student   a student build's stage files (pt_trace.student); CSV:
**                      a "# student" line before the column names
**            scene ... framebuffer, viewport, camera, one entry per model with
**                      its stages, what was left out and why
**   vertex   model, v  model name, 1-based vertex number as in the scene
**            stage     model camera image pixel viewport framebuffer index
**            x y z     model, camera, image; x y: pixel, viewport, framebuffer
**            behind    image only, true when z_c > 0 under perspective
**            inside    viewport only
**            i         index only; null outside the framebuffer
**   pixel    model, segment, x, y, i   a pixel written (framebuffer coords)
**   clip     model, segment, count, first, last   a run of clipped steps
**                                      (viewport coords)
**   skip     model, segment, why       a segment not rasterized
**   summary  counts    see pt_summary in pipeline.h
*/
#ifndef PT_TRACE_H
#define PT_TRACE_H

#include <stdint.h>
#include <stdio.h>
#include "core/pipetrace.h"
#include "io/explain.h"
#include "io/numfmt.h"

#define PT_TRACE_VERSION 1
#define PT_TRACE_NUMBITS 8       /* log2 of the doubles whose spelling is kept */
#define PT_TRACE_BLOCK (1 << 18) /* output block: 256 KiB, one write(2) with an
                                 ** unbuffered f (fewer system calls; a larger
                                 ** block no longer stays in the cache) */

typedef enum pt_format { PT_FORMAT_TEXT, PT_FORMAT_JSONL, PT_FORMAT_CSV,
                         PT_FORMAT_KRAFT,          /* the course's debug log, and */
                         PT_FORMAT_KRAFT_PIXELS    /* with its pixels: written by
                                                   ** pt_kraft_write (trace_kraft.h),
                                                   ** not by this listener */
} pt_format;

typedef struct pt_trace {
    FILE *f;                     /* destination, not owned */
    pt_format fmt;               /* output format */
    int precision;               /* text: digits after the point, 0..17 */
    const pt_model *model;       /* model of the vertex being traced */
    uint64_t v;                  /* its 1-based number */
    int clipv;                   /* 1: records of a point made by clipping: */
    uint64_t seg, from, to;      /*   segment seg, from -> to (1-based) */
    double t_clip;               /*   at parameter t, */
    pt_vec4 q_clip;              /*   its clip coordinates */
    int explain;                 /* 1: each vertex record gets its formula with
                                 ** the numbers put in (--explain); set after init,
                                 ** before pt_trace_listener() */
    const char *student;         /* a student build's stage files ("pixel=FILE#CKSUM
                                 ** ..."), written into the header; NULL or "" in
                                 ** the reference build.  Set after init */
    const pt_scene *scene;       /* the scene and the plan, from the header (or */
    const pt_plan *plan;         /*   set by hand: tlanes.c); they outlive the run */
    pt_journey journey;          /* with explain: the point's whole journey, */
    int journey_made;            /*   as pt_run() handed it over */
    int failed;                  /* after a write error: its errno value (EIO
                                 ** when none was set), else 0 */
    size_t len;                  /* bytes waiting in buf */
    char *buf;                   /* the output block (PT_TRACE_BLOCK bytes): block */
    void (*out)(void *ud, struct pt_trace *t);  /* NULL: a full block goes to f;
                                 ** else out takes buf[0..len), points buf at a
                                 ** block (this one or another) and sets len 0 */
    void *out_ud;                /* passed back to out */
    const pt_model *pix_model;   /* the segment whose pixels are being written */
    uint64_t pix_seg;            /*   (trace.c: pixel_prefix) */
    size_t pix_len;              /* how their records begin: pix[0..pix_len), */
    char pix[96];                /*   0 when that does not fit; */
    size_t pix_mlen;             /*   JSON Lines: pix[0..pix_mlen) up to the segment */
    pt_digits4 digits;           /* 0000 .. 9999, for integers (trace.c: digits_at) */
    const pt_model *vx_model;    /* the model whose vertex records begin so: */
    size_t vx_mlen;              /*   vx[0..vx_mlen), 0 when it does not fit; */
    uint64_t vx_v;               /*   then the digits of vertex vx_v, up to */
    size_t vx_len;               /*   vx_len (0: none yet) */
    char vx[96];                 /*   (trace.c: vertex_prefix, vertex_opening_at) */
    struct pt_trace_frag {       /* a stage's pieces of a record, made once from */
        char s[31];              /*   pt_stage_infos (trace.c: frags_init): JSON */
        unsigned char len;       /*   ',"stage":"camera","x":', then ',"y":' ...; */
    } frag[PT_NSTAGES_ALL][5];   /*   CSV the name, then nothing.  len comes last:
                                 **   frag_at() copies the whole 32-byte slot */
    struct pt_trace_num {        /* recent doubles, by their bits' hash, */
        uint64_t bits;           /*   spelled as pt_fmt_shortest() spells them */
        unsigned char len;       /*   (trace.c: short_at) */
        char s[PT_SHORTLEN];
    } nums[1 << PT_TRACE_NUMBITS];
    char block[PT_TRACE_BLOCK];  /* buf's, unless out has put another there */
} pt_trace;

/* Prepare t to write fmt to f.  This function can't fail. */
void pt_trace_init(pt_trace *t, FILE *f, pt_format fmt, int precision);

/* Fill *l with callbacks that write to t (with t->explain: also the one that
** takes each point's journey, pt_listener.journey). */
void pt_trace_listener(pt_trace *t, pt_listener *l);

/* Write what is buffered.  Returns 0, or -1 when any write failed (why:
** t->failed). */
int pt_trace_finish(pt_trace *t);

#endif
