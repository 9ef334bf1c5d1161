/*
** stages/rv_raster.h -- renderers 7 and 9: rasterize a clipped primitive into the viewport
** See LICENSE for copyright and license.
**
** in : (x_p, y_p)   image plane, clipped to [-1,1] x [-1,1] (NaN passes the clip)
** out: pixels of the framebuffer, written as FrameBuffer.setPixelVP writes them
**   x_pp = 0.5 + w/2.001 * (x_p + 1)      (w/2.001 first; Blinn p.142)
**   y_pp = 0.5 + h/2.001 * (y_p + 1)
**   x_pp, y_pp = Math.round(...)          (a line's ends, a point's centre)
**   x_vp = x_pp - 1,  y_vp = h - y_pp      (pixel plane: y up; viewport: y down)
**   index = (y_ul + y_vp)*W + (x_ul + x_vp)   (Java int arithmetic; x past W
**                                             wraps to the next row, an index
**                                             outside W*H is "Bad pixel coordinate")
** A line (a DDA): transposed iff |dy| > |dx|, ends swapped so x0 <= x1, then
**   m = (y1 - y0)/(x1 - x0),  slope_c = (double)(c1 - c0 in float)/(x1 - x0)
**   for x = x0 .. x1-1:  y += m (accumulated),  c = (float)|c0 + slope_c*(x - x0)|
**     AA off: pixel (x, Math.round(y)), gamma(c)
**     AA on : pixels (x, (int)y) and (x, (int)y + 1) (the second = the first when
**             y == h, or w transposed: the edge rule), weight f = (float)(y - (int)y),
**             low = (1-f)*c + f*bg, hi = f*c + (1-f)*bg in float, gamma on all six
**   last pixel (x1, y1) and a one-pixel segment: the raw colour, no gamma, no AA.
** A point: gamma(c) on rows (int)y - r .. (int)y + r (outer), columns likewise,
**   each written iff 0 < x <= w and 0 < y <= h (pixel plane).
**   gamma(c) = (float)Math.pow(c, 1/2.2);  byte = (int)((double)(c*255f) + 0.5)
** Why: the 2.001 keeps x_p = 1 inside the viewport (w/2.001*2 < w), Math.round
** picks the logical pixel, transposing makes every step move one pixel in x.
** (NOTES.md of the course's reference, sections 3 to 6.)
**
**    y_pp                      viewport row 0
**     ^  . . . .                +--------> x_vp
**     |  . . . .    ==>         | . . . .
**     +--------> x_pp           v y_vp
*/
#ifndef PT_RV_RASTER_H
#define PT_RV_RASTER_H
#include "rv_model.h"

/* The byte a gamma-encoded component is written as, byte(gamma(c)) =
** pt_color_byte(pt_gamma(c)), by table instead of pow().  Every float c has
** a bigger gamma(c) than the float below it (floats are 2^-24 apart, and
** gamma(c + dc) - gamma(c) = (1/2.2) gamma(c) dc/c is millions of times
** pow's error), so byte(gamma(c)) only steps up as c grows: below 2^-20 it
** is byte(gamma(0)) = 0, from 1 up 255, and in between each of the ranges
** of 2^16 floats with the same exponent and top 7 bits of mantissa holds at
** most one step (gamma changes by less than 0.0035 of itself across one:
** under one byte's step) -- found by bisection at init.  Negative c and NaN
** take pow() (pt_rv_gamma_byte). */
#define PT_RV_LUT_N 2560         /* 20 exponents (2^-20 .. 2^-1) x 128 ranges */
typedef struct pt_rv_gamma_lut {
    uint32_t step[PT_RV_LUT_N];  /* the bits of range k's first float of byte
                                 ** lo[k] + 1 (past the range: no step) */
    unsigned char lo[PT_RV_LUT_N];   /* byte(gamma(c)) at range k's first float */
    int ok;                      /* 0: the table did not come out monotone
                                 ** (a broken pow): not used */
} pt_rv_gamma_lut;

/* The viewport and framebuffer a primitive is drawn into, and the switches. */
typedef struct pt_rv_raster_par {
    int w, h;                    /* the viewport's size */
    int x_ul, y_ul;              /* its upper-left corner in the framebuffer */
    int W, H;                    /* the framebuffer's size */
    unsigned char bg[3];         /* the viewport's background (AA blends with it) */
    int antialias, gamma;        /* Rasterize.doAntiAliasing, doGamma */
    const pt_rv_gamma_lut *lut;  /* NULL, or a table for the bytes of the
                                 ** pixels whose gamma-encoded floats nobody
                                 ** reads (pt_rv_gamma_lut_init) */
} pt_rv_raster_par;

