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

/* The reference run: the classic journey, the exact line between the ends
** rounded exactly, the matrices with bounds on their rounding, the matrix
** camera's journey (with bounds on the clip coordinates' rounding, j->kerr)
** and clipping, all in double-double. */
extern const pt_acc_ops pt_acc_dd_ops;

#endif
