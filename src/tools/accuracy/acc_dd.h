/*
** src/tools/accuracy/acc_dd.h -- both cameras' stages and the DDA in double-double: the reference
** See LICENSE for copyright and license.
**
** The reference run of `pipetrace accuracy` (accuracy.h describes its
** semantics): the classic camera's stages, the matrix camera's matrices (with
** bounds on their rounding), stages and clipping, and the exact line the DDA
** approximates, each written out in double-double.
*/
#ifndef PT_ACC_DD_H
#define PT_ACC_DD_H

#include "tools/accuracy/acc_shared.h"

/* The classic journey of v (model m of scene s) in double-double.  This
** function can't fail. */
void pt_acc_dd_journey(const pt_scene *s, const pt_model *m, pt_vec3 v, pt_acc_journey *j);

/* The exact line between the pixel-plane points p0 and p1 (rounded exactly),
** for the steps in the viewport's band.  Returns 0, or -1 when an endpoint has
** no integer pixel (nothing drawn).  This function can't fail. */
int pt_acc_dd_raster(const pt_dd p0[2], const pt_dd p1[2], const pt_acc_dda *o);

/* Fill c's double-double matrices and their error bounds (c->s set).
** Returns 0, or -1 when out of memory. */
int pt_acc_dd_mcam(pt_acc_mcam *c);

/* The matrix camera's journey of v_m of model k in double-double, with
** bounds on the clip coordinates' rounding (j->kerr).  This function can't
** fail. */
void pt_acc_dd_mjourney(const pt_acc_mcam *c, size_t k, pt_vec3 v_m, pt_acc_mjourney *j);

/* The segment a-b clipped in clip space in double-double, g->made set by the
** caller: returns 1 and fills the made ends, or 0 when culled.  This function
** can't fail. */
int pt_acc_dd_mseg(const pt_acc_mcam *c, const pt_acc_mjourney *a,
                   const pt_acc_mjourney *b, pt_acc_mseg *g);

#endif
