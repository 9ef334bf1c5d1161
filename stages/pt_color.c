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
