/*
** src/tools/journey/journey.h -- one vertex's journey drawn: a panel per coordinate system (SVG)
** See LICENSE for copyright and license.
**
** Seven panels, one per stage of the classic camera, in pipeline order:
**
**   1 model space      3-D view: axes, the model's wireframe, the vertex
**   2 camera space     3-D side view: camera, view pyramid (or box), image plane,
**                      the wireframe moved by the translation, the projection ray
**   3 image plane      the view rectangle [-1, 1]^2 and the projected wireframe
**   4 logical pixels   the logical viewport [0.5, w+0.5] x [0.5, h+0.5], y up
**   5 viewport         the w x h pixel grid, y down, the vertex's pixel filled
**   6 framebuffer      the W x H framebuffer with the viewport outlined and
**                      the whole frame's pixels, every model's, in grey
**   7 pixel array      the array as a strip of rows, the index marked
**
** Every panel marks the vertex and labels it with its coordinates (the text of
** pt_explain_values(), so the numbers are the trace's), and draws the segments
** that use it over the rest of the model.  The numbers are the journeys
** pt_run() hands over (pt_run_journeys()), the trace's own records.
**
** A panel is a background that depends only on the model (frame, title,
** axes, grid, the faint wireframe) and a foreground for one vertex (its
** segments, marker, label, a zoom inset).  The panel's scale is chosen per
** model so that one background serves every vertex of the model: the drawn
** range grows from the stage's own rectangle to take in the model's vertices,
** but at most to PT_JOURNEY_REACH times the rectangle's size; a vertex beyond
** that (or behind the camera, or huge) is marked by an arrow at the panel's
** edge pointing toward it.  When pixels are too small to see, the pixel
** panels add a zoom inset around the vertex's pixel.
**
** Everything is written into a pt_sbuf (no stdio); coordinates in panel units
** with one decimal, every text XML-escaped.
**
** The matrix camera (s->matrix) has ten panels, one per stage of
** pt_matrix_order: model, world, view (eye, frustum), clip space (the four
** side planes against w_k), the cvv (near and far, the outcode), the NDC cube,
** screen, then viewport, framebuffer and pixel array as above.  Its own
** panels are drawn by journey_matrix.c; a vertex outside the view volume stops
** at the cvv, and its segments are drawn after the cvv from the points
** clipping made, which pt_run() reports with their journeys.
*/
#ifndef PT_JOURNEY_H
#define PT_JOURNEY_H

#include <stdint.h>
#include "core/pipetrace.h"
#include "io/explain.h"
#include "io/sbuf.h"

#define PT_JOURNEY_PW      400   /* a panel's width, SVG units */
#define PT_JOURNEY_PH      340   /* a panel's height */
#define PT_JOURNEY_REACH   4.0   /* drawn range: at most this many times the
                                 ** stage's rectangle in each direction */
#define PT_JOURNEY_MAXSEG  5000  /* faint wireframe: the first this many segments */
#define PT_JOURNEY_MAXV    2000  /* the HTML page: at most this many vertices */
#define PT_JOURNEY_FRAMEMAX 16777216  /* framebuffer panel: the whole frame drawn
                                      ** up to this many pixels (W x H) */
#define PT_JOURNEY_RED_RGB {214, 39, 40}    /* the vertex's red, "#d62728" in the
                                            ** panels (journey.c's C_VTX) */

/* A window of data coordinates mapped onto a box of panel units, same scale on
** both axes.  Invariant: x0 < x1, y0 < y1, s > 0, s * (x1 - x0) == bw (and y). */
typedef struct pt_jview {
    double x0, y0, x1, y1;       /* the window, data coordinates */
    double bx, by, bw, bh;       /* the box, panel units (y down) */
    double s;                    /* panel units per data unit */
    int ydown;                   /* 1: data y grows downward (pixel rows) */
} pt_jview;

/* The panels' geometry for one model: shared by all its vertices. */
typedef struct pt_jmodel {
    const pt_scene *s;           /* the scene, not owned */
    const pt_model *m;           /* the model drawn, not owned */
    pt_stage_params par;         /* the numbers of the formulas */
    pt_journey *js;              /* js[k]: vertex k + 1's journey, from pt_run(); owned */
    pt_jview view[PT_NSTAGES_ALL];  /* each panel's main view (index: unused) */
    pt_jview clip_y, clip_z;     /* matrix: the (w_k, y_k) and (w_k, z_k) plots */
    pt_journey *cut;             /* matrix: the points clipping made, owned */
    size_t ncut, *cutix;         /* cutix[2s], [2s + 1]: segment s's end a, b:
                                 ** 0 the vertex, i + 1 cut[i], CULLED: none; owned */
    double axis_m, axis_c;       /* axis lengths of the two 3-D panels */
    double depth;                /* camera panel: depth of the view pyramid */
    struct pt_jplace *place;     /* place[st]: stage st's lines, boxes and labels
                                 ** (jplace.h), recorded by its background; owned */
    const pt_fb *frame;          /* the scene rendered, every model: the
                                 ** framebuffer panel's pixels; NULL when
                                 ** W x H > PT_JOURNEY_FRAMEMAX */
    pt_fb own_frame;             /* frame, when this jm rendered it; owned */
    int owns_frame;
} pt_jmodel;

/* Lay out the panels of model m of scene s (the classic camera: !s->matrix),
** running the scene for the journeys of its vertices.  frame: the scene
** rendered by another model's pt_jmodel (its ->frame, kept until this one is
** freed), or NULL to render it here.  Returns 0, or -1 when out of memory
** (then nothing is left to free). */
int pt_jmodel_init(pt_jmodel *jm, const pt_scene *s, const pt_model *m, const pt_fb *frame);

/* Free what *jm owns (a zeroed or freed jm too).  This function can't fail. */
void pt_jmodel_free(pt_jmodel *jm);

/* Render scene s into fb (initialised here) as `pipetrace render` does, with
** no trace.  Returns 0, or -1 when out of memory (fb is then freed). */
int pt_journey_render(pt_fb *fb, const pt_scene *s);

/* The panel's title ("camera space") and its coordinates ("(x_c, y_c, z_c)").
** This function can't fail. */
const char *pt_journey_title(pt_stage st);

/* Append the background of stage st's panel, in panel units (0..PW x 0..PH):
** frame, title, formula, axes, grid, the model's wireframe.  On allocation
** failure sb->failed is set (as for every pt_sbuf writer). */
void pt_journey_panel_bg(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st);

/* Append the foreground for the model's 1-based vertex v (1 <= v <= nv):
** its segments, marker or edge arrow, the coordinates label
** (<text class="coords">) and a note (<text class="note">), a zoom inset. */
void pt_journey_panel_fg(pt_sbuf *sb, const pt_jmodel *jm, uint64_t v, pt_stage st);

/* Append a whole SVG document: every panel for vertex v of model m, a header
** and a legend.  The root has a viewBox and width="100%", so it scales.
** Returns 0, or -1 when out of memory. */
int pt_journey_svg(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t v);

/* Append a self-contained HTML page (journey_html.c): one panel at a time with
** its formula and numbers, Prev/Next buttons and a choice of vertex; data for
** up to PT_JOURNEY_MAXV used vertices of the scene, or, pick not NULL, for the
** vertices k + 1 of m with pick[k] set (used or not); vertex v of m first
** shown.  Returns 0, or -1 when out of memory. */
int pt_journey_html(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t v,
                    const unsigned char *pick);

/* ===== the matrix camera (journey_matrix.c) ===== */

#define PT_JOURNEY_CULLED ((size_t)-1)   /* cutix: the segment is wholly outside */

/* Run the scene once more for the points clipping made on jm's model and lay
** out the matrix camera's panels.  Returns 0, or -1 when out of memory. */
int pt_jmatrix_init(pt_jmodel *jm);

/* Segment s's ends as stage st sees them (see journey.c's seg_ends).  Returns
** 0 when the stage sees none of it.  This function can't fail. */
int pt_jmatrix_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb);

