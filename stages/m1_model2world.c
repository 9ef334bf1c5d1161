/*
** stages/m1_model2world.c -- matrix camera: model coordinates -> world coordinates
** See LICENSE for copyright and license.
*/
#include "m1_model2world.h"

void pt_emit_vec4(const pt_sink *sink, pt_stage st, pt_vec4 v, int lost)
{
    pt_vrec r = {0};
    double a[4];

    r.stage = st;
    r.x = a[0] = v.x; r.y = a[1] = v.y; r.z = a[2] = v.z; r.w = a[3] = v.w;
    r.warn = pt_warn_nonfinite(a, 4);
    pt_warn_lost(&r, PT_WARN_CANCEL, lost);
    pt_emit(sink, &r);
}

pt_vec4 pt_model2world(pt_vec3 m, const pt_mat4 *world, const pt_sink *sink)
{
    pt_vec4 p = {m.x, m.y, m.z, 1.0}, w;

    w = pt_vec4_mul(p, world);              /* (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World */
    if (sink) pt_emit_vec4(sink, PT_STAGE_WORLD, w, pt_vec4_mul_bits_lost(p, world, w));
    return w;
}
