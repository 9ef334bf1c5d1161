/*
** src/tools/accuracy/acc_double.h -- both cameras in double: the real stages and rasterizer
** See LICENSE for copyright and license.
**
** The double run of `pipetrace accuracy` (accuracy.h) is the pipeline
** itself: the stage functions of stages/ (their reference copy, ptref_*,
** stages/pt_ref.h, so that a student build measures the formulas, not the
** student's stage), the pipeline's plan for the matrix camera's matrices,
** stages/ms_clip_segment.c's clipping and src/core/raster.c's rasterizer, called as
** they are, so its values are the reference build's trace's.  Only the
** two choices the pipeline does not make are written out here: 2 for 2.001
** (PT_ACC_TWO) and the DDA that recomputes y each step (PT_ACC_RECOMPUTE).
*/
#ifndef PT_ACC_DOUBLE_H
#define PT_ACC_DOUBLE_H

#include "tools/accuracy/acc_shared.h"

/* The double run: stages s1 .. s6 (PT_ACC_TWO: s3's formula with 2 for
** 2.001); pt_raster_segment() with o->to_vp, each step's accumulated y to
** o->step when not NULL (PT_ACC_RECOMPUTE: a DDA that computes y = y0 + m*(x
** - x0) each step instead); the pipeline's plan for the matrices; stages
** m1 .. m7, s5, s6 and pt_clip_segment() for the matrix camera. */
extern const pt_acc_ops pt_acc_double_ops;

#endif
