/*
** stages/m4_clip2cvv.h -- matrix camera: clip space -> the CVV outcode
** See LICENSE for copyright and license.
**
** in : (x_k, y_k, z_k, w_k)   a point in clip space
** out: code                   one bit per plane of the canonical view volume
**                             (CVV) that the point lies outside of:
**   0x01 near   z < 0          0x04 left   x < -w       0x10 bottom y < -w
**   0x02 far    z > w          0x08 right  x > w        0x20 top    y > w
** Inside the CVV, -w <= x, y <= w and 0 <= z <= w: after the divide by w that
** is the cube [-1,1] x [-1,1] x [0,1].  Testing before the divide matters:
** a point behind the eye has w < 0, and dividing would flip it into view.
** Two endpoints with a common bit lie outside the same plane: the segment is
** invisible.  docs/cameras.md#cvv.
*/
#ifndef PT_M4_CLIP2CVV_H
#define PT_M4_CLIP2CVV_H

#include "pt_mat4.h"

#define PT_CVV_NEAR    0x01u
#define PT_CVV_FAR     0x02u
#define PT_CVV_LEFT    0x04u
#define PT_CVV_RIGHT   0x08u
#define PT_CVV_BOTTOM  0x10u
#define PT_CVV_TOP     0x20u
#define PT_CVV_NPLANES 6

/* Plane names in bit order: "near", "far", "left", "right", "bottom", "top". */
extern const char *const pt_cvv_names[PT_CVV_NPLANES];

/* The outcode of k; reported to sink (may be NULL) as a record with code set
** and x y z w repeated.  A NaN coordinate sets every bit.  Can't fail. */
unsigned pt_clip2cvv(pt_vec4 k, const pt_sink *sink);

/* The signed distances of k to the six planes, inside >= 0, in bit order:
** z, w - z, w + x, w - x, w + y, w - y.  The clipper interpolates these. */
void pt_cvv_distances(pt_vec4 k, double d[PT_CVV_NPLANES]);

#endif
