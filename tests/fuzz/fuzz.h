/*
** tests/fuzz/fuzz.h -- the four fuzz targets: scene, OBJ, trace and image readers
** See LICENSE for copyright and license.
**
** Each target takes any bytes and returns 0 when the reader accepted them, 1
** when it refused them with one "NAME:LINE:COL: error: ..." line, and -1 when
** it broke a promise (a silent or malformed refusal, a record out of place).
** A crash, a leak or undefined behaviour shows under the sanitizers.  Two drivers call them:
** libFuzzer (`make fuzz`, clang: each file's LLVMFuzzerTestOneInput() under
** PT_LIBFUZZER) and tests/unit/test_fuzz.c, which replays the regression corpus
** tests/fuzz/corpus/TARGET/ in `make test` with any compiler.
*/
#ifndef PT_FUZZ_H
#define PT_FUZZ_H

#include <stddef.h>
#include <stdint.h>

int pt_fuzz_scene(const uint8_t *data, size_t size);   /* pt_scene_parse(), then the run */
int pt_fuzz_obj(const uint8_t *data, size_t size);     /* pt_scene_load() of a .obj file */
int pt_fuzz_trace(const uint8_t *data, size_t size);   /* pt_tread_parse() */
int pt_fuzz_image(const uint8_t *data, size_t size);   /* pt_image_parse() */

/* 1 when err is one line "NAME:LINE:COL: error: ..." for the file name,
** with LINE and COL >= 1. */
int pt_fuzz_message_ok(const char *err, const char *name);

/* LLVMFuzzerTestOneInput() for target fn: a broken promise aborts, which
** libFuzzer reports as a finding. */
#ifdef PT_LIBFUZZER
#include <stdlib.h>
#define PT_FUZZ_TARGET(fn)                                                  \
    int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);           \
    int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)            \
    {                                                                       \
        if (fn(data, size) < 0) abort();                                    \
        return 0;                                                           \
    }
#else
#define PT_FUZZ_TARGET(fn)
#endif

#endif
