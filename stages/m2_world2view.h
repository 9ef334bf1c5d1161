/*
** stages/m2_world2view.h -- matrix camera: world coordinates -> view coordinates
** See LICENSE for copyright and license.
**
** in : (x_w, y_w, z_w, w_w)   a point in world coordinates
** out: (x_v, y_v, z_v, w_v)   the same point seen from the camera
**   (x_v y_v z_v w_v) = (x_w y_w z_w w_w) * View
**   View: columns h, u, d (horizontal, up, direction, unit vectors), last row
**         (-eye.h, -eye.u, -eye.d, 1)
** Moving the eye to the origin and turning h, u, d onto the x, y, z axes is the
** same as taking the dot product of (p - eye) with each of them:
**
**   x_v = (p - eye) . h      y_v = (p - eye) . u      z_v = (p - eye) . d
**
**        u |  / d            z_v > 0: in front of the camera
**          | /               (left-handed: x right, y up, z forward)
**      eye +----- h
**
** Built by pt_lookat() (pt_mat4.h).  A point close to the eye compared with
** their distances from the origin cancels most of p - eye: flagged
** `cancellation`.  docs/cameras.md#view.
*/
#ifndef PT_M2_WORLD2VIEW_H
#define PT_M2_WORLD2VIEW_H

#include "pt_mat4.h"

/* Return p * view and report the view record to sink (may be NULL).  This
** function can't fail. */
pt_vec4 pt_world2view(pt_vec4 p, const pt_mat4 *view, const pt_sink *sink);

#endif
