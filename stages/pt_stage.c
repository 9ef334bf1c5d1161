/*
** stages/pt_stage.c -- the table of stages: names, spaces, values, formulas, order
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <string.h>
#include "pt_stage.h"

const pt_stage_info pt_stage_infos[PT_NSTAGES_ALL] = {
    { "model",       "scene",       "model",
      "(x_m, y_m, z_m) as given by the scene",
      "the vertex as the scene gives it, in its model's own coordinates",
      3, 0, {"x_m", "y_m", "z_m", NULL}, {"x", "y", "z", NULL},
      PT_VAL_REAL, 0 },
    { "camera",      "model",       "camera",
      "x_c = x_m + x_t, y_c = y_m + y_t, z_c = z_m + z_t",
      "move the model in front of the camera: add its translation",
      3, 0, {"x_c", "y_c", "z_c", NULL}, {"x", "y", "z", NULL},
      PT_VAL_REAL, 0 },
    { "image",       "camera",      "image plane",
      "x_ip = x_c / -z_c, y_ip = y_c / -z_c, z_ip = -1 (orthographic: x_ip = x_c, y_ip = y_c, z_ip = 0)",
      "project onto the image plane z = -1: divide by the distance -z_c (similar triangles)",
      3, 0, {"x_ip", "y_ip", "z_ip", NULL}, {"x", "y", "z", NULL},
      PT_VAL_REAL, PT_REC_BEHIND },
    { "pixel",       "image plane", "pixel plane",
      "x_pp = 0.5 + w/2.001 * (x_ip + 1), y_pp = 0.5 + h/2.001 * (y_ip + 1)",
      "stretch the view rectangle [-1, 1] x [-1, 1] over the viewport's logical pixels",
      2, 0, {"x_pp", "y_pp", NULL, NULL}, {"x", "y", NULL, NULL},
      PT_VAL_REAL, 0 },
    { "viewport",    "pixel plane", "viewport",
      "x_vp = round(x_pp) - 1, y_vp = h - round(y_pp)",
      "round to the nearest logical pixel, then count from 0 and from the top row down",
      0, 2, {"x_vp", "y_vp", NULL, NULL}, {"x", "y", NULL, NULL},
      PT_VAL_PIXEL, PT_REC_INSIDE | PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y },
    { "framebuffer", "viewport",    "framebuffer",
      "x_fb = x_ul + x_vp, y_fb = y_ul + y_vp",
      "shift by the viewport's upper-left corner (x_ul, y_ul) in the framebuffer",
      0, 2, {"x_fb", "y_fb", NULL, NULL}, {"x", "y", NULL, NULL},
      PT_VAL_PIXEL, PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y },
    { "index",       "framebuffer", "pixel array",
      "idx = y_fb * W + x_fb",
      "number the framebuffer's pixels row by row, top row first",
      0, 1, {"idx", NULL, NULL, NULL}, {"i", NULL, NULL, NULL},
      PT_VAL_INDEX, PT_REC_NULL },
    /* the matrix camera's own stages (docs/cameras.md) */
    { "world",       "model",       "world",
      "(x_w y_w z_w w_w) = (x_m y_m z_m 1) * World",
      "place the model in the world: multiply by its world matrix",
      4, 0, {"x_w", "y_w", "z_w", "w_w"}, {"x", "y", "z", "w"},
      PT_VAL_REAL, 0 },
    { "view",        "world",       "view",
      "(x_v y_v z_v w_v) = (x_w y_w z_w w_w) * View",
      "look from the camera: move the eye to the origin, turn its axes onto x, y, z",
      4, 0, {"x_v", "y_v", "z_v", "w_v"}, {"x", "y", "z", "w"},
      PT_VAL_REAL, 0 },
    { "clip",        "view",        "clip space",
      "x_k = x_v*cot(fov/2)/aspect, y_k = y_v*cot(fov/2), z_k = z_v*f/(f-n) - f*n/(f-n), w_k = z_v",
      "scale the view frustum to the box -w <= x, y <= w, 0 <= z <= w",
      4, 0, {"x_k", "y_k", "z_k", "w_k"}, {"x", "y", "z", "w"},
      PT_VAL_REAL, 0 },
    { "cvv",         "clip space",  "outcode",
      "0x01 z<0, 0x02 z>w, 0x04 x<-w, 0x08 x>w, 0x10 y<-w, 0x20 y>w",
      "test the point against the six planes of the canonical view volume",
      0, 1, {"code", NULL, NULL, NULL}, {"code", NULL, NULL, NULL},
      PT_VAL_OUTCODE, 0 },
    { "ndc",         "clip space",  "normalised device coordinates",
      "x_n = x_k / w_k, y_n = y_k / w_k, z_n = z_k / w_k",
      "the homogeneous divide: the perspective happens here",
      3, 0, {"x_n", "y_n", "z_n", NULL}, {"x", "y", "z", NULL},
      PT_VAL_REAL, 0 },
    { "screen",      "ndc",         "screen",
      "x_s = (x_n + 1) * w * 0.5, y_s = (1 - y_n) * h * 0.5, z_s = z_n",
      "stretch [-1, 1] x [-1, 1] over the viewport, y pointing down",
      3, 0, {"x_s", "y_s", "z_s", NULL}, {"x", "y", "z", NULL},
      PT_VAL_REAL, 0 },
};

