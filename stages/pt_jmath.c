/*
** stages/pt_jmath.c -- Java's Math.atan, bit for bit
** See LICENSE for copyright and license.
**
** The algorithm and its constants: see the header.  Every operation is one
** IEEE double operation in the order fdlibm writes it (the build has
** -ffp-contract=off, so no fused multiply-add changes a bit).
*/
#include <stdint.h>
#include <string.h>
#include "pt_jmath.h"

/* atan(1/2), atan(1), atan(3/2), atan(inf) = pi/2, each as hi + lo. */
static const double atanhi[4] = {
    0x1.dac670561bb4fp-2, 0x1.921fb54442d18p-1, 0x1.f730bd281f69bp-1, 0x1.921fb54442d18p0,
};
static const double atanlo[4] = {
    0x1.a2b7f222f65e2p-56, 0x1.1a62633145c07p-55, 0x1.007887af0cbbdp-56, 0x1.1a62633145c07p-54,
};
/* atan(t) ~ t - t*(aT0 z + aT1 z^2 + ... + aT10 z^11), z = t^2 */
static const double aT[11] = {
     0x1.555555555550dp-2, -0x1.999999998ebc4p-3, 0x1.24924920083ffp-3,
    -0x1.c71c6fe231671p-4,  0x1.745cdc54c206ep-4, -0x1.3b0f2af749a6dp-4,
     0x1.10d66a0d03d51p-4, -0x1.dde2d52defd9ap-5,  0x1.97b4b24760debp-5,
    -0x1.2b4442c6a6c2fp-5,  0x1.0ad3ae322da11p-6,
};

double pt_jmath_atan(double x)
{
    uint64_t bits;
    uint32_t ix, lo;
    int neg, id;
    double t, z, w, s1, s2;

    memcpy(&bits, &x, sizeof bits);
    ix = (uint32_t)(bits >> 32) & 0x7fffffffu;   /* high word without the sign */
    lo = (uint32_t)bits;
    neg = (bits >> 63) != 0;
    if (ix >= 0x44100000u) {                     /* |x| >= 2^66, inf, NaN */
        if (ix > 0x7ff00000u || (ix == 0x7ff00000u && lo != 0)) return x + x;
        return neg ? -atanhi[3] - atanlo[3] : atanhi[3] + atanlo[3];
    }
    if (ix < 0x3fdc0000u) {                      /* |x| < 7/16 */
        if (ix < 0x3e200000u) return x;          /* |x| < 2^-29 */
        id = -1;
        t = x;
    } else {
        double a = neg ? -x : x;                 /* |x| */
        if (ix < 0x3ff30000u) {                  /* |x| < 19/16 */
            if (ix < 0x3fe60000u) { id = 0; t = (2.0 * a - 1.0) / (2.0 + a); }
            else                  { id = 1; t = (a - 1.0) / (a + 1.0); }
        } else if (ix < 0x40038000u) {           /* |x| < 39/16 */
            id = 2; t = (a - 1.5) / (1.0 + 1.5 * a);
        } else {                                 /* |x| < 2^66 */
            id = 3; t = -1.0 / a;
        }
    }
    z = t * t;
    w = z * z;
    s1 = z * (aT[0] + w * (aT[2] + w * (aT[4] + w * (aT[6] + w * (aT[8] + w * aT[10])))));
    s2 = w * (aT[1] + w * (aT[3] + w * (aT[5] + w * (aT[7] + w * aT[9]))));
    if (id < 0) return t - t * (s1 + s2);
    z = atanhi[id] - ((t * (s1 + s2) - atanlo[id]) - t);
    return neg ? -z : z;
}
