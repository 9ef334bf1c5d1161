/*
** src/io/png.h -- the framebuffer as a PNG file, written without a library
** See LICENSE for copyright and license.
**
** A PNG file is the 8-byte signature and a list of chunks, each
** length (4 bytes, big-endian) | type (4 ASCII bytes) | data | CRC-32 of type+data.
** pipetrace writes IHDR (size, 8-bit RGB, no interlace), IDAT and IEND.  The
** image data is a zlib stream (RFC 1950) of the rows, each row one filter
** byte 0 ("none") followed by its 3*W bytes; the stream uses stored deflate
** blocks (RFC 1951, BTYPE 00: LEN, NLEN, raw bytes, at most 65535 a block), so
** nothing is compressed and the file is about as large as the PPM.  The
** stream ends with the Adler-32 of the rows.  Each deflate block goes into
** its own IDAT chunk.
*/
#ifndef PT_PNG_H
#define PT_PNG_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "core/pipetrace.h"

/* CRC-32 of ISO 3309 / ITU-T V.42 (polynomial 0xedb88320, reflected), as PNG
** and zlib use it, continued from crc over n bytes at p.  Start with crc = 0;
** pt_crc32(0, "123456789", 9) == 0xcbf43926.  This function can't fail. */
uint32_t pt_crc32(uint32_t crc, const void *p, size_t n);

/* Adler-32 of RFC 1950, continued from adler over n bytes at p.  Start with
** adler = 1; pt_adler32(1, "Wikipedia", 9) == 0x11e60398.  Can't fail. */
uint32_t pt_adler32(uint32_t adler, const void *p, size_t n);

/* Write fb as a PNG file (8-bit RGB, uncompressed) to the open stream f.
** Returns 0, or -1 when a write failed (errno). */
int pt_fb_write_png(const pt_fb *fb, FILE *f);

/* 1 when path ends in ".png", in any case; 0 otherwise.  Can't fail. */
int pt_path_is_png(const char *path);

#endif
