/*
** src/tools/diff/dimage.c -- pipetrace diff: two images, pixel by pixel
** See LICENSE for copyright and license.
**
** Two images (PPM P6 or P3, or PNG as pipetrace writes it) are compared
** pixel by pixel: the differing ones listed, their bounding box, and with
** --image-out a picture of them in red over EXPECTED dimmed to gray.  When
** ACTUAL is EXPECTED moved, the shift is said; with --scene, a shift by
** exactly (-x_fb, -y_fb) of viewport pixel (0, 0) (the corner (x_ul, y_ul)
** taken off every pixel) names the rasterizer's mistake that writes its
** pixels without the offset (pt_raster_mistakes, no_offset): the course's log
** prints x_vp before setPixelVP, so only the image shows it.
** A student's own log (or trace) with pixel records and the image the same
** program wrote (pt_diff_own_image): the image is what the log drew when its
** lit pixels are exactly the logged framebuffer pixels, the scene's
** background elsewhere; when they are exactly the logged viewport pixels
** (x_vp, y_vp) instead, the corner not (0, 0), the corner was forgotten in
** setPixelVP, whatever other mistake the log shows.
*/
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/outfile.h"
#include "io/png.h"
#include "tools/diff/diff.h"

/* The color of (x, y) in img, or NULL outside it. */
static const unsigned char *rgb_at(const pt_ppm *img, int x, int y)
{
    if (x >= img->w || y >= img->h) return NULL;
    return img->rgb + 3 * ((size_t)y * (size_t)img->w + (size_t)x);
}

static void print_rgb(const unsigned char *c)
{
    if (c) printf("%3d %3d %3d", c[0], c[1], c[2]);
    else printf("(outside)  ");
}

/* Write the highlight: differing pixels red, the others a's, dimmed to gray;
** PNG when path ends in ".png", else binary PPM (P6). */
static int write_highlight(const char *path, const pt_ppm *a, const pt_ppm *b, int w, int h)
{
    pt_outfile out = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];
    pt_fb fb;
    int x, y, bad;

    fb.w = w;
    fb.h = h;
    fb.rgb = malloc(3 * (size_t)w * (size_t)h);
    if (!fb.rgb) { fputs("pipetrace: out of memory\n", stderr); return -1; }
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const unsigned char *ca = rgb_at(a, x, y), *cb = rgb_at(b, x, y);
            unsigned char *p = fb.rgb + 3 * ((size_t)y * (size_t)w + (size_t)x);
            if (!ca || !cb || memcmp(ca, cb, 3) != 0) { p[0] = 255; p[1] = 0; p[2] = 0; }
            else {                          /* luma / 3: the picture stays readable */
                int g = (299 * ca[0] + 587 * ca[1] + 114 * ca[2]) / 3000;
                p[0] = p[1] = p[2] = (unsigned char)g;
            }
        }
    }
    if (pt_outfile_open(&out, path, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace: %s\n", err);
        free(fb.rgb);
        return -1;
    }
    if (pt_path_is_png(path)) {
        bad = pt_fb_write_png(&fb, out.f) != 0;
    } else {
        fprintf(out.f, "P6\n%d %d\n255\n", w, h);
        bad = fwrite(fb.rgb, 1, 3 * (size_t)w * (size_t)h, out.f) != 3 * (size_t)w * (size_t)h;
    }
    free(fb.rgb);
    return pt_outfile_finish(&out, bad || ferror(out.f), "pipetrace");
}

/* 1 when b is a moved by exactly (dx, dy): every pixel of b is a's from
** (x - dx, y - dy), or a's background (its pixel (0, 0)) where that lies
** outside a; a's pixels moved off b are gone.  Same sizes only. */
static int moved_by(const pt_ppm *a, const pt_ppm *b, int dx, int dy)
{
    const unsigned char *bg = a->rgb;
    int x, y;

    if (a->w != b->w || a->h != b->h) return 0;
    for (y = 0; y < b->h; y++)
        for (x = 0; x < b->w; x++) {
            int sx = x - dx, sy = y - dy;
            const unsigned char *want = sx >= 0 && sy >= 0 && sx < a->w && sy < a->h ?
                                        rgb_at(a, sx, sy) : bg;
            if (memcmp(rgb_at(b, x, y), want, 3)) return 0;
        }
    return 1;
}

