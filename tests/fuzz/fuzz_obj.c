/*
** tests/fuzz/fuzz_obj.c -- fuzz target: the Wavefront OBJ reader
** See LICENSE for copyright and license.
**
** pt_scene_load() reads a file whose name ends in ".obj" as a plain OBJ file,
** and only from a file: the bytes go to a file of this process's own in the
** temporary directory first.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "fuzz.h"
#include "core/pipeline.h"

int pt_fuzz_obj(const uint8_t *data, size_t size)
{
    static char path[512];
    pt_scene s;
    char err[PT_ERRLEN];
    FILE *f;
    int rc;

    if (!path[0]) {
        const char *dir = getenv("TMPDIR");
        snprintf(path, sizeof path, "%s/pt-fuzz-%ld.obj", dir && dir[0] ? dir : "/tmp",
                 (long)getpid());
    }
    if (!(f = fopen(path, "wb"))) return 0;      /* no room to test in: not the reader's fault */
    rc = fwrite(data, 1, size, f) == size;
    if (fclose(f) != 0 || !rc) { remove(path); return 0; }
    err[0] = '\0';
    if (pt_scene_load(&s, path, err, sizeof err) != 0) rc = pt_fuzz_message_ok(err, path) ? 1 : -1;
    else { rc = s.from_obj == 1 && s.nmodels == 1 ? 0 : -1; pt_scene_free(&s); }
    remove(path);
    return rc;
}

PT_FUZZ_TARGET(pt_fuzz_obj)
