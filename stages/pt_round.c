/*
** stages/pt_round.c -- Java's rounding, the pixel limit, the inside tests
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "pt_round.h"

/*
** Why x - floor(x) is exact.  For x >= 1, floor(x) <= x < 2 floor(x), so the
** difference is exact (Sterbenz).  For 0 <= x < 1, floor(x) = 0.  For -1 < x < 0,
** floor(x) = -1: if x <= -0.5 then 1 + x is exact (Sterbenz again); if x > -0.5
** the true difference exceeds 0.5 and rounding cannot take it below 0.5, so the
** comparison is still right.  For x <= -1 the difference is a multiple of ulp(x)
** smaller than 1, which fits in 53 bits.  For |x| >= 2^52, x is an integer.
*/
double pt_java_round(double x)
{
    double r;

    if (isnan(x)) return 0.0;               /* Java: Math.round(NaN) = 0 */
    if (isinf(x)) return x;
    r = floor(x);
    if (x - r >= 0.5) r += 1.0;             /* ties go up: toward +infinity */
    return r;
}

void pt_emit_viewport_record(const pt_sink *sink, pt_pix vp, int w, int h)
{
    pt_vrec r = {0};

    r.stage = PT_STAGE_VIEWPORT;
    r.flags = pt_pix_flags(vp);             /* null per value */
    if (!vp.ok) r.warn |= PT_WARN_RANGE;
    else if (pt_inside(vp.x, vp.y, w, h)) r.flags |= PT_REC_INSIDE;
    r.ix = pt_pix_has(vp, 0) ? vp.x : 0;
    r.iy = pt_pix_has(vp, 1) ? vp.y : 0;
    pt_emit(sink, &r);
}
