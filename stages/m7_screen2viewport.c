/*
** stages/m7_screen2viewport.c -- matrix camera: screen -> viewport pixel
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include <math.h>
#include "m7_screen2viewport.h"
#include "pt_round.h"

pt_pix pt_screen2viewport(pt_vec3 s, int w, int h, const pt_sink *sink)
{
    pt_pix vp = {0, 0, 0};
    pt_vrec r = {0};

    assert(w > 0 && h > 0);
    if (fabs(s.x) < PT_PIX_LIMIT && fabs(s.y) < PT_PIX_LIMIT) {  /* false for NaN */
        vp.x = (int64_t)floor(s.x);         /* x_vp = floor(x_s) */
        vp.y = (int64_t)floor(s.y);         /* y_vp = floor(y_s) */
        vp.ok = 1;
    }
    r.stage = PT_STAGE_VIEWPORT;
    if (!vp.ok) { r.flags |= PT_REC_NULL; r.warn |= PT_WARN_RANGE; }
    else if (pt_inside(vp.x, vp.y, w, h)) r.flags |= PT_REC_INSIDE;
    r.ix = vp.x; r.iy = vp.y;
    pt_emit(sink, &r);
    return vp;
}

pt_vec2 pt_viewport2pixelplane(pt_pix vp, int h)
{
    pt_vec2 p;

    p.x = (double)(vp.x + 1);               /* x_pp = x_vp + 1 */
    p.y = (double)(h - vp.y);               /* y_pp = h - y_vp */
    return p;
}

pt_pix pt_pixelplane2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    pt_pix vp = {0, 0, 0};
    int64_t rx, ry;

    (void)w; (void)sink;
    if (pt_pix_round(pp.x, &rx) && pt_pix_round(pp.y, &ry)) {
        vp.x = rx - 1;                      /* x_vp = round(x_pp) - 1 */
        vp.y = h - ry;                      /* y_vp = h - round(y_pp) */
        vp.ok = 1;
    }
    return vp;
}
