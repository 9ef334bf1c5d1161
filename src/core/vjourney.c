/*
** src/core/vjourney.c -- one point's journey: the record of every stage pt_run() ran for it
** See LICENSE for copyright and license.
*/
#include <string.h>
#include "core/vjourney.h"

void pt_journey_start(pt_journey *j, const pt_stage_params *par, const pt_mat4 *world,
                      const pt_mat4 *view, const pt_mat4 *proj)
{
    memset(j, 0, sizeof *j);
    j->par = *par;
    j->order = world ? pt_matrix_order : pt_classic_order;
    if (!world) return;
    j->matrix = 1;
    j->world = *world;
    j->view = *view;
    j->proj = *proj;
}

void pt_journey_file(pt_journey *j, const pt_vrec *r)
{
    if ((int)r->stage >= PT_NSTAGES_ALL) return;
    j->rec[r->stage] = *r;
    j->reported |= 1u << r->stage;
}

int pt_journey_norder(int matrix, unsigned code)
{
    int i;

    if (!matrix) return pt_classic_norder;
    if (!code) return pt_matrix_norder;
    for (i = 0; i < pt_matrix_norder; i++)  /* outside: it stops at the cvv */
        if (pt_matrix_order[i] == PT_STAGE_CVV) return i + 1;
    return pt_matrix_norder;
}

const pt_stage_info *pt_journey_info(const pt_journey *j, pt_stage st)
{
    if (j->matrix && st == PT_STAGE_VIEWPORT) return &pt_matrix_viewport_info;
    return &pt_stage_infos[st];
}

/* 1 when a and b hold the same numbers (bit for bit), flags and warnings. */
static int same_rec(const pt_vrec *a, const pt_vrec *b)
{
    return a->stage == b->stage && a->flags == b->flags && a->code == b->code &&
           a->warn == b->warn && a->digits_lost == b->digits_lost &&
           memcmp(&a->x, &b->x, sizeof a->x) == 0 && memcmp(&a->y, &b->y, sizeof a->y) == 0 &&
           memcmp(&a->z, &b->z, sizeof a->z) == 0 && memcmp(&a->w, &b->w, sizeof a->w) == 0 &&
           a->ix == b->ix && a->iy == b->iy && a->i == b->i;
}

int pt_journey_matches(const pt_journey *j, const pt_vrec *r)
{
    return (int)r->stage < PT_NSTAGES_ALL && same_rec(&j->rec[r->stage], r);
}
