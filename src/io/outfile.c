/*
** src/io/outfile.c -- output files that appear whole or not at all
** See LICENSE for copyright and license.
*/
#define _GNU_SOURCE                   /* O_TMPFILE where Linux has it; POSIX.1-2008 */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "io/outfile.h"

/* How a file is replaced (see outfile.h):
**   RENAME   a temporary file in the target's directory, renamed onto it
**   COPY     a temporary file anywhere, copied into the target at the end
**   INPLACE  the target itself, emptied at open (no temporary file at all
**            could be made: the last resort) */
enum { RENAME, COPY, INPLACE };

struct pt_outfile_state {
    int how;                     /* RENAME, COPY, INPLACE */
    char *dir;                   /* the target's directory, owned */
    char *tmp;                   /* a named temporary file in dir, owned, or NULL */
    int dest;                    /* COPY: the target open for writing, else -1 */
    int created;                 /* COPY, INPLACE: the target was made here, so
                                 ** it goes away when the output does */
    int slot;                    /* its place in doomed[], or -1 */
    int have_old;                /* 1: a file is replaced, and */
    struct stat old;             /*   this is what it was */
};

/* ===== names to remove on a signal ===== */

/* Named temporary files, and targets made here, that a signal must not leave
** behind.  The handler removes them, then lets the signal do what it would
** have done.  A signal that was ignored when the first file was registered
** stays ignored. */
#define NDOOMED 8
static const char *volatile doomed[NDOOMED];
static int handlers_set;
static const int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
#define NSIGNALS (sizeof cleanup_signals / sizeof cleanup_signals[0])

static void on_signal(int sig)
{
    int k;

    for (k = 0; k < NDOOMED; k++)
        if (doomed[k]) unlink(doomed[k]);           /* async-signal-safe */
    signal(sig, SIG_DFL);
    raise(sig);                     /* delivered when the handler returns */
}

/* Hold the signals above off (the old mask into *old); release() lets them in. */
static void hold(sigset_t *old)
{
    sigset_t set;
    size_t k;

    sigemptyset(&set);
    for (k = 0; k < NSIGNALS; k++) sigaddset(&set, cleanup_signals[k]);
    sigprocmask(SIG_BLOCK, &set, old);
}

static void release(const sigset_t *old) { sigprocmask(SIG_SETMASK, old, NULL); }

/* Register name (which must live until spare()) for removal on a signal.
** Returns its slot, or -1 when all are taken (then it is not removed). */
static int doom(const char *name)
{
    sigset_t old;
    size_t k;
    int slot = -1;

    hold(&old);
    if (!handlers_set) {
        struct sigaction sa, prev;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        for (k = 0; k < NSIGNALS; k++) {
            if (sigaction(cleanup_signals[k], NULL, &prev) == 0 && prev.sa_handler == SIG_IGN)
                continue;
            sigaction(cleanup_signals[k], &sa, NULL);
        }
        handlers_set = 1;
    }
    for (k = 0; k < NDOOMED; k++)
        if (!doomed[k]) { doomed[k] = name; slot = (int)k; break; }
    release(&old);
    return slot;
}

static void spare(int slot)
{
    sigset_t old;

    if (slot < 0) return;
    hold(&old);
    doomed[slot] = NULL;
    release(&old);
}

/* ===== opening ===== */

static int fail(pt_outfile *o, char *err, size_t errlen, const char *why)
{
    snprintf(err, errlen, "cannot write '%s': %s", o->path, why);
    pt_outfile_abort(o);
    return -1;
}

/* A copy of s, or NULL when out of memory. */
static char *dup_str(const char *s, size_t n)
{
    char *t = malloc(n + 1);

    if (t) { memcpy(t, s, n); t[n] = '\0'; }
    return t;
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
    return dup_str(path, strlen(path));
}

/* The directory of path ("." when it names none), or NULL when out of memory. */
static char *dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');

    if (!slash) return dup_str(".", 1);
    return dup_str(path, slash == path ? 1 : (size_t)(slash - path));
}

/* An unnamed temporary file in dir, open for reading and writing, or -1. */
static int unnamed_temp(const char *dir)
{
#ifdef O_TMPFILE
    return open(dir, O_TMPFILE | O_RDWR, 0600);
#else
    (void)dir;
    errno = EOPNOTSUPP;
    return -1;
#endif
}

/* A temporary file in st->dir: unnamed where the system allows, else named
** ".pipetrace-XXXXXX" (st->tmp, registered for removal on a signal).
** Returns its descriptor, or -1 with errno set. */
static int make_temp(struct pt_outfile_state *st)
{
    sigset_t old;
    int fd = unnamed_temp(st->dir), e;

    if (fd >= 0) return fd;
    st->tmp = malloc(strlen(st->dir) + sizeof "/.pipetrace-XXXXXX");
    if (!st->tmp) { errno = ENOMEM; return -1; }
    strcpy(st->tmp, st->dir);
    strcat(st->tmp, "/.pipetrace-XXXXXX");
    hold(&old);                             /* no signal between make and doom */
    fd = mkstemp(st->tmp);
    e = errno;
    if (fd >= 0) st->slot = doom(st->tmp);
    release(&old);
    if (fd < 0) { free(st->tmp); st->tmp = NULL; errno = e; }
    return fd;
}

