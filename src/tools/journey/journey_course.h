/*
** src/tools/journey/journey_course.h -- renderers 7 and 9: one vertex's journey drawn (SVG)
** See LICENSE for copyright and license.
**
** The course's renderers work on whole models (core/course.h), so the
** panels are read off one render of the scene, heard through its listener:
** the position's model after every stage, the clip stages' cuts and the
** rasterizer's pixels; the vertex's own numbers are pt_cx_run()'s (the ones
** `step` shows).  One panel per stage, in pipeline order:
**
**   model          3-D: the model's wireframe, the vertex
**   world (r9)     3-D: the model placed by the position's matrix
**   view           3-D: r7 translated, r9 seen from the camera
**   view volume    side view (z_v across, y_v up): the camera at the origin,
**                  the volume's edges through b and t at z = -1 (a box from b
**                  to t, orthographic), the near plane z = n
**   normalized     side view of camera space: edges y = +-z_c (box -1..1)
**   near clip      the segments kept, cut at z = n; each cut point and its t
**   image plane    the view square [-1, 1]^2, the clip's cut points and t
**   viewport       the w x h pixel grid, y down, the position's pixels
**                  (anti-aliased ones shaded by their weight), the vertex's
**
** Every number written is the run's; labels as <text class="coords">.
** The page (--html) shows the same panels one at a time (journey_html.c's
** page, data from here); --image the render with the vertex's pixel ringed.
*/
#ifndef PT_JOURNEY_COURSE_H
#define PT_JOURNEY_COURSE_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "io/sbuf.h"
#include "io/explain_course.h"

/* One render of the scene heard for one position, and one vertex's journey
** through it: what the SVG, the page and the image are drawn from. */
typedef struct pt_jcourse pt_jcourse;

/* Render s (renderer 7 or 9) once, hearing the position of model mi, into
** *out (freed by pt_jcourse_close).  What is kept follows what the panels
** draw, not the model: per stage a bit a vertex (used or not), the reach of
** the used ones, the first PT_JOURNEY_MAXSEG primitives with their ends, the
** first PT_JOURNEY_MAXSEG cuts and the position's first pixels; the chosen
** vertex's journey comes from pt_cx_run().  whole 1 keeps the model stage's
** whole model too (pt_jcourse_model(), the page's sliders).  Returns 0, or
** -1 when out of memory. */
int pt_jcourse_open(pt_jcourse **out, const pt_scene *s, size_t mi, int whole);

/* Choose vertex v (1-based; past the model's own: one a clip stage made).
** Returns 0; 1 when the position has no vertex v in any stage; -1 when out
** of memory. */
int pt_jcourse_vertex(pt_jcourse *jc, uint64_t v);

/* The number of vertices the position has after its last stage (the
** clips' counted).  This function can't fail. */
uint64_t pt_jcourse_count(const pt_jcourse *jc);

/* The chosen vertex's journey (pt_cx_run's).  This function can't fail. */
const pt_cx_journey *pt_jcourse_journey(const pt_jcourse *jc);

/* The position's model as the driver built it (vertices, colours,
** primitives), or NULL when the position is hidden or jc was opened without
** whole.  Can't fail. */
const pt_rv_model *pt_jcourse_model(const pt_jcourse *jc, pt_rv_model *view);

/* The panels: how many (8 for renderer 9, 7 for renderer 7), and panel k's
** key (data-stage, "volume"), title, its spaces and what it shows, the
** formula written on it.  Can't fail. */
typedef struct pt_jcourse_stage {
    const char *key, *title, *from, *to, *what, *formula;
} pt_jcourse_stage;
int pt_jcourse_npanels(const pt_jcourse *jc);
void pt_jcourse_stage_of(const pt_jcourse *jc, int k, pt_jcourse_stage *out);

/* Append panel k of the chosen vertex in panel units (0..PW x 0..PH), its
** label's text (the coordinates), and its formula with the numbers put in
** (pt_cx_stage's text).  On allocation failure sb->failed is set. */
void pt_jcourse_panel(pt_sbuf *sb, const pt_jcourse *jc, int k);
void pt_jcourse_coords(pt_sbuf *sb, const pt_jcourse *jc, int k);
void pt_jcourse_here(pt_sbuf *sb, const pt_jcourse *jc, int k);

/* The coordinates' names at course stage st (PT_CST_*), "(x_c, y_c, z_c)",
** as the panels write them.  Can't fail. */
const char *pt_jcourse_label(int st);

/* The labels' texts for what a vertex lacks: k = 0 ": not yet, the vertex
** is made by the near clip", 1 the same for the clip, 2 the viewport's
** "(x_vp, y_vp): none, ...".  Can't fail. */
const char *pt_jcourse_text(int k);

/* Free jc (NULL too).  This function can't fail. */
void pt_jcourse_close(pt_jcourse *jc);

/* Append the SVG document for vertex v (1-based; past the model's own: one a
** clip stage made) of the position of model mi of s (renderer 7 or 9).
** Returns 0; 1 when that position has no vertex v in any stage; -1 when out
** of memory. */
int pt_journey_course_svg(pt_sbuf *sb, const pt_scene *s, size_t mi, uint64_t v);

/* Append the page (journey_html.c's, with these panels): vertex v first
** shown; listed, the vertices k + 1 with pick[k] set (k < npick), or, pick
** NULL, every vertex of the position, at most PT_JCOURSE_MAXV of them (v
** always).  Sliders: pt_journey_wasm_course().  Returns as
** pt_journey_course_svg(), or 2 when npick is more than the position's
** vertices (the clips' counted). */
#define PT_JCOURSE_MAXV 64
int pt_journey_course_html(pt_sbuf *sb, const pt_scene *s, size_t mi, uint64_t v,
                           const unsigned char *pick, uint64_t npick);

/* Render s into fb (initialised here) and give the framebuffer pixel of
** vertex v of the position of model mi in *x, *y: *has 0 when it has none
** (outside the view square after the clip).  Returns as
** pt_journey_course_svg() (fb is freed unless 0). */
int pt_journey_course_image(pt_fb *fb, const pt_scene *s, size_t mi, uint64_t v, int *has,
                            int64_t *x, int64_t *y);

#endif
