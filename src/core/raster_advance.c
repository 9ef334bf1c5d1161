/*
** src/core/raster_advance.c -- the rasterizer's exact fast-forward of y += m
** See LICENSE for copyright and license.
*/
#include <float.h>
#include <math.h>
#include "core/raster.h"

/* ===== exact fast-forward of y += m ===== */

/*
** Inside one binade [2^(e-1), 2^e) every double is a multiple of u = 2^(e-53).
** While the exact sum y + m stays inside the binade, fl(y + m) = y + d where d is
** m rounded to a multiple of u.  d is the same for every y, except when m is an
** odd multiple of u/2 (a tie): round-to-even then leaves y/u even after a step,
** and from there on d is the same every step.  So: take two real steps (the
** second inside one binade, which settles the parity), measure d with a third
** sum, and jump j steps at once: y + j*d is exact (a multiple of u inside the
** binade, j*d/u < 2^53).  The jump stops short of the binade's edge by a margin
** of 4|m| + 4|d|; the edge is crossed by real steps and it all starts over.
** tests/unit/test_raster.c checks this against the plain loop, ties included.
*/
double pt_raster_advance(double y, double m, uint64_t k)
{
    if (m == 0.0) return k ? y + m : y;     /* y + 0 turns -0 into +0, once */
    while (k > 0) {
        double y1, y2, d, lo, hi, room;
        int e1, e2;
        uint64_t jump;

        if (k < 3) { y += m; k--; continue; }
        y1 = y + m;                                 /* two real steps */
        y2 = y1 + m;
        k -= 2;
        y = y2;
        if (!isfinite(y2) || y1 == 0.0 || y2 == 0.0) continue;
        if ((y1 > 0) != (y2 > 0)) continue;         /* crossing zero */
        if (fabs(y1) < DBL_MIN && fabs(y2) < DBL_MIN) {
            lo = 0;                                 /* the subnormals: one grid, */
            hi = DBL_MIN;                           /* spacing 2^-1074 */
        } else {
            frexp(y1, &e1);
            frexp(y2, &e2);                         /* |y2| in [2^(e2-1), 2^e2) */
            if (e1 != e2 || fabs(y1) < DBL_MIN) continue;
            lo = ldexp(1.0, e2 - 1);
            hi = 2 * lo;
        }
        d = (y2 + m) - y2;                          /* the constant increment */
        if (d == 0.0) return y2;                    /* m too small: y stays put */
        if ((y2 > 0) == (d > 0)) room = hi - fabs(y2);   /* moving outward */
        else room = fabs(y2) - lo;                       /* moving inward */
        room -= 4 * fabs(m) + 4 * fabs(d);
        if (room <= 0) continue;
        jump = (uint64_t)fmin(room / fabs(d), 0x1p62);
        if (jump > k) jump = k;
        y = y2 + (double)jump * d;                  /* exact, see above */
        k -= jump;
    }
    return y;
}
