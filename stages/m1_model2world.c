/*
** stages/m1_model2world.c -- matrix camera: model coordinates -> world coordinates
** See LICENSE for copyright and license.
*/
#include "m1_model2world.h"

pt_vec4 pt_model2world(pt_vec3 m, const pt_mat4 *world, const pt_sink *sink)
{
    pt_vec4 p = {m.x, m.y, m.z, 1.0}, w;

    w = pt_vec4_mul(p, world);              /* (x_w y_w z_w w_w) = (x_m y_m z_m 1) * World */
    if (sink) pt_emit_vec4(sink, PT_STAGE_WORLD, w, pt_vec4_mul_bits_lost(p, world, w));
    return w;
}
