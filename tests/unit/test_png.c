/*
** tests/unit/test_png.c -- the PNG writer: checksums, chunks, stored deflate blocks
** See LICENSE for copyright and license.
**
** The checksums against their published check values; a framebuffer written
** as PNG and read back here, chunk by chunk, block by block, without zlib.
*/
#include <stdlib.h>
#include <string.h>
#include "io/png.h"
#include "testhelp.h"

static uint32_t rd32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Write fb to memory as PNG, parse it back; 1 when every check holds. */
static int roundtrip(const pt_fb *fb, unsigned *nblocks)
{
    FILE *f = tmpfile();
    unsigned char *b, *raw, *z = NULL;
    long n;
    size_t pos = 8, zn = 0, rawn = 0, k, rowlen = 1 + 3 * (size_t)fb->w;
    int ok = 1, seen_end = 0, final = 0;

    if (!f || pt_fb_write_png(fb, f) != 0) return 0;
    n = ftell(f);
    rewind(f);
    b = malloc((size_t)n);
    if (!b || fread(b, 1, (size_t)n, f) != (size_t)n) return 0;
    fclose(f);
    ok &= memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0;
    while (ok && pos + 12 <= (size_t)n) {
        uint32_t len = rd32(b + pos);
        const unsigned char *type = b + pos + 4, *d = b + pos + 8;
        ok &= pos + 12 + len <= (size_t)n;
        if (!ok) break;
        ok &= rd32(d + len) == pt_crc32(0, type, 4 + (size_t)len);
        if (!memcmp(type, "IHDR", 4))
            ok &= len == 13 && rd32(d) == (uint32_t)fb->w && rd32(d + 4) == (uint32_t)fb->h &&
                  d[8] == 8 && d[9] == 2 && d[10] == 0 && d[11] == 0 && d[12] == 0;
        if (!memcmp(type, "IDAT", 4)) {
            unsigned char *nz = realloc(z, zn + len + 1);
            if (!nz) return 0;
            z = nz;
            memcpy(z + zn, d, len);
            zn += len;
        }
        if (!memcmp(type, "IEND", 4)) { seen_end = 1; ok &= len == 0 && pos + 12 == (size_t)n; }
        pos += 12 + len;
    }
    ok &= seen_end && zn >= 6;
    if (!ok) return 0;
    ok &= z[0] == 0x78 && (z[0] * 256 + z[1]) % 31 == 0;
    raw = malloc(rowlen * (size_t)fb->h + 1);
    if (!raw) return 0;
    *nblocks = 0;
    for (k = 2; ok && !final; ) {                /* stored blocks only */
        unsigned len, nlen;
        ok &= k + 5 <= zn && (z[k] & 6) == 0;
        if (!ok) break;
        final = z[k] & 1;
        len = z[k + 1] | (unsigned)z[k + 2] << 8;
        nlen = z[k + 3] | (unsigned)z[k + 4] << 8;
        ok &= (len ^ 0xffffu) == nlen && k + 5 + len <= zn && rawn + len <= rowlen * (size_t)fb->h;
        if (!ok) break;
        memcpy(raw + rawn, z + k + 5, len);
        rawn += len;
        k += 5 + len;
        (*nblocks)++;
    }
    ok &= rawn == rowlen * (size_t)fb->h && k + 4 == zn;
    ok &= ok && rd32(z + k) == pt_adler32(1, raw, rawn);
    for (k = 0; ok && k < (size_t)fb->h; k++)
        ok &= raw[k * rowlen] == 0 &&
              memcmp(raw + k * rowlen + 1, fb->rgb + k * 3 * (size_t)fb->w, 3 * (size_t)fb->w) == 0;
    free(raw);
    free(z);
    free(b);
    return ok;
}

int main(void)
{
    static const unsigned char bg[3] = {24, 24, 40}, red[3] = {255, 0, 0};
    pt_fb fb;
    unsigned blocks = 0;
    size_t k;

    PT_CHECK("png-1.1 CRC-32 check value", pt_crc32(0, "123456789", 9) == 0xcbf43926u);
    PT_CHECK("png-1.2 CRC-32 of nothing", pt_crc32(0, "", 0) == 0);
    PT_CHECK("png-1.3 CRC-32 continues", pt_crc32(pt_crc32(0, "1234", 4), "56789", 5) == 0xcbf43926u);
    PT_CHECK("png-1.4 CRC-32 of IEND", pt_crc32(0, "IEND", 4) == 0xae426082u);
    PT_CHECK("png-1.5 Adler-32 check value", pt_adler32(1, "Wikipedia", 9) == 0x11e60398u);
    PT_CHECK("png-1.6 Adler-32 of nothing", pt_adler32(1, "", 0) == 1);
    {
        unsigned char *ff = malloc(100000);        /* past the 5552-byte reduction */
        uint32_t a = 1, s1 = 1, s2 = 0;
        if (ff) {
            memset(ff, 0xff, 100000);
            for (k = 0; k < 100000; k++) { s1 = (s1 + 0xff) % 65521; s2 = (s2 + s1) % 65521; }
            a = pt_adler32(1, ff, 100000);
            free(ff);
        }
        PT_CHECK("png-1.7 Adler-32 of 100000 bytes 0xff", a == (s2 << 16 | s1));
    }

    PT_CHECK("png-2.1 .png in any case", pt_path_is_png("a.png") && pt_path_is_png("A.PNG") &&
             pt_path_is_png(".Png"));
    PT_CHECK("png-2.2 not .png", !pt_path_is_png("a.ppm") && !pt_path_is_png("png") &&
             !pt_path_is_png("a.png.ppm") && !pt_path_is_png(""));

    if (pt_fb_init(&fb, 1, 1, bg) == 0) {
        PT_CHECK("png-3.1 1 x 1 reads back", roundtrip(&fb, &blocks) && blocks == 1);
        pt_fb_free(&fb);
    }
    if (pt_fb_init(&fb, 7, 5, bg) == 0) {
        pt_fb_set(&fb, 0, red);
        pt_fb_set(&fb, 34, red);
        PT_CHECK("png-3.2 7 x 5 reads back", roundtrip(&fb, &blocks) && blocks == 1);
        pt_fb_free(&fb);
    }
    /* 400 x 300: 360300 raw bytes, six blocks, rows split across blocks */
    if (pt_fb_init(&fb, 400, 300, bg) == 0) {
        for (k = 0; k < 400 * 300; k += 7) pt_fb_set(&fb, (int64_t)k, red);
        PT_CHECK("png-3.3 400 x 300 reads back in 6 blocks", roundtrip(&fb, &blocks) && blocks == 6);
        pt_fb_free(&fb);
    }
    if (pt_fb_init(&fb, 21844, 1, bg) == 0) {   /* 1 + 3 * 21844 = 65533 bytes */
        PT_CHECK("png-3.4 a row just under one block", roundtrip(&fb, &blocks) && blocks == 1);
        pt_fb_free(&fb);
    }
    if (pt_fb_init(&fb, 10922, 2, bg) == 0) {   /* 2 * (1 + 32766) = 65534 */
        PT_CHECK("png-3.5 two rows in one block", roundtrip(&fb, &blocks) && blocks == 1);
        pt_fb_free(&fb);
    }
    if (pt_fb_init(&fb, 5, 4369, bg) == 0) {    /* 4369 * 16 = 69904: two blocks */
        PT_CHECK("png-3.6 two blocks", roundtrip(&fb, &blocks) && blocks == 2);
        pt_fb_free(&fb);
    }
    return pt_test_report();
}
