/*
** src/outfile.h -- output files that appear whole or not at all
** See LICENSE for copyright and license.
**
** Output goes to a temporary file beside the target ("PATH.XXXXXX"), which is
** renamed onto PATH only once everything was written.  On any error the
** temporary file is removed, so no half-written file is ever left.  The path
** "-" means standard output (written directly).
*/
#ifndef PT_OUTFILE_H
#define PT_OUTFILE_H

#include <stdio.h>
#include <stddef.h>

typedef struct pt_outfile {
    FILE *f;                     /* where to write */
    const char *path;            /* the target, not owned */
    char *tmp;                   /* the temporary file's name, owned; NULL for "-" */
} pt_outfile;

/* Open path for writing.  Returns 0, or -1 with a message in err. */
int pt_outfile_open(pt_outfile *o, const char *path, char *err, size_t errlen);

/* Close and move the file into place.  Returns 0, or -1 with a message in err
** (the temporary file is then removed). */
int pt_outfile_commit(pt_outfile *o, char *err, size_t errlen);

/* Close and remove the temporary file.  This function can't fail. */
void pt_outfile_abort(pt_outfile *o);

#endif
