/*
** stages/r9_world2view.c -- renderer 9, stage 2: world -> view (the camera's translation)
** See LICENSE for copyright and license.
*/
#include "r9_world2view.h"

pt_vec4 pt_r9_world2view(pt_vec4 v, pt_vec3 view)
{
    pt_vec4 o;

    o.x = (-1 * view.x) + v.x;          /* viewVector.times(-1).plus(v) */
    o.y = (-1 * view.y) + v.y;
    o.z = (-1 * view.z) + v.z;
    o.w = 1.0;                          /* new Vertex(x, y, z): w back to 1 */
    return o;
}

void pt_r9_world2view_all(pt_vec4 *v, size_t n, pt_vec3 view)
{
    size_t k;

    for (k = 0; k < n; k++) v[k] = pt_r9_world2view(v[k], view);
}
