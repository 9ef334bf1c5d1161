/*
** stages/ms_clip_segment.c -- the matrix camera's segment stage: clip to the view volume
** See LICENSE for copyright and license.
*/
#include "ms_clip_segment.h"
#include "m4_clip2cvv.h"

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

pt_rgb pt_clip_color(pt_rgb c0, pt_rgb c1, double t)
{
    float t_ = (float)t;
    pt_rgb c;

    c.r = c0.r + t_ * (c1.r - c0.r);        /* c(t) = c0 + t (c1 - c0) */
    c.g = c0.g + t_ * (c1.g - c0.g);
    c.b = c0.b + t_ * (c1.b - c0.b);
    return c;
}

pt_cut pt_clip_cut(const pt_segend *a, const pt_segend *b, pt_made made[2], int moved[2])
{
    double t[2];
    pt_vec4 q[2];
    int e;

    if ((a->code | b->code) == 0) return PT_CUT_KEEP;       /* all inside */
    if (!pt_clip_segment(a->h, b->h, &t[0], &t[1], &q[0], &q[1])) return PT_CUT_DROP;
    moved[0] = a->code != 0;
    moved[1] = b->code != 0;
    for (e = 0; e < 2; e++) {
        made[e].stage = PT_STAGE_CVV;
        made[e].end = e;
        made[e].t = t[e];
        made[e].q = q[e];
        made[e].color = pt_clip_color(a->color, b->color, t[e]);
    }
    return PT_CUT_NEW;
}
