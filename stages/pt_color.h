/*
** stages/pt_color.h -- the colour of a rasterizer step, and its gamma encoding
** See LICENSE for copyright and license.
**
** The course's line rasterizer (renderer 4, NOTES.md 11.2 and 11.4) gives
** each step of a segment a colour of its own, in float and double as Java
** computes it, and writes it gamma-encoded:
**   c        = byte / 255f                          (getRGBComponents)
**   slope    = (double)(c1 - c0) / (s1 - s0)         (float subtraction, widened)
**   c(s)     = (float)|c0 + slope * (s - s0)|        (in double)
**   gamma(c) = (float)Math.pow(c, 1 / 2.2)          (1 / 2.2 = 0.45454545454545453)
** s is the stepped coordinate (x for an x-major segment, y for a y-major
** one), s0 .. s1 the segment's after its ends are put in stepping order, c0
** and c1 the colours of those ends.  A degenerate segment (one pixel) is
** written in c0, without gamma.  Anti-aliasing (11.2 step 7) splits a step
** between the two pixels that bracket a = the other coordinate, blending
** with the viewport's background bg in float:
**   a_low    = floor(a),  weight = (float)(a - a_low)
**   low      = (1 - weight)*c + weight*bg,   hi = weight*c + (1 - weight)*bg
** then gamma on both.  A component is written as java.awt.Color(float) keeps
** it: byte = (int)((double)(c * 255f) + 0.5) (NOTES.md 4).
*/
#ifndef PT_COLOR_H
#define PT_COLOR_H

#include <math.h>

/* The formulas a rasterizer runs at every step are inline here; pow is in
** pt_color.c. */

/* The course's 1 / 2.2 (Rasterize.GAMMA = 2.2; 1.0 / 2.2 in double). */
#define PT_GAMMA_INV 0.45454545454545453

/* Colour byte c (0..255) as the course's float component, c / 255f.  This
** function can't fail. */
static inline float pt_color_float(unsigned char c)
{
    return (float)c / 255.0f;                       /* c / 255f */
}

/* The change of a colour component per step, from c0 at the first end to
** c1 at the last, over ds = s1 - s0 steps (ds != 0).  This function can't
** fail. */
static inline double pt_color_slope(float c0, float c1, double ds)
{
    return (double)(c1 - c0) / ds;                  /* (c1 - c0) / (s1 - s0) */
}

/* The component at step s of a segment whose first end s0 has c0, changing
** by slope a step: (float)|c0 + slope * (s - s0)|.  This function can't
** fail. */
static inline float pt_color_at(float c0, double slope, double s, double s0)
{
    return (float)fabs((double)c0 + slope * (s - s0));   /* |c0 + slope*(s - s0)| */
}

/* The course's gamma encoding of component c (0..1): (float)pow(c, 1/2.2).
** This function can't fail. */
float pt_gamma(float c);

/* Component c (0..1) as the byte java.awt.Color(float) stores:
** (int)((double)(c*255f) + 0.5), the product in float; NaN gives 0 (Java's
** (int)NaN), and beyond 1 gives 255 (Java would refuse it).  This function
** can't fail. */
static inline unsigned char pt_color_byte(float c)
{
    double v = (double)(c * 255.0f) + 0.5;          /* (double)(c*255f) + 0.5 */

    if (!(v >= 1.0)) return 0;                      /* (int) truncates; NaN: 0 */
    if (v >= 255.0) return 255;
    return (unsigned char)v;
}

/* The anti-aliasing weight of a step whose other coordinate is a, its lower
** pixel a_low = floor(a): (float)(a - a_low).  This function can't fail. */
static inline float pt_aa_weight(double a, double a_low)
{
    return (float)(a - a_low);                      /* weight = (float)(a - a_low) */
}

/* The two shares of component c at weight w with background component bg:
** *low = (1 - w)*c + w*bg, *hi = w*c + (1 - w)*bg, in float.  This function
** can't fail. */
static inline void pt_aa_blend(float c, float bg, float w, float *low, float *hi)
{
    *low = (1.0f - w) * c + w * bg;                 /* (1 - w)*c + w*bg */
    *hi = w * c + (1.0f - w) * bg;                  /* w*c + (1 - w)*bg */
}

#endif
