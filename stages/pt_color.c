/*
** stages/pt_color.c -- the colour of a rasterizer step, and its gamma encoding
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "pt_color.h"

float pt_color_float(unsigned char c)
{
    return (float)c / 255.0f;                       /* c / 255f */
}

double pt_color_slope(float c0, float c1, double ds)
{
    return (double)(c1 - c0) / ds;                  /* (c1 - c0) / (s1 - s0) */
}

float pt_color_at(float c0, double slope, double s, double s0)
{
    return (float)fabs((double)c0 + slope * (s - s0));   /* |c0 + slope*(s - s0)| */
}

float pt_gamma(float c)
{
    return (float)pow((double)c, PT_GAMMA_INV);     /* c^(1/2.2) */
}

unsigned char pt_color_byte(float c)
{
    double v = (double)(c * 255.0f) + 0.5;          /* (double)(c*255f) + 0.5 */

    if (!(v >= 1.0)) return 0;                      /* (int) truncates; NaN: 0 */
    if (v >= 255.0) return 255;
    return (unsigned char)v;
}

float pt_aa_weight(double a, double a_low)
{
    return (float)(a - a_low);                      /* weight = (float)(a - a_low) */
}

void pt_aa_blend(float c, float bg, float w, float *low, float *hi)
{
    *low = (1.0f - w) * c + w * bg;                 /* (1 - w)*c + w*bg */
    *hi = w * c + (1.0f - w) * bg;                  /* w*c + (1 - w)*bg */
}
