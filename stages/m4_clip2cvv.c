/*
** stages/m4_clip2cvv.c -- matrix camera: clip space -> the CVV outcode
** See LICENSE for copyright and license.
*/
#include "m4_clip2cvv.h"

const char *const pt_cvv_names[PT_CVV_NPLANES] = {
    "near", "far", "left", "right", "bottom", "top",
};

void pt_cvv_distances(pt_vec4 k, double d[PT_CVV_NPLANES])
{
    d[0] = k.z;                             /* near:   z >= 0 */
    d[1] = k.w - k.z;                       /* far:    z <= w */
    d[2] = k.w + k.x;                       /* left:   x >= -w */
    d[3] = k.w - k.x;                       /* right:  x <= w */
    d[4] = k.w + k.y;                       /* bottom: y >= -w */
    d[5] = k.w - k.y;                       /* top:    y <= w */
}

unsigned pt_clip2cvv(pt_vec4 k, const pt_sink *sink)
{
    double d[PT_CVV_NPLANES];
    unsigned code = 0;
    pt_vrec r = {0};
    int i;

    pt_cvv_distances(k, d);
    for (i = 0; i < PT_CVV_NPLANES; i++)
        if (!(d[i] >= 0)) code |= 1u << i;  /* NaN counts as outside */
    r.stage = PT_STAGE_CVV;
    r.x = k.x; r.y = k.y; r.z = k.z; r.w = k.w;
    r.code = code;
    pt_emit(sink, &r);
    return code;
}
