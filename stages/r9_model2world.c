/*
** stages/r9_model2world.c -- renderer 9, stage 1: model -> world (the position's matrix)
** See LICENSE for copyright and license.
*/
#include "r9_model2world.h"

pt_vec4 pt_r9_model2world(pt_vec4 v_m, const pt_jmat *m)
{
    return pt_jmat_times_vec(m, v_m);       /* v_w = M v_m, w included */
}

void pt_r9_model2world_all(pt_vec4 *v, size_t n, const pt_jmat *m)
{
    pt_jmat_times_vecs(m, v, n);            /* v_w = M v_m, each */
}
