/*
** src/core/vjourney.c -- one point's journey: the record of every stage pt_run() ran for it
** See LICENSE for copyright and license.
*/
#include <string.h>
#include "core/vjourney.h"

void pt_journey_start(pt_journey *j, const pt_pipeline *pl, const pt_pipe_in *in)
{
    memset(j, 0, sizeof *j);
    j->par = in->par;
    j->pipe = pl;
    j->order = pl->order;
    if (in->mx.world) j->world = *in->mx.world;
    if (in->mx.view) j->view = *in->mx.view;
    if (in->mx.proj) j->proj = *in->mx.proj;
}

void pt_journey_file(pt_journey *j, const pt_vrec *r)
{
    if ((int)r->stage >= PT_NSTAGES_ALL) return;
    j->rec[r->stage] = *r;
    j->reported |= 1u << r->stage;
}

const pt_stage_info *pt_journey_info(const pt_journey *j, pt_stage st)
{
    return pt_pipeline_info(j->pipe, st);
}

int pt_journey_stopped(const pt_journey *j, pt_stage st)
{
    int i;

    for (i = j->norder; i < j->pipe->norder; i++)
        if (j->pipe->order[i] == st) return 1;
    return 0;
}

/* 1 when a and b hold the same numbers (bit for bit), flags and warnings. */
static int same_rec(const pt_vrec *a, const pt_vrec *b)
{
    return a->stage == b->stage && a->flags == b->flags && a->code == b->code &&
           a->warn == b->warn && a->digits_lost == b->digits_lost &&
           memcmp(&a->x, &b->x, sizeof a->x) == 0 && memcmp(&a->y, &b->y, sizeof a->y) == 0 &&
           memcmp(&a->z, &b->z, sizeof a->z) == 0 && memcmp(&a->w, &b->w, sizeof a->w) == 0 &&
           a->ix == b->ix && a->iy == b->iy && a->i == b->i &&
           memcmp(&a->color, &b->color, sizeof a->color) == 0;
}

int pt_journey_matches(const pt_journey *j, const pt_vrec *r)
{
    return (int)r->stage < PT_NSTAGES_ALL && same_rec(&j->rec[r->stage], r);
}
