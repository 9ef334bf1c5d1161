/*
** stages/s3_image2pixel.h -- image plane -> logical pixel plane
** See LICENSE for copyright and license.
**
** in : (x_ip, y_ip)   view rectangle [-1,1] x [-1,1]
** out: (x_pp, y_pp)   logical viewport [0.5, w+0.5) x [0.5, h+0.5)
**   x_pp = 0.5 + w/2.001 * (x_ip + 1)      w, h: the viewport's size in pixels
**   y_pp = 0.5 + h/2.001 * (y_ip + 1)
** The line through (-1, 0.5) and (1, w+0.5) is x_pp = 0.5 + w/2 * (x_ip + 1).
** The code divides by 2.001 instead of 2 so that x_ip = 1 lands just short of
** w + 0.5 and still rounds to pixel w, for w up to 2001 (beyond, w/2.001 * 2
** falls a whole pixel short: docs/stages.md) (Blinn, "A Trip Down the Graphics
** Pipeline", 1996, p. 142).  The order of operations is the formula's:
** (w / 2.001) first, then times (x_ip + 1), then plus 0.5.
**
**   (-1,1) +-------+ (1,1)        (0.5,h+.5) +-----------+ (w+.5,h+.5)
**          |   .   |      ==>                | . . . . . |
**  (-1,-1) +-------+ (1,-1)        (0.5,0.5) +-----------+ (w+.5,0.5)
**
** Logical pixels are the points with integer coordinates.  docs/stages.md#s3.
** Warning: nonfinite (an infinite x_ip, or overflow for |x_ip| near 1e308).
*/
#ifndef PT_S3_IMAGE2PIXEL_H
#define PT_S3_IMAGE2PIXEL_H

#include "pt_stage.h"

/* The divisor of the formula: 2.001, not 2 (Blinn, "A Trip Down the Graphics
** Pipeline", 1996, p. 142; see above).  s3_image2pixel.c writes the number
** itself, so that a student's copy shows the whole formula; the tools that
** recompute the formula (src/tools/catalogue.c) use this name. */
#define PT_PIXEL_DIVISOR 2.001

/* Map (ip.x, ip.y) into the pixel plane of a w x h viewport and report the pixel
** record to sink (may be NULL).  Requires w, h >= 1.  This function can't fail. */
pt_vec2 pt_image2pixel(pt_vec3 ip, int w, int h, const pt_sink *sink);

#endif
