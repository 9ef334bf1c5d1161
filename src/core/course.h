/*
** src/core/course.h -- renderers 7 and 9 of the course: a scene through their stages
** See LICENSE for copyright and license.
**
** pt_course_render() renders a scene with `renderer 7` or `renderer 9` as the
** course's Pipeline.render does (renderer 9's Pipeline2 with `pipeline2`):
**
**   per position, in file order:
**     hidden position or model: reported, nothing drawn
**     CheckModel's warnings; white per vertex when the scene gives no colour
**     r7: model -> view (translation) -> camera (view volume normalized)
**     r9: model -> world (matrix) -> view (-view vector) -> camera (normalize)
**     -> near clip (z = n) -> image plane (projection) -> clip (-1 .. 1)
**     -> the rasterizer, primitive by primitive, into the viewport
**
** Pipeline2 runs the same stages, each over every position before the next
** stage starts.  The framebuffer is cleared to the scene's background, its
** viewport to `viewport-background`.  Each stage works on the model in place
** (stages/rv_model.h): the model a stage reports is the one after it.
**
** The driver computes and reports to a pt_course_ls; it formats nothing.
** The course's log (io/trace_course.h) and pipetrace's trace of these scenes
** are listeners.
*/
#ifndef PT_COURSE_H
#define PT_COURSE_H

#include <stddef.h>
#include <stdint.h>
#include "core/scene.h"
#include "core/fb.h"
#include "stages/rv_model.h"
#include "stages/rv_raster.h"
#include "stages/r9_matrix.h"

/* The stages whose model the driver reports, in pipeline order (renderer 7
** has no world stage: its first transform goes from model to view). */
typedef enum pt_course_stage {
    PT_CST_MODEL,                /* 0. Model: the scene's vertices */
    PT_CST_WORLD,                /* r9 1. World: the position's matrix */
    PT_CST_VIEW,                 /* r7 1. View (translation); r9 2. View */
    PT_CST_CAMERA,               /* the view volume normalized */
    PT_CST_NEARCLIP,             /* clipped at z = n */
    PT_CST_IMAGE,                /* projected onto the image plane */
    PT_CST_CLIP                  /* clipped to the square -1 .. 1 */
} pt_course_stage;
#define PT_NCST 7

/* What happens to a position, in the order Pipeline.render logs it. */
typedef enum pt_course_mark {
    PT_CMK_BEGIN,                /* the scene's render begins (camera known) */
    PT_CMK_POSITION,             /* a visible position: its placement known */
    PT_CMK_MODEL,                /* its visible model */
    PT_CMK_MODEL_END,
    PT_CMK_MODEL_HIDDEN,         /* a hidden model */
    PT_CMK_POSITION_END,
    PT_CMK_POSITION_HIDDEN,      /* a hidden position */
    PT_CMK_END,                  /* the scene's render ends */
    PT_CMK_PHASE,                /* Pipeline2: stage pos->phase begins, */
    PT_CMK_STEP,                 /*   runs on the model of pos (stages 2 .. 7), */
    PT_CMK_STEP_END,
    PT_CMK_PHASE_END             /*   and ends (pos->sm NULL for the phase) */
} pt_course_mark;

/* CheckModel's warnings and the default colour's (printed whatever the
** debug switches). */
typedef enum pt_course_warn {
    PT_CWN_NO_VERTICES,          /* primitives but no vertices */
    PT_CWN_NO_PRIMITIVES,        /* vertices but no primitives */
    PT_CWN_NO_COLORS,            /* vertices but no colours */
    PT_CWN_DUMP,                 /* after either of the first two: the model */
    PT_CWN_DEFAULT_COLOR         /* white added, one a vertex */
} pt_course_warn;

/* The camera as the scene sets it up. */
typedef struct pt_course_cam {
    pt_rv_camera cam;            /* l r b t n, projection, view vector */
    pt_jmat norm;                /* r9: its normalize matrix */
} pt_course_cam;

/* A position being rendered. */
typedef struct pt_course_pos {
    const pt_model *sm;          /* the scene's model (its name, position name) */
    size_t index;                /* its place in the scene's models */
    const char *pos_name;        /* the Position's name */
    pt_vec3 translate;           /* r7: its translation vector */
    pt_jmat matrix;              /* r9: its matrix */
    int phase;                   /* Pipeline2: the stage number 1 .. 7 running */
} pt_course_pos;

/* What the rasterizer did, counted (pt_course_ls.tally): it lets a test see
** that a run skips what it should. */
typedef struct pt_course_tally {
    uint64_t prims_wanted;       /* primitives of the pieces wanted */
    uint64_t prims_drawn;        /* primitives the rasterizer ran on */
} pt_course_tally;

