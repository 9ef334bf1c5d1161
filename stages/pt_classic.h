/*
** stages/pt_classic.h -- the classic camera's six stages, run in order
** See LICENSE for copyright and license.
**
** The one place that says in which order, and with which numbers, the classic
** stages are called: the pipeline, the step-through and every other tool that
** follows a vertex call this, so their numbers agree bit for bit.
**
**   model --s1--> camera --s2--> image --s3--> pixel --s4--> viewport
**         --s5--> framebuffer --s6--> index
*/
#ifndef PT_CLASSIC_H
#define PT_CLASSIC_H

#include "pt_stage.h"

/* Run v_m through the model record and the six stages with par; stage st
** reports to sinks[st] (NULL: not reported).  Sets *z_c (for "behind")
** and returns the pixel-plane point, which the rasterizer uses.  When none of
** the viewport, framebuffer and index stages reports (all three sinks NULL),
** they are not run: their values would go nowhere.  Requires
** par->w, h, W, H >= 1.  This function can't fail. */
pt_vec2 pt_classic_journey(const pt_stage_params *par, pt_vec3 v_m,
                           const pt_sink *const sinks[PT_NSTAGES_ALL], double *z_c);

#endif
