/*
** src/tools/quiz79.h -- pipetrace quiz for the course's renderers 7 and 9
** See LICENSE for copyright and license.
**
** The questions of renderers 7 and 9 for one vertex V of a model: the
** segment it follows is the model's first segment that uses V (else its
** first point), taken through the renderer's stages on its own
** (pt_course_step(), core/course.h), V's end at every stage:
**   model     x_m y_m z_m         (the scene gives it)
**   world     x_w y_w z_w         (renderer 9: the position's matrix)
**   view      x_v y_v z_v
**   camera    x_c y_c z_c         (the view volume normalized)
**   nearclip  t x y z | none | dropped   (the near plane's cut of V's end)
**   image     x_p y_p z_p         (V's end after the near clip, projected)
**   clip      EDGE t x y | none | dropped   (one question per cut of V's
**             end; EDGE x=+1, x=-1, y=+1 or y=-1; clip2, clip3, ... after)
**   pixel     x_pp y_pp           (the rasterizer's pixel plane, unrounded)
**   viewport  x_vp y_vp           (Math.round(x_pp) - 1, h - Math.round(y_pp))
**   color     r g b | none        (the bytes the whole render leaves in the
**             pixel the course writes: pt_raster_fb_pixel's index, wrapped
**             where the viewport sticks out; none where the course drops it)
** After "dropped" the segment is gone: no more questions.  A wrong answer
** "follows" when the stage, run on the sheet's own answer before it, gives it.
** A wrong answer is shown its stage's formula with the right numbers put in
** (pt_q79_worked(): io/explain_course.c's text, as pipetrace step writes it);
** the colour's are the last write at the pixel, as the rasterizer told it.
*/
#ifndef PT_QUIZ79_H
#define PT_QUIZ79_H

#include <stdio.h>
#include "core/pipetrace.h"

#define PT_Q79_MAX 16            /* questions of one vertex, at most */

typedef struct pt_q79 pt_q79;    /* a vertex's questions and answers */

/* The questions for vertex v (1-based) of model m of s (renderer 7 or 9).
** Returns NULL with a message on standard error ("pipetrace quiz: ...")
** when the model is hidden or out of memory. */
pt_q79 *pt_q79_make(const pt_scene *s, const pt_model *m, unsigned long long v);
void pt_q79_free(pt_q79 *q);

/* How many questions; question k's name ("clip2") and its values' names
** ("x_c y_c z_c"). */
int pt_q79_count(const pt_q79 *q);
const char *pt_q79_name(const pt_q79 *q, int k);
const char *pt_q79_values(const pt_q79 *q, int k);

/* The scene's renderer: 7 or 9. */
int pt_q79_renderer(const pt_q79 *q);

/* Which primitive the questions follow, as a sentence, into b. */
void pt_q79_describe(const pt_q79 *q, char *b, size_t n);

/* 1 when name may be a question's name ("nearclip", "clip2"). */
int pt_q79_stage_name(const char *name);

/* Question k's right answer as a sheet would write it, into b. */
void pt_q79_answer(const pt_q79 *q, int k, char *b, size_t n);

/* Question k's formula, as pipetrace step shows its stage (io/explain_course.h);
** NULL for the model's, which the scene gives.  Can't fail. */
const char *pt_q79_formula(const pt_q79 *q, int k);

/* Question k's stage with the right answer's numbers put in, as pipetrace
** step writes it (pt_cx_explain_step()), the equations separated by sep,
** into b; the colour's: the render's last write at the pixel
** (pt_cx_explain_write()), or why the pixel has none.  Returns its length
** (>= n: cut short; the colour's can pass PT_EXPLAINLEN), 0 for none. */
size_t pt_q79_worked(const pt_q79 *q, int k, char *b, size_t n, const char *sep);

/* Grade line as the answer to question k.  res[] holds the results of the
** questions before k (1 right, 0 wrong, 2 follows, -1 unanswered), lines[]
** the sheet's answers to them (NULL: not kept).  Returns 1 right, 0 wrong,
** 2 follows (wrong, but what the stage gives from the sheet's answer before
** it), or -1 when the line cannot be read as an answer to k: then *col is
** the 1-based column of what is wrong and why says what. */
int pt_q79_grade(const pt_q79 *q, int k, const char *line, const int *res,
                 const char *const *lines, int *col, const char **why);

/* 1 when the sheet's n answer lines have the form of a renderer 4 sheet
** (model, camera, image, pixel, viewport, framebuffer, index) and not of q's. */
int pt_q79_r4_sheet(const pt_q79 *q, const char *const *lines, int n);

#endif
