/*
** src/tools/accuracy/acc_double.h -- both cameras in double: the real stages and rasterizer
** See LICENSE for copyright and license.
**
** The double run of `pipetrace accuracy` (accuracy.h) is the pipeline
** itself: the stage functions of stages/, the pipeline's plan for the matrix
** camera's matrices, src/core/clip.c's clipping and src/core/raster.c's
** rasterizer, called as they are, so its values are the trace's.  Only the
** two choices the pipeline does not make are written out here: 2 for 2.001
** (PT_ACC_TWO) and the DDA that recomputes y each step (PT_ACC_RECOMPUTE).
*/
#ifndef PT_ACC_DOUBLE_H
#define PT_ACC_DOUBLE_H

#include "tools/accuracy/acc_shared.h"

/* The classic journey of v (model m of scene s): stages s1 .. s6 (with
** PT_ACC_TWO, s3's formula with 2 for 2.001).  This function can't fail. */
void pt_acc_double_journey(const pt_scene *s, const pt_model *m, pt_vec3 v,
                           unsigned choices, pt_acc_journey *j);

/* The segment p0-p1 of the pixel plane: pt_raster_segment() with o->to_vp,
** its pixels to o->pixel, and each step's accumulated y to o->step (when not
** NULL); with recompute, a DDA that computes y = y0 + m*(x - x0) each step.
** Returns 0, or -1 when an endpoint has no integer pixel (nothing drawn).
** This function can't fail. */
int pt_acc_double_raster(const pt_dd p0[2], const pt_dd p1[2], int recompute,
                         const pt_acc_dda *o);

/* Fill c's double matrices (c->s set): the pipeline's plan of the scene.
** Returns 0, or -1 when out of memory. */
int pt_acc_double_mcam(pt_acc_mcam *c);

/* The matrix camera's journey of v_m of model k: stages m1 .. m7, s5, s6.
** This function can't fail. */
void pt_acc_double_mjourney(const pt_acc_mcam *c, size_t k, pt_vec3 v_m, pt_acc_mjourney *j);

/* The segment a-b clipped by pt_clip_segment(), g->made set by the caller:
** returns 1 and fills the made ends, or 0 when culled.  This function can't
** fail. */
int pt_acc_double_mseg(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                       const pt_acc_mjourney *b, pt_acc_mseg *g);

#endif
