/*
** src/core/clip.h -- clip a segment against the canonical view volume, before the divide
** See LICENSE for copyright and license.
**
** The matrix camera clips in clip space, where every plane of the CVV is linear
** in (x, y, z, w): the signed distances d_i (stages/m4_clip2cvv.h) change
** linearly along a segment P(t) = P0 + t (P1 - P0), so each plane cuts the
** segment at t = d0 / (d0 - d1).  Liang and Barsky's method keeps the largest t
** where the segment enters a plane and the smallest where it leaves one; if
** enter <= leave, the piece [enter, leave] is inside the volume.  Because this
** happens before dividing by w, a point behind the eye (w < 0) is cut off at the
** near plane instead of being flipped into view.
*/
#ifndef PT_CLIP_H
#define PT_CLIP_H

#include "stages/pt_mat4.h"

/* Clip p0-p1 against the CVV.  Returns 0 when nothing of it is inside; else 1
** with *t0 <= *t1 the visible piece's parameters (0 and 1 when an endpoint
** is inside) and *q0, *q1 its endpoints.  This function can't fail. */
int pt_clip_segment(pt_vec4 p0, pt_vec4 p1, double *t0, double *t1,
                    pt_vec4 *q0, pt_vec4 *q1);

/* p0 + t (p1 - p0), component by component.  This function can't fail. */
pt_vec4 pt_clip_lerp(pt_vec4 p0, pt_vec4 p1, double t);

#endif
