/*
** tests/student/s2_silent.c -- s2, one mistake: computes right, reports nothing
** See LICENSE for copyright and license.
**
** stages/s2_camera2image.c without its record: the numbers are right, but the
** stage never calls pt_emit(), so a trace made with it has no image records.
** For tests/diff.sh and docs/teaching.md: pipetrace diff must say that the
** stage did not report, not blame the pixel stage.
** Build: make STAGE_projection=tests/student/s2_silent.c
*/
#include "s2_camera2image.h"

pt_vec3 pt_camera2image(pt_vec3 c, double z_scale, int perspective, const pt_sink *sink)
{
    pt_vec3 ip;

    (void)z_scale;
    (void)sink;                             /* MISTAKE: never given the record */
    if (perspective) {
        ip.x = c.x / -c.z;                  /* x_ip = x_c / -z_c */
        ip.y = c.y / -c.z;                  /* y_ip = y_c / -z_c */
        ip.z = -1.0;                        /* z_ip = -1 */
    } else {
        ip.x = c.x;                         /* x_ip = x_c */
        ip.y = c.y;                         /* y_ip = y_c */
        ip.z = 0.0;                         /* z_ip = 0 */
    }
    return ip;                              /* MISTAKE: no pt_emit(sink, &r) */
}
