/*
** tests/student/s4_nominus1.c -- s4, one mistake: no -1 in x_vp
** See LICENSE for copyright and license.
**
** A copy of stages/s4_pixel2viewport.c with one mistake, marked MISTAKE below, for
** tests/diff.sh and docs/teaching.md.  x_vp = round(x_pp) forgets that
** logical pixels count from 1: everything moves one pixel right.
** Build: make STAGE_viewport=tests/student/s4_nominus1.c
*/
#include <assert.h>
#include <math.h>
#include "s4_pixel2viewport.h"

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

int pt_pix_round(double x, int64_t *out)
{
    double r = pt_java_round(x);

    if (!isfinite(x) || fabs(r) >= PT_PIX_LIMIT) { *out = 0; return 0; }
    *out = (int64_t)r;                      /* exact: |r| < 2^62 */
    return 1;
}

int pt_vp_inside(int64_t x_vp, int64_t y_vp, int w, int h)
{
    return x_vp >= 0 && x_vp < w && y_vp >= 0 && y_vp < h;
}

pt_pix pt_pixel2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink)
{
    pt_pix vp = {0, 0, 0};
    pt_vrec r = {0};
    int64_t rx, ry;

    assert(w > 0 && h > 0);
    if (pt_pix_round(pp.x, &rx) && pt_pix_round(pp.y, &ry)) {
        vp.x = rx;                          /* MISTAKE: x_vp = round(x_pp) */
        vp.y = h - ry;                      /* y_vp = h - round(y_pp) */
        vp.ok = 1;
    }
    r.stage = PT_STAGE_VIEWPORT;
    if (!vp.ok) { r.flags |= PT_REC_NULL; r.warn |= PT_WARN_RANGE; }
    else if (pt_vp_inside(vp.x, vp.y, w, h)) r.flags |= PT_REC_INSIDE;
    r.ix = vp.x; r.iy = vp.y;
    pt_emit(sink, &r);
    return vp;
}
