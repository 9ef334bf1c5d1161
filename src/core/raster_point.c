/*
** src/core/raster_point.c -- the course's points (renderer 4), pixel by pixel
** See LICENSE for copyright and license.
**
** raster.h says what a point's pixels are.  The 2.001 map is applied to a
** vertex already in the pixel plane (NOTES.md 11.3, "mapped twice"): the
** course's code is reproduced, so a point lands near (w*x_pp/2, h*y_pp/2)
** and only vertices just left of and below the view rectangle show.
*/
#include <limits.h>
#include <math.h>
#include "core/raster.h"
#include "stages/pt_round.h"
#include "stages/s3_image2pixel.h"

/* Java's (int)(double)Math.round(x): ties up, NaN 0, saturated to an int. */
static int64_t java_int_round(double x)
{
    double r = pt_java_round(x);                    /* Math.round, as a double */

    if (r != r) return 0;
    if (r >= (double)INT_MAX) return INT_MAX;
    if (r <= (double)INT_MIN) return INT_MIN;
    return (int64_t)r;
}

int64_t pt_raster_point(pt_vec2 pp, int r, int w, int h, int every, int64_t most,
                        pt_raster_dot_fn *fn, void *ud)
{
    pt_vec3 ip;
    pt_vec2 q;
    pt_raster_dot dt;
    int64_t ylo, yhi, xlo, xhi, n;

    ip.x = pp.x; ip.y = pp.y; ip.z = 0.0;
    q = pt_image2pixel(ip, w, h, NULL);             /* x = 0.5 + w/2.001 * (x_pp + 1) */
    if (!isfinite(q.x) || !isfinite(q.y)) return -1;
    dt.x_pp = q.x;
    dt.y_pp = q.y;
    dt.cx = java_int_round(q.x);
    dt.cy = java_int_round(q.y);
    if (r < 0) return 0;
    if (dt.cx + r > INT_MAX - 1 || dt.cy + r > INT_MAX - 1 ||
        dt.cx - r < INT_MIN || dt.cy - r < INT_MIN)
        return -1;                                  /* the int loop would wrap */
    n = (2 * (int64_t)r + 1) * (2 * (int64_t)r + 1);
    ylo = dt.cy - r; yhi = dt.cy + r;
    xlo = dt.cx - r; xhi = dt.cx + r;
    if (!every) {                                   /* the pixels inside only */
        if (ylo < 1) ylo = 1;
        if (yhi > h) yhi = h;
        if (xlo < 1) xlo = 1;
        if (xhi > w) xhi = w;
    }
    for (dt.y_ = ylo; dt.y_ <= yhi; dt.y_++)
        for (dt.x_ = xlo; dt.x_ <= xhi; dt.x_++) {
            if (every && most-- <= 0) return n;
            dt.vp.x = dt.x_ - 1;                    /* (x_ - 1, h - y_) */
            dt.vp.y = h - dt.y_;
            dt.vp.ok = 1;
            dt.inside = dt.x_ > 0 && dt.x_ <= w && dt.y_ > 0 && dt.y_ <= h;
            fn(ud, &dt);
        }
    return n;
}
