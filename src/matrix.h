/*
** src/matrix.h -- the matrix camera's part of the pipeline
** See LICENSE for copyright and license.
**
** A vertex goes model -> world -> view -> clip -> cvv.  Inside the canonical
** view volume it goes on: ndc -> screen -> viewport -> framebuffer -> index.
** Outside, it stops at the cvv: dividing by w would be wrong for a point behind
** the eye.  Its segments are clipped in clip space first (src/clip.h), and each
** point the clipping makes travels the rest of the way itself (the tail).  The
** rasterizer then draws between the two ends' pixels: the classic rasterizer,
** fed through the mapping of stages/m7_screen2viewport.h.
*/
#ifndef PT_MATRIX_H
#define PT_MATRIX_H

#include "pipeline.h"

/* Build View, Projection and each model's World into *p.  Returns 0; the
** parser has already checked that the camera can be built. */
int pt_matrix_plan(pt_plan *p, const pt_scene *s, const pt_options *o);

/* The journey of v_m of model k up to the cvv, and on when inside.  sinks[st]
** receives stage st's record.  Sets *clip to its clip coordinates and *code to
** its outcode; returns its pixel-plane point (NaN when outside the CVV). */
pt_vec2 pt_matrix_journey(const pt_scene *s, const pt_plan *p, size_t k, pt_vec3 v_m,
                          const pt_sink *const sinks[PT_NSTAGES_ALL],
                          pt_vec4 *clip, unsigned *code);

/* From clip coordinates on: ndc, screen, viewport, framebuffer, index.
** w_scale is the magnitude clip.w was computed from (stages/m5_clip2ndc.h):
** pt_matrix_journey()'s for a vertex, |w| for a point clipping made (it lies
** in the view volume, w >= near).  Returns the pixel-plane point for the
** rasterizer.  Can't fail. */
pt_vec2 pt_matrix_tail(const pt_scene *s, pt_vec4 clip, double w_scale,
                       const pt_sink *const sinks[PT_NSTAGES_ALL]);

#endif
