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
** Memory follows what is drawn, not the model: the one run keeps the whole
** journeys of the vertices drawn (shown, their neighbours, the wireframe's
** first PT_JOURNEY_MAXSEG segments), the pixels of the segments shown, and
** of every other vertex only its part in the layout, gathered as it passes
** (pt_jspan); per vertex a few bytes, per segment its pixels' place.
**
** Everything is written into a pt_sbuf (no stdio); coordinates in panel units
** with one decimal, every text XML-escaped.
**
** The matrix camera (pt_pipe_matrix) has ten panels, one per stage of
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
#include "tools/journey/jmodel.h"

/* Lay out the panels of model m of scene s (its pipeline's, jrows.c),
** running the scene for the journeys of its vertices.  frame: the scene
** rendered by another model's pt_jmodel (its ->frame, kept until this one is
** freed), or NULL to render it here.  show[k] (m->nv of them, read here
** only): 1 when vertex k + 1's foreground will be drawn; the pixels of its
** segments are kept, no others.  Returns 0, or -1 when out of memory, -2 when
** those segments draw more than PT_JOURNEY_MAXPIX pixels (then nothing is
** left to free). */
int pt_jmodel_init(pt_jmodel *jm, const pt_scene *s, const pt_model *m, const pt_fb *frame,
                   const unsigned char *show);

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
** Returns 0, or -1 when out of memory, -2 past PT_JOURNEY_MAXPIX pixels. */
int pt_journey_svg(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t v);

/* Append a self-contained HTML page (journey_html.c): one panel at a time with
** its formula and numbers, Prev/Next buttons and a choice of vertex; data for
** up to PT_JOURNEY_MAXV used vertices of the scene, or, pick not NULL, for the
** vertices k + 1 of m with pick[k] set (used or not); vertex v of m first
** shown.  Returns 0, or -1 when out of memory, -2 past PT_JOURNEY_MAXPIX
** pixels. */
int pt_journey_html(pt_sbuf *sb, const pt_scene *s, const pt_model *m, uint64_t v,
                    const unsigned char *pick);

/* The page's parts, for a page of other panels (journey_course.c): the
** head (title "pipetrace journey: MODEL vV"), style and body up to the
** data, which the caller appends as <script type="application/json"
** id="data"> in the form above; then the script that shows it.  On
** allocation failure sb->failed is set. */
void pt_journey_page_head(pt_sbuf *sb, const char *model, uint64_t v);
void pt_journey_page_script(pt_sbuf *sb);

/* Append stage k's entry (k > 0: after a comma) of the data's "stages"
** list: its trace name, title, spaces, formula (NULL: none) and what it
** does.  On allocation failure sb->failed is set. */
void pt_journey_page_stage(pt_sbuf *sb, int k, const char *name, const char *title,
                           const char *from, const char *to, const char *formula,
                           const char *what);

#endif
