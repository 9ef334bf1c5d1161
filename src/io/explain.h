/*
** src/io/explain.h -- each stage's formula with one vertex's numbers put in
** See LICENSE for copyright and license.
**
** A pt_journey (src/core/vjourney.h) is the record of every stage pt_run()
** ran for one vertex, handed over by pt_run() itself (so its numbers are the
** trace's numbers, bit for bit).  The explain functions turn a journey into
** text for people: the formula of a stage with this vertex's numbers put in, and
** a note on what the next stage will do with the result.  Every number is
** written as the shortest decimal that reads back to the same double, so a
** student can redo each step with a calculator and get the same digits.
**
** USAGE
**   pt_journey j;  pt_run_journey(&j, scene, model, v, 0);
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
** framebuffer").  Every equation is true arithmetic: the numbers put in are
** the run's record of the stage before (what the stage was handed), the
** result is the reference stage's (pt_ref_stage(), stages/pt_ref.h; the
** matrix camera's own stages and the model are the run's).  Where the run's
** record of st differs from it (a student's stage, make STAGE_x=FILE.c), the
** coordinate's equation is followed by sep and "your stage gave y_vp = 2".
** Returns the length (see above).  This function can't fail. */
size_t pt_explain_stage(char *buf, size_t len, const pt_journey *j, pt_stage st,
                        const char *sep);

/* j as the reference stages compute it, into *ref: a copy of j in which
** each of j's stages the reference has (pt_pipeline_ref()) is computed again, in j's
** order, from the reference's own record of the stage before; the model and
** the matrix camera's own stages stay j's.  In a build without student
** stages the values are j's.  This function can't fail. */
void pt_explain_reference(pt_journey *ref, const pt_journey *j);

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

/* 1 when explain has every row stage st of pipeline pl asks for: its formula
** (for pl's own viewport stage, the one of pl's viewport row), what comes
** after it, and for pl's first stage what pl's second stage does with it.
** tests/unit/test_explain.c asks it for every stage of every pipeline, so that a
** new stage or pipeline without its rows fails there, not in a student's
** hands.  This function can't fail. */
int pt_explain_has_rows(const pt_pipeline *pl, pt_stage st);

/* What the Java renderer's (int)Math.round(x) holds: Math.round returns a
** long, 0 for NaN and saturated at -2^63 and 2^63 - 1, and the int cast keeps
** its low 32 bits (two's complement).  So 1e300 gives -1, -1e300 gives 0, 3e9
** gives 3e9 - 2^32.  pipetrace never uses it for a pixel; it says what Java
** would have done where the two part.  This function can't fail. */
int32_t pt_explain_java_int_round(double x);

#endif
