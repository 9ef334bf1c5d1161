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
    int has = (fabs(s.x) < PT_PIX_LIMIT) | (fabs(s.y) < PT_PIX_LIMIT) << 1;  /* 0 for NaN */

    assert(w > 0 && h > 0);
    if (has & 1) vp.x = (int64_t)floor(s.x);   /* x_vp = floor(x_s) */
    if (has & 2) vp.y = (int64_t)floor(s.y);   /* y_vp = floor(y_s) */
    vp = pt_pix_mark(vp, has);              /* null per value */
    pt_emit_viewport(sink, vp, w, h);       /* record: null, inside or outside */
    return vp;
}

pt_vec2 pt_viewport2pixelplane(pt_pix vp, int h)
{
    pt_vec2 p;

    p.x = (double)(vp.x + 1);               /* x_pp = x_vp + 1 */
    p.y = (double)(h - vp.y);               /* y_pp = h - y_vp */
    return p;
}

/* s4's formula, written as the inverse of pt_viewport2pixelplane() above:
** round each coordinate, then undo x_pp = x_vp + 1 and y_pp = h - y_vp.  It
** reports nothing (sink is not used). */
pt_pix pt_pixelplane2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    pt_pix vp = {0, 0, 0};
    int64_t r[2];                           /* round(x_pp), round(y_pp) */

    (void)w; (void)sink;
    vp.ok = pt_pix_round(pp.x, &r[0]) && pt_pix_round(pp.y, &r[1]);
    if (vp.ok) {
        vp.x = r[0] - 1;                    /* x_vp = round(x_pp) - 1 */
        vp.y = h - r[1];                    /* y_vp = h - round(y_pp) */
    }
    return vp;
}
