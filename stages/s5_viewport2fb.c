/*
** stages/s5_viewport2fb.c -- viewport pixel -> framebuffer pixel
** See LICENSE for copyright and license.
*/
#include "s5_viewport2fb.h"

pt_pix pt_viewport2fb(pt_pix vp, int x_ul, int y_ul, const pt_sink *sink)
{
    pt_pix fb = {0, 0, 0};

    if (pt_pix_has(vp, 0) || pt_pix_has(vp, 1)) {  /* one without value: none */
        fb.x = pt_pix_has(vp, 0) ? x_ul + vp.x : PT_PIX_NONE;  /* x_fb = x_ul + x_vp */
        fb.y = pt_pix_has(vp, 1) ? y_ul + vp.y : PT_PIX_NONE;  /* y_fb = y_ul + y_vp */
        fb.ok = vp.ok;
    }
    if (!sink) return fb;                   /* nobody listens: no record */
    pt_vrec r = {0};
    r.stage = PT_STAGE_FRAMEBUFFER;
    r.flags = pt_pix_flags(fb);             /* null per value */
    r.ix = pt_pix_has(fb, 0) ? fb.x : 0;
    r.iy = pt_pix_has(fb, 1) ? fb.y : 0;
    pt_emit(sink, &r);
    return fb;
}
