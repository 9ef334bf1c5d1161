/*
** stages/m7_screen2viewport.h -- matrix camera: screen -> viewport pixel
** See LICENSE for copyright and license.
**
** in : (x_s, y_s)     screen coordinates, y down, pixel centres at k + 0.5
** out: (x_vp, y_vp)   the pixel containing the point
**   x_vp = floor(x_s),  y_vp = floor(y_s)
**   inside when 0 <= x_vp < w and 0 <= y_vp < h
** Screen coordinates already point down and start at 0, so the classic
** camera's "- 1" and "h -" are not needed.  For the rasterizer, which works in
** the classic pixel plane (y up, pixels 1..w), the one mapping used is
**   x_pp = x_vp + 1,  y_pp = h - y_vp
** whose Java rounding gives back exactly (x_vp, y_vp) (both are integers);
** the rasterizer's steps come back by its inverse, pt_pixelplane2viewport(),
** x_vp = round(x_pp) - 1, y_vp = h - round(y_pp): the classic viewport
** stage's formula, kept here too so that a student's s4 (which the matrix
** camera does not trace) leaves the matrix camera's image alone
** (tests/unit/test_stages.c ties the two together).
** No value (PT_REC_NULL, out_of_range) when |x_s| or |y_s| >= 2^62 or is not a
** number.  docs/cameras.md#viewport.
*/
#ifndef PT_M7_SCREEN2VIEWPORT_H
#define PT_M7_SCREEN2VIEWPORT_H

#include "pt_mat4.h"

/* The viewport pixel of s in a w x h viewport, reported to sink (may be NULL)
** as a viewport record.  Requires w, h >= 1.  This function can't fail. */
pt_pix pt_screen2viewport(pt_vec3 s, int w, int h, const pt_sink *sink);

/* The classic pixel-plane point the rasterizer uses for viewport pixel vp of a
** viewport of height h (see above).  This function can't fail. */
pt_vec2 pt_viewport2pixelplane(pt_pix vp, int h);

/* The viewport pixel of the rasterizer's point pp, the inverse of the above,
** with the signature of a viewport stage (sink is not used; ok == 0 when a
** coordinate has no integer value).  This function can't fail. */
pt_pix pt_pixelplane2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink);

#endif
