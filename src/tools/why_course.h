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

#endif
