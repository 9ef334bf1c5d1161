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
#include "stages/s3_image2pixel.h"

/* Java's (int)(double)Math.round(x): ties up, NaN 0, saturated to an int. */
static int64_t java_int_round(double x)
{
    return pt_raster_java_int(pt_raster_java_round(x));
}

int64_t pt_raster_point(pt_vec2 pp, int r, int w, int h, int every, int64_t most,
                        pt_raster_dot *d, pt_raster_dot_fn *fn, void *ud)
{
    pt_vec3 ip;
    pt_vec2 q;
    int64_t ylo, yhi, xlo, xhi, n;

    ip.x = pp.x; ip.y = pp.y; ip.z = 0.0;
    q = pt_image2pixel(ip, w, h, NULL);             /* the pixel stage again, on x_pp */
    d->x_pp = q.x;
    d->y_pp = q.y;
    if (isinf(q.x) || isinf(q.y)) return -1;        /* NaN rounds to 0, as in Java */
    d->cx = java_int_round(q.x);
    d->cy = java_int_round(q.y);
    if (r < 0) return 0;
    if (d->cx + r > INT_MAX - 1 || d->cy + r > INT_MAX - 1 ||
        d->cx - r < INT_MIN || d->cy - r < INT_MIN)
        return -1;                                  /* the int loop would wrap */
    n = (2 * (int64_t)r + 1) * (2 * (int64_t)r + 1);
    ylo = d->cy - r; yhi = d->cy + r;
    xlo = d->cx - r; xhi = d->cx + r;
    if (!every) {                                   /* the pixels inside only */
        if (ylo < 1) ylo = 1;
        if (yhi > h) yhi = h;
        if (xlo < 1) xlo = 1;
        if (xhi > w) xhi = w;
    }
    for (d->y_ = ylo; d->y_ <= yhi; d->y_++)
        for (d->x_ = xlo; d->x_ <= xhi; d->x_++) {
            if (every && most-- <= 0) return n;
            d->vp.x = d->x_ - 1;                    /* (x_ - 1, h - y_) */
            d->vp.y = h - d->y_;
            d->vp.ok = 1;
            d->inside = d->x_ > 0 && d->x_ <= w && d->y_ > 0 && d->y_ <= h;
            fn(ud, d);
        }
    return n;
}
