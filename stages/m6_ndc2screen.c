/*
** stages/m6_ndc2screen.c -- matrix camera: NDC -> screen coordinates
** See LICENSE for copyright and license.
*/
#include "m6_ndc2screen.h"

pt_vec3 pt_ndc2screen(pt_vec3 n, int w, int h, const pt_sink *sink)
{
    pt_vec3 s;
    pt_vrec r = {0};
    double a[2];

    s.x = (n.x + 1) * w * 0.5;              /* x_s = (x_n + 1) * w * 0.5 */
    s.y = (1 - n.y) * h * 0.5;              /* y_s = (1 - y_n) * h * 0.5 */
    s.z = n.z;                              /* z_s = z_n */
    r.stage = PT_STAGE_SCREEN;
    r.x = a[0] = s.x; r.y = a[1] = s.y; r.z = s.z;
    r.warn = pt_warn_nonfinite(a, 2);
    pt_emit(sink, &r);
    return s;
}
