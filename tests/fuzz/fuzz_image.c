/*
** tests/fuzz/fuzz_image.c -- fuzz target: the image reader (P6, P3, PNG)
** See LICENSE for copyright and license.
**
** The bytes, NUL-terminated as pt_tread_file() leaves them, go to
** pt_image_parse().  An image read has w x h pixels and every one of its
** 3*w*h bytes is read here, so that a short buffer shows under the
** sanitizers.
*/
#include <stdlib.h>
#include <string.h>
#include "fuzz.h"
#include "io/tread.h"

static volatile unsigned sink;

int pt_fuzz_image(const uint8_t *data, size_t size)
{
    pt_ppm img;
    char err[1024], *buf = malloc(size + 1);
    int rc;

    if (!buf) return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    err[0] = '\0';
    if (pt_image_parse(&img, "fuzz", buf, size, err, sizeof err) != 0) {
        rc = pt_fuzz_message_ok(err, "fuzz") && img.owned == NULL ? 1 : -1;
    } else {
        size_t n = 3 * (size_t)img.w * (size_t)img.h, k;
        unsigned sum = 0;
        rc = img.w >= 1 && img.h >= 1 && img.maxval >= 1 && img.maxval <= 255 && img.rgb ? 0 : -1;
        for (k = 0; rc == 0 && k < n; k++) sum += img.rgb[k];
        sink = sum;                     /* so that the reads stay */
        pt_image_free(&img);
    }
    free(buf);
    return rc;
}

PT_FUZZ_TARGET(pt_fuzz_image)
