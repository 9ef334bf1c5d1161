/*
** stages/rv_nearclip.h -- renderers 7 and 9: clip the camera-space model at the near plane z = n
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_RV_NEARCLIP_H
#define PT_RV_NEARCLIP_H
#include "rv_model.h"
/* Clip m's primitives at z = n in place: new vertices and colours appended,
** the primitive list replaced.  0, or -1 when out of memory. */
int pt_rv_nearclip(pt_rv_model *m, double n, const pt_rv_clip_ls *ls);
#endif
