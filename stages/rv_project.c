/*
** stages/rv_project.c -- renderers 7 and 9: camera -> image plane (projection)
** See LICENSE for copyright and license.
*/
#include "rv_project.h"

pt_vec4 pt_rv_project(pt_vec4 v, int perspective)
{
    pt_vec4 p;

    if (perspective) {
        p.x = v.x / -v.z;               /* x_p = x_c / -z_c */
        p.y = v.y / -v.z;               /* y_p = y_c / -z_c */
        p.z = -1;
    } else {
        p.x = v.x;                      /* x_p = x_c */
        p.y = v.y;
        p.z = 0;
    }
    p.w = 1.0;                          /* new Vertex(x, y, z) */
    return p;
}

void pt_rv_project_all(pt_vec4 *v, size_t n, int perspective)
{
    size_t k;

    for (k = 0; k < n; k++) v[k] = pt_rv_project(v[k], perspective);
}