/* Who hears the driver.  Any callback may be NULL.  The clip listeners and
** the rasterizer's are handed to those stages as they are. */
typedef struct pt_course_ls {
    void (*mark)(void *ud, pt_course_mark k, const pt_course_cam *cam,
                 const pt_course_pos *pos);
    void (*warn)(void *ud, pt_course_warn w, const pt_course_pos *pos,
                 const pt_rv_model *m);          /* m: as CheckModel sees it */
    void (*stage)(void *ud, pt_course_stage st, const pt_course_pos *pos,
                  const pt_rv_model *m);         /* m: the model after st */
    void (*raster)(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                   const pt_rv_prim *p);         /* before p is drawn */
    void (*drawn)(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                  const pt_rv_prim *p, uint64_t npixels);   /* after */
    pt_rv_clip_ls nearclip;      /* handed to pt_rv_nearclip() */
    pt_rv_clip_ls clip;          /* handed to pt_rv_clip() */
    const pt_rv_raster_ls *raster_ls;   /* handed to pt_rv_raster_prim() */
    int measure;                 /* 1: the rasterizer is not run: raster hears each
                                 ** primitive it would draw, drawn nothing (a
                                 ** look at what would be drawn, before drawing) */
    int (*piece)(void *ud, uint64_t n, int last);
                                 /* NULL: one piece.  Else the render is cut into
                                 ** pieces where the scene alone says (below) and
                                 ** asks at the start of each (n = 0, 1, ...; last
                                 ** = 1 after the end mark) whether its records
                                 ** are wanted: 1 when they are.  Every event of a
                                 ** piece not wanted still comes (a listener keeps
                                 ** its counts), but the rasterizer's pixel lines,
                                 ** which go to nobody */
    uint64_t piece_vertices;     /* where the cuts fall: 0 for PT_COURSE_PIECE_* */
    uint64_t piece_prims;
    uint64_t piece_pixels;
    int skip_unwanted;           /* with piece, 1: a primitive of a piece not
                                 ** wanted is not drawn (drawn hears it with
                                 ** npixels 0, fb lacks its pixels): for a run
                                 ** whose image and pixel counts nobody reads,
                                 ** the second lane of io/tlanes.h */
    pt_course_tally *tally;      /* NULL, or where the primitives are counted */
    void *ud;
} pt_course_ls;

/* Where the render is cut into pieces (pt_course_ls.piece), by default: a
** cut may fall before each position's setup, before each step of a model,
** and before each primitive the rasterizer draws, and falls there once the
** piece holds PT_COURSE_PIECE_VERTICES vertices (a model's, once for its
** setup and once for each step before the rasterizer), PT_COURSE_PIECE_PRIMS
** primitives or PT_COURSE_PIECE_PIXELS pixel lines, or more.  A primitive's
** pixel lines are pt_rv_raster_steps(), found from its ends without
** drawing, so runs of the same scene cut alike, whatever the answers and
** whether they draw. */
#define PT_COURSE_PIECE_VERTICES 1024
#define PT_COURSE_PIECE_PRIMS    1024
#define PT_COURSE_PIECE_PIXELS   4096

/* The scene's camera (l r b t n, view vector, normalize matrix).  Can't fail. */
void pt_course_camera(const pt_scene *s, pt_course_cam *out);

/* Render s (s->renderer 7 or 9) into fb, s->fb_w x s->fb_h, which it clears
** first, telling ls (NULL: nobody).  With fb->rgb NULL nothing is written,
** and ls hears all it would hear with pixels (a run that only tells: the
** second lane of io/tlanes.h).
** Returns 0, or -1 when out of memory (fb then holds part of the image). */
int pt_course_render(const pt_scene *s, pt_fb *fb, const pt_course_ls *ls);

/* Run one stage st (PT_CST_WORLD .. PT_CST_CLIP, or PT_CST_RASTER: the
** rasterizer, every primitive of m into fb) on m as s's render runs it for
** position pos, telling ls (NULL: nobody).  For a tool that follows a few
** vertices of its own through the stages (the quiz): m may hold any
** vertices, colours and primitives.  0; -1 when st is no stage or out of
** memory (then m holds what the stage kept so far). */
#define PT_CST_RASTER PT_NCST
int pt_course_step(const pt_scene *s, const pt_course_pos *pos, int st, pt_rv_model *m,
                   pt_fb *fb, const pt_course_ls *ls);

#endif