/* Give the temporary file fd the old file's owner, group and mode, or a new
** file's mode (0666 less the umask, as fopen would). */
static void set_mode(int fd, const struct pt_outfile_state *st)
{
    mode_t mask;

    if (st->have_old) {
        if (st->old.st_uid != geteuid() || st->old.st_gid != getegid()) {
            int ignored = fchown(fd, st->old.st_uid, st->old.st_gid);
            (void)ignored;                  /* not allowed: the user's own */
        }
        (void)fchmod(fd, st->old.st_mode & 07777);
        return;
    }
    mask = umask(0);
    umask(mask);
    (void)fchmod(fd, 0666 & ~mask);
}

/* COPY: open the target itself for the copy at the end (made empty when it
** does not exist) and a temporary file anywhere: unnamed in its directory,
** else tmpfile()'s.  Failing both, the target itself (INPLACE).  Returns the
** descriptor to write to, or -1 with errno set. */
static int open_copy(pt_outfile *o, struct pt_outfile_state *st)
{
    sigset_t old;
    FILE *t;
    int fd;

    st->how = COPY;
    hold(&old);
    if (st->have_old) st->dest = open(o->target, O_WRONLY);
    else if ((st->dest = open(o->target, O_WRONLY | O_CREAT | O_EXCL, 0666)) >= 0) {
        st->created = 1;
        st->slot = doom(o->target);
    }
    release(&old);
    if (st->dest < 0) return -1;
    if ((fd = unnamed_temp(st->dir)) >= 0) return fd;
    if ((t = tmpfile()) != NULL) {
        fd = dup(fileno(t));
        fclose(t);
        if (fd >= 0) return fd;
    }
    st->how = INPLACE;
    if (ftruncate(st->dest, 0) != 0) return -1;
    fd = st->dest;
    st->dest = -1;                          /* the FILE owns it now */
    return fd;
}

int pt_outfile_open(pt_outfile *o, const char *path, char *err, size_t errlen)
{
    struct pt_outfile_state *st;
    int fd = -1, direct;

    o->path = path;
    o->target = NULL;
    o->st = NULL;
    o->f = NULL;
    if (strcmp(path, "-") == 0) { o->f = stdout; return 0; }
    o->target = replace_target(path, &direct);
    if (direct) {
        o->f = fopen(path, "wb");
        return o->f ? 0 : fail(o, err, errlen, strerror(errno));
    }
    if (!o->target) return fail(o, err, errlen, "out of memory");
    st = o->st = calloc(1, sizeof *st);
    if (!st) return fail(o, err, errlen, "out of memory");
    st->dest = -1;
    st->slot = -1;
    st->have_old = stat(o->target, &st->old) == 0;
    if (st->have_old && faccessat(AT_FDCWD, o->target, W_OK, AT_EACCESS) != 0)
        return fail(o, err, errlen, strerror(errno));
    if (st->have_old && !(st->old.st_mode & 0222))     /* root may, but should not */
        return fail(o, err, errlen, "the file is read-only");
    if (!(st->dir = dir_of(o->target))) return fail(o, err, errlen, "out of memory");
    if (!st->have_old || st->old.st_nlink <= 1) {      /* else rename splits links */
        st->how = RENAME;
        fd = make_temp(st);
    }
    if (fd < 0) fd = open_copy(o, st);                 /* no temporary file here */
    if (fd < 0) return fail(o, err, errlen, strerror(errno));
    if (st->how == RENAME) set_mode(fd, st);
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        int e = errno;
        close(fd);
        return fail(o, err, errlen, strerror(e));
    }
    return 0;
}

/* ===== finishing ===== */

/* Write all n bytes of buf to fd at offset at.  Returns 0, or -1 with errno. */
static int put_all(int fd, const char *buf, size_t n, off_t at)
{
    while (n) {
        ssize_t w = pwrite(fd, buf, n, at);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) { if (w == 0) errno = EIO; return -1; }
        buf += w; n -= (size_t)w; at += w;
    }
    return 0;
}

/* Copy the whole of file from into file to, which ends where from does; the
** signals above wait until it is done.  Returns 0, or -1 with errno. */
static int copy_into(int from, int to)
{
    char buf[1 << 16];
    off_t at = 0;
    sigset_t old;
    int rc = 0;

    hold(&old);
    for (;;) {
        ssize_t n = pread(from, buf, sizeof buf, at);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0 || (n > 0 && put_all(to, buf, (size_t)n, at) != 0)) { rc = -1; break; }
        if (n == 0) { rc = ftruncate(to, at); break; }
        at += n;
    }
    release(&old);
    return rc;
}

