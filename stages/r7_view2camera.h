/*
** stages/r7_view2camera.h -- renderer 7, stage 2: view -> camera (normalize the view volume)
** See LICENSE for copyright and license.
**
** in : (x_v, y_v, z_v)  view coordinates; the camera's view rectangle l..r,
**                       b..t sits at z = -1 (perspective) or is the volume's
**                       cross-section (orthographic)
** out: (x_c, y_c, z_c)  camera coordinates: the rectangle becomes -1..1
**   perspective:  x = x_v + (z_v*(r+l))/2.0;   x_c = (2.0*x)/(r-l)   (y: t, b)
**   orthographic: x = x_v - (r+l)/2.0;         x_c = (2.0*x)/(r-l)
**   z_c = z_v
** Derivation: the skew x + z*(r+l)/2 moves the rectangle's centre (r+l)/2 at
** z = -1 to x = 0 (the line through the origin and the centre becomes the
** -z axis); scaling by 2/(r-l) makes the half-width 1.  The orthographic
** volume is a box: translate its centre to 0, then scale the same way.
**      l      r                -1      1
**      +------+ z=-1    ==>     +------+ z=-1
**       \    /                  |\    /|
**        \  /  (skewed)          | \  / |
**          o                         o
** Java: View2Camera.java:175-202; `v_z * (r + l)/2.0` parses as
** (v_z*(r+l))/2.0, and 2.0*x is divided by (r-l), not multiplied by
** 2/(r-l): renderer 9's matrix rounds differently (r9_view2camera.h).
*/
#ifndef PT_R7_VIEW2CAMERA_H
#define PT_R7_VIEW2CAMERA_H
#include "rv_model.h"
/* v in camera coordinates for cam (its perspective, l, r, b, t); w = 1.
** This function can't fail (a flat rectangle gives infinities or NaN, as in Java). */
pt_vec4 pt_r7_view2camera(pt_vec4 v, const pt_rv_camera *cam);
/* The stage on a whole model: each of the n vertices v[k] in place, as the
** course's stages take whole models (the loop here, where the compiler sees
** the formula above and passes no vertex through memory).  This function
** can't fail. */
void pt_r7_view2camera_all(pt_vec4 *v, size_t n, const pt_rv_camera *cam);
/* Its first half, the x and y before the scaling: the skew (perspective) or
** the translation (orthographic); z and w as the result's.  pipetrace step
** shows it.  This function can't fail. */
pt_vec4 pt_r7_view2camera_shift(pt_vec4 v, const pt_rv_camera *cam);
#endif
