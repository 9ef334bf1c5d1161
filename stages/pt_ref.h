/*
** stages/pt_ref.h -- the reference stages, a second copy that no student file replaces
** See LICENSE for copyright and license.
**
** `make STAGE_pixel=FILE.c` links a student's file as pt_image2pixel(); the
** tools still need the formula itself, to say what the stage should have
** given.  So the Makefile compiles stages/s1_model2camera.c .. s6_fb2index.c
** a second time, in every build, with pt_ref_names.h put in front of each
** (-include): that header renames each stage function pt_x to ptref_x, so
** the same source text becomes ptref_model2camera() .. ptref_fb2index().  In
** build/ both copies are the same code; in build-student/ the pt_ ones are
** the student's and the ptref_ ones stay the reference.  Nothing else is
** copied: the rounding, the inside test and the records' helpers
** (pt_round.h, pt_stage.h) are shared, and no student file replaces them.
**
** The prototypes below must match the stages' own: the second compilation
** sees both (this header, then the stage's header with the names changed),
** so a stage whose signature changes without this header stops the build.
** Who says "the formula" calls the ptref_ functions or pt_ref_stage(); who
** says "your stage" shows the run's records.
*/
#ifndef PT_REF_H
#define PT_REF_H

#include "pt_stage.h"
#include "pt_round.h"

/* The reference copies of stages/s1 .. s6, as their headers describe them.
** These functions can't fail. */
pt_vec3 ptref_model2camera(pt_vec3 m, pt_vec3 t, const pt_sink *sink);
pt_vec3 ptref_camera2image(pt_vec3 c, double z_scale, int perspective, const pt_sink *sink);
pt_vec2 ptref_image2pixel(pt_vec3 ip, int w, int h, const pt_sink *sink);
pt_pix ptref_pixel2viewport(pt_vec2 pp, int w, int h, const pt_sink *sink);
pt_pix ptref_viewport2fb(pt_pix vp, int x_ul, int y_ul, const pt_sink *sink);
int64_t ptref_fb2index(pt_pix fb, int W, int H, const pt_sink *sink);

/* 1 when the reference has a copy of stage st: camera .. index (a pipeline
** says which of its stages are these files: pt_pipeline.ref_stages).  This
** function can't fail. */
int pt_ref_has(pt_stage st);

/* The record the reference stage st (pt_ref_has(st, 0)) reports when handed
** in, the record of the stage before it, with the numbers of par, into *out.
** The image stage's warning of lost digits is judged from z_c alone (the
** runner also knows z_m).  Returns 1, or 0 (and *out zeroed) for a stage
** without a reference here.  Requires par->w, h, W, H >= 1.  This function
** can't fail. */
int pt_ref_stage(pt_stage st, const pt_stage_params *par, const pt_vrec *in, pt_vrec *out);

/* Which values of stage st differ between records a and b, bit for bit
** (-0.0 differs from 0.0; NaN agrees with NaN): bit k for value k; all of an
** integer stage's bits when one has a value and the other none.  0 when they
** agree.  This function can't fail. */
unsigned pt_ref_differ(pt_stage st, const pt_vrec *a, const pt_vrec *b);

#endif
