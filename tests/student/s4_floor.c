/*
** tests/student/s4_floor.c -- s4, one mistake: floor(x + 0.5) for Math.round
** See LICENSE for copyright and license.
**
** A copy of stages/s4_pixel2viewport.c with one mistake, marked MISTAKE below, for
** tests/diff.sh and docs/teaching.md.  floor(x + 0.5) rounds the sum
** first: 0.49999999999999994 + 0.5 is 1.0, so it gives 1 where Math.round
** gives 0.  The rasterizer rounds with it too (pt_pix_round).
** Build: make STAGE_viewport=tests/student/s4_floor.c
*/
#include <assert.h>
#include <math.h>
#include "s4_pixel2viewport.h"

double pt_java_round(double x)
{
    if (isnan(x)) return 0.0;               /* Java: Math.round(NaN) = 0 */
    if (isinf(x)) return x;
    return floor(x + 0.5);                  /* MISTAKE: the sum is rounded first */
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
        vp.x = rx - 1;                      /* x_vp = round(x_pp) - 1 */
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
