/*
** stages/r7_view2camera.c -- renderer 7, stage 2: view -> camera (normalize the view volume)
** See LICENSE for copyright and license.
*/
#include "r7_view2camera.h"

pt_vec4 pt_r7_view2camera_shift(pt_vec4 v, const pt_rv_camera *cam)
{
    double l = cam->l, r = cam->r, b = cam->b, t = cam->t;
    pt_vec4 c;

    if (cam->perspective) {
        c.x = v.x + (v.z * (r + l))/2.0;    /* skew: x + z*(r+l)/2 */
        c.y = v.y + (v.z * (t + b))/2.0;
    } else {
        c.x = v.x - (r + l)/2.0;            /* translate: x - (r+l)/2 */
        c.y = v.y - (t + b)/2.0;
    }
    c.z = v.z;
    c.w = 1.0;
    return c;
}

pt_vec4 pt_r7_view2camera(pt_vec4 v, const pt_rv_camera *cam)
{
    double l = cam->l, r = cam->r, b = cam->b, t = cam->t;
    pt_vec4 c = pt_r7_view2camera_shift(v, cam);

    c.x = (2.0 * c.x)/(r - l);              /* scale: 2x/(r-l) */
    c.y = (2.0 * c.y)/(t - b);
    c.z = v.z;
    c.w = 1.0;
    return c;
}

void pt_r7_view2camera_all(pt_vec4 *v, size_t n, const pt_rv_camera *cam)
{
    size_t k;

    for (k = 0; k < n; k++) v[k] = pt_r7_view2camera(v[k], cam);
}
