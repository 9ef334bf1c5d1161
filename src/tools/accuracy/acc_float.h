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

/* The float run: the classic journey (choices: PT_ACC_TWO divides by 2, not
** 2.001), the DDA on the ends rounded to float (y += m, or with
** PT_ACC_RECOMPUTE y = y0 + m*(x - x0) each step), the matrices from the
** scene's numbers rounded to float, the matrix camera's journey and clipping. */
extern const pt_acc_ops pt_acc_float_ops;

#endif
