/*
** stages/pt_segment.h -- segment stages: what they take and what they give back
** See LICENSE for copyright and license.
**
** A vertex stage maps one point to the next space; a segment stage takes a
** whole segment, between the vertex stages and the rasterizer, and gives back
** nothing (dropped), the segment as it is, or the segment with new end
** points.  Each new point says where it came from: the stage that made it,
** its segment, which end it replaces, the parameter t along the segment, its
** coordinates, and its colour interpolated at t.  The driver then takes the
** new point through the stages that follow (core/pipelines.h).
**
**   a ----------------- b      keep:  a ----------------- b
**        | the cut |           new:        m0 ------ m1     (t0, t1)
**                              drop:  (nothing)
*/
#ifndef PT_SEGMENT_H
#define PT_SEGMENT_H

#include <stdint.h>
#include "pt_stage.h"
#include "pt_mat4.h"

/* One end of a segment as a segment stage sees it. */
typedef struct pt_segend {
    pt_vec4 h;                   /* its coordinates in the stage's space */
    unsigned code;               /* its runner's code (matrix: CVV outcode) */
    pt_rgb color;                /* its colour */
} pt_segend;

/* A point a segment stage made: where it lies and where it came from. */
typedef struct pt_made {
    pt_stage stage;              /* the stage whose space it was made in */
    uint64_t seg;                /* the segment's 1-based number in its model */
    uint64_t from, to;           /* the segment's 1-based end vertices */
    int end;                     /* 0: it replaces the first end, 1: the last */
    double t;                    /* along the segment: P(t) = P0 + t (P1 - P0) */
    pt_vec4 q;                   /* its coordinates in that space */
    pt_rgb color;                /* its colour, interpolated at t */
} pt_made;

/* What a segment stage does with a segment. */
typedef enum pt_cut {
    PT_CUT_DROP,                 /* nothing of it goes on */
    PT_CUT_KEEP,                 /* it goes on as it is */
    PT_CUT_NEW                   /* one or both ends are new points */
} pt_cut;

/* A segment stage: ends a and b in, PT_CUT_* out; with PT_CUT_NEW, made[e]
** for each end e with moved[e] set (the driver fills seg, from and to). */
typedef pt_cut (*pt_segstage_fn)(const pt_segend *a, const pt_segend *b,
                                 pt_made made[2], int moved[2]);

#endif
