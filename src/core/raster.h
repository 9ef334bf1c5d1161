/*
** src/core/raster.h -- draw one line segment of the pixel plane into a viewport
** See LICENSE for copyright and license.
**
** The teaching renderer's DDA, operation for operation:
**   1. round both endpoints to logical pixels (Java's Math.round);
**   2. if they coincide, the segment is the one pixel of the first endpoint;
**   3. if |dy| <= |dx|, step x = x0..x1 left to right, y starting at y0 and
**      growing by m = dy/dx each step (y += m, accumulated); else the same
**      with x and y exchanged, stepping y from bottom to top;
**   4. each step's point of the pixel plane goes through the viewport stage
**      (the caller's to_vp: pt_pixel2viewport for the classic camera, so a
**      student's stage reaches the image as it reaches the trace), giving
**      (x - 1, h - round(y)) with the reference formula;
**   5. write a pixel only when it lies inside the viewport; the others are
**      clipped and reported as runs of consecutive clipped steps;
**   6. the classic camera (the course's renderer 4) writes each step in its
**      own colour (stages/pt_color.h: interpolated, gamma-encoded, a
**      degenerate segment raw), or with anti-aliasing a pair of pixels
**      blended with the viewport's background; raster_point.c its points.
** Steps far outside the viewport's band are clipped without asking to_vp and
** skipped with an exact fast-forward of the accumulated sum (see raster.c):
** drawing costs time in proportion to the steps near the viewport, never to
** the segment's length.
*/
#ifndef PT_RASTER_H
#define PT_RASTER_H

#include <stdint.h>
#include "stages/pt_stage.h"
#include "stages/pt_color.h"
#include "core/fb.h"

#define PT_RASTER_DRAWN       0    /* stepped from end to end */
#define PT_RASTER_DEGENERATE  1    /* both ends round to one pixel: one step */
#define PT_RASTER_SKIPPED   (-1)   /* an endpoint has no integer pixel */

/* ===== the DDA's records (for a listener of steps) =====
**
** A listener of steps (pt_raster_walk()) hears, per segment, one setup
** record, then one step record for every step in step order, clipped ones
** included: the plain walk, without the fast-forward past the viewport's
** band (steps whose stepped coordinate lies beyond the range of an int, which
** the course's int loop never takes, are still skipped unreported).  The
** colours are the course's (stages/pt_color.h): each step's, gamma-encoded
** when the switch says so, is what the course's renderer writes and its log
** prints; with anti-aliasing a step is a pair of pixels. */

/* The course's colours of a segment and its rasterizer's switches (renderer
** 4, NOTES.md 11.2 and 11.4). */
typedef struct pt_raster_colors {
    float c0[3], c1[3];          /* the colours of p0 and p1, 0..1 (pt_color_float,
                                 ** or a `vcolor-float` as given) */
    int gamma;                   /* 1: gamma-encode (Rasterize.doGamma) */
    int aa;                      /* 1: anti-alias (Rasterize.doAntiAliasing) */
    int java;                    /* 1: the course's renderer 4: a segment with an
                                 ** end without an integer pixel has Java's
                                 ** (double)Math.round ends (pt_raster_java_round:
                                 ** NaN 0, an infinity +-2^63) and its loop runs
                                 ** over (int) of them; 0: such a segment is
                                 ** skipped */
    float bg[3];                 /* with aa: the viewport's background, 0..1 */
    int one;                     /* 1: c0 == c1, and c, rgb hold that colour
                                 ** gamma-encoded (pt_raster_colors_prepare) */
    float c[3];                  /* with one: the colour of every step */
    unsigned char rgb[3];        /* with one: its bytes */
} pt_raster_colors;

/* Set col->one, and with it col->c and col->rgb, from c0, c1 and gamma: a
** caller whose segments share their colours prepares them once, and the
** rasterizer does not compute them again per segment.  This function can't
** fail. */
void pt_raster_colors_prepare(pt_raster_colors *col);

/* A segment as the DDA sets it up.  s is the stepped coordinate (x when
** x-major, y when y-major), a the other one. */
typedef struct pt_raster_setup {
    int kind;                    /* PT_RASTER_DRAWN, _DEGENERATE or _SKIPPED (then
                                 ** only kind is set, the rest is 0) */
    int64_t x0, y0, x1, y1;      /* the endpoints rounded (Math.round), p0's and
                                 ** p1's, in the order given */
    int ymajor;                  /* 1: |y1 - y0| > |x1 - x0|, steps y; 0: steps x */
    int swapped;                 /* 1: the ends were exchanged, to step toward
                                 ** increasing s (then s0 is p1's) */
    int64_t s0, s1;              /* the first and last step's s, s0 <= s1 */
    double a0;                   /* a at s0 */
    double m;                    /* a's change a step: dy/dx (x-major), dx/dy
                                 ** (y-major); 0 when degenerate */
    pt_pix vp0, vp1;             /* the viewport pixels of the ends in stepping
                                 ** order, from the viewport stage */
    float c0[3], c1[3];          /* the colours of the ends in stepping order */
    double dc[3];                /* the colours' change a step (pt_color_slope) */
} pt_raster_setup;

