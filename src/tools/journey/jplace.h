/*
** src/tools/journey/jplace.h -- where a panel's labels go: clear of each other, of lines and of insets
** See LICENSE for copyright and license.
**
** A panel is drawn in two passes over one pt_jplace.  While shapes are drawn,
** what a label must not cover is recorded: the lines (pt_jplace_seg), the
** boxes of fixed texts, markers and insets (pt_jplace_box); a label that may
** move is only asked for (pt_jplace_label), with the place it wants.  Then
** pt_jplace_run() puts the labels, most important first, each at the
** candidate that costs least:
**
**     cost = 1e6 * (leaves the area) + 1000 * (texts, labels, insets it overlaps)
**          + 150 * (small marks it overlaps: a segment's end dot)
**          + 100 * (lines it crosses, dashed ones too)
**          + (how far it moved, panel units)
**
** The candidates are the wanted place and places moved from it by up to
** 106 units in sixteen directions, nearest first, and when none of those is
** free, every place of the area on a grid of 8 units; a placed label becomes
** a box for the next.  So a label stays where it was asked for unless something is
** there, and moves as little as it can.
**
** A label's box is estimated from its text: the advance widths of DejaVu Sans
** (regular or bold) or 0.603 em for DejaVu Sans Mono, the fonts the panels
** ask for first;
** height from the font's ascent (0.928 em) to its descent (0.236 em), the box
** a browser gives a line of text.  tests/journey/journey_fontwidths.py checks the
** table against the font files where they are installed.
*/
#ifndef PT_JPLACE_H
#define PT_JPLACE_H

#include <stddef.h>

#define PT_JLABEL_TEXT 240       /* a label's text, bytes with the NUL */
#define PT_JLABEL_EXTRA 200      /* its more attributes */

/* A label that may move.  prio >= 0: smaller is placed first. */
typedef struct pt_jlabel {
    double x, y, size, maxw;     /* the wanted place (baseline), size, squeeze width */
    int prio;
    double w, want[4];           /* set by pt_jplace_label(): its width, its box
                                 ** at the wanted place */
    char anchor[8];              /* "start", "middle", "end" */
    char extra[PT_JLABEL_EXTRA];
    char text[PT_JLABEL_TEXT];
} pt_jlabel;

typedef struct pt_jplace {
    double (*box)[5];            /* taken: x0, y0, x1, y1 (y down), the cost of covering */
    double (*seg)[4];            /* lines: ax, ay, bx, by */
    pt_jlabel *lab;              /* labels to place */
    size_t nbox, capbox, nseg, capseg, nlab, caplab;
    double area[4];              /* where labels may go */
    int ready;                   /* 1: a background was recorded */
    int failed;                  /* 1: out of memory (then labels may overlap) */
} pt_jplace;

/* How far a pt_jplace was filled; pt_jplace_back() returns to it. */
typedef struct pt_jplace_mark { size_t nbox, nseg, nlab; } pt_jplace_mark;

enum { PT_JFACE_REGULAR, PT_JFACE_BOLD, PT_JFACE_MONO };

/* The face a <text>'s attributes extra ask for: monospace, bold or regular. */
int pt_jtext_face(const char *extra);

/* Estimated width of text t (UTF-8) at size in face (PT_JFACE_*). */
double pt_jtext_width(const char *t, double size, int face);

/* The box b of text t with its baseline at (x, y), anchored at anchor, no
** wider than maxw when maxw > 0 (a squeezed text). */
void pt_jtext_box(double b[4], double x, double y, double size, const char *anchor,
                  int face, const char *t, double maxw);

/* Start empty (no memory held) with labels allowed in area a. */
void pt_jplace_init(pt_jplace *p, const double a[4]);
void pt_jplace_free(pt_jplace *p);
void pt_jplace_clear(pt_jplace *p);
pt_jplace_mark pt_jplace_save(const pt_jplace *p);
void pt_jplace_back(pt_jplace *p, pt_jplace_mark m);

/* Record a taken box, a line, a label to place.  On allocation failure
** p->failed is set and the item is dropped. */
#define PT_JPLACE_TAKEN 1000.0   /* pt_jplace_box(): a text, a label, an inset, the marker */
#define PT_JPLACE_MARK  150.0    /* a small mark */
void pt_jplace_box(pt_jplace *p, double x0, double y0, double x1, double y1, double cost);
void pt_jplace_seg(pt_jplace *p, double ax, double ay, double bx, double by);
void pt_jplace_label(pt_jplace *p, const pt_jlabel *l);

/* What box b would cost where it is (the formula above, without the move;
** lines only when lines is 1: an opaque inset may cover them); labels not
** yet placed count with the box they want. */
double pt_jplace_cost(const pt_jplace *p, const double b[4], int lines);

/* Place the labels asked for and hand each to put() with its place (x, y);
** they are then boxes of p.  This function can't fail. */
void pt_jplace_run(pt_jplace *p, void (*put)(void *ud, const pt_jlabel *l, double x, double y),
                   void *ud);

#endif
