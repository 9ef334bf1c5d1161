/*
** src/tools/class/class.h -- pipetrace class: every student's file of a folder against one EXPECTED
** See LICENSE for copyright and license.
**
** A folder of students' traces, logs and images is diffed file by file
** against one EXPECTED (a scene, rendered once, or a trace or log), each
** diff in a child process of its own (pt_diff_run(), two at a time), and
** the findings come back as data (pt_diff_outcome): the verdict, the first
** wrong stage, the mistakes named, the counts.  cmd_class.c reads the folder
** and runs the diffs; class_report.c writes what they found: the table and
** histograms on the terminal, --csv and --html.
**
** A student is a file name without its last extension: alice.log and
** alice.ppm are one row, the log diffed against the expected trace and the
** image against the expected image; EXPECTED a scene, the image against
** the student's own log too (is it what the log drew?), which names the
** viewport's corner forgotten in setPixelVP behind another mistake.  Nothing in the folder is written, and
** nothing in it but regular files (or links to them) is opened: anything
** else gets a row that says what it is.
*/
#ifndef PT_CLASS_H
#define PT_CLASS_H

#include <stddef.h>
#include "io/sbuf.h"
#include "tools/diff/doutcome.h"

/* One student's row. */
typedef struct pt_class_row {
    char *name;                  /* the student: the file name without its
                                 ** extension; owned */
    char *trace, *image;         /* the files diffed (names in the folder), or
                                 ** NULL; owned */
    char *why;                   /* why the row has no verdict (a file that could
                                 ** not be read, diff's own message), or NULL; owned */
    pt_diff_outcome t, im, own;  /* what the diffs of trace and image found, and
                                 ** of the image against the student's own trace */
    int has_t, has_im, has_own;  /* 1: that diff ran */
    pt_sbuf text[3];             /* what the three diffs printed, for --html */
} pt_class_row;

/* A whole class. */
typedef struct pt_class {
    const char *expected;        /* EXPECTED as given */
    const char *dir;             /* the folder */
    int scene;                   /* 1: EXPECTED is a scene, rendered here */
    int have_image;              /* 1: there is an expected image */
    const char *rendered[2];     /* EXPECTED's trace and image as rendered here
                                 ** (temporary files), or NULL: their names in the
                                 ** diffs' text become EXPECTED's */
    pt_class_row *row;           /* sorted by name; owned */
    size_t nrow;
} pt_class;

/* How a row reads: "PASS", "FAIL", "NOT PROVEN" or "UNREADABLE". */
const char *pt_class_verdict(const pt_class_row *r);

/* The row's mistake, as a table says it, into buf (n bytes): "-" (none
** looked for), "unknown", a name, or "ambiguous: A or B"; then, when the
** image against the student's own trace names a mistake not yet said,
** "; " and its name (alone in place of "-").  Returns buf. */
const char *pt_class_mistake(const pt_class_row *r, char *buf, size_t n);

/* Append the terminal report (the table, then the histograms by stage and by
** mistake); untrusted names made safe for a terminal. */
void pt_class_text(pt_sbuf *sb, const pt_class *c);

/* Append the CSV report (RFC 4180, a header line, a row per student). */
void pt_class_csv(pt_sbuf *sb, const pt_class *c);

/* Append the HTML report: one self-contained page, a bar chart per stage
** and per mistake, a row per student linking to that student's diff. */
void pt_class_html(pt_sbuf *sb, const pt_class *c);

#endif
