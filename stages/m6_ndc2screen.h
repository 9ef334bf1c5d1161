/*
** stages/m6_ndc2screen.h -- matrix camera: NDC -> screen coordinates
** See LICENSE for copyright and license.
**
** in : (x_n, y_n, z_n)   normalised device coordinates, y up
** out: (x_s, y_s, z_s)   screen coordinates of a w x h viewport, y DOWN
**   x_s = (x_n + 1) * w * 0.5
**   y_s = (1 - y_n) * h * 0.5
**   z_s = z_n
** The line through x_n = -1 -> 0 and x_n = 1 -> w; for y the same, flipped so
** that y_n = 1 (top) lands on row 0.  Pixel (i, j) covers i <= x_s < i + 1,
** j <= y_s < j + 1: its centre is at (i + 0.5, j + 0.5).  No 2.001 here: the
** right edge x_s = w belongs to no pixel of the viewport.
**
**   (-1,1) +------+ (1,1)        (0,0) +------+ (w,0)
**          |      |       ==>          |      |
**  (-1,-1) +------+ (1,-1)       (0,h) +------+ (w,h)
**
** docs/cameras.md#screen.
*/
#ifndef PT_M6_NDC2SCREEN_H
#define PT_M6_NDC2SCREEN_H

#include "pt_mat4.h"

/* Map n to the screen of a w x h viewport and report the screen record to sink
** (may be NULL).  Requires w, h >= 1.  This function can't fail. */
pt_vec3 pt_ndc2screen(pt_vec3 n, int w, int h, const pt_sink *sink);

#endif
