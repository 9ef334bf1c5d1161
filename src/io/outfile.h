/*
** src/io/outfile.h -- output files that appear whole or not at all
** See LICENSE for copyright and license.
**
** A regular file (or a path that does not exist yet) is written to a
** temporary file beside it ("PATH.XXXXXX"), renamed onto PATH only once
** everything was written; on any error the temporary file is removed, so no
** half-written file is ever left.  A symbolic link is followed: the file it
** names is replaced that way and the link stays.  Anything else that exists
** at PATH -- a FIFO, a terminal, /dev/null -- is written directly: renaming
** onto it would replace the device itself.  "-" means standard output.
*/
#ifndef PT_OUTFILE_H
#define PT_OUTFILE_H

#include <stdio.h>
#include <stddef.h>

typedef struct pt_outfile {
    FILE *f;                     /* where to write */
    const char *path;            /* the target as given, not owned */
    char *target;                /* the file to replace (PATH, or the file a link
                                 ** names), owned; NULL when written directly */
    char *tmp;                   /* the temporary file's name, owned; NULL when
                                 ** written directly */
} pt_outfile;

/* Open path for writing.  Returns 0, or -1 with a message in err. */
int pt_outfile_open(pt_outfile *o, const char *path, char *err, size_t errlen);

/* Finish the file: flush it, and move a temporary file into place.  Returns
** 0, or -1 with a message in err (a temporary file is then removed). */
int pt_outfile_commit(pt_outfile *o, char *err, size_t errlen);

/* Close and remove the temporary file.  This function can't fail. */
void pt_outfile_abort(pt_outfile *o);

/* End a file whose writing went wrong when bad is set (then abort it), else
** commit it; on failure print "WHO: cannot write 'PATH'" or the commit's
** message, prefixed "WHO: ", to standard error.  Returns 0, or -1. */
int pt_outfile_finish(pt_outfile *o, int bad, const char *who);

#endif