/* RENAME with an unnamed file fd: give it a name.  A new target is linked
** to its own name at once (linkat fails rather than replace a file that has
** appeared meanwhile); else a name ".pipetrace-PID-N" in the directory, left
** in st->tmp for the rename.  Where linking cannot work (no /proc), the
** content is copied into the target instead.  Returns 0, or -1 with errno. */
static int name_unnamed(pt_outfile *o, int fd)
{
    struct pt_outfile_state *st = o->st;
    char proc[64], *name;
    sigset_t old;
    int k, to;

    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd);
    if (!st->have_old && linkat(AT_FDCWD, proc, AT_FDCWD, o->target, AT_SYMLINK_FOLLOW) == 0)
        return 0;
    name = malloc(strlen(st->dir) + 48);
    if (!name) { errno = ENOMEM; return -1; }
    for (k = 0; k < 100; k++) {
        sprintf(name, "%s/.pipetrace-%ld-%d", st->dir, (long)getpid(), k);
        hold(&old);
        if (linkat(AT_FDCWD, proc, AT_FDCWD, name, AT_SYMLINK_FOLLOW) == 0) {
            st->tmp = name;
            st->slot = doom(name);
            release(&old);
            return 0;
        }
        release(&old);
        if (errno != EEXIST) break;
    }
    free(name);
    to = open(o->target, O_WRONLY | O_CREAT, 0666);     /* no /proc: copy */
    if (to < 0) return -1;
    if (copy_into(fd, to) != 0) { int e = errno; close(to); errno = e; return -1; }
    return close(to);
}

/* Put the written temporary file where the target was.  Returns 0, or -1
** with errno set. */
static int put_in_place(pt_outfile *o)
{
    struct pt_outfile_state *st = o->st;
    int fd = fileno(o->f);

    if (st->how == COPY) {
        if (copy_into(fd, st->dest) != 0) return -1;
        st->created = 0;
        fd = st->dest;
        st->dest = -1;
        return close(fd);
    }
    if (st->how == RENAME && !st->tmp && name_unnamed(o, fd) != 0) return -1;
    if (st->how == RENAME && st->tmp) {
        if (rename(st->tmp, o->target) != 0) return -1;
        spare(st->slot);
        st->slot = -1;
        free(st->tmp);                      /* renamed: nothing to remove */
        st->tmp = NULL;
    }
    st->created = 0;
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
    bad = fflush(o->f) != 0 || ferror(o->f) != 0;
    if (!bad && o->st && o->st->how != INPLACE) bad = put_in_place(o) != 0;
    if (!bad && o->st) o->st->created = 0;
    if (!bad) { bad = fclose(o->f) != 0; o->f = NULL; }
    if (bad) return fail(o, err, errlen, errno ? strerror(errno) : "write error");
    pt_outfile_abort(o);                    /* frees what is left */
    return 0;
}

void pt_outfile_abort(pt_outfile *o)
{
    struct pt_outfile_state *st = o->st;

    if (o->f && o->f != stdout) fclose(o->f);
    o->f = NULL;
    if (st) {
        if (st->dest >= 0) close(st->dest);
        if (st->tmp) unlink(st->tmp);
        if (st->created) unlink(o->target);
        spare(st->slot);
        free(st->tmp);
        free(st->dir);
        free(st);
    }
    free(o->target);
    o->st = NULL;
    o->target = NULL;
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

/* Where a file that does not exist yet would be made: its directory's real
** path, "/", its last name.  NULL when that directory does not exist (or out
** of memory). */
static char *new_place(const char *path)
{
    char *dir = dir_of(path), *real = dir ? realpath(dir, NULL) : NULL, *out = NULL;
    const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;

    if (real && (out = malloc(strlen(real) + strlen(base) + 2)) != NULL)
        sprintf(out, "%s/%s", real, base);
    free(real);
    free(dir);
    return out;
}

int pt_outfile_same(const char *a, const char *b)
{
    struct stat sa, sb;
    int ha, hb, same;
    char *pa, *pb;

    if (!strcmp(a, "-") || !strcmp(b, "-")) return 0;
    ha = stat(a, &sa) == 0;
    hb = stat(b, &sb) == 0;
    if (ha && hb)
        return S_ISREG(sa.st_mode) && S_ISREG(sb.st_mode) && sa.st_dev == sb.st_dev
               && sa.st_ino == sb.st_ino;
    if (ha || hb || lstat(a, &sa) == 0 || lstat(b, &sb) == 0) return 0;
    pa = new_place(a);                      /* two new files: the same name? */
    pb = new_place(b);
    same = pa && pb && !strcmp(pa, pb);
    free(pa);
    free(pb);
    return same;
}

size_t pt_outfile_among(const char *out, const char *const *in, size_t n)
{
    size_t k;

    for (k = 0; k < n; k++)
        if (pt_outfile_same(out, in[k])) break;
    return k;
}
