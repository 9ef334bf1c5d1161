/*
** src/tools/why_course.h -- pipetrace why on a scene of the course's renderer 7 or 9
** See LICENSE for copyright and license.
**
** One render of the scene (core/course.h), heard through its listener, follows
** every primitive of every position through the near clip and the rectangle
** clip to the rasterizer, and keeps the pixel lines that land on the pixel
** asked about: which primitives lit it, each with its coverage (1, or 1 - f
** and f of an anti-aliased step, f = pt_aa_weight) and the colour bytes it
** wrote (gamma-encoded where gamma applies); and for each that did not,
** whether a clip dropped it or cut it (the plane or edge and t, the new
** vertex as the trace numbers it), or it was drawn elsewhere.  The pixel
** records of the trace (`--format jsonl`: "pixel" with "rgb" and "coverage")
** are the same numbers.
*/
#ifndef PT_WHY_COURSE_H
#define PT_WHY_COURSE_H

#include <stdio.h>
#include "core/pipetrace.h"

/* Write to f why framebuffer pixel (X, Y) of s (renderer 7 or 9; X, Y inside
** the framebuffer) has its colour; sel (or NULL) limits the primitives
** listed to those of its positions.  Returns 0, or -1 when out of memory
** (a message on stderr). */
int pt_whyc_report(FILE *f, const pt_scene *s, int X, int Y, const pt_model *sel);

/* ===== a viewport that sticks out of the framebuffer (renderers 4, 7, 9) =====
**
** The course's framebuffer writes viewport pixel (x_vp, y_vp) at the index
** the core's pt_raster_fb_pixel() gives, rows wrapping past the framebuffer's
** edges (docs/scene-format.md), so one framebuffer pixel can be written from
** several viewport pixels.  why lists them, the viewport's clearing's order
** (row by row) being theirs, and explains each. */

/* The viewport pixels (x_vp, y_vp) of s whose writes land on framebuffer
** pixel (X, Y) (inside the framebuffer), in the clearing's order, the first
** n of them into out[]; returns how many land there in all (at most vp_h).
** With the viewport inside the framebuffer: the one pixel (X - x_ul,
** Y - y_ul) when the viewport holds it, else none.  This function can't
** fail. */
size_t pt_whyc_sources(const pt_scene *s, int64_t X, int64_t Y, pt_pix *out, size_t n);

/* The viewport pixels explained on one pixel, at most: those after them are
** listed only (a viewport far wider than the framebuffer has up to vp_h). */
#define PT_WHYC_EXPLAINED 64

/* Write to f what pipetrace why says first of a scene whose viewport sticks
** out: how the course's framebuffer writes its pixels, and how many (nsrc)
** land on framebuffer pixel (X, Y).  This function can't fail. */
void pt_whyc_wrap_head(FILE *f, const pt_scene *s, int64_t X, int64_t Y, size_t nsrc);

/* Write to f the line that opens viewport pixel vp's part of the report on
** framebuffer pixel (X, Y): its framebuffer pixel, index, and where the
** index shows it when its row wraps.  This function can't fail. */
void pt_whyc_source(FILE *f, const pt_scene *s, int64_t X, int64_t Y, pt_pix vp);

#endif
