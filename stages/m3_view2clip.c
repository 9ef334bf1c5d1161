/*
** stages/m3_view2clip.c -- matrix camera: view coordinates -> clip space
** See LICENSE for copyright and license.
*/
#include "m3_view2clip.h"

pt_vec4 pt_view2clip(pt_vec4 v, const pt_mat4 *proj, const pt_sink *sink)
{
    pt_vec4 k = pt_vec4_mul(v, proj);       /* (x_k y_k z_k w_k) = v * Projection */

    if (sink) pt_emit_vec4(sink, PT_STAGE_CLIP, k, pt_vec4_mul_bits_lost(v, proj, k));
    return k;
}
