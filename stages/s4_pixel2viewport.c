/*
** stages/s4_pixel2viewport.c -- logical pixel plane -> viewport pixel
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include "s4_pixel2viewport.h"

pt_pix pt_pixel2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    pt_pix vp;
    int64_t rx, ry;
    int has;

    assert(w > 0 && h > 0);
    has = pt_pix_round(pp.x, &rx) | pt_pix_round(pp.y, &ry) << 1;
    vp.x = rx - 1;                          /* x_vp = round(x_pp) - 1 */
    vp.y = h - ry;                          /* y_vp = h - round(y_pp) */
    vp = pt_pix_mark(vp, has);              /* null per value */
    pt_emit_viewport(sink, vp, w, h);       /* record: null, inside or outside */
    return vp;
}
