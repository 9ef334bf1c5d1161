/*
** src/io/tread_image.c -- read the images pipetrace diff compares: PPM (P6, P3) and PNG
** See LICENSE for copyright and license.
**
** A binary PPM is used in place (its pixels are the buffer's bytes); a plain
** PPM's decimal samples and a PNG's rows are decoded into memory of their
** own.  The PNG is read as png.h describes what pipetrace writes: stored
** deflate blocks only, every row filter.  An error is one "FILE:1:1: error:
** ..." message.
*/
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread.h"
#include "io/tread_int.h"
#include "io/png.h"

/* Write "FILE:1:1: error: ..." to err; returns -1. */
static int img_fail(char *err, size_t errlen, const char *path, const char *fmt, ...)
    PT_TR_PRINTF_LIKE(4, 5);
static int img_fail(char *err, size_t errlen, const char *path, const char *fmt, ...)
{
    va_list ap;
    int k = snprintf(err, errlen, "%s:1:1: error: ", path);
    size_t n = k < 0 ? 0 : (size_t)k;

    if (n < errlen) {
        va_start(ap, fmt);
        vsnprintf(err + n, errlen - n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

/* ===== PPM ===== */

/* Skip whitespace and '#' comments in a PPM header. */
static size_t ppm_ws(const char *b, size_t k, size_t len)
{
    while (k < len) {
        if (b[k] == '#') while (k < len && b[k] != '\n') k++;
        else if (b[k] == ' ' || b[k] == '\t' || b[k] == '\n' || b[k] == '\r') k++;
        else break;
    }
    return k;
}

/* A decimal number of a PPM header at b[*k], at most 65535. */
static int ppm_num(const char *b, size_t *k, size_t len, int *out)
{
    long v = 0;
    size_t s = *k = ppm_ws(b, *k, len);

    while (*k < len && b[*k] >= '0' && b[*k] <= '9' && v <= 65535) v = v * 10 + (b[(*k)++] - '0');
    if (*k == s || v > 65535 || (*k < len && b[*k] >= '0' && b[*k] <= '9')) return -1;
    *out = (int)v;
    return 0;
}

/* "P6 W H MAXVAL" or "P3 ...": the header of either PPM, up to the pixels. */
static int ppm_header(pt_ppm *img, const char *path, const char *buf, size_t len, size_t *k,
                      char *err, size_t errlen)
{
    *k = 2;
    if (ppm_num(buf, k, len, &img->w) || ppm_num(buf, k, len, &img->h) ||
        ppm_num(buf, k, len, &img->maxval) || img->w < 1 || img->h < 1 ||
        img->maxval < 1 || img->maxval > 255 || *k >= len ||
        (buf[*k] != ' ' && buf[*k] != '\t' && buf[*k] != '\n' && buf[*k] != '\r'))
        return img_fail(err, errlen, path, "bad %s header: expected '%s W H MAXVAL' with "
                        "sizes 1..65535 and MAXVAL 1..255", img->format, img->format);
    ++*k;                                   /* the one whitespace byte */
    return 0;
}

static int p6_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                    char *err, size_t errlen)
{
    size_t k;

    if (ppm_header(img, path, buf, len, &k, err, errlen) != 0) return -1;
    if ((len - k) / 3 / (size_t)img->w < (size_t)img->h)
        return img_fail(err, errlen, path, "the image is cut short: %d x %d pixels need "
                        "%zu bytes, the file has %zu", img->w, img->h,
                        3 * (size_t)img->w * (size_t)img->h, len - k);
    img->rgb = (const unsigned char *)buf + k;
    return 0;
}

/* Plain PPM: the samples as decimal numbers separated by whitespace. */
static int p3_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                    char *err, size_t errlen)
{
    size_t k, i, n;
    int v;

    if (ppm_header(img, path, buf, len, &k, err, errlen) != 0) return -1;
    n = 3 * (size_t)img->w * (size_t)img->h;
    if (n > (len - k + 1) / 2)              /* each sample takes a digit and a space */
        return img_fail(err, errlen, path, "%zu samples cannot fit in the %zu bytes "
                        "left: the image is cut short", n, len - k);
    if (!(img->owned = malloc(n))) return img_fail(err, errlen, path, "out of memory");
    for (i = 0; i < n; i++) {
        if (ppm_num(buf, &k, len, &v) != 0 || v > img->maxval) {
            pt_image_free(img);
            return img_fail(err, errlen, path, "sample %zu of %zu: expected a number "
                            "0..%d%s", i + 1, n, img->maxval,
                            ppm_ws(buf, k, len) >= len ? " (the image is cut short)" : "");
        }
        img->owned[i] = (unsigned char)v;
    }
    img->rgb = img->owned;
    return 0;
}

/* ===== PNG ===== */

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* The Paeth predictor of the PNG specification, section 9.4. */
static int paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);

    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Undo each row's filter in place (raw: h rows of 1 + 3w bytes) into rgb. */
static int png_unfilter(const unsigned char *raw, unsigned char *rgb, int w, int h)
{
    size_t stride = 3 * (size_t)w, x;
    int y;

    for (y = 0; y < h; y++) {
        const unsigned char *in = raw + (size_t)y * (stride + 1);
        unsigned char *out = rgb + (size_t)y * stride;
        const unsigned char *up = y ? out - stride : NULL;
        int f = in[0];

        if (f > 4) return -1;
        for (x = 0; x < stride; x++) {
            int a = x >= 3 ? out[x - 3] : 0, b = up ? up[x] : 0, c = up && x >= 3 ? up[x - 3] : 0;
            int pred = f == 1 ? a : f == 2 ? b : f == 3 ? (a + b) / 2 : f == 4 ? paeth(a, b, c) : 0;
            out[x] = (unsigned char)(in[1 + x] + pred);
        }
    }
    return 0;
}

