/*
** stages/s2_camera2image.c -- camera coordinates -> image plane (projection)
** See LICENSE for copyright and license.
*/
#include "s2_camera2image.h"

pt_vec3 pt_camera2image(pt_vec3 c, double z_scale, int perspective, const pt_sink *sink)
{
    pt_vec3 ip;
    double v[2];

    if (perspective) {
        ip.x = c.x / -c.z;                  /* x_ip = x_c / -z_c */
        ip.y = c.y / -c.z;                  /* y_ip = y_c / -z_c */
        ip.z = -1.0;                        /* z_ip = -1 */
    } else {
        ip.x = c.x;                         /* x_ip = x_c */
        ip.y = c.y;                         /* y_ip = y_c */
        ip.z = 0.0;                         /* z_ip = 0 */
    }
    if (!sink) return ip;                   /* nobody listens: no record */
    pt_vrec r = {0};
    r.stage = PT_STAGE_IMAGE;
    r.x = v[0] = ip.x; r.y = v[1] = ip.y; r.z = ip.z;
    r.warn = pt_warn_nonfinite(v, 2);
    if (perspective) {
        if (c.z > 0) r.flags |= PT_REC_BEHIND;
        /* the quotient keeps z_c's error */
        pt_warn_lost(&r, PT_WARN_ILLCOND, pt_bits_lost(z_scale, c.z));
    }
    pt_emit(sink, &r);
    return ip;
}
