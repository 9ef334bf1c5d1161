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
** Only the SVG: the page (--html) and --image are renderer 4's.
*/
#ifndef PT_JOURNEY_COURSE_H
#define PT_JOURNEY_COURSE_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "io/sbuf.h"

/* Append the SVG document for vertex v (1-based; past the model's own: one a
** clip stage made) of the position of model mi of s (renderer 7 or 9).
** Returns 0; 1 when that position has no vertex v in any stage; -1 when out
** of memory. */
int pt_journey_course_svg(pt_sbuf *sb, const pt_scene *s, size_t mi, uint64_t v);

#endif
