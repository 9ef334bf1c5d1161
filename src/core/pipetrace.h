/*
** src/core/pipetrace.h -- the core's one public header: what io and the tools use
** See LICENSE for copyright and license.
**
** The core parses a scene, plans its stages, runs every vertex through the
** stages of stages/ and rasterizes the segments into a framebuffer:
**
**   pt_scene_load -> pt_plan_make -> pt_run (stages, then raster) -> listener
**
** Everything above the core (src/io: trace writers and readers, images,
** files, numbers as text; src/tools: the commands) includes this header and no
** other header of src/core or stages/; tests/repo/layers.py checks it.  It names
** only what they use: no runner (pt_classic.h, pt_matrix.h: pt_run() is the
** one way through the stages), no stage the tools do not call themselves.
** USAGE is in pipeline.h; the stages' formulas are at the top of each
** stages/ header.
*/
#ifndef PT_PIPETRACE_H
#define PT_PIPETRACE_H

/* the records, the stage table, numbers as Java rounds them, matrices */
#include "stages/pt_stage.h"           /* vectors, stage ids, records, the table */
#include "stages/pt_round.h"           /* Java's rounding, the inside tests */
#include "stages/pt_jmath.h"           /* Java's Math.atan (the course log's fovy) */
#include "stages/pt_mat4.h"            /* 4x4 matrices on row vectors */
/* the stage functions the tools call themselves: the reference copies of
** s1 .. s6 ("the formula"), the run's own viewport, framebuffer and index
** (the pixels a run drew, read back), the matrix camera's stages (accuracy's
** double run), its segment stage, and the pixel plane's divisor */
#include "stages/pt_ref.h"             /* the reference copy of s1..s6 (ptref_) */
#include "stages/s3_image2pixel.h"
#include "stages/s4_pixel2viewport.h"
#include "stages/s5_viewport2fb.h"
#include "stages/s6_fb2index.h"
#include "stages/m1_model2world.h"
#include "stages/m2_world2view.h"
#include "stages/m3_view2clip.h"
#include "stages/m4_clip2cvv.h"
#include "stages/m5_clip2ndc.h"
#include "stages/m6_ndc2screen.h"
#include "stages/m7_screen2viewport.h"
#include "stages/ms_clip_segment.h"    /* the matrix camera's: clip to the CVV */
#include "stages/rv_raster.h"          /* renderers 7 and 9: the rasterizer */
#include "stages/r7_model2view.h"      /* ... their stages (accuracy's double run, */
#include "stages/r7_view2camera.h"     /*   diff's catalogue of their mistakes) */
#include "stages/r9_model2world.h"
#include "stages/r9_world2view.h"
#include "stages/r9_view2camera.h"
#include "stages/rv_nearclip.h"
#include "stages/rv_project.h"
#include "stages/rv_clip.h"
#include "stages/wasm/pt_wasm_in.h"    /* the journey page's module: where its inputs go */
/* the core: parse, plan, run, listen; the DDA; one point's journey */
#include "core/scene.h"                /* the scene, parsed */
#include "core/shapes.h"               /* the course's models: `shape NAME ARGS` */
#include "core/builtin.h"              /* the scene rendered when given none */
#include "core/fb.h"                   /* the framebuffer */
#include "core/raster.h"               /* the DDA (accuracy's double run) */
#include "core/vjourney.h"             /* one point's records, every stage */
#include "core/pipelines.h"            /* a pipeline as data */
#include "core/pipeline.h"             /* plan, run, listen */
#include "core/course.h"               /* renderers 7 and 9: their driver */

#endif
