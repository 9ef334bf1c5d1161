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
