/*
** tests/student/s3_swapwh.c -- s3, one mistake: w and h swapped
** See LICENSE for copyright and license.
**
** A copy of stages/s3_image2pixel.c with one mistake, marked MISTAKE below, for
** tests/diff.sh and docs/teaching.md.  x is scaled by the height and
** y by the width: a wide viewport squeezes the picture.
** Build: make STAGE_pixel=tests/student/s3_swapwh.c
*/
#include <assert.h>
#include "s3_image2pixel.h"

pt_vec2 pt_image2pixel(pt_vec3 ip, int w, int h, const pt_sink *sink)
{
    pt_vec2 pp;
    pt_vrec r = {0};
    double v[2];

    assert(w > 0 && h > 0);
    pp.x = 0.5 + h / 2.001 * (ip.x + 1);    /* MISTAKE: x_pp = 0.5 + h/2.001 * (x_ip + 1) */
    pp.y = 0.5 + w / 2.001 * (ip.y + 1);    /* MISTAKE: y_pp = 0.5 + w/2.001 * (y_ip + 1) */
    r.stage = PT_STAGE_PIXEL;
    r.x = v[0] = pp.x; r.y = v[1] = pp.y;
    r.warn = pt_warn_nonfinite(v, 2);
    pt_emit(sink, &r);
    return pp;
}
