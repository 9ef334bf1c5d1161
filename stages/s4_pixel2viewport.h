/*
** stages/s4_pixel2viewport.h -- logical pixel plane -> viewport pixel
** See LICENSE for copyright and license.
**
** in : (x_pp, y_pp)   a point in the logical pixel plane, y up, pixels 1..w, 1..h
** out: (x_vp, y_vp)   the physical pixel in the viewport, y down, 0-based
**   x_vp = round(x_pp) - 1
**   y_vp = h - round(y_pp)
**   inside when 0 <= x_vp < w and 0 <= y_vp < h; other pixels are clipped
** round is Java's Math.round: the nearest integer, ties toward +infinity
** (round(-2.5) = -2), exact for every double (round(0.49999999999999994) = 0,
** where floor(x + 0.5) would give 1); it lives in pt_round.h with the inside
** test, so that a student's version of this file replaces only the formula.
**
**   y_pp                             (0,0) +---------> x_vp
**   h |  . . logical pixel (m,n)           |  physical pixel
**   1 |  . .        ==>                    |  (m-1, h-n)
**     +-------> x_pp                 y_vp  v
**
** Java keeps these numbers in 32-bit ints; pipetrace keeps them in 64 bits and
** gives no pixel (PT_REC_NULL) when |x_pp| or |y_pp| >= PT_PIX_LIMIT or is not a
** number (null per value: the other coordinate keeps its value; pt_pix_has()),
** with the warning out_of_range (Java's (int) cast wraps from 2^31 on,
** and Math.round itself saturates from 2^63).  docs/stages.md#s4.
*/
#ifndef PT_S4_PIXEL2VIEWPORT_H
#define PT_S4_PIXEL2VIEWPORT_H

#include "pt_stage.h"
#include "pt_round.h"

/* Find the viewport pixel of pp in a w x h viewport and report the viewport record
** to sink (may be NULL).  The result has ok == 0 when either coordinate has no
** integer value.  Requires w, h >= 1.  This function can't fail. */
pt_pix pt_pixel2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink);

#endif
