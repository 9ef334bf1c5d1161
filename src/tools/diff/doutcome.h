/*
** src/tools/diff/doutcome.h -- what one diff found, as data (for `pipetrace class`)
** See LICENSE for copyright and license.
**
** `pipetrace diff --verdict` ends with a paragraph for a reader; the same
** findings, as fields, are what `pipetrace class` tabulates for a whole
** folder.  pt_diff_run() is pt_cmd_diff() that also fills a pt_diff_outcome:
** diff prints exactly what it prints without it, and the fields are set where
** the verdict's words are chosen (dfit.c, cmd_diff.c, dimage.c), so the two
** cannot disagree.
*/
#ifndef PT_DOUTCOME_H
#define PT_DOUTCOME_H

#include <stddef.h>

#define PT_DIFF_MAXNAMED 4           /* names kept of the mistakes that explain all */

typedef struct pt_diff_outcome {
    int status;                  /* diff's exit status: 0 PASS, 1 differs, 2 bad
                                 ** input, 3 NOT PROVEN */
    int images;                  /* 1: two images were compared */
    char stage[32];              /* the stage that goes wrong first, "pixels" when
                                 ** every vertex agrees, "" otherwise */
    int nnamed;                  /* known mistakes that explain every vertex and
                                 ** pixel: 0 none (unknown), 1 named, more: ambiguous */
    char named[PT_DIFF_MAXNAMED][96];   /* their names, the first PT_DIFF_MAXNAMED */
    int silent;                  /* 1: the first wrong stage does not report */
    size_t vertices, differ, only;      /* vertices in both traces, those that
                                        ** differ, those in one trace only */
    int px_compared;             /* 1: both traces have raster records */
    size_t px_missing, px_extra; /* lit pixels EXPECTED has and ACTUAL lacks, and
                                 ** the other way */
    size_t img_differ, img_total;       /* images: differing pixels, of these */
    int sep;                     /* 1: a separating scene was printed (the
                                 ** verdict is ambiguous), -1: --separating-scene's
                                 ** file could not be written, 0: neither */
} pt_diff_outcome;

/* pipetrace diff with argv (argv[0] "diff"), its findings into *out (zeroed
** first; out->status is the return value).  Returns the exit status. */
int pt_diff_run(int argc, char **argv, pt_diff_outcome *out);

#endif
