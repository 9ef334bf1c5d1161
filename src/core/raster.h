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
**      clipped and reported as runs of consecutive clipped steps.
** Steps far outside the viewport's band are clipped without asking to_vp and
** skipped with an exact fast-forward of the accumulated sum (see raster.c):
** drawing costs time in proportion to the steps near the viewport, never to
** the segment's length.
*/
#ifndef PT_RASTER_H
#define PT_RASTER_H

#include <stdint.h>
#include "stages/pt_stage.h"
#include "core/fb.h"

/* What the rasterizer reports, in step order. */
typedef struct pt_raster_out {
    void (*pixel)(void *ud, int64_t x_vp, int64_t y_vp);   /* a pixel inside */
    void (*clip)(void *ud, uint64_t count,                 /* a run of clipped */
                 pt_pix first, pt_pix last);               /* steps, viewport coords */
    void *ud;                                              /* passed back unchanged */
} pt_raster_out;

#define PT_RASTER_DRAWN       0    /* stepped from end to end */
#define PT_RASTER_DEGENERATE  1    /* both ends round to one pixel: one step */
#define PT_RASTER_SKIPPED   (-1)   /* an endpoint has no integer pixel */

/* A point of the pixel plane -> its viewport pixel, with the signature of the
** viewport stages (called with a NULL sink). */
typedef pt_pix (*pt_raster_vp)(pt_vec2 pp, int w, int h, const pt_sink *sink);

/* Rasterize the segment p0-p1 (pixel-plane coordinates) into a w x h viewport,
** each step's pixel found by to_vp.  Returns PT_RASTER_DRAWN or
** PT_RASTER_DEGENERATE, or PT_RASTER_SKIPPED without reporting anything when
** an endpoint is not finite or beyond PT_PIX_LIMIT.  Requires w, h >= 1. */
int pt_raster_segment(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_vp to_vp,
                      const pt_raster_out *out);

/* Told of the pixels pt_raster_draw() draws, in step order, a run of n at a
** time (a segment's pixels can come in several runs: at most
** PT_RASTER_RUN each, and one ends before each report of clipped steps to
** out->clip, so the two stay in step order). */
typedef void pt_raster_drawn(void *ud, const pt_fb_pixel *px, size_t n);

#define PT_RASTER_RUN 64

/* What the classic camera draws into (pt_raster_draw): an image, a listener
** of the pixels, or both. */
typedef struct pt_raster_image {
    pt_fb *fb;                   /* the framebuffer (W x H), or NULL: no image */
    int W, H;                    /* the framebuffer's size */
    int x_ul, y_ul;              /* the viewport's upper-left corner in it */
    const unsigned char *color;  /* the segment's color, RGB */
    uint64_t pixels;             /* pixels drawn (inside the viewport), added to */
    pt_raster_drawn *pixel;      /* told of the pixels drawn, or NULL */
    void *pixel_ud;              /* passed back to it unchanged */
} pt_raster_image;

/* pt_raster_segment() for the classic camera: each step's pixel from
** pt_pixel2viewport(), each pixel inside through pt_viewport2fb() and
** pt_fb2index() into im->fb (unless the stages put it outside the pixel
** array) and to im->pixel, counted in im->pixels; runs of clipped steps
** still go to out->clip (out->pixel is not used).  The same pixels, with the
** three stages inlined into the loop: the classic camera's render. */
int pt_raster_draw(pt_vec2 p0, pt_vec2 p1, int w, int h, pt_raster_image *im,
                   const pt_raster_out *out);

/* y after k steps of y += m, exactly as k additions in double would leave it.
** Costs O(number of binades crossed), not O(k).  This function can't fail. */
double pt_raster_advance(double y, double m, uint64_t k);

#endif
