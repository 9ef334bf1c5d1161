/*
** src/core/fb.c -- the framebuffer: W x H RGB pixels, row-major, top row first
** See LICENSE for copyright and license.
*/
#define _POSIX_C_SOURCE 200809L     /* posix_memalign */
#define _DEFAULT_SOURCE             /* madvise */
#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif
#include "core/fb.h"

/* n bytes for the pixels.  A large framebuffer is asked for in huge pages
** where the system has them (Linux, MADV_HUGEPAGE): a 1920 x 1080 image is
** 6 MB, some 1,500 pages of 4 KiB, each a page fault when first touched, and
** on a virtual machine a fault costs microseconds; in pages of 2 MiB it is
** three.  Only speed depends on it: the bytes are the same. */
static unsigned char *pixels_alloc(size_t n)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const size_t huge = (size_t)2 << 20;
    void *p;

    if (n >= huge) {
        if (posix_memalign(&p, huge, n) != 0) return NULL;
        madvise(p, n, MADV_HUGEPAGE);       /* a hint: fine if refused */
        return p;
    }
#endif
    return malloc(n);
}

int pt_fb_init(pt_fb *fb, int w, int h, const unsigned char bg[3])
{
    size_t n, k;

    assert(w > 0 && h > 0);
    n = (size_t)w * (size_t)h;
    fb->w = w; fb->h = h;
    fb->rgb = pixels_alloc(3 * n);
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

void pt_fb_blend(pt_fb *fb, int64_t idx, const unsigned char color[3], float coverage)
{
    unsigned char *p;
    int k;

    assert(idx >= 0 && idx < (int64_t)fb->w * fb->h);
    assert(coverage >= 0.0f && coverage <= 1.0f);
    p = fb->rgb + 3 * (size_t)idx;
    for (k = 0; k < 3; k++) {
        float c = coverage * color[k] + (1.0f - coverage) * p[k];  /* in 0 .. 255 */
        p[k] = (unsigned char)(c + 0.5f);
    }
}

void pt_fb_fill(pt_fb *fb, int x, int y, int w, int h, const unsigned char color[3])
{
    int64_t npix = (int64_t)fb->w * fb->h, j, i, lo, hi;

    for (j = 0; j < h; j++) {                   /* row y + j: one run of the array */
        lo = ((int64_t)y + j) * fb->w + x;      /* pixel (x, y + j) */
        hi = lo + w;                            /* one past (x + w - 1, y + j) */
        if (lo < 0) lo = 0;
        if (hi > npix) hi = npix;
        for (i = lo; i < hi; i++) pt_fb_set(fb, i, color);
    }
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
