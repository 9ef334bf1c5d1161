/*
** src/io/explain_course.h -- renderers 7 and 9: one vertex's stages with its numbers put in
** See LICENSE for copyright and license.
**
** The course's renderers 7 and 9 (core/course.h) work on whole models, so
** a vertex's journey is read off one render of the scene: pt_cx_run()
** listens to the driver and keeps, for vertex v of one position, its value
** and colour after every stage, the cut that made it (a vertex the near clip
** or the rectangle clip made: numbered after the model's, as the trace
** numbers it), the cuts that cut it off, and the rasterizer's pixel lines at
** its pixel.  The text functions put those numbers into each stage's formula:
** every number is the run's own (the shortest decimal that reads back to
** it), so each equation can be redone with a calculator.
**
**   model -> [r9: world (M v)] -> view (r7: + t; r9: - view vector)
**     -> camera (skew or shift, then scale to -1..1) -> nearclip (z <= n)
**     -> image (x_c / -z_c) -> clip (the square -1..1)
**     -> pixel plane (0.5 + w/2.001 * (x_p + 1)) -> viewport (Math.round,
**        x_vp = x_pp - 1, y_vp = h - y_pp) -> pixel (anti-aliasing's weight,
**        gamma, the colour bytes)
**
** USAGE
**   pt_cx_journey j;
**   if (pt_cx_run(&j, scene, model_index, v) == 0)
**       for (i = 0; i < j.nsteps; i++) pt_cx_stage(b, sizeof b, &j, j.steps[i], "\n");
*/
#ifndef PT_EXPLAIN_COURSE_H
#define PT_EXPLAIN_COURSE_H

#include <stddef.h>
#include "core/pipetrace.h"

/* The stages step shows for renderers 7 and 9, in order (r7 has no world). */
typedef enum pt_cx_step {
    PT_CXS_MODEL, PT_CXS_WORLD, PT_CXS_VIEW, PT_CXS_CAMERA, PT_CXS_NEARCLIP,
    PT_CXS_IMAGE, PT_CXS_CLIP, PT_CXS_PIXEL, PT_CXS_VIEWPORT, PT_CXS_RASTER
} pt_cx_step;
#define PT_NCXS 10

#define PT_CX_MAXPX 8            /* pixel lines kept at the vertex's pixel */
#define PT_CX_MAXCUT 8           /* cuts kept that cut the vertex off */

/* A cut that cut the vertex off a primitive. */
typedef struct pt_cx_off {
    pt_course_stage stage;       /* PT_CST_NEARCLIP or PT_CST_CLIP */
    uint64_t prim;               /* the primitive, 1-based in that stage's list */
    pt_rv_cut cut;
} pt_cx_off;

/* A rasterizer pixel line at the vertex's pixel, of a primitive ending there. */
typedef struct pt_cx_px {
    uint64_t prim;               /* 1-based in the rasterizer's list (the trace's) */
    pt_rv_pixel px;              /* px.par is not kept: j->par is it */
    pt_rgb end_c;                /* the primitive's colour at the vertex's end */
} pt_cx_px;

typedef struct pt_cx_journey {
    int renderer;                /* 7 or 9 */
    size_t mi;                   /* the position's model (index in the scene) */
    uint64_t v;                  /* the vertex, 1-based */
    size_t nv;                   /* the scene model's vertex count */
    size_t nv_last;              /* its model's vertex count after the last
                                 ** stage (the clips' new ones counted) */
    pt_course_cam cam;
    pt_vec3 translate;           /* r7: the position's translation */
    pt_jmat matrix;              /* r9: its matrix */
    pt_rv_raster_par par;        /* viewport, framebuffer, switches */
    int nearclip;                /* 1: the near clip runs */
    int have[PT_NCST];           /* 1: the vertex exists after that stage */
    pt_vec4 at[PT_NCST];         /* its value after each stage */
    pt_rgb col[PT_NCST];         /* its colour (colour list index = vertex's) */
    int has_col[PT_NCST];
    pt_course_stage born;        /* PT_CST_MODEL, or the clip stage that made it */
    pt_rv_cut cut;               /*   that cut (born in a clip stage) */
    uint64_t cut_prim;           /*   of primitive cut_prim (1-based, that stage's) */
    size_t noff;                 /* cuts that cut it off (PT_CX_MAXCUT at most) */
    pt_cx_off off[PT_CX_MAXCUT];
    uint64_t nends;              /* primitives drawn with an end at the vertex */
    size_t npx;                  /* their pixel lines at its pixel */
    pt_cx_px px[PT_CX_MAXPX];
    pt_cx_step steps[PT_NCXS];   /* the stages step shows for it, in order */
    int nsteps;
    /* private: the render's place */
    size_t cur;                  /* the position being worked on */
    uint64_t prim_no, raster_no;
    pt_rv_prim clip_prim;        /* the clip stage's primitive, cut so far */
    int end_here;                /* the primitive being drawn ends at v, */
    pt_rgb end_c;                /*   in this colour */
    int mapped;                  /* 1: inside the view rectangle after the clip, */
    int64_t px_x, px_y;          /*   its viewport pixel */
} pt_cx_journey;

/* Render s (renderer 7 or 9) and keep vertex v (1-based; past the model's
** vertices: one a clip stage made) of the position of model mi.  Returns 0;
** 1 when that position has no vertex v in any stage (hidden, or v too
** large); -1 when out of memory.  s is not changed. */
int pt_cx_run(pt_cx_journey *j, const pt_scene *s, size_t mi, uint64_t v);

