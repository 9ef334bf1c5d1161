/*
** src/core/fb.c -- the framebuffer: W x H RGB pixels, row-major, top row first
** See LICENSE for copyright and license.
*/
#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/fb.h"

int pt_fb_init(pt_fb *fb, int w, int h, const unsigned char bg[3])
{
    size_t n, k;

    assert(w > 0 && h > 0);
    n = (size_t)w * (size_t)h;
    fb->w = w; fb->h = h;
    fb->rgb = malloc(3 * n);
    if (!fb->rgb) return -1;
    if (bg[0] == bg[1] && bg[1] == bg[2]) {     /* gray (black): one byte */
        memset(fb->rgb, bg[0], 3 * n);
        return 0;
    }
    for (k = 0; k < 3; k++) fb->rgb[k] = bg[k]; /* one pixel, then doubling */
    for (k = 1; k < n; k *= 2)
        memcpy(fb->rgb + 3 * k, fb->rgb, 3 * (k < n - k ? k : n - k));
    return 0;
}

int pt_fb_write_ppm(const pt_fb *fb, FILE *f)
{
    size_t n = 3 * (size_t)fb->w * (size_t)fb->h;

    if (fprintf(f, "P6\n%d %d\n255\n", fb->w, fb->h) < 0) return -1;
    return fwrite(fb->rgb, 1, n, f) == n ? 0 : -1;
}

void pt_fb_free(pt_fb *fb)
{
    free(fb->rgb);
    fb->rgb = NULL;
}