/* 1 when b is a moved by (dx, dy) != (0, 0) (moved_by).  The shift is read
** off the boxes of the pixels that are not the background.  Same sizes
** only. */
static int image_shift(const pt_ppm *a, const pt_ppm *b, int *dx, int *dy)
{
    const unsigned char *bg = a->rgb;
    int box[2][4], k, x, y;

    if (a->w != b->w || a->h != b->h) return 0;
    for (k = 0; k < 2; k++) {
        const pt_ppm *m = k ? b : a;
        box[k][0] = m->w; box[k][1] = m->h; box[k][2] = -1; box[k][3] = -1;
        for (y = 0; y < m->h; y++)
            for (x = 0; x < m->w; x++) {
                if (!memcmp(rgb_at(m, x, y), bg, 3)) continue;
                if (x < box[k][0]) box[k][0] = x;
                if (y < box[k][1]) box[k][1] = y;
                if (x > box[k][2]) box[k][2] = x;
                if (y > box[k][3]) box[k][3] = y;
            }
        if (box[k][2] < 0) return 0;
    }
    /* the box's corner that stays inside: the upper-left one unless it moved out */
    *dx = box[1][0] - box[0][0];
    *dy = box[1][1] - box[0][1];
    if (box[1][0] == 0) *dx = box[1][2] - box[0][2];
    if (box[1][1] == 0) *dy = box[1][3] - box[0][3];
    if (*dx == 0 && *dy == 0) return 0;
    return moved_by(a, b, *dx, *dy);
}

/* 1 when the lit pixels of img (those that are not bg) are exactly the n
** pixel records of px moved by (-dx, -dy), each inside img.  mark: w * h
** bytes to work in. */
static int lit_exactly(const pt_ppm *img, const unsigned char bg[3], const pt_tpix *px,
                       size_t n, int64_t dx, int64_t dy, unsigned char *mark)
{
    size_t k, npix = (size_t)img->w * (size_t)img->h;

    memset(mark, 0, npix);
    for (k = 0; k < n; k++) {
        int64_t x = px[k].x - dx, y = px[k].y - dy;
        if (x < 0 || y < 0 || x >= img->w || y >= img->h) return 0;
        mark[(size_t)y * (size_t)img->w + (size_t)x] = 1;
    }
    for (k = 0; k < npix; k++)
        if ((memcmp(img->rgb + 3 * k, bg, 3) != 0) != mark[k]) return 0;
    return 1;
}

/* --scene's viewport corner: the framebuffer pixel of viewport pixel (0, 0),
** where the framebuffer stage puts it, into *ul.  Returns 1, 0 without
** --scene, or the exit status (2) after the message. */
static int scene_corner(const dopts *o, pt_pix *ul)
{
    pt_scene sc;
    pt_pix o0 = {0, 0, 1};
    int renderer;

    if (!o->scene) return 0;
    if (pt_cli_load(&sc, o->scene) != 0) return PT_EXIT_TROUBLE;
    renderer = sc.renderer;
    *ul = pt_viewport2fb(o0, sc.vp_x, sc.vp_y, NULL);
    pt_scene_free(&sc);
    if (renderer != 4) {
        fprintf(stderr, "pipetrace diff: %s: error: --scene with two images is for the "
                "classic camera's and the matrix camera's scenes, not renderer %d's\n",
                o->scene, renderer);
        return PT_EXIT_TROUBLE;
    }
    return 1;
}

/* The rasterizer's mistake that writes each pixel without the viewport's
** offset (setPixelVP). */
static const pt_raster_mistake *no_offset_mistake(void)
{
    size_t j;

    for (j = 0; j < PT_NRASTER_MISTAKES; j++)
        if (pt_raster_mistakes[j].no_offset) return &pt_raster_mistakes[j];
    return NULL;
}

