/*
** stages/s5_viewport2fb.h -- viewport pixel -> framebuffer pixel
** See LICENSE for copyright and license.
**
** in : (x_vp, y_vp)   a pixel in viewport coordinates, (0,0) = its upper-left
** out: (x_fb, y_fb)   the same pixel in framebuffer coordinates
**   x_fb = x_ul + x_vp       (x_ul, y_ul): the viewport's upper-left corner
**   y_fb = y_ul + y_vp       in the framebuffer
**
**   (0,0) +-------------------------+ framebuffer
**         |  (x_ul,y_ul) +-------+  |
**         |              | (x_vp,|  |   x_fb = x_ul + x_vp
**         |              |  y_vp)|  |   y_fb = y_ul + y_vp
**         |              +-------+  |
**         +-------------------------+
**
** The formula is applied even to a pixel outside the viewport: that is how a
** missing clip test puts pixels next to the viewport.  docs/stages.md#s5.
*/
#ifndef PT_S5_VIEWPORT2FB_H
#define PT_S5_VIEWPORT2FB_H

#include "pt_stage.h"

/* Offset vp by the viewport corner (x_ul, y_ul) and report the framebuffer record
** to sink (may be NULL).  A vp without pixel (ok == 0) gives none either; a
** coordinate of it that has a value (pt_pix_has()) is still offset.
** Requires |vp.x|, |vp.y| < 2^62 (s4 guarantees it).  This function can't fail. */
pt_pix pt_viewport2fb(pt_pix vp, int x_ul, int y_ul, const pt_sink *sink);

#endif
