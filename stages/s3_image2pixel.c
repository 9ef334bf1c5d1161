/*
** stages/s3_image2pixel.c -- image plane -> logical pixel plane
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include "s3_image2pixel.h"

pt_vec2 pt_image2pixel(pt_vec3 ip, int w, int h, const pt_sink *sink)
{
    pt_vec2 pp;
    double v[2];

    assert(w > 0 && h > 0);
    pp.x = 0.5 + w / 2.001 * (ip.x + 1);    /* x_pp = 0.5 + w/2.001 * (x_ip + 1) */
    pp.y = 0.5 + h / 2.001 * (ip.y + 1);    /* y_pp = 0.5 + h/2.001 * (y_ip + 1) */
    if (!sink) return pp;                   /* nobody listens: no record */
    pt_vrec r = {0};
    r.stage = PT_STAGE_PIXEL;
    r.x = v[0] = pp.x; r.y = v[1] = pp.y;
    r.warn = pt_warn_nonfinite(v, 2);
    pt_emit(sink, &r);
    return pp;
}