/* One step of the DDA. */
typedef struct pt_raster_step {
    int64_t s;                   /* the stepped coordinate, a whole number */
    double a;                    /* the other one, accumulated: a0 + m + m ... */
    pt_vec2 pp;                  /* the step's point of the pixel plane: (s, a)
                                 ** x-major, (a, s) y-major */
    pt_pix vp;                   /* its viewport pixel, from the viewport stage */
    int inside;                  /* 1: inside the viewport, drawn; 0: clipped */
    float color[3];              /* the course's colour written, 0..1: gamma-
                                 ** encoded (a degenerate segment's: c0, raw) */
    pt_fb_paint paint;           /* what pipetrace writes: those bytes, and
                                 ** the share of the pixel covered */
    int aa;                      /* 1: anti-aliased: vp .. paint are the lower
                                 ** pixel's (floor(a)), the rest the upper's */
    float weight;                /* with aa: (float)(a - floor(a)) */
    pt_pix vp_hi;                /* with aa: the upper pixel (floor(a) + 1), */
    int inside_hi;               /* inside, */
    float color_hi[3];           /* its colour, */
    unsigned char rgb_hi[3];     /* and its bytes */
} pt_raster_step;

/* Who hears the DDA's records, and the colours they carry. */
typedef struct pt_raster_steps {
    void (*setup)(void *ud, const pt_raster_setup *su);    /* may be NULL */
    void (*step)(void *ud, const pt_raster_step *st);      /* may be NULL */
    void *ud;                                              /* passed back unchanged */
    void (*paint)(void *ud, int64_t x_vp, int64_t y_vp,    /* a pixel inside in its */
                  const pt_fb_paint *pa);                  /* colour, with ud, instead
                                                           ** of out->pixel; may be NULL */
    pt_raster_colors col;        /* the segment's colours and switches */
} pt_raster_steps;

/* What the rasterizer reports, in step order. */
typedef struct pt_raster_out {
    void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp);   /* a pixel inside */
    void (*clip)(void *ud, uint64_t count,                 /* a run of clipped */
                 pt_pix first, pt_pix last);               /* steps, viewport coords */
    void *ud;                                              /* passed back unchanged */
} pt_raster_out;

/* A point of the pixel plane -> its viewport pixel, with the signature of the
** viewport stages (called with a NULL sink). */
typedef pt_pix (*pt_raster_vp)(pt_vec2 pp, int w, int h, const pt_sink *sink);

/* Java's (double)Math.round(x), as the course's renderer 4 rounds a
** segment's ends and a point's centre: the nearest integer (ties up), NaN 0,
** saturated to the long range (from 2^63 on 2^63, an infinity too; below
** -2^63, -2^63).  This function can't fail. */
double pt_raster_java_round(double x);

/* Java's (int) of a double d that is a whole number or +-2^63: saturated to
** [INT_MIN, INT_MAX].  This function can't fail. */
int64_t pt_raster_java_int(double d);

/* 1 when the course's renderer 4 would never end segment p0-p1 (pixel
** plane), an end of which has no integer pixel: not degenerate, and the
** last step of its loop, (int) of the larger rounded end of the stepped
** coordinate, is INT_MAX (see below).  This function can't fail. */
int pt_raster_endless(pt_vec2 p0, pt_vec2 p1);

/* Rasterize the segment p0-p1 (pixel-plane coordinates) into a w x h viewport,
** each step's pixel found by to_vp.  Returns PT_RASTER_DRAWN or
** PT_RASTER_DEGENERATE, or PT_RASTER_SKIPPED without reporting anything when
** an endpoint is not finite or beyond PT_PIX_LIMIT.  Requires w, h >= 1.
**
** With the course's colours (col->java, pt_raster_walk and pt_raster_draw)
** no segment is skipped: a segment with an end without an integer pixel
** (not finite, or beyond PT_PIX_LIMIT) has its ends rounded as Java rounds
** them (pt_raster_java_round: a NaN end is the pixel 0, an infinite one
** +-2^63), and its steps run from (int)s0 to (int)s1 (pt_raster_java_int),
** the colours interpolated over the rounded ends s1 - s0, as the course's
** loop does (the others step in 64 bits, as pipetrace's pixel plane is:
** docs/stability.md).  Where (int)s1 is INT_MAX the course's loop `s <= (int)s1` never
** ends (s wraps to INT_MIN); pipetrace stops after that step (a cap,
** docs/renderer4.md).  The setup record's x0 .. y1 are the rounded ends
** saturated to int64_t. */
int pt_raster_segment(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_vp to_vp,
                      const pt_raster_out *out);

/* pt_raster_segment() telling ls of the DDA's records as well: the setup
** record (also of a skipped segment), then each step's, before its pixel to
** out->pixel or the clip record that counts it; the walk is the plain one,
** step by step (above).  The same pixels and clip records, the same result. */
int pt_raster_walk(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_vp to_vp,
                   const pt_raster_out *out, const pt_raster_steps *ls);

