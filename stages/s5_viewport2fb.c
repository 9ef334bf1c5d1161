/*
** stages/s5_viewport2fb.c -- viewport pixel -> framebuffer pixel
** See LICENSE for copyright and license.
*/
#include "s5_viewport2fb.h"

pt_pix pt_viewport2fb(pt_pix vp, int x_ul, int y_ul, const pt_sink *sink)
{
    pt_pix fb = {0, 0, 0};

    if (vp.ok) {
        fb.x = x_ul + vp.x;                 /* x_fb = x_ul + x_vp */
        fb.y = y_ul + vp.y;                 /* y_fb = y_ul + y_vp */
        fb.ok = 1;
    }
    if (!sink) return fb;                   /* nobody listens: no record */
    pt_vrec r = {0};
    r.stage = PT_STAGE_FRAMEBUFFER;
    if (!fb.ok) r.flags |= PT_REC_NULL;
    r.ix = fb.x; r.iy = fb.y;
    pt_emit(sink, &r);
    return fb;
}
