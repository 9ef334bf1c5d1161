/*
** src/io/png.c -- the framebuffer as a PNG file, written without a library
** See LICENSE for copyright and license.
**
** See png.h for the layout.  The rows are streamed: a 64 KiB block is filled
** from the framebuffer, checksummed and written, so no second copy of the
** image is ever held in memory.
*/
#include <stdlib.h>
#include <string.h>
#include "io/png.h"

#define BLOCK_MAX 65535u         /* the largest stored deflate block (LEN is 16 bits) */

/* ===== checksums ===== */

uint32_t pt_crc32(uint32_t crc, const void *p, size_t n)
{
    static uint32_t table[256];
    static int ready;
    const unsigned char *b = p;
    size_t k;

    if (!ready) {
        uint32_t c, i;
        int bit;
        for (i = 0; i < 256; i++) {
            c = i;
            for (bit = 0; bit < 8; bit++)
                c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
        ready = 1;
    }
    crc = ~crc;
    for (k = 0; k < n; k++)
        crc = table[(crc ^ b[k]) & 0xffu] ^ (crc >> 8);
    return ~crc;
}

uint32_t pt_adler32(uint32_t adler, const void *p, size_t n)
{
    const unsigned char *b = p;
    uint32_t s1 = adler & 0xffffu, s2 = adler >> 16;
    size_t k;

    for (k = 0; k < n; ) {
        size_t run = n - k < 5552 ? n - k : 5552;   /* 5552: no uint32 overflow (zlib) */
        for (; run; run--, k++) { s1 += b[k]; s2 += s1; }
        s1 %= 65521u;
        s2 %= 65521u;
    }
    return (s2 << 16) | s1;
}

/* ===== chunks ===== */

static void be32(unsigned char *o, uint32_t v)
{
    o[0] = (unsigned char)(v >> 24); o[1] = (unsigned char)(v >> 16);
    o[2] = (unsigned char)(v >> 8);  o[3] = (unsigned char)v;
}

/* Write one chunk: length, type, the n data bytes at d, CRC of type + data. */
static int chunk(FILE *f, const char *type, const unsigned char *d, size_t n)
{
    unsigned char b[4];
    uint32_t crc = pt_crc32(0, type, 4);

    crc = pt_crc32(crc, d, n);
    be32(b, (uint32_t)n);
    if (fwrite(b, 1, 4, f) != 4 || fwrite(type, 1, 4, f) != 4) return -1;
    if (n && fwrite(d, 1, n, f) != n) return -1;
    be32(b, crc);
    return fwrite(b, 1, 4, f) == 4 ? 0 : -1;
}

/* ===== the image ===== */

int pt_fb_write_png(const pt_fb *fb, FILE *f)
{
    static const unsigned char sig[8] = {137, 'P', 'N', 'G', '\r', '\n', 26, '\n'};
    unsigned char *buf;
    unsigned char ihdr[13];
    size_t rowlen = 1 + 3 * (size_t)fb->w;            /* filter byte + RGB */
    uint64_t total = (uint64_t)rowlen * (uint64_t)fb->h, done = 0;
    size_t row = 0, col = 0;                           /* next raw byte: row, offset */
    uint32_t adler = 1;
    int rc = 0;

    if (fwrite(sig, 1, 8, f) != 8) return -1;
    be32(ihdr, (uint32_t)fb->w);
    be32(ihdr + 4, (uint32_t)fb->h);
    ihdr[8] = 8;                 /* bit depth */
    ihdr[9] = 2;                 /* color type: RGB */
    ihdr[10] = 0;                /* compression: deflate */
    ihdr[11] = 0;                /* filter method 0 */
    ihdr[12] = 0;                /* no interlace */
    if (chunk(f, "IHDR", ihdr, sizeof ihdr) != 0) return -1;
    /* room for the zlib header, a block header, a full block and the Adler-32 */
    buf = malloc(2 + 5 + BLOCK_MAX + 4);
    if (!buf) return -1;

    for (;;) {                   /* total >= 2: w, h >= 1 */
        size_t n = 0, k, len;
        uint64_t left = total - done;
        unsigned blk = left > BLOCK_MAX ? BLOCK_MAX : (unsigned)left;
        int last = (uint64_t)blk == left;
        unsigned char *d;

        if (done == 0) {         /* zlib header: deflate, 32K window, no dictionary */
            buf[n++] = 0x78;     /* CMF: CM 8, CINFO 7 */
            buf[n++] = 0x01;     /* FLG: (0x78 * 256 + 0x01) % 31 == 0, level 0 */
        }
        buf[n++] = (unsigned char)(last ? 1 : 0);       /* BFINAL, BTYPE 00 */
        buf[n++] = (unsigned char)(blk & 0xffu);        /* LEN, little-endian */
        buf[n++] = (unsigned char)(blk >> 8);
        buf[n++] = (unsigned char)(~blk & 0xffu);       /* NLEN = ~LEN */
        buf[n++] = (unsigned char)((~blk >> 8) & 0xffu);
        d = buf + n;
        for (k = 0; k < blk; k += len) {                /* copy raw row bytes */
            if (col == 0) { d[k] = 0; col = 1; len = 1; continue; }  /* filter: none */
            len = rowlen - col < blk - k ? rowlen - col : blk - k;
            memcpy(d + k, fb->rgb + row * (rowlen - 1) + (col - 1), len);
            col += len;
            if (col == rowlen) { col = 0; row++; }
        }
        adler = pt_adler32(adler, d, blk);
        n += blk;
        done += blk;
        if (last) { be32(buf + n, adler); n += 4; }
        if (chunk(f, "IDAT", buf, n) != 0) { rc = -1; break; }
        if (last) break;
    }
    free(buf);
    return rc != 0 ? -1 : chunk(f, "IEND", NULL, 0);
}

int pt_path_is_png(const char *path)
{
    size_t n = strlen(path);
    const char *e = path + n - 4;

    return n >= 4 && e[0] == '.' && (e[1] | 0x20) == 'p' && (e[2] | 0x20) == 'n' &&
           (e[3] | 0x20) == 'g';
}
