/*
** src/io/explain.h -- one vertex's journey, and each stage's formula with its numbers
** See LICENSE for copyright and license.
**
** A pt_journey is everything the seven stages compute for one vertex, filled by
** calling the stage functions of stages/ in pipeline order (so its numbers are
** the trace's numbers, bit for bit).  The explain functions turn a journey into
** text for people: the formula of a stage with this vertex's numbers put in, and
** a note on what the next stage will do with the result.  Every number is
** written as the shortest decimal that reads back to the same double, so a
** student can redo each step with a calculator and get the same digits.
**
** USAGE
**   pt_stage_params par;  pt_stage_params_of(&par, scene, model);
**   pt_journey j;  pt_journey_compute(&j, &par, model->v[v - 1]);
**   char b[PT_EXPLAINLEN];
**   pt_explain_stage(b, sizeof b, &j, PT_STAGE_PIXEL, "; ");
**     -> "x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1)
**         = 5.497501249375313; y_pp = ..."
**   pt_explain_next(b, sizeof b, &j, PT_STAGE_VIEWPORT)
**     -> "inside the viewport: ..."
**
** The functions here write into the caller's buffer and never print.  Each
** returns the length of the whole text; when that is >= len the text was cut
** short (still NUL-terminated).  PT_EXPLAINLEN is always enough.
*/
#ifndef PT_EXPLAIN_H
#define PT_EXPLAIN_H

#include <stddef.h>
#include "core/pipetrace.h"

#define PT_EXPLAINLEN 1024       /* room for any text written here */

/* One vertex's full journey.  rec[st] is the record stage st reports (model:
** the vertex itself), whether or not a trace would leave the stage out. */
typedef struct pt_journey {
    pt_stage_params par;         /* the numbers used */
    pt_vrec rec[PT_NSTAGES_ALL]; /* each stage's values, indexed by pt_stage */
    const pt_stage *order;       /* the stages this journey went through, */
    int norder;                  /*   in pipeline order, and how many */
    int matrix;                  /* 1: the matrix camera's journey */
    pt_mat4 world, view, proj;   /* matrix camera: World, View, Projection */
} pt_journey;

/* Run v_m (model coordinates) through the classic camera's six stages with
** par.  Requires par->w, h, W, H >= 1.  This function can't fail. */
void pt_journey_compute(pt_journey *j, const pt_stage_params *par, pt_vec3 v_m);

/* The journey of 1-based vertex v of model m in scene s, through whichever
** camera s has, exactly as pt_run() computes it (raw_lookat as its option).
** Under the matrix camera a vertex outside the view volume stops at the cvv
** stage.  Returns 0, or -1 when out of memory. */
int pt_journey_of(pt_journey *j, const pt_scene *s, const pt_model *m, uint64_t v,
                  int raw_lookat);

/* The same under plan p, the one pt_run() got (p may be NULL for the classic
** camera): no plan is built, so a caller with many vertices pays for one plan,
** not one per vertex.  This function can't fail. */
void pt_journey_of_plan(pt_journey *j, const pt_scene *s, const pt_plan *p,
                        const pt_model *m, uint64_t v);

/* The journey of a point the matrix camera's clipping made on a segment of
** model m, from its clip coordinates q (the listener's clipvertex_begin gets
** them): ndc .. index, as pt_run() computes them.  Its clip and cvv records
** hold q itself; the earlier stages have none.  This function can't fail. */
void pt_journey_of_clip(pt_journey *j, const pt_scene *s, const pt_plan *p,
                        const pt_model *m, pt_vec4 q);

/* The name, spaces and formula of stage st as j's camera has it (the matrix
** camera's viewport stage floors instead of rounding).  Can't fail. */
const pt_stage_info *pt_journey_info(const pt_journey *j, pt_stage st);

/* 1 when r is the record of its stage in j, number for number.  This function
** can't fail. */
int pt_journey_matches(const pt_journey *j, const pt_vrec *r);

/* 1 when pt_run() reports, for every used vertex of s, exactly the records of
** its pt_journey; 0 when it does not (a scene whose camera takes other stages,
** which the explain functions do not know); -1 when out of memory. */
int pt_journey_agrees(const pt_scene *s);

/* 1 when some segment of m uses its 1-based vertex v.  This function can't fail. */
int pt_vertex_used(const pt_model *m, uint64_t v);

/* How many coordinates stage st has (3, 2 or 1), and the name of the k-th
** ("x_pp").  This function can't fail. */
int pt_coord_count(pt_stage st);
const char *pt_coord_name(pt_stage st, int k);

/* Stage st's formula with j's numbers substituted and the result, one
** coordinate after the other, separated by sep:
**   "x_c = x_m + x_t = -1 + (-1.5) = -2.5" sep "y_c = ..." sep "z_c = ..."
** Negative numbers after an operator are put in parentheses.  A result with no
** value says why ("none: (x_fb, y_fb) = (-2, 4) lies outside the 12 x 8
** framebuffer").  Returns the length (see above).  This function can't fail. */
size_t pt_explain_stage(char *buf, size_t len, const pt_journey *j, pt_stage st,
                        const char *sep);

/* Stage st's values in j as one tuple: "(x_c, y_c, z_c) = (-1, -1, -2)",
** "idx = 144", "(x_vp, y_vp) = none".  Returns the length.  Can't fail. */
size_t pt_explain_values(char *buf, size_t len, const pt_journey *j, pt_stage st);

/* Stage st's values in j without their names: "(-1, -1, -2)", "144",
** "none".  Returns the length.  This function can't fail. */
size_t pt_explain_tuple(char *buf, size_t len, const pt_journey *j, pt_stage st);

/* What the result of stage st means for the stages after it, in one sentence:
** "outside the viewport: its pixel is clipped ...", "behind the camera (z_c >
** 0): projected mirrored ...".  Returns the length.  This function can't fail. */
size_t pt_explain_next(char *buf, size_t len, const pt_journey *j, pt_stage st);

/* What the Java renderer's (int)Math.round(x) holds: Math.round returns a
** long, 0 for NaN and saturated at -2^63 and 2^63 - 1, and the int cast keeps
** its low 32 bits (two's complement).  So 1e300 gives -1, -1e300 gives 0, 3e9
** gives 3e9 - 2^32.  pipetrace never uses it for a pixel; it says what Java
** would have done where the two part.  This function can't fail. */
int32_t pt_explain_java_int_round(double x);

#endif
