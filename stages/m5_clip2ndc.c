/*
** stages/m5_clip2ndc.c -- matrix camera: clip space -> normalised device coordinates
** See LICENSE for copyright and license.
*/
#include "m5_clip2ndc.h"

pt_vec3 pt_clip2ndc(pt_vec4 k, double w_scale, const pt_sink *sink)
{
    pt_vec3 n;
    pt_vrec r = {0};
    double a[3];
    int lost = pt_bits_lost(w_scale, k.w);  /* the quotients keep w_k's error */

    n.x = k.x / k.w;                        /* x_n = x_k / w_k */
    n.y = k.y / k.w;                        /* y_n = y_k / w_k */
    n.z = k.z / k.w;                        /* z_n = z_k / w_k */
    r.stage = PT_STAGE_NDC;
    r.x = a[0] = n.x; r.y = a[1] = n.y; r.z = a[2] = n.z;
    r.warn = pt_warn_nonfinite(a, 3);
    pt_warn_lost(&r, PT_WARN_ILLCOND, lost);
    pt_emit(sink, &r);
    return n;
}