/* What b, a (EXPECTED) moved by (dx, dy) when shifted is 1, says, the
** scene's corner ul known (known 1) or not: the mistake named when b is a
** moved by exactly (-x_ul, -y_ul), not (0, 0); a shift by anything else, or
** pixels that do not all move, name nothing (and say so when the corner is
** known). */
static void explain_shift(const dopts *o, const pt_ppm *a, const pt_ppm *b, int shifted, int dx,
                          int dy, int known, pt_pix ul)
{
    const pt_raster_mistake *mk = no_offset_mistake();
    pbuf s;

    s.n = 0;
    s.b[0] = '\0';
    if (known && mk && (ul.x || ul.y) && moved_by(a, b, (int)-ul.x, (int)-ul.y)) {
        pt_diff_add(&s, "The shift is the viewport's corner (x_ul, y_ul) = (%" PRId64 ", %" PRId64
                    ") of %s taken off every pixel. Likely mistake: %s: %s, %s.", ul.x, ul.y,
                    o->scene, mk->name, mk->where, mk->how);
        pt_diff_outcome_named(o->out, mk->name);
    } else if (known && (ul.x || ul.y)) {
        pt_diff_add(&s, "ACTUAL is not EXPECTED moved by (%" PRId64 ", %" PRId64 "), the "
                    "viewport's corner (x_ul, y_ul) = (%" PRId64 ", %" PRId64 ") of %s taken "
                    "off every pixel: no known mistake is named.", -ul.x, -ul.y, ul.x, ul.y,
                    o->scene);
    } else if (shifted && known) {
        pt_diff_add(&s, "The viewport's corner (x_ul, y_ul) of %s is (0, 0): forgetting it "
                    "moves nothing, so no known mistake is named.", o->scene);
    } else if (shifted) {
        pt_diff_add(&s, "With --scene SCENE, diff tells whether the shift is the viewport's "
                    "corner forgotten in setPixelVP: a corner (x_ul, y_ul) = (%d, %d) taken "
                    "off every pixel.", -dx, -dy);
    }
    if (s.n) pt_diff_para("", s.b);
}

int pt_diff_images(const dopts *o, const pt_ppm img[2])
{
    const pt_ppm *a = &img[0], *b = &img[1];
    int w = a->w > b->w ? a->w : b->w, h = a->h > b->h ? a->h : b->h;
    int x, y, x0 = w, y0 = h, x1 = -1, y1 = -1, k;
    size_t ndiff = 0, shown = 0;
    int differ = a->w != b->w || a->h != b->h || a->maxval != b->maxval, shifted;
    pt_pix ul = {0, 0, 0};
    int known = scene_corner(o, &ul);

    if (known == PT_EXIT_TROUBLE) return known;

    for (k = 0; k < 2; k++)
        printf("%-9s %s  (%s, %d x %d, maxval %d)\n", pt_diff_side[k], o->path[k],
               img[k].format, img[k].w, img[k].h, img[k].maxval);
    if (a->w != b->w || a->h != b->h)
        printf("The sizes differ; pixels inside one image only count as different.\n");
    if (a->maxval != b->maxval)
        printf("The maxvals differ; the color bytes are compared as they are.\n");
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const unsigned char *ca = rgb_at(a, x, y), *cb = rgb_at(b, x, y);
            if (ca && cb && memcmp(ca, cb, 3) == 0) continue;
            if (ndiff++ == 0) printf("\n");
            if (x < x0) x0 = x;
            if (x > x1) x1 = x;
            if (y < y0) y0 = y;
            if (y > y1) y1 = y;
            if (shown < o->show) {
                printf("  (%d, %d)  expected ", x, y);
                print_rgb(ca);
                printf("  actual ");
                print_rgb(cb);
                printf("\n");
                shown++;
            }
        }
    }
    o->out->images = 1;
    o->out->img_differ = ndiff;
    o->out->img_total = (size_t)w * (size_t)h;
    if (ndiff > shown) printf("  ... and %zu more\n", ndiff - shown);
    printf("\n");
    if (ndiff)
        printf("%zu of %zu pixels differ, all within the box (x, y) = (%d, %d) .. (%d, %d).\n",
               ndiff, (size_t)w * (size_t)h, x0, y0, x1, y1);
    shifted = ndiff && image_shift(a, b, &x, &y);
    if (shifted)
        printf("ACTUAL is EXPECTED moved by (%d, %d): the same picture, shifted.\n", x, y);
    if (ndiff)
        explain_shift(o, a, b, shifted, x, y, known, ul);
    else if (!ndiff && a->maxval != b->maxval)
        printf("The color bytes are the same: %d x %d pixels; the maxvals differ.\n", w, h);
    else if (!ndiff)
        printf("The images are the same: %d x %d pixels.\n", w, h);
    if (o->image_out) {
        if (write_highlight(o->image_out, a, b, w, h) != 0) return PT_EXIT_INPUT;
        printf("Highlight written to %s: differing pixels red, the others EXPECTED's in "
               "dimmed gray.\n", o->image_out);
    }
    return ndiff || differ ? PT_EXIT_DIFFER : PT_EXIT_OK;
}

