/*
** src/tools/accuracy/acc_float.h -- both cameras' stages and the DDA in float
** See LICENSE for copyright and license.
**
** The float run of `pipetrace accuracy` (accuracy.h): the scene's numbers
** rounded to float, then the classic camera's stages, the matrix camera's
** matrices, stages and clipping, and the DDA, each written out in float.
** Values are handed back widened to pt_dd (lo = 0).
*/
#ifndef PT_ACC_FLOAT_H
#define PT_ACC_FLOAT_H

#include "tools/accuracy/acc_shared.h"

/* The classic journey of v (model m of scene s) in float; choices: PT_ACC_TWO
** divides by 2 instead of 2.001.  This function can't fail. */
void pt_acc_float_journey(const pt_scene *s, const pt_model *m, pt_vec3 v,
                          unsigned choices, pt_acc_journey *j);

/* The DDA in float between the pixel-plane points p0 and p1 (rounded to
** float): y += m, or y = y0 + m*(x - x0) when recompute is set, for the steps
** in the viewport's band.  Returns 0, or -1 when an endpoint has no integer
** pixel (nothing drawn).  This function can't fail. */
int pt_acc_float_raster(const pt_dd p0[2], const pt_dd p1[2], int recompute,
                        const pt_acc_dda *o);

/* Fill c's float matrices (c->s set): View, Projection and every World from
** the scene's numbers rounded to float.  Returns 0, or -1 when out of memory. */
int pt_acc_float_mcam(pt_acc_mcam *c);

/* The matrix camera's journey of v_m of model k in float.  This function
** can't fail. */
void pt_acc_float_mjourney(const pt_acc_mcam *c, size_t k, pt_vec3 v_m, pt_acc_mjourney *j);

/* The segment a-b clipped in clip space in float, g->made set by the caller:
** returns 1 and fills the made ends, or 0 when culled.  This function can't
** fail. */
int pt_acc_float_mseg(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                      const pt_acc_mjourney *b, pt_acc_mseg *g);

#endif
