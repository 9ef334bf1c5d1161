/*
** tests/student/s2_divz.c -- s2, one mistake: divides by z_c, not -z_c
** See LICENSE for copyright and license.
**
** A copy of stages/s2_camera2image.c with one mistake, marked MISTAKE below, for
** tests/diff.sh and docs/teaching.md.  x_ip = x_c / z_c: for a
** point in front of the camera (z_c < 0) the image comes out mirrored.
** Build: make STAGE_projection=tests/student/s2_divz.c
*/
#include "s2_camera2image.h"

pt_vec3 pt_camera2image(pt_vec3 c, double z_scale, int perspective, const pt_sink *sink)
{
    pt_vec3 ip;
    pt_vrec r = {0};
    double v[2];
    int lost = 0;

    if (perspective) {
        ip.x = c.x / c.z;                   /* MISTAKE: x_ip = x_c / z_c */
        ip.y = c.y / c.z;                   /* MISTAKE: y_ip = y_c / z_c */
        ip.z = -1.0;                        /* z_ip = -1 */
        if (c.z > 0) r.flags |= PT_REC_BEHIND;
        lost = pt_bits_lost(z_scale, c.z);  /* the quotient keeps z_c's error */
    } else {
        ip.x = c.x;                         /* x_ip = x_c */
        ip.y = c.y;                         /* y_ip = y_c */
        ip.z = 0.0;                         /* z_ip = 0 */
    }
    r.stage = PT_STAGE_IMAGE;
    r.x = v[0] = ip.x; r.y = v[1] = ip.y; r.z = ip.z;
    r.warn = pt_warn_nonfinite(v, 2);
    pt_warn_lost(&r, PT_WARN_ILLCOND, lost);
    pt_emit(sink, &r);
    return ip;
}
