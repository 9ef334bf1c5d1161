/*
** stages/s6_fb2index.h -- framebuffer pixel -> pixel-array index
** See LICENSE for copyright and license.
**
** in : (x_fb, y_fb)   a pixel of a W x H framebuffer, (0,0) = top-left
** out: idx            its position in the row-major pixel array int[W*H]
**   idx = y_fb * W + x_fb       (64-bit; W is the framebuffer's width)
**
**   row 0:     idx 0       1     ...  W-1
**   row 1:     idx W       W+1   ...  2W-1
**   row y_fb:  idx y_fb*W  ...  y_fb*W + x_fb  ...
**
** A pixel outside the framebuffer has no index (PT_REC_NULL): the formula would
** name some other pixel, or one past the array's end; the record carries the
** warning outside_pixel_array.  docs/stages.md#s6.
*/
#ifndef PT_S6_FB2INDEX_H
#define PT_S6_FB2INDEX_H

#include "pt_stage.h"
#include "pt_round.h"

/* Return the index of fb in a W x H framebuffer, or -1 when fb has no value or
** lies outside; report the index record to sink (may be NULL).  Requires
** 1 <= W, H.  This function can't fail. */
int64_t pt_fb2index(pt_pix fb, int W, int H, const pt_sink *sink);

#endif
