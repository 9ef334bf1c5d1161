/*
** stages/s1_model2camera.c -- model coordinates -> camera coordinates
** See LICENSE for copyright and license.
*/
#include "s1_model2camera.h"

pt_vec3 pt_model2camera(pt_vec3 m, pt_vec3 t, const pt_sink *sink)
{
    pt_vec3 c;
    pt_vrec r = {0};

    c.x = m.x + t.x;                        /* x_c = x_m + x_t */
    c.y = m.y + t.y;                        /* y_c = y_m + y_t */
    c.z = m.z + t.z;                        /* z_c = z_m + z_t */
    r.stage = PT_STAGE_CAMERA;
    r.x = c.x; r.y = c.y; r.z = c.z;
    pt_emit(sink, &r);
    return c;
}
