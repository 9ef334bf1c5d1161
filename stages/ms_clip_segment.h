/*
** stages/ms_clip_segment.h -- the matrix camera's segment stage: clip to the view volume
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
**
** As a segment stage (pt_segment.h), it runs after m4 (the outcode): a segment
** whose ends are both inside goes on as it is; otherwise the ends outside are
** replaced by the points where it enters and leaves the volume, each with its
** t and the colour interpolated at t; nothing of it inside drops it.
**
**        enter                leave         P(t) = P0 + t (P1 - P0)
**   P0 ----+======================+---- P1  c(t) = c0 + t (c1 - c0)  (float)
**     outside    inside the CVV    outside
*/
#ifndef PT_MS_CLIP_SEGMENT_H
#define PT_MS_CLIP_SEGMENT_H

#include "pt_mat4.h"
#include "pt_segment.h"

/* Clip p0-p1 against the CVV.  Returns 0 when nothing of it is inside; else 1
** with *t0 <= *t1 the visible piece's parameters (0 and 1 when an endpoint
** is inside) and *q0, *q1 its endpoints.  This function can't fail. */
int pt_clip_segment(pt_vec4 p0, pt_vec4 p1, double *t0, double *t1,
                    pt_vec4 *q0, pt_vec4 *q1);

/* p0 + t (p1 - p0), component by component.  This function can't fail. */
pt_vec4 pt_clip_lerp(pt_vec4 p0, pt_vec4 p1, double t);

/* The colour at t of a segment from c0 to c1: c0 + t (c1 - c0), in float with
** t rounded to float first.  This function can't fail. */
pt_rgb pt_clip_color(pt_rgb c0, pt_rgb c1, double t);

/* The segment stage: ends a and b in clip space (h), with their outcodes
** (code) and colours.  Returns PT_CUT_KEEP when both are inside,
** PT_CUT_DROP when nothing of the segment is, else PT_CUT_NEW with made[e]
** (stage PT_STAGE_CVV, end e, t, q, colour) for each end e outside
** (moved[e] = 1).  This function can't fail. */
pt_cut pt_clip_cut(const pt_segend *a, const pt_segend *b, pt_made made[2], int moved[2]);

#endif
