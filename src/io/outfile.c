/*
** src/io/outfile.c -- output files that appear whole or not at all
** See LICENSE for copyright and license.
*/
#define _XOPEN_SOURCE 700             /* realpath(), with POSIX.1-2008 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "io/outfile.h"

static int fail(pt_outfile *o, char *err, size_t errlen, const char *why)
{
    snprintf(err, errlen, "cannot write '%s': %s", o->path, why);
    pt_outfile_abort(o);
    return -1;
}

/* The file to replace by rename: path itself, or the file a link names.
** NULL with *direct = 1 when something other than a regular file is there
** (write to it directly); NULL with *direct = 0 when out of memory. */
static char *replace_target(const char *path, int *direct)
{
    struct stat st;
    char *t;

    *direct = 0;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {     /* FIFO, device, ... */
        *direct = 1;                        /* (a directory fails at fopen) */
        return NULL;
    }
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        t = realpath(path, NULL);           /* NULL: a dangling link */
        if (!t) *direct = 1;
        return t;
    }
    t = malloc(strlen(path) + 1);
    if (t) strcpy(t, path);
    return t;
}

int pt_outfile_open(pt_outfile *o, const char *path, char *err, size_t errlen)
{
    size_t n;
    mode_t mask;
    int fd, direct;

    o->path = path;
    o->target = o->tmp = NULL;
    o->f = NULL;
    if (strcmp(path, "-") == 0) { o->f = stdout; return 0; }
    o->target = replace_target(path, &direct);
    if (direct) {
        o->f = fopen(path, "wb");
        return o->f ? 0 : fail(o, err, errlen, strerror(errno));
    }
    if (!o->target) return fail(o, err, errlen, "out of memory");
    n = strlen(o->target);
    o->tmp = malloc(n + 8);
    if (!o->tmp) return fail(o, err, errlen, "out of memory");
    memcpy(o->tmp, o->target, n);
    memcpy(o->tmp + n, ".XXXXXX", 8);
    fd = mkstemp(o->tmp);
    if (fd < 0) {
        int e = errno;
        free(o->tmp); o->tmp = NULL;        /* nothing to remove */
        return fail(o, err, errlen, strerror(e));
    }
    mask = umask(0);                        /* mkstemp gives 0600; use the */
    umask(mask);                            /* permissions fopen would */
    (void)fchmod(fd, 0666 & ~mask);
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        int e = errno;
        close(fd);
        return fail(o, err, errlen, strerror(e));
    }
    return 0;
}

int pt_outfile_commit(pt_outfile *o, char *err, size_t errlen)
{
    int bad;

    if (o->f == stdout) {
        if (fflush(o->f) != 0) {
            snprintf(err, errlen, "cannot write to standard output: %s", strerror(errno));
            return -1;
        }
        return 0;
    }
    errno = 0;
    bad = ferror(o->f) != 0;
    bad |= fclose(o->f) != 0;
    o->f = NULL;
    if (!bad && o->tmp && rename(o->tmp, o->target) != 0) bad = 1;
    if (bad) return fail(o, err, errlen, errno ? strerror(errno) : "write error");
    free(o->tmp);                           /* renamed: nothing to remove */
    o->tmp = NULL;
    pt_outfile_abort(o);                    /* frees the target's name */
    return 0;
}

void pt_outfile_abort(pt_outfile *o)
{
    if (o->f && o->f != stdout) fclose(o->f);
    o->f = NULL;
    if (o->tmp) { remove(o->tmp); free(o->tmp); }
    free(o->target);
    o->tmp = o->target = NULL;
}

int pt_outfile_finish(pt_outfile *o, int bad, const char *who)
{
    char err[512];

    if (bad) {
        fprintf(stderr, "%s: cannot write '%s'\n", who, o->path);
        pt_outfile_abort(o);
        return -1;
    }
    if (pt_outfile_commit(o, err, sizeof err) != 0) {
        fprintf(stderr, "%s: %s\n", who, err);
        return -1;
    }
    return 0;
}
