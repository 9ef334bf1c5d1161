/*
** stages/r7_model2view.c -- renderer 7, stage 1: model -> view (the position's translation)
** See LICENSE for copyright and license.
*/
#include "r7_model2view.h"

pt_vec4 pt_r7_model2view(pt_vec4 v_m, pt_vec3 t)
{
    pt_vec4 v;

    v.x = t.x + v_m.x;                  /* x_v = t_x + x_m (Vector.plus(Vertex)) */
    v.y = t.y + v_m.y;
    v.z = t.z + v_m.z;
    v.w = 1.0;                          /* renderer 7's Vertex has no w */
    return v;
}

void pt_r7_model2view_all(pt_vec4 *v, size_t n, pt_vec3 t)
{
    size_t k;

    for (k = 0; k < n; k++) v[k] = pt_r7_model2view(v[k], t);
}