int pt_diff_own_image(const dopts *o, const pt_tread *t, const pt_ppm *img)
{
    const pt_raster_mistake *mk = no_offset_mistake();
    pt_pix o0 = {0, 0, 1}, ul;
    unsigned char bg[3], *mark;
    pt_scene sc;
    int renderer, drawn, moved;
    pbuf ps;

    if (pt_cli_load(&sc, o->scene) != 0) return PT_EXIT_TROUBLE;
    renderer = sc.renderer;
    memcpy(bg, sc.background, 3);
    pt_scene_free(&sc);
    if (renderer != 4) {
        fprintf(stderr, "pipetrace diff: %s: error: --scene with a log and an image is for the "
                "classic camera's and the matrix camera's scenes, not renderer %d's\n",
                o->scene, renderer);
        return PT_EXIT_TROUBLE;
    }
    if (!t->hdr.have || !t->npx) {
        fprintf(stderr, "%s:1:1: error: no pixel records: nothing to compare the image %s "
                "with\n", o->path[0], o->path[1]);
        return PT_EXIT_TROUBLE;
    }
    ul = pt_viewport2fb(o0, t->hdr.vp_x, t->hdr.vp_y, NULL);   /* viewport pixel (0, 0) */
    if (!(mark = malloc((size_t)img->w * (size_t)img->h + 1))) return -1;
    drawn = lit_exactly(img, bg, t->px, t->npx, 0, 0, mark);
    moved = !drawn && (ul.x || ul.y) && lit_exactly(img, bg, t->px, t->npx, ul.x, ul.y, mark);
    free(mark);
    printf("%-9s %s  (%zu pixel records, corner (%" PRId64 ", %" PRId64 "))\n",
           pt_diff_side[0], o->path[0], t->npx, ul.x, ul.y);
    printf("%-9s %s  (%s, %d x %d, maxval %d)\n\n", pt_diff_side[1], o->path[1], img->format,
           img->w, img->h, img->maxval);
    o->out->images = 1;
    ps.n = 0;
    ps.b[0] = '\0';
    if (drawn) {
        pt_diff_add(&ps, "The image is what the log drew: its lit pixels are the logged "
                    "framebuffer pixels, %s's background elsewhere.", o->scene);
    } else if (moved && mk) {
        pt_diff_add(&ps, "The image's lit pixels are the logged ones at their viewport "
                    "coordinates (x_vp, y_vp), not at (x_ul + x_vp, y_ul + y_vp): the "
                    "viewport's corner (x_ul, y_ul) = (%" PRId64 ", %" PRId64 ") taken off "
                    "every pixel. Likely mistake: %s: %s, %s.", ul.x, ul.y, mk->name,
                    mk->where, mk->how);
        pt_diff_outcome_named(o->out, mk->name);
    } else {
        pt_diff_add(&ps, "The image's lit pixels are neither the logged framebuffer pixels "
                    "nor the logged viewport pixels (x_vp, y_vp) on %s's background: no "
                    "known mistake is named.", o->scene);
    }
    pt_diff_para("", ps.b);
    if (drawn) return PT_EXIT_OK;
    return PT_EXIT_DIFFER;
}