const pt_stage_info pt_matrix_viewport_info = {
    "viewport", "screen", "viewport",
    "x_vp = floor(x_s), y_vp = floor(y_s)",
    "the pixel whose square contains the point (centres at k + 0.5)",
    0, 2, {"x_vp", "y_vp", NULL, NULL}, {"x", "y", NULL, NULL},
    PT_VAL_PIXEL, PT_REC_INSIDE | PT_REC_NULL | PT_REC_HAS_X | PT_REC_HAS_Y,
};

const pt_stage pt_classic_order[PT_CLASSIC_NORDER] = {
    PT_STAGE_MODEL, PT_STAGE_CAMERA, PT_STAGE_IMAGE, PT_STAGE_PIXEL,
    PT_STAGE_VIEWPORT, PT_STAGE_FRAMEBUFFER, PT_STAGE_INDEX,
};
const int pt_classic_norder = PT_CLASSIC_NORDER;

const pt_stage pt_matrix_order[PT_MATRIX_NORDER] = {
    PT_STAGE_MODEL, PT_STAGE_WORLD, PT_STAGE_VIEW, PT_STAGE_CLIP, PT_STAGE_CVV,
    PT_STAGE_NDC, PT_STAGE_SCREEN, PT_STAGE_VIEWPORT, PT_STAGE_FRAMEBUFFER,
    PT_STAGE_INDEX,
};
const int pt_matrix_norder = PT_MATRIX_NORDER;

const pt_stage pt_trace_order[PT_NSTAGES_ALL] = {
    PT_STAGE_MODEL, PT_STAGE_CAMERA, PT_STAGE_IMAGE, PT_STAGE_PIXEL,  /* classic */
    PT_STAGE_WORLD, PT_STAGE_VIEW, PT_STAGE_CLIP, PT_STAGE_CVV,       /* matrix */
    PT_STAGE_NDC, PT_STAGE_SCREEN,
    PT_STAGE_VIEWPORT, PT_STAGE_FRAMEBUFFER, PT_STAGE_INDEX,          /* both */
};

const char *const pt_stage_course[PT_NSTAGES_ALL] = {
    "0. Model", "1. Camera", "2. Projected", "3. Pixel-plane"   /* the rest: NULL */
};

int pt_stage_nvalues(pt_stage st)
{
    return pt_stage_infos[st].nreal + pt_stage_infos[st].nint;
}

int pt_stage_by_name(const char *s)
{
    int k;

    for (k = 0; k < PT_NSTAGES_ALL; k++)
        if (strcmp(s, pt_stage_infos[k].name) == 0) return k;
    return -1;
}

const char *const pt_warn_names[PT_NWARN] = {
    "nonfinite", "cancellation", "ill_conditioned", "out_of_range", "outside_pixel_array",
};

/* ilogb(x) for finite x != 0: a normal double's exponent field less its
** bias, read off its bits (no call); a subnormal's from ilogb(). */
static int binary_exponent(double x)
{
    union { double d; uint64_t bits; } v;   /* C11 6.5.2.3: the bytes as bits */
    int e;

    v.d = x;
    e = (int)(v.bits >> 52 & 0x7ff);
    return e ? e - 1023 : ilogb(x);
}

int pt_bits_lost(double scale, double x)
{
    int lost;

    if (x == 0 || !isfinite(x) || !isfinite(scale) || fabs(x) >= fabs(scale)) return 0;
    lost = binary_exponent(scale) - binary_exponent(x);    /* exact: ilogb's */
    return lost > 53 ? 53 : lost;
}

int pt_bits_to_digits(int bits)
{
    return (int)((long)bits * 30103L / 100000L);    /* log10(2) = 0.30103 */
}

void pt_warn_lost(pt_vrec *r, unsigned warn, int lost)
{
    if (lost <= PT_BITS_LOST_WARN) return;
    r->warn |= warn;
    r->digits_lost = pt_bits_to_digits(lost);
}
