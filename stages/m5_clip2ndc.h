/*
** stages/m5_clip2ndc.h -- matrix camera: clip space -> normalised device coordinates
** See LICENSE for copyright and license.
**
** in : (x_k, y_k, z_k, w_k)   a point in clip space, inside the CVV (w_k > 0)
** out: (x_n, y_n, z_n)        the homogeneous divide
**   x_n = x_k / w_k,  y_n = y_k / w_k,  z_n = z_k / w_k
** This is where the perspective happens: w_k = z_v, so dividing by it shrinks
** far points toward the centre.  Inside the CVV the result lies in the cube
** [-1,1] x [-1,1] x [0,1].  Points outside the CVV are clipped before they
** reach this stage (stages/ms_clip_segment.c), so w_k > 0 here.  w_scale is the magnitude
** w_k was computed from (stages/pt_matrix.c); when w_k is far smaller, it lost the
** digits of the difference, the quotients lost them too, and the record is
** flagged `ill_conditioned`, as in the classic projection.  docs/cameras.md#ndc.
*/
#ifndef PT_M5_CLIP2NDC_H
#define PT_M5_CLIP2NDC_H

#include "pt_mat4.h"

/* Return (x/w, y/w, z/w) and report the ndc record to sink (may be NULL).
** This function can't fail (w = 0 gives infinities, flagged nonfinite). */
pt_vec3 pt_clip2ndc(pt_vec4 k, double w_scale, const pt_sink *sink);

#endif