/* A PNG as png.h describes what pipetrace writes; stored deflate blocks only
** (a compressed stream is refused: decoding Huffman codes is not worth its
** size here), every filter type. */
static int png_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                     char *err, size_t errlen)
{
    const unsigned char *b = (const unsigned char *)buf;
    unsigned char *z = NULL, *raw = NULL;
    size_t k = 8, nz = 0, nraw = 0, want = 0, zk;
    int have_ihdr = 0, ended = 0;
    const char *why = NULL;

    img->maxval = 255;
    while (!why && !ended) {                /* the chunks; IDAT data gathered in z */
        uint32_t n;
        const unsigned char *type, *data;

        if (len - k < 12) { why = "the file is cut short (no IEND chunk)"; break; }
        n = rd32(b + k);
        type = b + k + 4;
        data = b + k + 8;
        if (n > len - k - 12) { why = "a chunk runs past the end of the file"; break; }
        if (pt_crc32(pt_crc32(0, type, 4), data, n) != rd32(data + n)) {
            why = "a chunk's CRC does not match: the file is damaged";
            break;
        }
        if (!memcmp(type, "IHDR", 4)) {
            if (n != 13) { why = "bad IHDR chunk"; break; }
            if (rd32(data) < 1 || rd32(data) > 65535 || rd32(data + 4) < 1 ||
                rd32(data + 4) > 65535) { why = "sizes outside 1..65535"; break; }
            img->w = (int)rd32(data);
            img->h = (int)rd32(data + 4);
            if (data[8] != 8 || data[9] != 2 || data[10] != 0 || data[11] != 0 || data[12] != 0)
                why = "not 8-bit RGB without interlace, as pipetrace writes it";
            want = (1 + 3 * (size_t)img->w) * (size_t)img->h;
            have_ihdr = 1;
        } else if (!memcmp(type, "IDAT", 4)) {
            unsigned char *nzb;
            if (!have_ihdr) { why = "IDAT before IHDR"; break; }
            if (!(nzb = realloc(z, nz + n + 1))) { why = "out of memory"; break; }
            z = nzb;
            memcpy(z + nz, data, n);
            nz += n;
        } else if (!memcmp(type, "IEND", 4)) {
            ended = 1;
        } else if (!(type[0] & 0x20)) {
            why = "a critical chunk other than IHDR, IDAT, IEND";
        }
        k += 12 + (size_t)n;
    }
    if (!why && !have_ihdr) why = "no IHDR chunk";
    if (!why && want > nz) why = "the image data is cut short";  /* stored: raw <= nz */
    if (!why && !(raw = malloc(want))) why = "out of memory";
    /* the zlib stream: CMF FLG, then stored blocks BFINAL|BTYPE, LEN, NLEN, bytes */
    if (!why && (nz < 2 || (z[0] & 0x0f) != 8 || (z[0] << 8 | z[1]) % 31 != 0 || (z[1] & 0x20)))
        why = "bad zlib header in IDAT";
    for (zk = 2; !why; ) {
        unsigned blen;
        int final;
        if (nz - zk < 5) { why = "the image data is cut short"; break; }
        if ((z[zk] >> 1 & 3) != 0) {
            why = "its image data is compressed; pipetrace diff reads only the uncompressed "
                  "PNG that pipetrace writes (convert the image to P6 PPM, e.g. "
                  "'pngtopnm A.png > A.ppm')";
            break;
        }
        final = z[zk] & 1;
        blen = (unsigned)z[zk + 1] | (unsigned)z[zk + 2] << 8;
        if ((blen ^ ((unsigned)z[zk + 3] | (unsigned)z[zk + 4] << 8)) != 0xffffu) {
            why = "bad stored block in the image data (LEN and NLEN disagree)";
            break;
        }
        zk += 5;
        if (blen > nz - zk || blen > want - nraw) {
            why = blen > nz - zk ? "the image data is cut short"
                                 : "more image data than the size needs";
            break;
        }
        memcpy(raw + nraw, z + zk, blen);
        nraw += blen;
        zk += blen;
        if (final) break;
    }
    if (!why && nraw != want) why = "the image data is cut short";
    if (!why && (nz - zk < 4 || rd32(z + zk) != pt_adler32(1, raw, nraw)))
        why = "the image data's Adler-32 does not match: the file is damaged";
    if (!why && !(img->owned = malloc(3 * (size_t)img->w * (size_t)img->h))) why = "out of memory";
    if (!why && png_unfilter(raw, img->owned, img->w, img->h) != 0) why = "unknown row filter";
    free(z);
    free(raw);
    if (why) {
        pt_image_free(img);
        return img_fail(err, errlen, path, "PNG: %s", why);
    }
    img->rgb = img->owned;
    return 0;
}

/* ===== either ===== */

int pt_image_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                   char *err, size_t errlen)
{
    pt_tkind kind = pt_tread_kind(buf, len);

    memset(img, 0, sizeof *img);
    img->format = kind == PT_TK_PNG ? "PNG" : kind == PT_TK_P3 ? "P3" : "P6";
    if (kind == PT_TK_PPM) return p6_parse(img, path, buf, len, err, errlen);
    if (kind == PT_TK_P3) return p3_parse(img, path, buf, len, err, errlen);
    if (kind == PT_TK_PNG) return png_parse(img, path, buf, len, err, errlen);
    return img_fail(err, errlen, path, "not an image pipetrace diff reads: "
                    "%s", PT_TR_IMG_FORMATS);
}

void pt_image_free(pt_ppm *img)
{
    free(img->owned);
    img->owned = NULL;
    img->rgb = NULL;
}

