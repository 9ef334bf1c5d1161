/*
** stages/rv_clip.h -- renderers 7 and 9: clip the image-plane model to the view rectangle -1..1
** See LICENSE for copyright and license.  (Formula and derivation: to be written by its owner.)
*/
#ifndef PT_RV_CLIP_H
#define PT_RV_CLIP_H
#include "rv_model.h"
/* Clip m's primitives to the square in place (vertices and colours appended,
** primitive list replaced).  0, or -1 when out of memory. */
int pt_rv_clip(pt_rv_model *m, const pt_rv_clip_ls *ls);
#endif
