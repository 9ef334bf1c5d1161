/*
** src/outfile.c -- output files that appear whole or not at all
** See LICENSE for copyright and license.
*/
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "outfile.h"

int pt_outfile_open(pt_outfile *o, const char *path, char *err, size_t errlen)
{
    size_t n = strlen(path);
    mode_t mask;
    int fd;

    o->path = path;
    o->tmp = NULL;
    o->f = NULL;
    if (strcmp(path, "-") == 0) { o->f = stdout; return 0; }
    o->tmp = malloc(n + 8);
    if (!o->tmp) { snprintf(err, errlen, "%s: out of memory", path); return -1; }
    memcpy(o->tmp, path, n);
    memcpy(o->tmp + n, ".XXXXXX", 8);
    fd = mkstemp(o->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        free(o->tmp); o->tmp = NULL;
        return -1;
    }
    mask = umask(0);                        /* mkstemp gives 0600; use the */
    umask(mask);                            /* permissions fopen would */
    (void)fchmod(fd, 0666 & ~mask);
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        close(fd);
        pt_outfile_abort(o);
        return -1;
    }
    return 0;
}

int pt_outfile_commit(pt_outfile *o, char *err, size_t errlen)
{
    int bad;

    if (!o->tmp) {                          /* standard output */
        if (fflush(o->f) != 0) {
            snprintf(err, errlen, "cannot write to standard output: %s", strerror(errno));
            return -1;
        }
        return 0;
    }
    bad = ferror(o->f) != 0;
    bad |= fclose(o->f) != 0;
    o->f = NULL;
    if (bad || rename(o->tmp, o->path) != 0) {
        snprintf(err, errlen, "cannot write '%s': %s", o->path,
                 errno ? strerror(errno) : "write error");
        pt_outfile_abort(o);
        return -1;
    }
    free(o->tmp);
    o->tmp = NULL;
    return 0;
}

void pt_outfile_abort(pt_outfile *o)
{
    if (o->f && o->tmp) fclose(o->f);
    o->f = NULL;
    if (o->tmp) { remove(o->tmp); free(o->tmp); }
    o->tmp = NULL;
}
