/*
** stages/pt_matrix.h -- the matrix camera's stages, run in order
** See LICENSE for copyright and license.
**
** The one place that says in which order, and with which numbers, the matrix
** camera's stages are called (pt_classic.h is its classic twin):
**
**   model --m1--> world --m2--> view --m3--> clip --m4--> cvv outcode
**   inside (outcode 0):  clip --m5--> ndc --m6--> screen --m7--> viewport
**                        --s5--> framebuffer --s6--> index
**
** A vertex outside the canonical view volume stops at the cvv: dividing by w
** would be wrong for a point behind the eye.  Its segments are clipped in clip
** space (ms_clip_segment.h), and each point the clipping makes runs the tail,
** m5 on, itself.  The rasterizer then draws between the two ends' points of
** the classic pixel plane (m7's pt_viewport2pixelplane()).
*/
#ifndef PT_MATRIX_H
#define PT_MATRIX_H

#include "pt_stage.h"
#include "pt_mat4.h"

/* The three matrices of one model's journey, on row vectors. */
typedef struct pt_matrices {
    const pt_mat4 *world;        /* the model's: its `world` lines, then translate */
    const pt_mat4 *view;         /* the camera's look-at */
    const pt_mat4 *proj;         /* the camera's perspective projection */
} pt_matrices;

/* A model's World: its `world` lines' matrix, then its translate.  This
** function can't fail. */
pt_mat4 pt_matrix_world(const pt_mat4 *lines, pt_vec3 translate);

/* Run v_m through the model record and the stages up to the cvv with mx and
** par (w .. H); inside the view volume on through the tail.  Stage st reports
** to sinks[st] (NULL: not reported).  Sets *clip to the clip coordinates and
** *code to the outcode; returns the pixel-plane point for the rasterizer (NaN
** when outside the view volume or without a pixel).  This function can't fail. */
pt_vec2 pt_matrix_journey(const pt_stage_params *par, const pt_matrices *mx, pt_vec3 v_m,
                          const pt_sink *const sinks[PT_NSTAGES_ALL],
                          pt_vec4 *clip, unsigned *code);

/* The tail from clip coordinates on: ndc, screen, viewport, framebuffer, index.
** w_scale is the magnitude clip.w was computed from (m5_clip2ndc.h):
** pt_matrix_journey()'s for a vertex, |w| for a point clipping made (it lies in
** the view volume, w >= near).  Returns the pixel-plane point for the
** rasterizer (NaN without a pixel).  This function can't fail. */
pt_vec2 pt_matrix_tail(const pt_stage_params *par, pt_vec4 clip, double w_scale,
                       const pt_sink *const sinks[PT_NSTAGES_ALL]);

#endif