/* The rasterizer's pixel-plane point of a journey's viewport pixel (m7's
** pt_viewport2pixelplane()).  Returns 0, or -1 when it has no pixel. */
int pt_jmatrix_pixelplane(const pt_journey *j, int h, pt_vec2 *pp);

/* The 1-based place of stage st in its camera's order.  Can't fail. */
int pt_jmatrix_number(const pt_jmodel *jm, pt_stage st);

/* The matrix camera's own backgrounds (world .. screen) and foregrounds
** (clip, cvv, a stage the vertex did not reach), and its notes: returns 1
** when it wrote the note t.  These functions can't fail. */
void pt_jmatrix_bg(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st);
void pt_jmatrix_fg(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st);
int pt_jmatrix_note(char *t, size_t n, const pt_journey *j, pt_stage st);

/* Mark, in stage st's panel (ndc, screen), the points where clipping cut
** vertex k's segments.  This function can't fail. */
void pt_jmatrix_cuts(pt_sbuf *sb, const pt_jmodel *jm, size_t k, pt_stage st);

/* The coordinates label of a stage the vertex did not reach: "(x_n, y_n,
** z_n): not reached".  Returns its length (cut short when >= n).  Can't fail. */
size_t pt_jmatrix_unreached(char *t, size_t n, pt_stage st);

/* journey.c's drawing, for journey_matrix.c: text (pt_jtext stays where it
** is put, pt_jtext_label may move clear of the rest: jplace.h), lines, circles,
** rectangles in panel units; views (pt_jview) in data units; the 3-D panels'
** projection, axes and lines; the faint wireframe, the vertex's segments and
** its marker as the classic panels draw them. */
void pt_jtext(pt_sbuf *sb, double x, double y, double size, const char *anchor,
              const char *extra, const char *t, double maxw);
void pt_jtext_label(pt_sbuf *sb, double x, double y, double size, const char *anchor,
                    const char *extra, const char *t, double maxw);
void pt_jline(pt_sbuf *sb, double ax, double ay, double bx, double by, const char *stroke,
              double width, const char *extra);
void pt_jcircle(pt_sbuf *sb, double x, double y, double r, const char *fill, const char *extra);
void pt_jrect(pt_sbuf *sb, double x, double y, double w, double h, const char *fill,
              const char *stroke, const char *extra);
void pt_jview_fit(pt_jview *v, const double b[4], int ydown, double bx, double by, double bw,
                  double bh);
int pt_jview_line(pt_sbuf *sb, const pt_jview *v, double ax, double ay, double bx, double by,
                  const char *stroke, double width, const char *extra);
double pt_jview_x(const pt_jview *v, double x);
double pt_jview_y(const pt_jview *v, double y);
int pt_jview_in(const pt_jview *v, double x, double y);
void pt_jview_label(pt_sbuf *sb, const pt_jview *v, double x, double y, double dx, double dy,
                    const char *anchor, const char *t);
int pt_jstage_xy(const pt_journey *j, pt_stage st, double *x, double *y);
void pt_jproj(pt_stage st, double x, double y, double z, double *px, double *py);
void pt_jaxis3(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st, double x, double y, double z,
               const char *label);
int pt_jline3(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st, const double *a, const double *b,
              const char *stroke, double width, const char *extra);
void pt_jwireframe(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st);
void pt_jsegments(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, pt_stage st, size_t k);
void pt_jmarker(pt_sbuf *sb, const pt_jview *v, int ok, double x, double y, uint64_t vn);

#endif
