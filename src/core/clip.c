/*
** src/core/clip.c -- clip a segment against the canonical view volume, before the divide
** See LICENSE for copyright and license.
*/
#include "core/clip.h"
#include "stages/m4_clip2cvv.h"

pt_vec4 pt_clip_lerp(pt_vec4 p0, pt_vec4 p1, double t)
{
    pt_vec4 r;

    r.x = p0.x + t * (p1.x - p0.x);         /* P(t) = P0 + t (P1 - P0) */
    r.y = p0.y + t * (p1.y - p0.y);
    r.z = p0.z + t * (p1.z - p0.z);
    r.w = p0.w + t * (p1.w - p0.w);
    return r;
}

int pt_clip_segment(pt_vec4 p0, pt_vec4 p1, double *t0, double *t1,
                    pt_vec4 *q0, pt_vec4 *q1)
{
    double d0[PT_CVV_NPLANES], d1[PT_CVV_NPLANES], enter = 0, leave = 1;
    int i;

    pt_cvv_distances(p0, d0);
    pt_cvv_distances(p1, d1);
    for (i = 0; i < PT_CVV_NPLANES; i++) {
        if (!(d0[i] >= 0) && !(d1[i] >= 0)) return 0;   /* both outside: gone */
        if (d0[i] < 0) {                    /* entering through plane i */
            double t = d0[i] / (d0[i] - d1[i]);
            if (t > enter) enter = t;
        } else if (d1[i] < 0) {             /* leaving through plane i */
            double t = d0[i] / (d0[i] - d1[i]);
            if (t < leave) leave = t;
        }
    }
    if (enter > leave) return 0;            /* enters after it has left */
    *t0 = enter;
    *t1 = leave;
    *q0 = enter == 0 ? p0 : pt_clip_lerp(p0, p1, enter);
    *q1 = leave == 1 ? p1 : pt_clip_lerp(p0, p1, leave);
    return 1;
}
