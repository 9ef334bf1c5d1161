/*
** src/core/vjourney.h -- one point's journey: the record of every stage pt_run() ran for it
** See LICENSE for copyright and license.
**
** A pt_journey holds what the stages computed for one vertex (or one point
** the matrix camera's clipping made), filed by stage: the records pt_run()
** got from the stages themselves, also those of stages a trace leaves out
** (identity stages, --stage), so a left-out stage's value is there to feed
** the next one.  pt_run() fills one for each traced point when its listener
** asks (pt_listener.journey, pipeline.h); pt_run_journey() and
** pt_run_journeys() (pipeline.h) are the short ways to get them.  There is no
** second computation: the numbers are the trace's, bit for bit, because they
** are the trace's records.
*/
#ifndef PT_VJOURNEY_H
#define PT_VJOURNEY_H

#include "stages/pt_stage.h"
#include "stages/pt_mat4.h"
#include "core/pipelines.h"

/* One point's journey.  rec[st] is the record stage st reported (model: the
** vertex itself); a stage the point did not reach holds zeros.  order[0 ..
** norder) are the stages it went through, in pipeline order: the classic
** camera's 7; the matrix camera's 10, or 5 for a vertex outside the view
** volume (it stops at the cvv).  A point clipping made starts at the clip
** stage: its clip and cvv records hold its clip coordinates (cvv code 0), the
** stages before have none, order and norder are the matrix camera's all. */
typedef struct pt_journey {
    pt_stage_params par;         /* the numbers used */
    pt_vrec rec[PT_NSTAGES_ALL]; /* each stage's values, indexed by pt_stage */
    const pt_stage *order;       /* the stages this journey went through, */
    int norder;                  /*   in pipeline order, and how many */
    unsigned reported;           /* bit st: stage st reported its record (a
                                 ** student's stage may not: its rec is zeros) */
    const pt_pipeline *pipe;     /* the pipeline it went through */
    pt_mat4 world, view, proj;   /* matrix camera: World, View, Projection */
} pt_journey;

/* Start an empty journey through pipeline pl with the numbers in (its
** matrices copied when it has them); no records yet, norder 0 (the caller
** sets it).  This function can't fail. */
void pt_journey_start(pt_journey *j, const pt_pipeline *pl, const pt_pipe_in *in);

/* File record r under its stage in j and mark the stage reported (a stage
** past the last is ignored).  This function can't fail. */
void pt_journey_file(pt_journey *j, const pt_vrec *r);

/* The name, spaces and formula of stage st as j's pipeline has it (the
** matrix camera's viewport stage floors instead of rounding).  Can't fail. */
const pt_stage_info *pt_journey_info(const pt_journey *j, pt_stage st);

/* 1 when j's point stopped before stage st of its pipeline (a matrix camera
** vertex outside the view volume stops at the cvv).  This function can't
** fail. */
int pt_journey_stopped(const pt_journey *j, pt_stage st);

/* 1 when r is the record of its stage in j, number for number (bit for bit,
** flags and all).  This function can't fail. */
int pt_journey_matches(const pt_journey *j, const pt_vrec *r);

#endif