/* The forms of the course's pixel log lines. */
typedef enum pt_rv_px_kind {
    PT_RV_PX_STEP,               /* a loop pixel, AA off */
    PT_RV_PX_AA,                 /* a loop pixel's two AA pixels */
    PT_RV_PX_END,                /* the last pixel, or a one-pixel segment's */
    PT_RV_PX_POINT               /* a pixel of a point */
} pt_rv_px_kind;

/* One pixel line.  x_pp and y_pp are as the log prints them: a STEP or AA
** line of a segment that is not transposed has an int x_pp (the step), a
** transposed one an int y_pp; END has the rounded ends, POINT the rounded
** centre (not the pixel).  STEP, END, POINT: the pixel (x_vp, y_vp).  AA not
** transposed: column x_vp, rows lo = h - y_low, hi = h - y_hi; transposed:
** row y_vp, columns lo = y_low - 1, hi = y_hi - 1.  c[0] the colour written
** (gamma-encoded where gamma applies; before gamma when the listener says
** bytes_only), c[1] AA's second pixel's; b[0] and b[1] their bytes as
** written: byte(gamma(c)), or byte(c) without gamma and at the last pixel. */
typedef struct pt_rv_pixel {
    pt_rv_px_kind kind;
    int transposed;              /* STEP, AA: the segment is transposed */
    double x_pp, y_pp;
    int x_vp, y_vp;
    int lo, hi;                  /* AA: the pair's varying coordinates */
    pt_rgb c[2];
    unsigned char b[2][3];       /* the bytes written: c[0]'s, c[1]'s */
    int clipped;                 /* POINT: outside the viewport (not written) */
    const pt_rv_raster_par *par; /* the viewport and framebuffer (the log's prefix) */
} pt_rv_pixel;

/* A segment's slopes, after transposing and ordering its ends. */
typedef struct pt_rv_slopes {
    double m;                    /* dy/dx (transposed coordinates) */
    int transposed;
    double mc[3];                /* red, green, blue per step */
    double x0_vp, y0_vp;         /* x0 - 1, h - y0 (transposed coordinates) */
    double x1_vp, y1_vp;
} pt_rv_slopes;

/* One pixel of a run (pt_rv_raster_ls.pixels): where a loop step writes,
** its bytes as written and its coverage (1 without AA; an AA step's low
** pixel 1 - f, its high one f, f = (float)(y - (int)y)). */
typedef struct pt_rv_px_out {
    int x_vp, y_vp;
    float coverage;
    unsigned char b[3];
} pt_rv_px_out;

#define PT_RV_RUN 64             /* the most pixels a run holds */

/* Who hears the rasterizer: every number the course's debug log prints for
** a primitive, in its order (any callback may be NULL).
**   ends   a segment's ends in the pixel plane, before rounding
**   slopes a segment that is not one pixel
**   point  a point's centre in the pixel plane, before rounding
**   pixel  each pixel line, before its write(s)
**   bad    a write whose index is outside the framebuffer (dropped): its
**          framebuffer coordinates, after the pixel line it belongs to */
struct pt_rv_raster_ls {
    void (*ends)(void *ud, double x0_pp, double y0_pp, double x1_pp, double y1_pp);
    void (*slopes)(void *ud, const pt_rv_slopes *s);
    void (*point)(void *ud, double x_pp, double y_pp);
    void (*pixel)(void *ud, const pt_rv_pixel *px);
    void (*bad)(void *ud, int x_fb, int y_fb, int W, int H);
    void *ud;
    int clipped_points;          /* 1: pixel hears a point's clipped pixels too
                                 ** (the log prints them); 0: only the written
                                 ** ones, and a point's loops are cut to the
                                 ** viewport (the same pixels, in the same order) */
    int bytes_only;              /* 1: pixel reads a pixel's bytes b[], not its
                                 ** gamma-encoded floats: c[] is the colour
                                 ** before gamma and the bytes come from
                                 ** par->lut (no pow a component) */
    void (*pixels)(void *ud, const pt_rv_raster_par *par, const pt_rv_px_out *px, size_t n);
                                 /* with bytes_only and no bad (NULL: not
                                 ** used): the loop steps of a segment whose
                                 ** ends lie within 2^30 come here, in runs
                                 ** of up to PT_RV_RUN pixels in order (an AA
                                 ** step's low pixel, then its high one), and
                                 ** not to pixel; other segments' steps, last
                                 ** pixels and points still go to pixel */
};
typedef struct pt_rv_raster_ls pt_rv_raster_ls;

