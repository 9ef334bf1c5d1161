/*
** stages/s2_camera2image.h -- camera coordinates -> image plane (projection)
** See LICENSE for copyright and license.
**
** in : (x_c, y_c, z_c)       a point in camera coordinates
** out: (x_ip, y_ip, z_ip)    its projection; the view rectangle is [-1,1] x [-1,1]
**   perspective:  x_ip = x_c / -z_c,  y_ip = y_c / -z_c,  z_ip = -1
**   orthographic: x_ip = x_c,         y_ip = y_c,         z_ip = 0
** Similar triangles in the xz-plane (lengths are positive, hence -z_c):
**
**        x |          + (x_c, z_c)         x_ip     x_c
**     x_ip +     +    |                    ----  =  ----
**          |  +  |    |                     1       -z_c
**          +-----+----+----> -z
**          0    -1   z_c
**
** A point behind the camera (z_c > 0) is still projected, mirrored through the
** origin; the record then carries PT_REC_BEHIND.  Full derivation:
** docs/stages.md#s2.
** Warnings: nonfinite (z_c = 0, overflow), ill_conditioned (z_c is tiny next
** to the operands it came from, so most of its digits, and of the quotient's,
** are rounding error).
*/
#ifndef PT_S2_CAMERA2IMAGE_H
#define PT_S2_CAMERA2IMAGE_H

#include "pt_stage.h"

/* Project c (perspective when perspective != 0, else orthographic) and report the
** image record to sink (may be NULL).  z_scale is the largest magnitude z_c was
** computed from (max(|z_m|, |z_t|); |z_c| itself when z_c is exact): it tells
** how many of z_c's digits are real.  z_c = 0 gives infinities or NaN, as the
** formula does.  This function can't fail. */
pt_vec3 pt_camera2image(pt_vec3 c, double z_scale, int perspective, const pt_sink *sink);

#endif
