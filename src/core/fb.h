/*
** src/core/fb.h -- the framebuffer: W x H RGB pixels, row-major, top row first
** See LICENSE for copyright and license.
*/
#ifndef PT_FB_H
#define PT_FB_H

#include <assert.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct pt_fb {
    int w, h;                    /* size in pixels, 1..PT_MAX_SIZE */
    unsigned char *rgb;          /* 3*w*h bytes; pixel idx at rgb[3*idx]; owned */
} pt_fb;

/* A pixel drawn, as the framebuffer and index stages name it: (x_fb, y_fb)
** and its place in the pixel array, idx (none when outside 0 .. w*h - 1: a
** student's stage can put it there); the colour written there and the share
** of the pixel the segment covers (1: all of it; an anti-aliasing rasterizer
** writes a pair of pixels whose coverages add up to 1). */
typedef struct pt_fb_paint {
    unsigned char rgb[3];        /* the colour written */
    float coverage;              /* 0 .. 1 */
} pt_fb_paint;

typedef struct pt_fb_pixel {
    int64_t x_fb, y_fb, idx;
    pt_fb_paint paint;           /* what was written there (one 8-byte copy
                                 ** for a rasterizer that writes a segment's
                                 ** pixels alike) */
} pt_fb_pixel;

/* Allocate a w x h framebuffer filled with bg.  Returns 0, or -1 when out of
** memory (then fb->rgb is NULL). */
int pt_fb_init(pt_fb *fb, int w, int h, const unsigned char bg[3]);

/* Set pixel idx (0 <= idx < w*h) to color.  This function can't fail.
** Inline: the rasterizer calls it for every pixel it draws. */
static inline void pt_fb_set(pt_fb *fb, int64_t idx, const unsigned char color[3])
{
    unsigned char *p;

    assert(idx >= 0 && idx < (int64_t)fb->w * fb->h);
    p = fb->rgb + 3 * (size_t)idx;
    p[0] = color[0]; p[1] = color[1]; p[2] = color[2];
}

/* Blend color into pixel idx (0 <= idx < w*h) with weight coverage in 0 .. 1:
** each component becomes round(coverage * color + (1 - coverage) * old), in
** float arithmetic, halves up; coverage 1 writes color as pt_fb_set().  For a
** rasterizer that blends with what is drawn (the course's renderers blend
** with the background colour instead, and write).  This function can't fail. */
void pt_fb_blend(pt_fb *fb, int64_t idx, const unsigned char color[3], float coverage);

/* Fill the w x h rectangle whose upper-left corner is (x, y) with color, as
** the course's Viewport.clearVP does, pixel by pixel through setPixelFB:
** pixel (x + i, y + j) is the array's pixel (y + j)*W + x + i when that lies
** in 0 .. W*H - 1 (an x + i past the width lands in the next row, before 0
** in the row above; the others are dropped).  A rectangle inside fb is
** just that rectangle.  |x|, |y|, w, h <= 2^30.  This function can't fail. */
void pt_fb_fill(pt_fb *fb, int x, int y, int w, int h, const unsigned char color[3]);

/* Write fb as binary PPM (P6) to the open stream f.  Returns 0 or -1 (errno). */
int pt_fb_write_ppm(const pt_fb *fb, FILE *f);

/* Free the pixels.  This function can't fail. */
void pt_fb_free(pt_fb *fb);

#endif
