/*
** stages/m3_view2clip.h -- matrix camera: view coordinates -> clip space
** See LICENSE for copyright and license.
**
** in : (x_v, y_v, z_v, 1)     a point in view coordinates
** out: (x_k, y_k, z_k, w_k)   homogeneous clip coordinates
**   x_k = x_v * cot(fov/2) / aspect
**   y_k = y_v * cot(fov/2)
**   z_k = z_v * f/(f-n) - f*n/(f-n)
**   w_k = z_v
** Dividing by w_k later gives the perspective: a point twice as far is half as
** far from the centre.  cot(fov/2) scales the view frustum's sides to x = +-w,
** y = +-w; z_k is chosen linear in z_v with z_k = 0 at z_v = n and z_k = w_k at
** z_v = f, so after the divide the depth runs from 0 (near) to 1 (far):
**
**        \  visible  /         n*f/(f-n) - f*n/(f-n) = 0       (near -> 0)
**     ----\---------/---- f    f*f/(f-n) - f*n/(f-n) = f = w_k  (far  -> 1)
**          \       /
**        ---\-----/--- n
**            \ . / eye
** A point close to the near plane cancels most of z_k (z_v f/(f-n) against
** f n/(f-n)): flagged `cancellation`.  docs/cameras.md#clip.
*/
#ifndef PT_M3_VIEW2CLIP_H
#define PT_M3_VIEW2CLIP_H

#include "pt_mat4.h"

/* Return v * proj and report the clip record to sink (may be NULL).  This
** function can't fail. */
pt_vec4 pt_view2clip(pt_vec4 v, const pt_mat4 *proj, const pt_sink *sink);

#endif
