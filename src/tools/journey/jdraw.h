/*
** src/tools/journey/jdraw.h -- the journey's drawing: SVG shapes, texts and labels, views, markers
** See LICENSE for copyright and license.
**
** Every panel of `pipetrace journey` is drawn with these, in panel units
** (0..PT_JOURNEY_PW x 0..PT_JOURNEY_PH, y down) or, through a pt_jview, in a
** stage's own coordinates.  Numbers are written with at most one decimal;
** every text is XML-escaped.
**
** The panel being drawn is the one place these functions share: between
** pt_jdraw_to(p) and pt_jdraw_to(NULL) the lines, circles and texts drawn are
** recorded in p, and labels that may move wait there for their place
** (jplace.h) until pt_jdraw_labels() writes them.  Outside a panel (the
** legend, the header) a label is written where it was asked for.
*/
#ifndef PT_JDRAW_H
#define PT_JDRAW_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "io/sbuf.h"
#include "tools/journey/jplace.h"

/* ===== look ===== */

#define PT_JFONT     "DejaVu Sans, Helvetica, Arial, sans-serif"
#define PT_JMONO     "DejaVu Sans Mono, Menlo, Consolas, monospace"
#define PT_JC_TEXT    "#222"
#define PT_JC_NOTE    "#5f6670"
#define PT_JC_AXIS    "#6b7280"
#define PT_JC_FAINT   "#b9bfc9"
#define PT_JC_SEG     "#1f6fd1"
#define PT_JC_CELL    "#a8c7ee"
#define PT_JC_VTX     "#d62728"     /* PT_JOURNEY_RED_RGB (journey.h) */
#define PT_JC_AREA    "#e6eefa"
#define PT_JC_EDGE    "#7f9cc6"
#define PT_JC_GRID    "#d3d9e3"
#define PT_JC_FRAME   "#c9ced6"
#define PT_JC_FRAMEPX "#a3abb7"     /* a pixel of the rendered frame */

/* A label over drawings: a white halo keeps it legible. */
#define PT_JHALO "stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\""

#define PT_JBOX_X    10.0           /* a panel's plot box, panel units */
#define PT_JBOX_Y    42.0
#define PT_JBOX_W    380.0
#define PT_JBOX_H    248.0

/* A window of data coordinates mapped onto a box of panel units, same scale on
** both axes.  Invariant: x0 < x1, y0 < y1, s > 0, s * (x1 - x0) == bw (and y). */
typedef struct pt_jview {
    double x0, y0, x1, y1;       /* the window, data coordinates */
    double bx, by, bw, bh;       /* the box, panel units (y down) */
    double s;                    /* panel units per data unit */
    int ydown;                   /* 1: data y grows downward (pixel rows) */
} pt_jview;

/* How a stage's panel shows a point: in a 3-D space seen from `eye` (a
** direction toward the viewer), on a plane (x, y), as a pixel of a grid, or
** not as a point at all.  One row per stage, pt_jlooks[st]: a new stage adds
** its row. */
typedef enum pt_jkind { PT_JKIND_NONE, PT_JKIND_SPACE, PT_JKIND_PLANE, PT_JKIND_PIXELS } pt_jkind;
typedef struct pt_jlook {
    pt_jkind kind;
    double eye[3];               /* PT_JKIND_SPACE: the direction it is seen from */
} pt_jlook;
extern const pt_jlook pt_jlooks[PT_NSTAGES_ALL];

/* ===== the panel being drawn ===== */

/* Record what is drawn from now on into p (NULL: into nothing) and return
** the panel recorded so far.  This function can't fail. */
pt_jplace *pt_jdraw_to(pt_jplace *p);

/* The panel being recorded into, or NULL.  This function can't fail. */
pt_jplace *pt_jdraw_place(void);

/* Place p's labels (pt_jplace_run()) and append them to sb.  This function
** can't fail (out of memory: sb->failed). */
void pt_jdraw_labels(pt_sbuf *sb, pt_jplace *p);

/* ===== numbers and elements ===== */

/* A panel coordinate with at most one decimal ("12", "12.5"; never "-0");
** and ` name="x"` with x such a coordinate.  These functions can't fail. */
void pt_jnum(pt_sbuf *sb, double x);
void pt_jattr(pt_sbuf *sb, const char *name, double x);

/* An integer as text into b (n bytes, cut short).  This function can't fail. */
void pt_jfmt_i64(char *b, size_t n, int64_t x);

/* <text> at (x, y) that stays where it is put: size, anchor ("start",
** "middle", "end"), more attributes (extra, may be ""), the text escaped;
** squeezed to maxw (> 0) when its estimated width exceeds it.  Can't fail. */
void pt_jtext(pt_sbuf *sb, double x, double y, double size, const char *anchor,
              const char *extra, const char *t, double maxw);

/* A label's importance: the vertex's name first, then axes, then the rest. */
enum { PT_JLAB_VERTEX, PT_JLAB_AXIS, PT_JLAB_OTHER };