/* Draw primitive p of m into rgb (the framebuffer, W x H, 3 bytes a pixel,
** row-major, top row first), written as FrameBuffer.setPixelVP writes,
** telling ls (NULL: nobody).  rgb NULL: nothing is written, and all else is
** as with a framebuffer (the count, what ls hears).  p's indices must be
** valid for m.  The loops run as Java's do, over Java ints: a NaN
** coordinate rounds to 0; a point's rows and columns stop at INT_MAX where
** Java's would wrap around forever.  The work is the segment's length in
** pixels, or (2 radius + 1)^2: bounded by the viewport for the clipped
** model the course gives it (|x|, |y| <= 1 or NaN), up to 2^32 steps for
** coordinates far outside it, as in Java.
** Returns the number of pixels written.  This function can't fail. */
uint64_t pt_rv_raster_prim(const pt_rv_model *m, const pt_rv_prim *p,
                           const pt_rv_raster_par *par, unsigned char *rgb,
                           const pt_rv_raster_ls *ls);

/* The number of pixel lines pt_rv_raster_prim(m, p, par, ...) tells a
** listener without clipped_points, found from p's ends alone, without
** drawing: a line's loop steps (int)x0 .. (int)x1 - 1 (its ends rounded,
** transposed and ordered as the DDA takes them) and its last pixel, 1 for
** a one-pixel segment; a point's rows times columns inside the viewport.
** An AA step is one line (two pixels); a pixel whose index is "bad" is
** one line too.  p's indices must be valid for m.  This function can't
** fail. */
uint64_t pt_rv_raster_steps(const pt_rv_model *m, const pt_rv_prim *p,
                            const pt_rv_raster_par *par);

/* pt_rv_raster_prim(m, p, par, rgb, ls), which also sets *steps (unless
** NULL) to pt_rv_raster_steps(m, p, par), found on the way.  This function
** can't fail. */
uint64_t pt_rv_raster_prim_steps(const pt_rv_model *m, const pt_rv_prim *p,
                                 const pt_rv_raster_par *par, unsigned char *rgb,
                                 const pt_rv_raster_ls *ls, uint64_t *steps);

/* FrameBuffer.setPixelVP(x_vp, y_vp) -> setPixelFB(x_ul + x_vp, y_ul + y_vp):
** sets *x_fb, *y_fb (Java ints) and returns the pixel's index y_fb*W + x_fb
** in the pixel array, in Java's int arithmetic (an x_fb past W lands in the
** next row), or -1 when that index lies outside the W*H array (the
** course's "Bad pixel coordinate": nothing is written).  The rasterizer
** writes each pixel there (inside a viewport that lies inside the
** framebuffer by a shortcut to the same element).  This function can't
** fail. */
int pt_rv_fb_index(const pt_rv_raster_par *par, int x_vp, int y_vp, int *x_fb, int *y_fb);

/* Fill the viewport with its background as Viewport.clearVP() does: pixel
** by pixel through setPixelVP, so a viewport reaching past the framebuffer
** wraps and reports its "bad" pixels to ls (NULL: nobody); rgb NULL as for
** pt_rv_raster_prim.  Returns the number of pixels written.  This function
** can't fail. */
uint64_t pt_rv_clear_vp(const pt_rv_raster_par *par, unsigned char *rgb,
                        const pt_rv_raster_ls *ls);

/* Fill lut with the steps of byte(gamma(c)) (some 6,000 calls of pow).
** This function can't fail (lut->ok says whether the table is usable). */
void pt_rv_gamma_lut_init(pt_rv_gamma_lut *lut);

/* byte(gamma(c)) = pt_color_byte(pt_gamma(c)), through lut when it can.
** This function can't fail. */
unsigned char pt_rv_gamma_byte(const pt_rv_gamma_lut *lut, float c);

#endif
