/*
** src/io/outfile.h -- output files that appear whole or not at all
** See LICENSE for copyright and license.
**
** A regular file (or a path that does not exist yet) is written to a
** temporary file in its directory and moved onto PATH by rename() only once
** everything was written; on any error the temporary file goes away, so no
** half-written file is ever left.  Where the system has it (Linux: O_TMPFILE)
** the temporary file has no name until it is linked at the end, so even
** SIGKILL leaves nothing behind; a named one (".pipetrace-XXXXXX", short, so
** names of up to 255 bytes work) is removed on SIGINT, SIGTERM, SIGHUP and
** SIGPIPE, after which the signal does what it would have done.
**
** Replacing keeps what the old file was: its mode (a 0600 file stays
** private), its owner and group where the user may set them, and its hard
** links.  A file with more than one link cannot be replaced by rename (that
** would split the links), so it is written in place: the output goes to an
** unnamed temporary file first and is copied into the old file at the end,
** with the signals above held off, so a failed run still leaves the old file
** as it was.  The same copy is made where no temporary file can be made next
** to the old one (a read-only or immutable directory).  A file the user could
** not overwrite is refused (exit 2): one without write permission for the
** user, and one without any write bit even for root, who could otherwise
** write anything.
**
** A symbolic link is followed: the file it names is replaced and the link
** stays.  Anything else that exists at PATH -- a FIFO, a terminal, /dev/null
** -- is written directly: renaming onto it would replace the device itself.
** "-" means standard output.
*/
#ifndef PT_OUTFILE_H
#define PT_OUTFILE_H

#include <stdio.h>
#include <stddef.h>

struct pt_outfile_state;

typedef struct pt_outfile {
    FILE *f;                     /* where to write */
    const char *path;            /* the target as given, not owned */
    char *target;                /* the file to replace (PATH, or the file a link
                                 ** names), owned; NULL when written directly */
    struct pt_outfile_state *st; /* how it is replaced (outfile.c), owned; NULL
                                 ** when written directly */
} pt_outfile;

/* Open path for writing.  Returns 0, or -1 with a message in err. */
int pt_outfile_open(pt_outfile *o, const char *path, char *err, size_t errlen);

/* Finish the file: flush it, and move a temporary file into place.  Returns
** 0, or -1 with a message in err (a temporary file is then removed). */
int pt_outfile_commit(pt_outfile *o, char *err, size_t errlen);

/* Close and remove the temporary file.  Safe on a pt_outfile that is all
** NULL (never opened).  This function can't fail. */
void pt_outfile_abort(pt_outfile *o);

/* End a file whose writing went wrong when bad is set (then abort it), else
** commit it; on failure print "WHO: cannot write 'PATH'" or the commit's
** message, prefixed "WHO: ", to standard error.  Returns 0, or -1. */
int pt_outfile_finish(pt_outfile *o, int bad, const char *who);

/* 1 when a and b both name one existing regular file (same device and
** inode, links followed) or, neither existing, one new file (the same name
** in the same directory), else 0; "-" (standard output) and devices are no
** file here (--image /dev/null --trace /dev/null is fine).  For the checks
** that refuse to write an output over an input or over another output.
** This function can't fail. */
int pt_outfile_same(const char *a, const char *b);

/* The index of the first of the n paths in[] that out names, as
** pt_outfile_same() tells, or n when it names none: for refusing an output
** over an input of the run (the OBJ files a scene reads).  This function
** can't fail. */
size_t pt_outfile_among(const char *out, const char *const *in, size_t n);

#endif
