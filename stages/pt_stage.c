/*
** stages/pt_stage.c -- the table of stages: names, spaces, formulas
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <string.h>
#include "pt_stage.h"

const pt_stage_info pt_stage_infos[PT_NSTAGES] = {
    { "model",       "scene",       "model",
      "(x_m, y_m, z_m) as given by the scene" },
    { "camera",      "model",       "camera",
      "x_c = x_m + x_t, y_c = y_m + y_t, z_c = z_m + z_t" },
    { "image",       "camera",      "image plane",
      "x_ip = x_c / -z_c, y_ip = y_c / -z_c, z_ip = -1 (orthographic: x_ip = x_c, y_ip = y_c, z_ip = 0)" },
    { "pixel",       "image plane", "pixel plane",
      "x_pp = 0.5 + w/2.001 * (x_ip + 1), y_pp = 0.5 + h/2.001 * (y_ip + 1)" },
    { "viewport",    "pixel plane", "viewport",
      "x_vp = round(x_pp) - 1, y_vp = h - round(y_pp)" },
    { "framebuffer", "viewport",    "framebuffer",
      "x_fb = x_ul + x_vp, y_fb = y_ul + y_vp" },
    { "index",       "framebuffer", "pixel array",
      "idx = y_fb * W + x_fb" },
};

int pt_stage_by_name(const char *s)
{
    int k;

    for (k = 0; k < PT_NSTAGES; k++)
        if (strcmp(s, pt_stage_infos[k].name) == 0) return k;
    return -1;
}

const char *const pt_warn_names[PT_NWARN] = {
    "nonfinite", "cancellation", "ill_conditioned", "out_of_range", "outside_pixel_array",
};

int pt_bits_lost(double scale, double x)
{
    int lost;

    if (x == 0 || !isfinite(x) || !isfinite(scale) || fabs(x) >= fabs(scale)) return 0;
    lost = ilogb(scale) - ilogb(x);         /* exact: binary exponents */
    return lost > 53 ? 53 : lost;
}

int pt_bits_to_digits(int bits)
{
    return (int)((long)bits * 30103L / 100000L);    /* log10(2) = 0.30103 */
}

unsigned pt_warn_nonfinite(const double *v, int n)
{
    int k;

    for (k = 0; k < n; k++)
        if (!isfinite(v[k])) return PT_WARN_NONFINITE;
    return 0;
}
