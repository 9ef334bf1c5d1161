/*
** src/io/trace_course.h -- the course's debug log of renderers 7 and 9 (--format kraft)
** See LICENSE for copyright and license.
**
** The course's renderers 7 and 9 print, on System.err, what their
** PipelineLogger and stages log while Pipeline.render (or renderer 9's
** Pipeline2.render) runs: the camera, each position's translation or
** matrix, every stage's vertex, colour and primitive lists, each clip stage's
** primitives one by one, each primitive the rasterizer draws, and the
** warnings.  This module writes that log byte for byte, listening to the
** driver (core/course.h).  Which lines appear follows the course's flags,
** the PT_KDBG_* bits of io/trace_kraft.h:
**   scene.debug or Position.debug   every line but those below (the
**                                   warnings are printed always)
**     + Clip.debug                  the clip stages' "-- ..." lines
**     + Rasterize.debug             the rasterizer's lines (io/rv_log_raster.h)
** Numbers are spelled as Java spells them (io/jnum.h).
*/
#ifndef PT_TRACE_COURSE_H
#define PT_TRACE_COURSE_H

#include <stdio.h>
#include "core/pipetrace.h"
#include "io/trace.h"

/* How the log or the trace is written: on one thread, or on two (io/tlanes.h:
** a second render with no pixels to write, the driver's pieces shared, the
** same bytes as on one; the second render runs the rasterizer on the
** primitives of its own pieces only). */
typedef struct pt_course_cuts {
    int threads;                 /* 2: two threads, when a second is to be had */
    uint64_t vertices, prims, pixels;   /* the pieces' sizes (pt_course_ls.piece_*):
                                 ** 0 for the driver's default */
    uint64_t taken[2];           /* out: the pieces each thread wrote */
    pt_course_tally tally[2];    /* out: each thread's primitives, those of its
                                 ** pieces and those it drew (the second draws
                                 ** only its pieces') */
    int failed;                  /* out: the errno value of the first write to f
                                 ** that failed, or 0 (then ferror(f) tells) */
} pt_course_cuts;

/* Render s (renderer 7 or 9) into fb (s->fb_w x s->fb_h) and write its log
** to f with the course's flags dbg (PT_KDBG_*).  Returns 0; or -1 with a
** message in err when out of memory, or, with the rasterizer's lines, when
** a point the rasterizer gets has more pixels than a point's pixel log may
** have (pt_kraft_point_check, the rule of renderer 4's log: checked before
** anything is written).  A segment's lines need no such rule: the clip
** stage keeps its ends in the view rectangle (or NaN, which rounds to 0), so
** it has at most the viewport's width or height plus one.  cuts: on one
** thread or two (NULL: one).  Write errors show in ferror(f). */
int pt_course_log(FILE *f, const pt_scene *s, unsigned dbg, pt_course_cuts *cuts,
                  pt_fb *fb, char *err, size_t errlen);

/* Render s (renderer 7 or 9) into fb and write pipetrace's trace of it to f
** in format fmt (PT_FORMAT_TEXT, _JSONL or _CSV; text with precision digits
** after the point): each stage's vertices, the clip stages' new vertices
** with where they came from, the pixels (docs/trace-format.md).  With
** explain (text and jsonl), each vertex record also gets its stage's formula
** with its numbers put in (io/explain_course.h).  cuts: on one thread or
** two (NULL: one).  Returns 0; or -1 with a message in err when out of
** memory.  Write errors show in ferror(f). */
int pt_course_trace(FILE *f, const pt_scene *s, int fmt, int precision, int explain,
                    pt_course_cuts *cuts, pt_fb *fb, char *err, size_t errlen);

/* ===== for the two writers above ===== */

/* A writer's lane: the first member of each writer's state. */
typedef struct pt_course_lane {
    pt_trace *t;                 /* the writer's block */
    int taken;                   /* 1: the piece going on is its (io/tlanes.h) */
    uint64_t pieces;             /* the pieces it wrote */
    const pt_course_cuts *cuts;  /* NULL: one thread, every piece its */
    int skips;                   /* 1: draws only its pieces' primitives */
    pt_course_tally tally;       /* its primitives, counted */
} pt_course_lane;

/* With ln->cuts, set ls to cut the render where they say, to ask ln's lane
** whether each piece is its (ls->ud: the writer's state, which begins with
** ln), to skip the rasterizer for the others' pieces when ln->skips, and
** to count into ln->tally.  This function can't fail. */
void pt_course_lane_ls(pt_course_ls *ls, pt_course_lane *ln);

/* Render s on two threads (io/tlanes.h) as cuts says, lane k calling
** walk(w[k], fb_k) (its header, its render with pt_course_lane_ls, its
** summary), w[k] a writer's state that begins with its pt_course_lane (t
** set, nothing written), fb_0 = fb and fb_1 of fb's size with no pixels
** (rgb NULL: lane 1 runs the rasterizer on the primitives of its own
** pieces only and writes nothing; lane 0 draws them all); the pieces each
** wrote into cuts->taken, the primitives each counted into cuts->tally.
** Returns 0, -1 when a walk did, or 1 when no second thread is to be had:
** nothing has run. */
int pt_course_lanes(const pt_scene *s, pt_fb *fb, pt_course_cuts *cuts,
                    int (*walk)(void *w, pt_fb *fb), void *const w[2]);

#endif
