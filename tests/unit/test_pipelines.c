/*
** tests/unit/test_pipelines.c -- the pipeline descriptors: names, orders, segment stages
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <string.h>
#include "testhelp.h"
#include "core/pipeline.h"

/* Each descriptor sits at its id, is found by its name, and says its order. */
static void test_table(void)
{
    int k, i, at_id = 1, by_name = 1, ends = 1, unique = 1;

    for (k = 0; k < PT_NPIPES; k++) {
        const pt_pipeline *pl = pt_pipelines[k];
        unsigned seen = 0;

        at_id &= (int)pl->id == k;
        by_name &= pt_pipeline_by_name(pl->name) == pl;
        ends &= pl->order[0] == PT_STAGE_MODEL && pl->order[pl->norder - 1] == PT_STAGE_INDEX;
        for (i = 0; i < pl->norder; i++) {
            if (seen & 1u << pl->order[i]) unique = 0;
            seen |= 1u << pl->order[i];
            if (!pt_pipeline_has(pl, pl->order[i])) unique = 0;
        }
        if (pt_pipeline_info(pl, PT_STAGE_VIEWPORT) != pl->viewport_info) ends = 0;
    }
    PT_CHECK("pipe-1.1 pt_pipelines[id] has that id", at_id);
    PT_CHECK("pipe-1.2 each is found by its name", by_name);
    PT_CHECK("pipe-1.3 an unknown name finds none", pt_pipeline_by_name("renderer") == NULL);
    PT_CHECK("pipe-1.4 each runs from model to index, its viewport its own", ends);
    PT_CHECK("pipe-1.5 no stage twice in an order", unique);
    PT_CHECK("pipe-1.6 the classic order is the stage table's",
             pt_pipe_classic.norder == pt_classic_norder &&
             memcmp(pt_pipe_classic.order, pt_classic_order,
                    sizeof pt_classic_order) == 0);
    PT_CHECK("pipe-1.7 the matrix camera's too, and it floors to the viewport",
             pt_pipe_matrix.norder == pt_matrix_norder &&
             pt_pipe_matrix.viewport_info == &pt_matrix_viewport_info);
    PT_CHECK("pipe-1.8 the classic camera has no world stage, the matrix no pixel",
             !pt_pipeline_has(&pt_pipe_classic, PT_STAGE_WORLD) &&
             !pt_pipeline_has(&pt_pipe_matrix, PT_STAGE_PIXEL));
    PT_CHECK("pipe-1.9 a matrix vertex outside stops after the cvv (5 stages)",
             pt_pipeline_norder(&pt_pipe_matrix, 0x01) == 5 &&
             pt_pipe_matrix.order[4] == PT_STAGE_CVV &&
             pt_pipeline_norder(&pt_pipe_matrix, 0) == pt_matrix_norder);
    PT_CHECK("pipe-1.10 a classic vertex goes all the way",
             pt_pipeline_norder(&pt_pipe_classic, 0) == pt_classic_norder);
}

/* The scene names its pipeline. */
static void test_scene(void)
{
    static const char classic[] = "model m\nv 0 0 -1\nv 1 0 -1\nl 1 2\n";
    static const char matrix[] = "camera lookat 0 0 5 0 0 -1 0 1 0\nprojection perspective 90 auto 1 100\n"
                                 "model m\nv 0 0 -1\nv 1 0 -1\nl 1 2\n";
    pt_scene s;
    char err[PT_ERRLEN];
    int ok;

    ok = pt_scene_parse(&s, "c.scene", classic, sizeof classic - 1, err, sizeof err) == 0;
    PT_CHECK("pipe-2.1 a scene without a camera line takes the classic pipeline",
             ok && pt_scene_pipeline(&s) == &pt_pipe_classic);
    if (ok) pt_scene_free(&s);
    ok = pt_scene_parse(&s, "m.scene", matrix, sizeof matrix - 1, err, sizeof err) == 0;
    if (!ok) printf("  %s\n", err);
    PT_CHECK("pipe-2.2 camera lookat takes the matrix camera's",
             ok && pt_scene_pipeline(&s) == &pt_pipe_matrix);
    if (ok) pt_scene_free(&s);
}

/* The matrix camera's segment stage: keep, drop, or new ends. */
static void test_cut(void)
{
    const pt_segstage *ss = &pt_pipe_matrix.segstages[0];
    pt_segend a, b;
    pt_made made[2];
    int moved[2] = {0, 0};
    pt_vec4 in = {0, 0, 0.5, 1}, right = {3, 0, 0.5, 1}, far_right = {5, 0, 0.5, 1};

    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    PT_CHECK("pipe-3.1 the matrix camera has one segment stage, at the cvv",
             pt_pipe_matrix.nsegstages == 1 && ss->stage == PT_STAGE_CVV &&
             pt_pipe_classic.nsegstages == 0);
    a.h = in; b.h = in;
    PT_CHECK("pipe-3.2 both ends inside: kept", ss->cut(&a, &b, made, moved) == PT_CUT_KEEP);
    a.h = right; a.code = 0x08; b.h = far_right; b.code = 0x08;
    PT_CHECK("pipe-3.3 both beyond x = w: dropped", ss->cut(&a, &b, made, moved) == PT_CUT_DROP);
    a.h = in; a.code = 0;
    b.color.r = 1.0f; b.color.g = 0.5f;
    PT_CHECK("pipe-3.4 one end beyond: a new last end",
             ss->cut(&a, &b, made, moved) == PT_CUT_NEW && !moved[0] && moved[1] &&
             made[1].end == 1 && made[1].t == 0.2 && made[1].q.x == 1 &&
             made[1].stage == PT_STAGE_CVV);
    PT_CHECK("pipe-3.5 ... with the colour at t, in float",
             made[1].color.r == 0.2f && made[1].color.g == 0.1f && made[1].color.b == 0.0f);
}

/* A journey's records carry colours, and matching sees them. */
static void test_colour(void)
{
    pt_journey j;
    pt_pipe_in in;
    pt_vrec r;

    memset(&in, 0, sizeof in);
    pt_journey_start(&j, &pt_pipe_classic, &in);
    memset(&r, 0, sizeof r);
    r.stage = PT_STAGE_MODEL;
    r.flags = PT_REC_COLOR;
    r.color.r = 0.5f; r.color.g = 0.25f; r.color.b = 1.0f;
    pt_journey_file(&j, &r);
    PT_CHECK("pipe-4.1 a record with a colour is filed with it", pt_journey_matches(&j, &r));
    r.color.g = 0.2509804f;
    PT_CHECK("pipe-4.2 ... and another colour does not match", !pt_journey_matches(&j, &r));
    PT_CHECK("pipe-4.3 the journey knows its pipeline",
             j.pipe == &pt_pipe_classic && pt_journey_info(&j, PT_STAGE_VIEWPORT) ==
             &pt_stage_infos[PT_STAGE_VIEWPORT]);
}

int main(void)
{
    test_table();
    test_scene();
    test_cut();
    test_colour();
    return pt_test_report();
}
