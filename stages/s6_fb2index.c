/*
** stages/s6_fb2index.c -- framebuffer pixel -> pixel-array index
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include "s6_fb2index.h"

int64_t pt_fb2index(pt_pix fb, int W, int H, const pt_sink *sink)
{
    int64_t idx = -1;

    assert(W > 0 && H > 0);
    if (fb.ok && pt_inside(fb.x, fb.y, W, H))
        idx = fb.y * (int64_t)W + fb.x;     /* idx = y_fb * W + x_fb */
    if (!sink) return idx;                  /* nobody listens: no record */
    pt_vrec r = {0};
    r.stage = PT_STAGE_INDEX;
    if (idx < 0) r.flags |= PT_REC_NULL;
    if (idx < 0 && fb.ok) r.warn |= PT_WARN_OUTSIDE;
    r.i = idx;
    pt_emit(sink, &r);
    return idx;
}