/* The first position (in file order) whose model has a vertex v after some
** stage (its own, or one a clip stage made), into *mi: one render.
** Returns 0; 1 when none has; -1 when out of memory.  */
int pt_cx_find(const pt_scene *s, uint64_t v, size_t *mi);

/* Step st's name ("camera"), the spaces it maps between, what it does and
** its formula.  Can't fail. */
typedef struct pt_cx_row {
    const char *name, *from, *to, *what;
    const char *formula7;        /* renderer 7's (and 9's, without formula9);
                                 ** NULL for the pixel plane, whose formula is
                                 ** the stage table's: ask pt_cx_formula() */
    const char *formula9;        /* NULL: renderer 9's is renderer 7's */
} pt_cx_row;
const pt_cx_row *pt_cx_row_of(pt_cx_step st);

/* Step st's formula for renderer 7 or 9; NULL for the world stage of
** renderer 7, which has none.  Can't fail. */
const char *pt_cx_formula(int renderer, pt_cx_step st);

/* 1 when explain has rows (name, what, a formula) for step st of renderer r.
** tests/unit/test_explain.c asks it for every stage course.c drives.  Can't fail. */
int pt_cx_has_rows(int renderer, pt_cx_step st);

/* The step that shows course stage cs (PT_CST_*).  Can't fail. */
pt_cx_step pt_cx_step_of(pt_course_stage cs);

/* Step st of j with its numbers put in, one equation after the other,
** separated by sep.  Returns the length of the whole text (>= len: cut
** short, still NUL-terminated).  Can't fail. */
size_t pt_cx_stage(char *buf, size_t len, const pt_cx_journey *j, pt_cx_step st,
                   const char *sep);

/* One write of the rasterizer at a framebuffer pixel, as its listener told
** it (stages/rv_raster.h): the quiz's colour question names the last one. */
typedef struct pt_cx_write {
    const char *model;           /* the scene model's name */
    const char *position;        /* its position's name */
    uint64_t prim;               /* 1-based in the rasterizer's list (the trace's
                                 ** "primitive" of the pixel record) */
    pt_rv_prim p;                /* it (indices in the model the clips left) */
    uint64_t v[2];               /* its ends' vertices, 1-based as the trace numbers them */
    pt_rgb c[2];                 /* its ends' colours */
    double ends[4];              /* its ends in the pixel plane, before rounding:
                                 ** x0, y0, x1, y1 (the rasterizer's "ends") */
    int has_slopes;              /* 1: a segment longer than one pixel, */
    pt_rv_slopes sl;             /*   its setup as the rasterizer told it */
    pt_rv_pixel px;              /* the pixel line (px.par not kept) */
    int upper;                   /* 1: the second pixel of an anti-aliased pair */
    float coverage;              /* 1; an anti-aliased pair's 1 - f and f */
    pt_fb_pixel at;              /* where: x_fb, y_fb and the index
                                 ** (pt_raster_fb_pixel), at.paint the bytes */
} pt_cx_write;

/* The worked numbers of write w into scene s's framebuffer: which primitive,
** which step of its DDA, the colour the step interpolates (its slopes as the
** rasterizer computed them), anti-aliasing's weight and blend, gamma and the
** bytes, each function of stages/pt_color.h asked again and checked against
** what the rasterizer wrote; nwrites is how many writes the pixel had.  The
** equations separated by sep.  Returns the length (>= len: cut short).
** Can't fail. */
size_t pt_cx_explain_write(char *buf, size_t len, const pt_scene *s, const pt_cx_write *w,
                           uint64_t nwrites, const char *sep);

/* One vertex record of a trace of a renderer 7 or 9 scene (--explain). */
typedef struct pt_cx_rec {
    pt_course_stage st;          /* the stage whose record it is */
    const pt_course_pos *pos;    /* its position */
    pt_vec4 prev;                /* the vertex after the stage before (not
                                 ** read for the model stage nor for a cut) */
    pt_vec4 cur;                 /* the vertex after st */
    const pt_rgb *color;         /* its colour, or NULL */
    const pt_rv_cut *cut;        /* a clip stage's new vertex: the cut that
                                 ** made it, else NULL */
    uint64_t cut_prim;           /*   of that stage's primitive cut_prim (1-based) */
} pt_cx_rec;

/* Record r of scene s (camera cam), its stage's formula with its numbers put
** in, as pt_cx_stage() writes it for step.  Returns the length (>= len: cut
** short).  Can't fail. */
size_t pt_cx_explain_rec(char *buf, size_t len, const pt_scene *s, const pt_course_cam *cam,
                         const pt_cx_rec *r, const char *sep);

/* The same for step st: r->st's own (pt_cx_step_of()), or, when r is the
** clip's record of a vertex the clip keeps, PT_CXS_PIXEL or PT_CXS_VIEWPORT
** (the rasterizer's map of it; PT_CXS_RASTER needs a render's pixel lines:
** pt_cx_run()).  Returns the length (>= len: cut short).  Can't fail. */
size_t pt_cx_explain_step(char *buf, size_t len, const pt_scene *s, const pt_course_cam *cam,
                          const pt_cx_rec *r, pt_cx_step st, const char *sep);

#endif
