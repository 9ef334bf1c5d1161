/*
** tests/unit/test_journey.c -- the journey's panel rows (src/tools/journey/jrows.c) and its index formula
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include "testhelp.h"
#include "core/pipetrace.h"
#include "tools/journey/jrows.h"
#include "tools/journey/jdraw.h"
#include "tools/journey/journey_classic.h"

/* Every stage of every pipeline's order has a row with its three hooks, and
** no stage outside the order has one; a pipeline whose points may stop
** before its last stage has the three `stopped` hooks. */
static void test_rows(void)
{
    int k, i, st, rows = 1, only = 1, hooks = 1, stops = 1, looks = 1;

    for (k = 0; k < PT_NPIPES; k++) {
        const pt_pipeline *pl = pt_pipelines[k];
        const pt_jrows *r = &pt_jpipes[k];
        int can_stop = pl->stops_at != pl->order[pl->norder - 1];

        hooks &= r->layout != NULL && r->ends != NULL && r->pixelplane != NULL;
        for (i = 0; i < pl->norder; i++) {
            const pt_jstage_row *row = r->stage[pl->order[i]];
            rows &= row != NULL && row->bg != NULL && row->fg != NULL && row->note != NULL;
        }
        for (st = 0; st < PT_NSTAGES_ALL; st++)
            if (!pt_pipeline_has(pl, (pt_stage)st) && r->stage[st]) only = 0;
        if (can_stop)
            stops &= r->stopped_fg != NULL && r->stopped_coords != NULL && r->stopped_note != NULL;
    }
    for (st = 0; st < PT_NSTAGES_ALL; st++) {  /* a space is seen from somewhere */
        const double *e = pt_jlooks[st].eye;
        looks &= e[0] != 0 || e[1] != 0 || e[2] != 0;
    }
    PT_CHECK("jrow-1.1 each pipeline has its layout, ends and pixel-plane hooks", hooks);
    PT_CHECK("jrow-1.2 every stage of every order has bg, fg and note", rows);
    PT_CHECK("jrow-1.3 ... and no stage outside the order has a row", only);
    PT_CHECK("jrow-1.4 a pipeline whose points may stop draws what they did not reach", stops);
    PT_CHECK("jrow-1.5 every stage has a look with a direction", looks);
}

/* The pixel-array panel's own copy of the index formula, for pixels off the
** frame, gives pt_fb2index()'s number on every pixel of the frame. */
static void test_would_index(void)
{
    static const int sizes[][2] = { {1, 1}, {6, 5}, {7, 1}, {1, 9}, {33, 17} };
    int n, x, y, same = 1;

    for (n = 0; n < (int)(sizeof sizes / sizeof sizes[0]); n++) {
        int W = sizes[n][0], H = sizes[n][1];
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                pt_pix fb;
                fb.x = x; fb.y = y; fb.ok = 1;
                same &= pt_jclassic_would_index(x, y, W) == pt_fb2index(fb, W, H, NULL);
            }
    }
    PT_CHECK("jrow-2.1 the panel's y * W + x is pt_fb2index() on the frame", same);
    PT_CHECK("jrow-2.2 ... and goes on off it: (-1, 2) of W 6 -> 11",
             pt_jclassic_would_index(-1, 2, 6) == 11);
}

int main(void)
{
    test_rows();
    test_would_index();
    return pt_test_report();
}
