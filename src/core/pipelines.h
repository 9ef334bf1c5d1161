/*
** src/core/pipelines.h -- a pipeline as data: its stages, its runners, its segment stages
** See LICENSE for copyright and license.
**
** A pipeline is the road a scene's vertices take, described once, here: the
** order of its stages (their formulas are in stages/), the hook that plans
** what its models need, the runner that takes a vertex through the stages,
** the segment stages that may drop a segment or give it new end points
** between the vertex stages and the rasterizer, the runner that takes such a
** new point on, and the viewport stage the rasterizer asks for every step.
** The scene names one (pt_scene.pipe); the plan, the run, a journey and
** the trace's header follow it, and nothing asks "which camera" any other way.
**
**   classic  model -> camera -> image -> pixel -> viewport -> framebuffer -> index
**   matrix   model -> world -> view -> clip -> cvv -> [cut the segment to the
**            view volume] -> ndc -> screen -> viewport -> framebuffer -> index
**
** This header holds the types only (the scene names a pipeline by its id);
** the descriptors, whose hooks plan and run, are in pipeline.c.  A new
** pipeline needs its stage files and ids (stages/), a row for each new stage
** in pt_stage_infos[], an order, a runner, an id here and a descriptor in
** pipeline.c; docs/architecture.md has the recipe.
*/
#ifndef PT_PIPELINES_H
#define PT_PIPELINES_H

#include <stddef.h>
#include <stdint.h>
#include "stages/pt_stage.h"
#include "stages/pt_matrix.h"
#include "stages/pt_segment.h"
#include "core/raster.h"

struct pt_scene;
struct pt_plan;

/* The pipelines a scene can name. */
typedef enum pt_pipe_id {
    PT_PIPE_CLASSIC,             /* the teaching renderer's (renderer 4's) */
    PT_PIPE_MATRIX               /* the matrix camera: `camera lookat` */
} pt_pipe_id;

/* How many pipelines there are: not an id, so that a switch over pt_pipe_id
** lists exactly the pipelines (-Wswitch-enum). */
#define PT_NPIPES ((int)PT_PIPE_MATRIX + 1)

/* The numbers one model's vertices go through the stages with. */
typedef struct pt_pipe_in {
    pt_stage_params par;         /* translation, camera, viewport, framebuffer */
    pt_matrices mx;              /* World, View, Projection (pointers into the
                                 ** plan), or all NULL where the pipeline has none */
} pt_pipe_in;

/* What a runner hands the driver besides the records. */
typedef struct pt_vtx {
    pt_vec2 pp;                  /* the point of the pixel plane the rasterizer
                                 ** draws from (NaN: none) */
    pt_vec4 h;                   /* the coordinates segment stages cut in
                                 ** (matrix: clip space); unused without them */
    unsigned code;               /* 0, or why it stopped early (matrix: the
                                 ** CVV outcode of a vertex outside) */
    int behind;                  /* 1: behind the camera */
    int norder;                  /* how many stages of the order it went through */
} pt_vtx;

/* A segment stage of a pipeline (its function in stages/, pt_segment.h). */
typedef struct pt_segstage {
    pt_stage stage;              /* the space it cuts in */
    const char *what;            /* what it does, in a few words */
    const char *dropped;         /* why a dropped segment is not drawn (the
                                 ** trace's skip record) */
    pt_segstage_fn cut;          /* the stage */
} pt_segstage;

typedef struct pt_pipeline {
    pt_pipe_id id;               /* its place in pt_pipelines[] */
    const char *name;            /* its name in the trace's header: "classic" */
    const char *title;           /* what the tools call it: "matrix camera" */
    const char *camera;          /* the camera line's word for it: "lookat", or
                                 ** NULL where the projection names it */
    const pt_stage *order;       /* its stages in pipeline order, */
    int norder;                  /*   and how many */
    pt_stage stops_at;           /* a point whose runner says code != 0 stops
                                 ** after this stage (matrix: the cvv) */
    const pt_stage_info *viewport_info;     /* its viewport stage's row */
    int matrices;                /* 1: the plan holds its View, Projection and
                                 ** each model's World (pt_plan, pipeline.h) */
    unsigned ref_stages;         /* bit st: its stage st is computed by a file
                                 ** of s1 .. s6 (a student's can replace it),
                                 ** whose reference copy (stages/pt_ref.h)
                                 ** says what it should give */
    void (*plan)(struct pt_plan *p, const struct pt_scene *s, int raw_lookat);
                                 /* what the plan holds for it (matrices), or NULL */
    void (*model_in)(pt_pipe_in *in, const struct pt_scene *s,
                     const struct pt_plan *p, size_t k);
                                 /* the numbers of model k */
    void (*run_vertex)(const pt_pipe_in *in, pt_vec3 v_m,
                       const pt_sink *const sinks[PT_NSTAGES_ALL], pt_vtx *out);
                                 /* a vertex through the stages, stage st
                                 ** reporting to sinks[st] (NULL: not reported) */
    const pt_segstage *segstages;   /* its segment stages, in order, */
    int nsegstages;                 /*   and how many (0: none) */
    int (*seed)(const pt_made *mp, pt_vrec rec[2]);
                                 /* the records a made point's journey starts
                                 ** with (not traced: the point's own line says
                                 ** them); returns how many */
    void (*run_made)(const pt_pipe_in *in, const pt_made *mp,
                     const pt_sink *const sinks[PT_NSTAGES_ALL], pt_vtx *out);
                                 /* a made point on from its stage */
    pt_raster_vp to_viewport;    /* the viewport stage the rasterizer asks */
    int inlined_dda;             /* 1: to_viewport is pt_pixel2viewport, whose
                                 ** DDA with the stages inlined draws the image
                                 ** (pt_raster_draw) */
} pt_pipeline;

/* The row of stage st as pipeline pl has it (its own viewport stage).  This
** function can't fail. */
static inline const pt_stage_info *pt_pipeline_info(const pt_pipeline *pl, pt_stage st)
{
    return st == PT_STAGE_VIEWPORT ? pl->viewport_info : &pt_stage_infos[st];
}

/* 1 when pl's stage st is a file of s1 .. s6, with a reference copy.  This
** function can't fail. */
static inline int pt_pipeline_ref(const pt_pipeline *pl, pt_stage st)
{
    return (pl->ref_stages >> st) & 1u;
}

/* The stage before st in pl's order, or -1 (st is the first, or not pl's).
** This function can't fail. */
static inline int pt_pipeline_prev(const pt_pipeline *pl, pt_stage st)
{
    int i;

    for (i = 1; i < pl->norder; i++)
        if (pl->order[i] == st) return (int)pl->order[i - 1];
    return -1;
}

/* 1 when stage st is one of pl's.  This function can't fail. */
static inline int pt_pipeline_has(const pt_pipeline *pl, pt_stage st)
{
    int i;

    for (i = 0; i < pl->norder; i++)
        if (pl->order[i] == st) return 1;
    return 0;
}

/* How many of pl's stages a point whose runner said `code` goes through: all
** of them when code is 0, else up to pl->stops_at.  This function can't fail. */
static inline int pt_pipeline_norder(const pt_pipeline *pl, unsigned code)
{
    int i;

    if (!code) return pl->norder;
    for (i = 0; i < pl->norder; i++)
        if (pl->order[i] == pl->stops_at) return i + 1;
    return pl->norder;
}

#endif
