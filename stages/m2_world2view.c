/*
** stages/m2_world2view.c -- matrix camera: world coordinates -> view coordinates
** See LICENSE for copyright and license.
*/
#include "m2_world2view.h"

pt_vec4 pt_world2view(pt_vec4 p, const pt_mat4 *view, const pt_sink *sink)
{
    pt_vec4 v = pt_vec4_mul(p, view);       /* (x_v y_v z_v w_v) = p * View */

    if (sink) pt_emit_vec4(sink, PT_STAGE_VIEW, v, pt_vec4_mul_bits_lost(p, view, v));
    return v;
}
