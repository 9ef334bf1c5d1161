/*
** stages/pt_color.c -- the colour of a rasterizer step, and its gamma encoding
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "pt_color.h"

float pt_gamma(float c)
{
    return (float)pow((double)c, PT_GAMMA_INV);     /* c^(1/2.2) */
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