/* Told of the pixels pt_raster_draw() draws, in step order, a run of n at a
** time (a segment's pixels can come in several runs: at most
** PT_RASTER_RUN each, and one ends before each report of clipped steps to
** out->clip, so the two stay in step order). */
typedef void pt_raster_drawn(void *ud, const pt_fb_pixel *px, size_t n);

#define PT_RASTER_RUN 64

/* ===== a viewport pixel into the pixel array ===== */

/* Viewport pixel (x_vp, y_vp) into *px: the framebuffer stage
** (pt_viewport2fb, corner (x_ul, y_ul)) gives px->x_fb, y_fb, the index
** stage (pt_fb2index, a W x H framebuffer) px->idx, -1 for none; px->paint
** is left alone.  With wrap (the viewport sticks out of the framebuffer:
** pt_scene_vp_inside() 0), as the course's FrameBuffer.setPixelFB writes
** pixel_buffer[y_fb*W + x_fb] without testing x_fb against the width: a
** pixel the index stage leaves out is asked again as the pixel that index
** names, (x_fb mod W, y_fb + floor(x_fb / W)) -- an x_fb past the width
** lands in the next row, one before 0 in the row above -- and idx is -1
** only when that lies outside the array too (the course drops it and prints
** "FrameBuffer: Bad pixel coordinate (x_fb, y_fb) [w=W, h=H]").  x_fb and
** y_fb stay the framebuffer stage's.  Returns px->idx.  This function
** can't fail. */
int64_t pt_raster_fb_pixel(int64_t x_vp, int64_t y_vp, int x_ul, int y_ul, int W, int H,
                           int wrap, pt_fb_pixel *px);

/* What the classic camera draws into (pt_raster_draw): an image, a listener
** of the pixels, or both. */
typedef struct pt_raster_image {
    pt_fb *fb;                   /* the framebuffer (W x H), or NULL: no image */
    int W, H;                    /* the framebuffer's size */
    int x_ul, y_ul;              /* the viewport's upper-left corner in it */
    int wrap;                    /* 1: the viewport sticks out of it: pixels go
                                 ** where the course's index puts them
                                 ** (pt_raster_fb_pixel) */
    pt_raster_colors col;        /* the segment's colours and switches */
    uint64_t pixels;             /* pixels drawn (inside the viewport), added to */
    pt_raster_drawn *pixel;      /* told of the pixels drawn, or NULL */
    void *pixel_ud;              /* passed back to it unchanged */
} pt_raster_image;

/* pt_raster_segment() for the classic camera: each step's pixel from
** pt_pixel2viewport(), each pixel inside through pt_viewport2fb() and
** pt_fb2index() into im->fb (unless the stages put it outside the pixel
** array; with im->wrap as pt_raster_fb_pixel() puts it) and to im->pixel, counted in im->pixels; runs of clipped steps
** still go to out->clip (out->pixel is not used).  The same pixels, with the
** three stages inlined into the loop, each in the course's colour of its
** step (im->col: a segment of one colour without anti-aliasing computes it
** once); with anti-aliasing two pixels a step.  The classic camera's render. */
int pt_raster_draw(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_image *im,
                   const pt_raster_out *out);

/* ===== points (raster_point.c) ===== */

/* A point as the course's renderer 4 rasterizes it (NOTES.md 11.3): the
** pixel-plane vertex pp goes through the 2.001 map (pt_image2pixel) a second
** time, giving (x_pp, y_pp), rounded (Math.round) to the centre (cx, cy);
** then the pixels x_ = cx - r .. cx + r in rows y_ = cy - r .. cy + r, each
** at viewport pixel (x_ - 1, h - y_) and drawn iff 0 < x_ <= w and
** 0 < y_ <= h.  A negative radius has no pixels. */
typedef struct pt_raster_dot {
    double x_pp, y_pp;           /* the twice-mapped centre */
    int64_t cx, cy;              /* rounded, as Java's (int)Math.round */
    int64_t x_, y_;              /* the pixel at hand */
    pt_pix vp;                   /* its viewport pixel (x_ - 1, h - y_) */
    int inside;                  /* 1: drawn (the course's clip test) */
} pt_raster_dot;

typedef void pt_raster_dot_fn(void *ud, const pt_raster_dot *dt);

/* Visit the pixels of the point at pp of radius r in a w x h viewport, in
** the course's order, each told to fn in *dt: all (2r + 1)^2 of them when
** every (its log; at most `most` visited, the count returned either way),
** else only those inside (the image).  dt's centre is set in any case.
** Returns the number of pixels the course's loop visits (0 for r < 0), or -1
** when the centre is infinite or its loop would leave the int range (the
** course's would not end or wrap); a NaN centre rounds to 0, as in Java.  This function can't fail otherwise. */
int64_t pt_raster_point(pt_vec2 pp, int r, int w, int h, int every, int64_t most,
                        pt_raster_dot *dt, pt_raster_dot_fn *fn, void *ud);

/* y after k steps of y += m, exactly as k additions in double would leave it.
** Costs O(number of binades crossed), not O(k).  This function can't fail. */
double pt_raster_advance(double y, double m, uint64_t k);

#endif
