/*
** stages/s1_model2camera.c -- model coordinates -> camera coordinates
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "s1_model2camera.h"

/* Bits of c = m + t lost to cancellation: the larger operand's rounding error
** (from reading decimal input) is what is left when the sum is much smaller. */
static int sum_bits_lost(double m, double t, double c)
{
    return pt_bits_lost(fmax(fabs(m), fabs(t)), c);
}

pt_vec3 pt_model2camera(pt_vec3 m, pt_vec3 t, const pt_sink *sink)
{
    pt_vec3 c;
    double v[3];
    int lost, ly, lz;

    c.x = m.x + t.x;                        /* x_c = x_m + x_t */
    c.y = m.y + t.y;                        /* y_c = y_m + y_t */
    c.z = m.z + t.z;                        /* z_c = z_m + z_t */
    if (!sink) return c;                    /* nobody listens: no record */
    pt_vrec r = {0};
    r.stage = PT_STAGE_CAMERA;
    r.x = v[0] = c.x; r.y = v[1] = c.y; r.z = v[2] = c.z;
    r.warn = pt_warn_nonfinite(v, 3);
    lost = sum_bits_lost(m.x, t.x, c.x);    /* the most any coordinate lost */
    ly = sum_bits_lost(m.y, t.y, c.y);
    lz = sum_bits_lost(m.z, t.z, c.z);
    if (ly > lost) lost = ly;
    if (lz > lost) lost = lz;
    pt_warn_lost(&r, PT_WARN_CANCEL, lost);
    pt_emit(sink, &r);
    return c;
}