/* A label that wants to be at (x, y) and may move (prio: PT_JLAB_*): written
** by pt_jdraw_labels(), or at once when no panel is drawn.  Can't fail. */
void pt_jlabel_at(pt_sbuf *sb, double x, double y, double size, const char *anchor,
               const char *extra, const char *t, double maxw, int prio);

/* Lines, rectangles, circles in panel units; a filled triangle with its tip
** at (bx, by), pointing from (ax, ay).  extra, stroke: may be "".  These
** functions can't fail. */
void pt_jline(pt_sbuf *sb, double ax, double ay, double bx, double by, const char *stroke,
              double width, const char *extra);
void pt_jrect(pt_sbuf *sb, double x, double y, double w, double h, const char *fill,
              const char *stroke, const char *extra);
void pt_jcircle(pt_sbuf *sb, double x, double y, double r, const char *fill, const char *extra);
void pt_jarrow(pt_sbuf *sb, double ax, double ay, double bx, double by, double size,
               const char *fill);

/* Many lines or cells as one <path>: opened by the first command ("M", "L",
** "H", "V", ... with n = 1 or 2 numbers), closed with its attributes by
** pt_jpath_end() (nothing written when no command came).  Can't fail. */
typedef struct pt_jpath {
    pt_sbuf *sb;
    int open;                    /* 1: "<path d=\"" written */
} pt_jpath;
void pt_jpath_start(pt_jpath *p, pt_sbuf *sb);
void pt_jpath_cmd(pt_jpath *p, const char *c, int n, double a, double b);
void pt_jpath_end(pt_jpath *p, const char *attrs);

/* ===== views ===== */

/* Fit the data rectangle b = [x0, y0, x1, y1] into the box (bx, by, bw, bh),
** centred, one scale.  This function can't fail. */
void pt_jview_fit(pt_jview *v, const double b[4], int ydown, double bx, double by, double bw,
                  double bh);

/* Data coordinates to panel units, and whether (x, y) is in the window. */
double pt_jview_x(const pt_jview *v, double x);
double pt_jview_y(const pt_jview *v, double y);
int pt_jview_in(const pt_jview *v, double x, double y);

/* Clip the data segment a-b to the window (Liang-Barsky).  Returns 1 and the
** clipped ends, or 0 when nothing is left or a number is not finite. */
int pt_jview_clip(const pt_jview *v, double *ax, double *ay, double *bx, double *by);

/* Draw the data segment a-b clipped to the window; returns 1 when drawn. */
int pt_jview_line(pt_sbuf *sb, const pt_jview *v, double ax, double ay, double bx, double by,
                  const char *stroke, double width, const char *extra);

/* Draw the data rectangle [x, x + w] x [y, y + h] clipped to the window, at
** least minsize units wide and high (grown about its centre).  Can't fail. */
void pt_jview_rect(pt_sbuf *sb, const pt_jview *v, double x, double y, double w, double h,
                   const char *fill, const char *stroke, const char *extra, double minsize);

/* A small label at data point (x, y) when it is in view, offset (dx, dy)
** units.  This function can't fail. */
void pt_jview_label(pt_sbuf *sb, const pt_jview *v, double x, double y, double dx, double dy,
                    const char *anchor, const char *t);

/* Grid lines with spacing 1 over the data rectangle r, offset off (0: at
** integers, 0.5: at half-integers), when cells are at least mincell units;
** and the outline of r as four lines; both clipped.  These can't fail. */
void pt_jgrid(pt_sbuf *sb, const pt_jview *v, const double r[4], double off, double mincell);
void pt_joutline(pt_sbuf *sb, const pt_jview *v, const double r[4], const char *stroke,
                 double width);

/* The vertex's marker at data point (x, y) when ok and in view, else an arrow
** at the box's edge toward it; its name "v<vn>" as a label.  ring: 0 a dot, 1
** a ring (around a tiny filled pixel), 2 nothing (the pixel is big).  Sets
** (*px, *py), when not NULL, to where it is in panel units, NaN when nowhere.
** This function can't fail. */
void pt_jmarker(pt_sbuf *sb, const pt_jview *v, int ok, double x, double y, uint64_t vn,
                int ring, double *px, double *py);

/* ===== 3-D views ===== */

/* Point (x, y, z) of stage st's space projected on its panel's plane (seen
** from pt_jlooks[st].eye).  This function can't fail. */
void pt_jproj(pt_stage st, double x, double y, double z, double *px, double *py);

/* The 3-D segment a-b of stage st's space in view v; returns 1 when drawn. */
int pt_jline3(pt_sbuf *sb, const pt_jview *v, pt_stage st, const double *a, const double *b,
              const char *stroke, double width, const char *extra);

/* An arrow-tipped axis of stage st's space from the origin to (x, y, z),
** dashed on the negative side, labelled.  This function can't fail. */
void pt_jaxis3(pt_sbuf *sb, const pt_jview *v, pt_stage st, double x, double y, double z,
               const char *label);

#endif
